# Request (parties): a masquerade mask on a stick for a New Year's Eve ball.
# - Mask from 1.5 mm birch ply, 170 mm across from tip to tip, symmetric: a pointed crest
#   rising to 55 mm above the eye line at the centre, brow bumps, side tips at 12 mm up where
#   the ribbons tie, cheeks down to 30 mm below the eye line and a rounded nose arch rising to
#   8 mm below it at the centre.
# - Almond eye openings 32 mm wide, 62 mm apart centre to centre (adult eye spacing), pointed
#   at both ends; over each eye an arc of 5 filigree holes 3.5 mm on a 21 mm radius from the
#   eye's centre, 45 to 135 deg.
# - 4 mm ribbon holes 8 mm in from each side tip; an engraved swirl on each cheek.
# - Handle: a separate 280 x 12 mm stick of 3 mm ply with rounded ends, glued behind the
#   mask's right cheek.

units mm

half = [(0, 55), (10, 38), (30, 42), (55, 38), (75, 28), (85, 12), (80, -5), (60, -22),
        (35, -30), (14, -20), (0, -8)]

assembly masquerade {
    solid mask {
        thickness 1.5 mm
        outline = Spline(mirror(half, about="y"), closed=true, corners=[0, 5, 15])
        axis = Line((0, -40), (0, 70), construction=true)

        hole right_eye {
            eye = Spline([(15, 3), (30, 14), (47, 9), (31, -4)], closed=true, corners=[0, 2])
            for i in range(5) {
                dot = Circle(center=polar((31, 4), 21, (45 + i * 22.5) * 1 deg), diameter=3.5)
            }
        }
        left_eye = Mirrored(right_eye, axis)

        hole right_ribbon { c = Circle(center=(77, 12), diameter=4) }
        left_ribbon = Mirrored(right_ribbon, axis)

        drawing right_swirl {
            s = Spline([(40, -12), (52, -14), (62, -8), (58, -2), (53, -6)])
        }
        left_swirl = Mirrored(right_swirl, axis)
    }

    solid stick {
        thickness 3 mm
        bar = RoundedRectangle(center=(0, 0), width=280, height=12, corner_radius=6)
    }
    Fixed(mask)
    Below(stick, mask, gap=10)
    AlignCenterX(stick, mask)

    # the request's numbers
    assert mask.outline.points[5].x - mask.outline.points[15].x == 170 mm, "170 tip to tip"
    assert mask.outline.points[0].y == 55 mm, "crest 55 above the eye line"
    assert (mask.right_eye.eye.points[2].x - mask.right_eye.eye.points[0].x == 32 mm),
        "eyes 32 wide"
    assert ((mask.right_eye.eye.points[0].x + mask.right_eye.eye.points[2].x) / 2 -
            (mask.left_eye.eye.points[0].x + mask.left_eye.eye.points[2].x) / 2 == 62 mm),
        "eyes 62 apart"
    assert len(mask.right_eye.dot) == 5, "5 filigree holes per eye"
    assert mask.outline.points[5].x - mask.right_ribbon.c.center.x == 8 mm, "ribbon 8 in"
    assert stick.bar.bb.width == 280 mm and stick.bar.bb.height == 12 mm, "stick 280 x 12"
}
