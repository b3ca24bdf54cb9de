# Bird-feeder roof panel: 180 x 130 mm (the top edge is the ridge); an 8 mm hanging hole
# centred left-right, its centre 12 mm below the ridge; two slots 3.2 x 25 mm (for the
# gables' tabs) running up-down, 20 mm in from the left and right edges (slot centres),
# centred on the panel's height; 2 mm chamfers on the two bottom (eave) corners.
param w = 180 mm, min = 120 mm, max = 260 mm
param h = 130 mm, min = 90 mm, max = 200 mm
thickness 3 mm

solid roof {
    panel = Rectangle(center=(0, 0), width=w, height=h)
    hole hang { c = Circle(center=(0, 53), diameter=8) }
    At(hang.c.center, panel.top.midpoint, dy=-12)
    hole slot_l { s = Rectangle(center=(-70, 0), width=3.2, height=25) }
    hole slot_r { s = Rectangle(center=(70, 0), width=3.2, height=25) }
    At(slot_l.s.center, panel.left.midpoint, dx=20)
    At(slot_r.s.center, panel.right.midpoint, dx=-20)
    Chamfer([panel.bottom_left, panel.bottom_right], 2)
    assert panel.bb.top - hang.c.center.y == 12 mm, "12 mm below the ridge"
    assert hang.c.diameter == 8 mm, "8 mm hole"
}
