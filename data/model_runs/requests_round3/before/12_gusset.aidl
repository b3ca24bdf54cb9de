# A triangular gusset plate: base 60.325 mm, height 45.72 mm (apex above the left
# end of the base), a 6.35 mm hole at its centroid, 4.763 mm thick.

param base = 60.325 mm
param height = 45.72 mm
param hole_d = 6.35 mm

thickness 4.763 mm

solid gusset {
    tri = Triangle((0, 0), (base, 0), (0, height))
    Fixed(tri)
    hole h {
        c = Circle(center=(base / 3, height / 3), diameter=hole_d)
    }
    # the centroid is the mean of the three corners
    h.c.center.x == (tri.a.x + tri.b.x + tri.c.x) / 3
    h.c.center.y == (tri.a.y + tri.b.y + tri.c.y) / 3
}
