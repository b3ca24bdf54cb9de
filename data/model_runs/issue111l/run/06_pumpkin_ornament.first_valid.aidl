# Holidays: Halloween pumpkin window decoration, 3 mm orange acrylic: an elliptical pumpkin
# 120 mm wide and 100 mm tall; a stem 14 mm wide rising 15 mm above the pumpkin's top,
# with R3 top corners and a 4 mm hanging hole 7 mm below its top; two triangular eyes
# (24 mm base, 18 mm tall, pointing up) centred 22 mm either side of the middle, their
# centres 15 mm above the pumpkin's centre; a triangular nose (14 mm base, 12 mm tall) at
# the centre; a smile: an 8 mm wide arc slot on radius 38 mm about a point 5 mm above the
# centre, from 215 to 325 degrees; five engraved ribs (arcs) are not wanted: plain face.

thickness 3 mm

solid pumpkin {
    body = Ellipse(center=(0, 0), rx=60, ry=50)
    stem = RoundedRectangle(center=(0, 52.5), width=14, height=25, corner_radii=[3, 3, 0, 0])
    AlignCenterX(stem, body)
    stem.bb.top == body.bb.top + 15

    hole hang { c = Circle(center=(0, 58), diameter=4) }
    AlignCenterX(hang, stem)
    hang.c.center.y == stem.bb.top - 7

    hole left_eye { t = Triangle(center=(-22, 15), base=24, height=18) }
    hole right_eye { t = Triangle(center=(22, 15), base=24, height=18) }
    left_eye.t.center == body.center + (-22, 15)
    right_eye.t.center == body.center + (22, 15)

    hole nose { t = Triangle(center=(0, 0), base=14, height=12) }
    nose.t.center == body.center

    hole smile { s = ArcSlot(center=(0, 5), radius=38, start_angle=215, end_angle=325, width=8) }
    smile.s.center == body.center + (0, 5)

    assert body.bb.width == 120 mm and body.bb.height == 100 mm, "120 x 100 pumpkin"
    assert stem.bb.width == 14 mm, "14 mm stem"
    assert stem.bb.top - body.bb.top == 15 mm, "stem 15 above"
    assert hang.c.diameter == 4 mm and stem.bb.top - hang.c.center.y == 7 mm, "4 mm hole 7 down"
    assert right_eye.t.center.x - body.center.x == 22 mm, "eyes 22 either side"
    assert left_eye.t.center.y - body.center.y == 15 mm, "eyes 15 up"
    assert left_eye.bb.width == 24 mm and left_eye.bb.height == 18 mm, "eye 24 x 18"
    assert nose.bb.width == 14 mm and nose.bb.height == 12 mm, "nose 14 x 12"
    assert smile.s.radius == 38 mm and smile.s.width == 8 mm, "smile R38, 8 wide"
    assert smile.bb.bottom > body.bb.bottom + 3 mm, "smile inside the pumpkin"
    assert smile.bb.top < nose.bb.bottom, "nose above the smile"
}
