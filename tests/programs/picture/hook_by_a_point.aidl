# A leaf pendant whose hanging loop (a ring) meets the leaf only at the tip of the
# leaf's stem: the loop's outer circle (radius 4) touches the stem's end at one point, so
# the cut part hangs by a point (issue 84).
solid pendant {
    leaf = Ellipse(center=(0, 0), rx=12, ry=20)
    stem = Polygon(points=[(-1, 19), (1, 19), (0, 26)])
    loop = Shell(Circle(center=(0, 30), radius=2.5), 1.5)
}
