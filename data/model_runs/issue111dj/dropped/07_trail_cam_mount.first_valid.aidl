# Request: a tree mount for a trail camera, 6 mm exterior ply. A back plate 80 x 160 mm
# against the trunk, held by two 25 mm webbing straps: a pair of 27 x 5 mm vertical strap
# slots 20 mm apart (centres), centred across, 65 mm above and 65 mm below the middle (the
# strap crosses the front only between each pair). A wedge tilts the camera 15 degrees
# down: two ribs 50 mm apart (centre planes), each 100 mm tall against the back plate,
# 40 mm deep at the top and 40 - 100 x tan 15 deg deep at the bottom, with two 20 mm glued
# tabs into the back plate and two into the front plate. The front plate is 70 mm wide
# and as long as the rib's sloping edge (100 / cos 15 deg), with a 6.5 mm hole in its
# middle for a 1/4"-20 bolt into the camera's tripod socket. "CAM 1" engraved on the back
# plate between the lower strap slots... no: on each rib's outer face, 6 mm letters.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
tilt = 15 deg
H = 100 mm                     # rib height against the back plate
D = 40 mm                      # rib depth at the top
Db = D - H * tan(tilt)         # rib depth at the bottom
F = H / cos(tilt)              # length of the sloping front edge
rib_gap = 50 mm                # between the ribs' centre planes

def rib() -> solid {
    # (0, 0): the back plate's front face at the rib's bottom; the tabs' tips are the
    # polygon's back edge (x = -t) and its front edge (t in front of the sloping face)
    body = Polygon([(-t, 0), (Db + t / cos(tilt), 0), (D + t / cos(tilt), H), (-t, H)])
    back_tabs = tab_and_slot(part="tab", length=H, thickness=t, tabs=2, tab=20, screw=0,
                             rotation=90 deg, cx=-t, cy=H / 2)
    front_tabs = tab_and_slot(part="tab", length=F, thickness=t, tabs=2, tab=20, screw=0,
                              rotation=-(90 deg + tilt),
                              cx=(Db + D) / 2 + t / cos(tilt), cy=H / 2)
    drawing name {
        w = Text("CAM 1", position=((Db + D) / 4, H / 2), size=6, rotation=90 deg,
                 valign="middle")
    }
}

assembly cam_mount {
    solid back {
        plate = Rectangle(center=(0, 0), width=80, height=160)
        left_slots = tab_and_slot(part="slot", length=H, thickness=t, tabs=2, tab=20,
                                  screw=0, rotation=90 deg, cx=-rib_gap / 2, cy=0)
        right_slots = tab_and_slot(part="slot", length=H, thickness=t, tabs=2, tab=20,
                                   screw=0, rotation=90 deg, cx=rib_gap / 2, cy=0)
        hole straps {
            for y in [65 mm, -65 mm] {
                for x in [-10 mm, 10 mm] {
                    s = Rectangle(center=(x, y), width=5, height=27)
                }
            }
        }
    }

    left_rib = rib()
    right_rib = rib()

    solid front {
        plate = Rectangle(center=(0, 0), width=70, height=F)
        left_slots = tab_and_slot(part="slot", length=F, thickness=t, tabs=2, tab=20,
                                  screw=0, rotation=90 deg, cx=-rib_gap / 2, cy=0)
        right_slots = tab_and_slot(part="slot", length=F, thickness=t, tabs=2, tab=20,
                                   screw=0, rotation=90 deg, cx=rib_gap / 2, cy=0)
        hole bolt {
            c = Circle(center=(0, 0), diameter=6.5)
        }
    }

    # flat layout
    RightOf(left_rib, back, gap=8)
    RightOf(right_rib, left_rib, gap=8)
    RightOf(front, right_rib, gap=8)
    AlignTop(left_rib, back)
    AlignTop(right_rib, back)
    AlignTop(front, back)

    # 3D: the trunk behind y = 6, the camera looking to -y and 15 deg down
    Place(back, position=(0, t, 0), face="front", up="up")
    Place(left_rib, position=(-rib_gap / 2 + t / 2, 0, -H / 2), face="left", up="up")
    Place(right_rib, position=(rib_gap / 2 + t / 2, 0, -H / 2), face="left", up="up")
    Place(front, position=(0, -(Db + D) / 2, 0), face=(0, -cos(tilt), -sin(tilt)),
          up=(0, -sin(tilt), cos(tilt)))

    # the request's numbers
    assert back.plate.bb.width == 80 mm and back.plate.bb.height == 160 mm, "back 80 x 160"
    assert back.straps.s[0][1].center.x - back.straps.s[0][0].center.x == 20 mm, "strap slots 20 apart"
    assert back.straps.s[0][0].center.y == 65 mm and back.straps.s[1][0].center.y == -65 mm, "straps 65 up and down"
    assert sum([len(r) for r in back.straps.s]) == 4, "two pairs of strap slots"
    assert abs((D - Db) / H - tan(15 deg)) < 1e-9, "15 deg tilt"
    assert front.plate.bb.height == 100 mm / cos(15 deg), "front as long as the sloping edge"
    assert front.plate.bb.width == 70 mm, "front 70 wide"
    assert front.bolt.c.diameter == 6.5 mm, "1/4 in bolt hole"
    assert right_rib.body.bb.height == 100 mm, "ribs 100 tall"
}
