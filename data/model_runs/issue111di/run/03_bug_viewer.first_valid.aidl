# Request (garden): a bug viewer for the kids to take round the garden. A little box of
# 3 mm birch ply, outside 120 long x 100 deep x 90 tall, finger-jointed, its lid hinged at
# the back (pins cut from the sheet) to drop a bug in. A 50 mm magnifier lens sits in the
# lid: a 46 mm hole in the middle of the lid (the lens rests on its rim) and a ring 66 mm
# across with a 50.5 mm hole, glued on the lid round it, keeps the lens centred. All four
# walls get air holes: 3 mm holes in a honeycomb 8 mm apart, 9 across and 5 rows, centred
# on each wall, except on the front where the group's middle is 32 mm above the bottom.
# The front has BUG VIEWER engraved filled in bold sans 9 mm tall, centred across, its
# middle 18 mm below the front's top edge.

import "std/boxes.aidl"

thickness 3 mm

def air_holes() -> hole {
    c = Circle(center=(0, 0), diameter=3)
    g = GridPattern(c, 5, 9, (8, 6.93), stagger=true)
}

assembly bug_viewer {
    box = hinged_box(length=120 mm, width=100 mm, height=90 mm, thickness=3 mm,
                     finger=10 mm, outside=true)

    hole lens_hole { c = Circle(center=(0, 0), diameter=46) }
    CenterInside(lens_hole, box.lid)
    CutInto(lens_hole, box.lid)

    solid lens_ring {
        rim = Circle(center=(0, 0), diameter=66)
        hole bore { c = Circle(center=(0, 0), diameter=50.5) }
    }
    RightOf(lens_ring, box.right, gap=10)
    # glued on the lid round the lens hole (the box stands on z = 0, centred on x = y = 0)
    Place(lens_ring, position=(0, 0, 90), face="up")

    front_air = air_holes()
    AlignCenterX(front_air, box.front)
    front_air.bb.center_y == box.front.bb.bottom + 32 mm
    CutInto(front_air, box.front)

    back_air = air_holes()
    CenterInside(back_air, box.back)
    CutInto(back_air, box.back)

    left_air = air_holes()
    CenterInside(left_air, box.left)
    CutInto(left_air, box.left)

    right_air = air_holes()
    CenterInside(right_air, box.right)
    CutInto(right_air, box.right)

    drawing label {
        t = Text("BUG VIEWER", position=(0, 0), size=9, font="sans:Bold", valign="middle",
                 fill=true)
    }
    AlignCenterX(label, box.front)
    label.t.position.y == box.front.bb.top - 18 mm
    CutInto(label, box.front)

    assert box.lid.bb.width == 120 mm, "120 long"
    assert lens_hole.c.diameter == 46 mm, "46 mm lens seat"
    assert lens_ring.rim.diameter == 66 mm and lens_ring.bore.c.diameter == 50.5 mm,
        "ring 66 / 50.5"
    assert len(front_air.g) == 45, "9 x 5 air holes"
    assert front_air.bb.center_y - box.front.bb.bottom == 32 mm, "front holes 32 up"
    assert box.front.bb.top - label.t.position.y == 18 mm, "label 18 below the top"
    assert label.t.bb.bottom > front_air.bb.top + 3 mm, "label clear of the air holes"
}
