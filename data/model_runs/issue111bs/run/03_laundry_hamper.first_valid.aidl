# Request: a bathroom laundry hamper, 6 mm poplar ply, finger-jointed (fingers at least
# 30 mm), 400 mm long, 300 mm deep and 550 mm tall outside with its lift-off lid. Front and
# back each vented by a honeycomb of 20 mm holes (6 rows of 9, 30 mm apart along a row, rows
# 26 mm apart, odd rows shifted half a step) centred on the panel. A 100 x 30 mm hand hole
# in each side, upright, its centre 70 mm below the top edge of the wall, centred
# front-to-back. In the lid a 100 x 28 mm finger slot 50 mm below the lid's centre and
# "LAUNDRY" engraved filled, 40 mm bold, 50 mm above the centre.

import "std/boxes.aidl"

thickness 6 mm

def vent_field() -> hole {
    c = Circle(center=(0, 0), diameter=20)
    grid = GridPattern(c, 6, 9, (30, 26), stagger=true)
}

assembly hamper {
    box = lid_box(length=400 mm, width=300 mm, height=550 mm, thickness=6 mm, finger=30 mm)

    vents_front = vent_field()
    vents_back = vent_field()
    CenterInside(vents_front, box.body.front)
    CenterInside(vents_back, box.body.back)
    CutInto(vents_front, box.body.front)
    CutInto(vents_back, box.body.back)

    # the sides lie on their side in the net: the left's top edge at -x, the right's at +x
    hole hand_left { s = Slot(center=(0, 0), length=100, width=30, rotation=90 deg) }
    hole hand_right { s = Slot(center=(0, 0), length=100, width=30, rotation=90 deg) }
    AlignCenterY(hand_left, box.body.left)
    AlignCenterY(hand_right, box.body.right)
    hand_left.s.center.x == box.body.left.bb.left + 70 mm
    hand_right.s.center.x == box.body.right.bb.right - 70 mm
    CutInto(hand_left, box.body.left)
    CutInto(hand_right, box.body.right)

    hole grip { s = Slot(center=(0, 0), length=100, width=28) }
    AlignCenterX(grip, box.lid)
    grip.s.center.y == box.lid.bb.center_y - 50 mm
    CutInto(grip, box.lid)

    drawing label {
        t = Text("LAUNDRY", position=(0, 0), size=40, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(label, box.lid)
    label.t.position.y == box.lid.bb.center_y + 50 mm
    CutInto(label, box.lid)

    # the request's numbers
    assert box.body.front.bb.width == 400 mm, "400 mm long"
    assert box.body.left.bb.height == 300 mm, "300 mm deep"
    assert len(vents_front.grid) == 54, "6 rows of 9 vents"
    assert vents_front.grid[1].center.x - vents_front.grid[0].center.x == 30 mm, "30 mm along a row"
    assert vents_front.grid[9].center.y - vents_front.grid[0].center.y == 26 mm, "rows 26 mm apart"
    assert hand_left.s.bb.height == 100 mm and hand_left.s.bb.width == 30 mm, "hand holes 100 x 30"
    assert box.lid.bb.center_y - grip.s.center.y == 50 mm, "slot 50 mm below the centre"
}
