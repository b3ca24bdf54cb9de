# Request (kitchen): a display stand for a decorative plate up to 27 cm across, in 4 mm plywood:
# two identical side legs and one cross rail that slot together with cross halvings. Each leg
# (seen from the side) stands 150 mm tall on a 120 mm long foot; its front edge leans back at
# 75 degrees from the ground, and at its foot a groove 12 mm wide and 12 mm deep holds the
# plate's rim behind a 6 mm thick lip. The leg's two top corners are rounded 3 mm. The rail is
# 160 mm wide x 40 mm tall with 8 mm rounded top corners and an arch cut 110 mm wide x 15 mm high
# in its bottom edge, leaving two feet. The legs cross the rail 100 mm apart, 32 mm behind the
# leg's front, each halving taking half of the rail's height (20 mm).

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
leg_h = 150 mm
foot = 120 mm
lean = 75 deg
lip = 6 mm
groove_w = 12 mm
groove_d = 12 mm
lean_start = 20 mm                 # the leaning edge starts this high, just above the groove
rail_w = 160 mm
rail_h = 40 mm
leg_pitch = 100 mm
cross_at = 32 mm                   # the rail's middle, behind the leg's front

def leg() -> solid {
    # side profile: x runs back from the front of the lip, y up from the ground
    p = Polygon([(0, 0), (foot, 0), (foot, 10),
                 (lip + groove_w + (leg_h - lean_start) / tan(lean) + 10, leg_h),
                 (lip + groove_w + (leg_h - lean_start) / tan(lean), leg_h),
                 (lip + groove_w, lean_start),
                 (lip + groove_w, lip + groove_d - groove_d),
                 (lip, lip + groove_d - groove_d),
                 (lip, lip + groove_d),
                 (0, lip + groove_d)])
    Fillet([p.points[3], p.points[4]], 3)
    # the halving runs up from the foot
    h = cross_halving(depth=rail_h / 2, thickness=t, rotation=180 deg, cx=cross_at, cy=0 mm)
}

assembly plate_stand {
    left_leg = leg()
    right_leg = leg()

    solid rail {
        body = RoundedRectangle(center=(0, rail_h / 2), width=rail_w, height=rail_h,
                                corner_radii=[8, 8, 0, 0])
        hole arch {
            a = Arc(start=(-55, 0), through=(0, 15), end=(55, 0))
            base = Line((55, 0), (-55, 0))
        }
        h1 = cross_halving(depth=rail_h / 2, thickness=t, cx=-leg_pitch / 2, cy=rail_h)
        h2 = cross_halving(depth=rail_h / 2, thickness=t, cx=leg_pitch / 2, cy=rail_h)
    }

    RightOf(right_leg, left_leg, gap=10)
    AlignBottom(right_leg, left_leg)
    Above(rail, left_leg, gap=10)
    AlignLeft(rail, left_leg)

    # the request's numbers
    assert left_leg.p.bb.height == 150 mm, "leg 150 mm tall"
    assert left_leg.p.bb.width == 120 mm, "foot 120 mm long"
    assert abs(atan2(left_leg.p.points[4].y - left_leg.p.points[5].y,
                     left_leg.p.points[4].x - left_leg.p.points[5].x) - 75 deg) < 0.01 deg,
        "front edge leans at 75 degrees"
    assert left_leg.p.points[6].x - left_leg.p.points[7].x == 12 mm, "groove 12 mm wide"
    assert left_leg.p.points[8].y - left_leg.p.points[7].y == 12 mm, "groove 12 mm deep"
    assert left_leg.p.points[7].x - left_leg.p.points[0].x == 6 mm, "lip 6 mm thick"
    assert rail.body.bb.width == 160 mm and rail.body.bb.height == 40 mm, "rail 160 x 40"
    assert rail.arch.bb.width == 110 mm and rail.arch.bb.height == 15 mm, "arch 110 x 15"
    assert rail.h2.cut.bb.center_x - rail.h1.cut.bb.center_x == 100 mm, "legs 100 mm apart"
    assert left_leg.h.cut.bb.center_x - left_leg.p.bb.left == 32 mm, "rail 32 mm behind the front"
    assert rail.h1.cut.bb.height + left_leg.h.cut.bb.height == 40 mm, "halvings meet"
}
