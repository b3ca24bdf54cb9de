# Bathroom: one side panel (cut two) of a three-tier nail-polish rack, 6 mm birch ply.
# Stepped profile 120 mm deep x 150 mm tall: three steps, each 40 mm deep and 50 mm tall,
# rising toward the back (x = 0 is the back edge, on the wall). Outer corners of the profile R3.
# Each step holds its shelf board by a mortise 30 x 6.2 mm (for 6 mm ply tabs), centred on the
# step's depth, its top 8 mm below the step's top edge. Engraved on the top step: "3" "2" "1"
# tier numbers, 6 mm strokes, 10 mm below each mortise.
thickness 6 mm

param step_d = 40 mm, min = 30, max = 60
param step_h = 50 mm, min = 35, max = 70
param slot_w = 30 mm, min = 20, max = 36
param ply = 6.2 mm, min = 3, max = 12

solid side {
    profile = Polygon([(0, 0), (3 * step_d, 0), (3 * step_d, step_h), (2 * step_d, step_h),
                       (2 * step_d, 2 * step_h), (step_d, 2 * step_h), (step_d, 3 * step_h),
                       (0, 3 * step_h)])
    Fillet(profile, 3)

    hole mortise {
        for i in range(3) {
            m = Rectangle(center=(step_d / 2 + i * step_d, (3 - i) * step_h - 8 - ply / 2),
                          width=slot_w, height=ply)
        }
    }
    drawing tiers {
        for i in range(3) {
            t = Text(str(3 - i), (step_d / 2 + i * step_d, (3 - i) * step_h - 8 - ply - 10 - 6),
                     size=6)
        }
    }

    assert profile.bb.width == 120 mm, "120 mm deep"
    assert profile.bb.height == 150 mm, "150 mm tall"
    assert len(mortise.m) == 3, "three mortises"
    assert mortise.m[0].width == 30 mm and mortise.m[0].height == 6.2 mm, "mortise 30 x 6.2"
    assert profile.bb.top - mortise.m[0].bb.top == 8 mm, "mortise top 8 mm below the step's top"
    assert mortise.m[1].center.x - mortise.m[0].center.x == 40 mm, "steps 40 mm deep"
    assert mortise.m[0].center.y - mortise.m[1].center.y == 50 mm, "steps 50 mm tall"
}
