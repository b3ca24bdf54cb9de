# Request: a party shot ski for four, 820 mm long and 100 mm wide: a square tail
# end with R15 corners and a rounded ski tip (an elliptical end 120 mm long). Two
# layers: a 6 mm ply top with four 46 mm holes for shot glasses at a 180 mm pitch,
# the first 100 mm from the tail, glued onto a 3 mm ply base that closes the holes
# from below. It must cut on a 600 x 400 mm bed, so each layer is two halves
# joined by a sliding dovetail (two tails, 12 mm deep) across the ski: the top's
# joint 410 mm from the tail, the base's at 370 mm so the joints don't line up.
# "CHEERS" engraved (filled, bold sans, 16 mm capitals) on the top layer's tip,
# centred 740 mm from the tail.

import "std/joints.aidl"

thickness 6 mm

ski_l = 820 mm
ski_w = 100 mm
tip_l = 120 mm
dt = 12 mm
top_joint = 410 mm
base_joint = 370 mm
pitch = 180 mm
glass_d = 46 mm

# FIX after the first valid program: the base's halves took the file's 6 mm
# (W0517: the base ran 3 mm into the top); each half now states its material
def tail_half(joint=410 mm, t=6 mm) -> solid {
    thickness t
    body = RoundedRectangle(bottom_left=(0, -ski_w / 2), width=joint + dt, height=ski_w,
                            corner_radii=[15, 0, 0, 15])
    j = dovetail(part="tail", length=ski_w, depth=dt, tails=2, angle=10 deg,
                 rotation=-90 deg, cx=joint, cy=0 mm)
}

def tip_half(joint=410 mm, t=6 mm) -> solid {
    thickness t
    body = Rectangle(bottom_left=(joint, -ski_w / 2), width=ski_l - tip_l - joint, height=ski_w)
    tip = Ellipse(center=(ski_l - tip_l, 0), rx=tip_l, ry=ski_w / 2)
    j = dovetail(part="socket", length=ski_w, depth=dt, tails=2, angle=10 deg,
                 clearance=0.1 mm, rotation=-90 deg, cx=joint, cy=0 mm)
}

assembly shot_ski {
    top_tail = tail_half(joint=top_joint)
    top_tip = tip_half(joint=top_joint)
    # a hole cuts one solid: the two glasses on each half
    hole glasses_a {
        for i in range(2) {
            c = Circle(center=(100 + i * pitch, 0), diameter=glass_d)
        }
    }
    hole glasses_b {
        for i in range(2) {
            c = Circle(center=(100 + (i + 2) * pitch, 0), diameter=glass_d)
        }
    }
    drawing cheers {
        t = Text("CHEERS", position=(740, 0), size=16, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CutInto(glasses_a, top_tail)
    CutInto(glasses_b, top_tip)
    CutInto(cheers, top_tip)

    base_tail = tail_half(joint=base_joint, t=3 mm)
    base_tip = tip_half(joint=base_joint, t=3 mm)

    # flat: the base's halves under the top's
    Below(base_tail, top_tail, gap=10)
    Below(base_tip, top_tip, gap=10)

    # assembled: the base on the table, the top glued on it
    Place(base_tail, position=(0, 0, 0))
    Place(base_tip, position=(0, 0, 0))
    Place(top_tail, position=(0, 0, 3))
    Place(top_tip, position=(0, 0, 3))

    assert top_tip.tip.bb.right - top_tail.body.bb.left == 820 mm, "820 long"
    assert top_tail.body.height == 100 mm, "100 wide"
    assert len(glasses_a.c) + len(glasses_b.c) == 4, "four glasses"
    assert glasses_a.c[1].center.x - glasses_a.c[0].center.x == 180 mm, "180 pitch"
    assert glasses_b.c[0].center.x - glasses_a.c[1].center.x == 180 mm, "180 pitch"
    assert glasses_a.c[0].center.x - top_tail.body.bb.left == 100 mm, "first 100 from the tail"
    assert glasses_a.c[0].diameter == 46 mm, "46 mm holes"
    assert distance(glasses_a, top_tail.j) >= 10 mm, "holes clear of the top joint"
    assert distance(glasses_b, top_tip.j) >= 10 mm, "holes clear of the top joint"
    assert top_tail.j.bb.left - top_tail.body.bb.left == 410 mm, "top joint 410 from the tail"
    assert base_tail.j.bb.left - base_tail.body.bb.left == 370 mm, "base joint 370 from the tail"
    assert top_tail.bb.width <= 594 mm and top_tip.bb.width <= 594 mm, "halves fit the bed"
    assert base_tail.bb.width <= 594 mm and base_tip.bb.width <= 594 mm, "halves fit the bed"
    assert cheers.t.position.x - top_tail.body.bb.left == 740 mm, "CHEERS at 740"
    assert distance(cheers, glasses_b) >= 10 mm, "CHEERS clear of the last glass"
    assert distance(cheers, top_tip.tip) >= 3 mm, "CHEERS inside the tip"
}
