# Electronics: a base plate for a full-size (830-point) breadboard, 3 mm
# acrylic, 180 x 80 mm with 5 mm rounded corners. Four M3 holes (3.4 mm)
# countersunk 6.5 mm for flat-head screws, 5 mm in from each side at the
# corners. The breadboard's footprint 165 x 55 mm is engraved as a line,
# centred left-right, its bottom edge 15 mm above the plate's bottom edge.
# "BREADBOARD 830" engraved 3.5 mm high, centred, its baseline 6 mm above the
# plate's bottom edge.

thickness 3 mm
param plate_w = 180 mm, min = 170, max = 250
param plate_h = 80 mm, min = 70, max = 150

solid base {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=5)
    hole m3 {
        c = Circle(center=(0, 0), diameter=3.4)
    }
    screws = CornerPattern(m3, body, inset=5)
    Countersink(m3, diameter=6.5)
    drawing footprint {
        r = Rectangle(center=(0, -plate_h / 2 + 15 + 55 / 2), width=165, height=55)
    }
    drawing label {
        t = Text("BREADBOARD 830", (0, -plate_h / 2 + 6), size=3.5)
    }
    assert body.bb.width == 180 mm and body.bb.height == 80 mm, "plate 180 x 80"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - body.bb.left == 5 mm, "screws 5 in from the side"
    assert screws[0].c.center.y - body.bb.bottom == 5 mm, "screws 5 in from the bottom"
    assert footprint.r.bb.width == 165 mm and footprint.r.bb.height == 55 mm, "breadboard 165 x 55"
    assert footprint.r.bb.bottom - body.bb.bottom == 15 mm, "footprint 15 above the bottom"
    assert abs(footprint.r.bb.center_x - body.bb.center_x) < 0.01 mm, "footprint centred"
    assert label.t.position.y - body.bb.bottom == 6 mm, "label baseline 6 above the bottom"
}
