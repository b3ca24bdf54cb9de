# Request (kitchen): a bread box for the counter, 6 mm birch ply, finger-jointed (20 mm
# fingers). Outside 360 mm long x 240 mm deep x 200 mm tall with the lid on. The lid lifts on
# pins at the back (a hinged box). "BREAD" engraved filled across the middle of the front,
# sans bold, 40 mm tall. Each side wall gets an air vent: 15 holes of 8 mm, 3 rows of 5 at
# 16 mm pitch (5 along the length of the side, 3 up it), centred on the side. An M5 hole for
# a wooden knob in the lid, centred side to side, 30 mm in from the lid's front edge.

import "std/boxes.aidl"
import "std/fasteners.aidl"

thickness 6 mm

param length = 360 mm, min = 260 mm, max = 420 mm
param width = 240 mm, min = 180 mm, max = 300 mm
param height = 200 mm, min = 140 mm, max = 260 mm
t = 6 mm
pitch = 16 mm

def vent() -> hole {
    c = Circle(center=(0, 0), diameter=8 mm)
}

assembly bread_box {
    box = hinged_box(length=length, width=width, height=height, thickness=t, finger=20 mm)

    # the word on the front (the front lies upright, its top edge at +y)
    drawing word {
        w = Text("BREAD", position=(0, 0), size=40 mm, font="sans:Bold", valign="middle",
                 fill=true)
    }
    Concentric(word.w.position, box.front.bb.center)
    CutInto(word, box.front)

    # vents: a side lies on its side, its height along x and its depth along y
    left_vent = vent()
    left_grid = GridPattern(left_vent, 5, 3, (pitch, pitch))
    left_vent.c.center.x == box.left.bb.center_x - pitch
    left_vent.c.center.y == box.left.bb.center_y - 2 * pitch
    CutInto(left_vent, box.left)

    right_vent = vent()
    right_grid = GridPattern(right_vent, 5, 3, (pitch, pitch))
    right_vent.c.center.x == box.right.bb.center_x - pitch
    right_vent.c.center.y == box.right.bb.center_y - 2 * pitch
    CutInto(right_vent, box.right)

    # the knob's hole (the lid lies with its hinge edge, the back, at +y)
    knob = clearance_hole(size=5)
    AlignCenterX(knob, box.lid)
    knob.c.center.y == box.lid.bb.bottom + 30 mm
    CutInto(knob, box.lid)

    assert box.lid.bb.width == 360 mm, "360 mm long outside"
    assert box.left.panel.outline.height == 240 mm, "240 mm deep outside"
    assert box.front.bb.height + 6 mm == 200 mm, "200 mm tall with the lid on"
    assert len(left_grid) == 15 and len(right_grid) == 15, "15 vent holes a side"
    assert knob.c.center.y - box.lid.bb.bottom == 30 mm, "knob 30 mm from the lid's front"
    assert word.w.size == 40 mm, "letters 40 mm tall"
}
