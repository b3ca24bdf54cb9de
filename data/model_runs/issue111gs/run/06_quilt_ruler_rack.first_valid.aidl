# Request: an upright rack for my acrylic quilting rulers, 6 mm birch ply, glued.
# - Base 320 x 130 mm and back 320 x 240 mm, joined along the base's back edge by a
#   finger joint with 20 mm fingers; the base's front corners and the back's top
#   corners rounded R10.
# - Eight dividers stand across the base at a 40 mm pitch, centred (x = -140 ... +140),
#   leaving 34 mm slots for the rulers: each divider runs from 10 mm behind the base's
#   front edge to the back, stands 200 mm above the base at the back and 60 mm at the
#   front, its front edge a scooped curve between the two; each is glued in by two
#   25 mm tabs through the base and two through the back (flush behind).
# - "PATCHWORK RULERS" engraved in filled bold letters 14 mm tall on the back's front
#   face, centred in the strip above the dividers.
# Slots 0.1 mm over for glue.

units mm
thickness 6 mm
import "std/joints.aidl"

def divider() -> solid {
    # seen from the right: x toward the back (world y), y up from the floor (world z);
    # the base's top is y = 6, the back's front face x = 59
    bottom = Line((-55, 0), (59, 0))
    notch_a = Line((59, 0), (59, 6))
    notch_b = Line((59, 6), (65, 6))
    back = Line((65, 6), (65, 206))
    top = Line((65, 206), (45, 206))
    scoop = Arc(start=(-55, 66), through=(7, 127), end=(45, 206))
    front = Line((-55, 66), (-55, 0))
    feet = tab_and_slot(part="tab", length=114, thickness=6, tabs=2, tab=25, screw=0,
                        rotation=180 deg, cx=2, cy=0)
    spine = tab_and_slot(part="tab", length=200, thickness=6, tabs=2, tab=25, screw=0,
                         rotation=-90 deg, cx=65, cy=106)
    Rigid(self)
}

assembly ruler_rack {
    solid base {
        slab = Rectangle(center=(0, 0), width=320, height=130)
        joint = finger_edge(length=320, thickness=6, finger=20, start="tab", cx=0, cy=65)
        for k in range(8) {
            mortise = tab_and_slot(part="slot", length=114, thickness=6, tabs=2, tab=25,
                                   screw=0, clearance=0.1, rotation=90 deg,
                                   cx=-140 + 40 * k, cy=2)
        }
        Fillet([slab.bottom_left, slab.bottom_right], 10)
    }

    solid back {
        # seen from the front: y up from the floor
        slab = Rectangle(center=(0, 120), width=320, height=240)
        joint = finger_edge(length=320, thickness=6, finger=20, start="gap",
                            rotation=180 deg, cx=0, cy=0)
        for k in range(8) {
            mortise = tab_and_slot(part="slot", length=200, thickness=6, tabs=2, tab=25,
                                   screw=0, clearance=0.1, rotation=90 deg,
                                   cx=-140 + 40 * k, cy=106)
        }
        Fillet([slab.top_left, slab.top_right], 10)
        drawing label {
            t = Text("PATCHWORK RULERS", position=(0, 223), size=14, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    for k in range(8) {
        d = divider()
        d.bb.left == 340 + (k % 4) * 130
        d.bb.bottom == -65 - (k // 4) * 215
        Place(d, position=(-143 + 40 * k, 0, 0), face="right", up="up")
    }

    Below(back, base, gap=10)
    AlignLeft(back, base)

    # assembled: the base on the floor, its back edge at y = 65; the back upright behind
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(back, position=(0, 65, 0), face="front", up="up")

    # the request's numbers
    assert base.slab.width == 320 mm and base.slab.height == 130 mm, "base 320 x 130"
    assert back.slab.width == 320 mm and back.slab.height == 240 mm, "back 320 x 240"
    assert len(d) == 8 and len(base.mortise) == 8 and len(back.mortise) == 8, "eight dividers"
    assert base.mortise[1].slot[0].bb.center_x - base.mortise[0].slot[0].bb.center_x == 40 mm,
        "40 mm pitch"
    assert base.mortise[7].slot[0].bb.center_x + base.mortise[0].slot[0].bb.center_x == 0 mm,
        "dividers centred"
    assert d[0].back.end.y - 6 mm == 200 mm and d[0].front.start.y - 6 mm == 60 mm,
        "200 tall at the back, 60 at the front"
    assert d[0].bottom.start.x - (0 mm - 65 mm) == 10 mm, "dividers 10 behind the base's front"
    assert 40 mm - 6 mm >= 34 mm, "34 mm slots"
    assert back.label.t.size == 14 mm, "label 14 mm"
    assert back.label.bb.bottom - d[0].back.end.y >= 4 mm, "label above the dividers"
    assert back.slab.bb.top - back.label.bb.top >= 4 mm, "label below the top"
}
