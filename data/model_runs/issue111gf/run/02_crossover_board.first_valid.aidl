# Request (electronics): a mounting board for a 2-way passive speaker crossover, 6 mm plywood.
# Base 160 x 110 mm (R4 corners) screwed inside the cabinet by four M4 flat-head screws, holes
# 6 mm in from each corner, countersunk 8 mm. On the base: a 45 mm air-core coil (its outline
# engraved, a 5 mm hole at its centre for a nylon screw) at 40 mm from the left edge and 55 mm
# up; two film capacitors 20 x 45 mm (outlines engraved) centred at x 95 and x 130, y 55, each
# held by two cable ties: a pair of 5 x 2 mm tie slots 3 mm beside each long side, 12 mm above
# and below the capacitor's middle. Labels "L1 0.56mH", "C1 6.8uF", "C2 3.3uF" engraved below
# the parts, and "2-WAY XO 2.5kHz" along the front edge. A terminal plate 160 x 60 mm stands on
# the base with its back face 6 mm in from the base's back edge, glued in by two 20 mm tabs; it
# carries two pairs of binding posts (9 mm holes, 19 mm apart in a pair, pairs 70 mm apart
# centre to centre, 35 mm above the base), "+" and "-" engraved above each post and "WOOFER" /
# "TWEETER" below each pair.

units mm
thickness 6 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

base_w = 160
base_d = 110
term_h = 60
t = 6
post_pitch = 19
pair_pitch = 70
post_y = 35
plane_y = base_d - 6 - t / 2   # the terminal plate's mid-plane on the base

assembly crossover {
    solid base {
        body = RoundedRectangle(bottom_left=(0, 0), width=base_w, height=base_d, corner_radius=4)
        Fixed(body)

        screw = clearance_hole(size=4)
        screws = CornerPattern(screw, body, inset=6)
        Countersink(screws, diameter=8)

        hole coil_screw { c = Circle(center=(40, 55), diameter=5) }

        drawing parts {
            coil = Circle(center=(40, 55), diameter=45)
            c1 = Rectangle(center=(95, 55), width=20, height=45)
            c2 = Rectangle(center=(130, 55), width=20, height=45)
        }

        for cx in [95, 130] {
            for side in [-1, 1] {
                for dy in [-12, 12] {
                    hole tie {
                        s = Slot(center=(cx + side * (10 + 3 + 1), 55 + dy), length=5, width=2,
                                 rotation=90)
                    }
                }
            }
        }

        drawing labels {
            l1 = Text("L1 0.56mH", position=(40, 22), size=4)
            lc1 = Text("C1 6.8uF", position=(95, 22), size=4)
            lc2 = Text("C2 3.3uF", position=(130, 22), size=4)
            title = Text("2-WAY XO 2.5kHz", position=(base_w / 2, 8), size=5)
        }

        j = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=2, tab=20, screw=0,
                         clearance=0.1, cx=base_w / 2, cy=plane_y)
    }

    solid term {
        body = Rectangle(bottom_left=(0, -t), width=base_w, height=term_h + t)
        Fixed(body)
        j = tab_and_slot(part="tab", length=base_w, thickness=t, tabs=2, tab=20, screw=0,
                         rotation=180, cx=base_w / 2, cy=-t)

        for k in range(4) {
            hole post {
                c = Circle(center=(base_w / 2 + (k // 2 - 0.5) * pair_pitch + (k % 2 - 0.5) * post_pitch,
                                   post_y), diameter=9)
            }
        }
        drawing signs {
            for k in range(4) {
                s = Text("+" if k % 2 == 0 else "-",
                         position=(base_w / 2 + (k // 2 - 0.5) * pair_pitch + (k % 2 - 0.5) * post_pitch,
                                   post_y + 9), size=5)
            }
            w = Text("WOOFER", position=(base_w / 2 - pair_pitch / 2, post_y - 14), size=4)
            tw = Text("TWEETER", position=(base_w / 2 + pair_pitch / 2, post_y - 14), size=4)
        }
    }

    Above(term, base, gap=10)
    AlignLeft(term, base)

    Place(base, position=(0, 0, 0))
    Place(term, position=(0, base_d - 6, t), face="front", up="up")

    assert len(base.screws) == 4, "four screws"
    assert base.screws[0].c.center.x - base.body.bb.left == 6 mm, "screws 6 mm in"
    assert base.screws[0].c.center.y - base.body.bb.bottom == 6 mm, "screws 6 mm in"
    assert base.body.bb.width == 160 mm and base.body.bb.height == 110 mm, "base 160 x 110"
    assert len(term.post) == 4, "two pairs of posts"
    assert term.post[1].c.center.x - term.post[0].c.center.x == 19 mm, "19 mm in a pair"
    assert term.post[2].c.center.x - term.post[0].c.center.x == 70 mm, "pairs 70 mm apart"
    assert term.post[0].c.center.y - term.body.bb.bottom == 35 mm + t, "posts 35 mm above the base"
    assert base.coil_screw.c.center.x - base.body.bb.left == 40 mm, "coil at x 40"
    assert base_d - (plane_y + t / 2) == 6 mm, "terminal plate 6 mm in from the back edge"
    # the middle gap (between the two tabs) lies between the two slots, within the clearance
    assert abs((base.j.slot[0].bb.right - base.body.bb.left) -
        (term.j.gap[1].bb.left - term.body.bb.left)) <= 0.1 mm, "tabs over their slots"
    assert abs((base.j.slot[1].bb.left - base.body.bb.left) -
        (term.j.gap[1].bb.right - term.body.bb.left)) <= 0.1 mm, "tabs over their slots"
    assert distance(base.labels, base.tie) >= 1 mm, "labels clear of the tie slots"
}
