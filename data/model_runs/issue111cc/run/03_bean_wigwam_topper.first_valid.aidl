# Request: a topper that gathers 8 bamboo canes (12 mm) into a runner-bean wigwam, 6 mm exterior
# ply. Two discs held 100 mm apart by two upright ribs: a top disc 120 mm across with eight
# 15 mm cane holes on an 80 mm circle, a bottom disc 180 mm across with eight 15 mm holes on a
# 140 mm circle, the holes at 22.5 deg + k x 45 deg so the canes lean out between the ribs.
# The ribs are cross-halved into each other (0.1 mm play) and glued into the discs by two 10 mm
# tabs at each end (0.1 mm play in the slots); each rib 60 mm wide at the top and 120 mm at the
# bottom. "RUNNER BEANS" engraved round the top disc outside the holes, 5 mm letters.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

t = 6 mm
gap_h = 100 mm        # between the discs
top_w = 60 mm
bottom_w = 120 mm
play = 0.1 mm

def cane_holes(pcd) -> hole {
    for k in range(8) {
        c = Circle(center=(pcd / 2 * cos(22.5 deg + k * 45 deg), pcd / 2 * sin(22.5 deg + k * 45 deg)),
                   diameter=15 mm)
    }
}

def disc(d, pcd, slot_len) -> solid {
    body = Circle(center=(0, 0), diameter=d)
    canes = cane_holes(pcd=pcd)
    slots_a = tab_and_slot(part="slot", length=slot_len, thickness=t, tabs=2, tab=10 mm, screw=0,
                           clearance=play, rotation=0 deg, cx=0 mm, cy=0 mm)
    slots_b = tab_and_slot(part="slot", length=slot_len, thickness=t, tabs=2, tab=10 mm, screw=0,
                           clearance=play, rotation=90 deg, cx=0 mm, cy=0 mm)
}

def rib(from_top=true) -> solid {
    web = Trapezoid(center=(0, gap_h / 2), bottom_width=bottom_w, top_width=top_w, height=gap_h)
    top_band = Rectangle(bottom_left=(-top_w / 2, gap_h), width=top_w, height=t)
    bottom_band = Rectangle(bottom_left=(-bottom_w / 2, -t), width=bottom_w, height=t)
    top_tabs = tab_and_slot(part="tab", length=top_w, thickness=t, tabs=2, tab=10 mm, screw=0,
                            rotation=0 deg, cx=0 mm, cy=gap_h + t)
    bottom_tabs = tab_and_slot(part="tab", length=bottom_w, thickness=t, tabs=2, tab=10 mm,
                               screw=0, rotation=180 deg, cx=0 mm, cy=-t)
    if from_top {
        halving = cross_halving(depth=gap_h / 2, thickness=t, clearance=play, cx=0 mm, cy=gap_h)
    } else {
        halving = cross_halving(depth=gap_h / 2, thickness=t, clearance=play, rotation=180 deg,
                                cx=0 mm, cy=0 mm)
    }
}

assembly topper {
    bottom_disc = disc(d=180 mm, pcd=140 mm, slot_len=bottom_w)
    top_disc = disc(d=120 mm, pcd=80 mm, slot_len=top_w)
    drawing label {
        words = text_on_arc(text="RUNNER BEANS", radius=51 mm, size=5 mm, angle=90 deg)
        ring = Circle(center=(0, 0), radius=51 mm, construction=true)
        Rigid(words, ring)
    }
    rib_a = rib(from_top=true)
    rib_b = rib(from_top=false)

    Concentric(label.ring, top_disc.body)
    CutInto(label, top_disc)

    # flat, side by side for cutting
    Fixed(bottom_disc)
    RightOf(top_disc, bottom_disc, gap=10 mm)
    RightOf(rib_a, top_disc, gap=10 mm)
    RightOf(rib_b, rib_a, gap=10 mm)
    AlignBottom(top_disc, bottom_disc)
    AlignBottom(rib_a, bottom_disc)
    AlignBottom(rib_b, bottom_disc)

    # assembled: bottom disc on the ground, ribs standing on it, top disc on the ribs
    Place(bottom_disc, position=(0, 0, 0))
    Place(rib_a, rotation=(90 deg, 0, 0), position=(0, t / 2, t))
    Place(rib_b, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, t))
    Place(top_disc, position=(0, 0, t + gap_h))

    assert bottom_disc.body.diameter == 180 mm and top_disc.body.diameter == 120 mm, "disc sizes"
    assert len(bottom_disc.canes.c) == 8 and len(top_disc.canes.c) == 8, "8 canes"
    assert top_disc.canes.c[0].diameter == 15 mm, "15 mm cane holes"
    assert rib_a.web.height == 100 mm, "discs 100 mm apart"
    assert rib_a.web.top_width == 60 mm and rib_a.web.bottom_width == 120 mm, "rib widths"
}
