# Request (music): "A crate for about 60 LP records, in 6 mm ply, finger-jointed, open top.
# Inside: 330 mm wide (the sleeves are 315 mm square and stand facing the front), 300 mm front to
# back, 250 mm tall. Cut a half-oval scoop 220 mm wide and 90 mm deep out of the middle of the
# front's top edge so I can flip through the records, and a 110 x 32 mm hand hole in each side,
# centred front to back, its centre 45 mm below the top edge. Engrave 'LP' in filled bold letters
# 60 mm tall on the front, centred under the scoop, and 'A - Z' in 30 mm filled letters on the
# back."

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
in_w = 330 mm
in_d = 300 mm
in_h = 250 mm

assembly lp_crate {
    box = finger_box(length=in_w, depth=in_d, height=in_h, thickness=t, finger=20 mm,
                     closed=false, outside=false)

    hole scoop {
        e = Ellipse(center=(0, 0), rx=110, ry=90)
    }
    AlignCenterX(scoop, box.front)
    scoop.e.center.y == box.front.bb.top
    CutInto(scoop, box.front)

    drawing front_word {
        w = Text("LP", position=(0, 0), size=60, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(front_word, box.front)
    front_word.w.position.y == (box.front.bb.bottom + scoop.bb.bottom) / 2
    CutInto(front_word, box.front)

    drawing back_word {
        w = Text("A - Z", position=(0, 0), size=30, font="sans:Bold", valign="middle", fill=true)
    }
    CenterInside(back_word, box.back)
    CutInto(back_word, box.back)

    # the sides lie on their side in the net, top edge outward (left's at -x, right's at +x)
    hole hand_l {
        s = Slot(center=(0, 0), length=110, width=32, rotation=90 deg)
    }
    AlignCenterY(hand_l, box.left)
    hand_l.s.center.x == box.left.bb.left + 45 mm
    CutInto(hand_l, box.left)

    hole hand_r {
        s = Slot(center=(0, 0), length=110, width=32, rotation=90 deg)
    }
    AlignCenterY(hand_r, box.right)
    hand_r.s.center.x == box.right.bb.right - 45 mm
    CutInto(hand_r, box.right)

    assert box.front.bb.width - 2 * t == 330 mm, "330 inside, side to side"
    assert in_w >= 315 mm + 10 mm, "a sleeve fits with room"
    assert box.front.bb.height - t == 250 mm, "250 inside, tall"
    assert box.left.bb.height - 2 * t == 300 mm, "300 inside, front to back"
    assert scoop.bb.width == 220 mm, "scoop 220 wide"
    assert box.front.bb.top - scoop.bb.bottom == 90 mm, "scoop 90 deep"
    assert distance(front_word, scoop) >= 10 mm, "LP clear of the scoop"
    assert box.left.bb.left + 45 mm + 16 mm <= box.left.bb.right - t, "hand hole on the side"
}
