# Request: a comb for paper marbling that rests across a 300 mm tray. Three 3 mm
# acrylic layers, each 340 x 30 mm with R5 corners, glued in a stack. Two rows of
# dressmaker pins (0.6 mm shanks, 1.8 mm heads) point down: row A has 28 pins at a
# 10 mm pitch, 8 mm in front of the centre line; row B has 27 pins, 8 mm behind
# it, staggered 5 mm, so the two rows together comb at 5 mm. The bottom layer has
# 0.7 mm holes the shanks push through, the middle layer 2.2 mm holes that take
# the heads, the top layer closes them and is engraved "MARBLING COMB 10/5 MM"
# (4 mm single-stroke capitals) on the centre line and a 3 mm tick over each
# pin of row A. Both rows centred on the bar.

thickness 3 mm

bar_l = 340 mm
bar_w = 30 mm
pitch = 10 mm
row_off = 8 mm

def layer(hole_d=0.7 mm) -> solid {
    body = RoundedRectangle(center=(0, 0), width=bar_l, height=bar_w, corner_radius=5)
    hole row_a {
        for i in range(28) {
            c = Circle(center=(-135 + i * pitch, -row_off), diameter=hole_d)
        }
    }
    hole row_b {
        for i in range(27) {
            c = Circle(center=(-130 + i * pitch, row_off), diameter=hole_d)
        }
    }
    Fixed(body)
}

assembly comb {
    bottom = layer(hole_d=0.7 mm)
    middle = layer(hole_d=2.2 mm)
    solid top {
        body = RoundedRectangle(center=(0, 0), width=bar_l, height=bar_w, corner_radius=5)
        drawing marks {
            label = Text("MARBLING COMB 10/5 MM", position=(0, 0), size=4, valign="middle")
            for i in range(28) {
                tick = Line((-135 + i * pitch, -row_off - 1.5 mm), (-135 + i * pitch, -row_off + 1.5 mm))
            }
        }
        Fixed(body)
    }

    # flat: the layers one under another
    Below(middle, bottom, gap=5)
    AlignLeft(middle, bottom)
    Below(top, middle, gap=5)
    AlignLeft(top, middle)

    # assembled: stacked, the bottom layer lowest (the pins point down)
    Place(bottom, position=(0, 0, 0))
    Place(middle, position=(0, 0, 3))
    Place(top, position=(0, 0, 6))

    assert bottom.body.width == 340 mm and bottom.body.height == 30 mm, "340 x 30"
    assert len(bottom.row_a.c) == 28 and len(bottom.row_b.c) == 27, "28 + 27 pins"
    assert bottom.row_a.c[1].center.x - bottom.row_a.c[0].center.x == 10 mm, "10 mm pitch"
    assert bottom.row_b.c[0].center.x - bottom.row_a.c[0].center.x == 5 mm, "staggered 5"
    assert bottom.row_b.c[0].center.y - bottom.row_a.c[0].center.y == 16 mm, "rows 8 each side"
    assert bottom.row_a.c[0].diameter == 0.7 mm and middle.row_a.c[0].diameter == 2.2 mm, "hole sizes"
    # FIX after the first valid program: the centring asserts lacked abs(), so a row
    # off-centre to one side would have passed (no defect in the part itself)
    assert abs((bottom.row_a.bb.left - bottom.body.bb.left) - (bottom.body.bb.right - bottom.row_a.bb.right)) < 0.01 mm, "row A centred"
    assert abs((bottom.row_b.bb.left - bottom.body.bb.left) - (bottom.body.bb.right - bottom.row_b.bb.right)) < 0.01 mm, "row B centred"
    assert bottom.row_a.bb.right - bottom.row_a.bb.left <= 300 mm - 20 mm, "pins clear of the tray's walls"
    assert top.marks.bb.width <= top.body.width - 10 mm, "engraving on the bar"
}
