# Request (sport): a tennis net gauge for the club: a flat stick 50 mm wide whose top edge
# is exactly 914 mm (the net's centre height) above its foot, so the net's tape should
# just touch it. Cut from 6 mm ply in two pieces that lock together with a flat sliding
# dovetail (2 tails, 8 mm deep, 10 degrees, 0.1 mm clearance) whose joint line is 451 mm
# above the foot, so each piece fits a 600 mm bed.
# - a scale up the right edge from the foot: a tick every 10 mm (5 mm long), 8 mm long
#   every 50 mm, 12 mm long every 100 mm, the 100 mm ticks numbered in cm (10 to 90) with
#   3.5 mm figures just left of the tick;
# - engraved up the lower piece "CENTRE HEIGHT", up the upper piece "TENNIS NET 914 mm",
#   both in filled bold letters 9 mm tall, left of the middle;
# - an 8 mm hanging hole centred 20 mm below the top, 10 mm left of the middle; the top
#   corners rounded 5 mm.
# Drawn assembled, the pieces in place.

import "std/joints.aidl"

units mm
thickness 6 mm

height = 914 mm
joint = 451 mm
w = 50 mm
dt_depth = 8 mm

assembly net_gauge {
    solid lower {
        body = Rectangle(corner=(-w / 2, 0), opposite=(w / 2, joint + dt_depth))
        tails = dovetail(part="tail", length=w, depth=dt_depth, tails=2, angle=10 deg,
                         cx=0, cy=joint)
        drawing scale {
            for k in range(1, 46) {
                tick = Line((w / 2 - (12 if k % 10 == 0 else (8 if k % 5 == 0 else 5)), k * 10),
                            (w / 2 - 1, k * 10))
            }
            for c in range(1, 5) {
                num = Text(str(c * 10), position=(w / 2 - 15, c * 100), size=3.5, anchor="end",
                           valign="middle")
            }
        }
        drawing words {
            word = Text("CENTRE HEIGHT", position=(-8, 230), size=9, font="sans:Bold",
                        rotation=90 deg, valign="middle", fill=true)
        }
    }

    solid upper {
        body = Rectangle(corner=(-w / 2, joint), opposite=(w / 2, height))
        sockets = dovetail(part="socket", length=w, depth=dt_depth, tails=2, angle=10 deg,
                           clearance=0.1, cx=0, cy=joint)
        hole hang {
            c = Circle(center=(-10, height - 20), diameter=8)
        }
        drawing scale {
            for k in range(46, 92) {
                tick = Line((w / 2 - (12 if k % 10 == 0 else (8 if k % 5 == 0 else 5)), k * 10),
                            (w / 2 - 1, k * 10))
            }
            for c in range(5, 10) {
                num = Text(str(c * 10), position=(w / 2 - 15, c * 100), size=3.5, anchor="end",
                           valign="middle")
            }
        }
        drawing words {
            word = Text("TENNIS NET 914 mm", position=(-8, (joint + dt_depth + height - 30) / 2),
                        size=9, font="sans:Bold", rotation=90 deg, valign="middle", fill=true)
        }
        Fillet([(-w / 2, height), (w / 2, height)], 5)
    }

    # FIX after the first valid program: the ticks ended 0.5 mm from the edge, and the 910 mm
    # one ran into the rounded top corner (W0516); they now end 1 mm from the edge

    # drawn assembled: the tails sit in their sockets
    AllowOverlap(lower, upper)

    assert upper.body.bb.top - lower.body.bb.bottom == 914 mm, "top edge 914 mm above the foot"
    assert upper.body.bb.bottom - lower.body.bb.bottom == 451 mm, "joint line 451 mm up"
    assert lower.body.bb.width == 50 mm and upper.body.bb.width == 50 mm, "50 mm wide"
    assert lower.body.bb.height <= 600 mm and upper.body.bb.height <= 600 mm, "fits the bed"
    assert len(lower.scale.tick) + len(upper.scale.tick) == 91, "a tick every 10 mm to 910"
    assert len(lower.scale.num) + len(upper.scale.num) == 9, "numbered 10 to 90"
    assert upper.body.bb.top - upper.hang.c.center.y == 20 mm, "hole 20 mm below the top"
    assert upper.hang.c.diameter == 8 mm
    assert distance(upper.words, upper.hang) >= 3 mm, "the words clear the hole"
    assert distance(upper.words, upper.scale) >= 2 mm, "the words clear the scale"
    assert distance(lower.words, lower.scale) >= 2 mm, "the words clear the scale"
}
