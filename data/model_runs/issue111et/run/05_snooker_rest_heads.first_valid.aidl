# Request: two replacement heads for snooker rests (the originals' brass heads broke), cut
# from 6 mm clear cast acrylic; each is riveted into the slotted ferrule of its stick
# through two 4 mm holes on the stem's centre line, 35 mm and 48 mm below the head's centre.
# - Cross rest ("X"): two bars 100 mm long tip to tip and 14 mm wide with round ends,
#   crossing at the head's centre, the two upper arms 80 degrees apart (each 40 degrees off
#   vertical); a round cue seat of R6.5 cut into the bottom of the upper V, its centre 16 mm
#   above the head's centre; a stem 20 mm wide running 55 mm down from the centre.
# - Spider: an arch, a ring segment of outer radius 60 mm and inner radius 42 mm from 15 to
#   165 degrees, on a 20 mm wide web that runs from the arch's top down to 50 mm below the
#   arch's centre (the stem); three V notches in the arch's top edge for the cue at 60, 90
#   and 120 degrees, each 8 mm deep and 16 degrees wide at its mouth (opening to 63 mm).
# Every corner of both outlines rounded R3 (felt-free acrylic, no sharp corner to scratch
# the cloth).

units mm
thickness 6 mm
kerf 0.15 mm

stem_w = 20 mm

def v_notch(a) = [(52 * cos(a), 52 * sin(a)), (63 * cos(a - 8 deg), 63 * sin(a - 8 deg)),
                  (63 * cos(a + 8 deg), 63 * sin(a + 8 deg))]

assembly rest_heads {
    solid cross_head {
        arm1 = Slot(center=(0, 0), length=100, width=14, rotation=50 deg)
        arm2 = Slot(center=(0, 0), length=100, width=14, rotation=130 deg)
        stem = Rectangle(bottom_left=(-stem_w / 2, -55), width=stem_w, height=55)
        hole seat { c = Circle(center=(0, 16), radius=6.5) }
        hole rivets {
            for i in range(2) { c = Circle(center=(0, -35 - 13 * i), diameter=4) }
        }
        Fixed(stem)
        Fillet(3)
    }

    solid spider_head {
        arch = Sector(center=(0, 0), radius=60, start_angle=15 deg, end_angle=165 deg,
                      inner_radius=42)
        web = Rectangle(bottom_left=(-stem_w / 2, -50), width=stem_w, height=50 + 43)
        hole notches {
            for a in [60 deg, 90 deg, 120 deg] {
                v = Polygon(v_notch(a))
            }
        }
        hole rivets {
            for i in range(2) { c = Circle(center=(0, -35 - 13 * i), diameter=4) }
        }
        Fixed(arch)
        Fillet(3)
    }

    RightOf(spider_head, cross_head, gap=10)
    AlignBottom(spider_head, cross_head)

    assert cross_head.arm1.length == 100 mm and cross_head.arm1.width == 14 mm
    assert abs(cross_head.arm2.spine.angle - cross_head.arm1.spine.angle) == 80 deg, "upper arms 80 deg apart"
    assert cross_head.seat.c.radius == 6.5 mm
    assert cross_head.seat.c.center.y - cross_head.arm1.center.y == 16 mm
    assert cross_head.stem.width == 20 mm and cross_head.stem.height == 55 mm
    assert cross_head.rivets.c[0].center.y - cross_head.arm1.center.y == -35 mm
    assert cross_head.rivets.c[1].center.y - cross_head.arm1.center.y == -48 mm
    assert cross_head.rivets.c[0].diameter == 4 mm
    assert spider_head.arch.radius == 60 mm and spider_head.arch.inner_radius == 42 mm
    assert spider_head.web.bb.bottom - spider_head.arch.center.y == -50 mm
    assert spider_head.rivets.c[1].center.y - spider_head.arch.center.y == -48 mm
    assert len(spider_head.notches.v) == 3
    assert distance(spider_head.notches, spider_head.rivets) > 20 mm
}
