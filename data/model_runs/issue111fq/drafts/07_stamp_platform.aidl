# Request: a stamping platform for card making. A base 230 x 230 mm in 6 mm birch ply; an
# L-shaped fence of the same ply glued on top along its top and left edges, each arm 20 mm
# wide, located by three 6 mm dowels through fence and base (10 mm from the outer edges: at
# the corner, at the end of the top arm 20 mm from the right, at the end of the left arm 20 mm
# from the bottom). The working area is the 210 x 210 square inside the L: a 10 mm grid
# engraved on the base, and on the fence a scale along both inner edges from the corner: a
# 2 mm tick every 10 mm, a 4 mm tick and a number (0 to 200, 4 mm tall) every 20 mm, kept at
# least 1 mm clear of the dowels. A stamp carrier of 3 mm clear acrylic, 200 x 200 mm, that
# butts into the L: that corner sharp, the other three R5, a 30 mm half-round finger notch in
# the middle of the edge opposite the left arm, and "CORNER" engraved 4 mm tall near the
# sharp corner.
# (attempt 2: the end dowels 15 mm from the ends sat under the "200"s: they go 20 mm from the
# right and from the bottom, between the 180 and the 200; the left scale's 0 tick is the top
# scale's, drawn once.)

units mm
thickness 6 mm

B = 230 mm
ARM = 20 mm
X0 = -B / 2 + ARM      # the inner corner of the L: x
Y0 = B / 2 - ARM       # and y
DOWELS = [(-B / 2 + 10, B / 2 - 10), (B / 2 - 20, B / 2 - 10), (-B / 2 + 10, -B / 2 + 20)]
LID = 200 mm

assembly platform {
    solid base {
        body = Rectangle(center=(0, 0), width=B, height=B)
        hole pins {
            for p in DOWELS {
                c = Circle(center=p, diameter=6)
            }
        }
        drawing grid {
            for i in range(1, 21) {
                v = Line((X0 + i * 10, -B / 2 + 5), (X0 + i * 10, Y0))
                h = Line((X0, Y0 - i * 10), (B / 2 - 5, Y0 - i * 10))
            }
        }
    }
    Place(base, position=(0, 0, 0), face="up")

    solid fence {
        top_arm = Rectangle(bottom_left=(-B / 2, Y0), width=B, height=ARM)
        left_arm = Rectangle(bottom_left=(-B / 2, -B / 2), width=ARM, height=B)
        hole pins {
            for p in DOWELS {
                c = Circle(center=p, diameter=6)
            }
        }
        drawing scale {
            for i in range(21) {
                tt = Line((X0 + i * 10, Y0), (X0 + i * 10, Y0 + (4 if i % 2 == 0 else 2)))
            }
            for i in range(1, 21) {
                lt = Line((X0, Y0 - i * 10), (X0 - (4 if i % 2 == 0 else 2), Y0 - i * 10))
            }
            for k in range(11) {
                tn = Text(str(k * 20), position=(X0 + k * 20, Y0 + 5.5), size=4)
            }
            for k in range(1, 11) {
                ln = Text(str(k * 20), position=(X0 - 5.5, Y0 - k * 20), size=4, rotation=90)
            }
        }
    }
    RightOf(fence, base, gap=10 mm)
    AlignTop(fence, base)
    Place(fence, position=(0, 0, 6), face="up")

    solid carrier {
        thickness 3 mm
        plate = RoundedRectangle(center=(0, 0), width=LID, height=LID, corner_radii=[0, 5, 5, 5])
        hole notch {
            c = Circle(center=(LID / 2, 0), diameter=30)
        }
        drawing mark {
            t = Text("CORNER", position=(-LID / 2 + 6, LID / 2 - 8), size=4, anchor="start")
        }
    }
    Below(carrier, base, gap=10 mm)
    AlignLeft(carrier, base)
    Place(carrier, position=(X0 + LID / 2, Y0 - LID / 2, 6), face="up")

    assert base.body.bb.width == 230 mm and base.body.bb.height == 230 mm, "base 230 x 230"
    assert fence.top_arm.bb.height == 20 mm and fence.left_arm.bb.width == 20 mm, "arms 20 wide"
    assert base.body.bb.right - X0 == 210 mm and Y0 - base.body.bb.bottom == 210 mm,
        "210 x 210 inside the L"
    assert len(fence.pins.c) == 3, "three dowels"
    assert fence.pins.c[1].center.x == B / 2 - 20 mm, "20 mm from the right"
    assert base.grid.v[1].start.x - base.grid.v[0].start.x == 10 mm, "10 mm grid"
    assert len(fence.scale.tn) == 11, "0 to 200 along the top"
    assert fence.scale.tn[10].text == "200", "ends at 200"
    assert distance(fence.scale, fence.pins) >= 1 mm, "scale clear of the dowels"
    assert carrier.plate.bb.width == 200 mm and carrier.plate.bb.height == 200 mm, "200 x 200"
    assert carrier.notch.c.diameter == 30 mm, "30 mm notch"
    assert carrier.notch.c.center.x == carrier.plate.bb.right, "notch on the right edge"
}
