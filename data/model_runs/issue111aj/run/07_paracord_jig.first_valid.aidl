# Request (camping): a paracord bracelet jig, 6 mm ply, three parts, no glue. Base 290 x 70 mm,
# corners R6, with a 6 mm hanging hole 12 mm from its right end. Two uprights 70 wide x 50
# tall (plus the tabs), each with a buckle tongue 16 wide rising 22 mm from the middle of its
# top edge (top corners R6) and two 12 mm tabs, 6 mm long, on its bottom edge. The fixed
# upright's slots stand 20 mm from the base's left end; the sliding upright plugs into any of
# 9 slot pairs set every half inch from 5.5 in to 9.5 in from the fixed one (the bracelet's
# length, centre to centre), slots 0.2 mm clearance. Each slot pair is numbered with its
# length in inches ("5.5" ... "9.5", engraved, size 4) on the base's centre line, and
# "INCHES" is engraved between the fixed upright and the first pair.

import "std/joints.aidl"

thickness 6 mm
mat = 6 mm
base_w = 70 mm
fixed_x = 20 mm
first_len = 5.5 in
step = 0.5 in
pairs = 9

def upright() -> solid {
    body = Rectangle(center=(0, 0), width=base_w, height=50 + mat)
    tongue = RoundedRectangle(bottom_left=(-8, (50 + mat) / 2 - 1), width=16, height=23,
                              corner_radii=[6, 6, 0, 0])
    tabs = tab_and_slot(part="tab", length=base_w, thickness=mat, tabs=2, tab=12 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-(50 + mat) / 2)
    assert tongue.bb.top - body.bb.top == 22 mm, "tongue rises 22 mm"
}

assembly paracord_jig {
    solid base {
        body = RoundedRectangle(bottom_left=(0, -base_w / 2), width=290, height=base_w,
                                corner_radius=6)
        fixed_slots = tab_and_slot(part="slot", length=base_w, thickness=mat, tabs=2, tab=12 mm,
                                   screw=0, clearance=0.2 mm, rotation=90 deg, cx=fixed_x, cy=0 mm)
        for i in range(pairs) {
            pair = tab_and_slot(part="slot", length=base_w, thickness=mat, tabs=2, tab=12 mm,
                                screw=0, clearance=0.2 mm, rotation=90 deg,
                                cx=fixed_x + first_len + i * step, cy=0 mm)
        }
        hole hang {
            c = Circle(center=(290 - 12, 0), diameter=6)
        }
        drawing marks {
            for i in range(pairs) {
                n = Text(f"{5.5 + i * 0.5:.1f}", position=(fixed_x + first_len + i * step, 0),
                         size=4, valign="middle")
            }
            unit = Text("INCHES", position=((fixed_x + fixed_x + first_len) / 2, 0), size=5,
                        valign="middle")
        }
        assert len(pair) == 9, "nine slot pairs"
        assert pair[0].cx - fixed_slots.cx == 5.5 in, "first pair at 5.5 in"
        assert pair[8].cx - fixed_slots.cx == 9.5 in, "last pair at 9.5 in"
        assert body.bb.right - pair[8].cx > 20 mm, "the last pair is well inside the base"
    }
    fixed_up = upright()
    slide_up = upright()
    Below(fixed_up, base, gap=8)
    AlignLeft(fixed_up, base)
    RightOf(slide_up, fixed_up, gap=8)
    AlignTop(slide_up, fixed_up)
}
