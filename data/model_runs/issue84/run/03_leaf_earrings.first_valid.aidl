# A pair of leaf earrings: each leaf 40 mm long and 20 mm wide, pointed at both
# ends, a 1.5 mm hole 3 mm from the top tip for the hook, an engraved midrib
# and four side veins. Two separate pieces.

def leaf() -> solid {
    blade = Spline([(0, -20), (10, -4), (0, 20), (-10, -4)], closed=true, corners=[0, 2])
    hole hook { c = Circle(center=(0, 15.5), diameter=1.5) }
    drawing veins {
        rib = Line((0, -17), (0, 13))
        for i in range(2) {
            r = Line((0, -8 + i * 8), (6, -3 + i * 8))
            l = Line((0, -8 + i * 8), (-6, -3 + i * 8))
        }
    }
}

assembly earrings {
    left = leaf()
    right = leaf()
    left.bb.center == (-15, 0)
    right.bb.center == (15, 0)
}
