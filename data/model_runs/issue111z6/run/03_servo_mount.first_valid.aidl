# Electronics: a mounting plate for an SG90 micro servo, cut from 3 mm acrylic.
# Plate 60 x 40 mm, corners R4. A 23 x 12.6 mm cut-out for the servo body in the middle
# (its long side along the plate); two 2.2 mm holes for the servo's tab screws on the
# cut-out's centre line, 28 mm apart; four 3.4 mm mounting holes (M3) countersunk 6.5 mm,
# 5 mm in from each side at the corners; "SG90" engraved 4 mm high, centred 14 mm below
# the plate's centre.

thickness 3 mm

param body_w = 23 mm, min = 22 mm, max = 24 mm
param body_h = 12.6 mm, min = 12 mm, max = 13.5 mm

solid mount {
    plate = RoundedRectangle(center=(0, 0), width=60, height=40, corner_radius=4)
    Fixed(plate)

    hole servo {
        cut = Rectangle(center=(0, 0), width=body_w, height=body_h)
    }
    CenterInside(servo, plate)

    hole tab_screw {
        c = Circle(center=(-14, 0), diameter=2.2)
    }
    tab_screws = LinearPattern(tab_screw, 2, (28, 0))

    hole m3 {
        c = Circle(center=(-25, -15), diameter=3.4)
    }
    corners = CornerPattern(m3, plate, inset=5)
    Countersink(corners, diameter=6.5)

    drawing label {
        t = Text("SG90", position=(0, -14), size=4, valign="middle")
    }

    assert plate.width == 60 mm and plate.height == 40 mm, "plate 60 x 40"
    assert servo.cut.width == 23 mm and servo.cut.height == 12.6 mm, "cut-out 23 x 12.6"
    assert tab_screws[1].c.center.x - tab_screws[0].c.center.x == 28 mm, "tab screws 28 mm apart"
    assert tab_screws[0].c.center.y == servo.cut.center.y, "tab screws on the cut-out's centre line"
    assert len(corners) == 4, "four mounting holes"
    assert m3.c.center.x - plate.bb.left == 5 mm and m3.c.center.y - plate.bb.bottom == 5 mm, "5 mm in"
    assert corners[2].c.center.x == plate.bb.right - 5 mm, "top-right 5 mm in"
    assert plate.center.y - label.t.position.y == 14 mm, "label 14 mm below the centre"
}
