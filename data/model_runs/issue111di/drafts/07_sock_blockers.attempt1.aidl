# Request (crafts): a pair of sock blockers for my hand-knitted socks, adult EU 38-41, from
# 4 mm poplar ply. Each is a sock silhouette 330 tall: a leg 95 wide with its top corners
# rounded R15, and a foot 90 high running forward to 240 mm from the back of the heel; the
# heel and the toe are full half-rounds (R45); the inner corner where the front of the leg
# meets the top of the foot is rounded R30. To dry quicker and weigh less: a slot 140 x 35
# up the middle of the leg (its bottom at 150 above the sole) and a slot 110 x 35 along the
# middle of the foot (from 95 to 205 from the back of the heel). A 10 mm hanging hole 15 mm
# below the top, centred. "EU 38-41" engraved filled in bold sans 8 mm tall on the ankle,
# centred across the leg, its middle 120 above the sole. The two are mirror images (the
# toes point opposite ways) but the lettering reads the right way on both.

thickness 4 mm

def blocker(side=1) -> solid {
    # side 1: toe toward +x; -1: toe toward -x. x = 0 at the back of the heel, y = 0 the sole
    leg = RoundedRectangle(corner=(min(0, side * 95), 45), opposite=(max(0, side * 95), 330),
                           corner_radii=[15, 15, 0, 0])
    foot = Slot(start=(side * 45, 45), end=(side * (240 - 45), 45), width=90)
    Fillet([leg, foot], 30)
    hole leg_slot {
        s = Slot(center=(side * 47.5, 150 + 70), length=140, width=35, rotation=90 deg)
    }
    hole foot_slot {
        s = Slot(center=(side * 150, 45), length=110, width=35)
    }
    hole hang {
        c = Circle(center=(side * 47.5, 330 - 15), diameter=10)
    }
    drawing size_label {
        t = Text("EU 38-41", position=(side * 47.5, 120), size=8, font="sans:Bold",
                 valign="middle", fill=true)
    }
    assert leg.bb.top - foot.bb.bottom == 330 mm, "330 tall"
    assert abs(foot.bb.right - foot.bb.left) == 240 mm, "foot 240 from the heel"
    assert leg.bb.width == 95 mm, "leg 95 wide"
    assert foot.bb.height == 90 mm, "foot 90 high"
    assert leg.bb.top - hang.c.center.y == 15 mm, "hang hole 15 below the top"
    assert leg_slot.s.bb.bottom - foot.bb.bottom == 150 mm, "leg slot from 150 up"
    assert abs(foot_slot.s.bb.center_x - side * 150) < 0.001 mm, "foot slot 95 to 205"
    assert size_label.t.bb.bottom > foot.bb.top, "label above the foot"
    assert size_label.t.bb.top < leg_slot.s.bb.bottom, "label below the leg slot"
    assert size_label.t.bb.width < 95 mm - 10 mm, "label inside the leg"
}

assembly sock_blockers {
    right = blocker(side=1)
    left = blocker(side=-1)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
}
