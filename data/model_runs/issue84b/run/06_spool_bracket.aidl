# Spool bracket: a 60 x 110 mm upright plate with a round top (30 mm radius), an
# open U-slot at the top for an 8 mm axle (8.5 mm wide, 22 mm deep), and three
# 4.5 mm screw holes at the bottom: two 12 mm above the bottom edge 36 mm apart,
# one 30 mm above the bottom on the centre line.

solid bracket {
    body = Rectangle(center=(0, -15), width=60, height=80)
    top = Circle(center=(0, 25), radius=30)
    hole axle {
        s = Slot(start=(0, 55 - 22 + 4.25), end=(0, 60), width=8.5)
    }
    hole screws {
        a = Circle(center=(-18, -55 + 12), diameter=4.5)
        b = Circle(center=(18, -55 + 12), diameter=4.5)
        c = Circle(center=(0, -55 + 30), diameter=4.5)
    }
}
