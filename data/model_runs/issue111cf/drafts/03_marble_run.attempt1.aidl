# Request: a wall marble run for 16 mm glass marbles, 6 mm ply. A 220 x 300 mm backboard
# (10 mm corners) hung on one keyhole at the top centre, "MARBLE RUN" engraved across the
# top and "START" at the first ramp's high end. Two ramps, 170 mm long, standing out 30 mm,
# sloping 6 degrees in a zigzag: the upper one falls to the right, the lower one to the
# left, the marble dropping from the upper ramp's low end onto the lower ramp's high end.
# Each ramp is glued into mortises in the board by three 30 mm tabs and carries a 20 mm
# lip along its front edge (glued down into it by two tabs) that keeps the marble on.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

T = 6 mm
slope = 6 deg
ramp_len = 170 mm
depth = 30 mm
lip_h = 20 mm
# where each ramp's mid-plane meets the board (board frame = height on the wall)
r1 = (-10, 40)
r2 = (10, -30)

def ramp() -> solid {
    body = Rectangle(center=(0, -12), width=170, height=36)   # y -30 .. 6: 30 out + tabs
    into_board = tab_and_slot(part="tab", length=170 mm, thickness=6 mm, tabs=3, tab=30 mm,
                              screw=0, cx=0 mm, cy=6 mm)
    lip_slots = tab_and_slot(part="slot", length=170 mm, thickness=6 mm, tabs=2, tab=30 mm,
                             screw=0, cx=0 mm, cy=-27 mm)
}

def lip() -> solid {
    body = Rectangle(center=(0, 7), width=170, height=26)      # y -6 .. 20: tabs + 20 high
    into_ramp = tab_and_slot(part="tab", length=170 mm, thickness=6 mm, tabs=2, tab=30 mm,
                             screw=0, rotation=180 deg, cx=0 mm, cy=-6 mm)
}

assembly marble_run {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=220, height=300, corner_radius=10)
        hang = keyhole(cx=0 mm, cy=130 mm)
        upper = tab_and_slot(part="slot", length=170 mm, thickness=6 mm, tabs=3, tab=30 mm,
                             screw=0, rotation=-slope, cx=r1[0], cy=r1[1])
        lower = tab_and_slot(part="slot", length=170 mm, thickness=6 mm, tabs=3, tab=30 mm,
                             screw=0, rotation=slope, cx=r2[0], cy=r2[1])
        drawing words {
            title = Text("MARBLE RUN", (0, 100), size=14)
            start = Text("START", (-80, 62), size=6)
        }
    }
    ramp1 = ramp()
    ramp2 = ramp()
    lip1 = lip()
    lip2 = lip()

    # flat on the sheet
    RightOf(ramp1, board, gap=10)
    AlignTop(ramp1, board)
    Below(ramp2, ramp1, gap=10)
    Below(lip1, ramp2, gap=10)
    Below(lip2, lip1, gap=10)
    AlignLeft(ramp2, ramp1)
    AlignLeft(lip1, ramp1)
    AlignLeft(lip2, ramp1)

    # in 3D: board face at y = 0, parts stick out toward -y; ramp 1 falls to the right
    # (turned +6 deg about y), ramp 2 to the left
    Place(board, position=(0, 6, 0), rotation=(90 deg, 0, 0))
    Place(ramp1, position=(r1[0] - 3 * sin(slope), 0, r1[1] - 3 * cos(slope)),
          rotation=(0, slope, 0))
    Place(ramp2, position=(r2[0] + 3 * sin(slope), 0, r2[1] - 3 * cos(slope)),
          rotation=(0, -slope, 0))
    Place(lip1, position=(r1[0] - 3 * sin(slope) + 6 * sin(slope), -24,
                          r1[1] - 3 * cos(slope) + 6 * cos(slope)),
          rotation=(90 deg, slope, 0))
    Place(lip2, position=(r2[0] + 3 * sin(slope) - 6 * sin(slope), -24,
                          r2[1] - 3 * cos(slope) + 6 * cos(slope)),
          rotation=(90 deg, -slope, 0))

    assert board.body.bb.width == 220 mm and board.body.bb.height == 300 mm, "board 220 x 300"
    assert ramp1.body.bb.width == 170 mm, "ramps 170 long"
    assert ramp1.body.bb.height - T == 30 mm, "ramps stand out 30"
    assert lip1.body.bb.height - T == 20 mm, "lips 20 high"
    assert ramp1.lip_slots.slot[0].bb.bottom - ramp1.body.bb.bottom == 3 mm,
        "lip flush with the ramp's front edge"
}
