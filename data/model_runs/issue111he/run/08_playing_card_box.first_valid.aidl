# Request (gifts): a box for two packs of playing cards (cards 63 x 88 mm, a pack 18 mm
# thick), a present for my card-playing grandad: 3 mm plywood, finger-jointed, with a lid
# that slides out. Inside: 132 mm long (the packs side by side with 6 mm to spare), 92 mm
# wide and 22 mm under the lid. The lid is engraved with GAME NIGHT in filled serif capitals
# 10 mm tall and under it the four suits (heart, spade, diamond, club), each about 14 mm
# tall, filled, 20 mm apart; all of it clear of the lid's finger pull.

import "std/boxes.aidl"

thickness 3 mm

assembly card_box {
    box = sliding_lid_box(length=132 mm, width=92 mm, height=22 mm, thickness=3 mm,
                          finger=10 mm, outside=false)

    drawing title {
        t = Text("GAME NIGHT", position=(0, 0), size=10, font="serif:Bold", valign="middle",
                 fill=true)
    }

    drawing suits {
        # heart, centred at x = -30
        h1 = Hull(Circle(center=(-33.2, 2), radius=3.6), Point(-30, -6.4), fill=true)
        h2 = Hull(Circle(center=(-26.8, 2), radius=3.6), Point(-30, -6.4), fill=true)
        # spade, centred at x = -10: an upside-down heart on a stem
        s1 = Hull(Circle(center=(-13.2, -1), radius=3.6), Point(-10, 7.4), fill=true)
        s2 = Hull(Circle(center=(-6.8, -1), radius=3.6), Point(-10, 7.4), fill=true)
        s3 = Triangle(center=(-10, -5), base=5, height=4, fill=true)
        # diamond, centred at x = 10
        d = Polygon([(10, 7), (15, 0), (10, -7), (5, 0)], fill=true)
        # club, centred at x = 30: three balls on a stem
        c1 = Circle(center=(30, 3.5), radius=3, fill=true)
        c2 = Circle(center=(26.5, -1.5), radius=3, fill=true)
        c3 = Circle(center=(33.5, -1.5), radius=3, fill=true)
        c4 = Triangle(center=(30, -5), base=5, height=4, fill=true)
    }

    AlignCenterX(title, box.lid)
    AlignCenterX(suits, box.lid)
    title.t.position.y == box.lid.bb.center_y + 22 mm
    suits.bb.center_y == box.lid.bb.center_y
    CutInto(title, box.lid)
    CutInto(suits, box.lid)

    assert box.length - 2 * 63 mm == 6 mm, "two packs side by side, 6 mm spare"
    assert box.width - 88 mm >= 4 mm, "cards 88 long fit across"
    assert box.height - 2 * 0 mm >= 18 mm, "a pack 18 thick fits under the lid"
    assert suits.d.bb.height == 14 mm, "suits about 14 mm tall"
    assert distance(suits, box.lid.pull) >= 5 mm and distance(title, box.lid.pull) >= 5 mm,
        "art clear of the finger pull"
    assert distance(title, suits) >= 5 mm, "title above the suits"
    assert title.bb.left - box.lid.bb.left >= 8 mm, "title inside the lid"
}
