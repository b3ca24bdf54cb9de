# Request: a box-joint (finger-joint) jig for my table saw, cut from 6 mm birch ply, for
# 6 mm fingers cut with a 6 mm dado stack.
# - Base plate 400 x 220 mm. A 7 mm wide blade slot 60 mm right of the centre, open at the
#   front edge and stopping 10 mm short of the back edge. Four countersunk M4 holes
#   (9 mm heads) for the hardwood runner, in a line 100 mm left of the centre, at
#   y = -95, -55, -15 and 25 mm from the base's centre.
# - Fence 400 x 100 mm standing on the base (its front face 76 mm behind the base's front
#   edge), glued into the base with 3 tabs 20 mm wide. Blade notch 7 mm wide x 25 mm tall at
#   the bottom, over the base's blade slot; key notch 6 x 12 mm at the bottom, its centre
#   12 mm left of the blade's centre (one 6 mm finger of gap between key and blade).
#   Engraved on its front: "BOX JOINT 6 mm" and a tick every 6 mm, 10 each side of the blade.
# - Two triangular braces behind the fence (76 mm along the base, 86 mm up the fence),
#   150 mm left and right of the centre, each glued with 2 tabs 15 mm wide into base and fence.
# - The key: a 6 x 60 mm strip (a 6 x 6 mm square stick) resting on the base through the key notch.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

param t = 6 mm, min = 5 mm, max = 7 mm
param finger = 6 mm, min = 3 mm, max = 12 mm
blade_x = 60 mm
fence_y = 40 mm          # the fence's back face, from the base's centre
brace_x = 150 mm

def brace() -> solid {
    body = Polygon([(0, 0), (76, 0), (0, 86)])
    foot = tab_and_slot(part="tab", length=76 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=180 deg, cx=38 mm, cy=0 mm)
    back = tab_and_slot(part="tab", length=86 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                        rotation=90 deg, cx=0 mm, cy=43 mm)
}

assembly jig {
    solid base {
        plate = Rectangle(center=(0, 0), width=400, height=220)
        hole blade_slot {
            s = Rectangle(bottom_left=(blade_x - 3.5 mm, -111), width=7, height=201)
        }
        runner = clearance_hole(size=4, cx=-100 mm, cy=-95 mm)
        screws = LinearPattern(runner, 4, (0, 40))
        Countersink(screws, diameter=9 mm)
        fence_slots = tab_and_slot(part="slot", length=400 mm, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, cx=0 mm, cy=fence_y - t / 2)
        left_brace_slots = tab_and_slot(part="slot", length=76 mm, thickness=t, tabs=2,
                                        tab=15 mm, screw=0, rotation=90 deg,
                                        cx=-brace_x + t / 2, cy=fence_y - t + 38 mm)
        right_brace_slots = tab_and_slot(part="slot", length=76 mm, thickness=t, tabs=2,
                                         tab=15 mm, screw=0, rotation=90 deg,
                                         cx=brace_x + t / 2, cy=fence_y - t + 38 mm)
        Fixed(plate)
        assert plate.width == 400 mm and plate.height == 220 mm
        assert len(screws) == 4
        assert blade_slot.s.bb.top == plate.bb.top - 10 mm, "slot stops 10 mm short of the back"
        assert blade_slot.s.center.x - plate.center.x == 60 mm
    }

    solid fence {
        panel = Rectangle(center=(0, 50), width=400, height=100)
        feet = tab_and_slot(part="tab", length=400 mm, thickness=t, tabs=3, tab=20 mm,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        hole blade_notch { n = Rectangle(center=(blade_x, 12), width=7, height=26) }
        hole key_notch { n = Rectangle(center=(blade_x - 2 * finger, 5.5), width=finger, height=13) }
        left_brace_slots = tab_and_slot(part="slot", length=86 mm, thickness=t, tabs=2,
                                        tab=15 mm, screw=0, rotation=90 deg,
                                        cx=-brace_x + t / 2, cy=43 mm)
        right_brace_slots = tab_and_slot(part="slot", length=86 mm, thickness=t, tabs=2,
                                         tab=15 mm, screw=0, rotation=90 deg,
                                         cx=brace_x + t / 2, cy=43 mm)
        drawing marks {
            title = Text("BOX JOINT 6 mm", position=(-100, 70), size=10, valign="middle")
            for k in range(1, 11) {
                r = Line((blade_x + k * finger, 88), (blade_x + k * finger, 96))
                l = Line((blade_x - k * finger, 88), (blade_x - k * finger, 96))
            }
            zero = Line((blade_x, 84), (blade_x, 96))
        }
        Fixed(panel)
        Fixed(marks)
        assert panel.width == 400 mm and panel.height == 100 mm
        assert blade_notch.n.center.x - key_notch.n.center.x == 12 mm, "key one finger from the blade"
        assert len(marks.r) == 10 and len(marks.l) == 10
    }

    left_brace = brace()
    right_brace = brace()

    solid key {
        stick = Rectangle(center=(0, 0), width=6, height=60)
    }

    # flat on the sheet: side by side
    Above(fence, base, gap=10)
    AlignCenterX(fence, base)
    RightOf(left_brace, base, gap=10)
    AlignTop(left_brace, base)
    RightOf(right_brace, base, gap=10)
    Below(right_brace, left_brace, gap=10)
    RightOf(key, left_brace, gap=10)
    AlignTop(key, base)

    # 3D: base flat, fence standing with its tabs through the base, braces behind it
    Place(base, position=(0, 0, 0), face="up")
    Place(fence, position=(0, fence_y, 0), face="front", up="up")
    Place(left_brace, position=(-brace_x, fence_y - t, 0), face="right", up="up")
    Place(right_brace, position=(brace_x, fence_y - t, 0), face="right", up="up")
    Place(key, position=(blade_x - 2 * finger, 10, t), face="up")
}
