# Kitchen: a gingerbread-man cutting template, 3 mm food-safe acrylic, laid on rolled dough and
# cut around with a knife. Overall 120 mm tall and 90 mm wide (arm tip to arm tip).
# Head: a 40 mm circle at the top. Body: 50 x 50 mm with R15 corners. Arms: one 18 mm wide bar
# straight across, rounded ends. Legs: 18 mm wide, rounded feet, splayed. Inside corners R4.
# Eyes: two 4 mm holes 14 mm apart, 5 mm above the head's centre (to mark with a skewer);
# three 5 mm button holes down the middle 13 mm apart; an engraved smile (R10 arc, 120 deg).
thickness 3 mm

param height = 120 mm, min = 80, max = 200
param span = 90 mm, min = 60, max = 160

solid gingerbread {
    head = Circle(center=(0, 40), diameter=40)
    body = RoundedRectangle(center=(0, 5), width=50, height=50, corner_radius=15)
    arms = Slot(start=(-36, 18), end=(36, 18), width=18)
    leg_l = Slot(start=(-13, -10), end=(-22, -51), width=18)
    leg_r = Slot(start=(13, -10), end=(22, -51), width=18)

    hole eyes {
        eye_l = Circle(center=(-7, 45), diameter=4)
        eye_r = Circle(center=(7, 45), diameter=4)
    }
    hole buttons {
        for i in range(3) {
            b = Circle(center=(0, 18 - i * 13), diameter=5)
        }
    }
    drawing face {
        smile = Arc(center=(0, 40), radius=10, start_angle=210, end_angle=330)
    }

    Fillet(4)

    assert self.bb.height == 120 mm, "120 mm tall"
    assert self.bb.width == 90 mm, "90 mm arm tip to arm tip"
    assert head.diameter == 40 mm, "40 mm head"
    assert eyes.eye_r.center.x - eyes.eye_l.center.x == 14 mm, "eyes 14 mm apart"
    assert eyes.eye_l.center.y - head.center.y == 5 mm, "eyes 5 mm above the head's centre"
    assert len(buttons.b) == 3, "three buttons"
    assert buttons.b[0].center.y - buttons.b[1].center.y == 13 mm, "buttons 13 mm apart"
}
