# Request (signs): a "DELIVERIES" sign for our front gate, pointing couriers round the side.
# A 300 x 160 base of 3 mm dark grey acrylic, 10 mm rounded corners, four countersunk M4
# holes (4.5 mm, 8 mm heads) 12 mm in from each corner.
# - "DELIVERIES" in 30 mm bold sans as raised letters cut from 3 mm white acrylic, glued on;
#   the base gets the letters' outlines engraved as a gluing guide; baseline 15 mm above
#   the base's middle, centred.
# - Below it, engraved: a parcel pictogram (a 40 x 40 filled square with a 6 mm unengraved
#   tape cross) centred 100 mm left of the middle and 35 mm below it; "ROUND THE SIDE" in
#   8 mm single-stroke capitals, centred, baseline 38 mm below the middle; a filled arrow
#   pointing right, 60 mm long, 24 mm high, centred 85 mm right of the middle, 35 mm below it.

units mm
thickness 3 mm

W = 300 mm
H = 160 mm
word_y = 15 mm

assembly sign {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
        hole screw { c = Circle(center=(0, 0), diameter=4.5) }
        screws = CornerPattern(screw, body, inset=12)
        Countersink(screws, diameter=8)
        drawing guide {
            t = Text("DELIVERIES", position=(0, word_y), size=30, font="sans:Bold")
        }
        drawing parcel {
            box = Rectangle(center=(-100, -35), width=40, height=40, fill=true)
            hole tape {
                v = Rectangle(center=(-100, -35), width=6, height=40)
                h = Rectangle(center=(-100, -35), width=40, height=6)
            }
        }
        drawing words {
            t = Text("ROUND THE SIDE", position=(0, -38), size=8)
        }
        drawing arrow {
            a = Polygon([(55, -29), (91, -29), (91, -23), (115, -35), (91, -47), (91, -41),
                         (55, -41)], fill=true)
        }
    }

    # raised letters: separate pieces, cut from the white sheet
    assembly letters {
        solid word {
            t = Text("DELIVERIES", position=(0, word_y), size=30, font="sans:Bold")
        }
    }

    Below(letters, base, gap=10)
    AlignCenterX(letters, base)
    Place(base, position=(0, 0, 0))
    Place(letters, position=(0, 0, 3))

    assert base.body.bb.width == 300 mm and base.body.bb.height == 160 mm, "300 x 160"
    assert len(base.screws) == 4, "four screws"
    assert base.body.bb.right - base.screws[1].c.center.x == 12 mm, "12 mm in"
    assert base.guide.t.position.y - base.body.center.y == 15 mm, "baseline 15 mm up"
    assert base.arrow.bb.width == 60 mm and base.arrow.bb.height == 24 mm, "arrow 60 x 24"
    assert base.arrow.bb.center_x - base.body.center.x == 85 mm, "arrow 85 mm right"
    assert base.parcel.bb.center_x - base.body.center.x == -100 mm, "parcel 100 mm left"
    assert distance(base.guide, base.screws) >= 5 mm, "letters clear of the screw heads"
    assert distance(base.words, base.arrow) >= 4 mm, "words clear of the arrow"
    assert distance(base.words, base.parcel) >= 4 mm, "words clear of the parcel"
    assert distance(base.words, base.guide) >= 4 mm, "two lines apart"
    assert letters.word.t.bb.width == base.guide.t.bb.width, "letters match their guide"
}
