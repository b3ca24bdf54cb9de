# Pegboard hook (side view, cut from 6 mm acrylic) for 1/4" pegboard with 1"
# hole spacing: a 6 mm wide, 40 mm tall back plate; at its top an L-peg (5 mm
# bar going 8 mm back through the board, then 6 mm up); 25.4 mm below it a
# straight 5 x 8 mm support peg; from the bottom of the plate an 80 mm arm, 8 mm
# thick, rising at 15 degrees, ending in a 10 mm round knob.

solid hook {
    back = Rectangle(center=(0, 0), width=6, height=40)
    # the pegs point left (into the board); the top one hooks up
    peg_top = Rectangle(bottom_left=(-3 - 8, 20 - 5 - 2), width=8 + 0.5, height=5)
    peg_up = Rectangle(bottom_left=(-3 - 8, 20 - 2), width=5, height=6)
    peg_low = Rectangle(bottom_left=(-3 - 8, 20 - 5 - 2 - 25.4), width=8 + 0.5, height=5)
    arm = Rectangle(start=(0, -16), end=(80 * cos(15 deg), -16 + 80 * sin(15 deg)), width=8)
    knob = Circle(center=(80 * cos(15 deg), -16 + 80 * sin(15 deg)), diameter=10)
}
