# A right-triangle plate with legs of 95.149 mm and 15.482 mm, 3.175 mm thick.

param a = 95.149 mm   # horizontal leg
param b = 15.482 mm   # vertical leg

thickness 3.175 mm

solid plate {
    tri = Triangle((0, 0), (a, 0), (0, b))
    Fixed(tri)
    # the 9 deg tip is too thin to cut: round it 0.5 mm across
    Fillet(tri.b, 0.25 mm)
}
