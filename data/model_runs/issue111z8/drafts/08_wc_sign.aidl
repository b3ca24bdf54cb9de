# Signs: a backlit toilet door sign, 3 mm white acrylic. Plate 160 x 80 mm with
# 8 mm corner radius. "WC" in bold sans letters 36 mm tall (cap height) cut
# right through the plate (the light shines through), the capitals' middle 8 mm
# above the plate's centre, centred left to right. "TOILETS" engraved
# (single-stroke) 7 mm tall, its baseline 10 mm above the bottom edge. Two 4 mm
# screw holes countersunk for 8 mm heads, 14 mm in from the left and right
# edges, at the plate's mid-height.

units mm
thickness 3 mm

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=160, height=80, corner_radius=8)
    Fixed(plate)

    hole letters {
        word = Text("WC", position=(0, 8), size=36, font="sans:Bold", valign="middle")
    }
    drawing label {
        t = Text("TOILETS", position=(0, -40 + 10), size=7)
    }
    hole left_screw {
        c = Circle(center=(-80 + 14, 0), diameter=4)
    }
    right_screw = Mirrored(left_screw, about=Line((0, -40), (0, 40), construction=true))
    Countersink([left_screw, right_screw], diameter=8)

    assert plate.width == 160 mm and plate.height == 80 mm, "plate 160 x 80"
    assert letters.word.size == 36 mm, "letters 36 tall"
    assert letters.word.position.y - plate.center.y == 8 mm, "letters' middle 8 above the centre"
    assert letters.word.position.x == plate.center.x, "letters centred"
    assert label.t.position.y - plate.bb.bottom == 10 mm, "label 10 above the bottom"
    assert left_screw.c.center.x - plate.bb.left == 14 mm, "left screw 14 in"
    assert plate.bb.right - right_screw.c.center.x == 14 mm, "right screw 14 in"
    assert left_screw.c.center.y == plate.center.y, "screws at mid-height"
}
