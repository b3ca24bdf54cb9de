# Request (holidays): "A jack-o'-lantern tealight lantern for Halloween, 3 mm poplar ply: a
# finger-jointed 100 mm cube (10 mm fingers). The front and the back each have a pumpkin face
# cut out, centred: two upward triangle eyes 26 mm wide and 22 mm tall, centres 22 mm either
# side of the middle and 18 mm above it; a 14 x 12 mm triangle nose at the middle; a jagged
# grin 68 mm wide with two teeth hanging from its top edge and one rising from its bottom.
# Each side has three 4 mm pumpkin ribs cut through, running up and down: a straight one
# 64 mm long in the middle and two arcs (60 mm radius, 60 deg) bowing outward either side,
# 20 mm off the middle. The lid has six 10 mm vent holes on a 30 mm radius and, in its
# middle, a mortise (0.1 mm play) for a curly stem with an 8 mm tenon: a 10 mm wide stalk
# leaning right and a leaf. A 40 mm ring is engraved in the middle of the bottom where the
# tealight stands."

import "std/joints.aidl"

thickness 3 mm

def face() -> hole {
    left_eye = Triangle(center=(-22, 18), base=26, height=22)
    right_eye = Triangle(center=(22, 18), base=26, height=22)
    nose = Triangle(center=(0, 0), base=14, height=12)
    mouth = Polygon([(-34, -12), (-14, -16), (-10, -24), (-6, -16), (6, -16), (10, -24),
                     (14, -16), (34, -12), (26, -26), (14, -32), (4, -33), (0, -26),
                     (-4, -33), (-14, -32), (-26, -26)])
}

# the ribs of a side, its up-and-down axis along x (the sides lie on their side in the net)
def ribs() -> hole {
    middle = Slot(center=(0, 0), length=64, width=4)
    upper = ArcSlot(center=(0, -40), radius=60, start_angle=60, end_angle=120, width=4)
    lower = ArcSlot(center=(0, 40), radius=60, start_angle=240, end_angle=300, width=4)
}

assembly lantern {
    box = finger_box(length=100 mm, depth=100 mm, height=100 mm, thickness=3 mm, finger=10 mm)

    front_face = face()
    At(front_face.nose.center, box.front.bb.center)
    CutInto(front_face, box.front)
    back_face = face()
    At(back_face.nose.center, box.back.bb.center)
    CutInto(back_face, box.back)

    left_ribs = ribs()
    At(left_ribs.middle.center, box.left.bb.center)
    CutInto(left_ribs, box.left)
    right_ribs = ribs()
    At(right_ribs.middle.center, box.right.bb.center)
    CutInto(right_ribs, box.right)

    hole lid_cuts {
        stem_mortise = tab_and_slot(part="slot", length=12 mm, thickness=3 mm, tabs=1, tab=8 mm,
                                    screw=0, clearance=0.1 mm, cx=0 mm, cy=0 mm)
        for k in range(6) {
            vent = Circle(center=(30 * cos(k * 60 deg), 30 * sin(k * 60 deg)), diameter=10)
        }
    }
    At(lid_cuts.stem_mortise.slot[0].center, box.lid.bb.center)
    CutInto(lid_cuts, box.lid)

    drawing candle_ring { ring = Circle(center=(0, 0), diameter=40) }
    At(candle_ring.ring.center, box.bottom.bb.center)
    CutInto(candle_ring, box.bottom)

    solid stem {
        shoulder = Rectangle(bottom_left=(-6, 0), width=12, height=6)
        stalk = Slot(start=(0, 3), end=(5, 26), width=10)
        leaf = Ellipse(center=(10, 12), rx=8, ry=4, rotation=30 deg)
        tenon = tab_and_slot(part="tab", length=12 mm, thickness=3 mm, tabs=1, tab=8 mm,
                             screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
    }
    RightOf(stem, box, gap=8)
    AlignBottom(stem, box)
    # assembled: stood in the lid's mortise, its tenon through the lid (z 97 to 100)
    Place(stem, position=(0, 1.5, 97), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert box.front.bb.width == 100 mm and box.front.bb.height == 100 mm, "100 mm cube"
    assert front_face.left_eye.base == 26 mm and front_face.left_eye.height == 22 mm, "eyes"
    assert front_face.right_eye.center.x - front_face.nose.center.x == 22 mm, "eyes 22 off"
    assert front_face.left_eye.center.y - box.front.bb.center_y == 18 mm, "eyes 18 up"
    assert front_face.mouth.bb.width == 68 mm, "grin 68 wide"
    assert front_face.nose.base == 14 mm and front_face.nose.height == 12 mm, "nose"
    assert left_ribs.middle.length == 64 mm and left_ribs.middle.width == 4 mm, "middle rib"
    assert left_ribs.upper.radius == 60 mm, "60 mm arcs"
    assert left_ribs.upper.midpoint.y - left_ribs.middle.center.y == 20 mm, "rib 20 off"
    assert len(lid_cuts.vent) == 6 and lid_cuts.vent[0].diameter == 10 mm, "six 10 mm vents"
    assert abs(distance(lid_cuts.vent[2].center, box.lid.bb.center) - 30 mm) < 0.001 mm, "r 30"
    assert candle_ring.ring.diameter == 40 mm, "40 mm ring"
    assert stem.stalk.width == 10 mm, "10 mm stalk"
}
