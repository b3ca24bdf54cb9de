# Request: a wall rack for three rolling pins up to 50 mm across, 6 mm birch ply.
# Back board 300 wide x 360 tall with R12 corners, hung on two wall screws by
# keyholes (10 mm head, 5 mm slot, 12 mm long, pointing up) 220 mm apart, 25 mm
# below the top edge. "BAKE" engraved (filled, bold serif, 24 mm capitals) centred
# 40 mm below the top. Two hook arms stand out from the board, 200 mm apart centre
# to centre, their bottoms 40 mm above the board's bottom edge: each arm is 240 tall
# and 95 deep (from its back edge), a 28 mm spine along the wall carrying three
# hooks at a 100 mm pitch; a hook is a 95 x 40 block with a 54 mm round cradle
# whose centre is on the block's top edge, 55 mm from the arm's back edge. Each arm
# is glued into the board with two 30 mm tabs in closed slots.

import "std/joints.aidl"
import "std/plates.aidl"

thickness 6 mm

param board_w = 300 mm, min = 260 mm, max = 400 mm
param board_h = 360 mm, min = 340 mm, max = 450 mm
param arm_gap = 200 mm, min = 120 mm, max = 240 mm
pitch = 100 mm
arm_h = 240 mm
arm_d = 95 mm
cradle_d = 54 mm

def hook_arm() -> solid {
    spine = Rectangle(bottom_left=(0, 0), width=28, height=arm_h)
    for i in range(3) {
        blk = Rectangle(bottom_left=(0, i * pitch), width=arm_d, height=40)
    }
    hole cradles {
        for i in range(3) {
            c = Circle(center=(55, i * pitch + 40), diameter=cradle_d)
        }
    }
    # the back edge (x = 0) goes into the board: two glued tabs
    j = tab_and_slot(part="tab", length=arm_h, thickness=6 mm, tabs=2, tab=30 mm, screw=0,
                     rotation=90 deg, cx=0 mm, cy=arm_h / 2)
    # round the hooks' front corners and the inside corners under them (not the
    # tab roots: a rounded root would not seat in its mortise)
    Fillet([b.top_right for b in blk] + [b.bottom_right for b in blk], 4)
    Fillet([[blk[i].bottom, spine.right] for i in range(1, 3)], 4)
}

assembly rack {
    solid back {
        board = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=12)
        k1 = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, direction=90 deg,
                     cx=-110 mm, cy=board_h / 2 - 25 mm)
        k2 = keyhole(head=10 mm, slot_width=5 mm, length=12 mm, direction=90 deg,
                     cx=110 mm, cy=board_h / 2 - 25 mm)
        # mortises for the arms, centred on the arms' height
        sl = tab_and_slot(part="slot", length=arm_h, thickness=6 mm, tabs=2, tab=30 mm,
                          screw=0, rotation=90 deg, cx=-arm_gap / 2,
                          cy=-board_h / 2 + 40 mm + arm_h / 2)
        sr = tab_and_slot(part="slot", length=arm_h, thickness=6 mm, tabs=2, tab=30 mm,
                          screw=0, rotation=90 deg, cx=arm_gap / 2,
                          cy=-board_h / 2 + 40 mm + arm_h / 2)
        drawing word {
            t = Text("BAKE", position=(0, board_h / 2 - 40 mm), size=24, font="serif:Bold",
                     valign="middle", fill=true)
        }
        Fixed(board)
    }
    left = hook_arm()
    right = hook_arm()

    # flat: the arms beside the board
    RightOf(left, back, gap=10)
    AlignBottom(left, back)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    # assembled: the board on the wall (its back face on y = 0), the arms standing out
    # to the front, their tab tips at the board's back face
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(left, position=(-arm_gap / 2 + 3 mm, 0, -board_h / 2 + 40 mm), face="left", up="up")
    Place(right, position=(arm_gap / 2 + 3 mm, 0, -board_h / 2 + 40 mm), face="left", up="up")

    assert back.board.width == 300 mm and back.board.height == 360 mm, "board 300 x 360"
    assert back.k2.head_hole.center.x - back.k1.head_hole.center.x == 220 mm, "keyholes 220 apart"
    assert back.board.bb.top - back.k1.head_hole.center.y == 25 mm, "keyholes 25 below the top"
    assert back.sr.slot[0].bb.center_x - back.sl.slot[0].bb.center_x == 200 mm, "arms 200 apart"
    assert back.sl.slot[0].bb.bottom >= back.board.bb.bottom + 40 mm, "slots within the arm"
    assert left.spine.height == 240 mm, "arm 240 tall"
    assert left.blk[0].width == 95 mm and left.blk[0].height == 40 mm, "hook 95 x 40"
    assert left.cradles.c[1].center.y - left.cradles.c[0].center.y == 100 mm, "100 mm pitch"
    assert left.cradles.c[0].diameter == 54 mm, "54 mm cradle"
    assert left.blk[1].bb.bottom - left.blk[0].bb.top >= 55 mm, "room to lift a 50 mm pin over the lip"
    assert left.blk[0].bb.right - left.cradles.c[0].bb.right >= 10 mm, "front lip at least 10 mm"
    assert distance(back.word, back.k1) >= 5 mm, "BAKE clear of the keyholes"
}
