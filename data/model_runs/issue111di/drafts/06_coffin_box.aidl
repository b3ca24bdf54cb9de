# Request (holidays): a Halloween coffin box for the kids' trick-or-treat sweets, glued up
# from stacked layers of 6 mm ply. The coffin outline: 150 mm long, 80 wide at the
# shoulders (40 mm from the head end), 50 wide at the head end and 40 at the foot. A solid
# base, three rings with 8 mm walls (a box 24 mm deep), and a lid: the outline grown 2 mm
# all round (round corners, an overhang to lift it by) with a lip under it, the opening's
# shape less 0.3 mm all round, that drops 6 mm into the top ring. On the lid, engraved
# filled: a cross (bar 7 wide, 45 tall, cross bar 26 wide, its middle 15 mm below the
# cross's top), R.I.P. in bold sans 12 mm tall under it, and HAPPY HALLOWEEN in small bold
# letters near the foot (no wider than 44 mm).

thickness 6 mm

pts = [(-25, 75), (25, 75), (40, 35), (20, -75), (-20, -75), (-40, 35)]

def coffin_layer(kind="ring") -> solid {
    if kind == "lip" {
        o = Polygon(pts, construction=true)
        body = Inset(o, 8.3)
    } else {
        body = Polygon(pts)
    }
    if kind == "ring" {
        hole opening {
            o = Polygon(pts, construction=true)
            i = Inset(o, 8)
        }
    }
}

assembly coffin_box {
    base = coffin_layer(kind="base")
    for i in range(3) {
        ring = coffin_layer(kind="ring")
    }
    lip = coffin_layer(kind="lip")

    solid lid {
        o = Polygon(pts, construction=true)
        body = Offset(o, 2)
        drawing art {
            upright = Rectangle(center=(0, 55 - 22.5), width=7, height=45, fill=true)
            bar = Rectangle(center=(0, 55 - 15), width=26, height=7, fill=true)
            rip = Text("R.I.P.", position=(0, -8), size=12, font="sans:Bold", fill=true)
            greet = Text("HAPPY HALLOWEEN", position=(0, -45), size=6, font="sans:Bold",
                         fill=true, max_width=44)
        }
        assert art.upright.bb.top - art.bar.bb.center_y == 15 mm, "cross bar 15 below the top"
        assert art.rip.bb.top < art.upright.bb.bottom, "R.I.P. under the cross"
        assert art.greet.bb.width <= 44 mm, "greeting at most 44 wide"
    }

    # laid out in a row for cutting
    RightOf(ring[0], base, gap=8)
    for i in range(1, 3) {
        RightOf(ring[i], ring[i - 1], gap=8)
    }
    RightOf(lip, ring[2], gap=8)
    RightOf(lid, lip, gap=8)
    for i in range(3) {
        AlignCenterY(ring[i], base)
    }
    AlignCenterY(lip, base)
    AlignCenterY(lid, base)

    # 3D: stacked
    Place(base, position=(0, 0, 0), face="up")
    for i in range(3) {
        Place(ring[i], position=(0, 0, 6 + 6 * i), face="up")
    }
    Place(lip, position=(0, 0, 18), face="up")
    Place(lid, position=(0, 0, 24), face="up")

    assert base.body.bb.height == 150 mm, "150 long"
    assert base.body.bb.width == 80 mm, "80 at the shoulders"
    assert len(ring) == 3, "three rings"
    assert lid.body.bb.width - base.body.bb.width == 4 mm, "lid 2 mm over all round"
}
