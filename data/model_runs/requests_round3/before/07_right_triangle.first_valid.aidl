# A right-triangle plate with legs of 95.149 mm and 15.482 mm, 3.175 mm thick.

param a = 95.149 mm   # horizontal leg
param b = 15.482 mm   # vertical leg

thickness 3.175 mm

solid plate {
    tri = Triangle((0, 0), (a, 0), (0, b))
    Fixed(tri)
}
