# Sundial gnomon for latitude 50 degrees: a right triangle with a 100 mm base,
# its sloping edge (the style) rising at 50 degrees from the base's left end to
# the top of a vertical back edge (100 * tan 50 = 119.2 mm tall); two tabs
# 15 mm wide and 3 mm deep below the base, their left edges 20 mm and 65 mm
# from the base's left end, to slot into a 3 mm dial plate.

param lat = 50 deg, min = 30 deg, max = 60 deg
param base = 100 mm, min = 60 mm, max = 150 mm

solid gnomon {
    blade = Polygon([(0, 0), (base, 0), (base, base * tan(lat))])
    tab1 = Rectangle(bottom_left=(20, -3), width=15, height=3)
    tab2 = Rectangle(bottom_left=(65, -3), width=15, height=3)
    At(tab1.top_left, blade.points[0], dx=20)
    At(tab2.top_left, blade.points[0], dx=65)

    assert abs(atan2(blade.points[2].y - blade.points[0].y, blade.points[2].x - blade.points[0].x) - 50 deg) < 0.001 deg, "style at 50 degrees"
    assert blade.bb.width == 100 mm, "100 mm base"
}
