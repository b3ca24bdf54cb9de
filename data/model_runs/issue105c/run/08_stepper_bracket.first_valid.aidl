# 28BYJ-48 stepper bracket: 60 x 40 mm plate, a 9.5 mm shaft-boss hole whose centre
# sits 8 mm above the motor centre, two M4 mounting holes 35 mm apart on the
# motor centre line (motor body 28 mm), and two 3.4 mm screw holes at the bottom
# corners, 6 mm in.
solid bracket {
    body = RoundedRectangle(center=(0, 0), width=60, height=40, corner_radius=4)
    motor = Circle(center=(0, -2), diameter=28, construction=true)
    At(motor.center, body.center, dy=-2)
    hole shaft {
        c = Circle(center=(0, 6), diameter=9.5)
    }
    At(shaft.c.center, motor.center, dy=8)
    hole ears {
        l = Circle(center=(-17.5, -2), diameter=4.2)
        r = Circle(center=(17.5, -2), diameter=4.2)
    }
    At(ears.l.center, motor.center, dx=-17.5)
    At(ears.r.center, motor.center, dx=17.5)
    hole base {
        c = Circle(center=(-24, -14), diameter=3.4)
    }
    CornerPattern(base, body, inset=6)
}
