# Request (electronics): a cage for two 3.5" hard drives in my home-built NAS, cut from 4 mm
# plywood, four parts glued with tabs into mortises:
# - a base 122 mm wide and 176 mm deep;
# - two side plates 170 mm long and 90 mm tall (tabs included) standing on the base, 102 mm
#   apart inside (a 101.6 mm drive plus 0.4 mm), each with 3 tabs 20 mm wide into the base and
#   2 tabs 20 mm wide into the front plate; each has four 3.6 mm holes for 6-32 drive screws:
#   28.5 mm and 101.6 mm behind the drive's front face, which sits 19 mm behind the cage front,
#   and 6.35 mm above each drive's bottom; the lower drive's bottom 6 mm above the base, the
#   drives 38.1 mm apart (26.1 mm drive plus 12 mm of air); "BAY 1" and "BAY 2" engraved on
#   the outside of each side beside its drive's holes. The two sides are mirror images.
# - a front plate 122 mm wide and 90 mm tall that carries an 80 mm fan: four 4.3 mm holes on
#   a 71.5 mm square, and a grille of 7 mm holes on a staggered 9 mm grid within 33 mm of the
#   fan's axis, the fan's axis 47 mm above the bottom of the cage; 3 tabs 20 mm into the base.
# The drives slide in from the back, so the SATA plugs stay free.

import "std/joints.aidl"

t = 4 mm
thickness t

param drive_w = 101.6 mm, min = 101.6 mm, max = 102 mm
inner = drive_w + 0.4 mm          # between the side plates
side_x = inner / 2 + t / 2        # the side plates' middle planes
L = 170 mm                        # side plate length (front to back)
Hs = 90 mm                        # side and front plate height, tabs included
Wf = inner + 2 * t + 12 mm        # front plate and base width: 6 mm beyond each side
front_gap = 19 mm                 # cage front to the drive's front face
hole_y = [28.5 mm, 101.6 mm]      # side screw holes behind the drive's front face
drive_z = [t + 6 mm, t + 6 mm + 38.1 mm]   # each drive's bottom above the cage's bottom
hole_up = 6.35 mm
fan_z = 47 mm
fan_sq = 71.5 mm
sx = [-1, 1, 1, -1]
sy = [-1, -1, 1, 1]

def side_plate(front_at_left=true) -> solid {
    body = Rectangle(corner=(0, 0), opposite=(L, Hs))
    Fixed(body)
    bottom = tab_and_slot(part="tab", length=L, thickness=t, tabs=3, tab=20 mm, screw=0,
                          rotation=180 deg, cx=L / 2, cy=0 mm)
    front = tab_and_slot(part="tab", length=Hs - t, thickness=t, tabs=2, tab=20 mm, screw=0,
                         rotation=90 deg if front_at_left else -90 deg,
                         cx=0 mm if front_at_left else L, cy=(Hs + t) / 2)
    hole screw {
        for d in range(2) {
            for k in range(2) {
                c = Circle(center=(front_gap + hole_y[k] if front_at_left
                                   else L - front_gap - hole_y[k],
                                   drive_z[d] + hole_up), diameter=3.6 mm)
            }
        }
    }
    drawing label {
        for d in range(2) {
            bay = Text(f"BAY {d + 1}", position=(L / 2, drive_z[d] + hole_up), size=5,
                       valign="middle")
        }
    }
}

