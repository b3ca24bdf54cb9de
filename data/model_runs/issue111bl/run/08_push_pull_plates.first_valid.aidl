# Request (signs): a pair of door plates for a shop's glass door, 3 mm black acrylic. Each plate is
# 100 x 300 mm (portrait, corners r8) with a 2 mm engraved (filled) border 6 mm in from the edge,
# and its word engraved filled in bold sans 22 mm tall (at most 76 mm wide), centred 100 mm above the
# plate's middle: "PUSH" on one, "PULL" on the other. Each plate is held by two M4 countersunk
# screws (9 mm heads) on its centre line, 15 mm from the top and bottom ends. The PULL plate also
# takes a D handle with 128 mm hole centres: two M5 clearance holes on the centre line, the upper
# one 24 mm above the plate's middle.

import "std/fasteners.aidl"

thickness 3 mm

plate_w = 100 mm
plate_h = 300 mm
word_y = 100 mm
handle_pitch = 128 mm
handle_top = 24 mm

def door_plate(word="PUSH", handle=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
    top_screw = clearance_hole(size=4, cx=0, cy=plate_h / 2 - 15)
    bottom_screw = clearance_hole(size=4, cx=0, cy=-plate_h / 2 + 15)
    Countersink([top_screw, bottom_screw], diameter=9 mm)
    if handle {
        upper = clearance_hole(size=5, cx=0, cy=handle_top)
        lower = clearance_hole(size=5, cx=0, cy=handle_top - handle_pitch)
    }
    drawing marks {
        line = RoundedRectangle(center=(0, 0), width=plate_w - 12, height=plate_h - 12,
                                corner_radius=2, construction=true)
        border = Shell(line, -2, fill=true)
        txt = Text(word, position=(0, word_y), size=22, font="sans:Bold", valign="middle",
                   max_width=76, fill=true)
    }
}

assembly door {
    push = door_plate(word="PUSH")
    pull = door_plate(word="PULL", handle=true)
    RightOf(pull, push, gap=5)
    AlignBottom(pull, push)

    # the request's numbers
    assert push.body.bb.width == 100 mm and push.body.bb.height == 300 mm, "plate size"
    assert push.marks.txt.position.y - push.body.bb.center_y == 100 mm, "word 100 above"
    assert push.marks.txt.bb.width <= 76 mm and pull.marks.txt.bb.width <= 76 mm, "words fit"
    assert push.body.bb.top - push.top_screw.c.center.y == 15 mm, "top screw 15 from the end"
    assert push.bottom_screw.c.center.y - push.body.bb.bottom == 15 mm, "bottom screw 15"
    assert pull.upper.c.center.y - pull.lower.c.center.y == 128 mm, "handle centres 128"
    assert pull.upper.c.center.y - pull.body.bb.center_y == 24 mm, "upper handle hole 24 up"
    assert push.body.bb.right - push.marks.border.bb.right == 6 mm, "border 6 in"
}
