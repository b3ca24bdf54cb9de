# Music: a box for a 10-hole diatonic harmonica (101 x 27 x 20 mm), 3 mm plywood, finger
# joints (fingers at least 8 mm), a lift-off lid with a lip. Space inside 104 x 30 x 22 mm.
# The lid (110 x 36 mm outside) is engraved: "HARMONICA" in sans Bold, filled, 7 mm tall,
# its middle 6 mm above the lid's centre; below it a row of 10 engraved squares 4 x 4 mm,
# 8 mm apart, centred, their middles 7 mm below the lid's centre (the harmonica's holes).

units mm
thickness 3 mm

import "std/boxes.aidl"

assembly harmonica_case {
    box = lid_box(length=104 mm, width=30 mm, height=22 mm, thickness=3 mm, finger=8 mm,
                  outside=false)

    drawing art {
        word = Text("HARMONICA", position=(0, 6), size=7, font="sans:Bold", valign="middle",
                    fill=true)
        for i in range(10) {
            sq = Rectangle(center=(-36 + i * 8, -7), width=4, height=4)
        }
    }
    CutInto(art, box.lid)
    At(art.word.position, box.lid.bb.center, dy=6)
    art.sq[0].center.x + art.sq[9].center.x == 2 * box.lid.bb.center_x

    assert box.lid.bb.width == 110 mm and box.lid.bb.height == 36 mm, "lid 110 x 36 outside"
    assert len(art.sq) == 10, "10 holes"
    assert art.sq[1].center.x - art.sq[0].center.x == 8 mm, "8 mm apart"
    assert box.lid.bb.center_y - art.sq[0].center.y == 7 mm, "squares 7 below the centre"
    assert art.word.size == 7 mm, "7 mm letters"
}
