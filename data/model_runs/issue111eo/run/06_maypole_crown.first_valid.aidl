# Request: a May Day maypole crown in 6 mm exterior ply, glued onto a 25 mm dowel spigot at the
# top of the pole. A disc 300 mm across with a 25 mm centre hole for the spigot and 12 ribbon
# holes 10 mm across on a 276 mm circle (the first at 15 degrees, so they sit between the
# arches' feet). On the disc, engraved filled in bold serif 14 mm: "MAY DAY" over the top of a
# 190 mm circle and "2027" under it. Two half-ring arches cross over the middle: bands 15 mm
# wide, 280 mm across the outside (R140, R125 inside), each foot a single 9 mm tab through the
# disc into a mortise; the arches cross-halve at the top (one slotted from the top, one from
# underneath, 7.5 mm each). Eight 6 mm flower holes along each arch, every 20 degrees from
# 20 to 160.

import "std/joints.aidl"

t = 6 mm
thickness t

disc_d = 300 mm
r_out = 140 mm
r_in = 125 mm
band = r_out - r_in
foot_x = (r_out + r_in) / 2
tab_w = 9 mm

def arch(from_top=true) -> solid {
    # the tabs' tips on y = 0, the arch's shoulders (resting on the disc) on y = t
    ring = Sector(center=(0, t), radius=r_out, start_angle=0 deg, end_angle=180 deg,
                  inner_radius=r_in)
    right_foot = Rectangle(corner=(r_in, 0), opposite=(r_out, t))
    left_foot = Rectangle(corner=(-r_out, 0), opposite=(-r_in, t))
    right_tab = tab_and_slot(part="tab", length=band, thickness=t, tabs=1, tab=tab_w, screw=0,
                             rotation=180 deg, cx=foot_x, cy=0 mm)
    left_tab = tab_and_slot(part="tab", length=band, thickness=t, tabs=1, tab=tab_w, screw=0,
                            rotation=180 deg, cx=-foot_x, cy=0 mm)
    if from_top {
        halving = cross_halving(depth=band / 2, thickness=t, cx=0 mm, cy=t + r_out)
    } else {
        halving = cross_halving(depth=band / 2, thickness=t, rotation=180 deg, cx=0 mm,
                                cy=t + r_in)
    }
    hole flower {
        f = Circle(center=(foot_x * cos(20 deg), t + foot_x * sin(20 deg)), diameter=6)
    }
    flowers = CircularPattern(flower, 8, ring.center, step=20 deg)
}

assembly crown {
    solid disc {
        plate = Circle(center=(0, 0), diameter=disc_d)
        hole spigot { c = Circle(center=(0, 0), diameter=25) }
        hole ribbon { c = Circle(center=(138 * cos(15 deg), 138 * sin(15 deg)), diameter=10) }
        ribbons = CircularPattern(ribbon, 12, plate.center)
        east = tab_and_slot(part="slot", length=band, thickness=t, tabs=1, tab=tab_w, screw=0,
                            cx=foot_x, cy=0 mm)
        west = tab_and_slot(part="slot", length=band, thickness=t, tabs=1, tab=tab_w, screw=0,
                            cx=-foot_x, cy=0 mm)
        north = tab_and_slot(part="slot", length=band, thickness=t, tabs=1, tab=tab_w, screw=0,
                             rotation=90 deg, cx=0 mm, cy=foot_x)
        south = tab_and_slot(part="slot", length=band, thickness=t, tabs=1, tab=tab_w, screw=0,
                             rotation=90 deg, cx=0 mm, cy=-foot_x)
        drawing words {
            ring = Circle(center=(0, 0), diameter=190, construction=true)
            top = Text("MAY DAY", along=ring, size=14, font="serif:Bold", fill=true)
            bottom = Text("2027", along=ring, size=14, font="serif:Bold", fill=true, flip=true)
        }
    }

    arch_a = arch(from_top=true)
    arch_b = arch(from_top=false)

    # on the sheet
    RightOf(arch_a, disc, gap=8)
    AlignTop(arch_a, disc)
    Below(arch_b, arch_a, gap=8)
    AlignLeft(arch_b, arch_a)

    # in 3D: the disc flat on z = 0; arch A in the x-z plane, arch B in the y-z plane,
    # each centred on its axis, tabs flush with the disc's underside
    Place(disc, position=(0, 0, 0), face="up")
    Place(arch_a, position=(0, t / 2, 0), face="front", up="up")
    Place(arch_b, position=(-t / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert disc.plate.diameter == 300 mm and disc.spigot.c.diameter == 25 mm
    assert len(disc.ribbons) == 12 and disc.ribbon.c.diameter == 10 mm
    assert distance(disc.ribbons[0].c.center, disc.plate.center) == 138 mm
    assert arch_a.ring.radius == 140 mm and arch_a.ring.inner_radius == 125 mm
    assert arch_a.bb.width == 280 mm
    assert arch_a.halving.depth + arch_b.halving.depth == 15 mm, "halvings meet"
    assert len(arch_a.flowers) == 8 and arch_a.flower.f.diameter == 6 mm
    assert disc.east.slot[0].bb.width == 9 mm and disc.north.slot[0].bb.height == 9 mm
    assert disc.words.top.size == 14 mm
    assert distance(disc.words, disc.north) >= 5 mm and distance(disc.words, disc.south) >= 5 mm
    assert distance(disc.ribbons[0], disc.east) >= 10 mm
}
