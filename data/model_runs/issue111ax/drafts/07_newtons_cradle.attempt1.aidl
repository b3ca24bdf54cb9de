# Request (science): the frame of a Newton's cradle for five 19 mm steel balls, 3 mm ply,
# glued. A 200 x 150 mm base (6 mm rounded corners) with "NEWTON'S CRADLE" engraved 7 mm
# tall along its front. Two end frames 100 mm wide standing 160 mm apart, 120 mm tall above
# the base, each with a 70 x 80 mm window (10 mm rounded corners) whose bottom is 12 mm over
# the base, held in the base by two glued 10 mm tabs. Two top rails 170 mm long and 15 mm
# tall, 80 mm apart (40 mm either side of the centre line), cross-halved into the frame tops
# so their tops are flush; each rail has five 2 mm string holes at 20 mm pitch, centred.
units mm
thickness 3 mm
import "std/joints.aidl"

param span = 160 mm, min = 120, max = 220
param frame_h = 120 mm, min = 90, max = 180
T = 3 mm
FW = 100 mm          # frame width (across the balls' line)
RAIL_Y = 40 mm       # each rail from the centre line
RAIL_H = 15 mm
RAIL_L = 170 mm
PITCH = 20 mm

def end_frame() -> solid {
    body = Rectangle(bottom_left=(-FW / 2, 0), width=FW, height=T + frame_h)
    hole window {
        w = RoundedRectangle(center=(0, T + 12 + 40), width=70, height=80, corner_radius=10)
    }
    feet = tab_and_slot(part="tab", length=FW, thickness=T, tabs=2, tab=10 mm, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    front_halving = cross_halving(depth=RAIL_H / 2, thickness=T, cx=-RAIL_Y, cy=T + frame_h)
    back_halving = cross_halving(depth=RAIL_H / 2, thickness=T, cx=RAIL_Y, cy=T + frame_h)
}

def top_rail() -> solid {
    body = Rectangle(bottom_left=(-RAIL_L / 2, 0), width=RAIL_L, height=RAIL_H)
    left_halving = cross_halving(depth=RAIL_H / 2, thickness=T, rotation=180 deg,
                                 cx=-span / 2, cy=0)
    right_halving = cross_halving(depth=RAIL_H / 2, thickness=T, rotation=180 deg,
                                  cx=span / 2, cy=0)
    hole strings {
        for i in range(5) {
            s = Circle(center=((i - 2) * PITCH, RAIL_H / 2), diameter=2)
        }
    }
}

assembly cradle {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=6)
        left_slot = tab_and_slot(part="slot", length=FW, thickness=T, tabs=2, tab=10 mm,
                                 screw=0, rotation=90 deg, cx=-span / 2, cy=0)
        right_slot = tab_and_slot(part="slot", length=FW, thickness=T, tabs=2, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=span / 2, cy=0)
        drawing title {
            t = Text("NEWTON'S CRADLE", position=(0, -63), size=7, valign="middle")
        }
    }
    left_frame = end_frame()
    right_frame = end_frame()
    front_rail = top_rail()
    back_rail = top_rail()

    # on the sheet
    Below(left_frame, base, gap=6)
    AlignLeft(left_frame, base)
    RightOf(right_frame, left_frame, gap=6)
    AlignBottom(right_frame, left_frame)
    Below(front_rail, left_frame, gap=6)
    AlignLeft(front_rail, base)
    Below(back_rail, front_rail, gap=6)
    AlignLeft(back_rail, base)

    # assembled: frames stand in the planes x = -span/2 and span/2 ((u, v, w) -> (w, u, v)),
    # rails stand in the planes y = -RAIL_Y and RAIL_Y ((u, v, w) -> (u, -w, v)), tops flush
    Place(base, position=(0, 0, 0))
    Place(left_frame, position=(-span / 2 - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right_frame, position=(span / 2 - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(front_rail, position=(0, -RAIL_Y + T / 2, T + frame_h - RAIL_H),
          rotation=(90 deg, 0, 0))
    Place(back_rail, position=(0, RAIL_Y + T / 2, T + frame_h - RAIL_H),
          rotation=(90 deg, 0, 0))

    assert base.body.width == 200 mm and base.body.height == 150 mm, "200 x 150 base"
    assert left_frame.body.width == 100 mm, "100 mm frames"
    assert left_frame.body.height - T == 120 mm, "120 mm above the base"
    assert base.right_slot.bb.center_x - base.left_slot.bb.center_x == 160 mm, "160 mm apart"
    assert left_frame.window.w.width == 70 mm and left_frame.window.w.height == 80 mm,
        "70 x 80 window"
    assert left_frame.window.bb.bottom - left_frame.body.bb.bottom - T == 12 mm,
        "window 12 mm over the base"
    assert left_frame.back_halving.cut.bb.center_x - left_frame.front_halving.cut.bb.center_x
        == 80 mm, "rails 80 mm apart"
    assert front_rail.body.width == 170 mm and front_rail.body.height == 15 mm, "170 x 15 rails"
    assert left_frame.front_halving.depth + front_rail.left_halving.depth == 15 mm,
        "halvings meet: tops flush"
    assert len(front_rail.strings.s) == 5, "five strings"
    assert front_rail.strings.s[1].center.x - front_rail.strings.s[0].center.x == 20 mm,
        "20 mm pitch"
    assert left_frame.window.bb.top < left_frame.front_halving.cut.bb.bottom - 5 mm,
        "window clear of the halvings"
    assert base.title.bb.top < base.left_slot.bb.bottom - 3 mm, "title in front of the frames"
}
