# Request (home): a drum pendant lampshade in 3 mm birch ply, glued. Two rings 200 mm
# across with a 22 mm band (156 mm opening). The top ring also has a 64 mm hub with a
# 42 mm hole for an E27 lampholder's threaded ring, held by three 10 mm spokes at 90, 210
# and 330 deg. Eight ribs stand radially between the rings, 180 mm apart: each rib's
# inner edge is straight at 82 mm from the axis, its outer edge an arc bulging from
# 100 mm at the rings to 118 mm at mid-height (a barrel shade); three 10 mm round
# windows up its middle (98 mm from the axis, at 55, 90 and 125 mm up). A 10 x 3 mm tab
# at each end of a rib (85..95 mm from the axis) is glued into a 10.2 x 3.2 mm radial
# mortise in each ring, one every 45 deg.

thickness 3 mm

param ribs = 8, min = 6, max = 12

def ring(hub=false) -> solid {
    solid band {
        disc = Circle(center=(0, 0), diameter=200)
        hole opening { c = Circle(center=(0, 0), diameter=156) }
    }
    if hub {
        solid holder {
            boss = Circle(center=(0, 0), diameter=64)
            for k in range(3) {
                spoke = Rectangle(center=(55 * cos(90 deg + k * 120 deg), 55 * sin(90 deg + k * 120 deg)),
                                  width=54, height=10, rotation=90 deg + k * 120 deg)
            }
            hole lampholder { c = Circle(center=(0, 0), diameter=42) }
        }
    }
    hole mortises {
        for i in range(ribs) {
            m = Rectangle(center=(90 * cos(i * 360 deg / ribs), 90 * sin(i * 360 deg / ribs)),
                          width=10.2, height=3.2, rotation=i * 360 deg / ribs)
        }
    }
    assert band.disc.diameter == 200 mm, "rings 200 mm across"
    assert band.opening.c.diameter == 156 mm, "156 mm opening (22 mm band)"
    assert len(mortises.m) == ribs, "one mortise per rib"
}

def rib() -> solid {
    # x: distance from the shade's axis, y: height above the bottom ring
    body = Intersect(Circle(center=(-116, 90), radius=234),
                     Rectangle(bottom_left=(82, 0), width=50, height=180))
    tab_top = Rectangle(bottom_left=(85, 180), width=10, height=3)
    tab_bottom = Rectangle(bottom_left=(85, -3), width=10, height=3)
    hole windows {
        for j in range(3) {
            w = Circle(center=(98, 55 + j * 35), diameter=10)
        }
    }
    assert body.bb.height == 180 mm, "rings 180 mm apart"
    assert abs(body.bb.right - 118 mm) < 0.01 mm, "outer edge bulges to 118 mm"
    assert tab_top.width == 10 mm and tab_top.height == 3 mm, "10 x 3 tabs"
}

assembly lampshade {
    top = ring(hub=true)
    bottom = ring(hub=false)
    RightOf(bottom, top, gap=10)
    AlignCenterY(bottom, top)
    for i in range(ribs) {
        r = rib()
        Below(r, top, gap=10)
        r.bb.left == top.bb.left + i * 45 mm
    }
    assert len(r) == 8, "eight ribs"
    assert top.holder.lampholder.c.diameter == 42 mm, "42 mm lampholder hole"
    assert top.holder.boss.diameter == 64 mm, "64 mm hub"
}
