# Bottle-opener keychain: 70 x 26 mm rounded body (corner radius 13), a cap opening
# (16 mm circle plus a 6 x 12 mm lip notch) near one end, a 5 mm key-ring hole 6 mm
# from the other end.
solid keychain {
    body = RoundedRectangle(center=(0, 0), width=70, height=26, corner_radius=13)
    hole mouth {
        round = Circle(center=(-18, 0), diameter=16)
        lip = Rectangle(center=(-26, 0), width=6, height=12)
    }
    AlignCenterY(mouth, body)
    mouth.bb.left == body.bb.left + 5
    hole ring {
        c = Circle(center=(29, 0), diameter=5)
    }
    AlignCenterY(ring, body)
    HorizontalDistance(ring.c.center, body.right.midpoint, 6)
}
