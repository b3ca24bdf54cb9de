# Issue 73 model run, e01: a stand's side whose slot (meant for a cross bar) runs through
# the 6 mm base strip and cuts the side in two.
solid side {
    base = Rectangle(bottom_left=(0, 0), width=80, height=6)
    back = Polygon([(10, 6), (20, 6), (45, 90), (38, 92)])
    hole slot { s = Rectangle(center=(60, 3), width=3, height=6) }
}
