# Request (crafts): a windowsill rack for my pottery glaze test tiles (each 40 mm wide, 70 mm tall,
# 8 mm thick), numbered to match my glaze notebook. 6 mm ply, four parts:
# - a floor board and a comb board, each 480 x 50 mm between the sides, with two 12 mm glued
#   tabs at each end into closed slots in the sides (0.1 mm clearance);
# - the comb holds the tiles upright 20 mm above the floor: ten 42 x 9 mm slots at 48 mm pitch,
#   centred, 5 mm behind the board's middle; the numbers 1 to 10 engraved (6 mm single-stroke)
#   in front of their slots;
# - two sides 50 mm deep, 75 mm tall with a round (R25) top; the floor's underside 8 mm above the
#   sill so the slots have wood under them.

import "std/joints.aidl"

thickness 6 mm

param clear = 0.1 mm, min = 0 mm, max = 0.3 mm

tiles = 10
pitch = 48 mm
tile_w = 40 mm
tile_t = 8 mm
tile_h = 70 mm
board_len = 480 mm
depth = 50 mm
floor_z = 8 mm
comb_gap = 20 mm
comb_z = floor_z + 6 mm + comb_gap

def board(comb=false) -> solid {
    body = Rectangle(center=(0, 0), width=board_len + 12, height=depth)
    left_end = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=2, tab=12 mm, screw=0,
                            rotation=90 deg, cx=-board_len / 2 - 6, cy=0 mm)
    right_end = tab_and_slot(part="tab", length=50 mm, thickness=6 mm, tabs=2, tab=12 mm, screw=0,
                             rotation=-90 deg, cx=board_len / 2 + 6, cy=0 mm)
    if comb {
        hole slot {
            s = Rectangle(center=(-(tiles - 1) * pitch / 2, 5), width=42, height=9)
        }
        slots = LinearPattern(slot, tiles, (pitch, 0))
        drawing numbers {
            for i in range(tiles) {
                n = Text(str(i + 1), position=(-(tiles - 1) * pitch / 2 + i * pitch, -15), size=6)
            }
        }
    }
}

def side() -> solid {
    lower = Rectangle(bottom_left=(-25, 0), width=50, height=50)
    top = Circle(center=(0, 50), radius=25)
    floor_slots = tab_and_slot(part="slot", length=50 mm, thickness=6 mm, tabs=2, tab=12 mm,
                               screw=0, clearance=clear, cx=0 mm, cy=floor_z + 3 mm)
    comb_slots = tab_and_slot(part="slot", length=50 mm, thickness=6 mm, tabs=2, tab=12 mm,
                              screw=0, clearance=clear, cx=0 mm, cy=comb_z + 3 mm)
}

assembly rack {
    floor = board()
    comb = board(comb=true)
    left = side()
    right = side()

    # on the sheet
    Above(comb, floor, gap=5)
    AlignLeft(comb, floor)
    Above(left, comb, gap=5)
    AlignLeft(left, comb)
    RightOf(right, left, gap=5)
    AlignBottom(right, left)

    # in 3D: boards level between the sides, sides' top faces outward
    Place(floor, position=(0, 0, floor_z), face="up", up="back")
    Place(comb, position=(0, 0, comb_z), face="up", up="back")
    Place(left, position=(-board_len / 2, 0, 0), face="left", up="up")
    Place(right, position=(board_len / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert len(comb.slots) == 10, "ten tiles"
    assert comb.slots[1].s.center.x - comb.slots[0].s.center.x == 48 mm, "48 pitch"
    assert comb.slots[0].s.width - tile_w >= 1 mm and comb.slots[0].s.height - tile_t >= 0.5 mm, "tile fits its slot"
    assert comb.slots[9].s.bb.right - comb.slots[0].s.bb.left <= board_len - 2 * 10 mm, "slots clear of the sides"
    assert comb.slot.s.center.y == 5 mm, "slots 5 behind the middle"
    assert comb_z - (floor_z + 6 mm) == 20 mm, "comb 20 above the floor"
    assert tile_h - comb_gap - 6 mm >= 40 mm, "40 mm of each tile shows above the comb"
    assert left.bb.height == 75 mm and left.bb.width == 50 mm, "sides 50 x 75"
    assert left.comb_slots.slot[0].bb.top <= 50 mm, "comb slots under the round top"
    assert floor_z - 0.05 mm >= 5 mm, "wood under the floor slots"
    assert len(comb.numbers.n) == 10 and comb.numbers.n[9].text == "10", "numbered 1 to 10"
    assert comb.numbers.bb.top <= comb.slot.s.bb.bottom - 2 mm, "numbers in front of the slots"
}
