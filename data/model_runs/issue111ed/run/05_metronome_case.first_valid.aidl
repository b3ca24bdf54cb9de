# Request (music): a pyramid case for a clockwork metronome movement (bought as a
# kit part), 3 mm walnut ply. Front and back are trapezoids 110 mm wide at the
# bottom, 36 mm at the top, 210 mm tall, standing 70 mm apart inside; the two
# sides lean in along the trapezoids' slanting edges, 86 mm wide so they stand
# 5 mm proud of the front and back, and stop under a 50 x 90 mm (R4) top cap.
# Joints: four 20 mm tabs on each slanting edge of the front and back into
# mortises in the sides, and one 16 mm tab on each top edge into the cap (0.1 mm
# clearance). The front has a 12 mm pendulum slot from 45 to 188 mm up, with the
# Maelzel tempo scale engraved beside it: ticks and the numbers 40 50 60 72 84 96
# 108 120 132 144 160 176 192 208 (40 at the top, 180 mm up; 208 at 60 mm up) on
# the right, the names Largo Adagio Andante Moderato Allegro Presto on the left
# (2.5 mm strokes). The back has a 12 mm winding-key hole 100 mm up and two M3
# holes for the movement 70 mm up, 40 apart. "M.M." engraved filled on the cap.

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
thickness 3 mm

T = 3 mm
BOT = 110 mm
TOP = 36 mm
HT = 210 mm
IN = 70 mm                         # inside, front to back
CAP_Z = HT - T                     # the cap's underside
LEAN = atan((BOT - TOP) / 2 / HT)  # the sides' lean from vertical
SL = CAP_Z / cos(LEAN)             # the slanting joint's length, table to cap
EDGE_X = BOT / 2 - (BOT - TOP) / 2 * (CAP_Z / 2) / HT   # the edge's x at the joint's middle
SIDE_W = IN + 2 * T + 2 * 5 mm     # 86
TEMPI = [40, 50, 60, 72, 84, 96, 108, 120, 132, 144, 160, 176, 192, 208]
STEP = (180 mm - 60 mm) / (len(TEMPI) - 1)
NAMES = ["Largo", "Adagio", "Andante", "Moderato", "Allegro", "Presto"]
NAME_AT = [1, 3, 5, 7, 9, 12]      # the tempo each name stands beside

def tempo_y(i) = 180 mm - i * STEP

# front (is_front=1) or back
def face_panel(is_front=1) -> solid {
    body = Trapezoid(center=(0, HT / 2), bottom_width=BOT, top_width=TOP, height=HT)
    Fixed(body)
    jr = tab_and_slot(part="tab", length=SL, thickness=T, tabs=4, tab=20 mm, screw=0,
                      rotation=-(90 deg - LEAN), cx=EDGE_X, cy=CAP_Z / 2)
    jl = tab_and_slot(part="tab", length=SL, thickness=T, tabs=4, tab=20 mm, screw=0,
                      rotation=90 deg - LEAN, cx=-EDGE_X, cy=CAP_Z / 2)
    jt = tab_and_slot(part="tab", length=TOP, thickness=T, tabs=1, tab=16 mm, screw=0,
                      cx=0 mm, cy=HT)
    if is_front == 1 {
        hole pendulum {
            s = Slot(start=(0, 45 + 6), end=(0, 188 - 6), width=12)
        }
        drawing scale {
            for i in range(len(TEMPI)) {
                tick = Line((7, tempo_y(i)), (11, tempo_y(i)))
                num = Text(str(TEMPI[i]), position=(13, tempo_y(i)), size=2.5,
                           anchor="start", valign="middle")
            }
            for k in range(len(NAMES)) {
                name = Text(NAMES[k], position=(-9, tempo_y(NAME_AT[k])), size=2.5,
                            anchor="end", valign="middle")
            }
        }
    } else {
        hole key {
            c = Circle(center=(0, 100), diameter=12)
        }
        m1 = clearance_hole(size=3, cx=-20 mm, cy=70 mm)
        m2 = clearance_hole(size=3, cx=20 mm, cy=70 mm)
    }
}

