# Request (parties): a freestanding wedding hashtag sign for the guest-book table, from
# 6 mm ply. "#JONESWED" cut out as letters in bold sans, 50 mm capitals, standing on a
# rail 440 mm long and 25 mm tall with 5 mm rounded corners; the letters' feet run 2 mm
# down into the rail so each letter is joined to it. The date "12.06.2027" engraved on the
# rail, 8 mm high, centred. Two feet, 100 x 25 mm with 5 mm rounded corners, cross-halved
# into the rail 160 mm either side of the centre (12.5 mm into each part, 0.1 mm clearance).

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
rail_l = 440 mm
rail_h = 25 mm
cap = 50 mm
overlap = 2 mm
foot_x = 160 mm
rail_bottom = overlap - rail_h

def foot() -> solid {
    body = RoundedRectangle(center=(0, rail_h / 2), width=100, height=rail_h, corner_radius=5)
    slot = cross_halving(depth=rail_h / 2, thickness=t, clearance=0.1 mm, cx=0 mm, cy=rail_h)
}

assembly hashtag {
    solid sign {
        word = Text("#JONESWED", (0, 0), size=cap, font="sans:Bold")
        rail = RoundedRectangle(center=(0, overlap - rail_h / 2), width=rail_l, height=rail_h,
                                corner_radius=5)
        left_slot = cross_halving(depth=rail_h / 2, thickness=t, clearance=0.1 mm,
                                  rotation=180 deg, cx=-foot_x, cy=rail_bottom)
        right_slot = cross_halving(depth=rail_h / 2, thickness=t, clearance=0.1 mm,
                                   rotation=180 deg, cx=foot_x, cy=rail_bottom)
        drawing date {
            d = Text("12.06.2027", (0, rail_bottom + rail_h / 2 - overlap / 2), size=8,
                     valign="middle")
        }
        assert word.bb.width <= rail_l - 20 mm, "letters within the rail"
        assert distance(date, left_slot) >= 10 mm, "date clear of the halvings"
    }

    left_foot = foot()
    right_foot = foot()
    Below(left_foot, sign, gap=15)
    AlignLeft(left_foot, sign)
    RightOf(right_foot, left_foot, gap=15)
    AlignTop(right_foot, left_foot)

    Place(sign, position=(0, t / 2, rail_h - overlap), face="front", up="up")
    Place(left_foot, position=(-foot_x - t / 2, 0, 0), face="right", up="up")
    Place(right_foot, position=(foot_x - t / 2, 0, 0), face="right", up="up")

    assert sign.word.size == 50 mm, "50 mm capitals"
    assert sign.rail.bb.width == 440 mm and sign.rail.bb.height == 25 mm, "rail"
    assert sign.right_slot.cut.bb.center_x - sign.left_slot.cut.bb.center_x == 320 mm,
        "feet 160 either side"
    assert sign.left_slot.cut.bb.height + left_foot.slot.cut.bb.height == 25 mm,
        "halvings meet"
}
