# Pets: a perch ladder for a budgie cage, 6 mm birch plywood, glued tab-and-slot joints.
# (attempt 1 used std tab_and_slot with tabs=1: E0405 "at least 2 tabs"; now drawn by hand)
# Two rails 250 mm long x 20 mm wide with fully rounded ends (R10), each with six
# mortises for the rungs (tab 8 mm + 0.2 clearance by 6 mm + 0.2), centred across the
# rail, the first 30 mm from the bottom end, 35 mm apart; a 6 mm hole 12 mm from the top
# end of each rail to hang it with a wire hook. Six rungs 14 mm tall, 80 mm between the
# rails (92 mm over the tabs), each end a single 8 mm tab 6 mm long, centred.

thickness 6 mm

def rail(length=250 mm, width=20 mm, t=6 mm) -> solid {
    body = RoundedRectangle(center=(0, length / 2), width=width, height=length,
                            corner_radius=width / 2)
    # tab_and_slot needs at least 2 tabs (E0405): one 8 mm mortise a rung, drawn by hand
    hole m {
        for i in range(6) {
            r = Rectangle(center=(0, 30 + i * 35), width=t + 0.2, height=8.2)
        }
    }
    hole hang {
        c = Circle(center=(0, length - 12), diameter=6)
    }
}

def rung(length=80 mm, height=14 mm, t=6 mm) -> solid {
    bar = Rectangle(center=(0, 0), width=length, height=height)
    # one 8 mm tab, t long, centred on each end (tab_and_slot needs 2 tabs or more)
    right_tab = Rectangle(center=(length / 2 + t / 2, 0), width=t, height=8)
    left_tab = Rectangle(center=(-length / 2 - t / 2, 0), width=t, height=8)
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
assert len(ladder.left.m.r) == 6, "six mortises a rail"
assert ladder.left.m.r[0].center.y - ladder.left.bb.bottom == 30 mm, "first mortise 30 from the bottom"
assert ladder.left.m.r[1].center.y - ladder.left.m.r[0].center.y == 35 mm, "mortises 35 apart"
assert ladder.left.m.r[0].width == 6.2 mm and ladder.left.m.r[0].height == 8.2 mm, "mortise 6.2 x 8.2"
assert ladder.left.m.r[0].center.x == ladder.left.body.center.x, "mortises centred across the rail"
assert ladder.left.bb.top - ladder.left.hang.c.center.y == 12 mm, "hang hole 12 from the top"
assert len(ladder.r) == 6, "six rungs"
assert ladder.r[0].bb.width == 92 mm and ladder.r[0].bb.height == 14 mm, "rung 92 over the tabs, 14 tall"
