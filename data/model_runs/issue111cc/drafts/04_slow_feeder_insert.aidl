# Request: a slow-feeder insert for our greedy labrador's steel bowl (flat bottom 160 mm across,
# the wall flaring out about 15 deg). Cut in 5 mm acrylic (kerf 0.15 mm): a base disc 155 mm
# across with four 12 mm holes 50 mm from the middle (so it does not suck down in the wet bowl),
# and two fins 45 mm tall standing on it in an X, crossing at the middle at 90 deg, each fin
# 150 mm long at the bottom and 174 mm at the top (following the flare), top corners rounded r8.
# The fins are cross-halved into each other (0.1 mm play) and glued into the disc by two 15 mm
# tabs each (0.1 mm play). Each fin has two paw prints cut through it as finger grips, centred
# 50 mm either side of the middle and 24.5 mm up: a pad and four toes, about 30 mm across.
# The fins lie on the diagonals, the drain holes between them.

import "std/joints.aidl"

thickness 5 mm
kerf 0.15 mm

t = 5 mm
fin_h = 45 mm
fin_bottom = 150 mm
fin_top = 174 mm
play = 0.1 mm

def paw() -> hole {
    pad = Hull(Circle(center=(-4, -5), radius=5.5), Circle(center=(4, -5), radius=5.5),
               Circle(center=(0, 0), radius=5))
    toe1 = Ellipse(center=(-12, 7), rx=3.2, ry=4.2, rotation=25 deg)
    toe2 = Ellipse(center=(-4.5, 13), rx=3.2, ry=4.2, rotation=8 deg)
    toe3 = Ellipse(center=(4.5, 13), rx=3.2, ry=4.2, rotation=-8 deg)
    toe4 = Ellipse(center=(12, 7), rx=3.2, ry=4.2, rotation=-25 deg)
}

def fin(from_top=true) -> solid {
    web = Trapezoid(center=(0, fin_h / 2), bottom_width=fin_bottom, top_width=fin_top,
                    height=fin_h)
    band = Rectangle(bottom_left=(-fin_bottom / 2, -t), width=fin_bottom, height=t)
    tabs = tab_and_slot(part="tab", length=fin_bottom, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-t)
    if from_top {
        halving = cross_halving(depth=fin_h / 2, thickness=t, clearance=play, cx=0 mm, cy=fin_h)
    } else {
        halving = cross_halving(depth=fin_h / 2, thickness=t, clearance=play, rotation=180 deg,
                                cx=0 mm, cy=0 mm)
    }
    paw_l = paw()
    paw_r = paw()
    paw_l.bb.center == (-50 mm, 24.5 mm)
    paw_r.bb.center == (50 mm, 24.5 mm)
    Fillet(web.top_left, 8 mm)
    Fillet(web.top_right, 8 mm)
}

assembly feeder {
    solid base {
        disc = Circle(center=(0, 0), diameter=155 mm)
        slots_a = tab_and_slot(part="slot", length=fin_bottom, thickness=t, tabs=2, tab=15 mm,
                               screw=0, clearance=play, rotation=45 deg, cx=0 mm, cy=0 mm)
        slots_b = tab_and_slot(part="slot", length=fin_bottom, thickness=t, tabs=2, tab=15 mm,
                               screw=0, clearance=play, rotation=135 deg, cx=0 mm, cy=0 mm)
        hole drains {
            for k in range(4) {
                c = Circle(center=(50 mm * cos(k * 90 deg), 50 mm * sin(k * 90 deg)), diameter=12 mm)
            }
        }
    }
    fin_a = fin(from_top=true)
    fin_b = fin(from_top=false)

    # flat for cutting
    Fixed(base)
    RightOf(fin_a, base, gap=8 mm)
    RightOf(fin_b, base, gap=8 mm)
    Above(fin_a, fin_b, gap=8 mm)
    AlignBottom(fin_b, base)

    # assembled: fins upright on the disc along the two diagonals
    Place(base, position=(0, 0, 0))
    Place(fin_a, rotation=(90 deg, 0, 45 deg), position=(-t / 2 * sin(45 deg), t / 2 * cos(45 deg), t))
    Place(fin_b, rotation=(90 deg, 0, 135 deg), position=(-t / 2 * sin(135 deg), t / 2 * cos(135 deg), t))

    assert base.disc.diameter == 155 mm, "155 mm disc"
    assert len(base.drains.c) == 4 and base.drains.c[0].diameter == 12 mm, "four 12 mm drains"
    assert fin_a.web.height == 45 mm, "fins 45 mm tall"
    assert fin_a.web.bottom_width == 150 mm and fin_a.web.top_width == 174 mm, "fin lengths"
    assert fin_a.paw_r.bb.width <= 31 mm, "paw about 30 mm across"
    assert fin_a.paw_r.bb.center_x - fin_a.web.center.x == 50 mm, "paw 50 mm off the middle"
}
