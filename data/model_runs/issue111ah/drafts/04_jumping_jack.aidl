# Request (toys): a pull-string jumping jack (a "Hampelmann") in 3 mm ply, 5 parts: a body
# with a 44 mm round head over a 50 x 80 mm torso (R10 corners), a 4 mm hanging hole 6 mm
# below the top of the head, an engraved face (two 4 mm eyes, a smile) and "JACK" engraved
# on the torso; two arms 55 mm from pivot to hand (24 mm wide at the shoulder, 14 mm at the
# hand) and two legs 70 mm from pivot to ankle (24 mm at the hip, 16 mm at the ankle) with a
# foot pointing outward. Each limb turns on a 3 mm brad: 3.2 mm pivot holes, shoulders 36 mm
# apart, hips 28 mm apart; each limb has a 1.5 mm string hole 6 mm inward and 4 mm above its
# pivot, so pulling the string lifts it. Parts laid out apart for cutting.

thickness 3 mm

pivot_d = 3.2 mm
string_d = 1.5 mm
shoulder_span = 36 mm
hip_span = 28 mm

def arm(side=1) -> solid {
    top = Circle(center=(0, 0), radius=12)
    hand = Circle(center=(0, -55), radius=7)
    limb = Hull(top, hand)
    hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
    hole pull { c = Circle(center=(side * 6, 4), diameter=string_d) }
}

def leg(side=1) -> solid {
    top = Circle(center=(0, 0), radius=12)
    ankle = Circle(center=(0, -70), radius=8)
    limb = Hull(top, ankle)
    foot = Ellipse(center=(-side * 8, -74), rx=14, ry=7)
    hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
    hole pull { c = Circle(center=(side * 6, 4), diameter=string_d) }
}

assembly jumping_jack {
    solid body {
        torso = RoundedRectangle(center=(0, 0), width=50, height=80, corner_radius=10)
        head = Circle(center=(0, 60), diameter=44)
        hole hang { c = Circle(center=(0, 82 - 6 - 2), diameter=4) }
        hole shoulders {
            left = Circle(center=(-shoulder_span / 2, 28), diameter=pivot_d)
            right = Circle(center=(shoulder_span / 2, 28), diameter=pivot_d)
        }
        hole hips {
            left = Circle(center=(-hip_span / 2, -30), diameter=pivot_d)
            right = Circle(center=(hip_span / 2, -30), diameter=pivot_d)
        }
        drawing face {
            eye_l = Circle(center=(-8, 64), diameter=4)
            eye_r = Circle(center=(8, 64), diameter=4)
            smile = Arc(center=(0, 58), radius=9, start_angle=200 deg, end_angle=340 deg)
            name = Text("JACK", position=(0, 0), size=8, valign="middle")
        }
        assert hang.c.center.y == head.bb.top - 6 mm - 2 mm, "hanging hole 6 mm below the head's top"
        assert shoulders.right.center.x - shoulders.left.center.x == 36 mm, "shoulders 36 apart"
        assert hips.right.center.x - hips.left.center.x == 28 mm, "hips 28 apart"
    }
    # left arm and leg: string hole toward the body's middle (+x); right ones mirrored
    arm_l = arm(side=1)
    arm_r = arm(side=-1)
    leg_l = leg(side=1)
    leg_r = leg(side=-1)

    LeftOf(arm_l, body, gap=8)
    RightOf(arm_r, body, gap=8)
    AlignTop(arm_l, body.torso)
    AlignTop(arm_r, body.torso)
    LeftOf(leg_l, arm_l, gap=8)
    RightOf(leg_r, arm_r, gap=8)
    AlignTop(leg_l, body.torso)
    AlignTop(leg_r, body.torso)

    assert arm_l.hand.center.y - arm_l.top.center.y == -55 mm, "arm 55 mm pivot to hand"
    assert leg_l.ankle.center.y - leg_l.top.center.y == -70 mm, "leg 70 mm pivot to ankle"
    assert arm_l.top.diameter == 24 mm and arm_l.hand.diameter == 14 mm, "arm widths"
    assert leg_l.top.diameter == 24 mm and leg_l.ankle.diameter == 16 mm, "leg widths"
}
