# Request: a push-up stand (one of a pair: cut it twice), 6 mm birch ply. Two cheeks 160 mm
# long and 105 mm tall: rounded feet (r8) at the ends, an arched top round a 32.5 mm hole for a
# 32 mm broom-handle grip whose centre is 75 mm up, and an arch 80 mm wide and 28 mm high cut
# out of the bottom between the feet. The cheeks stand parallel with 100 mm between them,
# held by two braces 130 x 40 mm that cross them 55 mm either side of the grip, in
# cross-halving slots 20 mm deep in each (0.1 mm play). "PUSH" is engraved filled, 12 mm bold,
# on the outside of each cheek under the grip.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
gap_in = 100 mm          # between the cheeks
cheek_y = gap_in / 2 + t / 2
brace_x = 55 mm
grip_up = 75 mm

def cheek_t() -> solid {
    # y = 0 is the floor
    outline = Hull(Circle(center=(-72, 8), radius=8), Circle(center=(72, 8), radius=8),
                   Circle(center=(0, grip_up), radius=30))
    hole grip { c = Circle(center=(0, grip_up), diameter=32.5) }
    hole arch { e = Ellipse(center=(0, 0), rx=40, ry=28) }
    front_slot = cross_halving(depth=20 mm, thickness=t, clearance=0.1 mm, rotation=180 deg,
                               cx=-brace_x, cy=0 mm)
    back_slot = cross_halving(depth=20 mm, thickness=t, clearance=0.1 mm, rotation=180 deg,
                              cx=brace_x, cy=0 mm)
    drawing word {
        w = Text("PUSH", position=(0, 38), size=12, font="sans:Bold", fill=true, valign="middle")
    }
}

def brace_t() -> solid {
    bar = Rectangle(bottom_left=(-65, 0), width=130, height=40)
    left_slot = cross_halving(depth=20 mm, thickness=t, clearance=0.1 mm, cx=-cheek_y, cy=40 mm)
    right_slot = cross_halving(depth=20 mm, thickness=t, clearance=0.1 mm, cx=cheek_y, cy=40 mm)
}

assembly stand {
    near = cheek_t()
    far = cheek_t()
    front = brace_t()
    back = brace_t()
    RightOf(far, near, gap=6)
    AlignBottom(far, near)
    Below(front, near, gap=6)
    AlignLeft(front, near)
    RightOf(back, front, gap=6)
    AlignBottom(back, front)

    # the cheeks in x-z planes, their engraved faces outward; the braces in y-z planes
    Place(near, rotation=(90 deg, 0, 0), position=(0, -cheek_y + t / 2, 0))
    Place(far, rotation=(90 deg, 0, 180 deg), position=(0, cheek_y - t / 2, 0))
    Place(front, rotation=(90 deg, 0, 90 deg), position=(-brace_x - t / 2, 0, 0))
    Place(back, rotation=(90 deg, 0, 90 deg), position=(brace_x - t / 2, 0, 0))

    assert near.outline.bb.width == 160 mm, "cheeks 160 long"
    assert near.outline.bb.height == 105 mm, "cheeks 105 tall"
    assert near.grip.c.diameter == 32.5 mm, "32.5 grip hole"
    assert near.grip.c.center.y - near.outline.bb.bottom == 75 mm, "grip 75 up"
    assert near.arch.e.rx * 2 == 80 mm and near.arch.e.ry == 28 mm, "arch 80 x 28"
    assert gap_in == 100 mm, "100 between the cheeks"
    assert front.bar.bb.width == 130 mm and front.bar.bb.height == 40 mm, "braces 130 x 40"
    assert near.front_slot.cut.bb.height + front.left_slot.cut.bb.height == 40 mm,
        "halvings meet"
    assert near.back_slot.cut.bb.center_x - near.grip.c.center.x == 55 mm, "braces 55 out"
    assert near.word.bb.top < near.grip.bb.bottom - 3 mm, "PUSH under the grip"
    assert near.word.bb.bottom > near.arch.bb.top + 3 mm, "PUSH over the arch"
}
