# Request: a bow-and-hair-clip board for my daughter Isla's bathroom wall, cut from
# 3 mm birch ply (four parts, glued).
# - Back board 180 mm wide, straight sides 300 mm tall, an arched top rising to
#   340 mm at the middle.
# - Three 25 mm ribbons hang down the front (bows get clipped onto them); each is
#   threaded through a 27 x 4 mm slot near the top (centre 245 mm up) and one near
#   the bottom (centre 70 mm up); ribbons centred at x = -50, 0 and +50 mm.
# - Two keyholes to hang it (8 mm head, 4 mm slot, 10 mm long, pointing up) at
#   x = -25 and +25 mm, 255 mm up.
# - "ISLA" engraved in filled bold letters 30 mm tall, centred 298 mm up.
# - At the bottom a shelf for brushes and hair ties: 180 mm wide, standing 60 mm
#   out from the board's face, its underside 40 mm up [50 after the fix], glued into the board by two
#   30 mm tabs; front corners R5.
# - Two triangular brackets under the shelf, 47 x 47 mm in front of the board and
#   under the shelf, at x = -65 and +65 mm, each with one 20 mm tab into the board
#   and one into the shelf. Slots 0.1 mm over for glue.

# FIX after the first valid program: the brackets (47 mm under a shelf whose underside
# was 40 mm up) hung 7 mm below the board's bottom edge in the assembled view. The
# shelf's underside now sits 50 mm up (board slots, Place moved with it), asserted.

units mm
thickness 3 mm
shelf_z = 50 mm     # the shelf's underside above the board's bottom edge
import "std/plates.aidl"
import "std/joints.aidl"

def bracket() -> solid {
    # drawn as seen from the right: +x toward the wall, +y up; (0, 0) is where the
    # tabs' tips meet (the board's back face, the shelf's top face)
    body = Polygon([(-50, 0), (-3, 0), (-3, -3), (0, -3), (0, -50)])
    top = tab_and_slot(part="tab", length=47, thickness=3, tabs=1, tab=20, screw=0,
                       cx=-26.5, cy=0)
    back = tab_and_slot(part="tab", length=47, thickness=3, tabs=1, tab=20, screw=0,
                        rotation=-90 deg, cx=0, cy=-26.5)
}

assembly clip_board {
    solid board {
        right = Line((90, 0), (90, 300))
        bottom = Line((90, 0), (-90, 0))
        left = Line((-90, 0), (-90, 300))
        arch = Arc(start=(-90, 300), through=(0, 340), end=(90, 300))

        hole ribbons {
            for i in range(3) {
                top = Slot(center=(-50 + i * 50, 245), length=27, width=4)
                low = Slot(center=(-50 + i * 50, 70), length=27, width=4)
            }
        }
        hang_l = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=-25, cy=255)
        hang_r = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=25, cy=255)

        # the shelf's two tabs (its underside 40 up: slots 40..43) and the brackets' tabs
        shelf_slots = tab_and_slot(part="slot", length=180, thickness=3, tabs=2, tab=30,
                                   screw=0, clearance=0.1, cx=0, cy=shelf_z + 1.5)
        br_slot_r = tab_and_slot(part="slot", length=47, thickness=3, tabs=1, tab=20,
                                 screw=0, clearance=0.1, rotation=90 deg, cx=65, cy=shelf_z + 3 - 26.5)
        br_slot_l = tab_and_slot(part="slot", length=47, thickness=3, tabs=1, tab=20,
                                 screw=0, clearance=0.1, rotation=90 deg, cx=-65, cy=shelf_z + 3 - 26.5)

        drawing name {
            t = Text("ISLA", position=(0, 298), size=30, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    solid shelf {
        # drawn from above, the wall side up: y = 0 is the board's back face
        slab = Rectangle(bottom_left=(-90, -63), width=180, height=63)
        back = tab_and_slot(part="tab", length=180, thickness=3, tabs=2, tab=30, screw=0,
                            cx=0, cy=0)
        br_r = tab_and_slot(part="slot", length=47, thickness=3, tabs=1, tab=20, screw=0,
                            clearance=0.1, rotation=90 deg, cx=65, cy=-26.5)
        br_l = tab_and_slot(part="slot", length=47, thickness=3, tabs=1, tab=20, screw=0,
                            clearance=0.1, rotation=90 deg, cx=-65, cy=-26.5)
        Fillet([slab.bottom_left, slab.bottom_right], 5)
    }

    bracket_r = bracket()
    bracket_l = bracket()

    # flat on the sheet: shelf beside the board, brackets under the shelf
    RightOf(shelf, board, gap=10)
    AlignTop(shelf, board)
    Below(bracket_r, shelf, gap=10)
    AlignLeft(bracket_r, shelf)
    RightOf(bracket_l, bracket_r, gap=10)
    AlignTop(bracket_l, bracket_r)

    # assembled: board upright facing front, its back face at y = 3
    Place(board, position=(0, 3, 0), face="front", up="up")
    Place(shelf, position=(0, 3, shelf_z), face="up", up="back")
    Place(bracket_r, position=(63.5, 3, shelf_z + 3), face="right", up="up")
    Place(bracket_l, position=(-66.5, 3, shelf_z + 3), face="right", up="up")

    # the request's numbers
    assert board.right.end.y - board.right.start.y == 300 mm, "sides 300 tall"
    assert board.bottom.length == 180 mm, "board 180 wide"
    assert board.arch.through.y - board.bottom.start.y == 340 mm, "arch 340 at the middle"
    assert len(board.ribbons.top) == 3 and len(board.ribbons.low) == 3, "three ribbons"
    assert board.ribbons.top[0].length == 27 mm and board.ribbons.top[0].width == 4 mm,
        "ribbon slots 27 x 4"
    assert board.ribbons.top[1].center.y - board.bottom.start.y == 245 mm, "top slots 245 up"
    assert board.ribbons.low[1].center.y - board.bottom.start.y == 70 mm, "low slots 70 up"
    assert board.ribbons.top[2].center.x - board.ribbons.top[0].center.x == 100 mm,
        "ribbons at -50 / 0 / +50"
    assert board.hang_r.head_hole.center.x - board.hang_l.head_hole.center.x == 50 mm,
        "keyholes at -25 / +25"
    assert board.hang_l.head_hole.center.y - board.bottom.start.y == 255 mm, "keyholes 255 up"
    assert board.name.t.size == 30 mm, "letters 30 tall"
    assert distance(board.name, board.hang_l) >= 3 mm and distance(board.name, board.hang_r) >= 3 mm,
        "name clear of the keyholes"
    assert shelf.slab.width == 180 mm and shelf.slab.height - 3 mm == 60 mm,
        "shelf 180 wide, 60 out from the board"
    assert len(shelf.back.gap) == 3, "two tabs (three gaps)"
    assert shelf_z + 3 mm - bracket_r.bb.height >= 0 mm, "brackets end above the board's bottom"
    assert board.ribbons.low[0].bb.bottom - (shelf_z + 3 mm) >= 10 mm, "ribbon slots clear of the shelf"
}
