# Request (garden): a hanging-basket wall bracket cut from 9 mm exterior ply. A wall post 40 mm
# wide and 200 mm tall; an arm 260 mm long (from the wall face) and 35 mm tall along the top of
# the post; between them a brace whose lower edge is a 140 mm radius concave curve running from
# the post to the arm. A U-notch 8 mm wide and 12 mm deep in the arm's top edge, centred 20 mm
# from the arm's end, for the basket's chain hook. A 20 mm round lightening hole in the brace,
# 31 mm (along the diagonal) from the inside corner. Three countersunk screw holes for M4 screws
# (9 mm heads) down the post's middle, at 17, 110 and 185 mm below the top. The arm's end and
# the post's bottom rounded R10. An engraved vine with leaves along the arm.

import "std/fasteners.aidl"

units mm
thickness 9 mm

post_w = 40 mm
post_h = 200 mm
arm_l = 260 mm
arm_h = 35 mm
cove_r = 140 mm
notch_w = 8 mm
notch_d = 12 mm
notch_from_end = 20 mm
screw_depths = [17 mm, 110 mm, 185 mm]

solid bracket {
    # the wall face is x = 0, the top edge y = 0
    post = Rectangle(bottom_left=(0, -post_h), width=post_w, height=post_h)
    arm = Rectangle(bottom_left=(0, -arm_h), width=arm_l, height=arm_h)

    # the brace: a square in the inside corner less a circle touching the post and the arm
    solid brace {
        sq = Rectangle(bottom_left=(post_w, -arm_h - cove_r), width=cove_r, height=cove_r)
        hole cove {
            c = Circle(center=(post_w + cove_r, -arm_h - cove_r), radius=cove_r)
        }
        hole lighten {
            c = Circle(center=(post_w + 31 mm * cos(45 deg), -arm_h - 31 mm * sin(45 deg)),
                       diameter=20)
        }
    }

    hole hook {
        r = Rectangle(center=(arm_l - notch_from_end, -(notch_d - notch_w / 2) / 2 + 1),
                      width=notch_w, height=notch_d - notch_w / 2 + 2, overrun=true)
        c = Circle(center=(arm_l - notch_from_end, -(notch_d - notch_w / 2)), diameter=notch_w)
    }

    for i in range(len(screw_depths)) {
        screws = clearance_hole(size=4, fit="medium", cx=post_w / 2, cy=-screw_depths[i])
    }
    Countersink(screws, diameter=9 mm)

    drawing vine {
        stem = Spline([(60 + 20 * k, -arm_h / 2 + (5 if k % 2 == 0 else -5)) for k in range(9)])
        # FIX after the first valid program: the leaves floated off the stem; each now grows
        # from a crest or trough of the stem, its base on the curve
        for k in range(1, 8) {
            leaf = Ellipse(center=(60 + 20 * k + 5 * cos(50 deg),
                                   -arm_h / 2 + (5 + 5 * sin(50 deg) if k % 2 == 0 else -5 - 5 * sin(50 deg))),
                           rx=5, ry=2.5, rotation=(50 deg if k % 2 == 0 else -50 deg))
        }
    }

    # FIX after the first valid program: W0406, the notch leaves room for R8 at the arm's top corner
    Fillet(at=[arm.bottom_right, post.bottom_left, post.bottom_right], radius=10)
    Fillet(arm.top_right, 8)

    # the request's own numbers
    assert arm.bb.width == 260 mm and arm.bb.height == 35 mm, "arm 260 x 35"
    assert post.bb.width == 40 mm and post.bb.height == 200 mm, "post 40 x 200"
    assert len(screws) == 3, "three screws"
    assert abs(arm.bb.right - hook.c.center.x - 20 mm) < 0.01, "notch 20 from the end"
    assert abs(arm.bb.top - (hook.c.center.y - notch_w / 2) - 12 mm) < 0.01, "notch 12 deep"
    assert abs(screws[2].c.center.y - (-185 mm)) < 0.01, "lowest screw 185 below the top"
    assert vine.bb.top < arm.bb.top - 2 and vine.bb.bottom > arm.bb.bottom + 2, "vine on the arm"
    assert vine.bb.right < hook.bb.left - 5, "vine clear of the notch"
}
