# Request: a bench stand for three airbrushes, cut from 6 mm birch ply.
# - Base 180 x 100 mm, R8 corners, with a 50 mm locating hole for the cleaning-pot jar
#   (centre 15 mm in front of the base's centre) and two 4.5 mm screw holes 15 mm from
#   the side edges and 12 mm from the front edge, to screw it to the bench.
# - A back plate 180 wide x 140 tall (from the bench), top corners R10, standing on the
#   base with its rear face 14 mm in from the base's back edge, glued into the base on
#   three 20 mm tenons. Its top edge has three cradles for the airbrush bodies: U notches
#   14 wide and 25 deep at 50 mm pitch, centred, mouths eased R2.
# - Two triangular gussets (80 along the base, 110 up the back, tenons included), their
#   middles 78 mm either side of the centre, each with a 24 mm tenon into the base and a
#   30 mm tenon into the back plate.
# - "AIRBRUSH" engraved 12 mm tall on the back plate's front face, 60 mm above the bench.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
GX = 78 mm          # gusset middle planes at +-GX
REAR = 36 mm        # y of the back plate's rear face on the base (50 - 14)
G_BASE = 80 mm      # gusset leg along the base (tenons included)
G_BACK = 110 mm     # gusset leg up the back (tenons included)

def gusset() -> solid {
    web = Polygon([(0, 0), (80, 0), (0, 110)])
    foot = tab_and_slot(part="tab", length=80 mm, thickness=6 mm, tabs=1, tab=24 mm,
                        screw=0, rotation=180 deg, cx=40 mm, cy=0 mm)
    heel = tab_and_slot(part="tab", length=110 mm, thickness=6 mm, tabs=1, tab=30 mm,
                        screw=0, rotation=90 deg, cx=0 mm, cy=55 mm)
}

assembly airbrush_stand {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=180, height=100, corner_radius=8)
        back_slots = tab_and_slot(part="slot", length=180 mm, thickness=T, tabs=3, tab=20 mm,
                                  screw=0, cx=0 mm, cy=REAR - T / 2)
        left_slot = tab_and_slot(part="slot", length=G_BASE, thickness=T, tabs=1, tab=24 mm,
                                 screw=0, rotation=90 deg, cx=-GX, cy=REAR - G_BASE / 2)
        right_slot = tab_and_slot(part="slot", length=G_BASE, thickness=T, tabs=1, tab=24 mm,
                                  screw=0, rotation=90 deg, cx=GX, cy=REAR - G_BASE / 2)
        hole pot { c = Circle(center=(0, -15), diameter=50) }
        hole screws {
            a = Circle(center=(-75, -38), diameter=4.5)
            b = Circle(center=(75, -38), diameter=4.5)
        }
    }

    solid back {
        panel = RoundedRectangle(center=(0, 70), width=180, height=140,
                                 corner_radii=[10, 10, 0, 0])
        feet = tab_and_slot(part="tab", length=180 mm, thickness=T, tabs=3, tab=20 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        left_mortise = tab_and_slot(part="slot", length=G_BACK, thickness=T, tabs=1, tab=30 mm,
                                    screw=0, rotation=90 deg, cx=-GX, cy=G_BACK / 2)
        right_mortise = tab_and_slot(part="slot", length=G_BACK, thickness=T, tabs=1, tab=30 mm,
                                     screw=0, rotation=90 deg, cx=GX, cy=G_BACK / 2)
        hole cradles {
            for i in range(3) {
                u = Slot(center=((i - 1) * 50, 140 - 25 + 20), length=40, width=14, rotation=90)
            }
        }
        for i in range(3) {
            Fillet([panel.top, cradles.u[i]], 2)
        }
        drawing label {
            word = Text("AIRBRUSH", position=(0, 60), size=12)
        }
    }

    left_gusset = gusset()
    right_gusset = gusset()

    # flat on the sheet: back above the base, gussets to the right
    Above(back, base, gap=8)
    AlignCenterX(back, base)
    RightOf(left_gusset, base, gap=8)
    AlignBottom(left_gusset, base)
    RightOf(right_gusset, left_gusset, gap=8)
    AlignBottom(right_gusset, base)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(back, position=(0, REAR, 0), face="front", up="up")
    Place(left_gusset, position=(-GX + T / 2, REAR, 0), face="left", up="up")
    Place(right_gusset, position=(GX + T / 2, REAR, 0), face="left", up="up")

    # the request's numbers
    assert base.plate.bb.width == 180 mm and base.plate.bb.height == 100 mm, "base 180 x 100"
    assert back.panel.bb.width == 180 mm and back.panel.bb.height == 140 mm, "back 180 x 140"
    assert len(back.cradles.u) == 3, "three cradles"
    assert back.cradles.u[1].center.x - back.cradles.u[0].center.x == 50 mm, "50 mm pitch"
    assert back.cradles.u[0].width == 14 mm, "cradles 14 wide"
    assert back.panel.bb.top - back.cradles.u[0].bb.bottom == 25 mm, "cradles 25 deep"
    assert back.cradles.u[1].center.x == back.panel.bb.center_x, "cradles centred"
    assert base.pot.c.diameter == 50 mm, "pot hole 50"
    assert base.plate.bb.center_y - base.pot.c.center.y == 15 mm, "pot 15 in front of centre"
    assert base.screws.a.center.x - base.plate.bb.left == 15 mm, "screws 15 from the side"
    assert base.screws.a.center.y - base.plate.bb.bottom == 12 mm, "screws 12 from the front"
    assert base.plate.bb.top - (base.back_slots.slot[0].bb.center_y + T / 2) == 14 mm,
        "back's rear face 14 in from the base's back edge"
    assert base.right_slot.slot[0].bb.center_x - base.plate.bb.center_x == 78 mm, "gussets at 78"
    assert back.right_mortise.slot[0].bb.center_x - back.panel.bb.center_x == 78 mm,
        "mortises at 78"
    assert left_gusset.web.bb.width == 80 mm and left_gusset.web.bb.height == 110 mm,
        "gusset 80 x 110"
}
