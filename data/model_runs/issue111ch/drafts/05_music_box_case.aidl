# Request (music): a case for an 18-note hand-crank music-box movement, 3 mm ply, a closed
# finger-jointed box 100 x 70 x 45 mm outside with 8 mm fingers. The lid is the soundboard:
# a 22 mm sound hole in its middle ringed by twelve 4 mm holes on a 34 mm circle, and the
# tune's name "CANON IN D" engraved 25 mm below the lid's centre in 5 mm letters. The
# movement screws to the bottom with two 2.6 mm holes 34 mm apart (front to back), 20 mm
# right of the bottom's centre; its crank shaft comes out through the right side in an
# 8 mm hole halfway from front to back, 16 mm above the box's underside.

import "std/joints.aidl"

units mm
thickness 3 mm

assembly music_box {
    box = finger_box(length=100 mm, depth=70 mm, height=45 mm, thickness=3 mm, finger=8 mm)

    hole rosette {
        sound = Circle(center=(0, 0), diameter=22)
        h = Circle(center=(17, 0), diameter=4)
        ring = CircularPattern(h, 12, sound.center)
    }
    CenterInside(rosette, box.lid)
    CutInto(rosette, box.lid)

    drawing title {
        t = Text("CANON IN D", (0, 0), size=5, valign="middle")
    }
    AlignCenterX(title, box.lid)
    title.t.position.y == box.lid.bb.center_y - 25 mm
    CutInto(title, box.lid)

    hole screws {
        a = Circle(center=(20, 17), diameter=2.6)
        b = Circle(center=(20, -17), diameter=2.6)
    }
    screws.bb.center_x == box.bottom.bb.center_x + 20 mm
    AlignCenterY(screws, box.bottom)
    CutInto(screws, box.bottom)

    # the right side lies flat with the box's underside at its left edge
    hole crank {
        c = Circle(center=(0, 0), diameter=8)
    }
    crank.c.center.x == box.right.bb.left + 16 mm
    AlignCenterY(crank, box.right)
    CutInto(crank, box.right)

    assert box.lid.bb.width == 100 mm and box.lid.bb.height == 70 mm, "100 x 70 outside"
    assert box.front.bb.height == 45 mm, "45 tall"
    assert len(rosette.ring) == 12, "twelve ring holes"
    assert rosette.sound.diameter == 22 mm, "22 mm sound hole"
    assert distance(rosette.ring[3].center, rosette.sound.center) == 17 mm, "on a 34 mm circle"
    assert rosette.sound.center.y - title.t.position.y == 25 mm, "title 25 below"
    assert screws.a.center.y - screws.b.center.y == 34 mm, "screws 34 apart"
    assert crank.c.center.x - box.right.bb.left == 16 mm, "shaft 16 up"
}
