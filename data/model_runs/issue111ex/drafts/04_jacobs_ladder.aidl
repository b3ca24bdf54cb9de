# Request: a Jacob's ladder toy for my nephew: six tiles of 6 mm ply, 60 x 45 mm, corners R2,
# to be joined by 8 mm ribbons running along the 45 mm side. Each tile's face has its number,
# 1 to 6, engraved filled in bold, 22 mm tall, centred; and the glue positions of the three
# ribbons (centred 20 mm left of the middle, on the middle and 20 mm right of it) are marked
# by 3 mm engraved ticks at the tile's top and bottom edges, one at each edge of a ribbon,
# stopping 0.5 mm short of the cut. Cut them in two rows of three, 4 mm apart.

thickness 6 mm

param tile_w = 60 mm
param tile_h = 45 mm
param ribbon = 8 mm
param gap = 4 mm

ribbon_x = [-20, 0, 20]

def tile(num=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=tile_w, height=tile_h, corner_radius=2)
    drawing face {
        digit = Text(str(num), position=(0, 0), size=22, font="sans:Bold", valign="middle",
                     fill=true)
        for r in range(3) {
            for e in [-1, 1] {
                top = Line((ribbon_x[r] + e * ribbon / 2, tile_h / 2 - 0.5 mm),
                           (ribbon_x[r] + e * ribbon / 2, tile_h / 2 - 3.5 mm))
                bottom = Line((ribbon_x[r] + e * ribbon / 2, -tile_h / 2 + 0.5 mm),
                              (ribbon_x[r] + e * ribbon / 2, -tile_h / 2 + 3.5 mm))
            }
        }
    }
}

assembly jacobs_ladder {
    for i in range(6) {
        t = tile(num=i + 1)
    }
    for i in range(1, 6) {
        if i % 3 == 0 {
            Below(t[i], t[i - 3], gap=gap)
            AlignLeft(t[i], t[i - 3])
        } else {
            RightOf(t[i], t[i - 1], gap=gap)
            AlignTop(t[i], t[i - 1])
        }
    }

    # the request's numbers
    assert len(t) == 6, "six tiles"
    assert t[0].body.width == 60 mm and t[0].body.height == 45 mm, "tiles 60 x 45"
    assert t[5].face.digit.text == "6", "the last tile is number 6"
    assert t[0].face.digit.size == 22 mm, "numbers 22 mm tall"
    assert t[0].face.top[0][1].start.x - t[0].face.top[0][0].start.x == 8 mm, "ribbons 8 mm"
    assert t[0].face.top[1][0].start.x - t[0].body.center.x == -4 mm, "middle ribbon centred"
    assert t[0].face.top[0][0].length == 3 mm, "3 mm ticks"
    assert t[0].body.bb.top - t[0].face.top[0][0].start.y == 0.5 mm, "ticks 0.5 mm short of the cut"
    assert t[1].bb.left - t[0].bb.right == 4 mm, "4 mm apart"
    assert t[0].bb.bottom - t[3].bb.top == 4 mm, "rows 4 mm apart"
}
