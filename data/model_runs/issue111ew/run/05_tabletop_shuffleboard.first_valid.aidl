# Request (parties): a tabletop shuffleboard for the garden party, 6 mm birch ply.
# - Board 560 x 160 mm (corners R3). Scoring zones engraved at the far end: three zones
#   40 mm deep, numbered 3 (at the end), 2, 1 in filled bold figures 20 mm high; a foul line
#   engraved 80 mm from the near end; "SHUFFLE" engraved (filled bold, 16 mm) across the
#   near end.
# - Two side rails standing 30 mm above the board, glued into mortises: three tabs 40 mm
#   wide each, rail centres 72 mm either side of the board's centre line (138 mm of play
#   between them), 0.1 mm clearance in the mortises.
# - An end bumper between the rails at the far end, standing 30 mm, two 30 mm tabs, its
#   face 5 mm in from the board's end.
# - Four pucks 40 mm across: two with a filled engraved dot 24 mm across, two with an
#   engraved 24 mm ring (the two teams).

import "std/joints.aidl"

units mm
thickness 6 mm

def side_rail() -> solid {
    body = Rectangle(bottom_left=(-280, 0), width=560, height=36)
    tabs = tab_and_slot(part="tab", length=560 mm, thickness=6 mm, tabs=3, tab=40 mm,
                        screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly shuffleboard {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=560, height=160, corner_radius=3)
        left_slots = tab_and_slot(part="slot", length=560 mm, thickness=6 mm, tabs=3,
                                  tab=40 mm, screw=0, clearance=0.1 mm, cx=0 mm, cy=72 mm)
        right_slots = tab_and_slot(part="slot", length=560 mm, thickness=6 mm, tabs=3,
                                   tab=40 mm, screw=0, clearance=0.1 mm, cx=0 mm, cy=-72 mm)
        end_slots = tab_and_slot(part="slot", length=138 mm, thickness=6 mm, tabs=2,
                                 tab=30 mm, screw=0, clearance=0.1 mm, rotation=90 deg,
                                 cx=272 mm, cy=0 mm)
        drawing zones {
            for i in range(3) {
                edge = Line((149 + i * 40, -66), (149 + i * 40, 66))
                num = Text(str(i + 1), position=(169 + i * 40, 0), size=20, font="sans:Bold",
                           valign="middle", fill=true)
            }
            foul = Line((-200, -66), (-200, 66))
        }
        drawing title {
            t = Text("SHUFFLE", position=(-245, 0), size=16, font="sans:Bold",
                     valign="middle", rotation=90 deg, fill=true)
        }
    }

    for i in range(2) {
        rail = side_rail()
    }

    solid bumper {
        body = Rectangle(bottom_left=(-69, 0), width=138, height=36)
        tabs = tab_and_slot(part="tab", length=138 mm, thickness=6 mm, tabs=2, tab=30 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    }

    for i in range(4) {
        solid puck {
            disc = Circle(center=(0, 0), diameter=40)
            if i < 2 {
                drawing mark { d = Circle(center=(0, 0), diameter=24, fill=true) }
            } else {
                drawing mark { d = Circle(center=(0, 0), diameter=24) }
            }
        }
    }

    # on the sheet
    Below(rail[0], board, gap=5)
    AlignLeft(rail[0], board)
    Below(rail[1], rail[0], gap=5)
    AlignLeft(rail[1], board)
    Below(bumper, rail[1], gap=5)
    AlignLeft(bumper, board)
    RightOf(puck[0], bumper, gap=5)
    AlignTop(puck[0], bumper)
    for i in range(1, 4) {
        RightOf(puck[i], puck[i - 1], gap=5)
        AlignTop(puck[i], bumper)
    }

    # assembled: board flat, rails and bumper standing in their mortises, pucks at the near end
    Place(board, position=(0, 0, 0), face="up")
    Place(rail[0], position=(0, 69, 0), face="back", up="up")
    Place(rail[1], position=(0, -69, 0), face="front", up="up")
    Place(bumper, position=(269, 0, 0), face="right", up="up")
    for i in range(4) {
        Place(puck[i], position=(-160 + i * 45, 0, 6), face="up")
    }

    assert board.body.width == 560 mm and board.body.height == 160 mm
    assert len(board.left_slots.slot) == 3 and len(board.right_slots.slot) == 3
    assert abs(board.left_slots.slot[0].bb.bottom - board.right_slots.slot[0].bb.top
               - 138 mm) <= 0.2 mm, "138 mm of play between the rails"
    assert rail[0].body.height - 6 mm == 30 mm, "rails stand 30 mm"
    assert bumper.body.height - 6 mm == 30 mm and bumper.body.width == 138 mm
    assert board.body.bb.right - board.end_slots.slot[0].bb.left <= 5 mm + 6.1 mm
    assert board.zones.edge[1].start.x - board.zones.edge[0].start.x == 40 mm
    assert board.body.bb.right - 5 mm - 6 mm - board.zones.edge[2].start.x == 40 mm,
        "the 3 zone ends at the bumper's face"
    assert board.zones.foul.start.x - board.body.bb.left == 80 mm
    assert distance(board.zones, board.left_slots) >= 2 mm
    assert distance(board.zones, board.right_slots) >= 2 mm
    assert distance(board.title, board.left_slots) >= 2 mm
    assert len(puck) == 4 and puck[0].disc.diameter == 40 mm and puck[3].mark.d.diameter == 24 mm
}