assembly cage {
    solid base {
        body = Rectangle(corner=(-Wf / 2, -6 mm), opposite=(Wf / 2, L))
        Fixed(body)
        left_slots = tab_and_slot(part="slot", length=L, thickness=t, tabs=3, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-side_x, cy=L / 2)
        right_slots = tab_and_slot(part="slot", length=L, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=side_x, cy=L / 2)
        front_slots = tab_and_slot(part="slot", length=Wf, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, cx=0 mm, cy=t / 2)
    }

    solid front {
        body = Rectangle(corner=(-Wf / 2, 0), opposite=(Wf / 2, Hs))
        Fixed(body)
        bottom = tab_and_slot(part="tab", length=Wf, thickness=t, tabs=3, tab=20 mm, screw=0,
                              rotation=180 deg, cx=0 mm, cy=0 mm)
        left_slots = tab_and_slot(part="slot", length=Hs - t, thickness=t, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-side_x, cy=(Hs + t) / 2)
        right_slots = tab_and_slot(part="slot", length=Hs - t, thickness=t, tabs=2, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=side_x, cy=(Hs + t) / 2)
        hole fan_screw {
            for i in range(4) {
                c = Circle(center=(sx[i] * fan_sq / 2, fan_z + sy[i] * fan_sq / 2),
                           diameter=4.3 mm)
            }
        }
        hole grille {
            for r in range(-4, 5) {
                for c in range(-4, 5) {
                    if (c * 9 mm + (4.5 mm if r % 2 != 0 else 0 mm)) ** 2 + (r * 7.8 mm) ** 2
                            <= (33 mm) ** 2 {
                        g = Circle(center=(c * 9 mm + (4.5 mm if r % 2 != 0 else 0 mm),
                                           fan_z + r * 7.8 mm), diameter=7 mm)
                    }
                }
            }
        }
    }

    rside = side_plate(front_at_left=true)
    lside = side_plate(front_at_left=false)

    # flat on the sheet
    RightOf(front, base, gap=10)
    AlignBottom(front, base)
    Above(rside, base, gap=10)
    AlignLeft(rside, base)
    RightOf(lside, rside, gap=10)
    AlignBottom(lside, rside)

    # in 3D: y is front (-) to back (+), the fan plate's outside face at y = 0
    Place(base, position=(0, 0, 0))
    Place(front, position=(0, t, 0), face="front", up="up")
    Place(rside, position=(inner / 2, 0, 0), face="right", up="up")
    Place(lside, position=(-inner / 2, L, 0), face="left", up="up")

    # the request's numbers
    assert base.body.bb.width == 122 mm and base.body.bb.height == 176 mm, "base 122 x 176"
    assert rside.body.bb.width == 170 mm and rside.body.bb.height == 90 mm, "sides 170 x 90"
    assert front.body.bb.width == 122 mm and front.body.bb.height == 90 mm, "front 122 x 90"
    assert inner == 102 mm, "102 mm between the sides"
    assert rside.screw.c[0][1].center.x - rside.screw.c[0][0].center.x == 101.6 mm - 28.5 mm,
        "drive holes 73.1 mm apart"
    assert rside.screw.c[0][0].center.x - rside.body.bb.left == 19 mm + 28.5 mm,
        "first hole 47.5 mm behind the cage front"
    assert lside.body.bb.right - lside.screw.c[0][0].center.x == 19 mm + 28.5 mm,
        "the left side is the mirror image"
    assert rside.screw.c[1][0].center.y - rside.screw.c[0][0].center.y == 38.1 mm,
        "drives 38.1 mm apart"
    assert rside.screw.c[0][0].center.y - rside.body.bb.bottom == 4 mm + 6 mm + 6.35 mm,
        "lower holes 6.35 mm above the lower drive, 6 mm above the base"
    assert rside.body.bb.top - (rside.screw.c[1][0].center.y - 6.35 mm + 26.1 mm) >= 5 mm,
        "the upper drive stays inside the side plates"
    assert front.fan_screw.c[1].center.x - front.fan_screw.c[0].center.x == 71.5 mm,
        "fan screws on a 71.5 mm square"
    assert front.fan_screw.c[0].center.y - front.body.bb.bottom == 47 mm - 71.5 mm / 2,
        "fan axis 47 mm up"
    assert distance(front.grille, front.fan_screw) >= 1.5 mm, "grille clear of the fan screws"
    assert distance(front.grille, front.left_slots) >= 3 mm, "grille clear of the side slots"
    assert len(rside.bottom.gap) == 4 and len(rside.front.gap) == 3, "3 + 2 tabs per side"
}
