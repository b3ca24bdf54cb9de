# Request: a router template for the hand-hold slots in the ends of a tool tote, cut from 6 mm
# ply. The finished hand-hold is a 120 x 32 mm stadium whose centre is 40 mm below the panel's
# top edge. I rout it with a 30 mm guide bushing and a 12.7 mm (1/2") straight bit, so the
# template's opening is the hand-hold grown by the offset (30 - 12.7) / 2 on every side.
# Template plate 260 x 140 mm with R6 corners; a 260 x 30 mm fence glued under it with three
# 30 mm tabs into mortises, the fence's inner face registers on the panel's top edge. Two
# countersunk M4 holes near the top corners (for screwing to a waste board), an engraved centre
# line through the opening, a V notch on the fence's lower edge at the centre to meet a pencil
# mark, and engraved "HANDHOLD 120 x 32" and "30 BUSH + 12.7 BIT".

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

param hold_len = 120 mm, min = 80 mm, max = 160 mm
param hold_w = 32 mm, min = 25 mm, max = 40 mm
bush = 30 mm
bit = 12.7 mm
offset = (bush - bit) / 2
plate_w = 260 mm
plate_h = 140 mm
fence_h = 30 mm
t = 6 mm
drop = 40 mm          # hand-hold centre below the panel's top edge
fence_y = -plate_h / 2 + t      # the fence's outer face, one thickness in from the plate's edge

assembly handhold_template {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=6)
        hole opening {
            s = Slot(center=(0, fence_y + t + drop), length=hold_len + 2 * offset,
                     width=hold_w + 2 * offset)
        }
        mortise = tab_and_slot(part="slot", length=plate_w, thickness=t, tabs=3, tab=30 mm,
                               screw=0, cx=0 mm, cy=fence_y + t / 2)
        screw = clearance_hole(size=4, cx=-110 mm, cy=55 mm)
        other = clearance_hole(size=4, cx=110 mm, cy=55 mm)
        Countersink([screw, other], diameter=8.5 mm)
        drawing marks {
            centre_up = Line((0, fence_y + t + drop + hold_w / 2 + offset + 3),
                             (0, plate_h / 2 - 4))
            centre_down = Line((0, fence_y + t + drop - hold_w / 2 - offset - 3),
                               (0, fence_y + t + 2))
            title = Text("HANDHOLD 120 x 32", position=(0, 50), size=7, valign="middle")
            tool = Text("30 BUSH + 12.7 BIT", position=(0, 38), size=5, valign="middle")
        }
        Fixed(body)
    }

    solid fence {
        bar = Rectangle(center=(0, -fence_h / 2), width=plate_w, height=fence_h)
        tabs = tab_and_slot(part="tab", length=plate_w, thickness=t, tabs=3, tab=30 mm,
                            screw=0, cx=0 mm, cy=0 mm)
        hole notch {
            v = Triangle(center=(0, -fence_h + 2.5), base=8, height=5, rotation=0)
        }
        AlignBottom(notch, bar)
    }
    Below(fence, plate, gap=10)

    Place(plate, position=(0, 0, 0))
    # fence hangs under the plate: its top face looks to the plate's near edge, tab tips flush
    # with the plate's top face
    Place(fence, position=(0, fence_y + t, t), face="front", up="up")

    assert plate.opening.s.length - hold_len == 30 mm - 12.7 mm, "bushing offset on the length"
    assert plate.opening.s.width - hold_w == 30 mm - 12.7 mm, "bushing offset on the width"
    assert plate.opening.s.center.y - (plate.body.bb.bottom + 2 * t) == 40 mm,
        "hand-hold centre 40 mm from the fence's inner face"
    assert plate.body.bb.width == 260 mm and plate.body.bb.height == 140 mm
    assert len(plate.mortise.slot) == 3
}
