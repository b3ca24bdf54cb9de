# A two-wheel robot chassis: 160 x 120 mm plate with 6 mm corner radii, two
# 30 x 70 mm wheel cut-outs centred on the left and right edges, slotted motor
# mounts (two 3.2 mm holes 17.5 mm apart above and below each wheel cut-out's
# inner edge), a 4-hole caster mount (3.2 mm on a 30 mm square) 20 mm from the
# rear (bottom) edge, a 20 mm cable hole in the middle, and the four Arduino
# Uno mounting holes (3.2 mm) centred on the front half.
solid chassis {
    plate = RoundedRectangle(center=(0, 0), width=160, height=120, corner_radius=6)
    hole wheel_l { r = Rectangle(center=(-65, 0), width=30, height=70) }
    hole wheel_r { r = Rectangle(center=(65, 0), width=30, height=70) }
    hole motor_l {
        a = Circle(center=(-42, 8.75), diameter=3.2)
        b = Circle(center=(-42, -8.75), diameter=3.2)
    }
    motor_r = Mirrored(motor_l, about=Line((0, -10), (0, 10), construction=true))
    hole caster {
        c = Circle(center=(-15, -55), diameter=3.2)
    }
    GridPattern(caster, rows=2, cols=2, spacing=30)
    hole cable { c = Circle(center=(0, 0), diameter=20) }
    hole uno {
        # Uno holes (14, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5) from the
        # board's corner; the 68.6 x 53.3 board centred at (0, 30)
        h1 = Circle(center=(-20.3, 5.85), diameter=3.2)
        h2 = Circle(center=(-19, 54.05), diameter=3.2)
        h3 = Circle(center=(31.8, 10.95), diameter=3.2)
        h4 = Circle(center=(31.8, 38.85), diameter=3.2)
    }
}
