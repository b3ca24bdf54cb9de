# A triangular gusset plate: base 60.325 mm, height 45.72 mm (apex above the left
# end of the base), a 6.35 mm hole at its centroid, 4.763 mm thick.
thickness 4.763 mm

solid gusset {
    tri = Triangle((0, 0), (60.325, 0), (0, 45.72))
    hole h { c = Circle(center=(20, 15), diameter=6.35) }
    Coincident(h.c.center, tri.centroid)
}
