# Request: a clip-on drinks table for a garden parasol, cut from 6 mm exterior ply. A round top
# 400 mm across, split across its middle into two halves so it goes round the pole without
# taking the parasol down; a 40 mm hole at the centre for the 38 mm pole. The halves lock edge
# to edge with two flat sliding dovetails, one either side of the pole, each 150 mm long with
# 2 tails 12 mm deep at 10 deg, 0.15 mm clearance, starting 35 mm from the centre. Four cup
# holes 85 mm across on a 280 mm circle at 45, 135, 225 and 315 deg (two in each half, clear of
# the split). "GARDEN BAR" engraved filled, 10 mm tall, near the rim between the cups on one
# half, "CHEERS" on the other, each reading from its own side. It rests on a hose clip
# tightened round the pole (bought).

thickness 6 mm

import "std/joints.aidl"

R = 200 mm
pole_d = 40 mm
cup_d = 85 mm
cup_r = 140 mm
dt_len = 150 mm
dt_depth = 12 mm
dt_from = 35 mm              # joint starts this far from the centre
dt_c = dt_from + dt_len / 2  # joint centre's distance from the centre

assembly parasol_table {
    solid half_a {
        top = Sector(center=(0, 0), radius=R, start_angle=0 deg, end_angle=180 deg)
        sock_l = dovetail(part="socket", length=dt_len, depth=dt_depth, tails=2, angle=10 deg,
                          clearance=0.15 mm, cx=-dt_c, cy=0)
        sock_r = dovetail(part="socket", length=dt_len, depth=dt_depth, tails=2, angle=10 deg,
                          clearance=0.15 mm, cx=dt_c, cy=0)
        hole pole {
            c = Circle(center=(0, 0), diameter=pole_d)
        }
        hole cups {
            for a in [45, 135] {
                c = Circle(center=(cup_r * cos(a * 1 deg), cup_r * sin(a * 1 deg)), diameter=cup_d)
            }
        }
        drawing label {
            t = Text("GARDEN BAR", position=(0, 168), size=10, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    solid half_b {
        top = Sector(center=(0, 0), radius=R, start_angle=180 deg, end_angle=360 deg)
        # the tail half reaches across the joint's band into the other half
        band_l = Rectangle(center=(-dt_c, dt_depth / 2), width=dt_len, height=dt_depth)
        band_r = Rectangle(center=(dt_c, dt_depth / 2), width=dt_len, height=dt_depth)
        tail_l = dovetail(part="tail", length=dt_len, depth=dt_depth, tails=2, angle=10 deg,
                          cx=-dt_c, cy=0)
        tail_r = dovetail(part="tail", length=dt_len, depth=dt_depth, tails=2, angle=10 deg,
                          cx=dt_c, cy=0)
        hole pole {
            c = Circle(center=(0, 0), diameter=pole_d)
        }
        hole cups {
            for a in [225, 315] {
                c = Circle(center=(cup_r * cos(a * 1 deg), cup_r * sin(a * 1 deg)), diameter=cup_d)
            }
        }
        drawing label {
            t = Text("CHEERS", position=(0, -168), size=10, font="sans:Bold", valign="middle",
                     rotation=180 deg, fill=true)
        }
    }

    # both halves lie flat at table height, as cut: the drawing is the assembled table
    Place(half_a, position=(0, 0, 700), face="up")
    Place(half_b, position=(0, 0, 700), face="up")

    # the request's numbers
    assert 2 * half_a.top.radius == 400 mm and 2 * half_b.top.radius == 400 mm, "400 across"
    assert half_a.pole.c.diameter == 40 mm and half_a.pole.c.diameter > 38 mm, "40 hole, 38 pole"
    assert len(half_a.cups.c) + len(half_b.cups.c) == 4, "four cups"
    assert half_a.cups.c[0].diameter == 85 mm, "85 mm cups"
    assert distance(half_a.cups.c[0].center, half_a.top.center) == 280 mm / 2, "280 circle"
    assert distance(half_b.cups.c[1].center, half_b.top.center) == 280 mm / 2, "280 circle"
    assert half_a.cups.bb.bottom >= half_a.top.center.y + 12 mm + 3 mm, "cups clear of the joint"
    assert R - (cup_r + cup_d / 2) >= 15 mm, "a 15 mm rim outside the cups"
    assert half_b.tail_r.bb.left - half_b.top.center.x == 35 mm, "joint starts 35 from centre"
    assert half_b.tail_r.bb.width <= 150 mm, "joint 150 long"
    assert half_a.label.t.size == 10 mm and half_b.label.t.size == 10 mm, "labels 10 tall"
    assert distance(half_a.label, half_a.cups) >= 3 mm, "label clear of the cups"
    assert distance(half_b.label, half_b.cups) >= 3 mm, "label clear of the cups"
}
