# Request (workshop): a planing stop for the end of my workbench, cut from 6 mm birch ply.
# A plate 240 mm wide and 70 mm tall overall. Its top edge is a row of 12 saw teeth at 20 mm
# pitch, 5 mm deep, each with a vertical face toward the left (the work) and a sloping back,
# so they bite into the end of a board pushed against them. Two vertical adjustment slots
# 7 mm wide and 35 mm long (M6 coach bolts into the bench end), centred 170 mm apart, their
# centres 26 mm below the root line of the teeth. Beside each slot an engraved height scale:
# a tick every 5 mm from 0 to 25 with its number (3 mm), 0 where the bolt sits at the slot's
# top end. "PLANING STOP" engraved filled in 6 mm bold sans, centred near the bottom edge.

import "std/shapes.aidl"

thickness 6 mm

param width = 240 mm, min = 160 mm, max = 400 mm
param height = 70 mm, min = 60 mm, max = 120 mm
param teeth = 12, min = 8, max = 20
param depth = 5 mm, min = 3 mm, max = 8 mm
param slot_pitch = 170 mm, min = 100 mm, max = 300 mm
param slot_len = 35 mm, min = 25 mm, max = 45 mm
param slot_w = 7 mm, min = 6.6 mm, max = 9 mm
param slot_drop = 26 mm, min = 20 mm, max = 40 mm

pitch = width / teeth
top = height / 2
root = top - depth
travel = slot_len - slot_w          # how far the bolt can move in its slot
slot_y = root - slot_drop           # the slots' centre height
zero_y = slot_y + travel / 2        # bolt at the slot's top end: scale 0

solid stop {
    # FIX after the first valid program: the first valid program's teeth had their vertical
    # faces toward the right (+x), not toward the work on the left as requested.
    # outline: bottom edge, right edge up to the last tooth's root, then tooth by tooth to the
    # left: each tooth's tip sits on its left end, above a vertical face
    teeth_pts = [(-width / 2 + pitch * (teeth - 1 - k // 2), top if k % 2 == 0 else root)
                 for k in range(2 * (teeth - 1))]
    body = Polygon([(-width / 2, -height / 2), (width / 2, -height / 2), (width / 2, root)] +
                   teeth_pts + [(-width / 2, top)])
    assert body.points[3].x == body.points[4].x and body.points[3].y > body.points[4].y,
        "a vertical face under each tip, facing left"
    Fixed(body)

    left_slot = slot_hole(length=slot_len, width=slot_w, rotation=90 deg,
                          cx=-slot_pitch / 2, cy=slot_y)
    right_slot = slot_hole(length=slot_len, width=slot_w, rotation=90 deg,
                           cx=slot_pitch / 2, cy=slot_y)

    drawing scale {
        for j in range(6) {
            lt = Line((-slot_pitch / 2 + slot_w / 2 + 2, zero_y - 5 * j),
                      (-slot_pitch / 2 + slot_w / 2 + 6, zero_y - 5 * j))
            ln = Text(str(5 * j), position=(-slot_pitch / 2 + slot_w / 2 + 8, zero_y - 5 * j),
                      size=3, anchor="start", valign="middle")
            rt = Line((slot_pitch / 2 - slot_w / 2 - 2, zero_y - 5 * j),
                      (slot_pitch / 2 - slot_w / 2 - 6, zero_y - 5 * j))
            rn = Text(str(5 * j), position=(slot_pitch / 2 - slot_w / 2 - 8, zero_y - 5 * j),
                      size=3, anchor="end", valign="middle")
        }
    }

    drawing label {
        name = Text("PLANING STOP", position=(0, -height / 2 + 10), size=6, font="sans:Bold",
                    valign="middle", fill=true)
    }

    # the request's numbers
    assert body.bb.width == 240 mm and body.bb.height == 70 mm, "plate 240 x 70 overall"
    assert teeth == 12 and width / teeth == 20 mm, "12 teeth at 20 mm pitch"
    assert top - root == 5 mm, "teeth 5 mm deep"
    assert len(teeth_pts) == 2 * 11, "11 inner roots and tips between the two end teeth"
    assert right_slot.s.center.x - left_slot.s.center.x == 170 mm, "slots 170 mm apart"
    assert right_slot.s.length == 35 mm and right_slot.s.width == 7 mm, "slots 7 x 35"
    assert root - left_slot.s.center.y == 26 mm, "slot centres 26 mm below the tooth roots"
    assert len(scale.ln) == 6, "ticks 0, 5, ... 25"
    assert zero_y - 25 mm >= slot_y - travel / 2, "the scale stays within the bolt's travel"
    assert distance(label, left_slot) >= 3 mm and distance(label, right_slot) >= 3 mm,
        "the label clears the slots"
    assert label.bb.bottom - body.bb.bottom >= 4 mm, "label on the plate"
    assert root - left_slot.bb.top >= 6 mm, "wood between slot and tooth roots"
}
