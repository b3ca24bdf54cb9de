# Bathroom toothpaste squeezer: a 70 x 35 mm plate, 4 mm corner radii, 3 mm acrylic;
# a 55 x 3 mm slot (round ends) for the tube, centred, 10 mm below the top edge; a 10 mm
# hanging hole centred 9 mm above the bottom edge; "SQUEEZE" engraved 5 mm tall, centred
# between the slot and the hanging hole.

thickness 3 mm

solid squeezer {
    plate = RoundedRectangle(center=(0, 0), width=70, height=35, corner_radius=4)

    hole tube {
        s = Slot(center=(0, 7.5), length=55, width=3)
    }
    AlignCenterX(tube, plate)
    tube.s.center.y == plate.bb.top - 10

    hole hang {
        c = Circle(center=(0, -8.5), diameter=10)
    }
    AlignCenterX(hang, plate)
    hang.c.center.y == plate.bb.bottom + 9

    drawing label {
        word = Text("SQUEEZE", (0, 0), size=5, valign="middle")
    }
    AlignCenterX(label, plate)
    label.word.position.y == (tube.bb.bottom + hang.bb.top) / 2

    assert plate.width == 70 mm and plate.height == 35 mm, "70 x 35"
    assert tube.s.length == 55 mm and tube.s.width == 3 mm, "55 x 3 slot"
    assert plate.bb.top - tube.s.center.y == 10 mm, "slot 10 below the top"
    assert tube.s.center.x == plate.center.x, "slot centred"
    assert hang.c.diameter == 10 mm, "10 mm hole"
    assert hang.c.center.y - plate.bb.bottom == 9 mm, "hole 9 above the bottom"
    assert label.word.size == 5 mm, "5 mm text"
    assert label.bb.right < plate.bb.right and label.bb.left > plate.bb.left, "text on the plate"
    assert label.bb.top < tube.bb.bottom and label.bb.bottom > hang.bb.top, "text between slot and hole"
}
