# Request: a propagation station for rooting three plant cuttings in 25 mm x 150 mm glass test
# tubes, in 4 mm birch ply, glued. Base 200 x 80, corners R6, with a 12 mm seat hole under each
# tube so its round bottom stays put. Two uprights 60 deep, standing 160 mm above the base's
# top face with a fully rounded top (R30), each on two 15 mm tenons into mortises through the
# base; their inner faces 170 mm apart, centred on the base. A rail 40 deep spanning between
# them, its bottom face 110 mm above the base's top face, fixed by one 20 mm tenon at each
# end through a mortise in each upright (flush outside); three 26 mm holes in the rail 55 mm
# apart, centred, right over the seats. Each upright's outer face engraved with a leaf 40 mm
# long and 16 mm wide (two R29 arcs) with a centre vein, 60 mm above the base. Mortises
# 0.1 mm over. Laid out flat to cut, 8 mm apart; assembled for a look.

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
base_w = 200 mm
base_d = 80 mm
up_d = 60 mm
up_h = 160 mm
inner = 170 mm
rail_d = 40 mm
rail_z = 110 mm       # rail's bottom face over the base's top face
tube_hole = 26 mm
pitch = 55 mm
ux = inner / 2 + t / 2  # uprights' middle planes

def upright() -> solid {
    body = RoundedRectangle(bottom_left=(-up_d / 2, -t), width=up_d, height=up_h + t,
                            corner_radii=[up_d / 2, up_d / 2, 0, 0])
    feet = tab_and_slot(part="tab", length=up_d, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0, cy=-t)
    rail_mortise = tab_and_slot(part="slot", length=rail_d, thickness=t, tabs=1, tab=20 mm,
                                screw=0, clearance=0.1 mm, cx=0, cy=rail_z + t / 2)
    drawing leaf {
        a = Circle(center=(-21, 60), radius=29, construction=true)
        b = Circle(center=(21, 60), radius=29, construction=true)
        outline = Intersect(a, b)
        vein = Line((0, 43), (0, 77))
    }
}

assembly station {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=base_w, height=base_d, corner_radius=6)
        left_mortise = tab_and_slot(part="slot", length=up_d, thickness=t, tabs=2, tab=15 mm,
                                    screw=0, clearance=0.1 mm, rotation=90 deg, cx=-ux, cy=0)
        right_mortise = tab_and_slot(part="slot", length=up_d, thickness=t, tabs=2, tab=15 mm,
                                     screw=0, clearance=0.1 mm, rotation=90 deg, cx=ux, cy=0)
        hole seat {
            for i in range(3) {
                c = Circle(center=((i - 1) * pitch, 0), diameter=12)
            }
        }
    }

    solid rail {
        body = Rectangle(center=(0, 0), width=inner + 2 * t, height=rail_d)
        left_tenon = tab_and_slot(part="tab", length=rail_d, thickness=t, tabs=1, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-(inner / 2 + t), cy=0)
        right_tenon = tab_and_slot(part="tab", length=rail_d, thickness=t, tabs=1, tab=20 mm,
                                   screw=0, rotation=-90 deg, cx=inner / 2 + t, cy=0)
        hole tube {
            for i in range(3) {
                c = Circle(center=((i - 1) * pitch, 0), diameter=tube_hole)
            }
        }
    }

    left_upright = upright()
    right_upright = upright()

    # flat, to cut
    Below(rail, base, gap=8)
    AlignLeft(rail, base)
    RightOf(left_upright, base, gap=8)
    AlignTop(left_upright, base)
    RightOf(right_upright, left_upright, gap=8)
    AlignTop(right_upright, base)

    # assembled: the base on z = 0, the uprights' outer faces outward
    Place(base, position=(0, 0, 0), face="up")
    Place(rail, position=(0, 0, t + rail_z), face="up")
    Place(left_upright, position=(-inner / 2, 0, t), face="left")
    Place(right_upright, position=(inner / 2, 0, t), face="right")

    # the request's numbers
    assert base.body.width == 200 mm and base.body.height == 80 mm, "base 200 x 80"
    assert len(base.seat.c) == 3 and base.seat.c[0].diameter == 12 mm, "three 12 mm seats"
    assert left_upright.body.bb.top - (left_upright.body.bb.bottom + t) == 160 mm, "uprights 160 above the base"
    assert left_upright.body.bb.width == 60 mm, "uprights 60 deep"
    assert 2 * (ux - t / 2) == 170 mm, "inner faces 170 apart"
    assert rail.body.height == 40 mm, "rail 40 deep"
    assert left_upright.rail_mortise.slot[0].bb.bottom + 0.05 mm == t + 110 mm - t, "rail 110 above the base"
    assert rail.tube.c[0].diameter == 26 mm, "26 mm tube holes"
    assert rail.tube.c[1].center.x - rail.tube.c[0].center.x == 55 mm, "55 apart"
    assert rail.tube.c[1].center.x == rail.body.center.x, "holes centred"
    assert rail.tube.c[2].center.x == base.seat.c[2].center.x and
        rail.tube.c[2].center.y == base.seat.c[2].center.y, "holes over the seats"
    assert left_upright.leaf.outline.bb.height == 40 mm and left_upright.leaf.outline.bb.width == 16 mm,
        "leaf 40 x 16"
    assert distance(left_upright.leaf, left_upright.rail_mortise) >= 3 mm, "leaf clear of the mortise"
    assert up_h + t - 4 mm >= rail_z + 150 mm - 110 mm, "tube's top below the uprights' tops"
}
