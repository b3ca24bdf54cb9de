# Request: a 1:6 dovetail saw guide for hand-cutting tails in 19 mm boards, laminated
# from four layers of 6 mm birch ply. Seen from the board's face the guide body is a
# trapezoid 60 mm tall, 70 mm wide at the bottom and 50 mm at the top, so both side
# faces lean 1:6 and the saw plate rides against either one. Three body layers (18 mm)
# sit on the board's end grain; the fourth, the fence, is the same trapezoid with a
# 70 x 30 mm skirt hanging down the board's back face. The middle body layer has two
# notches 6.2 mm wide and 3.2 mm deep in each sloping edge, at a quarter and three
# quarters up, for 6 x 3 mm disc magnets that hold the saw plate. Two 6 mm dowel holes,
# 30 mm apart on the centre line, 10 mm above the bottom, align the layers for gluing.
# The outer layer is engraved "1:6" and "DOVETAIL".

t = 6 mm
thickness t

BOT = 70 mm
TOP = 50 mm
H = 60 mm
SKIRT = 30 mm
MAG_W = 6.2 mm
MAG_D = 3.2 mm

# the left sloping edge runs from (-BOT/2, 0) to (-TOP/2, H); a point a fraction f up it
def left_edge(f) = (-BOT / 2 + (BOT - TOP) / 2 * f, H * f)
def right_edge(f) = (BOT / 2 - (BOT - TOP) / 2 * f, H * f)
SLOPE = atan2(H, (BOT - TOP) / 2)     # the edge's angle from +x on the left side

def layer(kind="core") -> solid {
    body = Trapezoid(center=(0, H / 2), bottom_width=BOT, top_width=TOP, height=H)
    if kind == "fence" {
        skirt = Rectangle(bottom_left=(-BOT / 2, -SKIRT), width=BOT, height=SKIRT)
    }
    hole dowels {
        d1 = Circle(center=(-15, 10), diameter=6)
        d2 = Circle(center=(15, 10), diameter=6)
    }
    if kind == "magnets" {
        hole magnets {
            for f in [0.25, 0.75] {
                # a bar from the edge inward, perpendicular to the edge
                ml = Rectangle(start=left_edge(f),
                               end=left_edge(f) + (MAG_D * sin(SLOPE), -MAG_D * cos(SLOPE)),
                               width=MAG_W)
                mr = Rectangle(start=right_edge(f),
                               end=right_edge(f) + (-MAG_D * sin(SLOPE), -MAG_D * cos(SLOPE)),
                               width=MAG_W)
            }
        }
    }
    if kind == "outer" {
        drawing mark {
            r = Text("1:6", position=(0, 38), size=10, valign="middle")
            w = Text("DOVETAIL", position=(0, 24), size=5, valign="middle")
        }
    }
}

assembly guide {
    fence = layer(kind="fence")
    inner = layer(kind="core")
    mid = layer(kind="magnets")
    outer = layer(kind="outer")

    # flat on the sheet: side by side
    RightOf(inner, fence, gap=5)
    RightOf(mid, inner, gap=5)
    RightOf(outer, mid, gap=5)
    AlignTop(inner, fence)
    AlignTop(mid, fence)
    AlignTop(outer, fence)

    # in 3D: stacked, the fence at the back
    Place(fence, position=(0, 0, 0))
    Place(inner, position=(0, 0, t))
    Place(mid, position=(0, 0, 2 * t))
    Place(outer, position=(0, 0, 3 * t))

    assert (fence.body.bottom_width - fence.body.top_width) / 2 / fence.body.height == 1 / 6,
        "sides lean 1:6"
    assert fence.body.height == 60 mm, "60 mm tall"
    assert fence.body.bottom_width == 70 mm and fence.body.top_width == 50 mm, "70 / 50 wide"
    assert fence.body.bb.bottom - fence.skirt.bb.bottom == 30 mm, "30 mm skirt"
    assert fence.skirt.bb.width == 70 mm, "skirt 70 wide"
    assert len(mid.magnets.ml) == 2 and len(mid.magnets.mr) == 2, "two magnets a side"
    assert mid.magnets.ml[0].width == 6.2 mm, "magnet notch 6.2 wide"
    assert distance(fence.dowels.d1.center, fence.dowels.d2.center) == 30 mm, "dowels 30 apart"
    assert fence.dowels.d1.center.y - fence.body.bb.bottom == 10 mm, "dowels 10 up"
    assert 3 * t == 18 mm, "body 18 mm on a 19 mm board"
}
