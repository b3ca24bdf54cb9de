# Request: a "WE NEED" shopping board for the kitchen wall, 6 mm birch ply. The board is
# 200 x 300 mm with 10 mm corners; "WE NEED" across the top, 16 mm tall, engraved filled in
# bold; two columns of ten everyday items engraved (7 mm letters), each with a 6.3 mm square
# peg hole to its left (rows 24 mm apart); two keyholes 160 mm apart near the top for hanging
# on screws (8 mm heads). Six pegs, each a 16 mm round head on a 6 mm wide, 10 mm long shank
# that pushes into a hole: when you run out of something you put a peg in next to it.

import "std/plates.aidl"

t = 6 mm
thickness t

board_w = 200 mm
board_h = 300 mm
peg_hole = 6.3 mm
row_pitch = 24 mm
pegs = 6

items = ["MILK", "BREAD", "EGGS", "BUTTER", "CHEESE", "COFFEE", "TEA", "SUGAR", "FLOUR", "RICE",
         "PASTA", "BEANS", "APPLES", "BANANAS", "ONIONS", "POTATOES", "TOMATOES", "JUICE",
         "CEREAL", "LOO ROLL"]

# grid position of item i: column i // 10, row i % 10, counted from the top
def hole_x(i) = -85 mm + (i // 10) * 93 mm
def row_y(i) = 90 mm - (i % 10) * row_pitch

def peg() -> solid {
    head = Circle(center=(0, 0), diameter=16 mm)
    shank = Rectangle(corner=(-t / 2, -18 mm), opposite=(t / 2, 0))
}

assembly kit {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=10)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-80 mm, cy=122 mm)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=80 mm, cy=122 mm)
        hole holes {
            for i in range(len(items)) {
                sq = Rectangle(center=(hole_x(i), row_y(i)), width=peg_hole, height=peg_hole)
            }
        }
        drawing title {
            word = Text("WE NEED", position=(0, 122), size=16, font="sans:Bold",
                        valign="middle", fill=true)
        }
        drawing list {
            for i in range(len(items)) {
                name = Text(items[i], position=(hole_x(i) + 10 mm, row_y(i)), size=7,
                            anchor="start", valign="middle")
            }
        }
        Fixed(body)

        assert len(items) == 20, "two columns of ten items"
        assert body.width == 200 mm and body.height == 300 mm, "a 200 x 300 board"
        assert hang_r.head_hole.center.x - hang_l.head_hole.center.x == 160 mm,
            "keyholes 160 mm apart"
        assert holes.sq[0].center.y - holes.sq[1].center.y == 24 mm, "rows 24 mm apart"
        assert holes.sq[0].width == 6.3 mm, "6.3 mm square peg holes"
        assert distance(title, hang_l) >= 3 mm and distance(title, hang_r) >= 3 mm,
            "the title clears the keyholes"
        assert list.bb.right <= body.bb.right - 8 mm, "the item names stay on the board"
        assert list.bb.bottom >= body.bb.bottom + 8 mm, "the last row stays on the board"
    }

    for i in range(pegs) {
        p = peg()
    }
    for i in range(pegs) {
        RightOf(p[i], board if i == 0 else p[i - 1], gap=6)
        AlignTop(p[i], board)
    }
    assert len(p) == 6, "six pegs"
    assert p[0].head.diameter == 16 mm and p[0].shank.bb.width == 6 mm, "16 mm heads, 6 mm shanks"
    assert p[0].head.bb.bottom - p[0].shank.bb.bottom == 10 mm, "a 10 mm shank below the head"
}
