# Pets: a perch ladder for a budgie cage, 6 mm birch plywood, glued tab-and-slot joints.
# Two rails 250 mm long x 20 mm wide with fully rounded ends (R10), each with six
# mortises for the rungs (tab 8 mm + 0.2 clearance by 6 mm + 0.2), centred across the
# rail, the first 30 mm from the bottom end, 35 mm apart; a 6 mm hole 12 mm from the top
# end of each rail to hang it with a wire hook. Six rungs 14 mm tall, 80 mm between the
# rails (92 mm over the tabs), each end a single 8 mm tab 6 mm long, centred.

import "std/joints.aidl"

thickness 6 mm

def rail(length=250 mm, width=20 mm, t=6 mm) -> solid {
    body = RoundedRectangle(center=(0, length / 2), width=width, height=length,
                            corner_radius=width / 2)
    for i in range(6) {
        m = tab_and_slot(part="slot", length=14 mm, thickness=t, tabs=1, tab=8 mm, screw=0,
                         clearance=0.2 mm, rotation=90 deg, cx=0 mm, cy=30 mm + i * 35 mm)
    }
    hole hang {
        c = Circle(center=(0, length - 12), diameter=6)
    }
}

def rung(length=80 mm, height=14 mm, t=6 mm) -> solid {
    bar = Rectangle(center=(0, 0), width=length + 2 * t, height=height)
    right_tab = tab_and_slot(part="tab", length=height, thickness=t, tabs=1, tab=8 mm,
                             screw=0, rotation=90 deg, cx=length / 2, cy=0 mm)
    left_tab = tab_and_slot(part="tab", length=height, thickness=t, tabs=1, tab=8 mm,
                            screw=0, rotation=-90 deg, cx=-length / 2, cy=0 mm)
}

assembly ladder {
    left = rail()
    right = rail()
    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    for i in range(6) {
        r = rung()
        r.bb.center == (110, 20 + i * 22)
    }
}

assert ladder.left.body.bb.height == 250 mm and ladder.left.body.bb.width == 20 mm, "rail 250 x 20"
assert len(ladder.left.m) == 6, "six mortises a rail"
assert ladder.left.m[0].bb.center_y - ladder.left.bb.bottom == 30 mm, "first mortise 30 from the bottom"
assert ladder.left.m[1].bb.center_y - ladder.left.m[0].bb.center_y == 35 mm, "mortises 35 apart"
assert ladder.left.m[0].bb.width == 6.2 mm and ladder.left.m[0].bb.height == 8.2 mm, "mortise 6.2 x 8.2"
assert ladder.left.bb.top - ladder.left.hang.c.center.y == 12 mm, "hang hole 12 from the top"
assert len(ladder.r) == 6, "six rungs"
assert ladder.r[0].bb.width == 92 mm and ladder.r[0].bb.height == 14 mm, "rung 92 over the tabs, 14 tall"
