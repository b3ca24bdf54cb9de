# Wall plate: 160 x 100 mm, 6 mm rounded corners, with two keyhole slots to hang it on
# screws: head 9 mm, slot 4.5 mm wide running 10 mm up from the head's centre; the heads
# 100 mm apart, centred left-right, their centres 30 mm below the top edge.
import "std/plates.aidl"
param w = 160 mm, min = 120 mm, max = 250 mm
param spacing = 100 mm, min = 60 mm, max = 200 mm
thickness 4 mm

solid wall_plate {
    body = RoundedRectangle(center=(0, 0), width=w, height=100, corner_radius=6)
    left = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg)
    right = keyhole(head=9 mm, slot_width=4.5 mm, length=10 mm, direction=90 deg)
    At(left.head_hole.center, body.bb.top_left, dx=w / 2 - spacing / 2, dy=-30)
    At(right.head_hole.center, left.head_hole.center, dx=spacing)
    assert right.head_hole.center.x - left.head_hole.center.x == 100 mm, "100 mm apart"
    assert body.bb.top - left.head_hole.center.y == 30 mm, "30 mm below the top"
    assert left.slot.bb.top < body.bb.top - 5 mm, "slot inside the plate"
}
