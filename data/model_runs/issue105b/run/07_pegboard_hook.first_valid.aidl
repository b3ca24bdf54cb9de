# Pegboard hook plate (side profile, cut from 6 mm acrylic) for 1/4" pegboard
# (holes 6.35 mm on a 25.4 mm grid, board 5 mm thick). A back plate 12 mm wide x
# 45 mm tall rests on the board's face. From it two 6 x 6 mm pegs go back through
# the board, 25.4 mm apart center to center: the upper one 5.5 mm long (board
# + clearance) then turned up 8 mm behind the board (a 6 mm wide finger), the lower
# one straight, 8 mm long. From the back plate's bottom a 60 mm long x 8 mm arm
# sticks out to the front, ending in a 6 mm wide x 14 mm tall upturned tip.

units mm
thickness 6 mm

param pitch = 25.4 mm, min = 25 mm, max = 26 mm
param board = 5 mm, min = 3 mm, max = 7 mm
param arm = 60 mm, min = 30 mm, max = 120 mm

solid hook {
    back = Rectangle(center=(0, 0), width=12, height=45)

    solid upper {
        peg = Rectangle(center=(-10, 15), width=board + 0.5, height=6)
        finger = Rectangle(center=(-15, 19), width=6, height=14)
        LeftOf(finger, peg)
        AlignBottom(finger, peg)
    }
    LeftOf(upper.peg, back)
    upper.peg.bb.top == back.bb.top - 3

    solid lower {
        peg = Rectangle(center=(-10, -10), width=8, height=6)
    }
    LeftOf(lower, back)
    VerticalDistance(lower.peg.center, upper.peg.center, pitch)

    solid front_arm {
        bar = Rectangle(center=(36, -18), width=arm, height=8)
        tip = Rectangle(center=(66, -10), width=6, height=14)
        AlignRight(tip, bar)
        AlignBottom(tip, bar)
    }
    RightOf(front_arm, back, gap=-12)
    AlignBottom(front_arm, back)
}
