# Pets: hamster house, a closed finger-jointed box 160 x 120 x 100 mm outside, 4 mm
# plywood, 10 mm fingers; in the front an arched doorway 50 mm wide, its sill 10 mm and the
# top of its arch 70 mm above the box's bottom edge, centred; a 30 mm round window centred
# in each side; in the lid a 3 x 5 grid of 8 mm air holes 20 mm apart, centred; "HAMMY"
# engraved 10 mm tall on the front, centred, its baseline 78 mm above the bottom edge.

import "std/joints.aidl"

thickness 4 mm

assembly hamster_house {
    box = finger_box(length=160 mm, depth=120 mm, height=100 mm, thickness=4 mm, finger=10 mm)

    hole door {
        leaf = Rectangle(center=(0, 27.5), width=50, height=35)
        arch = Circle(center=(0, 45), diameter=50)
    }
    AlignCenterX(door, box.front)
    door.bb.bottom == box.front.bb.bottom + 10
    CutInto(door, box.front)

    hole left_window { c = Circle(center=(0, 0), diameter=30) }
    CenterInside(left_window, box.left)
    CutInto(left_window, box.left)
    hole right_window { c = Circle(center=(0, 0), diameter=30) }
    CenterInside(right_window, box.right)
    CutInto(right_window, box.right)

    hole air {
        h = Circle(center=(0, 0), diameter=8)
    }
    vents = GridPattern(air, 3, 5, 20)
    CutInto(air, box.lid)
    (vents[0].h.center.x + vents[14].h.center.x) / 2 == box.lid.bb.center_x
    (vents[0].h.center.y + vents[14].h.center.y) / 2 == box.lid.bb.center_y

    drawing name {
        word = Text("HAMMY", (0, 0), size=10)
    }
    AlignCenterX(name, box.front)
    name.word.position.y == box.front.bb.bottom + 78
    CutInto(name, box.front)

    assert box.bottom.bb.width == 160 mm, "160 long"
    assert box.front.bb.height == 100 mm, "100 tall"
    assert box.left.bb.height == 120 mm, "120 deep"
    assert door.bb.width == 50 mm, "door 50 wide"
    assert door.bb.bottom - box.front.bb.bottom == 10 mm, "sill 10 up"
    assert door.bb.top - box.front.bb.bottom == 70 mm, "arch top 70 up"
    assert door.bb.center_x == box.front.bb.center_x, "door centred"
    assert left_window.c.diameter == 30 mm and right_window.c.diameter == 30 mm, "30 mm windows"
    assert len(vents) == 15, "3 x 5 air holes"
    assert vents[1].h.center.x - vents[0].h.center.x == 20 mm, "20 apart"
    assert vents[0].h.diameter == 8 mm, "8 mm air holes"
    assert name.word.size == 10 mm, "10 mm name"
    assert name.word.position.y - box.front.bb.bottom == 78 mm, "name baseline 78 up"
    assert name.bb.top < box.front.bb.top - 4 mm, "name under the front's top fingers"
}
