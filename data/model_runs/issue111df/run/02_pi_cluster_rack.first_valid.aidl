# Request (electronics): an open rack for a 3-node Raspberry Pi 4 cluster, 3 mm acrylic.
# Three carrier plates 100 x 70 mm (tabs included), each carrying one Pi 4 (board 85 x 56,
# M2.5 holes on a 58 x 49 mm rectangle, 3.5 mm in from the board's corners) on four M2.5
# clearance holes, with a 30 x 20 rounded opening under the SoC for air and the node name
# "node1".."node3" engraved on its front margin. The carriers sit 35 mm apart (first at 20 mm
# up), glued with two 15 mm tabs on each end into mortises in two side panels 80 wide x
# 120 tall. Side panels: top corners R8, a 50 x 8 mm notch in the bottom edge leaving two
# feet, one row of five 20 x 5 vent slots between each two carriers, and "PI CLUSTER"
# engraved along the top of the right panel. Five parts.

import "std/joints.aidl"
import "std/fasteners.aidl"

units mm
thickness 3 mm

param nodes = 3, min = 1, max = 3
pitch = 35 mm
first = 20 mm
side_w = 80 mm
side_h = 120 mm
carrier_w = 100 mm
carrier_d = 70 mm
t = 3 mm

def carrier(n) -> solid {
    plate = Rectangle(center=(0, 0), width=carrier_w, height=carrier_d)
    left_tabs = tab_and_slot(part="tab", length=carrier_d, thickness=t, tabs=2, tab=15,
                             screw=0, rotation=90 deg, cx=-carrier_w / 2, cy=0)
    right_tabs = tab_and_slot(part="tab", length=carrier_d, thickness=t, tabs=2, tab=15,
                              screw=0, rotation=-90 deg, cx=carrier_w / 2, cy=0)
    # the Pi's mounting holes: a 58 x 49 rectangle, the board centred on the plate
    pattern = Rectangle(center=(-42.5 + 3.5 + 29, 0), width=58, height=49, construction=true)
    m = clearance_hole(size=2.5)
    CornerPattern(m, pattern)
    hole air {
        a = RoundedRectangle(center=(-10, 0), width=30, height=20, corner_radius=4)
    }
    drawing name {
        label = Text(f"node{n}", (0, -carrier_d / 2 + 2), size=4)
    }
}

def side(right) -> solid {
    panel = RoundedRectangle(bottom_left=(-side_w / 2, 0), width=side_w, height=side_h,
                             corner_radii=[8, 8, 0, 0])
    for i in range(3) {
        mortise = tab_and_slot(part="slot", length=carrier_d, thickness=t, tabs=2, tab=15,
                               screw=0, clearance=0.1, cx=0, cy=first + i * pitch)
    }
    hole feet {
        n = Rectangle(center=(0, 3), width=50, height=8)
    }
    for r in range(2) {
        for c in range(5) {
            hole vent {
                s = Slot(center=(-24 + 12 * c, first + pitch / 2 + r * pitch), length=20,
                         width=5, rotation=90 deg)
            }
        }
    }
    if right {
        drawing title {
            label = Text("PI CLUSTER", (0, side_h - 12), size=6)
        }
    }
}

assembly rack {
    for i in range(nodes) {
        c = carrier(i + 1)
        Place(c, position=(0, 0, first + i * pitch - t / 2))
    }
    left = side(false)
    right = side(true)
    # sides stand in the planes x = -50..-47 and 47..50, their drawing's x along the depth
    Place(left, position=(-carrier_w / 2 + t, 0, 0), face="left", up="up")
    Place(right, position=(carrier_w / 2 - t, 0, 0), face="right", up="up")

    # on the sheet: sides in a row, carriers above them
    RightOf(right, left, gap=5)
    for i in range(nodes) {
        c[i].bb.bottom == left.bb.top + 5 + i * (carrier_d + 5)
        AlignLeft(c[i], left)
    }

    assert nodes == 3, "three nodes"
    assert c[0].plate.bb.width == 100 mm and c[0].plate.bb.height == 70 mm, "carriers 100 x 70"
    assert left.panel.bb.width == 80 mm and left.panel.bb.height == 120 mm, "sides 80 x 120"
    assert carrier_w - 2 * t >= 85 mm, "a Pi 4 board fits between the sides"
    assert c[0].pattern.width == 58 mm and c[0].pattern.height == 49 mm, "Pi 4 hole pattern"
    assert first + (nodes - 1) * pitch + 15 mm <= side_h, "the top carrier's Pi clears the top"
}
