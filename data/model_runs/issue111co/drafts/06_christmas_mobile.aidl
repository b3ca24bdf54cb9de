# Request: a Christmas mobile for the kids' window: a curved top bar 200 mm from end
# to end and 14 mm wide, with a 2.5 mm hole in its middle to hang it and four more
# 2.5 mm holes along it for the threads; four ornaments about 60 mm tall, each with a
# round hanging loop (9 mm, 2.5 mm hole) at its top: a five-point star, a three-tier
# tree with four 4 mm bauble holes, a bell with "2026" engraved and a clapper, and a
# crescent moon hung from its balance point so it hangs level. 3 mm poplar ply.

units mm
thickness 3 mm

param bar_r = 200 mm, min = 150 mm, max = 300 mm     # the bar's curve
param eye_d = 2.5 mm, min = 2 mm, max = 4 mm

bar_span = 60 deg                 # 200 mm chord on a 200 mm radius
bar_cy = -170 mm
thread_a = [66 deg, 80 deg, 100 deg, 114 deg]
loop_r = 4.5 mm

assembly christmas_mobile {
    solid bar {
        arc = ArcSlot(center=(0, bar_cy), radius=bar_r, start_angle=90 deg - bar_span / 2,
                      end_angle=90 deg + bar_span / 2, width=14)
        hole hang {
            c = Circle(center=(0, bar_cy + bar_r), diameter=eye_d)
        }
        hole threads {
            for a in thread_a {
                c = Circle(center=(bar_r * cos(a), bar_cy + bar_r * sin(a)), diameter=eye_d)
            }
        }
    }

    solid star {
        s = Star(center=(0, 0), points=5, outer_radius=30, inner_radius=13, tip_radius=1.5)
        loop = Circle(center=(0, 29.5), radius=loop_r)
        hole eye { c = Circle(center=(0, 30.5), diameter=eye_d) }
    }

    solid tree {
        top = Triangle(center=(0, 20), base=36, height=22)
        mid = Triangle(center=(0, 6), base=48, height=26)
        low = Triangle(center=(0, -10), base=60, height=30)
        trunk = Rectangle(center=(0, -30), width=12, height=12)
        loop = Circle(center=(0, 33), radius=loop_r)
        hole eye { c = Circle(center=(0, 34), diameter=eye_d) }
        hole baubles {
            for p in [(-8, 14), (10, 0), (-11, -12), (6, -16)] {
                c = Circle(center=p, diameter=4)
            }
        }
    }

    solid bell {
        body = Hull(Circle(center=(0, 6), radius=13), Rectangle(center=(0, -16), width=44, height=4))
        clapper = Circle(center=(0, -20), radius=5)
        loop = Circle(center=(0, 21), radius=loop_r)
        hole eye { c = Circle(center=(0, 22), diameter=eye_d) }
        drawing year {
            y = Text("2026", position=(0, -4), size=7, valign="middle")
        }
    }

    solid moon {
        disc = Circle(center=(0, 0), radius=25)
        hole bite { c = Circle(center=(9, 0), radius=21) }
        # the loop over the crescent's balance point (about x = -11)
        loop = Circle(center=(27 * cos(115 deg), 27 * sin(115 deg)), radius=loop_r)
        hole eye { c = Circle(center=(27 * cos(115 deg), 27 * sin(115 deg)), diameter=eye_d) }
    }

    # on the sheet: the bar on top, the ornaments in a row under it
    Below(star, bar, gap=6)
    AlignLeft(star, bar)
    RightOf(tree, star, gap=6)
    AlignTop(tree, star)
    RightOf(bell, tree, gap=6)
    AlignTop(bell, tree)
    RightOf(moon, bell, gap=6)
    AlignTop(moon, bell)

    # the request's numbers
    assert abs(distance(bar.arc.start, bar.arc.end) - 200 mm) < 0.01 mm, "bar 200 mm end to end"
    assert bar.arc.width == 14 mm, "bar 14 mm wide"
    assert len(bar.threads.c) == 4, "four thread holes"
    for o in [star, tree, bell, moon] {
        assert o.bb.height >= 50 mm and o.bb.height <= 75 mm, "ornaments about 60 mm tall"
    }
    assert star.loop.radius * 2 == 9 mm and star.eye.c.diameter == 2.5 mm, "9 mm loops, 2.5 mm holes"
    assert len(tree.baubles.c) == 4 and tree.baubles.c[0].diameter == 4 mm, "four 4 mm baubles"
}
