# Request (kitchen): a garlic keeper for the worktop in 3 mm plywood: a finger-jointed box
# 130 x 130 mm and 110 mm tall outside with a lift-off lid. Garlic needs dark and air: each
# of the four walls gets a grid of 12 vent holes, 10 mm across on a 20 mm pitch (4 across,
# 3 high). The lid has a 24 mm finger hole in its middle to lift it, and is engraved with a
# garlic bulb above the hole and the word GARLIC (filled serif letters, 14 mm tall) below it.

import "std/boxes.aidl"

thickness 3 mm

def vents(rows=3, cols=4) -> hole {
    c = Circle(center=(0, 0), diameter=10)
    g = GridPattern(c, rows, cols, (20, 20))
}

assembly garlic_keeper {
    box = lid_box(length=130 mm, width=130 mm, height=110 mm, thickness=3 mm, finger=10 mm)

    # vents: front and back upright (4 across, 3 high); the sides lie on their side in the
    # net, so their grid is turned: 3 across (the box's height), 4 high
    vf = vents(rows=3, cols=4)
    vb = vents(rows=3, cols=4)
    vl = vents(rows=4, cols=3)
    vr = vents(rows=4, cols=3)
    CenterInside(vf, box.body.front)
    CenterInside(vb, box.body.back)
    CenterInside(vl, box.body.left)
    CenterInside(vr, box.body.right)
    CutInto(vf, box.body.front)
    CutInto(vb, box.body.back)
    CutInto(vl, box.body.left)
    CutInto(vr, box.body.right)

    # the finger hole goes through the lid and the lip glued under it
    hole lift { c = Circle(center=(0, 0), diameter=24) }
    hole lift_lip { c = Circle(center=(0, 0), diameter=24) }
    CenterInside(lift, box.lid)
    CenterInside(lift_lip, box.lip)
    CutInto(lift, box.lid)
    CutInto(lift_lip, box.lip)

    drawing bulb {
        # one half of the bulb, from the pointed top to the root; mirrored about x = 0
        outline = Spline([(0, 22), (3, 15), (11, 8), (16, -2), (13, -12), (0, -16)],
                         closed=true, mirror="y", corners=[0])
        clove_l = Spline([(0, 20), (-6, 4), (-5, -15)])
        clove_r = Spline([(0, 20), (6, 4), (5, -15)])
        root1 = Line((0, -16), (-3, -21))
        root2 = Line((0, -16), (0, -22))
        root3 = Line((0, -16), (3, -21))
    }
    drawing word {
        t = Text("GARLIC", position=(0, 0), size=14, font="serif:Bold", valign="middle",
                 fill=true)
    }
    AlignCenterX(bulb, box.lid)
    AlignCenterX(word, box.lid)
    bulb.bb.bottom == lift.bb.top + 8 mm
    word.t.position.y == lift.c.center.y - 34 mm
    CutInto(bulb, box.lid)
    CutInto(word, box.lid)

    assert len(vf.g) == 12 and len(vl.g) == 12, "12 vent holes a wall"
    assert vf.c.diameter == 10 mm, "10 mm vents"
    assert lift.c.diameter == 24 mm, "24 mm finger hole"
    assert distance(word, lift) >= 5 mm and distance(bulb, lift) >= 5 mm, "art clears the hole"
}
