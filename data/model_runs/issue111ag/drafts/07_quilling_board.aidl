# Request (crafts): a paper-quilling circle sizer board, 3 mm ply, two layers glued.
# - top plate 200 x 120 mm, 6 mm corner radii, with 11 round holes: a top row of 6 holes
#   6, 8, 10, 12, 14, 16 mm across, 28 mm apart, their centres 20 mm above the plate's
#   centre line; a bottom row of 5 holes 18, 20, 22, 24, 26 mm across, 36 mm apart,
#   centres 25 mm below it; both rows centred left-right;
# - each hole's size engraved under it ("6" ... "26"), 4 mm tall, its top 3 mm below the
#   hole's lowest point;
# - "QUILLING CIRCLES" engraved 7 mm tall, centred, baseline 42 mm above the centre line;
# - a plain base plate of the same outline closes the holes so the coils sit in them.

units mm
thickness 3 mm

sizes_top = [6, 8, 10, 12, 14, 16]
sizes_bottom = [18, 20, 22, 24, 26]
pitch_top = 28 mm
pitch_bottom = 36 mm

assembly quilling_board {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=200, height=120, corner_radius=6)
        Fixed(body)
        hole row1 {
            for i in range(len(sizes_top)) {
                c = Circle(center=(-(len(sizes_top) - 1) * pitch_top / 2 + i * pitch_top, 20),
                           diameter=sizes_top[i])
            }
        }
        hole row2 {
            for i in range(len(sizes_bottom)) {
                c = Circle(center=(-(len(sizes_bottom) - 1) * pitch_bottom / 2 + i * pitch_bottom,
                                   -25), diameter=sizes_bottom[i])
            }
        }
        drawing labels1 {
            for i in range(len(sizes_top)) {
                t = Text(str(sizes_top[i]), position=(0, 0), size=4, valign="top")
            }
        }
        drawing labels2 {
            for i in range(len(sizes_bottom)) {
                t = Text(str(sizes_bottom[i]), position=(0, 0), size=4, valign="top")
            }
        }
        for i in range(len(sizes_top)) {
            At(labels1.t[i].position, row1.c[i].bottom, dy=-3)
        }
        for i in range(len(sizes_bottom)) {
            At(labels2.t[i].position, row2.c[i].bottom, dy=-3)
        }
        drawing title {
            t = Text("QUILLING CIRCLES", position=(0, 42), size=7)
        }
    }

    solid base {
        body = RoundedRectangle(center=(0, 0), width=200, height=120, corner_radius=6)
    }
    RightOf(base, top, gap=10)
    AlignBottom(base, top)

    assert top.body.bb.width == 200 mm and top.body.bb.height == 120 mm, "plate 200 x 120"
    assert len(top.row1.c) == 6 and len(top.row2.c) == 5, "6 + 5 holes"
    assert top.row1.c[0].diameter == 6 mm and top.row1.c[5].diameter == 16 mm, "6 to 16"
    assert top.row2.c[0].diameter == 18 mm and top.row2.c[4].diameter == 26 mm, "18 to 26"
    assert abs(top.row1.c[1].center.x - top.row1.c[0].center.x - 28 mm) < 0.01 mm, "28 apart"
    assert abs(top.row2.c[1].center.x - top.row2.c[0].center.x - 36 mm) < 0.01 mm, "36 apart"
    assert abs(top.row1.c[0].center.y - 20 mm) < 0.01 mm, "top row 20 above"
    assert abs(top.row2.c[0].center.y + 25 mm) < 0.01 mm, "bottom row 25 below"
    assert abs(top.row1.c[0].center.x + top.row1.c[5].center.x) < 0.01 mm, "top row centred"
    assert abs(top.row2.c[0].center.x + top.row2.c[4].center.x) < 0.01 mm, "bottom row centred"
    assert top.labels1.t[2].text == "10", "labels read the sizes"
    assert top.labels2.bb.bottom > top.body.bb.bottom + 3 mm, "labels on the plate"
    assert top.labels1.bb.bottom > top.row2.bb.top + 2 mm, "top labels clear the bottom row"
    assert top.title.bb.top < top.body.bb.top - 3 mm, "title on the plate"
    assert base.body.bb.width == top.body.bb.width, "base of the same outline"
}
