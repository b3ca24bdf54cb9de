# A phone stand from two flat pieces of 3 mm material that slot together at
# right angles (cross-halving): a side profile with a ledge and a leaning back
# support, slotted from below, and a cross foot slotted from above.

param t = 3 mm            # material thickness = slot width
param foot_w = 80 mm
param foot_h = 40 mm
slot_depth = foot_h / 2   # each piece is slotted half way
fit = 0.1 mm              # a little play so the slots slide together

assembly phone_stand {
    solid side {
        profile = Polygon([(0, 0), (100, 0), (100, 6), (67, 100), (55, 100), (18, 14),
                           (8, 14), (8, 20), (0, 20)])
        hole slot {
            s = Rectangle(center=(60, slot_depth / 2), width=t + fit, height=slot_depth)
        }
        AlignBottom(slot, profile)
        HorizontalDistance(profile.points[0], slot.s.center, 60 mm)
    }

    solid foot {
        plate = RoundedRectangle(center=(0, 0), width=foot_w, height=foot_h,
                                 corner_radii=[4, 4, 0, 0])
        hole slot {
            s = Rectangle(center=(0, foot_h / 2 - slot_depth / 2), width=t + fit,
                          height=slot_depth)
        }
        AlignTop(slot, plate)
        AlignCenterX(slot, plate)
    }

    # lay the two pieces side by side
    RightOf(foot, side, gap=10)
    AlignBottom(foot, side)
}
