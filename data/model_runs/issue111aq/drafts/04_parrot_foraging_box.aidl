# Request (pets): a chew-and-forage box for a parrot, 3 mm untreated ply, finger-jointed
# (10 mm fingers) and glued with non-toxic glue, 70 x 70 x 70 mm outside. The lid has a
# 6 mm hole in its middle for the stainless quick link it hangs from. Front and back each
# have a 25 mm round treat opening in the middle; the front has the bird's name "KIWI"
# engraved in filled bold letters 8 mm tall, centred 22 mm below the box's middle. Each
# side has four 12 mm holes on a 24 mm square (for paper stuffing), centred. The bottom has
# a 3 x 3 grid of 6 mm crumb holes 16 mm apart, centred.

import "std/joints.aidl"

thickness 3 mm

def treat_opening() -> hole {
    c = Circle(center=(0, 0), diameter=25)
}

def paper_holes() -> hole {
    for i in range(2) {
        for j in range(2) {
            c = Circle(center=(i * 24 - 12, j * 24 - 12), diameter=12)
        }
    }
}

assembly forage_box {
    box = finger_box(length=70 mm, depth=70 mm, height=70 mm, thickness=3 mm, finger=10 mm)

    hole hanger { c = Circle(center=(0, 0), diameter=6) }
    CenterInside(hanger, box.lid)
    CutInto(hanger, box.lid)

    front_opening = treat_opening()
    CenterInside(front_opening, box.front)
    CutInto(front_opening, box.front)
    back_opening = treat_opening()
    CenterInside(back_opening, box.back)
    CutInto(back_opening, box.back)

    drawing name {
        t = Text("KIWI", position=(0, 0), size=8, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(name.t.position, box.front)
    name.t.position.y == box.front.bb.center_y - 22 mm
    CutInto(name, box.front)

    left_holes = paper_holes()
    CenterInside(left_holes, box.left)
    CutInto(left_holes, box.left)
    right_holes = paper_holes()
    CenterInside(right_holes, box.right)
    CutInto(right_holes, box.right)

    hole crumbs {
        for i in range(3) {
            for j in range(3) {
                c = Circle(center=(i * 16, j * 16), diameter=6)
            }
        }
    }
    CenterInside(crumbs, box.bottom)
    CutInto(crumbs, box.bottom)

    assert box.front.bb.width == 70 mm and box.front.bb.height == 70 mm, "70 mm cube"
    assert len(crumbs.c) * len(crumbs.c[0]) == 9, "3 x 3 crumb holes"
    assert len(left_holes.c) * len(left_holes.c[0]) == 4, "four paper holes a side"
    assert front_opening.c.diameter == 25 mm, "25 mm treat opening"
    assert hanger.c.diameter == 6 mm, "6 mm hanging hole"
}
