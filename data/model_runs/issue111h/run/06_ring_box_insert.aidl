# Ring box insert (a wedding gift): a 60 x 60 mm square of 3 mm ply with 4 mm rounded
# corners that drops into a small box. Two straight slits (single laser cuts) 22 mm long,
# vertical, 12 mm apart, centred on the insert, hold two rings. A half-round finger notch
# of 8 mm radius centred on the bottom edge to lift the insert out. "M & J" engraved
# 5 mm high, centred, its baseline 10 mm below the top edge.

units mm
thickness 3 mm

param slit = 22 mm, min = 15 mm, max = 30 mm
param apart = 12 mm, min = 8 mm, max = 20 mm

solid insert {
    plate = RoundedRectangle(center=(0, 0), width=60, height=60, corner_radius=4)

    cut slits {
        left = Line((-apart / 2, -slit / 2), (-apart / 2, slit / 2))
        right = Line((apart / 2, -slit / 2), (apart / 2, slit / 2))
    }
    CenterInside(slits, plate)

    hole notch { c = Circle(center=(0, -30), radius=8) }
    Concentric(notch.c, plate.bottom.midpoint)

    drawing initials {
        word = Text("M & J", position=(0, 20), size=5)
    }
    AlignCenterX(initials, plate)
    initials.word.position.y == plate.bb.top - 10

    assert plate.bb.width == 60 mm and plate.bb.height == 60 mm, "60 x 60 insert"
    assert slits.left.length == 22 mm, "22 mm slits"
    assert slits.right.length == 22 mm, "22 mm slits"
    assert slits.right.start.x - slits.left.start.x == 12 mm, "12 mm apart"
    assert abs(slits.left.dx) < 0.001 mm, "vertical"
    assert abs(slits.bb.center_x - plate.center.x) < 0.001 mm, "slits centred across"
    assert abs(slits.bb.center_y - plate.center.y) < 0.001 mm, "slits centred up and down"
    assert notch.c.radius == 8 mm, "8 mm notch"
    assert notch.c.center.y == plate.bb.bottom, "notch on the bottom edge"
    assert plate.bb.top - initials.word.position.y == 10 mm, "baseline 10 mm below the top"
    assert initials.word.size == 5 mm, "5 mm text"
    assert initials.bb.bottom > slits.bb.top, "text clear of the slits"
}
