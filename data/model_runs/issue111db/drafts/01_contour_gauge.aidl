# Request: a 150 mm contour (profile) gauge cut from 3 mm acrylic for copying moulding and
# pipe profiles onto a board. 45 fingers, each 100 x 8 mm with round ends, stand side by side
# (45 x 3 mm = 135 mm of fingers) clamped between two 160 x 24 mm rails by two M4 bolts with
# wing nuts at 150 mm centres, outside the finger stack. The front rail carries an engraved
# mm scale along its top edge (a tick every 5 mm, long ticks every 10 mm, numbers every 20 mm,
# 0 at the centre) and "CONTOUR GAUGE" along its bottom edge. Rails' corners rounded 3 mm.

import "std/fasteners.aidl"

thickness 3 mm

param fingers = 45, min = 20, max = 48
param finger_len = 100 mm, min = 60 mm, max = 150 mm
param finger_w = 8 mm, min = 6 mm, max = 12 mm
rail_len = 160 mm
rail_h = 24 mm
bolt_pitch = 150 mm

def rail(scale=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=rail_len, height=rail_h, corner_radius=3)
    left_bolt = clearance_hole(size=4)
    right_bolt = clearance_hole(size=4)
    left_bolt.c.center == (-bolt_pitch / 2, 0)
    right_bolt.c.center == (bolt_pitch / 2, 0)
    if scale {
        drawing marks {
            for i in range(29) {
                tick = Line((-70 + 5 * i, rail_h / 2 - 1), (-70 + 5 * i, rail_h / 2 - (6 if i % 2 == 0 else 3.5)))
            }
            for k in range(7) {
                num = Text(str(abs(-60 + 20 * k)), position=(-60 + 20 * k, rail_h / 2 - 8.5), size=2.5, valign="top")
            }
            title = Text("CONTOUR GAUGE", position=(0, -rail_h / 2 + 2.5), size=3.5)
        }
    }
}

def finger() -> solid {
    strip = Slot(center=(0, 0), length=finger_len, width=finger_w)
}

assembly contour_gauge {
    front = rail(scale=true)
    back = rail()
    first = finger()
    row = LinearPattern(first, fingers, (0, finger_w + 2 mm))

    # on the sheet: rails side by side above the fingers
    Above(front, row[fingers - 1], gap=4)
    AlignLeft(front, first)
    RightOf(back, front, gap=4)
    AlignBottom(back, front)
    Fixed(first)

    # in 3D: fingers on edge, their length vertical, stacked along x; rails clamp their edges
    # FIX after the first valid program: a pattern copy keeps its sheet offset (0, 10 i) in its
    # own frame, so Place carried it 10 i mm back (W0517/W0518): take the offset off again
    for i in range(fingers) {
        Place(row[i], position=(-fingers * 3 mm / 2 + 3 mm * i, -(finger_w + 2 mm) * i, finger_len / 2), face="right", up="back")
    }
    Place(front, position=(0, -finger_w / 2, finger_len / 2), face="front", up="up")
    Place(back, position=(0, finger_w / 2, finger_len / 2), face="back", up="up")

    assert len(row) == 45, "45 fingers"
    assert first.strip.length == 100 mm and first.strip.width == 8 mm, "fingers 100 x 8"
    assert front.body.width == 160 mm and front.body.height == 24 mm, "rails 160 x 24"
    assert front.right_bolt.c.center.x - front.left_bolt.c.center.x == 150 mm, "bolts at 150 mm centres"
    assert fingers * 3 mm + 2 * front.left_bolt.c.radius < 150 mm, "bolts clear the finger stack"
}
