# Request (science): a polar planimeter for the maths club, in 3 mm clear acrylic.
# Pole arm: a 16 mm wide bar with round ends and 3 mm pivot holes 160 mm apart (the pole
# needle at one end, the elbow pivot at the other), "POLE ARM" engraved on it.
# Tracer arm: a 20 mm wide bar with round ends, a 3 mm elbow pivot hole at one end and a
# 1.5 mm hole for the tracer needle 200 mm from it; two mortises 3.1 x 12.2 mm across the
# arm, centred 40 and 48 mm from the pivot, take the two wheel cheeks; a scale engraved
# along its top edge from 60 to 190 mm (a tick every 10 mm, numbered at 100 and 150).
# Measuring wheel: 100 mm round (31.83 mm across) with a 3 mm axle hole and 100 engraved
# ticks, a long one every 10th, numbered 0 to 9 clockwise.
# Two cheeks 24 x 22 mm, each with a 12 mm wide, 3 mm tall tab on top into the arm and a
# 3 mm axle hole 15 mm below the tab's root.

units mm
thickness 3 mm

wheel_d = 100 mm / pi

def cheek() -> solid {
    plate = Rectangle(bottom_left=(-12, 0), width=24, height=22)
    tab = Rectangle(bottom_left=(-6, 22), width=12, height=3)
    hole axle { c = Circle(center=(0, 7), diameter=3) }
    assert plate.bb.top - axle.c.center.y == 15 mm, "axle 15 mm below the arm"
    assert tab.width == 12 mm, "12 mm tab"
}

assembly planimeter {
    solid tracer_arm {
        bar = Slot(start=(0, 0), end=(200, 0), width=20)
        hole pivot { c = Circle(center=(0, 0), diameter=3) }
        hole tracer { c = Circle(center=(200, 0), diameter=1.5) }
        hole cheeks {
            a = Rectangle(center=(40, 0), width=3.1, height=12.2)
            b = Rectangle(center=(48, 0), width=3.1, height=12.2)
        }
        drawing scale {
            for i in range(14) {
                tk = Line((60 + 10 * i, 10), (60 + 10 * i, 10 - (4 if i % 5 == 4 else 2.5)))
            }
            n100 = Text("100", position=(100, 1.5), size=3, valign="middle")
            n150 = Text("150", position=(150, 1.5), size=3, valign="middle")
        }
        Fixed(bar)
        assert tracer.c.center.x - pivot.c.center.x == 200 mm, "tracer 200 mm from the pivot"
        assert cheeks.a.center.x - pivot.c.center.x == 40 mm, "first cheek at 40"
        assert cheeks.b.center.x - cheeks.a.center.x == 8 mm, "cheeks 8 mm apart"
        assert scale.tk[13].start.x == 190 mm, "scale to 190"
    }

    solid pole_arm {
        bar = Slot(start=(0, 0), end=(160, 0), width=16)
        hole pole { c = Circle(center=(0, 0), diameter=3) }
        hole elbow { c = Circle(center=(160, 0), diameter=3) }
        drawing label {
            t = Text("POLE ARM", position=(80, 0), size=6, valign="middle")
        }
        Fixed(bar)
        assert elbow.c.center.x - pole.c.center.x == 160 mm, "pivots 160 mm apart"
    }

    solid wheel {
        disc = Circle(center=(0, 0), diameter=wheel_d)
        hole axle { c = Circle(center=(0, 0), diameter=3) }
        drawing marks {
            for i in range(100) {
                tick = Line(((wheel_d / 2 - 0.6 mm) * cos(90 deg - i * 3.6 deg),
                             (wheel_d / 2 - 0.6 mm) * sin(90 deg - i * 3.6 deg)),
                            ((wheel_d / 2 - (3.5 mm if i % 10 == 0 else 2 mm)) * cos(90 deg - i * 3.6 deg),
                             (wheel_d / 2 - (3.5 mm if i % 10 == 0 else 2 mm)) * sin(90 deg - i * 3.6 deg)))
            }
            ring = Circle(center=(0, 0), radius=9.5, construction=true)
            for k in range(10) {
                num = Text(str(k), along=ring, angle=90 deg - k * 36 deg, size=2.5)
            }
        }
        Fixed(disc)
        assert abs(disc.diameter * pi - 100 mm) < 0.01 mm, "rolls 100 mm a turn"
        assert len(marks.tick) == 100, "100 ticks"
    }

    c1 = cheek()
    c2 = cheek()

    Below(pole_arm, tracer_arm, gap=10 mm)
    AlignLeft(pole_arm, tracer_arm)
    RightOf(wheel, pole_arm, gap=10 mm)
    AlignTop(wheel, pole_arm)
    RightOf(c1, wheel, gap=10 mm)
    AlignTop(c1, wheel)
    RightOf(c2, c1, gap=10 mm)
    AlignTop(c2, wheel)
}
