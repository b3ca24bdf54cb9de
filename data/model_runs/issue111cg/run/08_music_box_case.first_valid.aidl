# Request (gifts): a personalised case for an 18-note wind-up music box movement, cut from
# 3 mm birch ply: a finger-jointed box 120 x 80 x 60 mm outside with a hinged lid. In the
# bottom: two 2.4 mm holes 42 mm apart for the movement's M2 screws, 8 mm behind the centre
# line, and a 10 mm hole for the winding key 10 mm in front of it, all centred left to right.
# In the front: a sound rose, a 6 mm hole in the middle of eight 5 mm holes on a 24 mm
# circle, centred on the panel. On the lid, engraved: the name "CLARA" in filled bold sans
# letters 14 mm tall, and under it a music stave: five lines 90 mm long, 2.5 mm apart.

import "std/boxes.aidl"

thickness 3 mm

assembly music_box_case {
    box = hinged_box(length=120 mm, width=80 mm, height=60 mm, thickness=3 mm, finger=10 mm)

    hole mount {
        s1 = Circle(center=(-21, 8), diameter=2.4)
        s2 = Circle(center=(21, 8), diameter=2.4)
        key = Circle(center=(0, -10), diameter=10)
    }
    AlignCenterX(mount, box.bottom)
    mount.s1.center.y == box.bottom.bb.center_y + 8 mm
    CutInto(mount, box.bottom)

    hole rose {
        mid = Circle(center=(0, 0), diameter=6)
        petal = Circle(center=(12, 0), diameter=5)
        ring = CircularPattern(petal, 8, mid.center)
    }
    CenterInside(rose, box.front)
    CutInto(rose, box.front)

    drawing deco {
        name = Text("CLARA", position=(0, 10), size=14, font="sans:Bold", valign="middle",
                    fill=true)
        for i in range(5) {
            staff = Line((-45, -8 - i * 2.5), (45, -8 - i * 2.5))
        }
    }
    CenterInside(deco, box.lid)
    CutInto(deco, box.lid)

    # the request's numbers
    assert box.length == 120 mm and box.width == 80 mm and box.height == 60 mm, "120 x 80 x 60"
    assert mount.s2.center.x - mount.s1.center.x == 42 mm, "screws 42 apart"
    assert mount.s1.center.y - mount.key.center.y == 18 mm, "key 10 in front of the centre line"
    assert len(rose.ring) == 8, "eight petals"
    assert rose.petal.diameter == 5 mm and rose.mid.diameter == 6 mm, "5 and 6 mm holes"
    assert len(deco.staff) == 5, "five stave lines"
    assert deco.staff[0].length == 90 mm, "stave 90 long"
}
