# Request: a small wall-mounted network patch box for six keystone jacks. Front: 150 x 50 mm
# of 2 mm acrylic (keystones clip into thin panels) with six 14.8 x 16.3 mm keystone openings
# 22 mm apart, centred across, 4 mm above the middle; the port numbers 1-6 engraved 5 mm high
# under each opening. Back: 150 x 50 mm of 3 mm ply, screwed to the wall through two 4 mm
# holes countersunk to 8 mm on the inside face, 50 mm either side of the middle, and a
# 60 x 14 mm slot in the middle for the cables. Two 3 mm ply end plates hold the front 40 mm
# clear of the back; they stand 68.5 mm either side of the middle (their centre planes) and
# are glued with two 12 mm tabs into slots in the front and two into the back.

import "std/joints.aidl"

thickness 3 mm

FRONT_T = 2 mm
PLY_T = 3 mm
DEPTH = 40 mm          # clear space between back and front
PITCH = 22 mm
END_X = 68.5 mm

def end_plate() -> solid {
    # u across the panel's height (-25 .. 25), v from the back (0) to the front (45):
    # tabs 3 mm into the back (v 0 .. 3) and 2 mm into the front (v 43 .. 45)
    body = Rectangle(bottom_left=(-25, 0), width=50, height=PLY_T + DEPTH + FRONT_T)
    to_back = tab_and_slot(part="tab", length=50 mm, thickness=PLY_T, tabs=2, tab=12 mm, screw=0,
                           rotation=180 deg, cx=0 mm, cy=0 mm)
    to_front = tab_and_slot(part="tab", length=50 mm, thickness=FRONT_T, tabs=2, tab=12 mm,
                            screw=0, cx=0 mm, cy=PLY_T + DEPTH + FRONT_T)
}

assembly patch_box {
    solid front {
        thickness 2 mm
        body = RoundedRectangle(center=(0, 0), width=150, height=50, corner_radius=3)
        hole ports {
            for i in range(6) {
                k = Rectangle(center=(-2.5 * PITCH + i * PITCH, 4), width=14.8, height=16.3)
            }
        }
        drawing numbers {
            for i in range(6) {
                n = Text(str(i + 1), position=(-2.5 * PITCH + i * PITCH, -16), size=5,
                         valign="middle")
            }
        }
        # slots for the end plates' tabs: as wide as the 3 mm ply
        left_slots = tab_and_slot(part="slot", length=50 mm, thickness=PLY_T, tabs=2, tab=12 mm,
                                  screw=0, rotation=90 deg, cx=-END_X, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=50 mm, thickness=PLY_T, tabs=2, tab=12 mm,
                                   screw=0, rotation=90 deg, cx=END_X, cy=0 mm)
    }

    solid back {
        body = RoundedRectangle(center=(0, 0), width=150, height=50, corner_radius=3)
        hole screws {
            a = Circle(center=(-50, 0), diameter=4)
            b = Circle(center=(50, 0), diameter=4)
        }
        Countersink(screws, diameter=8 mm)
        hole cables { s = Slot(center=(0, 0), length=60, width=14) }
        left_slots = tab_and_slot(part="slot", length=50 mm, thickness=PLY_T, tabs=2, tab=12 mm,
                                  screw=0, rotation=90 deg, cx=-END_X, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=50 mm, thickness=PLY_T, tabs=2, tab=12 mm,
                                   screw=0, rotation=90 deg, cx=END_X, cy=0 mm)
    }

    left_end = end_plate()
    right_end = end_plate()

    # 3D: the back flat on the wall (z 0 .. 3), the front 40 mm above it, the ends standing
    # in the planes x = -68.5 and x = 68.5
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, PLY_T + DEPTH))
    Place(left_end, rotation=(90 deg, 0, 90 deg), position=(-END_X - PLY_T / 2, 0, 0))
    Place(right_end, rotation=(90 deg, 0, 90 deg), position=(END_X - PLY_T / 2, 0, 0))

    # on the sheet
    Above(front, back, gap=6)
    AlignLeft(front, back)
    RightOf(left_end, back, gap=6)
    AlignBottom(left_end, back)
    RightOf(right_end, left_end, gap=6)
    AlignBottom(right_end, back)

    # the request's numbers
    assert len(front.ports.k) == 6, "six keystones"
    assert front.ports.k[0].width == 14.8 mm and front.ports.k[0].height == 16.3 mm, "opening"
    assert front.ports.k[1].center.x - front.ports.k[0].center.x == 22 mm, "22 mm apart"
    assert front.body.bb.width == 150 mm and front.body.bb.height == 50 mm, "front 150 x 50"
    assert left_end.body.bb.height - 3 mm - 2 mm == 40 mm, "front 40 mm clear of the back"
    assert back.screws.b.center.x - back.screws.a.center.x == 100 mm, "screws 50 either side"
    assert back.cables.s.length == 60 mm and back.cables.s.width == 14 mm, "cable slot"
}
