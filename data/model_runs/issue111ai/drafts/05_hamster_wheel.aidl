# Request (pets): a silent 200 mm running wheel for a dwarf hamster, from 3 mm birch ply.
# The running surface is a solid band (no rungs to trap toes), bent round on a living hinge:
# 200 mm inside diameter, 60 mm deep, made as two half-bands (each half the circumference
# at the ply's mid-thickness, pi x 203 / 2) with four 12 mm tabs 3 mm long on each long edge,
# evenly spaced. The tabs sit in 3.2 mm x 12.2 mm curved slots (0.2 mm clearance) on a
# 101.5 mm radius in a closed back disc (220 mm) and an open front ring (220 mm outside,
# 180 mm inside, so a 10 mm lip keeps bedding in). The back disc has an 8.5 mm axle hole for
# an M8 bolt, six 28 mm windows on a 55 mm radius, and "PEANUT" engraved 10 mm high over the
# top on an 80 mm radius. Stand: an upright 60 mm wide, round-topped, whose 8.5 mm axle hole is
# 130 mm above the foot (20 mm under the wheel), glued by two 15 mm tabs into mortises in a
# 220 x 120 mm foot (corners R10) 40 mm behind the foot's centre line.

units mm
thickness 3 mm
import "std/joints.aidl"
import "std/plates.aidl"

ply = 3 mm
fit = 0.2 mm
run_d = 200 mm                      # inside diameter of the band: the running surface
r_mid = run_d / 2 + ply / 2         # the band's mid-thickness radius, 101.5
depth = 60 mm
band_len = pi * 2 * r_mid / 2       # half the circumference at mid-thickness
tab_w = 12 mm
disc_d = 220 mm
axle_d = 8.5 mm
axle_h = 130 mm
upright_h = ply + axle_h + 30 mm    # the top's 30 mm round is centred on the axle

def band_half() -> solid {
    body = Rectangle(center=(0, 0), width=band_len, height=depth)
    for k in range(4) {
        top_tab = Rectangle(center=((k + 0.5) * band_len / 4 - band_len / 2, depth / 2 + ply / 2),
                            width=tab_w, height=ply)
        bottom_tab = Rectangle(center=((k + 0.5) * band_len / 4 - band_len / 2,
                                       -depth / 2 - ply / 2), width=tab_w, height=ply)
    }
    flex = living_hinge(width=band_len - 4 mm, height=depth, pitch=2 mm, cut=15 mm,
                        bridge=3 mm)
}

# eight curved slots on the band's mid radius, one per tab: tab centres at 22.5 + 45 k deg
def tab_slots() -> hole {
    for k in range(8) {
        s = Sector(center=(0, 0), radius=r_mid + (ply + fit) / 2,
                   inner_radius=r_mid - (ply + fit) / 2,
                   start_angle=22.5 deg + k * 45 deg - (tab_w + fit) / r_mid * 1 rad / 2,
                   end_angle=22.5 deg + k * 45 deg + (tab_w + fit) / r_mid * 1 rad / 2)
    }
}

assembly wheel {
    solid back_disc {
        disc = Circle(center=(0, 0), diameter=disc_d)
        slots = tab_slots()
        hole axle { c = Circle(center=(0, 0), diameter=axle_d) }
        hole window { w = Circle(center=(55, 0), diameter=28) }
        windows = CircularPattern(window, 6, disc.center)
        drawing name {
            ring = Circle(center=(0, 0), radius=80, construction=true)
            t = Text("PEANUT", along=ring, size=10)
        }
    }

    solid front_ring {
        rim = Circle(center=(0, 0), diameter=disc_d)
        slots = tab_slots()
        hole opening { c = Circle(center=(0, 0), diameter=180) }
    }
    RightOf(front_ring, back_disc, gap=10)
    AlignCenterY(front_ring, back_disc)

    band_a = band_half()
    band_b = band_half()
    Below(band_a, back_disc, gap=10)
    AlignLeft(band_a, back_disc)
    Below(band_b, band_a, gap=10)
    AlignLeft(band_b, band_a)

    solid upright {
        body = RoundedRectangle(center=(0, 0), width=60, height=upright_h,
                                corner_radii=[30, 30, 0, 0])
        feet = tab_and_slot(part="tab", length=60 mm, thickness=ply, tabs=2, tab=15 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-upright_h / 2)
        hole axle { c = Circle(center=(0, -upright_h / 2 + ply + axle_h), diameter=axle_d) }
    }
    RightOf(upright, front_ring, gap=10)
    AlignTop(upright, front_ring)

    solid foot {
        body = RoundedRectangle(center=(0, 0), width=220, height=120, corner_radius=10)
        mortise = tab_and_slot(part="slot", length=60 mm, thickness=ply, tabs=2, tab=15 mm,
                               screw=0, clearance=fit, cx=0 mm, cy=40 mm)
    }
    RightOf(foot, band_a, gap=10)
    AlignTop(foot, band_a)

    assert 2 * r_mid - ply == 200 mm, "200 mm running diameter"
    assert band_a.body.height == 60 mm, "60 mm deep"
    assert 2 * band_a.body.width == pi * 203 mm, "two halves make the circumference"
    assert len(band_a.top_tab) == 4 and len(band_a.bottom_tab) == 4, "four tabs each edge"
    assert band_a.top_tab[0].width == 12 mm, "12 mm tabs"
    assert len(back_disc.slots.s) == 8, "eight slots, one per tab"
    assert back_disc.slots.s[0].width == 3.2 mm, "3.2 mm slots"
    assert back_disc.disc.diameter == 220 mm and front_ring.opening.c.diameter == 180 mm,
        "220 disc, 180 opening"
    assert len(back_disc.windows) == 6, "six windows"
    assert upright.axle.c.center.y - (upright.body.bb.bottom + ply) == 130 mm,
        "axle 130 mm above the foot"
    assert axle_h - disc_d / 2 == 20 mm, "20 mm under the wheel"
    assert distance(back_disc.slots.s[0].center, back_disc.disc.center) < 0.001 mm,
        "slots concentric with the disc"
    assert distance(front_ring.slots.s[0].center, front_ring.rim.center) < 0.001 mm,
        "slots concentric with the ring"
}
