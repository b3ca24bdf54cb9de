# Request: a two-tone percussion wood block glued up from five layers of 6 mm birch ply
# (30 mm thick). Body 160 x 50 mm. Inside, two sound chambers 30 mm wide: the low one
# 70 mm long, 7 mm in from the left end; the high one 50 mm long, ending 18 mm from the
# right end. The middle layer opens each chamber to the outside through a slit: the low
# one 60 mm long on the back side, the high one 40 mm long on the front side. The three
# inner layers carry a handle 26 mm wide reaching 110 mm out of the left end, with a 6 mm
# lanyard hole 13 mm from its end. Two 6 mm alignment dowels (in the wall between the
# chambers and in the right end) run through all layers but the top. On the top layer
# "LOW" and "HIGH" engraved filled, 10 mm high, over their chambers.

thickness 6 mm

ply = 6 mm
low_x = -80 mm + 7 mm + 35 mm     # the low chamber's centre
high_x = 80 mm - 18 mm - 25 mm    # the high chamber's centre

def layer(kind="mid") -> solid {
    body = Rectangle(center=(0, 0), width=160, height=50)
    if kind != "top" and kind != "bottom" {
        handle = Slot(start=(-80 mm, 0), end=(-177 mm, 0), width=26)
        hole lanyard { c = Circle(center=(-177 mm, 0), diameter=6) }
        hole low {
            chamber = Rectangle(center=(low_x, 0), width=70, height=30)
            if kind == "slit" {
                slit = Rectangle(corner=(low_x - 30 mm, 14 mm), opposite=(low_x + 30 mm, 26 mm),
                                 overrun=true)
            }
        }
        hole high {
            chamber = Rectangle(center=(high_x, 0), width=50, height=30)
            if kind == "slit" {
                slit = Rectangle(corner=(high_x - 20 mm, -26 mm), opposite=(high_x + 20 mm, -14 mm),
                                 overrun=true)
            }
        }
    }
    if kind != "top" {
        hole dowels {
            a = Circle(center=(4.5 mm, 0), diameter=6)
            b = Circle(center=(71 mm, 0), diameter=6)
        }
    } else {
        drawing words {
            lo = Text("LOW", position=(low_x, 0), size=10, font="sans:Bold", valign="middle", fill=true)
            hi = Text("HIGH", position=(high_x, 0), size=10, font="sans:Bold", valign="middle", fill=true)
        }
    }
}

assembly wood_block {
    for k in range(5) {
        ply_layer = layer(kind=["bottom", "mid", "slit", "mid", "top"][k])
        Place(ply_layer, position=(0, 0, k * ply))
    }
    for k in range(1, 5) {
        Above(ply_layer[k], ply_layer[k - 1], gap=5)
        AlignRight(ply_layer[k], ply_layer[k - 1])
    }

    assert len(ply_layer) == 5
    assert ply_layer[0].body.width == 160 mm and ply_layer[0].body.height == 50 mm
    assert ply_layer[1].low.chamber.width == 70 mm and ply_layer[1].high.chamber.width == 50 mm
    assert ply_layer[1].low.chamber.height == 30 mm
    assert ply_layer[1].low.chamber.bb.left - ply_layer[1].body.bb.left == 7 mm
    assert ply_layer[1].body.bb.right - ply_layer[1].high.chamber.bb.right == 18 mm
    assert ply_layer[2].low.slit.width == 60 mm and ply_layer[2].high.slit.width == 40 mm
    assert ply_layer[2].body.bb.left - ply_layer[2].handle.bb.left == 110 mm
    assert ply_layer[2].handle.width == 26 mm
    assert ply_layer[2].lanyard.c.center.x - ply_layer[2].handle.bb.left == 13 mm
    assert ply_layer[4].words.lo.size == 10 mm
}
