# Bathroom razor holder: a 130 x 60 mm plate with 6 mm rounded corners, 4 mm acrylic,
# screwed to the wall under the mirror. Two U-slots open at the top edge hold razor
# handles: each 12 mm wide, 25 mm deep from the top edge (round bottom), their centres
# 40 mm apart and centred on the plate. Two 4 mm screw holes 15 mm in from the left and
# right ends and 15 mm up from the bottom, countersunk 8 mm. "RAZORS" engraved 6 mm high,
# centred, its baseline 10 mm above the bottom edge.

units mm
thickness 4 mm

param slot_w = 12 mm, min = 8 mm, max = 16 mm
param slot_depth = 25 mm, min = 15 mm, max = 35 mm
param pitch = 40 mm, min = 30 mm, max = 70 mm

def u_slot(w=12 mm, depth=25 mm) -> hole {
    # straight part runs 3 mm past the top edge so the slot opens cleanly
    bar = Rectangle(center=(0, (depth - w / 2 + 3 mm) / 2 - w / 2 + w / 2), width=w,
                    height=depth - w / 2 + 3 mm)
    end = Circle(center=(0, 0), diameter=w)
    bar.bottom.midpoint == end.center
}

solid holder {
    plate = RoundedRectangle(center=(0, 0), width=130, height=60, corner_radius=6)

    left_slot = u_slot(w=slot_w, depth=slot_depth)
    right_slot = u_slot(w=slot_w, depth=slot_depth)
    Rigid(left_slot)
    Rigid(right_slot)
    left_slot.end.center.x == plate.center.x - pitch / 2
    right_slot.end.center.x == plate.center.x + pitch / 2
    left_slot.end.bb.bottom == plate.bb.top - slot_depth
    right_slot.end.bb.bottom == plate.bb.top - slot_depth

    hole screw_l { c = Circle(center=(-50, -15), diameter=4) }
    hole screw_r { c = Circle(center=(50, -15), diameter=4) }
    HorizontalDistance(plate.bb.bottom_left, screw_l.c.center, 15)
    VerticalDistance(plate.bb.bottom_left, screw_l.c.center, 15)
    HorizontalDistance(screw_r.c.center, plate.bb.bottom_right, 15)
    VerticalDistance(plate.bb.bottom_right, screw_r.c.center, 15)
    Countersink([screw_l, screw_r], diameter=8)

    drawing label {
        word = Text("RAZORS", position=(0, -20), size=6)
    }
    AlignCenterX(label, plate)
    label.word.position.y == plate.bb.bottom + 10

    assert plate.bb.width == 130 mm, "plate 130 mm wide"
    assert plate.bb.height == 60 mm, "plate 60 mm high"
    assert left_slot.bb.width == 12 mm, "slots 12 mm wide"
    assert plate.bb.top - left_slot.end.bb.bottom == 25 mm, "left slot 25 mm deep"
    assert plate.bb.top - right_slot.end.bb.bottom == 25 mm, "right slot 25 mm deep"
    assert right_slot.end.center.x - left_slot.end.center.x == 40 mm, "slots 40 mm apart"
    assert (left_slot.end.center.x + right_slot.end.center.x) / 2 == plate.bb.center_x, "slots centred"
    assert left_slot.bb.top > plate.bb.top, "slots open at the top edge"
    assert screw_l.c.diameter == 4 mm, "4 mm screws"
    assert screw_l.c.center.x - plate.bb.left == 15 mm, "left screw 15 mm in"
    assert plate.bb.right - screw_r.c.center.x == 15 mm, "right screw 15 mm in"
    assert screw_l.c.center.y - plate.bb.bottom == 15 mm, "screws 15 mm up"
    assert screw_r.c.center.y - plate.bb.bottom == 15 mm, "screws 15 mm up"
    assert label.word.size == 6 mm, "text 6 mm"
    assert label.word.position.y - plate.bb.bottom == 10 mm, "baseline 10 mm up"
}
