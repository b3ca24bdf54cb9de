# Heart-shaped keychain, 40 mm wide, with a 5 mm key-ring hole and "A+B" engraved.
# The heart is a diamond (square turned 45 deg) with a round lobe on each upper edge.

param width = 40 mm
param ring_d = 5 mm

d = width / (1 + sqrt(2))      # center to tip of the diamond
r = d / sqrt(2)                # lobe radius = half the square's side

solid heart {
    diamond = Polygon([(0, -d), (d, 0), (0, d), (-d, 0)])
    left_lobe = Circle(center=(-d / 2, d / 2), radius=r)
    right_lobe = Circle(center=(d / 2, d / 2), radius=r)

    hole ring {
        eye = Circle(center=(-d / 2, d / 2 + r - 5), diameter=ring_d)
    }

    drawing initials {
        t = Text("A+B", position=(0, -1), size=7, valign="middle")
    }

    Fixed(diamond)
    # each lobe sits on the middle of an upper edge of the diamond
    Midpoint(left_lobe.center, diamond.edges[2])
    Midpoint(right_lobe.center, diamond.edges[1])
    # the ring hole sits in the left lobe, 2.5 mm of material above it
    AlignCenterX(ring, left_lobe)
    ring.eye.center.y == left_lobe.top.y - ring_d / 2 - 2.5 mm
    AlignCenterX(initials, diamond)
}
