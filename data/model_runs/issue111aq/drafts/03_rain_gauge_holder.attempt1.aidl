# Request (garden): a fence-post holder for a rain gauge tube (a flat-bottomed glass tube,
# 25 mm across, 150 mm long), 3 mm ply, glued. A backplate 50 x 220 mm with R6 corners and
# two countersunk holes for 4 mm screws (8 mm heads), centred, 12 mm from the bottom and
# from the top. Three shelves stand out 40 mm from it, each 50 mm wide with R8 front corners,
# and each glued into the backplate by one 20 x 3 mm tab in a 20.2 x 3.2 mm slot: a foot
# (slot centred 20 mm up, a 6 mm weep hole) and two collars (slots 135 and 160 mm up) with a
# 25.6 mm hole for the tube; the holes' centres are 22 mm out from the backplate. Engraved
# on the backplate behind the tube: a millimetre scale from 0 (the foot's top face) to
# 100 mm, a tick every 5 mm (10 mm long every 10 mm, else 5 mm), numbered every 10 mm on
# the left, "mm" above it, and "RAIN GAUGE" running up the right-hand side.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm

zero = 20 mm + 1.5 mm   # the foot's top face, up the backplate

solid backplate {
    body = RoundedRectangle(bottom_left=(-25, 0), width=50, height=220, corner_radius=6)
    low_screw = clearance_hole(size=4, cx=0, cy=12)
    high_screw = clearance_hole(size=4, cx=0, cy=208)
    Countersink([low_screw, high_screw], diameter=8 mm)
    foot_slot = tab_and_slot(part="slot", length=50, thickness=3, tabs=1, tab=20, screw=0,
                             clearance=0.2, cx=0, cy=20)
    low_slot = tab_and_slot(part="slot", length=50, thickness=3, tabs=1, tab=20, screw=0,
                            clearance=0.2, cx=0, cy=135)
    high_slot = tab_and_slot(part="slot", length=50, thickness=3, tabs=1, tab=20, screw=0,
                             clearance=0.2, cx=0, cy=160)
    drawing scale {
        for i in range(21) {
            tick = Line((-3 - (10 if i % 2 == 0 else 5), zero + i * 5), (-3, zero + i * 5))
        }
        for k in range(11) {
            n = Text(str(k * 10), position=(-14, zero + k * 10), size=3.5, anchor="end",
                     valign="middle")
        }
        unit = Text("mm", position=(-14, zero + 106), size=3.5, anchor="end", valign="middle")
        title = Text("RAIN GAUGE", position=(18, zero + 50), size=5, rotation=90 deg,
                     valign="middle")
    }
    assert body.height == 220 mm and body.width == 50 mm, "backplate 50 x 220"
    assert scale.tick[20].start.y - scale.tick[0].start.y == 100 mm, "scale 0 to 100 mm"
    assert len(scale.tick) == 21, "a tick every 5 mm"
    assert high_screw.c.center.y - body.bb.bottom == 208 mm, "top screw 12 mm from the top"
}

def shelf(bore=25.6 mm) -> solid {
    # y: out from the backplate's face; the tab stands 3 mm behind it
    body = RoundedRectangle(bottom_left=(-25, -3), width=50, height=43, corner_radii=[8, 8, 0, 0])
    joint = tab_and_slot(part="tab", length=50, thickness=3, tabs=1, tab=20, screw=0,
                         rotation=180 deg, cx=0, cy=-3)
    hole opening { c = Circle(center=(0, 22), diameter=bore) }
    assert body.bb.top == 40 mm, "stands out 40 mm"
}

assembly rain_gauge {
    back = backplate
    foot = shelf(bore=6 mm)
    low = shelf()
    high = shelf()
    RightOf(foot, back, gap=10)
    AlignBottom(foot, back)
    Above(low, foot, gap=8)
    Above(high, low, gap=8)
    AlignLeft(low, foot)
    AlignLeft(high, foot)
    assert low.opening.c.diameter == 25.6 mm, "25.6 mm tube holes"
}
