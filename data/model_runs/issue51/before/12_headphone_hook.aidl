# Headphone hook that screws under a desk: a J-shaped profile about 60 x 90 mm,
# with two 4 mm countersunk screw holes in its flat top flange.
# (The countersink itself is made by hand: its 8 mm rim is engraved around each hole.)

param bar = 12 mm         # width of the J's bar
param flange_h = 14 mm
param cup_r = 24 mm       # center-line radius of the J's bend
param screw_d = 4 mm
param sink_d = 8 mm

solid hook {
    flange = RoundedRectangle(bottom_left=(0, 76), width=60, height=flange_h, corner_radius=3)
    stem = Rectangle(bottom_left=(0, 30), width=bar, height=47)
    cup = ArcSlot(center=(30, 30), radius=cup_r, start_angle=180 deg, end_angle=360 deg, width=bar)
    lip = Slot(start=(54, 30), end=(54, 40), width=bar)

    # the stem hangs from the flange's left end, the bend starts at the stem's foot
    AlignLeft(stem, flange)
    stem.bb.top == flange.bb.bottom + 1 mm
    Coincident(cup.start, stem.bottom.midpoint)
    Coincident(lip.start, cup.end)
    Vertical(lip.start, lip.end)

    hole screws {
        s1 = Circle(center=(22, 83), diameter=screw_d)
        s2 = Circle(center=(48, 83), diameter=screw_d)
    }
    drawing countersinks {
        k1 = Circle(center=(22, 83), diameter=sink_d)
        k2 = Circle(center=(48, 83), diameter=sink_d)
    }
    Concentric(countersinks.k1, screws.s1)
    Concentric(countersinks.k2, screws.s2)
    AlignCenterY(screws, flange)
    # screws spread over the flange, clear of the stem
    HorizontalDistance(stem.right.midpoint, screws.s1.center, 10 mm)
    HorizontalDistance(screws.s2.center, flange.right.midpoint, 12 mm)

    Fixed(flange)
    Fillet(2 mm)
}
