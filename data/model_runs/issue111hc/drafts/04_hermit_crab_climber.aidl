# Request (pets): a climbing tree for my hermit crabs' tank, in 3 mm acrylic. Two
# tree-shaped panels, each 155 mm tall (tabs included) and 116 mm wide: a trunk 30 mm
# wide flaring to 100 mm at the foot over its lowest 30 mm, a round crown (33 mm
# radius, its top at 155 mm) between two side lobes (26 mm radius, centred 32 mm
# either side at 100 mm up). The panels slot together crosswise (a cross halving, one
# from the top, one from the bottom, each 77.5 mm deep) and stand on a 140 mm round
# base, each by two glued 15 mm tabs 50 mm apart. Each side lobe has five 7 mm grip
# holes on a 13 mm radius round its centre. SHELLDON is engraved on the base, 8 mm
# bold letters, filled, reading the right way up along its front edge (their
# baselines on a 56 mm radius circle, the letters inside it).

import "std/joints.aidl"

thickness 3 mm

tree_h = 155 mm
lobe_x = 32 mm
lobe_y = 100 mm
lobe_r = 26 mm
half = tree_h / 2

def tree_panel(from_top=true) -> solid {
    trunk = Rectangle(center=(0, 55), width=30, height=110)
    foot = Trapezoid(center=(0, 15), bottom_width=100, top_width=30, height=30)
    crown = Circle(center=(0, 122), radius=33)
    lobe_l = Circle(center=(-32, 100), radius=26)
    lobe_r = Circle(center=(32, 100), radius=26)
    hole grips {
        for k in range(5) {
            gl = Circle(center=(-32 + 13 * cos(k * 72 deg), 100 + 13 * sin(k * 72 deg)), diameter=7)
            gr = Circle(center=(32 + 13 * cos(k * 72 deg), 100 + 13 * sin(k * 72 deg)), diameter=7)
        }
    }
    if from_top {
        h = cross_halving(depth=77.5 mm, thickness=3 mm, cx=0 mm, cy=155 mm)
    } else {
        h = cross_halving(depth=77.5 mm, thickness=3 mm, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    tabs = tab_and_slot(part="tab", length=100 mm, thickness=3 mm, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly climber {
    pa = tree_panel(from_top=true)
    pb = tree_panel(from_top=false)

    solid base {
        disc = Circle(center=(0, 0), diameter=140)
        slots_a = tab_and_slot(part="slot", length=100 mm, thickness=3 mm, tabs=2, tab=15 mm,
                               screw=0, rotation=0 deg, cx=0 mm, cy=0 mm)
        slots_b = tab_and_slot(part="slot", length=100 mm, thickness=3 mm, tabs=2, tab=15 mm,
                               screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
        drawing name {
            ring = Circle(center=(0, 0), radius=56, construction=true)
            t = Text("SHELLDON", along=ring, flip=true, size=8 mm, font="sans:Bold", fill=true)
        }
        Fixed(disc)
    }

    RightOf(pa, base, gap=10 mm)
    AlignBottom(pa, base)
    RightOf(pb, pa, gap=10 mm)
    AlignBottom(pb, pa)

    assert pa.bb.height == 155 mm, "155 mm tall"
    assert pa.bb.width == 116 mm, "116 mm wide"
    assert pa.h.depth + pb.h.depth == 155 mm, "the halvings meet"
    assert base.disc.diameter == 140 mm, "140 mm base"
    assert len(pa.grips.gl) == 5 and len(pa.grips.gr) == 5, "five grip holes a lobe"
    assert base.slots_a.slot[1].bb.center_x - base.slots_a.slot[0].bb.center_x == 50 mm,
        "tabs 50 mm apart"
    assert distance(base.name, base.slots_a) >= 5 mm, "name clear of the slots"
    assert distance(base.name, base.slots_b) >= 5 mm, "name clear of the slots"
}
