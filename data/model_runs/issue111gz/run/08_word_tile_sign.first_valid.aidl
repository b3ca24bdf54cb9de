# Request (signs): "A 'HOME' wall sign made of word-game letter tiles, 3 mm birch ply. Four square
# tiles 50 x 50 mm with R4 corners, 2 mm apart; on each the letter engraved filled in bold serif
# capitals 30 mm tall, centred, and the tile's point value in 8 mm figures in the bottom-right
# corner (H 4, O 1, M 3, E 1), as on the game's tiles. The tiles are glued onto a hidden backing
# rail 206 x 30 mm (R4 corners) that hangs on two screws through keyholes (8 mm head, 4 mm slot
# 10 mm long, upward) 150 mm apart, centred; engrave guide lines on the rail at the edges of the
# 2 mm gaps so the tiles go on straight."

units mm
thickness 3 mm

import "std/plates.aidl"

letters = ["H", "O", "M", "E"]
points = [4, 1, 3, 1]
tile_s = 50 mm
gap = 2 mm
rail_w = 4 * tile_s + 3 * gap

def word_tile(letter="A", value=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=tile_s, height=tile_s, corner_radius=4)
    drawing face {
        big = Text(letter, position=(-2, 4), size=30, font="serif:Bold", valign="middle",
                   fill=true)
    }
    drawing score {
        v = Text(str(value), position=(tile_s / 2 - 4, -tile_s / 2 + 4), size=8, anchor="end",
                 font="serif:Bold", fill=true)
    }
    assert distance(face, score) >= 1 mm, "value clear of the letter"
    assert score.bb.right <= body.bb.right - 2 mm and score.bb.bottom >= body.bb.bottom + 2 mm,
        "value inside the tile"
}

assembly home_sign {
    for i in range(4) {
        tile = word_tile(letter=letters[i], value=points[i])
    }
    for i in range(1, 4) {
        RightOf(tile[i], tile[i - 1], gap=gap)
        AlignTop(tile[i], tile[i - 1])
    }

    solid rail {
        body = RoundedRectangle(center=(0, 0), width=rail_w, height=30, corner_radius=4)
        left_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-75 mm,
                           cy=-4 mm)
        right_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=75 mm,
                            cy=-4 mm)
        drawing guides {
            for i in range(3) {
                x0 = -rail_w / 2 + (i + 1) * tile_s + i * gap
                a = Line((x0, -13), (x0, 13))
                b = Line((x0 + gap, -13), (x0 + gap, 13))
            }
        }
        assert body.bb.width == 206 mm and body.bb.height == 30 mm, "rail 206 x 30"
        assert right_key.head_hole.center.x - left_key.head_hole.center.x == 150 mm,
            "keyholes 150 apart"
        assert distance(guides, left_key) >= 2 mm and distance(guides, right_key) >= 2 mm,
            "guides clear of the keyholes"
    }
    Below(rail, tile[0], gap=10)
    AlignLeft(rail, tile[0])

    assert tile[3].bb.right - tile[0].bb.left == 206 mm, "four tiles 2 mm apart span the rail"
    assert len(tile) == 4, "four tiles"
}
