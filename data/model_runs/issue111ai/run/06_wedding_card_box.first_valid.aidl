# Request (parties): a wedding reception card box, 3 mm birch ply, finger-jointed, with a
# lift-off lid so the couple can empty it: 240 x 240 mm and 200 mm tall outside (lid
# included), fingers about 15 mm. A 160 x 8 mm card slot through the middle of the lid and
# the lip glued under it. The front: a heart-shaped window 68 mm wide and 60 mm tall, its
# centre 125 mm above the bottom edge, and "CARDS" in bold sans, 28 mm capitals, engraved
# filled, its baseline 45 mm above the bottom edge. The lid: "ANNA & JAMES" in serif, 14 mm,
# engraved filled, 45 mm in front of... above the slot's centre line, and the date
# "14 . 06 . 2026" in 7 mm strokes 30 mm below it.

units mm
thickness 3 mm
import "std/boxes.aidl"

assembly card_box {
    box = lid_box(length=240 mm, width=240 mm, height=200 mm, thickness=3 mm, finger=15 mm)

    # the card slot, through the lid and through the lip under it
    hole slot_lid { s = Rectangle(center=(0, 0), width=160, height=8) }
    CenterInside(slot_lid, box.lid)
    CutInto(slot_lid, box.lid)
    hole slot_lip { s = Rectangle(center=(0, 0), width=160, height=8) }
    CenterInside(slot_lip, box.lip)
    CutInto(slot_lip, box.lip)

    drawing names {
        couple = Text("ANNA & JAMES", (0, 45), size=14, font="serif", fill=true)
        date = Text("14 . 06 . 2026", (0, 15), size=7)
    }
    AlignCenterX(names, box.lid)
    names.couple.position.y == box.lid.bb.center_y + 45 mm
    CutInto(names, box.lid)

    # the front: a heart window and the word
    hole heart {
        left = Hull(Circle(center=(-16, 10), radius=18), Point(0, -32))
        right = Hull(Circle(center=(16, 10), radius=18), Point(0, -32))
    }
    AlignCenterX(heart, box.body.front)
    heart.bb.center_y == box.body.front.bb.bottom + 125 mm
    CutInto(heart, box.body.front)

    drawing word { t = Text("CARDS", (0, 0), size=28, font="sans:Bold", fill=true) }
    AlignCenterX(word, box.body.front)
    word.t.position.y == box.body.front.bb.bottom + 45 mm
    CutInto(word, box.body.front)

    assert box.lid.bb.width == 240 mm, "240 wide"
    assert slot_lid.s.width == 160 mm and slot_lid.s.height == 8 mm, "160 x 8 card slot"
    assert heart.bb.width == 68 mm and heart.bb.height == 60 mm, "heart 68 x 60"
    assert names.couple.position.y - names.date.position.y == 30 mm, "date 30 mm below"
    assert word.t.size == 28 mm, "28 mm capitals"
}
