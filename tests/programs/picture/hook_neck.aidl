# A leaf pendant whose hanging loop overlaps the stem's tapered tip by a hair:
# the two members join over a neck 0.2 mm wide (issue 84).
solid pendant {
    leaf = Ellipse(center=(0, 0), rx=12, ry=20)
    stem = Polygon(points=[(-1, 19), (1, 19), (0, 26)])
    loop = Shell(Circle(center=(0, 29.9), radius=2.5), 1.5)
}
