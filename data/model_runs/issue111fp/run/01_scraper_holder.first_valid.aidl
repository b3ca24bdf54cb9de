# Request: a holder for my 150 x 64 mm cabinet card scraper (0.6 mm steel), so I can bow it
# with my thumbs without burning them. 6 mm birch ply. Two cheeks 210 x 56 mm with R10 corners
# clamp the top of the card between them; a finger grip slot 20 wide x 40 long through each
# end of both cheeks, 88 mm either side of the middle. Two M5 flat-head bolts 100 mm apart,
# 6 mm above the cheeks' middle line, clamp the cheeks; the card's top edge rests against
# their shanks, so at least 30 mm of the card sticks out below. The heads sit in 10 mm
# countersinks on the front cheek. An M6 bending bolt in the middle, 14 mm below the middle
# line, runs in a captive M6 nut trapped in the back cheek, covered by a glued 6 mm pad
# 50 x 24 (R6) with an M6 clearance hole. The front cheek has a notch 50 wide cut up from
# its bottom edge to 6 mm below the middle line so the card can bow forward. A 34 mm
# knurled knob (12 rounded ridges) holds the bending bolt's hex head. "CARD SCRAPER"
# engraved filled on the front cheek, 6 mm tall, centred 17 mm above the middle line.

import "std/fasteners.aidl"

thickness 6 mm

param cheek_w = 210 mm, min = 190 mm, max = 240 mm
param cheek_h = 56 mm, min = 50 mm, max = 70 mm
CARD_W = 150 mm
CARD_H = 64 mm
BOLT_DX = 100 mm
BOLT_Y = 6 mm
BEND_Y = -14 mm

def cheek(front=true) -> solid {
    body = RoundedRectangle(center=(0, 0), width=cheek_w, height=cheek_h, corner_radius=10)
    hole grips {
        left = Slot(center=(-88, 0), length=40, width=20, rotation=90 deg)
        right = Slot(center=(88, 0), length=40, width=20, rotation=90 deg)
    }
    bolt_l = clearance_hole(size=5, cx=-BOLT_DX / 2, cy=BOLT_Y)
    bolt_r = clearance_hole(size=5, cx=BOLT_DX / 2, cy=BOLT_Y)
    if front {
        hole notch {
            n = Rectangle(bottom_left=(-25, -cheek_h / 2 - 1), width=50, height=cheek_h / 2 + 1 - 6)
        }
        Countersink([bolt_l, bolt_r], diameter=10)
        drawing label {
            t = Text("CARD SCRAPER", position=(0, 17), size=6, font="sans:Bold", valign="middle",
                     fill=true)
        }
    } else {
        nut = nut_trap(size=6, cx=0, cy=BEND_Y)
    }
}

assembly scraper_holder {
    front_cheek = cheek(front=true)
    back_cheek = cheek(front=false)
    solid nut_cover {
        pad = RoundedRectangle(center=(0, 0), width=50, height=24, corner_radius=6)
        bore = clearance_hole(size=6, cx=0, cy=0)
    }
    solid knob {
        rim = Star(center=(0, 0), points=12, outer_radius=17, inner_radius=15, tip_radius=1.5)
        head = nut_trap(size=6, cx=0, cy=0)
    }
    # lay out flat for cutting
    Below(back_cheek, front_cheek, gap=8)
    AlignLeft(back_cheek, front_cheek)
    RightOf(nut_cover, back_cheek, gap=8)
    AlignTop(nut_cover, back_cheek)
    RightOf(knob, front_cheek, gap=8)
    AlignTop(knob, front_cheek)

    # in 3D: the cheeks meet at y = 0 (the card goes between them), the front one's engraving
    # and countersinks to the front; the pad on the back cheek over the nut; the knob behind it
    Place(front_cheek, position=(0, 0, 0), face="front", up="up")
    Place(back_cheek, position=(0, 0, 0), face="back", up="up")
    Place(nut_cover, on=back_cheek, position=(0, BEND_Y))
    Place(knob, on=nut_cover, position=(0, 0))

    # the request's numbers
    assert front_cheek.body.width == 210 mm and front_cheek.body.height == 56 mm, "cheek 210 x 56"
    assert front_cheek.bolt_r.c.center.x - front_cheek.bolt_l.c.center.x == 100 mm, "bolts 100 apart"
    assert front_cheek.bolt_l.c.center.y - front_cheek.body.center.y == 6 mm, "bolts 6 above the middle"
    # the card hangs from the bolts' shanks (M5: 2.5 mm radius)
    assert (front_cheek.bolt_l.c.center.y - 2.5 mm - 64 mm) <= front_cheek.body.bb.bottom - 30 mm,
        "at least 30 mm of the card sticks out"
    assert front_cheek.bolt_r.c.center.x - front_cheek.bolt_l.c.center.x <= 150 mm - 20 mm,
        "both bolts bear on the card's top edge"
    assert front_cheek.notch.n.width == 50 mm, "notch 50 wide"
    assert front_cheek.notch.n.bb.top - front_cheek.body.center.y == -6 mm, "notch up to 6 below the middle"
    assert back_cheek.nut.hex.center.y - back_cheek.body.center.y == -14 mm, "bending bolt 14 below"
    assert knob.bb.width <= 34 mm, "knob 34 across"
}
