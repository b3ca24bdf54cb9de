# Request: a two-finger gripper for my robot arm, driven by an SG90 micro servo, cut from
# 3 mm acrylic. Base plate 80 x 50 mm (R4 corners) with four M3 holes 6 mm in from the
# edges, a 23 x 12.5 mm window for the servo body, its two 2 mm ear-screw holes 27.5 mm
# apart, and an M3 pivot hole (3.2 mm) for the idler 24 mm from the servo's shaft; the shaft
# sits 5.5 mm from the body's middle, toward the idler. "SG90 GRIPPER" engraved 4 mm high
# along the front edge. Two fingers, each a 16-tooth gear of module 1.5 (they mesh 24 mm
# apart, 0.1 mm backlash) with an arm reaching 55 mm forward toward the middle and a jaw
# pad; closed, the jaws stand 1 mm apart. The driven finger: a 2.2 mm hole for the horn
# screw and two 1.6 mm holes for the horn's screws 8 and 14 mm out along the arm; the idler
# finger: a 3.2 mm pivot hole.

import "std/gears.aidl"
import "std/plates.aidl"

thickness 3 mm

centre_d = 24 mm        # gear centre to gear centre
shaft_off = 5.5 mm      # shaft from the servo body's middle
reach = 55 mm           # arm tip (centre of its round end) ahead of the gear centre
arm_dir = atan2(reach, 6 mm)

assembly gripper {
    solid base {
        plate = mounting_plate(width=80 mm, height=50 mm, corner_radius=4 mm, screw=3,
                               inset=6 mm, cx=5 mm, cy=0 mm)
        hole servo { window = Rectangle(center=(-shaft_off, 0), width=23, height=12.5) }
        hole ears {
            left = Circle(center=(-shaft_off - 13.75 mm, 0), diameter=2)
            right = Circle(center=(-shaft_off + 13.75 mm, 0), diameter=2)
        }
        hole pivot { c = Circle(center=(centre_d, 0), diameter=3.2) }
        drawing label { t = Text("SG90 GRIPPER", position=(5, -20), size=4, valign="middle") }
    }

    solid finger_l {
        gear = spur_gear(teeth=16, module=1.5 mm, backlash=0.1 mm, phase=0 deg, cx=0 mm, cy=0 mm)
        arm = Hull(Circle(center=(0, 0), radius=6), Circle(center=(6, reach), radius=5))
        jaw = Rectangle(corner=(4, 42), opposite=(11.5, 66))
        hole horn_screw { c = Circle(center=(0, 0), diameter=2.2) }
        hole horn {
            a = Circle(center=(8 mm * cos(arm_dir), 8 mm * sin(arm_dir)), diameter=1.6)
            b = Circle(center=(14 mm * cos(arm_dir), 14 mm * sin(arm_dir)), diameter=1.6)
        }
    }

    solid finger_r {
        # half a tooth turned, so that a tooth of the left gear sits in a gap of this one
        gear = spur_gear(teeth=16, module=1.5 mm, backlash=0.1 mm, phase=11.25 deg,
                         cx=centre_d, cy=0 mm)
        arm = Hull(Circle(center=(centre_d, 0), radius=6),
                   Circle(center=(centre_d - 6 mm, reach), radius=5))
        jaw = Rectangle(corner=(12.5, 42), opposite=(20, 66))
        hole pivot { c = Circle(center=(centre_d, 0), diameter=3.2) }
    }

    Place(base, position=(0, 0, 0))
    Place(finger_l, on=base, position=(0, 0))
    Place(finger_r, on=base, position=(0, 0))

    # flat on the sheet: the fingers beside the plate
    RightOf(finger_l, base, gap=5)
    AlignTop(finger_l, base)
    RightOf(finger_r, finger_l, gap=5)
    AlignTop(finger_r, finger_l)

    assert base.plate.body.width == 80 mm and base.plate.body.height == 50 mm
    assert base.servo.window.width == 23 mm and base.servo.window.height == 12.5 mm
    assert distance(base.ears.left.center, base.ears.right.center) == 27.5 mm
    assert base.pivot.c.center.x - base.servo.window.center.x == 24 mm + 5.5 mm
    assert finger_l.gear.teeth == 16 and finger_r.gear.teeth == 16
    assert finger_r.gear.hub.center.x - finger_l.gear.hub.center.x == 24 mm
    assert finger_r.jaw.bb.left - finger_l.jaw.bb.right == 1 mm, "closed jaws 1 mm apart"
    assert finger_l.arm.bb.top - finger_l.gear.hub.center.y == 55 mm + 5 mm
    assert distance(finger_l.horn.a.center, finger_l.horn_screw.c.center) == 8 mm
    assert distance(finger_l.horn.b.center, finger_l.horn_screw.c.center) == 14 mm
    assert base.label.t.size == 4 mm
}
