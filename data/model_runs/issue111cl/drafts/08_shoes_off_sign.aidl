# Request: a hallway sign from 3 mm ply, 200 x 90 mm with 8 mm rounded corners, reading
# "PLEASE REMOVE" over "YOUR SHOES" in bold sans capitals 14 mm tall, cut right through as
# stencil letters (the counters held by bridges) so the wall colour shows through. An engraved
# border line 5 mm in from the edge (3 mm corner radius) and two keyholes for 4 mm screws
# (8 mm head, 4 mm slot, 10 mm long, upward) 170 mm apart, inside the border.

import "std/plates.aidl"

units mm
thickness 3 mm

param sign_w = 200 mm, min = 160 mm, max = 300 mm
param sign_h = 90 mm, min = 70 mm, max = 140 mm
param letter = 14 mm, min = 10 mm, max = 20 mm

solid sign {
    board = RoundedRectangle(center=(0, 0), width=sign_w, height=sign_h, corner_radius=8)
    hole words {
        line1 = Text("PLEASE REMOVE", position=(0, 14), size=letter, font="sans:Bold",
                     valign="middle", stencil=true)
        line2 = Text("YOUR SHOES", position=(0, -14), size=letter, font="sans:Bold",
                     valign="middle", stencil=true)
    }
    drawing border {
        edge = RoundedRectangle(center=(0, 0), width=sign_w - 10, height=sign_h - 10,
                                corner_radius=3)
    }
    hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=-85 mm, cy=25 mm)
    hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                     cx=85 mm, cy=25 mm)

    assert board.width == 200 mm and board.height == 90 mm, "200 x 90 sign"
    assert hang_r.head_hole.center.x - hang_l.head_hole.center.x == 170 mm, "keyholes 170 mm apart"
    assert words.bb.width <= sign_w - 30 mm, "the words clear the border and keyholes"
    assert hang_l.bb.left >= border.edge.bb.left + 2 mm and hang_l.bb.top <= border.edge.bb.top - 2 mm, "keyholes inside the border"
    assert words.line1.size == 14 mm, "14 mm capitals"
}
