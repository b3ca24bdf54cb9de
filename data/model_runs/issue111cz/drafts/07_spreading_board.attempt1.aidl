# Request (science): an insect spreading (setting) board for butterflies of up to 90 mm span,
# 3 mm ply, glued. Two wing boards 300 x 45 mm either side of a 10 mm groove, each sloping up
# 5 degrees away from the groove, their groove edges 25 mm above the table. They lie on two
# end supports standing across a 300 x 100 base, 140 mm either side of its middle; each support
# has a 10 mm wide notch under the groove, down to 8 mm above the table, for a foam strip, and
# two glued tabs (15 mm) into closed slots in the base. The right wing board has a millimetre
# scale engraved along its groove edge: a tick every 5 mm (3 mm long, every 10 mm 5 mm long),
# numbered every 50 mm (3 mm text), 0 to 280 mm starting 10 mm in from the left end; the left
# board has "SPREADING BOARD" engraved 6 mm tall, centred, 8 mm in from its outer edge.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
LEN = 300 mm
B = 45 mm               # wing board width
GROOVE = 10 mm
SLOPE = 5 deg
EDGE_Z = 25 mm          # groove edges above the table
NOTCH_Z = 8 mm
SUPPORT_X = 140 mm
RUN = B * cos(SLOPE)
RISE = B * sin(SLOPE)
HALF = GROOVE / 2 + RUN  # half the support's width

def support() -> solid {
    # x across the board (the groove at 0), y up from the table
    body = Polygon([(-HALF, 0), (HALF, 0), (HALF, EDGE_Z + RISE), (GROOVE / 2, EDGE_Z),
                    (GROOVE / 2, NOTCH_Z), (-GROOVE / 2, NOTCH_Z), (-GROOVE / 2, EDGE_Z),
                    (-HALF, EDGE_Z + RISE)])
    feet = tab_and_slot(part="tab", length=2 * HALF, thickness=T, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
}

def wing(side=1) -> solid {
    # x along the board, y across from the groove edge (0) outward (side -1: toward -y)
    body = Rectangle(bottom_left=(-LEN / 2, 0 if side > 0 else -B), width=LEN, height=B)
}

assembly spreading_board {
    solid base {
        body = Rectangle(center=(0, 0), width=LEN, height=2 * HALF)
        left_slots = tab_and_slot(part="slot", length=2 * HALF, thickness=T, tabs=2, tab=15 mm,
                                  screw=0, rotation=90 deg, cx=-SUPPORT_X, cy=0)
        right_slots = tab_and_slot(part="slot", length=2 * HALF, thickness=T, tabs=2, tab=15 mm,
                                   screw=0, rotation=90 deg, cx=SUPPORT_X, cy=0)
    }
    end_l = support()
    end_r = support()
    wing_r = wing(side=1)
    wing_l = wing(side=-1)

    drawing scale {
        for i in range(57) {
            tick = Line((-LEN / 2 + 10 mm + i * 5 mm, 1 mm),
                        (-LEN / 2 + 10 mm + i * 5 mm, 1 mm + (5 mm if i % 2 == 0 else 3 mm)))
        }
        for k in range(6) {
            num = Text(str(k * 50), position=(-LEN / 2 + 10 mm + k * 50 mm, 8 mm), size=3 mm)
        }
    }
    CutInto(scale, wing_r)
    Rigid(scale)
    scale.tick[0].start == wing_r.body.bottom_left + (10 mm, 1 mm)

    drawing title {
        t = Text("SPREADING BOARD", position=(0, 0), size=6 mm, valign="top")
    }
    CutInto(title, wing_l)
    At(title.t.position, wing_l.body.bottom.midpoint, dy=8 mm + 6 mm)

    # on the sheet: base, then the wings above it, the supports below it
    Above(wing_r, base, gap=5 mm)
    Above(wing_l, wing_r, gap=5 mm)
    AlignCenterX(wing_r, base)
    AlignCenterX(wing_l, base)
    Below(end_l, base, gap=5 mm)
    Below(end_r, base, gap=5 mm)
    AlignLeft(end_l, base)
    AlignRight(end_r, base)

    # in 3D: x along, y across, z up
    Place(base, position=(0, 0, 0), face="up")
    Place(end_l, position=(-SUPPORT_X - T / 2, 0, 0), face="right", up="up")
    Place(end_r, position=(SUPPORT_X - T / 2, 0, 0), face="right", up="up")
    Place(wing_r, position=(0, GROOVE / 2, EDGE_Z), rotation=(SLOPE, 0, 0))
    Place(wing_l, position=(0, -GROOVE / 2, EDGE_Z), rotation=(-SLOPE, 0, 0))

    assert wing_r.body.bb.width == 300 mm and wing_r.body.bb.height == 45 mm, "wings 300 x 45"
    assert base.body.bb.width == 300 mm, "base 300 long"
    assert abs(base.body.bb.height - 100 mm) < 1 mm, "base about 100 wide"
    assert base.right_slots.slot[0].bb.center_x - base.left_slots.slot[0].bb.center_x == 280 mm,
        "supports 140 either side"
    assert len(scale.tick) == 57 and len(scale.num) == 6, "0..280 by 5, numbered every 50"
    assert scale.tick[56].start.x - scale.tick[0].start.x == 280 mm, "scale 280 long"
    assert wing_l.body.bb.top - title.t.position.y == 8 mm, "title 8 in from the outer edge"
}
