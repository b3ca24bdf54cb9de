# Request (office): a pendulum letter scale for letters up to 100 g, 6 mm birch ply.
# Three parts. (1) Stand: a plate 170 wide x 190 tall, corners R8, with a 4.2 mm pivot hole
# (M4 bolt) 30 mm below its top edge and 130 mm from its left edge; around the pivot an
# engraved scale arc: ticks every 10 g from 0 to 100 g, 8 mm long from radius 100 (those
# at 0, 20, 40 ... 100 g 12 mm long) and labels "0", "20" ... "100" on radius 122; the
# mark for m grams is at -90 deg - atan(m / K), K = 100 g / tan(60 deg) (100 g swings the
# pointer 60 deg); engraved "LETTER SCALE" and "GRAMS". A cross-halving slot 20 mm up from
# the middle of its bottom edge. (2) Foot: 160 x 40 with a cross-halving slot 20 mm down
# from the middle of its top edge. (3) Arm (pendulum), pivot hole 4.2 mm: a hub R12, a
# lever 12 mm wide to a 4 mm letter-clip hole 95 mm right of the pivot, a 12 mm stem down
# to a bob R26 whose centre is 55 mm below the pivot, with an 8.5 mm zero-adjust slot
# (M8 bolt and washers as the counterweight) from 16 mm left to 4 mm right of the bob's
# centre, and a pointer tip 98 mm below the pivot (2 mm short of the scale's ticks).

import "std/joints.aidl"

thickness 6 mm
mat = 6 mm

param full_g = 100, min = 50, max = 250        # grams at the last mark
full_angle = 60 deg                            # swing at full_g
k_g = full_g / tan(full_angle)
tick_r = 100 mm
label_r = 122 mm
pointer_r = 98 mm

def mark(m) = -90 deg - atan(m / k_g)

assembly letter_scale {
    solid stand {
        # pivot at the origin: left edge 130 mm left of it, top 30 mm above it
        body = RoundedRectangle(bottom_left=(-130, -160), width=170, height=190,
                                corner_radius=8)
        hole pivot {
            c = Circle(center=(0, 0), diameter=4.2)
        }
        foot_slot = cross_halving(depth=20 mm, thickness=mat, clearance=0.2 mm, rotation=180 deg,
                                  cx=-45 mm, cy=-160 mm)
        drawing scale {
            ring = Circle(center=(0, 0), radius=label_r, construction=true)
            for i in range(11) {
                m = i * full_g / 10
                long = 12 mm if i % 2 == 0 else 8 mm
                tick = Line(start=(tick_r * cos(mark(m)), tick_r * sin(mark(m))),
                            end=((tick_r + long) * cos(mark(m)), (tick_r + long) * sin(mark(m))))
            }
            for j in range(6) {
                lab = Text(str(j * full_g / 5), along=ring, angle=mark(j * full_g / 5), size=6,
                           flip=true)
            }
            title = Text("LETTER SCALE", position=(-65, 15), size=8, valign="middle")
            unit = Text("GRAMS", position=(-40, -70), size=6, valign="middle")
        }
        assert len(scale.tick) == 11, "ticks every 10 g from 0 to 100 g"
        assert body.bb.width == 170 mm and body.bb.height == 190 mm, "stand 170 x 190"
        assert body.bb.right - pivot.c.center.x == 40 mm and body.bb.top - pivot.c.center.y == 30 mm,
            "pivot 130 mm from the left edge, 30 mm below the top"
    }

    solid foot {
        bar = Rectangle(center=(0, 0), width=160, height=40)
        stand_slot = cross_halving(depth=20 mm, thickness=mat, clearance=0.2 mm, cx=0 mm, cy=20 mm)
    }

    solid arm {
        hub = Circle(center=(0, 0), radius=12)
        lever = Slot(start=(0, 0), end=(95, 0), width=12)
        stem = Slot(start=(0, 0), end=(0, -55), width=12)
        bob = Circle(center=(0, -55), radius=26)
        tip = Hull(Circle(center=(0, -75), radius=5), Point(0, -pointer_r))
        hole pivot {
            c = Circle(center=(0, 0), diameter=4.2)
        }
        hole clip {
            c = Circle(center=(95, 0), diameter=4)
        }
        hole zero {
            s = Slot(start=(-16, -55), end=(4, -55), width=8.5)
        }
        assert pivot.c.center.y - tip.bb.bottom == 98 mm, "pointer tip 98 mm below the pivot"
        assert clip.c.center.x - pivot.c.center.x == 95 mm, "clip hole 95 mm right"
    }

    Below(foot, stand, gap=8)
    AlignLeft(foot, stand)
    RightOf(arm, stand, gap=8)
    AlignTop(arm, stand)

    assert abs(mark(100) - (-150 deg)) < 0.01 deg, "100 g at 60 deg of swing"
    assert tick_r - pointer_r == 2 mm, "pointer 2 mm short of the ticks"
    assert stand.foot_slot.depth + foot.stand_slot.depth == 40 mm, "halvings add to the foot's height"
}
