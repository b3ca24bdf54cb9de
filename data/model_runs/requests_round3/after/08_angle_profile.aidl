# An L-shaped angle profile section: legs 40.000 and 25.400 mm long, each leg
# 0.340 mm thick; extruded 12.7 mm.
param t = 0.340 mm

thickness 12.7 mm
min_wall 0.3 mm

solid angle {
    l = Polygon([(0, 0), (40.000, 0), (40.000, t), (t, t), (t, 25.400), (0, 25.400)])
}
