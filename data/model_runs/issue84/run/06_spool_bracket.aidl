# A wall bracket for a filament spool: a 50 mm wide, 120 mm tall upright plate,
# round at the top, with a 25 mm axle hole 25 mm below the top, and two 4.5 mm
# screw holes 15 mm and 45 mm above the bottom edge, on the centre line.
param w = 50 mm
param h = 120 mm

solid bracket {
    stem = Rectangle(bottom_left=(-w / 2, 0), width=w, height=h - w / 2)
    cap = Circle(center=(0, h - w / 2), radius=w / 2)
    hole axle { c = Circle(center=(0, h - 25), diameter=25) }
    hole screw_low { c = Circle(center=(0, 15), diameter=4.5) }
    hole screw_high { c = Circle(center=(0, 45), diameter=4.5) }
}
