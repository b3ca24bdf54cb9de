# A violin top plate: the outline written once for the right half and mirrored,
# a closed Spline with four pointed corners (Spline corners=), two S-shaped
# f-holes cut by Stroke along two tangent arcs, and an end-pin hole.
# Try: --set f_width=4

param f_width = 3 mm  # the width of the f-holes' stem

# the right half, bottom to top; mirror() adds the left half
half = [(0, -178), (50, -172), (88, -152), (104, -112), (100, -74), (92, -50),
        (82, -30),  # lower corner
        (66, -24), (57, -8), (56, 10), (62, 26),
        (78, 36),  # upper corner
        (82, 56), (84, 86), (76, 124), (52, 158), (0, 176)]
n = len(half)
lower = 6
upper = 11

# an S of two tangent arcs from (0, 36) down to (0, -36) about x = 0
bend = 30 mm  # the arcs' centres are this far to the side
rise = 18 mm
r_s = sqrt(bend ** 2 + rise ** 2)
t = atan2(rise, bend)

def f_hole(x=0 mm, mirror_sign=1) -> hole {
    upper_arc = Arc(center=(x + mirror_sign * bend, rise), radius=r_s,
                    start_angle=(180 deg - t if mirror_sign > 0 else -t),
                    end_angle=(180 deg + t if mirror_sign > 0 else t))
    lower_arc = Arc(center=(x - mirror_sign * bend, -rise), radius=r_s,
                    start_angle=(-t if mirror_sign > 0 else 180 deg - t),
                    end_angle=(t if mirror_sign > 0 else 180 deg + t))
    stem = Stroke([upper_arc, lower_arc], width=f_width)
    top_eye = Circle(center=(x, 2 * rise), radius=3.5)
    bottom_eye = Circle(center=(x, -2 * rise), radius=4)
    Fixed(upper_arc.center)
    Fixed(lower_arc.center)
}

solid violin {
    top = Spline(mirror(half, about="y"), closed=true,
                 corners=[lower, upper, 2 * n - 2 - upper, 2 * n - 2 - lower])
    Fixed(top)
    left_f = f_hole(x=-42 mm, mirror_sign=-1)
    right_f = f_hole(x=42 mm, mirror_sign=1)
    hole end_pin {
        c = Circle(center=(0, -166), radius=3)
    }
    Fixed(left_f)
    Fixed(right_f)
    Fixed(end_pin)
}
