# Request: a giant lawn die for garden-party games (Yahtzee on the grass), a 120 mm cube of
# 6 mm exterior ply, finger-jointed on every edge (20 mm fingers), closed, glued. Pips engraved
# filled, 22 mm across, on a 3 x 3 grid 32 mm apart, centred on each face, as a real die:
# opposite faces add up to 7 (top 1, bottom 6, front 2, back 5, left 3, right 4). Every pip at
# least 5 mm clear of the finger zone (the outer 6 mm band of each face). All six faces'
# pips on the outside: the bottom panel, which the box puts engraved face in, is turned
# over so its pips look down.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
side = 120 mm
pip = 22 mm
d = 32 mm

# pip offsets from a face's centre, for 1 .. 6 (index 0 unused)
P = [[],
     [(0, 0)],
     [(-d, d), (d, -d)],
     [(-d, d), (0, 0), (d, -d)],
     [(-d, d), (d, d), (-d, -d), (d, -d)],
     [(-d, d), (d, d), (0, 0), (-d, -d), (d, -d)],
     [(-d, d), (d, d), (-d, 0), (d, 0), (-d, -d), (d, -d)]]

assembly die {
    box = finger_box(length=side, depth=side, height=side, thickness=t, finger=20 mm,
                     closed=true)

    drawing one { for p in P[1] { c = Circle(center=p, diameter=pip, fill=true) } }
    drawing two { for p in P[2] { c = Circle(center=p, diameter=pip, fill=true) } }
    drawing three { for p in P[3] { c = Circle(center=p, diameter=pip, fill=true) } }
    drawing four { for p in P[4] { c = Circle(center=p, diameter=pip, fill=true) } }
    drawing five { for p in P[5] { c = Circle(center=p, diameter=pip, fill=true) } }
    drawing six { for p in P[6] { c = Circle(center=p, diameter=pip, fill=true) } }

    CenterInside(one, box.lid)
    CenterInside(six, box.bottom)
    CenterInside(two, box.front)
    CenterInside(five, box.back)
    CenterInside(three, box.left)
    CenterInside(four, box.right)
    CutInto(one, box.lid)
    CutInto(six, box.bottom)
    CutInto(two, box.front)
    CutInto(five, box.back)
    CutInto(three, box.left)
    CutInto(four, box.right)

    # the bottom: finger_box places it itself, engraved face in (E0108 on a Place of it); its
    # outline is the same turned over, so it is glued in upside down: pips out

    # the request's numbers
    assert box.lid.bb.width == 120 mm and box.front.bb.height == 120 mm, "120 mm cube"
    assert len(one.c) == 1 and len(two.c) == 2 and len(three.c) == 3 and len(four.c) == 4 and
        len(five.c) == 5 and len(six.c) == 6, "1 to 6 pips"
    assert len(one.c) + len(six.c) == 7 and len(two.c) + len(five.c) == 7 and
        len(three.c) + len(four.c) == 7, "opposite faces add to 7"
    assert six.c[0].diameter == 22 mm, "22 mm pips"
    assert six.c[0].center.y - six.c[2].center.y == 32 mm, "32 mm grid"
    assert six.bb.left - box.bottom.bb.left >= t + 5 mm and box.bottom.bb.top - six.bb.top >= t + 5 mm,
        "pips 5 mm clear of the fingers"
    assert abs(one.c[0].center.x - box.lid.bb.center_x) < 0.01 mm and
        abs(one.c[0].center.y - box.lid.bb.center_y) < 0.01 mm, "the 1 in the middle of the lid"
}
