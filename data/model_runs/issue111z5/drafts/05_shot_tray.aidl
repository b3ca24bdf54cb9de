# Parties: a shot-glass serving tray of two glued 6 mm plywood layers. Both layers 320 x 120 mm
# with R10 corners and a hand slot 70 x 22 mm (vertical) at each end, its centre 20 mm from
# that end. The top layer has 10 glass holes 40 mm across in 2 rows of 5, 48 mm apart along a
# row and 60 mm between rows, centred on the tray, and "CHEERS" in sans Bold 8 mm tall engraved
# filled on the middle line between the rows. The bottom layer is plain.
thickness 6 mm

def blank() -> solid {
    plate = RoundedRectangle(center=(0, 0), width=320, height=120, corner_radius=10)
    hole hands {
        left = Slot(center=(-160 + 20, 0), length=70, width=22, rotation=90)
        right = Slot(center=(160 - 20, 0), length=70, width=22, rotation=90)
    }
}

assembly tray {
    top = blank()
    bottom = blank()
    Below(bottom, top, gap=10)
    AlignCenterX(bottom, top)

    hole glass {
        c = Circle(center=(-2 * 48, -30), diameter=40)
    }
    glasses = GridPattern(glass, 2, 5, (48, 60))
    CutInto(glass, top)
    # attempt 1: Below(bottom, top) moved the top 65 mm up too, off the literal holes: place the
    # holes and the text on the top layer by constraints
    At(glass.c.center, top.plate.center, dx=-2 * 48, dy=-30)

    drawing cheers {
        t = Text("CHEERS", position=(0, 0), size=8, font="sans:Bold", valign="middle", fill=true)
    }
    CutInto(cheers, top)
    At(cheers.t.position, top.plate.center)

    assert top.plate.bb.width == 320 mm and top.plate.bb.height == 120 mm, "320 x 120"
    assert bottom.plate.bb.width == 320 mm, "bottom the same"
    assert top.hands.left.length == 70 mm and top.hands.left.width == 22 mm, "hand slots 70 x 22"
    assert top.hands.left.center.x - top.plate.bb.left == 20 mm, "hand slot 20 from the end"
    assert len(glasses) == 10, "10 glasses"
    assert glass.c.diameter == 40 mm, "holes 40 across"
    assert glasses[1].c.center.x - glasses[0].c.center.x == 48 mm, "48 along a row"
    assert glasses[5].c.center.y - glasses[0].c.center.y == 60 mm, "60 between rows"
    assert (glasses[0].c.center.x + glasses[9].c.center.x) / 2 == top.plate.center.x, "centred across"
    assert (glasses[0].c.center.y + glasses[9].c.center.y) / 2 == top.plate.center.y, "centred up and down"
}
