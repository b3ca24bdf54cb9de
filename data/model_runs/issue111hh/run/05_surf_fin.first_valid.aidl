# Request (sport): a 9-inch single fin for my longboard's US fin box, laser-cut from 10 mm
# G10 as a blank that I then foil by hand.
# - The fin: 120 mm along its base, 228 mm deep from the base to the tip, raked back so the
#   tip sits 150 mm behind the base's front end; a smoothly curved leading edge, a rounded
#   tip and a trailing edge with a concave release, sharp corners only at the two base ends.
# - Under the base a tab 112 mm long and 10 mm tall, centred under the base, that slides
#   into the box: a 4.8 mm pin hole 8 mm in from the tab's rear end and 5 mm below the base,
#   and at the front a notch 8 mm long and 5 mm tall in the tab's lower front corner for the
#   box's screw plate.
# - "9.0 PIVOT" engraved filled in 8 mm bold letters on the fin, 40 mm above the base.

thickness 10 mm

depth = 228 mm
k = depth / 200       # the outline's points are written for a 200 mm fin

solid fin {
    outline = Spline([(0, 0), (25, 70 * k), (65, 135 * k), (115, 180 * k), (150, 200 * k),
                      (160, 196 * k), (140, 165 * k), (118, 120 * k), (108, 70 * k),
                      (110, 30 * k), (120, 0)], closed=true, corners=[0, 10])
    tab = Rectangle(bottom_left=(4, -10), width=112, height=12)

    hole pin {
        c = Circle(center=(116 - 8, -5), diameter=4.8)
    }
    hole plate_notch {
        n = Rectangle(bottom_left=(3, -11), width=9, height=6)
    }

    drawing label {
        t = Text("9.0 PIVOT", position=(62, 40), size=8, font="sans:Bold", fill=true)
    }

    assert outline.points[10].x - outline.points[0].x == 120 mm, "120 mm base"
    assert outline.points[4].y - outline.points[0].y == 228 mm, "228 mm deep"
    assert outline.points[4].x - outline.points[0].x == 150 mm, "tip 150 mm behind"
    assert tab.width == 112 mm and tab.bb.bottom == outline.points[0].y - 10 mm
    assert tab.bb.center_x == (outline.points[0].x + outline.points[10].x) / 2
    assert tab.bb.right - pin.c.center.x == 8 mm and outline.points[0].y - pin.c.center.y == 5 mm
    assert plate_notch.n.bb.top == tab.bb.bottom + 5 mm
    assert plate_notch.n.bb.right == tab.bb.left + 8 mm
    assert label.t.position.y - outline.points[0].y == 40 mm
}
