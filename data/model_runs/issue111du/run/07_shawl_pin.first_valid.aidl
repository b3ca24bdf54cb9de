# Request (crafts): a shawl pin for a knitted shawl, cut from 3 mm acrylic. The slide is a leaf:
# the lens where two R46.8 circles 48.6 mm apart overlap, 80 mm long and 45 mm wide, its tips
# rounded R4; two 8 mm holes on its long axis, 40 mm apart; a midrib and three pairs of veins
# engraved between the holes. The stick is 6 mm wide and 120 mm long from its rounded point
# (R1.5) to the top of the shaft, with a six-petal flower knob on top (R9 tips rounded R2, R6
# notches) that cannot pass through an 8 mm hole. The shaft's 6 x 3 mm section must pass the
# 8 mm holes.

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 4 mm
leaf_r = 46.8 mm
leaf_d = 48.6 mm
hole_d = 8 mm
hole_pitch = 40 mm
stick_w = 6 mm
stick_len = 120 mm

assembly shawl_pin {
    solid slide {
        leaf = Intersect(Circle(center=(0, leaf_d / 2), radius=leaf_r),
                         Circle(center=(0, -leaf_d / 2), radius=leaf_r))
        Fillet(4)
        hole eye_l { c = Circle(center=(-hole_pitch / 2, 0), diameter=hole_d) }
        hole eye_r { c = Circle(center=(hole_pitch / 2, 0), diameter=hole_d) }
        drawing veins {
            rib = Line((-12, 0), (12, 0))
            for i in range(3) {
                up = Line((-8 + 8 * i, 0), (-2 + 8 * i, 8))
                down = Line((-8 + 8 * i, 0), (-2 + 8 * i, -8))
            }
        }
    }

    solid stick {
        shaft = Rectangle(bottom_left=(-stick_w / 2, 15), width=stick_w, height=stick_len - 15)
        point = Hull(Circle(center=(0, 1.5), radius=1.5),
                     Rectangle(center=(0, 17), width=stick_w, height=4))
        knob = Star(center=(0, stick_len + 6), points=6, outer_radius=9, inner_radius=6,
                    tip_radius=2)
    }

    RightOf(stick, slide, gap=10)
    AlignBottom(stick, slide)

    # assembled: the stick lies along the slide over both holes
    Place(slide, position=(0, 0, 0))
    Place(stick, position=(-65, 0, t), rotation=(0, 0, -90 deg))

    assert slide.bb.height == 45 mm, "leaf 45 mm wide"
    assert slide.bb.width <= 80 mm and slide.bb.width >= 74 mm, "leaf about 80 long, tips rounded"
    assert slide.eye_r.c.center.x - slide.eye_l.c.center.x == 40 mm, "holes 40 mm apart"
    assert stick.shaft.bb.top - stick.point.bb.bottom == 120 mm, "stick 120 mm to the shaft's top"
    assert stick.knob.bb.bottom < stick.shaft.bb.top, "the knob overlaps the shaft (one piece)"
    assert sqrt(stick_w ** 2 + t ** 2) < hole_d, "the shaft passes the holes"
    assert 2 * stick.knob.inner_radius > hole_d, "the knob does not pass a hole"
}
