# Request (electronics): a 250-size quadcopter trainer frame from 4 mm plywood. Bottom plate
# in one piece: a 100 x 70 mm centre (8 mm corner radius) with four 20 mm wide arms in an X
# (45 deg), motor-to-motor diagonal 250 mm, a 30 mm round motor pad at each arm's end with
# the 2204-motor pattern (M3 holes 3.2 mm on 16 mm and 19 mm spacing) and a 7 mm shaft hole,
# and an 8 mm wide lightening slot 40 mm long in each arm. Centre: 30.5 x 30.5 mm flight
# controller holes (3.2 mm) and four 3.2 mm standoff holes at (+-42, +-27) mm. Top plate
# 100 x 70 mm with the same standoff holes, two 22 x 3.5 mm battery strap slots 50 mm apart
# and "TRAINER 250" engraved. The top plate sits on 30 mm standoffs above the bottom plate.

thickness 4 mm

param diagonal = 250 mm, min = 180 mm, max = 300 mm
param arm_w = 20 mm, min = 14 mm, max = 26 mm

r_motor = diagonal / 2
angles = [45 deg, 135 deg, 225 deg, 315 deg]
standoffs = [(-42, -27), (42, -27), (42, 27), (-42, 27)]

assembly quad {
    solid frame {
        centre = RoundedRectangle(center=(0, 0), width=100, height=70, corner_radius=8)
        for i in range(4) {
            arm = Rectangle(start=(0, 0), end=polar((0, 0), r_motor, angles[i]), width=arm_w)
            pad = Circle(center=polar((0, 0), r_motor, angles[i]), diameter=30)
        }
        hole motor_holes {
            for i in range(4) {
                shaft = Circle(center=polar((0, 0), r_motor, angles[i]), diameter=7)
                m1 = Circle(center=polar(polar((0, 0), r_motor, angles[i]), 8, angles[i]), diameter=3.2)
                m2 = Circle(center=polar(polar((0, 0), r_motor, angles[i]), 8, angles[i] + 180 deg), diameter=3.2)
                m3 = Circle(center=polar(polar((0, 0), r_motor, angles[i]), 9.5, angles[i] + 90 deg), diameter=3.2)
                m4 = Circle(center=polar(polar((0, 0), r_motor, angles[i]), 9.5, angles[i] + 270 deg), diameter=3.2)
            }
        }
        hole lightening {
            for i in range(4) {
                s = Slot(start=polar((0, 0), 59, angles[i]), end=polar((0, 0), 91, angles[i]), width=8)
            }
        }
        hole fc {
            for i in range(4) {
                h = Circle(center=(standoffs[i][0] / abs(standoffs[i][0]) * 15.25,
                                   standoffs[i][1] / abs(standoffs[i][1]) * 15.25), diameter=3.2)
            }
        }
        hole posts {
            for i in range(4) {
                h = Circle(center=standoffs[i], diameter=3.2)
            }
        }
    }

    solid top {
        plate = RoundedRectangle(center=(0, 0), width=100, height=70, corner_radius=8)
        hole posts {
            for i in range(4) {
                h = Circle(center=standoffs[i], diameter=3.2)
            }
        }
        hole straps {
            l = Rectangle(center=(-25, 0), width=3.5, height=22)
            r = Rectangle(center=(25, 0), width=3.5, height=22)
        }
        drawing label {
            t = Text("TRAINER 250", position=(0, -24), size=6)
        }
    }

    RightOf(top, frame, gap=10)
    AlignCenterY(top, frame)

    Place(frame, position=(0, 0, 0))
    Place(top, position=(0, 0, 34))

    assert distance(frame.pad[0].center, frame.pad[2].center) == 250 mm, "motor-to-motor 250"
    assert frame.arm[0].width == 20 mm
    assert frame.centre.width == 100 mm and frame.centre.height == 70 mm
    assert frame.lightening.s[0].length == 40 mm, "40 mm slots"
    assert distance(frame.motor_holes.m1[0].center, frame.motor_holes.m2[0].center) == 16 mm
    assert distance(frame.motor_holes.m3[0].center, frame.motor_holes.m4[0].center) == 19 mm
    assert frame.fc.h[1].center.x - frame.fc.h[0].center.x == 30.5 mm
    assert top.straps.r.center.x - top.straps.l.center.x == 50 mm
    assert len(frame.pad) == 4
}
