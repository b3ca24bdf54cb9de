# Heart-shaped keychain, 40 mm wide: a square turned 45 degrees with a
# circle on each upper side, a 5 mm key-ring hole in the left lobe,
# and the initials "A+B" engraved in the middle.

param width = 40 mm
param ring_d = 5 mm
param rim = 3 mm

s = width / (1 + sqrt(2) / 2)      # side of the turned square
h = s / (2 * sqrt(2))              # offset of each lobe's center

solid heart {
    point = Rectangle(center=(0, 0), width=s, height=s, rotation=45 deg)
    left_lobe = Circle(center=(-h, h), diameter=s)
    right_lobe = Circle(center=(h, h), diameter=s)
    Fixed(point)
    Concentric(left_lobe.center, (-h, h))

    hole ring {
        c = Circle(center=(-h, h + s / 2 - rim - ring_d / 2), diameter=ring_d)
    }
    Concentric(ring.c, left_lobe) 

    drawing initials {
        t = Text("A+B", position=(0, -1), size=7, valign="middle")
    }
    AlignCenterX(initials, point)
}
