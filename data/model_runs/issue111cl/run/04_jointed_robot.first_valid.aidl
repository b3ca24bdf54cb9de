# Request: a jointed robot toy for my nephew, from 3 mm ply, about 150 mm tall put together.
# Five pieces: a body (torso 60 x 70 mm with rounded corners, a 16 mm neck and a 40 x 30 mm
# head in one piece, an antenna with a ball on top and little bolt "ears"), two arms 14 x 55 mm
# with rounded ends and a V-shaped claw notch at the hand, and two legs 18 x 60 mm with a
# 26 mm foot pointing outward. Shoulders and hips pivot on 4 mm split pins: 4.2 mm holes,
# the arm's 7 mm and the leg's 9 mm from its top end. Engraved: two filled round eyes, a
# mouth grille of five bars, "R-7" and three buttons on the chest.

units mm
thickness 3 mm

param pin_d = 4.2 mm, min = 3.2 mm, max = 5.2 mm
param torso_w = 60 mm, min = 50 mm, max = 80 mm
param torso_h = 70 mm, min = 60 mm, max = 90 mm

head_w = 40 mm
head_h = 30 mm
neck_h = 6 mm
arm_w = 14 mm
arm_len = 55 mm
leg_w = 18 mm
leg_len = 60 mm
foot_len = 26 mm
shoulder = (torso_w / 2 - 5 mm, torso_h / 2 - 8 mm)
# hips 20 mm above the torso's bottom: the legs tuck up behind it (165 mm tall at 8 mm)
hip = (torso_w / 2 - 14 mm, -torso_h / 2 + 20 mm)

def arm() -> solid {
    # drawn hanging from its pivot at (0, 0)
    body = RoundedRectangle(center=(0, 7 - arm_len / 2), width=arm_w, height=arm_len,
                            corner_radius=arm_w / 2)
    hole pivot { c = Circle(center=(0, 0), diameter=pin_d) }
    # the V opens at the hand's end (apex up), its base 1 mm past the end
    hole claw { v = Triangle(center=(0, 7 - arm_len + 4), base=9, height=10) }
}

def leg(side=1) -> solid {
    # drawn hanging from its pivot at (0, 0); the foot points to `side` (+1 right, -1 left)
    shin = Rectangle(center=(0, 9 - leg_len / 2), width=leg_w, height=leg_len)
    foot = RoundedRectangle(center=(side * (foot_len - leg_w) / 2, 9 - leg_len + 4), width=foot_len,
                            height=8, corner_radii=[2, 2, 0, 0])
    hole pivot { c = Circle(center=(0, 0), diameter=pin_d) }
}

assembly robot {
    solid body {
        torso = RoundedRectangle(center=(0, 0), width=torso_w, height=torso_h, corner_radius=6)
        neck = Rectangle(center=(0, torso_h / 2 + neck_h / 2), width=16, height=neck_h + 2)
        head = RoundedRectangle(center=(0, torso_h / 2 + neck_h + head_h / 2), width=head_w,
                                height=head_h, corner_radius=4)
        stalk = Rectangle(center=(0, torso_h / 2 + neck_h + head_h + 5), width=3, height=12)
        ball = Circle(center=(0, torso_h / 2 + neck_h + head_h + 12), radius=4)
        ear_l = Rectangle(center=(-head_w / 2 - 2, torso_h / 2 + neck_h + head_h / 2), width=6, height=10)
        ear_r = Rectangle(center=(head_w / 2 + 2, torso_h / 2 + neck_h + head_h / 2), width=6, height=10)

        hole shoulders {
            l = Circle(center=(-shoulder[0], shoulder[1]), diameter=pin_d)
            r = Circle(center=(shoulder[0], shoulder[1]), diameter=pin_d)
        }
        hole hips {
            l = Circle(center=(-hip[0], hip[1]), diameter=pin_d)
            r = Circle(center=(hip[0], hip[1]), diameter=pin_d)
        }
        drawing face {
            eye_l = Circle(center=(-9, torso_h / 2 + neck_h + 20), radius=4, fill=true)
            eye_r = Circle(center=(9, torso_h / 2 + neck_h + 20), radius=4, fill=true)
            for i in range(5) {
                bar = Line((-8 + 4 * i, torso_h / 2 + neck_h + 6), (-8 + 4 * i, torso_h / 2 + neck_h + 11))
            }
        }
        drawing chest {
            name = Text("R-7", position=(0, 14), size=8, valign="middle")
            for i in range(3) {
                button = Circle(center=(-10 + 10 * i, -4), radius=3)
            }
        }
    }

    arm_l = arm()
    arm_r = arm()
    leg_l = leg(side=-1)
    leg_r = leg(side=1)

    # on the sheet: arms beside the body, legs below it
    LeftOf(arm_l, body, gap=6)
    RightOf(arm_r, body, gap=6)
    AlignTop(arm_l, body.torso)
    AlignTop(arm_r, body.torso)
    Below(leg_l, body, gap=6)
    Below(leg_r, body, gap=6)
    RightOf(leg_r, leg_l, gap=6)
    (leg_l.bb.center_x + leg_r.bb.center_x) / 2 == body.bb.center_x

    # put together: arms in front of the body, legs behind it, each on its pivot
    Place(body, position=(0, 0, 0))
    Place(arm_l, position=(-shoulder[0], shoulder[1], 3), rotation=(0, 0, -15 deg))
    Place(arm_r, position=(shoulder[0], shoulder[1], 3), rotation=(0, 0, 15 deg))
    Place(leg_l, position=(-hip[0], hip[1], -3))
    Place(leg_r, position=(hip[0], hip[1], -3))

    assert arm_l.pivot.c.diameter == 4.2 mm and body.shoulders.l.diameter == 4.2 mm, "4.2 mm pivots"
    assert arm_l.body.bb.top - arm_l.pivot.c.center.y == 7 mm, "arm pivot 7 mm from its end"
    assert leg_l.shin.bb.top - leg_l.pivot.c.center.y == 9 mm, "leg pivot 9 mm from its end"
    assert arm_l.body.height == 55 mm and arm_l.body.width == 14 mm, "14 x 55 arms"
    assert leg_l.shin.bb.height == 60 mm and leg_l.shin.bb.width == 18 mm, "18 x 60 legs"
    assert leg_l.foot.bb.width == 26 mm, "26 mm feet"
    assert body.head.bb.width == 40 mm and body.head.bb.height == 30 mm, "40 x 30 head"
    # height put together: antenna ball top to the foot's sole (hip pivot, then the leg)
    assert body.bb.top - (body.hips.l.center.y - (leg_l.pivot.c.center.y - leg_l.bb.bottom)) >= 140 mm, "about 150 mm tall"
    assert body.bb.top - (body.hips.l.center.y - (leg_l.pivot.c.center.y - leg_l.bb.bottom)) <= 160 mm, "about 150 mm tall"
}
