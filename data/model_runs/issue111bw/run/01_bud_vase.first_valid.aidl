# Request (home): "A bud vase for one stem, as a gift for my mum's windowsill. A closed
# finger-jointed box 60 x 60 x 130 mm outside in 3 mm birch ply, 10 mm fingers. A 16 mm glass
# test tube drops in through a 17 mm hole in the middle of the top and stands on the bottom.
# The front and the back each have a flower cut out: a head of five 10 mm round petals on a
# 6 mm radius round an 8 mm centre, its centre 85 mm up from the bottom edge, a 3 mm stem
# running 40 mm down from the head's centre and a 16 x 6 mm leaf on the stem. Under the
# flower on the front, "MUM" engraved filled, bold, 8 mm high, its baseline 14 mm up.
# Each side has a vertical row of three 12 mm round windows, 40, 65 and 90 mm up."

import "std/joints.aidl"

thickness 3 mm

def flower() -> hole {
    head = Circle(center=(0, 0), diameter=8)
    petal = Circle(center=(0, 6), diameter=10)
    petals = CircularPattern(petal, 5, head.center)
    stem = Slot(start=(0, 0), end=(0, -40), width=3)
    leaf = Ellipse(center=(6, -26), rx=8, ry=3, rotation=30 deg)
}

assembly vase {
    box = finger_box(length=60 mm, depth=60 mm, height=130 mm, thickness=3 mm, finger=10 mm)

    # the tube hole in the top
    hole tube { c = Circle(center=(0, 0), diameter=17) }
    CenterInside(tube, box.lid)
    CutInto(tube, box.lid)

    # the flowers, front and back
    front_flower = flower()
    AlignCenterX(front_flower.head.center, box.front)
    VerticalDistance(box.front.bb.bottom_left, front_flower.head.center, 85)
    CutInto(front_flower, box.front)

    back_flower = flower()
    AlignCenterX(back_flower.head.center, box.back)
    VerticalDistance(box.back.bb.bottom_left, back_flower.head.center, 85)
    CutInto(back_flower, box.back)

    # the name under the front flower
    drawing name {
        t = Text("MUM", position=(0, 0), size=8, font="sans:Bold", fill=true)
    }
    AlignCenterX(name.t.position, box.front)
    VerticalDistance(box.front.bb.bottom_left, name.t.position, 14)
    CutInto(name, box.front)

    # the side windows: the left side lies with its top edge at -x (the box's bottom at its
    # right edge), the right side with its top edge at +x
    hole left_win {
        for i in range(3) { c = Circle(center=(-(40 + 25 * i), 0), diameter=12) }
    }
    AlignCenterY(left_win, box.left)
    HorizontalDistance(left_win.c[0].center, box.left.bb.bottom_right, 40)
    CutInto(left_win, box.left)

    hole right_win {
        for i in range(3) { c = Circle(center=(40 + 25 * i, 0), diameter=12) }
    }
    AlignCenterY(right_win, box.right)
    HorizontalDistance(box.right.bb.bottom_left, right_win.c[0].center, 40)
    CutInto(right_win, box.right)

    # the request's numbers
    assert box.front.bb.width == 60 mm, "60 mm wide outside"
    assert box.front.bb.height == 130 mm, "130 mm tall outside"
    assert box.left.bb.height == 60 mm, "60 mm deep outside"
    assert tube.c.diameter == 17 mm, "17 mm tube hole"
    assert abs(tube.c.center.x - box.lid.bb.center_x) < 0.01 mm, "tube hole centred"
    assert front_flower.head.center.y - box.front.bb.bottom == 85 mm, "flower 85 mm up"
    assert back_flower.head.center.y - box.back.bb.bottom == 85 mm, "back flower 85 mm up"
    assert len(front_flower.petals) == 5, "five petals"
    assert name.t.position.y - box.front.bb.bottom == 14 mm, "name baseline 14 mm up"
    assert name.t.position.y + 8 mm < front_flower.stem.end.y - 1.5 mm, "name under the stem"
    assert len(left_win.c) == 3 and len(right_win.c) == 3, "three windows a side"
    assert box.left.bb.right - left_win.c[2].center.x == 90 mm, "top window 90 mm up"
    assert right_win.c[1].center.x - box.right.bb.left == 65 mm, "middle window 65 mm up"
}
