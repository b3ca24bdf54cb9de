# Request: a two-layer EXIT sign for the workshop door, 300 x 120 mm with 8 mm corners. Front plate
# 3 mm green acrylic: "EXIT" cut through in bold sans letters 50 mm high, centred 40 mm left of the
# middle, and a right-pointing arrow cut through to the right of it (70 mm long: a 40 x 16 mm shaft
# and a 30 mm head 44 mm wide, its tip 125 mm right of the middle), at least 10 mm clear of the word;
# an engraved border line 15 mm in from the edges (270 x 90, 4 mm corners); four M3 countersunk holes
# (6.5 mm heads) 10 mm in from the corners. Back plate 3 mm white acrylic showing through the cuts:
# four 2.5 mm holes under the front's screws (tapped M3), and two keyholes (8 mm head, 4 mm slot,
# 10 mm long, upwards) 100 mm either side of the middle, 40 mm above the centre line, to hang it on
# two screws. Two parts.

import "std/fasteners.aidl"
import "std/plates.aidl"

units mm
thickness 3 mm

assembly exit_sign {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=300, height=120, corner_radius=8)
        hole word {
            t = Text("EXIT", position=(-40, 0), size=50, font="sans:Bold", valign="middle")
        }
        hole arrow {
            a = Polygon([(55, -8), (95, -8), (95, -22), (125, 0), (95, 22), (95, 8), (55, 8)])
        }
        drawing border {
            b = RoundedRectangle(center=(0, 0), width=270, height=90, corner_radius=4)
        }
        screw = clearance_hole(size=3)
        screws = CornerPattern(screw, body, inset=10 mm)
        Countersink(screws, diameter=6.5 mm)
    }
    solid back {
        body = RoundedRectangle(center=(0, 0), width=300, height=120, corner_radius=8)
        hole tap { c = Circle(center=(0, 0), diameter=2.5) }
        taps = CornerPattern(tap, body, inset=10 mm)
        hang_l = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
        hang_r = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg)
        At(hang_l.head_hole.center, body.center, dx=-100 mm, dy=40 mm)
        At(hang_r.head_hole.center, body.center, dx=100 mm, dy=40 mm)
    }

    # flat on the sheet
    Below(back, front, gap=8 mm)
    AlignCenterX(back, front)

    # assembled: front on the back
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3 mm))

    # the request's numbers
    assert front.body.bb.width == 300 mm and front.body.bb.height == 120 mm, "300 x 120"
    assert back.body.bb.width == 300 mm and back.body.bb.height == 120 mm, "back the same"
    assert front.word.t.size == 50 mm, "letters 50 mm high"
    assert front.arrow.a.bb.width == 70 mm and front.arrow.a.bb.height == 44 mm, "arrow 70 x 44"
    assert front.arrow.a.bb.right - front.body.bb.center_x == 125 mm, "arrow tip 125 mm right"
    assert front.arrow.a.bb.left - front.word.t.bb.right >= 10 mm, "arrow clear of the word"
    assert front.word.t.bb.left - front.border.b.bb.left >= 5 mm, "word inside the border"
    assert front.border.b.bb.width == 270 mm and front.border.b.bb.height == 90 mm, "border"
    assert len(front.screws) == 4 and len(back.taps) == 4, "four screws"
    assert back.hang_r.head_hole.center.x - back.hang_l.head_hole.center.x == 200 mm, "keyholes"
    assert back.hang_r.head_hole.center.y - back.body.bb.center_y == 40 mm, "40 mm up"
}
