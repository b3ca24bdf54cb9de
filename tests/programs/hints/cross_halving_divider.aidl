// Issue 109 (law 4): a drawer divider, 200 x 60 mm, with two cross-halving slots from its
// top edge a pitch apart, for the two cross dividers. W0401 said to drop lines 18 and 19,
// "the template holds it already"; done as told, the second slot stayed where the template
// starts it, 40 mm off, and the assert below failed. The slot's Fixed(self) is where it
// starts: the distance and the alignment place it, and nothing here is redundant.
import "std/joints.aidl"

units mm
thickness 3 mm

param pitch = 80

solid divider {
    body = Rectangle(center=(0, 0), width=200, height=60)
    left_slot = cross_halving(depth=30 mm, thickness=3 mm, cx=-40 mm, cy=30 mm)
    right_slot = cross_halving(depth=30 mm, thickness=3 mm, cy=30 mm)
    Fixed(body)
    Fixed(left_slot)
    HorizontalDistance(left_slot.cut.center, right_slot.cut.center, pitch)
    AlignTop(right_slot, left_slot)
    assert right_slot.cut.center.x - left_slot.cut.center.x == pitch, "the slots are a pitch apart"
}
