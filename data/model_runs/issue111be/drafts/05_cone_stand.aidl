# Request (parties): an ice-cream cone stand for a kids' party, 3 mm birch ply. A 240 mm round
# top with eight 40 mm cone holes evenly on a 160 mm circle (the first at 22.5 deg, so none sits
# over the legs), "HAPPY BIRTHDAY" engraved 8 mm high along the top of the rim and "MIA 7"
# along the bottom; it sits 120 mm high (top face) on two 200 mm wide leg panels cross-halved
# into each other (one slotted from the top, one from the bottom), each with a shallow
# 120 x 30 mm arch cut from its bottom edge and two 20 mm tabs into slots in the top.

units mm
thickness 3 mm

import "std/joints.aidl"

t = 3 mm
top_d = 240 mm
cone_d = 40 mm
pcd = 160 mm
leg_w = 200 mm
stand_h = 120 mm             # top face above the floor
leg_h = stand_h - t          # the legs' shoulders carry the top; tab tips flush with its face

def leg(from_top=true) -> solid {
    body = Rectangle(bottom_left=(-leg_w / 2, 0), width=leg_w, height=leg_h + t)
    Fixed(body)
    tabs = tab_and_slot(part="tab", length=leg_w, thickness=t, tabs=2, tab=20, screw=0,
                        cx=0, cy=leg_h + t)
    hole arch { e = Ellipse(center=(0, 0), rx=60, ry=30) }
    if from_top {
        halving = cross_halving(depth=leg_h / 2, thickness=t, clearance=0.1, cx=0, cy=leg_h)
    } else {
        halving = cross_halving(depth=leg_h / 2, thickness=t, clearance=0.1, rotation=180 deg,
                                cx=0, cy=0)
    }
}

assembly cone_stand {
    solid top {
        disc = Circle(center=(0, 0), diameter=top_d)
        Fixed(disc)
        hole cone {
            c = Circle(center=(pcd / 2 * cos(22.5 deg), pcd / 2 * sin(22.5 deg)), diameter=cone_d)
        }
        cones = CircularPattern(cone, 8, disc.center)
        slots_x = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=2, tab=20, screw=0,
                               clearance=0.1, cx=0, cy=0)
        slots_y = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=2, tab=20, screw=0,
                               clearance=0.1, rotation=90 deg, cx=0, cy=0)
        drawing words {
            ring = Circle(center=(0, 0), radius=pcd / 2 + cone_d / 2 + 5, construction=true)
            over = Text("HAPPY BIRTHDAY", along=ring, size=8, font="sans:Bold", fill=true)
            under = Text("MIA 7", along=ring, size=8, flip=true, font="sans:Bold", fill=true)
        }
    }

    leg_a = leg(from_top=true)
    leg_b = leg(from_top=false)

    # on the sheet: the legs beside the top
    RightOf(leg_a, top, gap=6)
    RightOf(leg_b, top, gap=6)
    AlignTop(leg_a, top)
    Below(leg_b, leg_a, gap=6)

    # in 3D: the top flat on the legs' shoulders; leg_a along x, leg_b along y
    Place(top, position=(0, 0, leg_h))
    Place(leg_a, position=(0, t / 2, 0), rotation=(90 deg, 0, 0))
    Place(leg_b, position=(-t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    assert top.disc.diameter == 240 mm, "240 mm top"
    assert len(top.cones) == 8, "eight cones"
    assert top.cones[0].c.diameter == 40 mm, "40 mm cone holes"
    assert distance(top.cones[0].c.center, top.disc.center) == 160 mm / 2, "on a 160 circle"
    assert leg_a.body.bb.width == 200 mm and leg_b.body.bb.width == 200 mm, "legs 200 wide"
    assert leg_h + t == 120 mm, "top face 120 mm up"
    assert leg_a.arch.e.rx * 2 == 120 mm and leg_a.arch.e.ry == 30 mm, "arch 120 x 30"
    # the halvings meet: together they cross the whole leg below the shoulders
    assert leg_a.halving.depth + leg_b.halving.depth == leg_h, "halvings meet"
    # no cone hole reaches a leg (legs along the axes, t thick)
    assert pcd / 2 * sin(22.5 deg) - cone_d / 2 >= t / 2 + 5 mm, "cones clear the legs"
    assert top.words.over.size == 8 mm, "8 mm letters"
}
