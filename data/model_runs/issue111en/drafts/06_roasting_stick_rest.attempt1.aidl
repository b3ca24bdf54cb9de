# Request: a flat-pack rest for campfire roasting sticks, laser cut from 3 mm stainless steel.
# Two A-frame legs, 160 mm wide at the ground and 40 mm wide at the top, 120 mm tall above
# the ground, each foot ending in a 25 mm ground spike (16 mm wide at its root, on the outer
# edge of the foot), an R50 arch cut between the feet, and "S'MORES" cut through each leg as
# stencil letters 9 mm tall, their middle 62 mm above the ground. A crossbar 300 x 40 mm with
# R5 corners and five V notches in its top edge (20 mm wide, 15 mm deep) on a 50 mm pitch,
# centred. The bar and legs cross-halve: each leg slotted 20 mm down from the middle of its
# top, the bar slotted 20 mm up from its bottom edge 30 mm in from each end.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
LEG_H = 120 mm
BAR_L = 300 mm
BAR_H = 40 mm
PITCH = 50 mm
V_W = 20 mm
V_D = 15 mm

def leg() -> solid {
    body = Polygon([(0, 120), (20, 120), (80, 0), (74, -25), (64, 0), (0, 0)], mirror="y")
    hole arch { c = Circle(center=(0, 0), radius=50, overrun=true) }
    top_slot = cross_halving(depth=20 mm, thickness=T, cx=0 mm, cy=120 mm)
    hole word {
        t = Text("S'MORES", position=(0, 62), size=9, font="sans:Bold", valign="middle",
                 stencil=true)
    }
    assert body.bb.top - body.points[3].y == 120 mm, "120 tall above the ground"
    assert body.points[3].x - body.points[8].x == 160 mm, "160 wide at the ground"
    assert body.points[1].x - body.points[10].x == 40 mm, "40 wide at the top"
    assert body.points[3].y - body.bb.bottom == 25 mm, "25 mm spikes"
}

assembly stick_rest {
    solid bar {
        body = RoundedRectangle(center=(0, 0), width=BAR_L, height=BAR_H, corner_radius=5)
        hole vees {
            for i in range(5) {
                v = Polygon([((i - 2) * PITCH - V_W / 2 * (V_D + 2) / V_D, BAR_H / 2 + 2),
                             ((i - 2) * PITCH + V_W / 2 * (V_D + 2) / V_D, BAR_H / 2 + 2),
                             ((i - 2) * PITCH, BAR_H / 2 - V_D)], overrun=true)
            }
        }
        left_slot = cross_halving(depth=20 mm, thickness=T, rotation=180 deg,
                                  cx=-BAR_L / 2 + 30 mm, cy=-BAR_H / 2)
        right_slot = cross_halving(depth=20 mm, thickness=T, rotation=180 deg,
                                   cx=BAR_L / 2 - 30 mm, cy=-BAR_H / 2)
        assert len(vees.v) == 5, "five notches"
        assert vees.v[1].points[2].x - vees.v[0].points[2].x == 50 mm, "50 pitch"
        assert body.bb.top - vees.v[0].points[2].y == 15 mm, "15 deep"
        assert body.width == 300 mm and body.height == 40 mm
    }
    left_leg = leg()
    right_leg = leg()

    Below(left_leg, bar, gap=10)
    AlignLeft(left_leg, bar)
    RightOf(right_leg, left_leg, gap=10)
    AlignTop(right_leg, left_leg)

    # 3D: the bar along x in the plane y = 0, the legs across it at x = +-120, ground z = 0
    Place(bar, position=(0, T / 2, LEG_H), face="front", up="up")
    Place(left_leg, position=(-BAR_L / 2 + 30 mm - T / 2, 0, 0), face="right", up="up")
    Place(right_leg, position=(BAR_L / 2 - 30 mm - T / 2, 0, 0), face="right", up="up")
}
