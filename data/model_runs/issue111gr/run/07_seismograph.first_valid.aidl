# Request: a classroom pendulum seismograph, 6 mm ply. A 300 x 160 mm base (R8 corners).
# A gantry: two uprights 80 wide x 240 tall (top corners R10), standing across the base
# 130 mm apart (centres at y = -65 and 65), each with two 20 mm tabs glued into slots in
# the base; a top beam between them, 40 mm tall, its middle 210 mm above the underside of
# the base (the tips of the uprights' tabs), with a 20 mm tenon at each end through a mortise in each
# upright (0.2 mm clearance); a 4 x 4 mm notch in the middle of its bottom edge locates
# the pendulum string. The pendulum: three 70 mm discs glued into a mass, an 11 mm hole in
# the middle for a felt pen and two 3 mm string holes 50 mm apart. The paper strip (57 mm
# till roll) is pulled along the base between two rails 280 long x 20 tall standing on
# edge, 58 mm apart inside (centres at y = -32 and 32), each with three 20 mm tabs. Engraved
# on the base: "SEISMOGRAPH" (8 mm) in front of the rails at the right, "PULL PAPER ->"
# (6 mm) behind them.

import "std/joints.aidl"

t = 6 mm
thickness t

def base_plate() -> solid {
    body = RoundedRectangle(center=(0, 0), width=300, height=160, corner_radius=8)
    for y in [-65, 65] {
        upright_slots = tab_and_slot(part="slot", length=80 mm, thickness=6 mm, tabs=2,
                                     tab=20 mm, screw=0, clearance=0.2 mm, cx=0 mm, cy=y * 1 mm)
    }
    for y in [-32, 32] {
        rail_slots = tab_and_slot(part="slot", length=280 mm, thickness=6 mm, tabs=3,
                                  tab=20 mm, screw=0, clearance=0.2 mm, cx=0 mm, cy=y * 1 mm)
    }
    drawing words {
        name = Text("SEISMOGRAPH", position=(90, -48), size=8, valign="middle")
        pull = Text("PULL PAPER ->", position=(90, 48), size=6, valign="middle")
    }
}

def upright() -> solid {
    body = RoundedRectangle(bottom_left=(-40, 0), width=80, height=240, corner_radii=[10, 10, 0, 0])
    feet = tab_and_slot(part="tab", length=80 mm, thickness=6 mm, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    mortise = tab_and_slot(part="slot", length=40 mm, thickness=6 mm, tabs=1, tab=20 mm,
                           screw=0, clearance=0.2 mm, rotation=90 deg, cx=0 mm, cy=210 mm)
}

def top_beam() -> solid {
    body = Rectangle(center=(0, 0), width=136, height=40)
    tenon_l = tab_and_slot(part="tab", length=40 mm, thickness=6 mm, tabs=1, tab=20 mm,
                           screw=0, rotation=90 deg, cx=-68 mm, cy=0 mm)
    tenon_r = tab_and_slot(part="tab", length=40 mm, thickness=6 mm, tabs=1, tab=20 mm,
                           screw=0, rotation=-90 deg, cx=68 mm, cy=0 mm)
    hole string_notch { r = Rectangle(center=(0, -20), width=4, height=8, overrun=true) }
}

def rail() -> solid {
    body = Rectangle(bottom_left=(-140, 0), width=280, height=20)
    feet = tab_and_slot(part="tab", length=280 mm, thickness=6 mm, tabs=3, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
}

def mass_disc() -> solid {
    disc = Circle(center=(0, 0), diameter=70)
    hole pen { c = Circle(center=(0, 0), diameter=11) }
    hole strings {
        a = Circle(center=(-25, 0), diameter=3)
        b = Circle(center=(25, 0), diameter=3)
    }
}

assembly seismograph {
    base = base_plate()
    upright_a = upright()
    upright_b = upright()
    beam = top_beam()
    rail_a = rail()
    rail_b = rail()
    for k in range(3) {
        disc = mass_disc()
    }

    # flat on the sheet
    RightOf(upright_a, base, gap=8)
    AlignTop(upright_a, base)
    RightOf(upright_b, upright_a, gap=8)
    AlignTop(upright_b, upright_a)
    Below(beam, base, gap=8)
    AlignLeft(beam, base)
    Below(rail_a, beam, gap=8)
    AlignLeft(rail_a, beam)
    Below(rail_b, rail_a, gap=8)
    AlignLeft(rail_b, rail_a)
    RightOf(disc[0], beam, gap=8)
    AlignTop(disc[0], beam)
    RightOf(disc[1], disc[0], gap=8)
    AlignTop(disc[1], disc[0])
    RightOf(disc[2], disc[1], gap=8)
    AlignTop(disc[2], disc[1])

    # 3D: base on z = 0 .. 6; uprights and rails stand on it, tabs down into its slots
    Place(base, position=(0, 0, 0))
    Place(upright_a, position=(0, 68 mm, 0), face="front", up="up")
    Place(upright_b, position=(0, -62 mm, 0), face="front", up="up")
    Place(rail_a, position=(0, 35 mm, 0), face="front", up="up")
    Place(rail_b, position=(0, -29 mm, 0), face="front", up="up")
    # the beam across the uprights, length along y, its middle 210 mm up
    Place(beam, position=(-3 mm, 0, 210 mm), face="right", up="up")
    for k in range(3) {
        Place(disc[k], position=(0, 0, 60 mm + k * t))
    }

    # the request's numbers
    assert abs(base.body.width - 300 mm) < 0.01 mm and abs(base.body.height - 160 mm) < 0.01 mm, "base 300 x 160"
    assert abs(upright_a.body.width - 80 mm) < 0.01 mm and abs(upright_a.body.height - 240 mm) < 0.01 mm, "uprights 80 x 240"
    assert abs(base.upright_slots[1].slot[0].bb.center_y - base.upright_slots[0].slot[0].bb.center_y - 130 mm) < 0.01 mm, "uprights 130 mm apart"
    assert abs(beam.body.width - (130 mm + 6 mm)) < 0.01 mm, "beam reaches through both uprights"
    assert abs(upright_a.mortise.slot[0].bb.height - 20.2 mm) < 0.01 mm and abs(upright_a.mortise.slot[0].bb.width - 6.2 mm) < 0.01 mm, "mortise 20.2 x 6.2"
    assert abs(upright_a.mortise.slot[0].bb.center_y - upright_a.body.bb.bottom - 210 mm) < 0.01 mm, "mortise at the beam's middle, 210 mm up"
    assert abs(base.rail_slots[1].slot[0].bb.center_y - base.rail_slots[0].slot[0].bb.center_y - 6 mm - 58 mm) < 0.01 mm, "58 mm between the rails"
    assert len(disc) == 3, "three discs"
    assert abs(disc[0].pen.c.diameter - 11 mm) < 0.01 mm and abs(distance(disc[0].strings.a.center, disc[0].strings.b.center) - 50 mm) < 0.01 mm, "pen hole 11, strings 50 apart"
    assert distance(base.words, base.rail_slots[0]) >= 5 mm and distance(base.words, base.upright_slots[0]) >= 5 mm, "words clear of the slots"
}
