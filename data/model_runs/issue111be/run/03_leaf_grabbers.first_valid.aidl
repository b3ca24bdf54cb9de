# Request (garden): a pair of leaf grabbers (hand-held leaf scoops), 6 mm exterior ply. Each is
# 280 mm wide: a palm 170 mm tall at the sides with an arched top rising to 210 mm in the
# middle, and below it seven 28 mm wide tines, 100 mm long with round tips, 14 mm apart; a
# 100 x 32 mm hand slot centred 150 mm above the tines' roots; every other corner rounded 6 mm;
# "LEAVES" engraved filled, 20 mm high bold, centred 85 mm above the roots.

units mm
thickness 6 mm

W = 280 mm
side_h = 170 mm
crown_h = 210 mm
tines = 7
tine_w = 28 mm
tine_gap = 14 mm
tine_len = 100 mm

def grabber() -> solid {
    left_side = Line((-W / 2, 0), (-W / 2, side_h))
    crown = Arc(start=(-W / 2, side_h), through=(0, crown_h), end=(W / 2, side_h))
    right_side = Line((W / 2, side_h), (W / 2, 0))
    root = Line((W / 2, 0), (-W / 2, 0))
    for i in range(tines) {
        tine = Slot(start=(-W / 2 + tine_w / 2 + i * (tine_w + tine_gap), 5),
                    end=(-W / 2 + tine_w / 2 + i * (tine_w + tine_gap), -tine_len + tine_w / 2),
                    width=tine_w)
    }
    hole grip { s = Slot(center=(0, 150), length=100, width=32) }
    drawing word {
        t = Text("LEAVES", position=(0, 85), size=20, font="sans:Bold", valign="middle",
                 fill=true)
    }
    Fillet(6)
}

assembly leaf_grabbers {
    left = grabber()
    right = grabber()
    RightOf(right, left, gap=8)
    AlignBottom(right, left)

    assert len(left.tine) == 7, "seven tines"
    assert left.bb.width == 280 mm, "280 mm wide"
    assert tines * tine_w + (tines - 1) * tine_gap == 280 mm, "tines fill the width"
    assert left.tine[1].start.x - left.tine[0].start.x == 28 mm + 14 mm, "tines 14 mm apart"
    assert left.root.start.y - left.bb.bottom == 100 mm, "tines 100 mm long"
    assert left.bb.top - left.root.start.y == 210 mm, "crown 210 mm above the roots"
    assert left.left_side.end.y - left.left_side.start.y == 170 mm, "sides 170 mm"
    assert left.grip.s.center.y - left.root.start.y == 150 mm, "hand slot 150 up"
    assert left.grip.s.length == 100 mm and left.grip.s.width == 32 mm, "hand slot 100 x 32"
    assert left.word.t.position.y - left.root.start.y == 85 mm, "label 85 up"
}
