# Request (sport): a children's 3-in-1 jump box for PE, 9 mm birch ply, finger-jointed
# (40 mm fingers), 400 x 350 x 300 mm outside, so it stands 30, 35 or 40 cm tall depending
# on which face is down. A hand hole 120 x 35 mm (a stadium, running front to back) in each
# end panel, its centre 70 mm below the top edge. The height each face gives is engraved
# filled, bold: "30 cm" (80 mm) on the lid, "35 cm" (80 mm) on the front and the back,
# "40 cm" (70 mm, reading along the panel, clear of the hand hole) on both ends.

import "std/joints.aidl"

thickness 9 mm

assembly plyo {
    box = finger_box(length=400 mm, depth=350 mm, height=300 mm, thickness=9 mm,
                     finger=40 mm, gap=10 mm)

    # hand holes: the end panels lie on their side in the net, top edge outward
    hole hand_l { s = Slot(center=(0, 0), length=120, width=35, rotation=90 deg) }
    hole hand_r { s = Slot(center=(0, 0), length=120, width=35, rotation=90 deg) }
    AlignCenterY(hand_l, box.left)
    hand_l.s.center.x == box.left.bb.left + 70 mm
    AlignCenterY(hand_r, box.right)
    hand_r.s.center.x == box.right.bb.right - 70 mm
    CutInto(hand_l, box.left)
    CutInto(hand_r, box.right)

    drawing n30 { t = Text("30 cm", position=(0, 0), size=80, font="sans:Bold",
                           valign="middle", fill=true) }
    drawing n35f { t = Text("35 cm", position=(0, 0), size=80, font="sans:Bold",
                            valign="middle", fill=true) }
    drawing n35b { t = Text("35 cm", position=(0, 0), size=80, font="sans:Bold",
                            valign="middle", fill=true) }
    drawing n40l { t = Text("40 cm", position=(0, 0), size=70, font="sans:Bold",
                            valign="middle", rotation=90 deg, fill=true) }
    drawing n40r { t = Text("40 cm", position=(0, 0), size=70, font="sans:Bold",
                            valign="middle", rotation=-90 deg, fill=true) }
    CenterInside(n30, box.lid)
    CenterInside(n35f, box.front)
    CenterInside(n35b, box.back)
    CenterInside(n40l, box.left)
    CenterInside(n40r, box.right)
    CutInto(n30, box.lid)
    CutInto(n35f, box.front)
    CutInto(n35b, box.back)
    CutInto(n40l, box.left)
    CutInto(n40r, box.right)

    assert box.lid.bb.width == 400 mm and box.lid.bb.height == 350 mm
    assert box.front.bb.width == 400 mm and box.front.bb.height == 300 mm
    assert box.left.bb.width == 300 mm and box.left.bb.height == 350 mm
    assert hand_l.s.length == 120 mm and hand_l.s.width == 35 mm
    assert n40l.bb.right < hand_l.bb.left or n40l.bb.left > hand_l.bb.right, "clear of the hand hole"
}
