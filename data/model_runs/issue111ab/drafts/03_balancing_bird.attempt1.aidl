# Request (toys): a balancing bird, 3 mm ply. A flat bird seen from above, 260 mm across the
# wings, that balances level on its beak tip: the beak tip at the front on the centre line,
# the wings swept forward so their tips lie 48 mm ahead of the beak; a forked tail 110 mm
# behind the beak. Smooth outline (a spline), sharp at the beak, the wing tips and the tail.
# Engraved: two eyes (3 mm circles 4 mm either side of the centre line, 14 mm behind the
# beak) and a 16.25 mm ring on each wing (where a 1-cent coin is glued to tune the balance).
# A stand: a post 24 wide x 140 tall tapering over its top 30 mm to a 3 mm flat the beak
# sits on, "BALANCING BIRD" engraved up the post (5 mm letters); a foot 100 x 40 (top
# corners R4). Post and foot cross-halve: 20 mm slots, 3 mm + 0.1 clearance.

units mm
thickness 3 mm
kerf 0.15 mm

import "std/joints.aidl"

coin_d = 16.25 mm
post_w = 24 mm
post_h = 140 mm
foot_w = 100 mm
foot_h = 40 mm
halving = 20 mm

assembly toy {
    solid bird {
        half = [(0, 0), (6, -8), (9, -18), (14, -28), (55, -30), (100, -12), (125, 20),
                (130, 48), (112, 46), (92, 22), (66, -4), (40, -34), (22, -55), (14, -80),
                (28, -110), (0, -100)]
        body = Spline(mirror(half, about="y"), closed=true, corners=[0, 7, 23, 14, 16, 15])
        drawing marks {
            eye_r = Circle(center=(4, -14), diameter=3)
            eye_l = Circle(center=(-4, -14), diameter=3)
            coin_r = Circle(center=(110, 25), diameter=coin_d)
            coin_l = Circle(center=(-110, 25), diameter=coin_d)
        }
        assert body.points[7].y - body.points[0].y == 48 mm, "wing tips 48 ahead of the beak"
        assert body.points[0].y - body.points[15].y == 100 mm, "tail notch behind the beak"
        assert abs(body.bb.width - 260 mm) < 3 mm, "about 260 across the wings"
        assert abs(body.points[0].y - body.bb.bottom - 110 mm) < 1 mm, "tail 110 behind the beak"
    }

    solid post {
        shape = Polygon([(-post_w / 2, 0), (post_w / 2, 0), (post_w / 2, post_h - 30 mm),
                         (1.5, post_h), (-1.5, post_h), (-post_w / 2, post_h - 30 mm)])
        slot = cross_halving(depth=halving, thickness=3 mm, clearance=0.1 mm,
                             rotation=180 deg, cx=0 mm, cy=0 mm)
        drawing label {
            t = Text("BALANCING BIRD", position=(0, 65), size=5, rotation=90 deg,
                     valign="middle")
        }
        assert label.bb.bottom > slot.cut.bb.top + 3 mm, "label clear of the slot"
        assert label.bb.top < post_h - 30 mm, "label below the taper"
        assert abs(shape.bb.height - 140 mm) < 0.01, "post 140 tall"
    }

    solid foot {
        body = RoundedRectangle(center=(0, 0), width=foot_w, height=foot_h,
                                corner_radii=[4, 4, 0, 0])
        slot = cross_halving(depth=halving, thickness=3 mm, clearance=0.1 mm,
                             cx=0 mm, cy=foot_h / 2)
    }

    RightOf(post, bird, gap=10)
    RightOf(foot, post, gap=10)
    AlignBottom(post, bird)
    AlignBottom(foot, bird)

    assert post.slot.cut.bb.height + foot.slot.cut.bb.height == 40 mm, "halvings add to the foot"
    assert abs(foot.body.bb.width - 100 mm) < 0.01 and abs(foot.body.bb.height - 40 mm) < 0.01, "foot 100 x 40"
}
