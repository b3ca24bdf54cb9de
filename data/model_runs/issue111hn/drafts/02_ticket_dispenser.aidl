# Request (office): a "take a number" ticket dispenser for our front desk. It holds a roll
# of numbered tickets (roll 60 mm wide, 100 mm across) on an 8 mm dowel spindle.
# A finger-jointed box in 3 mm ply, 80 wide x 110 deep x 120 tall outside, fingers 10 mm.
# - The spindle: an 8.5 mm hole in each side, at mid-depth, 62 mm above the bottom.
# - The tickets leave through a 66 x 4 mm slot in the front, centred 20 mm above the bottom.
# - On the front, engraved filled in bold sans: "PLEASE TAKE" over "A NUMBER" (each line at
#   most 64 mm wide), and a filled arrow pointing down at the slot; the top line's top
#   14 mm under the front's top edge.
# - Two 4.5 mm screw holes in the back, 20 mm either side of the centre, 30 mm below the top,
#   to hang it on the wall.
# The lid lifts off to refill (not glued).

import "std/joints.aidl"

units mm
thickness 3 mm

roll_w = 60 mm
roll_d = 100 mm
axle_up = 62 mm

assembly dispenser {
    box = finger_box(length=80 mm, depth=110 mm, height=120 mm, thickness=3 mm, finger=10 mm)

    # spindle holes in both sides (a side lies with the box's top edge outward)
    hole axle_l { c = Circle(center=(0, 0), diameter=8.5) }
    axle_l.c.center.x == box.left.bb.right - axle_up
    AlignCenterY(axle_l, box.left)
    CutInto(axle_l, box.left)

    hole axle_r { c = Circle(center=(0, 0), diameter=8.5) }
    axle_r.c.center.x == box.right.bb.left + axle_up
    AlignCenterY(axle_r, box.right)
    CutInto(axle_r, box.right)

    # the ticket slot in the front
    hole exit { s = Rectangle(center=(0, 0), width=66, height=4) }
    AlignCenterX(exit, box.front)
    exit.s.center.y == box.front.bb.bottom + 20 mm
    CutInto(exit, box.front)

    # the front's sign: two lines and an arrow, drawn together
    drawing sign {
        l1 = Text("PLEASE TAKE", position=(0, 0), size=9, font="sans:Bold", fill=true,
                  max_width=64)
        l2 = Text("A NUMBER", position=(0, -14), size=9, font="sans:Bold", fill=true,
                  max_width=64)
        arrow = Polygon([(-4, -24), (4, -24), (4, -34), (10, -34), (0, -44), (-10, -34),
                         (-4, -34)], fill=true)
    }
    AlignCenterX(sign, box.front)
    sign.bb.top == box.front.bb.top - 14 mm
    CutInto(sign, box.front)

    # wall screws in the back
    hole screws {
        a = Circle(center=(-20, 0), diameter=4.5)
        b = Circle(center=(20, 0), diameter=4.5)
    }
    AlignCenterX(screws, box.back)
    screws.a.center.y == box.back.bb.top - 30 mm
    CutInto(screws, box.back)

    assert box.front.bb.width == 80 mm and box.front.bb.height == 120 mm, "80 wide, 120 tall"
    assert box.left.bb.height == 110 mm, "110 deep"
    assert box.left.bb.right - axle_l.c.center.x == 62 mm, "spindle 62 mm up (left)"
    assert axle_r.c.center.x - box.right.bb.left == 62 mm, "spindle 62 mm up (right)"
    assert exit.s.center.y - box.front.bb.bottom == 20 mm, "slot 20 mm up"
    assert exit.s.width == 66 mm, "66 mm slot"
    assert box.length - 2 * 3 mm >= roll_w + 2 mm, "the roll fits across"
    assert axle_up - roll_d / 2 >= 3 mm + 5 mm, "the roll clears the bottom"
    assert 120 mm - 3 mm - axle_up - roll_d / 2 >= 3 mm, "the roll clears the lid"
    assert sign.bb.bottom >= exit.s.bb.top + 3 mm, "the arrow stops above the slot"
    assert screws.b.center.x - screws.a.center.x == 40 mm, "screws 20 mm either side"
}
