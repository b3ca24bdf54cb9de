# A motor mounting plate and its four washers, built from the standard
# library (import "std/shapes.aidl"): a rounded plate with a corner hole in
# each corner (a loop), a bolt circle and shaft hole for a round motor
# flange, two adjustment slots, a hanging tab on top, and an engraved label.
# The washers are separate parts laid out in a row under the plate.
# Try: --set width=150  --set motor_pcd=50  --set washers=6

import "std/shapes.aidl"

param width = 120 mm
param height = 80 mm
param motor_pcd = 40 mm  # bolt circle of the motor flange
param screw = 5 mm       # corner screw size
param washers = 4

inset = 8 mm  # corner holes: distance from the edges

assembly kit {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=6)

        # a screw hole in each corner
        for i in range(4) {
            sx = 1 if i == 1 or i == 2 else -1
            sy = 1 if i >= 2 else -1
            hole corner {
                h = Circle(center=(sx * (width / 2 - inset), sy * (height / 2 - inset)), diameter=screw)
            }
            corner.bb.center_x == (body.bb.right - inset if sx > 0 else body.bb.left + inset)
            corner.bb.center_y == (body.bb.top - inset if sy > 0 else body.bb.bottom + inset)
        }

        # the motor: shaft boss hole and a bolt circle around it, left of center
        hole shaft {
            boss = Circle(center=(-width / 6, 0), diameter=0.55 * motor_pcd)
        }
        motor = bolt_circle(count=4, pcd=motor_pcd, hole_d=3.4 mm, start=45 deg, cx=-width / 6)
        Concentric(motor.pitch, shaft.boss)
        shaft.boss.center.x == body.center.x - width / 6
        AlignCenterY(shaft, body)

        # two vertical adjustment slots on the right
        for j in range(2) {
            adjust = slot_hole(length=24 mm, width=screw + 0.5 mm, rotation=90 deg,
                               cx=width / 4 + j * 14 mm)
            AlignCenterY(adjust, body)
            adjust.bb.center_x == body.center.x + width / 4 + j * 14 mm
        }

        tab = rounded_tab(width=24 mm, length=28 mm, hole_d=6 mm, cy=height / 2 - 2 mm)
        Above(tab, body, gap=-2 mm)
        AlignCenterX(tab, body)

        drawing label {
            t = Text("MOTOR MOUNT", (width / 2 - 2 * inset, -height / 2 + 6 mm), size=3.5, anchor="end")
        }
        # engraved along the bottom edge, clear of the corner hole
        label.bb.bottom == body.bb.bottom + 6 mm
        label.bb.right == body.bb.right - 2 * inset
    }

    # the washers, in a row under the plate
    for k in range(washers) {
        w = washer(outer=2.4 * screw, inner=screw + 0.3 mm,
                   cx=-width / 2 + 1.2 * screw + k * 3 * screw, cy=-height / 2 - 10 mm - 1.2 * screw)
        Below(w, plate, gap=10 mm)
        w.bb.left == plate.bb.left + k * 3 * screw
    }
}
