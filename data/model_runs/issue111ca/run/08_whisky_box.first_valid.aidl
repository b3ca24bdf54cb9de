# Request (gifts): a 40th-birthday gift box for a bottle of whisky (80 mm across, 300 mm
# long, laid on its side), from 6 mm ply: a finger-jointed box 340 x 120 x 120 mm outside
# (20 mm fingers) whose lid turns on pins cut from the sheet. On the lid, engraved filled and
# centred: "DAVID" (serif bold, 28 mm) over "40 YEARS  1985 - 2025" (serif, 10 mm). Inside,
# two 50 mm tall cradles standing across the box, 1 mm shorter than the inside width, with
# a half-round notch in each top edge: 82 mm for the bottle's body (60 mm right of the
# box's middle) and 34 mm for its neck (105 mm left of it), so the bottle lies level.

import "std/boxes.aidl"

thickness 6 mm

T = 6 mm
L = 340 mm
W = 120 mm
H = 120 mm
inner_w = W - 2 * T
cradle_h = 50 mm

def cradle(notch_d) -> solid {
    board = Rectangle(bottom_left=(-(inner_w - 1 mm) / 2, 0), width=inner_w - 1 mm,
                      height=cradle_h)
    hole notch { c = Circle(center=(0, cradle_h), diameter=notch_d) }
}

assembly gift {
    box = hinged_box(length=L, width=W, height=H, thickness=T, finger=20 mm)
    drawing words {
        name = Text("DAVID", position=(0, 8), size=28, font="serif:Bold", fill=true)
        years = Text("40 YEARS  1985 - 2025", position=(0, -16), size=10, font="serif",
                     fill=true)
    }
    CenterInside(words, box.lid)
    CutInto(words, box.lid)

    body_cradle = cradle(notch_d=82 mm)
    neck_cradle = cradle(notch_d=34 mm)
    RightOf(body_cradle, box, gap=10)
    AlignBottom(body_cradle, box)
    RightOf(neck_cradle, body_cradle, gap=10)
    AlignBottom(neck_cradle, body_cradle)

    # in 3D: standing across the box on its floor
    Place(body_cradle, rotation=(90 deg, 0, 90 deg), position=(60 mm - T / 2, 0, T))
    Place(neck_cradle, rotation=(90 deg, 0, 90 deg), position=(-105 mm - T / 2, 0, T))

    assert body_cradle.notch.c.diameter == 82 mm and neck_cradle.notch.c.diameter == 34 mm, "notches"
    assert body_cradle.board.bb.width == inner_w - 1 mm, "1 mm shorter than the inside"
    # the bottle lies level: its axis is at the same height in both notches
    assert body_cradle.notch.c.center.y - body_cradle.board.bb.bottom ==
        neck_cradle.notch.c.center.y - neck_cradle.board.bb.bottom, "bottle level"
    # the bottle clears the lid: its top under the inside height
    assert T + cradle_h + 41 mm < H - 2 * T, "bottle under the lid"
    assert words.name.size == 28 mm and words.years.size == 10 mm, "text sizes"
}
