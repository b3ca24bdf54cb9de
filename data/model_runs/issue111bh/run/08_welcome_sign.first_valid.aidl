# Request (signs): a layered "WELCOME" sign for a shop's front wall, from 6 mm ply. An oval
# backing board 440 x 180 mm with an engraved border 10 mm inside its edge, two keyholes
# (9 mm head, 4.5 mm slot, 10 mm long, pointing up) 240 mm apart and 55 mm above the
# middle, and "EST. 2019" engraved (10 mm single-stroke letters) 60 mm below the middle
# with a small engraved star (12 mm) each side of it. On it, glued, the word "WELCOME"
# cut as one piece: bold serif capitals 45 mm tall joined by a 6 mm rail along their
# baseline, centred 10 mm above the board's middle. Everything must stay inside the oval.

thickness 6 mm

param word = "WELCOME"
param cap = 45 mm, min = 30 mm, max = 60 mm
rx = 220 mm
ry = 90 mm
lift = 10 mm

import "std/plates.aidl"

assembly sign {
    solid board {
        oval = Ellipse(center=(0, 0), rx=rx, ry=ry)
        drawing border {
            inner = Ellipse(center=(0, 0), rx=rx - 10, ry=ry - 10)
        }
        k1 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                     cx=-120 mm, cy=55 mm)
        k2 = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg,
                     cx=120 mm, cy=55 mm)
        drawing est {
            t = Text("EST. 2019", position=(0, -60), size=10, valign="middle")
            s1 = Star(center=(-45, -60), points=5, outer_radius=6, inner_radius=2.5)
            s2 = Star(center=(45, -60), points=5, outer_radius=6, inner_radius=2.5)
        }
    }
    solid letters {
        w = Text(word, position=(0, lift), size=cap, font="serif:Bold", valign="middle")
        rail = Rectangle(center=(0, lift - cap / 2 + 2), width=w.bb.width - 10, height=6)
    }

    # flat on the sheet
    Above(letters, board, gap=10)
    AlignCenterX(letters, board)

    # assembled: the letters glued on the board's face
    Place(board, position=(0, 0, 0))
    Place(letters, position=(0, 0, 6))

    assert board.oval.bb.width == 440 mm and board.oval.bb.height == 180 mm, "440 x 180 oval"
    assert board.k2.head_hole.center.x - board.k1.head_hole.center.x == 240 mm, "keyholes 240 apart"
    assert letters.w.size == 45 mm, "45 mm capitals"
    # the word's corners inside the oval, as placed 10 mm above its middle
    assert (letters.w.bb.width / 2 / rx) ** 2 + ((lift + letters.w.bb.height / 2) / ry) ** 2 <= 1,
        "the word stays inside the oval"
}
