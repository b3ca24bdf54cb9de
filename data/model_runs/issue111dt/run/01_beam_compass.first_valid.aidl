# Request: a beam compass (trammel) for marking big circles on sheet goods, in 6 mm birch
# ply. The beam is 600 mm long and 30 mm wide with round ends (R15). My laser bed is only
# 400 x 300, so cut it as two halves joined by a flat sliding dovetail (2 tails, 10 mm deep,
# 8 deg, 0.1 mm clearance) about halfway. A 3 mm pivot hole for a nail sits 15 mm from the
# left end, on the centre line. Pencil holes 8 mm in diameter on the centre line every
# 20 mm, radius 40 mm to 560 mm from the pivot, except where the joint is (no hole may cut
# into the dovetail band). Each pencil hole gets its radius in cm engraved above it (4 mm
# text). A 5 mm hanging hole 10 mm from the right end. "BEAM COMPASS - RADIUS IN CM"
# engraved along the bottom edge of the left half.

import "std/joints.aidl"

units mm
thickness 6 mm

param beam_l = 600 mm, min = 500 mm, max = 700 mm
param beam_w = 30 mm, min = 26 mm, max = 40 mm
pivot_x = 15 mm
joint_x = 307 mm        # the dovetail's root line (the right half starts here)
band = 10 mm            # dovetail depth: the left half's tails reach to joint_x + band
pencil_d = 8 mm
pitch = 20 mm
n_left = 13             # radii 40 .. 280 mm
n_right = 13            # radii 320 .. 560 mm (300 would fall in the dovetail band)

assembly beam_compass {
    solid left {
        body = RoundedRectangle(bottom_left=(0, -beam_w / 2), width=joint_x + band,
                                height=beam_w, corner_radii=[beam_w / 2, 0, 0, beam_w / 2])
        tails = dovetail(part="tail", length=beam_w, depth=band, tails=2, angle=8 deg,
                         rotation=-90 deg, cx=joint_x, cy=0 mm)
        hole pivot {
            c = Circle(center=(pivot_x, 0), diameter=3)
        }
        hole pencils {
            for i in range(n_left) {
                c = Circle(center=(pivot_x + 40 mm + i * pitch, 0), diameter=pencil_d)
            }
        }
        drawing scale {
            for i in range(n_left) {
                t = Text(f"{4 + 2 * i:.0f}", position=(pivot_x + 40 mm + i * pitch, 6), size=4)
            }
        }
        drawing title {
            words = Text("BEAM COMPASS - RADIUS IN CM", position=(170, -12), size=4)
        }
    }

    solid right {
        body = RoundedRectangle(bottom_left=(joint_x, -beam_w / 2), width=beam_l - joint_x,
                                height=beam_w, corner_radii=[0, beam_w / 2, beam_w / 2, 0])
        sockets = dovetail(part="socket", length=beam_w, depth=band, tails=2, angle=8 deg,
                           clearance=0.1 mm, rotation=-90 deg, cx=joint_x, cy=0 mm)
        hole pencils {
            for i in range(n_right) {
                c = Circle(center=(pivot_x + 320 mm + i * pitch, 0), diameter=pencil_d)
            }
        }
        hole hang {
            c = Circle(center=(beam_l - 10 mm, 0), diameter=5)
        }
        drawing scale {
            for i in range(n_right) {
                t = Text(f"{32 + 2 * i:.0f}", position=(pivot_x + 320 mm + i * pitch, 6), size=4)
            }
        }
    }

    # both halves in one frame: joined flat on the bench
    Place(left, position=(0, 0, 0), face="up")
    Place(right, position=(0, 0, 0), face="up")

    # the request's numbers
    assert right.body.bb.right - left.body.bb.left == 600 mm, "beam is 600 mm long"
    assert left.body.bb.height == 30 mm, "beam is 30 mm wide"
    assert left.pivot.c.center.x - left.body.bb.left == 15 mm, "pivot 15 mm from the left end"
    assert left.pencils.c[0].center.x - left.pivot.c.center.x == 40 mm, "smallest radius 40 mm"
    assert right.pencils.c[n_right - 1].center.x - left.pivot.c.center.x == 560 mm,
        "largest radius 560 mm"
    assert right.body.bb.right - right.hang.c.center.x == 10 mm, "hanging hole 10 mm from the end"
    # no pencil hole reaches into the dovetail band
    assert left.pencils.c[n_left - 1].center.x + pencil_d / 2 < joint_x, "left holes clear the joint"
    assert right.pencils.c[0].center.x - pencil_d / 2 > joint_x + band, "right holes clear the joint"
    # each half fits my 400 x 300 bed
    assert left.bb.width <= 400 mm and right.bb.width <= 400 mm, "halves fit the bed"
}
