# Request (crafts): a sewing seam-allowance gauge, cut from 2 mm clear acrylic.
# A card 160 x 45 mm, its left corners R3 and its right end fully rounded (R22.5,
# for marking curves) with a 6 mm hanging hole centred in the round end. Five
# square-bottomed notches 2 mm wide cut down from the top edge to the common
# seam allowances 1/8, 1/4, 3/8, 1/2 and 5/8 inch, 20 mm apart, the first 20 mm
# from the left end; each notch's allowance engraved under it ("1/8" ...), 4 mm
# letters, their tops 2 mm below the notch's bottom. A 100 mm rule engraved
# along the bottom edge starting 5 mm from the left end: a tick every 1 mm
# (3 mm long), every 5 mm (4.5 mm), every 10 mm (6 mm), the centimetres
# numbered 0 to 10 in 3 mm figures just above the long ticks.

thickness 2 mm

card_w = 160 mm
card_h = 45 mm
allowances = [0.125 in, 0.25 in, 0.375 in, 0.5 in, 0.625 in]
names = ["1/8", "1/4", "3/8", "1/2", "5/8"]
notch_w = 2 mm
left = -card_w / 2
top = card_h / 2
bottom = -card_h / 2

solid gauge {
    body = RoundedRectangle(center=(0, 0), width=card_w, height=card_h,
                            corner_radii=[3 mm, card_h / 2, card_h / 2, 3 mm])

    hole hang {
        c = Circle(center=(card_w / 2 - card_h / 2, 0), diameter=6 mm)
    }

    hole notches {
        for i in range(5) {
            n = Rectangle(center=(left + 20 mm + i * 20 mm, top - allowances[i] / 2 + 0.5 mm),
                          width=notch_w, height=allowances[i] + 1 mm, overrun=true)
        }
    }

    drawing labels {
        for i in range(5) {
            t = Text(names[i], position=(left + 20 mm + i * 20 mm, top - allowances[i] - 2 mm),
                     size=4, valign="top")
        }
    }

    drawing rule {
        for i in range(101) {
            tick = Line((left + 5 mm + i * 1 mm, bottom),
                        (left + 5 mm + i * 1 mm,
                         bottom + (6 mm if i % 10 == 0 else (4.5 mm if i % 5 == 0 else 3 mm))))
        }
        for j in range(11) {
            num = Text(str(j), position=(left + 5 mm + j * 10 mm, bottom + 7 mm), size=3)
        }
    }

    assert body.bb.width == 160 mm and body.bb.height == 45 mm, "card 160 x 45"
    assert hang.c.diameter == 6 mm, "6 mm hanging hole"
    assert body.bb.right - hang.c.center.x == 22.5 mm, "hole centred in the round end"
    assert len(notches.n) == 5, "five notches"
    assert body.bb.top - (notches.n[0].center.y - notches.n[0].height / 2) == 0.125 in, "1/8 in notch"
    assert body.bb.top - (notches.n[4].center.y - notches.n[4].height / 2) == 0.625 in, "5/8 in notch"
    assert notches.n[0].center.x - body.bb.left == 20 mm, "first notch 20 mm from the left"
    assert notches.n[1].center.x - notches.n[0].center.x == 20 mm, "notches 20 mm apart"
    assert len(rule.tick) == 101, "a tick every mm over 100 mm"
    assert rule.tick[100].start.x - rule.tick[0].start.x == 100 mm, "100 mm rule"
    assert rule.tick[0].start.x - body.bb.left == 5 mm, "rule starts 5 mm in"
}
