# Request (workshop): a cam clamp for a jig, cut from 6 mm birch plywood. Three parts:
# - cam lever: a 50 mm cam disc with an 8.2 mm pivot hole 6 mm off the disc's centre
#   (the eccentric throw, towards the bottom), and a handle 18 mm wide with a rounded end
#   running along +x: 90 mm from the pivot to the handle's tip, with a 6 mm hanging hole
#   10 mm from the tip;
# - base plate: 120 x 70 with R5 corners, the 8.2 mm pivot hole 30 mm from its left edge,
#   centred in height, two countersunk M5 screw holes (10 mm heads) 15 mm from the right
#   edge and 40 mm apart, centred in height, and "CAM CLAMP" engraved between them;
# - a spacer washer 24 mm across with the 8.2 mm bore, under the lever.

import "std/fasteners.aidl"
import "std/shapes.aidl"

thickness 6 mm

pivot_d = 8.2 mm
throw = 6 mm

assembly cam_clamp {
    solid lever {
        disc = Circle(center=(0, -throw), diameter=50)
        handle = Slot(start=(0, 0), end=(81, 0), width=18)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        hole hang { c = Circle(center=(80, 0), diameter=6) }
        assert abs(distance(disc.center, pivot.c.center) - 6 mm) < 0.001 mm, "the cam's throw is 6 mm"
        assert abs(handle.bb.right - pivot.c.center.x - 90 mm) < 0.001 mm, "90 mm from pivot to tip"
        assert abs(handle.bb.right - hang.c.center.x - 10 mm) < 0.001 mm, "hanging hole 10 mm from the tip"
    }

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=120, height=70, corner_radius=5)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        HorizontalDistance(plate.left.midpoint, pivot.c.center, 30)
        AlignCenterY(pivot, plate)

        screw = clearance_hole(size=5)
        other = clearance_hole(size=5)
        Countersink([screw, other], diameter=10)
        HorizontalDistance(screw.c.center, plate.right.midpoint, 15)
        VerticalDistance(other.c.center, screw.c.center, 40)
        AlignCenterX(other, screw)
        plate.center.y == (screw.c.center.y + other.c.center.y) / 2

        drawing label {
            t = Text("CAM CLAMP", (0, 0), size=6, valign="middle")
        }
        # between the pivot and the screws
        label.bb.center_x == (pivot.bb.right + screw.bb.left) / 2
        AlignCenterY(label, plate)

        assert plate.bb.width == 120 mm and plate.bb.height == 70 mm, "base 120 x 70"
        assert abs(other.c.center.y - screw.c.center.y) == 40 mm, "screws 40 mm apart"
    }

    spacer = washer(outer=24, inner=pivot_d)

    Above(lever, base, gap=8)
    AlignLeft(lever, base)
    RightOf(spacer, lever, gap=8)
    AlignCenterY(spacer, lever)
}
