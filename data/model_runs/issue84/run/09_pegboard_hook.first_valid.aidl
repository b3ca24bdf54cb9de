# A flat pegboard hook for 1/4 in pegboard (holes 6 mm on 1 in = 25.4 mm
# pitch), cut from 5 mm sheet: a 30 x 40 mm back plate, two 5 mm pegs at the
# back plate's top edge, hooking over 25.4 mm apart vertically... drawn in
# side view: the back plate upright, two L-shaped pegs out of its back (left),
# one at the top and one 25.4 mm below, and a 60 mm arm out to the right at the
# bottom ending in a 12 mm upturned tip.
solid hook {
    back = Rectangle(bottom_left=(0, 0), width=6, height=45)
    solid top_peg {
        stem = Rectangle(bottom_left=(-6, 38), width=6, height=5)
        up = Rectangle(bottom_left=(-11, 38), width=5, height=12)
    }
    solid low_peg {
        stem = Rectangle(bottom_left=(-6, 12.6), width=6, height=5)
    }
    arm = Rectangle(bottom_left=(6, 0), width=60, height=6)
    tip = Rectangle(bottom_left=(60, 6), width=6, height=12)
    Fillet(1)
}
