# Electronics: front bezel for a 4-digit 7-segment clock module, 3 mm black acrylic. Plate
# 100 x 50 mm, corners R4. Display window 51 x 19.5 mm (sharp corners), centred left-right,
# its centre 6 mm above the plate's centre. Four 2.7 mm holes (M2.5) 5 mm in from each side at
# the corners. Two 7 mm push-button holes 15 mm below the plate's centre, 20 mm either side of
# the centre line, each labelled to its right ("SET" left, "MODE" right, 3 mm engraved text).

thickness 3 mm

param btn_d = 7 mm, min = 6 mm, max = 12 mm

solid bezel {
    plate = RoundedRectangle(center=(0, 0), width=100, height=50, corner_radius=4)

    hole window {
        w = Rectangle(center=(0, 6), width=51, height=19.5)
    }

    hole screw {
        c = Circle(center=(-45, -20), diameter=2.7)
    }
    screws = CornerPattern(screw, plate, inset=5)

    hole buttons {
        set = Circle(center=(-20, -15), diameter=btn_d)
        mode = Circle(center=(20, -15), diameter=btn_d)
    }

    drawing labels {
        a = Text("SET", (-20 + btn_d / 2 + 2, -15), size=3, anchor="start", valign="middle")
        b = Text("MODE", (20 + btn_d / 2 + 2, -15), size=3, anchor="start", valign="middle")
    }

    assert plate.bb.width == 100 mm and plate.bb.height == 50 mm, "plate 100 x 50"
    assert window.bb.width == 51 mm and window.bb.height == 19.5 mm, "window 51 x 19.5"
    assert window.bb.center_y - plate.bb.center_y == 6 mm, "window 6 mm above centre"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - plate.bb.left == 5 mm, "screws 5 in"
    assert screws[0].c.center.y - plate.bb.bottom == 5 mm, "screws 5 up"
    assert buttons.mode.center.x - buttons.set.center.x == 40 mm, "buttons 20 either side"
    assert plate.bb.center_y - buttons.set.center.y == 15 mm, "buttons 15 below"
    assert labels.bb.right <= plate.bb.right - 3 mm, "MODE label on the plate"
}