def side() -> solid {
    # x across (front to back), y up the slant from the table
    body = Rectangle(bottom_left=(-SIDE_W / 2, T * tan(LEAN)), width=SIDE_W,
                     height=SL - T * tan(LEAN))
    Fixed(body)
    mf = tab_and_slot(part="slot", length=SL, thickness=T, tabs=4, tab=20 mm, screw=0,
                      clearance=0.1 mm, rotation=90 deg, cx=-(IN / 2 + T / 2), cy=SL / 2)
    mb = tab_and_slot(part="slot", length=SL, thickness=T, tabs=4, tab=20 mm, screw=0,
                      clearance=0.1 mm, rotation=90 deg, cx=IN / 2 + T / 2, cy=SL / 2)
}

assembly metronome_case {
    front = face_panel(is_front=1)
    back = face_panel(is_front=0)
    right = side()
    left = side()
    solid cap {
        body = RoundedRectangle(center=(0, 0), width=50, height=90, corner_radius=4)
        Fixed(body)
        mf = tab_and_slot(part="slot", length=TOP, thickness=T, tabs=1, tab=16 mm, screw=0,
                          clearance=0.1 mm, cx=0 mm, cy=-(IN / 2 + T / 2))
        mb = tab_and_slot(part="slot", length=TOP, thickness=T, tabs=1, tab=16 mm, screw=0,
                          clearance=0.1 mm, cx=0 mm, cy=IN / 2 + T / 2)
        drawing mark {
            t = Text("M.M.", position=(0, 0), size=8, valign="middle", font="serif:Bold",
                     fill=true)
        }
    }

    # flat on the sheet
    RightOf(back, front, gap=5)
    AlignBottom(back, front)
    RightOf(right, back, gap=5)
    AlignBottom(right, front)
    RightOf(left, right, gap=5)
    AlignBottom(left, front)
    RightOf(cap, left, gap=5)
    AlignBottom(cap, front)

    # in 3D: inside x from the sides, y -35..35, the table z = 0
    Place(front, position=(0, -IN / 2, 0), face="front", up="up")
    Place(back, position=(0, IN / 2, 0), face="back", up="up")
    # the sides' outer faces run along the trapezoids' slanting edges
    Place(right, position=(BOT / 2 - T * cos(LEAN), 0, -T * sin(LEAN)),
          face=(cos(LEAN), 0, sin(LEAN)), up=(-sin(LEAN), 0, cos(LEAN)))
    Place(left, position=(-BOT / 2 + T * cos(LEAN), 0, -T * sin(LEAN)),
          face=(-cos(LEAN), 0, sin(LEAN)), up=(sin(LEAN), 0, cos(LEAN)))
    Place(cap, position=(0, 0, CAP_Z), face="up")

    # the request's numbers
    assert front.body.bottom_width == 110 mm and front.body.top_width == 36 mm, "110 / 36"
    assert front.body.height == 210 mm, "210 tall"
    assert right.body.bb.width == 86 mm, "sides 86 wide"
    assert cap.body.bb.width == 50 mm and cap.body.bb.height == 90 mm, "cap 50 x 90"
    assert front.pendulum.s.bb.bottom - front.body.bb.bottom == 45 mm, "slot from 45"
    assert front.pendulum.s.bb.top - front.body.bb.bottom == 188 mm, "slot to 188"
    assert front.pendulum.s.width == 12 mm, "12 mm slot"
    assert len(front.scale.num) == 14 and len(front.scale.name) == 6, "14 tempi, 6 names"
    assert front.scale.num[0].position.y - front.body.bb.bottom == 180 mm, "40 at 180 up"
    assert front.scale.num[13].position.y - front.body.bb.bottom == 60 mm, "208 at 60 up"
    assert back.key.c.diameter == 12 mm and back.key.c.center.y - back.body.bb.bottom == 100 mm,
        "key hole 12 at 100"
    assert back.m2.c.center.x - back.m1.c.center.x == 40 mm, "M3 holes 40 apart"
    assert distance(front.scale, front.pendulum) >= 1 mm, "scale clear of the slot"
    assert len(front.jr.gap) == 5 and len(right.mf.slot) == 4, "four tabs a slanting edge"
}
