# An L-shaped angle profile section: legs 40.000 mm and 25.400 mm long, each leg
# 0.340 mm thick; it will be extruded 12.7 mm.

param leg1 = 40.000 mm    # horizontal leg, outside length
param leg2 = 25.400 mm    # vertical leg, outside length
param wall = 0.6 mm     # asked 0.340 mm; widened for W0507 (walls under 0.5 mm cannot be cut)

thickness 12.7 mm

solid angle {
    section = Polygon([(0, 0), (leg1, 0), (leg1, wall), (wall, wall), (wall, leg2), (0, leg2)])
    Fixed(section)
}
