# Request: a push-along toy excavator for my nephew, cut from 6 mm birch plywood, five parts
# pinned together with 6 mm dowels (pivot holes 6.4 mm so the joints turn freely):
# - body, side view facing right: a track 150 mm long x 30 mm tall with fully rounded ends,
#   its bottom the floor line, with five road wheels engraved on it (20 mm circles, 30 mm
#   apart, centred on the track's height); on the track a house 100 x 40 mm whose left end is
#   5 mm in from the track's left end; a cab 40 mm wide x 30 mm tall on the house's right end
#   (its top-left corner rounded 8 mm) with a window 22 x 18 mm (2 mm corners) in it; a round
#   boom lug 22 mm across at the house's front, its pivot hole 8 mm right of the house's right
#   edge and 12 mm below the house's top;
# - a crosswise foot 100 x 30 mm that keeps the body upright: a cross-halving joint, the body
#   slotted 15 mm up from its bottom edge 20 mm left of its centre, the foot 15 mm down from
#   its top edge at its middle, so both stand on the floor;
# - a boom: a 20 mm wide bent arm with round ends, from its pivot 55 mm right and 45 mm up to
#   the knee, then 55 mm right and 10 mm down to the tip, a pivot hole at each end;
# - a stick 100 mm long (end to end) x 16 mm wide with round ends and a pivot hole at each
#   end's centre;
# - a bucket: a rounded scoop with a pivot hole at the top and a curved mouth.

import "std/joints.aidl"

units mm
thickness 6 mm

param pin = 6.4 mm, min = 6 mm, max = 7 mm

assembly excavator {
    solid body {
        track = RoundedRectangle(center=(0, 15), width=150, height=30, corner_radius=15)
        house = Rectangle(center=(-20, 50), width=100, height=40)
        cab = RoundedRectangle(center=(10, 85), width=40, height=30, corner_radii=[8, 0, 0, 0])
        lug = Circle(center=(38, 58), diameter=22)
        hole window {
            w = RoundedRectangle(center=(14, 85), width=22, height=18, corner_radius=2)
        }
        hole pivot {
            c = Circle(center=(38, 58), diameter=pin)
        }
        drawing wheels {
            for i in range(5) {
                w = Circle(center=(-60 + i * 30, 15), diameter=20)
            }
        }
        slot = cross_halving(depth=15 mm, thickness=6 mm, clearance=0.2 mm, rotation=180 deg, cx=-20 mm, cy=0 mm)
        AllowOverlap(wheels, self)

        assert track.bb.width == 150 mm and track.bb.height == 30 mm, "track 150 x 30"
        assert house.bb.left - track.bb.left == 5 mm, "house 5 mm in from the track's left end"
        assert house.bb.bottom == track.bb.top, "house on the track"
        assert cab.bb.right == house.bb.right and cab.bb.bottom == house.bb.top, "cab on the house's right end"
        assert pivot.c.center.x - house.bb.right == 8 mm, "boom pivot 8 mm right of the house"
        assert house.bb.top - pivot.c.center.y == 12 mm, "boom pivot 12 mm below the house top"
        assert len(wheels.w) == 5, "five road wheels"
        assert slot.cut.bb.center_x - track.bb.center_x == -20 mm, "halving 20 mm left of centre"
    }

    solid foot {
        bar = Rectangle(center=(0, 0), width=100, height=30)
        slot = cross_halving(depth=15 mm, thickness=6 mm, clearance=0.2 mm, cx=0 mm, cy=15 mm)
    }

    solid boom {
        spine = Polyline([(0, 0), (55, 45), (110, 35)], construction=true)
        arm = Stroke(spine, width=20)
        hole root { c = Circle(center=(0, 0), diameter=pin) }
        hole tip { c = Circle(center=(110, 35), diameter=pin) }
    }

    solid stick {
        bar = Slot(center=(0, 0), length=100, width=16)
        hole a { c = Circle(center=(-42, 0), diameter=pin) }
        hole b { c = Circle(center=(42, 0), diameter=pin) }
        assert bar.length == 100 mm and bar.width == 16 mm, "stick 100 x 16"
        assert b.c.center.x - a.c.center.x == 100 mm - 16 mm, "holes at the round ends' centres"
    }

    solid bucket {
        scoop = Hull(Circle(center=(0, 0), radius=10), Circle(center=(-30, -38), radius=3),
                     Circle(center=(14, -44), radius=3))
        hole pivot { c = Circle(center=(0, 0), diameter=pin) }
        hole mouth { c = Circle(center=(-30, -15), radius=16) }
        assert distance(mouth, pivot) >= 5 mm, "wall between the mouth and the pivot"
    }

    assert body.slot.depth + foot.slot.depth == 30 mm, "the two halvings add up to the 30 mm overlap"

    Below(foot, body, gap=10)
    AlignLeft(foot, body)
    RightOf(boom, body, gap=10)
    AlignTop(boom, body)
    Below(stick, boom, gap=10)
    AlignLeft(stick, boom)
    RightOf(bucket, stick, gap=10)
    AlignTop(bucket, stick)
}
