# Leaf earrings: a pair of round-bellied leaves 48 mm long and 24 mm wide (a
# pointed tip at the bottom, a 4 mm stem at the top), a 1.5 mm hook hole in the
# stem, an engraved midrib and three pairs of side veins. Cut from 3 mm wood.

def leaf(x=0 mm) -> solid {
    blade = Spline([(x, -24), (x + 9, -12), (x + 12, 2), (x + 8, 16), (x, 22),
                    (x - 8, 16), (x - 12, 2), (x - 9, -12)], closed=true, corners=[0])
    stem = Rectangle(center=(x, 24), width=4, height=6)
    hole hook { c = Circle(center=(x, 25), diameter=1.5) }
    drawing veins {
        rib = Line((x, -20), (x, 19))
        for k in range(3) {
            l = Line((x, -12 + k * 9), (x - 7, -6 + k * 9))
            r = Line((x, -12 + k * 9), (x + 7, -6 + k * 9))
        }
    }
}

assembly pair {
    left = leaf(x=-16)
    right = leaf(x=16)
}
