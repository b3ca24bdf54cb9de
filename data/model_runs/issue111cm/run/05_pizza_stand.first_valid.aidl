# Request: a raised pizza stand for a party buffet, from 6 mm birch plywood, that packs flat
# after the party. A round top 280 mm across standing 150 mm above the table on two
# trapezoid legs (240 mm wide at the foot, 200 mm at the top) slotted halfway into each
# other crosswise (0.2 mm clearance). Each leg has two 20 mm tabs on its top edge that press
# into mortises in the top (0.2 mm clearance), no glue. Each leg has two pizza-slice windows
# (45 mm slices, 60 deg wide, tip down). The top's rim is engraved "BUON APPETITO" over the
# top and "PIZZA PARTY" under the bottom, serif letters 8 mm, filled, baseline 125 mm from
# the centre.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
top_d = 280 mm
stand_h = 150 mm
leg_h = stand_h          # the leg's height to its tab tips, flush with the top's face
foot_w = 240 mm
leg_top_w = 200 mm
fit = 0.2 mm
under = leg_h - t        # leg height under the top
half = under / 2         # each halving slot runs half of it

def leg(from_top=true) -> solid {
    body = Trapezoid(center=(0, 0), bottom_width=foot_w, top_width=leg_top_w, height=leg_h)
    tabs = tab_and_slot(part="tab", length=leg_top_w, thickness=t, tabs=2, tab=20 mm,
                        screw=0, cx=0 mm, cy=leg_h / 2)
    if from_top {
        # from the top edge between the tabs (cut t down by the tab joint) to mid-height
        halving = cross_halving(depth=half, thickness=t, clearance=fit, cx=0 mm,
                                cy=leg_h / 2 - t)
    } else {
        halving = cross_halving(depth=half, thickness=t, clearance=fit, rotation=180 deg,
                                cx=0 mm, cy=-leg_h / 2)
    }
    for side in [-1, 1] {
        hole window {
            slice = Sector(center=(side * 55 mm, -30 mm), radius=45 mm, start_angle=60 deg,
                           end_angle=120 deg)
        }
    }
}

assembly pizza_stand {
    solid top {
        disc = Circle(center=(0, 0), diameter=top_d)
        mortise_a = tab_and_slot(part="slot", length=leg_top_w, thickness=t, tabs=2,
                                 tab=20 mm, screw=0, clearance=fit, cx=0 mm, cy=0 mm)
        mortise_b = tab_and_slot(part="slot", length=leg_top_w, thickness=t, tabs=2,
                                 tab=20 mm, screw=0, clearance=fit, rotation=90 deg,
                                 cx=0 mm, cy=0 mm)
        drawing rim {
            track = Circle(center=(0, 0), radius=125 mm, construction=true)
            over = Text("BUON APPETITO", along=track, size=8 mm, font="serif", fill=true)
            under_text = Text("PIZZA PARTY", along=track, size=8 mm, font="serif", fill=true,
                              flip=true)
        }
    }
    Place(top, position=(0, 0, stand_h - t), face="up")

    leg_a = leg(from_top=true)
    leg_b = leg(from_top=false)
    leg_a.bb.center == (-130, -240)
    leg_b.bb.center == (130, -240)
    # leg a in the x-z plane, leg b in the y-z plane, their feet on the table
    Place(leg_a, position=(0, t / 2, leg_h / 2), face="front", up="up")
    Place(leg_b, position=(-t / 2, 0, leg_h / 2), face="right", up="up")

    assert top.disc.diameter == 280 mm, "280 mm top"
    assert (leg_a.body.height - t) + t == 150 mm, "top 150 mm above the table"
    assert leg_a.body.bottom_width == 240 mm and leg_a.body.top_width == 200 mm,
        "legs 240 at the foot, 200 at the top"
    assert leg_a.halving.depth + leg_b.halving.depth == leg_h - t,
        "the two halvings fill the leg's height under the top"
    assert len(leg_a.window) == 2 and len(leg_b.window) == 2, "two windows a leg"
}
