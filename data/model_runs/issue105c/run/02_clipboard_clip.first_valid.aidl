# Clipboard clip plate: 100 mm wide x 40 mm tall, corners radius 5, a 30 x 12 mm
# finger slot centred 12 mm below the top edge, two 4 mm rivet holes 10 mm above the
# bottom edge and 20 mm in from each side.
solid clip {
    body = RoundedRectangle(center=(0, 0), width=100, height=40, corner_radius=5)
    hole finger {
        s = Slot(center=(0, 8), length=30, width=12)
    }
    AlignCenterX(finger, body)
    VerticalDistance(finger.s.center, body.top.midpoint, 12)
    hole rivet {
        c = Circle(center=(-30, -10), diameter=4)
    }
    At(rivet.c.center, body.bottom_left, dx=20, dy=10)
    hole rivet2 {
        c = Circle(center=(30, -10), diameter=4)
    }
    At(rivet2.c.center, body.bottom_right, dx=-20, dy=10)
}
