# Request (sport): a pair of ski-waxing cradles, 6 mm ply, that hold a ski base-up on the
# bench. Each cradle is an upright and a foot cross-halved into a + (25 + 25 mm). Upright:
# a trapezoid 200 mm at the bottom, 160 at the top, 140 tall, top corners R10; a notch
# 110 wide x 20 deep in the middle of the top (R4 in its bottom corners) that the ski sits
# in; an 80 x 25 hand slot under it; "TIP" on one and "TAIL" on the other, engraved filled
# 14 mm tall; a 100 x 5 relief in the middle of the bottom edge so it stands on two pads.
# Foot: 200 x 50 with top corners R8 and the same 100 x 5 relief. Four parts; the cradles
# stand 900 mm apart.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
up_bottom = 200 mm
up_top = 160 mm
up_h = 140 mm
foot_l = 200 mm
foot_h = 50 mm
notch_w = 110 mm
notch_d = 20 mm

def cradle(name) -> assembly {
    solid upright {
        body = Trapezoid(center=(0, up_h / 2), bottom_width=up_bottom, top_width=up_top,
                         height=up_h)
        Fillet(body.top_left, 10)
        Fillet(body.top_right, 10)
        hole notch {
            n = RoundedRectangle(center=(0, up_h), width=notch_w, height=2 * notch_d,
                                 corner_radius=4)
        }
        hole hand {
            s = Slot(center=(0, 95), length=80, width=25)
        }
        hole relief {
            r = Rectangle(center=(0, 0), width=100, height=10)
        }
        halving = cross_halving(depth=25, thickness=t, clearance=0.2, rotation=180 deg, cx=0,
                                cy=0)
        drawing label {
            word = Text(name, (0, 55), size=14, font="sans:Bold", fill=true, valign="middle")
        }
    }
    solid foot {
        body = RoundedRectangle(center=(0, foot_h / 2), width=foot_l, height=foot_h,
                                corner_radii=[8, 8, 0, 0])
        hole relief {
            r = Rectangle(center=(0, 0), width=100, height=10)
        }
        halving = cross_halving(depth=25, thickness=t, clearance=0.2, cx=0, cy=foot_h)
    }
    # 3D: the upright across the ski (x-z plane), the foot along it (y-z plane)
    Place(upright, position=(0, t / 2, 0), face="front", up="up")
    Place(foot, position=(-t / 2, 0, 0), face="right", up="up")
    RightOf(foot, upright, gap=5)
}

assembly cradles {
    tip = cradle("TIP")
    tail = cradle("TAIL")
    Place(tip, position=(0, 0, 0))
    Place(tail, position=(0, 900, 0))
    Below(tail, tip, gap=5)

    assert tip.upright.body.bb.width == 200 mm and tip.upright.body.bb.height == 140 mm,
        "upright 200 wide, 140 tall"
    assert tip.upright.notch.n.width == 110 mm, "notch 110 wide"
    assert tip.upright.body.bb.top - tip.upright.notch.bb.bottom == 20 mm, "notch 20 deep"
    assert tip.foot.body.bb.width == 200 mm and tip.foot.body.bb.height == 50 mm, "foot 200 x 50"
    assert tip.upright.halving.depth + tip.foot.halving.depth == foot_h, "halving 25 + 25"
}
