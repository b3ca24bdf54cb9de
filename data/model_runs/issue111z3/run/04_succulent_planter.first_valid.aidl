# Garden succulent planter: an open-top finger-jointed box 160 mm long x 80 mm deep x 70 mm tall
# (outside), 4 mm birch ply, 12 mm fingers. Three 8 mm drain holes in the bottom in a row along its
# length, 40 mm apart, centred. "SUCCULENTS" engraved on the front in filled sans Bold letters
# 10 mm high, centred on the front panel.

import "std/joints.aidl"

units mm
thickness 4 mm

param length = 160 mm, min = 100, max = 300
param depth = 80 mm, min = 60, max = 150
param height = 70 mm, min = 50, max = 120
param drain_pitch = 40 mm, min = 25, max = 60

assembly planter {
    box = finger_box(length=length, depth=depth, height=height, thickness=4 mm, finger=12 mm, closed=false)

    hole drains {
        for i in range(3) {
            c = Circle(center=(i * drain_pitch, 0), diameter=8)
        }
    }
    CenterInside(drains, box.bottom)
    CutInto(drains, box.bottom)

    drawing label {
        word = Text("SUCCULENTS", position=(0, 0), size=10, font="sans:Bold", valign="middle", fill=true)
    }
    At(label.word.position, box.front.bb.center)
    CutInto(label, box.front)

    assert box.front.bb.width == 160 mm, "160 long outside"
    assert box.front.bb.height == 70 mm, "70 tall outside"
    assert box.left.bb.height == 80 mm, "80 deep outside"
    assert len(drains.c) == 3, "three drain holes"
    assert drains.c[1].center.x - drains.c[0].center.x == 40 mm, "drains 40 apart"
    assert drains.c[0].diameter == 8 mm, "8 mm drains"
    assert label.word.size == 10 mm, "letters 10 high"
}
