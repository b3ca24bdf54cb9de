# Request: "A taco holder that keeps three filled tacos upright on the plate, 6 mm birch ply.
# Two wavy side rails 240 x 70 mm, each with three round dips of 30 mm radius, 35 mm deep,
# centres 80 mm apart, where the dips meet the top edge rounded r4 and the rails' two top
# corners r6; a 140 x 8 mm relief in the middle of the bottom edge leaves two feet. The
# rails stand 100 mm apart (inside faces), joined by three 20 mm tall cross bars at x = -100,
# 0 and 100 mm (their middles 22 mm above the table), whose 12 mm wide tenons go through
# mortises in the rails with 0.1 mm play."

import "std/joints.aidl"

units mm
thickness 6 mm

ply = 6 mm
rail_len = 240 mm
rail_h = 70 mm
dip_r = 30 mm
dip_depth = 35 mm
dip_pitch = 80 mm
inside = 100 mm
bar_h = 20 mm
bar_y = 22 mm
tenon = 12 mm
bar_xs = [-100 mm, 0 mm, 100 mm]

def rail() -> solid {
    body = Rectangle(bottom_left=(-rail_len / 2, 0), width=rail_len, height=rail_h)
    for i in range(3) {
        hole dip {
            c = Circle(center=((i - 1) * dip_pitch, rail_h - dip_depth + dip_r), radius=dip_r)
        }
    }
    hole relief {
        r = Rectangle(center=(0, 4), width=140, height=8)
        o = Rectangle(center=(0, -0.5), width=140, height=1, overrun=true)
    }
    for x in bar_xs {
        m = tab_and_slot(part="slot", length=bar_h, thickness=ply, tabs=1, tab=tenon, screw=0,
                         clearance=0.1 mm, rotation=90 deg, cx=x, cy=bar_y)
    }
    Fillet([[body, dip[0].c], [body, dip[1].c], [body, dip[2].c]], 4)
    Fillet([body.top_left, body.top_right], 6)
}

def bar() -> solid {
    # 100 mm between the shoulders, a 6 mm tenon at each end
    body = Rectangle(center=(0, 0), width=inside + 2 * ply, height=bar_h)
    left_t = tab_and_slot(part="tab", length=bar_h, thickness=ply, tabs=1, tab=tenon, screw=0,
                          rotation=90 deg, cx=-(inside / 2 + ply), cy=0)
    right_t = tab_and_slot(part="tab", length=bar_h, thickness=ply, tabs=1, tab=tenon, screw=0,
                           rotation=-90 deg, cx=inside / 2 + ply, cy=0)
}

assembly taco_holder {
    front = rail()
    back = rail()
    for x in bar_xs {
        b = bar()
    }
    # on the sheet
    Above(back, front, gap=6)
    AlignCenterX(back, front)
    Below(b[0], front, gap=6)
    AlignLeft(b[0], front)
    RightOf(b[1], b[0], gap=6)
    AlignCenterY(b[1], b[0])
    RightOf(b[2], b[1], gap=6)
    AlignCenterY(b[2], b[1])
    # assembled: the rails stand up 100 mm apart, the bars across them
    Place(front, position=(0, -inside / 2, 0), rotation=(90 deg, 0, 0))
    Place(back, position=(0, inside / 2 + ply, 0), rotation=(90 deg, 0, 0))
    for i in range(3) {
        Place(b[i], position=(bar_xs[i] - ply / 2, 0, bar_y), rotation=(90 deg, 0, 90 deg))
    }

    # the request's numbers
    assert abs(front.body.bb.width - 240 mm) < 0.01 and abs(front.body.bb.height - 70 mm) < 0.01,
        "rail 240 x 70"
    assert abs(front.dip[0].c.radius - 30 mm) < 0.01, "dips r30"
    assert abs((front.body.bb.top - front.dip[1].c.bb.bottom) - 35 mm) < 0.01, "dips 35 deep"
    assert abs((front.dip[1].c.center.x - front.dip[0].c.center.x) - 80 mm) < 0.01 and
        abs((front.dip[2].c.center.x - front.dip[1].c.center.x) - 80 mm) < 0.01, "dips 80 apart"
    assert abs(front.relief.r.bb.width - 140 mm) < 0.01 and abs(front.relief.r.bb.height - 8 mm) < 0.01,
        "relief 140 x 8"
    assert len(b) == 3, "three bars"
    assert abs(b[0].body.bb.height - 20 mm) < 0.01, "bars 20 tall"
    assert abs((b[0].right_t.bb.left - b[0].left_t.bb.right) - 100 mm) < 0.01,
        "100 mm between the shoulders"
    assert abs(front.m[0].slot[0].bb.height - 12.1 mm) < 0.01, "mortise 12 + 0.1"
    assert abs(front.m[0].slot[0].bb.center_x - front.body.bb.center_x - (-100 mm)) < 0.01,
        "first bar at x = -100"
    assert abs(front.m[1].slot[0].bb.center_y - front.body.bb.bottom - 22 mm) < 0.01,
        "bars' middles 22 mm up"
    # the bars stay clear of the tacos: their tops below the dips' bottoms
    assert bar_y + bar_h / 2 < rail_h - dip_depth, "bars below the dips"
}
