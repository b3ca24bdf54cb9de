# Request (garden): "A hand seed sower for sowing small seeds along a drill, 3 mm birch ply.
# A closed finger-jointed box 100 long x 50 wide x 50 tall outside (10 mm fingers). One end
# has a 6 mm outlet 14 mm below the end's centre and an M3 pivot hole at its centre. On it
# turns a 46 mm selector dial (3.4 mm pivot hole) with five seed holes of 1.5, 2, 2.5, 3.5
# and 5 mm on a 14 mm radius, 72 deg apart, each size engraved beside its hole (3 mm text at
# 19 mm radius), and 24 grip notches (3 mm round) round its rim. The lid has a 20 mm filling
# hole 22 mm from the lid's centre toward the far end, closed by a swivel cover: a 30 mm disc
# on an M3 screw 18 mm from the hole's centre (toward the middle), its arm ending in a 10 mm
# round end. 'SEED SOWER' engraved filled, bold, 8 mm high, centred on the front."

import "std/joints.aidl"

thickness 3 mm

sizes = [1.5 mm, 2 mm, 2.5 mm, 3.5 mm, 5 mm]
names = ["1.5", "2", "2.5", "3.5", "5"]
def feed_angle(i) = 180 deg + i * 72 deg

assembly sower {
    box = finger_box(length=100 mm, depth=50 mm, height=50 mm, thickness=3 mm, finger=10 mm)

    # the dial end: the left panel (its top edge at -x, its bottom edge at +x)
    hole end_holes {
        pivot = Circle(center=(0, 0), diameter=3.4)
        outlet = Circle(center=(14, 0), diameter=6)
    }
    At(end_holes.pivot.center, box.left.bb.center)
    CutInto(end_holes, box.left)

    # the filling hole and the cover's pivot in the lid
    hole lid_holes {
        fill = Circle(center=(0, 0), diameter=20)
        pivot = Circle(center=(-18, 0), diameter=3.4)
    }
    At(lid_holes.fill.center, box.lid.bb.center, dx=22)
    CutInto(lid_holes, box.lid)

    drawing label {
        t = Text("SEED SOWER", position=(0, 0), size=8, font="sans:Bold", valign="middle",
                 fill=true)
    }
    At(label.t.position, box.front.bb.center)
    CutInto(label, box.front)

    solid dial {
        disc = Circle(center=(0, 0), diameter=46)
        hole pivot { c = Circle(center=(0, 0), diameter=3.4) }
        hole feeds {
            for i in range(5) {
                c = Circle(center=(14 * cos(feed_angle(i)), 14 * sin(feed_angle(i))),
                           diameter=sizes[i])
            }
        }
        hole grip {
            for k in range(24) {
                n = Circle(center=(23 * cos(k * 15 deg), 23 * sin(k * 15 deg)), diameter=3)
            }
        }
        drawing sizes_text {
            for i in range(5) {
                t = Text(names[i], position=(19 * cos(feed_angle(i)), 19 * sin(feed_angle(i))),
                         size=3, valign="middle", rotation=feed_angle(i) - 90 deg)
            }
        }
    }

    solid cover {
        lid_disc = Circle(center=(0, 0), diameter=30)
        arm_end = Circle(center=(-18, 0), diameter=10)
        arm = Hull(lid_disc, arm_end)
        hole pivot { c = Circle(center=(-18, 0), diameter=3.4) }
    }

    # laid out flat to the right of the box's net
    RightOf(dial, box, gap=8)
    AlignCenterY(dial, box.bottom)
    Below(cover, dial, gap=8)
    AlignCenterX(cover, dial)

    # assembled: the dial on the outside of the left end (x = -50), the cover on the lid
    Place(dial, position=(-50, 0, 25), rotation=(0, -90 deg, 0))
    Place(cover, position=(22, 0, 50))

    # the request's numbers
    assert box.front.bb.width == 100 mm and box.front.bb.height == 50 mm, "100 long, 50 tall"
    assert box.left.bb.height == 50 mm, "50 wide"
    assert end_holes.outlet.diameter == 6 mm, "6 mm outlet"
    assert end_holes.outlet.center.x - box.left.bb.center_x == 14 mm, "outlet 14 below centre"
    assert dial.disc.diameter == 46 mm, "46 mm dial"
    assert len(dial.feeds.c) == 5, "five seed holes"
    assert dial.feeds.c[0].diameter == 1.5 mm and dial.feeds.c[4].diameter == 5 mm, "1.5 to 5 mm"
    assert abs(distance(dial.feeds.c[3].center, dial.disc.center) - 14 mm) < 0.001 mm, "on r 14"
    assert len(dial.grip.n) == 24, "24 grip notches"
    assert lid_holes.fill.diameter == 20 mm, "20 mm filling hole"
    assert lid_holes.fill.center.x - box.lid.bb.center_x == 22 mm, "22 mm off the lid's centre"
    assert distance(cover.pivot.c.center, cover.lid_disc.center) == 18 mm, "cover pivot 18 mm"
    assert cover.lid_disc.diameter == 30 mm, "30 mm cover"
}
