# Home: a picture-hanging drill template, 400 x 60 mm overall of 3 mm plywood, cut as two
# halves of 200 x 60 (the bed is only 300 mm) joined in the middle by a flat sliding dovetail
# (2 tails, 10 mm deep, 10 deg). Along a line 20 mm below the top edge: 3 mm pilot holes every
# 20 mm, 9 per half (18 in all) from 25 mm to 185 mm either side of the middle. Along the bottom
# edge engraved ticks every 10 mm (5 mm long, 10 mm long every 50 mm) with the distance from the
# middle in cm ("5", "10", "15") above the long ticks; "CENTRE" engraved over the joint.

import "std/joints.aidl"

thickness 3 mm

param half = 200 mm, min = 150 mm, max = 280 mm
param height = 60 mm, min = 40 mm, max = 100 mm
param pitch = 20 mm, min = 10 mm, max = 30 mm
param joint_depth = 10 mm, min = 6 mm, max = 15 mm

holes_per_half = 9
ticks = 19

assembly hanging_template {
    # left half: the tail panel reaches across the joint band x = 0 .. joint_depth
    solid left {
        body = Rectangle(bottom_left=(-half, 0), width=half + joint_depth, height=height)
        d = dovetail(part="tail", length=height, depth=joint_depth, tails=2, angle=10 deg,
                     rotation=-90 deg, cx=0 mm, cy=height / 2)
        hole pilots {
            for i in range(holes_per_half) {
                c = Circle(center=(-25 mm - i * pitch, height - 20 mm), diameter=3 mm)
            }
        }
        drawing scale {
            for i in range(ticks) {
                x = -(i + 1) * 10 mm
                tick = Line((x, 0), (x, 10 mm if (i + 1) % 5 == 0 else 5 mm))
            }
            for k in range(3) {
                lab = Text(str((k + 1) * 5), position=(-(k + 1) * 50 mm, 12 mm), size=4)
            }
        }
        Fixed(body)
    }

    # right half: the socket panel starts at the joint line
    solid right {
        body = Rectangle(bottom_left=(0, 0), width=half, height=height)
        d = dovetail(part="socket", length=height, depth=joint_depth, tails=2, angle=10 deg,
                     clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=height / 2)
        hole pilots {
            for i in range(holes_per_half) {
                c = Circle(center=(25 mm + i * pitch, height - 20 mm), diameter=3 mm)
            }
        }
        drawing scale {
            for i in range(ticks) {
                x = (i + 1) * 10 mm
                tick = Line((x, 0), (x, 10 mm if (i + 1) % 5 == 0 else 5 mm))
            }
            for k in range(3) {
                lab = Text(str((k + 1) * 5), position=((k + 1) * 50 mm, 12 mm), size=4)
            }
            word = Text("CENTRE", position=(30 mm, height / 2), size=5, valign="middle")
        }
        Fixed(body)
    }

    RightOf(right, left, gap=5 mm)

    assert right.body.bb.width == 200 mm, "each half 200 mm"
    assert left.body.bb.width - 10 mm == 200 mm, "the tail half is 200 mm plus the 10 mm tails"
    assert left.body.bb.height == 60 mm and right.body.bb.height == 60 mm, "60 mm high"
    assert len(left.pilots.c) + len(right.pilots.c) == 18, "18 pilot holes"
    assert left.pilots.c[0].diameter == 3 mm, "3 mm pilot holes"
    assert right.pilots.c[1].center.x - right.pilots.c[0].center.x == 20 mm, "every 20 mm"
    assert right.body.bb.top - right.pilots.c[0].center.y == 20 mm, "20 mm below the top"
}
