# Request (workshop): a table-saw push shoe from 6 mm birch ply. Overall 300 mm long. A sole
# 300 long x 30 tall whose flat underside rides on the workpiece; at the back end a heel hook
# 15 mm long drops 10 mm below the sole to push the workpiece's trailing edge. A handle rises
# over the back half to 135 mm above the heel's underside (hull of the sole's back 150 mm and a
# 60 mm round top centred 45 mm in from the back end), with a hand hole: a slot 28 mm wide
# from (215, 70) to (255, 100) (walls at least 10 mm all round). An 8 mm hanging hole 20 mm
# from the front end, mid-sole. "KEEP HANDS CLEAR" engraved along the sole, 7 mm letters.
# All corners rounded R3.

units mm
thickness 6 mm
kerf 0.15 mm

param length = 300 mm, min = 250 mm, max = 400 mm
sole_h = 30 mm
heel_len = 15 mm
heel_drop = 10 mm
top_r = 30 mm

solid push_stick {
    sole = Rectangle(bottom_left=(0, heel_drop), width=length, height=sole_h)
    heel = Rectangle(bottom_left=(length - heel_len, 0), width=heel_len, height=heel_drop)
    top = Circle(center=(length - 45 mm, 135 mm - top_r), radius=top_r, construction=true)
    base = Rectangle(bottom_left=(length - 150 mm, heel_drop), width=150 mm, height=sole_h,
                     construction=true)
    handle = Hull(base, top)

    hole grip {
        s = Slot(start=(length - 85 mm, 70), end=(length - 45 mm, 100), width=28)
    }
    hole hang {
        c = Circle(center=(20, heel_drop + sole_h / 2), diameter=8)
    }
    drawing label {
        t = Text("KEEP HANDS CLEAR", position=(88, heel_drop + sole_h / 2), size=7,
                 valign="middle")
    }

    Fillet(3)

    assert abs(sole.bb.width - 300 mm) < 0.01, "300 long"
    assert abs(sole.bb.height - 30 mm) < 0.01, "sole 30 tall"
    assert abs(heel.bb.width - 15 mm) < 0.01, "heel hook 15 long"
    assert abs(sole.bb.bottom - heel.bb.bottom - 10 mm) < 0.01, "heel drops 10 below the sole"
    assert abs(handle.bb.top - heel.bb.bottom - 135 mm) < 0.01, "handle 135 above the heel"
    assert abs(hang.c.diameter - 8 mm) < 0.01, "8 mm hanging hole"
    assert abs(hang.c.center.x - sole.bb.left - 20 mm) < 0.01, "hanging hole 20 from the front"
    assert label.bb.right < handle.bb.left - 5 mm, "label on the sole, clear of the handle"
    assert label.bb.left > hang.bb.right + 5 mm, "label clear of the hanging hole"
    assert grip.bb.bottom - sole.bb.top >= 10 mm, "hand hole clear of the sole"
    assert handle.bb.top - grip.bb.top >= 10 mm, "wall above the hand hole"
}
