# Request (camping): a s'mores caddy for the campfire, 3 mm plywood: an open finger-jointed
# tray 300 x 160 x 70 mm outside, three equal compartments across its length (crackers,
# marshmallows, chocolate) by two dividers. A hand hole in each end wall: a slot 90 long
# (along the end) x 25 mm, centred along the end, its top 15 mm below the top edge.
# Engraved filled on the front, 9 mm sans bold, each centred over its compartment at
# mid-height: GRAHAM, MALLOWS, CHOCOLATE (left to right as seen from the front).

import "std/boxes.aidl"

thickness 3 mm

assembly smores {
    k = divider_tray(length=300 mm, width=160 mm, height=70 mm, rows=1, cols=3,
                     thickness=3 mm, finger=10 mm, clearance=0.3 mm, outside=true)

    # hand holes: the sides lie with their top edge outward (left's at -x, right's at +x)
    hole grip_l {
        s = Slot(center=(0, 0), length=90, width=25, rotation=90 deg)
    }
    grip_l.s.bb.left == k.body.left.bb.left + 15 mm
    AlignCenterY(grip_l, k.body.left)
    CutInto(grip_l, k.body.left)
    hole grip_r {
        s = Slot(center=(0, 0), length=90, width=25, rotation=90 deg)
    }
    grip_r.s.bb.right == k.body.right.bb.right - 15 mm
    AlignCenterY(grip_r, k.body.right)
    CutInto(grip_r, k.body.right)

    # compartment labels on the front, 99 mm apart (96 inside + a 3 mm divider)
    drawing labels {
        a = Text("GRAHAM", position=(-99, 0), size=9, font="sans:Bold", valign="middle",
                 fill=true)
        b = Text("MALLOWS", position=(0, 0), size=9, font="sans:Bold", valign="middle",
                 fill=true)
        c = Text("CHOCOLATE", position=(99, 0), size=9, font="sans:Bold", valign="middle",
                 fill=true)
    }
    labels.b.position.x == k.body.front.bb.center_x
    labels.b.position.y == k.body.front.bb.center_y
    CutInto(labels, k.body.front)

    # the request's numbers
    assert k.body.front.bb.width == 300 mm and k.body.front.bb.height == 70 mm, "front 300 x 70"
    assert k.body.left.bb.height == 160 mm, "160 deep"
    assert len(k.col_divider) == 2, "two dividers: three compartments"
    assert grip_l.s.bb.height == 90 mm and grip_l.s.bb.width == 25 mm, "hand hole 90 x 25"
    assert grip_l.s.bb.left - k.body.left.bb.left == 15 mm, "hand hole 15 below the top"
    assert k.body.right.bb.right - grip_r.s.bb.right == 15 mm, "hand hole 15 below the top"
    # the inside is 294 long: three 96 mm compartments and two 3 mm dividers
    assert 3 * 96 mm + 2 * 3 mm == 300 mm - 2 * 3 mm, "compartments 96 wide"
    assert labels.c.bb.width <= 96 mm - 10 mm, "the longest label fits its compartment"
    assert labels.c.bb.right <= k.body.front.bb.right - 3 mm - 5 mm, "labels clear of the joints"
}
