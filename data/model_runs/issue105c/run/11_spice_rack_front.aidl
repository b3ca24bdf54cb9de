# Spice-rack front rail: 300 mm wide x 50 mm tall board whose top edge is scalloped:
# 6 semicircular bites 40 mm across, evenly spaced with the first centred 25 mm from
# the left end (pitch 50 mm); two 4 mm screw holes 12 mm above the bottom, 15 mm in.
solid front {
    body = Rectangle(bottom_left=(0, 0), width=300, height=50)
    hole bite {
        c = Circle(center=(25, 50), diameter=40)
    }
    bites = LinearPattern(bite, 6, (50, 0))
    Coincident(bite.c.center, body.top)
    HorizontalDistance(body.top_left, bite.c.center, 25)
    hole screw {
        c = Circle(center=(15, 12), diameter=4)
    }
    At(screw.c.center, body.bottom_left, dx=15, dy=12)
    hole screw2 {
        c = Circle(center=(285, 12), diameter=4)
    }
    At(screw2.c.center, body.bottom_right, dx=-15, dy=12)
}
