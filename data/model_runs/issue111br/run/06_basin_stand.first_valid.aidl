# Request: a flat-pack camp washstand for a collapsible basin (rim 300 mm, bowl 220 mm across
# and 100 deep), 6 mm plywood, no tools. Two leg panels 700 mm tall, 440 wide at the foot and
# 340 at the top, slotted into each other crosswise (cross halving, 0.2 mm clearance), each
# with a 200 mm wide, 60 mm tall arch between its feet (r30 corners) and a 260 mm wide, 120 mm
# deep notch at the top (r20) for the bowl. A 360 mm top ring with a 230 mm hole drops onto
# a 20 mm tab on each of the four horns (centred 150 mm out) and sits flush with the legs' tops.
# "CAMP" and "WASH" engraved 8 mm tall on the ring, between the tabs.

units mm
thickness 6 mm

import "std/joints.aidl"

T = 6 mm
H = 700 mm
ARCH_H = 60 mm
NOTCH_D = 120 mm
TAB_R = 150 mm
HALF = (H - NOTCH_D) / 2      # where the two halving slots meet

def leg(from_top=false) -> solid {
    body = Trapezoid(center=(0, H / 2), bottom_width=440, top_width=340, height=H)
    hole arch {
        a = RoundedRectangle(center=(0, 0), width=200, height=2 * ARCH_H, corner_radius=30)
    }
    hole notch {
        n = RoundedRectangle(center=(0, H), width=260, height=2 * NOTCH_D, corner_radius=20)
    }
    # the tabs stand on the horns' tops; the ring's thickness is cut down from the top
    left_tab = tab_and_slot(part="tab", length=40, thickness=T, tabs=1, tab=20 mm, screw=0,
                            cx=-TAB_R, cy=H)
    right_tab = tab_and_slot(part="tab", length=40, thickness=T, tabs=1, tab=20 mm, screw=0,
                             cx=TAB_R, cy=H)
    if from_top {
        halving = cross_halving(depth=H - NOTCH_D - HALF, thickness=T, clearance=0.2 mm,
                                cx=0, cy=H - NOTCH_D)
    } else {
        halving = cross_halving(depth=HALF - ARCH_H, thickness=T, clearance=0.2 mm,
                                rotation=180 deg, cx=0, cy=ARCH_H)
    }
}

assembly washstand {
    leg_a = leg(from_top=false)
    leg_b = leg(from_top=true)

    solid ring {
        body = Circle(center=(0, 0), diameter=360)
        hole bowl { c = Circle(center=(0, 0), diameter=230) }
        a_slots_l = tab_and_slot(part="slot", length=40, thickness=T, tabs=1, tab=20 mm, screw=0,
                                 clearance=0.2 mm, cx=-TAB_R, cy=0)
        a_slots_r = tab_and_slot(part="slot", length=40, thickness=T, tabs=1, tab=20 mm, screw=0,
                                 clearance=0.2 mm, cx=TAB_R, cy=0)
        b_slots_l = tab_and_slot(part="slot", length=40, thickness=T, tabs=1, tab=20 mm, screw=0,
                                 clearance=0.2 mm, rotation=90 deg, cx=0, cy=-TAB_R)
        b_slots_r = tab_and_slot(part="slot", length=40, thickness=T, tabs=1, tab=20 mm, screw=0,
                                 clearance=0.2 mm, rotation=90 deg, cx=0, cy=TAB_R)
        drawing words {
            track = Circle(center=(0, 0), radius=(115 + 180) / 2, construction=true)
            camp = Text("CAMP", along=track, angle=135 deg, size=8, valign="middle")
            wash = Text("WASH", along=track, angle=315 deg, size=8, valign="middle", flip=true)
        }
    }

    # 3D: leg A across x, leg B across y, the ring on top, flush with the legs' tops
    Place(leg_a, rotation=(90 deg, 0, 0), position=(0, T / 2, 0))
    Place(leg_b, rotation=(90 deg, 0, 90 deg), position=(-T / 2, 0, 0))
    Place(ring, position=(0, 0, H - T))

    # the sheet
    RightOf(leg_b, leg_a, gap=5)
    RightOf(ring, leg_b, gap=5)

    # the request's numbers
    assert leg_a.body.height == 700 mm, "700 tall"
    assert leg_a.body.bottom_width == 440 mm and leg_a.body.top_width == 340 mm, "440 / 340"
    assert ring.body.diameter == 360 mm and ring.bowl.c.diameter == 230 mm, "ring 360, hole 230"
    assert leg_a.notch.n.bb.width == 260 mm, "notch 260 wide"
    assert leg_a.body.bb.top - leg_a.notch.n.bb.bottom == 120 mm, "notch 120 deep"
    # the halving slots meet: A's runs up to where B's runs down to
    assert abs(leg_a.halving.cut.bb.top - leg_b.halving.cut.bb.bottom) < 0.001 mm,
        "the halvings meet"
    assert ring.bowl.c.diameter > 220 mm, "the bowl drops through"
}
