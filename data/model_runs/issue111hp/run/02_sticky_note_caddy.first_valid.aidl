# Request (office): a desk caddy in 3 mm ply for a 76 x 76 mm sticky-note pad and pens.
# An open-top finger-jointed box, 130 x 88 x 45 mm outside (10 mm fingers). Inside, a divider
# wall 35 mm tall, glued into the bottom on two 20 mm tabs, splits it into a pad bay 80 mm wide
# (inside) on the left and a pen bay on the right. The front has a round-bottomed thumb notch
# 30 mm wide and 20 mm deep over the middle of the pad bay, to pull a note off. "NOTES" is
# engraved filled 7 mm tall under the notch and "PENS" under the middle of the pen bay,
# both with their baseline 10 mm above the bottom edge.

import "std/joints.aidl"

thickness 3 mm

assembly caddy {
    box = finger_box(length=130 mm, depth=88 mm, height=45 mm, thickness=3 mm, finger=10 mm,
                     closed=false)

    # the divider: x along the box's depth, y up; its tabs' tips (y = -19) in the bottom's underside
    solid divider {
        wall = Rectangle(center=(0, 0), width=82, height=38)
        feet = tab_and_slot(part="tab", length=82 mm, thickness=3 mm, tabs=2, tab=20 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=-19 mm)
        Fixed(wall)
    }

    # box x: -65 .. 65 outside, -62 .. 62 inside; the pad bay -62 .. 18, the divider 18 .. 21
    hole divider_slots {
        j = tab_and_slot(part="slot", length=82 mm, thickness=3 mm, tabs=2, tab=20 mm,
                         screw=0, rotation=90 deg, cx=19.5 mm, cy=0 mm)
    }
    AlignCenterY(divider_slots, box.bottom)
    divider_slots.bb.center_x == box.bottom.bb.center_x + 19.5 mm
    CutInto(divider_slots, box.bottom)

    hole notch {
        s = Slot(center=(0, 0), length=40, width=30, rotation=90)
    }
    notch.s.center.x == box.front.bb.center_x - 22 mm
    notch.s.center.y == box.front.bb.bottom + 45 mm
    CutInto(notch, box.front)

    drawing labels {
        notes = Text("NOTES", position=(0, 0), size=7, font="sans:Bold", fill=true)
        pens = Text("PENS", position=(63.5, 0), size=7, font="sans:Bold", fill=true)
    }
    labels.notes.position.x == box.front.bb.center_x - 22 mm
    labels.notes.position.y == box.front.bb.bottom + 10 mm
    CutInto(labels, box.front)

    RightOf(divider, box, gap=5)
    AlignBottom(divider, box)

    Place(divider, position=(18, 0, 19), face="right", up="up")

    # the request's numbers
    assert 18 mm - (-62 mm) == 80 mm, "pad bay 80 wide inside"
    assert 18 mm - (-62 mm) >= 76 mm + 2 mm, "the 76 mm pad drops in"
    assert divider.wall.bb.height - 3 mm == 35 mm, "divider 35 tall above the bottom"
    assert notch.s.width == 30 mm, "notch 30 wide"
    assert box.front.bb.bottom + 45 mm - notch.s.bb.bottom == 20 mm, "notch 20 deep"
    assert labels.pens.position.x - labels.notes.position.x == (21 mm + 62 mm) / 2 - (-22 mm),
        "PENS under the pen bay's middle"
    assert notch.s.bb.bottom - labels.bb.top >= 3 mm, "NOTES clear of the notch"
}
