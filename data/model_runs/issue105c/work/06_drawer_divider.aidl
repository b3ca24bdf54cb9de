# Drawer divider: 300 x 60 mm board with two finger slots 40 x 18 mm (rounded ends)
# centred 15 mm below the top edge, 80 mm either side of the middle.
solid divider {
    body = Rectangle(center=(0, 0), width=300, height=60)
    hole slot_l {
        s = Slot(center=(-80, 15), length=40, width=18)
    }
    hole slot_r {
        s = Slot(center=(80, 15), length=40, width=18)
    }
    At(slot_l.s.center, body.top.midpoint, dx=-80, dy=-15)
    At(slot_r.s.center, body.top.midpoint, dx=80, dy=-15)
}
