# Towel-bar end plate, 6 mm plywood: a 70 mm disc with a 25.4 mm (1 in) hole for the bar
# in its center; two 4 mm screw holes 50 mm apart on the vertical center line, countersunk
# for 8.5 mm flat heads (90 degrees).

thickness 6 mm

solid end_plate {
    disc = Circle(center=(0, 0), diameter=70)
    hole bar {
        c = Circle(center=(0, 0), diameter=1 in)
    }
    hole screw {
        c = Circle(center=(0, 25), diameter=4)
    }
    Coincident(screw.c.center, polar(disc.center, 25, 90 deg))
    lower = Mirrored(screw, Line((-40, 0), (40, 0), construction=true))
    Countersink([screw, lower], diameter=8.5)
    assert distance(screw.c.center, lower.c.center) == 50 mm, "screws 50 mm apart"
    assert bar.c.diameter == 25.4 mm, "1 in bar hole"
    assert disc.diameter == 70 mm, "70 mm plate"
}
