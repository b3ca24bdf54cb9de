# Request (garden): a hawk silhouette to stick on a garden-room window so that small birds
# see it and do not fly into the glass. One piece of 3 mm black acrylic: a hawk seen from
# below in flight, wings spread 300 mm tip to tip, 138 mm from the top of the head to the
# end of the fanned tail, symmetric, the outline smooth except at the wing tips, the notches
# behind them, where the wings meet the tail and the tail's corners. Two 5 mm holes for
# suction cup studs, on the wings 45 mm either side of the centre line, 25 mm above the
# wing-tail line's... at y = 25 mm (the tail's end is at y = -63 mm).

thickness 3 mm

# the right half, head top to tail end, both on the centre line
half = [(0, 75), (7, 70), (10, 60), (14, 53), (40, 53), (85, 56), (125, 49), (150, 36),
        (140, 26), (122, 20), (95, 11), (60, 1), (24, -10), (15, -28), (26, -60), (0, -63)]
# sharp: wing tip 7, its notch 8, wing-tail join 12, tail corner 14, and their mirror images
# (point i's mirror is 30 - i)
sharp = [7, 8, 12, 14, 16, 18, 22, 23]

solid hawk {
    body = Spline(mirror(half, about="y"), closed=true, corners=sharp)
    hole studs {
        left = Circle(center=(-45, 25), diameter=5)
        right = Circle(center=(45, 25), diameter=5)
    }
    Fixed(body)

    # the request's numbers
    assert len(body.points) == 30, "a symmetric outline of 30 points"
    assert body.points[7].x - body.points[23].x == 300 mm, "wingspan 300 tip to tip"
    assert body.points[0].y - body.points[15].y == 138 mm, "head to tail 138"
    assert abs(body.points[7].x + body.points[23].x) < 0.01 mm, "symmetric"
    assert studs.right.center.x - studs.left.center.x == 90 mm, "studs 45 mm either side"
    assert studs.left.diameter == 5 mm, "5 mm stud holes"
    assert abs(body.bb.width - 300 mm) < 3 mm, "the spline does not bulge far past the tips"
}
