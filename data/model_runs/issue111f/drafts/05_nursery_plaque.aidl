# Nursery door name plaque (home). Full sizes: 4 mm ply, a stadium plate 220 mm long and
# 90 mm high (45 mm round ends). "EMMA" cut through in a bold sans font (letter outlines),
# 40 mm cap height but at most 140 mm wide, stencil style (the A's counter held by
# bridges), centred on the plate. An engraved border line 5 mm inside the edge all round (a
# 210 x 80 mm stadium). Two keyholes to hang it (8 mm head, 4 mm slot 10 mm long, upward),
# their head centres on the middle line 22 mm from the left and right ends.

import "std/plates.aidl"

units mm
thickness 4 mm

solid plaque {
    plate = Slot(center=(0, 0), length=220, width=90)

    hole name {
        word = Text("EMMA", position=(0, 0), size=40, valign="middle", font="sans:Bold",
                    stencil=true, max_width=140)
    }
    CenterInside(name, plate)

    drawing border {
        ring = Slot(center=(0, 0), length=210, width=80)
    }
    CenterInside(border, plate)

    left_hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-88, cy=0)
    right_hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=88, cy=0)
    left_hang.head_hole.center.x == plate.bb.left + 22
    right_hang.head_hole.center.x == plate.bb.right - 22
    left_hang.head_hole.center.y == plate.center.y
    right_hang.head_hole.center.y == plate.center.y

    assert plate.bb.width == 220 mm and plate.bb.height == 90 mm, "plate 220 x 90"
    assert plate.radius == 45 mm, "45 mm round ends"
    assert name.bb.width <= 140 mm, "name at most 140 mm wide"
    assert name.bb.height <= 40 mm, "name at most 40 mm high"
    assert abs(name.bb.center_x - plate.bb.center_x) < 0.01 mm, "name centred across"
    assert abs(name.bb.center_y - plate.bb.center_y) < 0.01 mm, "name centred up and down"
    assert border.ring.bb.width == 210 mm and border.ring.bb.height == 80 mm, "border 5 mm in"
    assert left_hang.head_hole.diameter == 8 mm, "8 mm keyhole head"
    assert left_hang.slot.width == 4 mm, "4 mm keyhole slot"
    assert left_hang.head_hole.center.x - plate.bb.left == 22 mm, "left keyhole 22 mm in"
    assert plate.bb.right - right_hang.head_hole.center.x == 22 mm, "right keyhole 22 mm in"
    assert left_hang.bb.right < name.bb.left and right_hang.bb.left > name.bb.right, "keyholes clear of the name"
}
