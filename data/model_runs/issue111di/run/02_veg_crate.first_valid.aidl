# Request (kitchen): a vegetable crate for potatoes in the pantry. 6 mm birch ply, outside
# 360 long x 260 deep x 220 tall, open top, finger-jointed with fingers of about 20 mm.
# Each short end has a hand hole 90 x 30 mm with round ends, its centre 35 mm below the top
# edge, centred across the end. The long front and back each have 2 rows of 6 air holes
# 20 mm across on a 50 mm grid, the lower row's centres 60 mm above the bottom, the group
# centred across. The bottom has 3 x 5 air holes 20 mm across on a 60 mm grid, centred.
# The front has POTATOES engraved filled in bold sans, 30 mm tall, centred across, its
# middle 45 mm below the top edge.

import "std/joints.aidl"

thickness 6 mm

def air_grid(rows=2, cols=6, pitch=50 mm, d=20 mm) -> hole {
    for r in range(rows) {
        for c in range(cols) {
            h = Circle(center=(c * pitch, r * pitch), diameter=d)
        }
    }
}

def hand_hole() -> hole {
    s = Slot(center=(0, 0), length=90, width=30, rotation=90 deg)
}

assembly veg_crate {
    box = finger_box(length=360 mm, depth=260 mm, height=220 mm, thickness=6 mm,
                     finger=20 mm, closed=false, outside=true)

    # hand holes in the short ends (they lie on their side in the net, top edge outward)
    left_hand = hand_hole()
    AlignCenterY(left_hand, box.left)
    left_hand.s.center.x == box.left.bb.left + 35 mm
    CutInto(left_hand, box.left)

    right_hand = hand_hole()
    AlignCenterY(right_hand, box.right)
    right_hand.s.center.x == box.right.bb.right - 35 mm
    CutInto(right_hand, box.right)

    # air holes in front and back
    front_air = air_grid()
    AlignCenterX(front_air, box.front)
    front_air.h[0][0].center.y == box.front.bb.bottom + 60 mm
    CutInto(front_air, box.front)

    back_air = air_grid()
    AlignCenterX(back_air, box.back)
    back_air.h[0][0].center.y == box.back.bb.bottom + 60 mm
    CutInto(back_air, box.back)

    # air holes in the bottom
    bottom_air = air_grid(rows=3, cols=5, pitch=60 mm)
    CenterInside(bottom_air, box.bottom)
    CutInto(bottom_air, box.bottom)

    drawing label {
        t = Text("POTATOES", position=(0, 0), size=30, font="sans:Bold", valign="middle",
                 fill=true)
    }
    AlignCenterX(label, box.front)
    label.t.position.y == box.front.bb.top - 45 mm
    CutInto(label, box.front)

    assert box.front.bb.width == 360 mm, "360 long"
    assert box.front.bb.height == 220 mm, "220 tall"
    assert box.bottom.bb.height == 260 mm, "260 deep"
    assert left_hand.s.length == 90 mm and left_hand.s.width == 30 mm, "hand hole 90 x 30"
    assert left_hand.s.center.x - box.left.bb.left == 35 mm, "hand hole 35 below the top"
    assert box.right.bb.right - right_hand.s.center.x == 35 mm, "hand hole 35 below the top"
    assert len(front_air.h) == 2 and len(front_air.h[0]) == 6, "2 rows of 6"
    assert len(bottom_air.h) == 3 and len(bottom_air.h[0]) == 5, "3 x 5 in the bottom"
    assert front_air.h[0][0].center.y - box.front.bb.bottom == 60 mm, "lower row 60 up"
    assert box.front.bb.top - label.t.position.y == 45 mm, "label 45 below the top"
    # the label clears the upper row of air holes
    assert label.t.bb.bottom > front_air.bb.top + 10 mm, "label clear of the air holes"
}
