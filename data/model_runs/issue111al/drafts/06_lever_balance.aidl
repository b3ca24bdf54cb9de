# Request (science): a classroom lever balance (the "maths balance" for moments), 6 mm
# plywood. A beam 400 x 32 mm that swings on a 6 mm dowel through a 6.5 mm pivot hole 8 mm
# above its centre line (so it rights itself); ten 4 mm hook holes each side of the pivot,
# 18 mm apart starting 18 mm out, 6 mm below the centre line, numbered 1-10 above them
# (5 mm engraved figures); a pointer 12 mm wide hanging 26 mm below the beam's middle. The
# stand: an upright trapezoid 160 mm wide at the foot, 30 mm at the top, 220 mm tall, with
# a 6 mm hole for the dowel 15 mm below its top and an engraved scale the pointer reads
# (ticks every 5 deg to +-20 deg, from 2 mm outside the pointer's tip, zero longer); a foot
# 160 x 40 mm crossing it by a cross halving (each slot 20 mm), "LEVER BALANCE" engraved on
# the foot. Two washers (16 mm, 6.5 mm bore): one between beam and upright, one outside.

import "std/joints.aidl"
import "std/shapes.aidl"

thickness 6 mm

T = 6 mm
beam_l = 400 mm
beam_h = 32 mm
pivot_up = 8 mm        # pivot above the beam's centre line
pitch = 18 mm
hole_y = -6 mm
ptr_len = 26 mm
up_h = 220 mm
axle_down = 15 mm      # dowel hole below the upright's top
tip_r = pivot_up + beam_h / 2 + ptr_len   # pointer tip from the pivot

assembly balance {
    solid beam {
        bar = Rectangle(center=(0, 0), width=beam_l, height=beam_h)
        pointer = Triangle(center=(0, -beam_h / 2 - ptr_len / 2 + 0.5 mm), base=12 mm,
                           height=ptr_len + 1 mm, rotation=180 deg)
        Fillet([bar, pointer], 2 mm)
        hole pivot { c = Circle(center=(0, pivot_up), diameter=6.5 mm) }
        hole hr { c = Circle(center=(pitch, hole_y), diameter=4 mm) }
        hole hl { c = Circle(center=(-pitch, hole_y), diameter=4 mm) }
        right = LinearPattern(hr, 10, (pitch, 0))
        left = LinearPattern(hl, 10, (-pitch, 0))
        drawing numbers {
            for i in range(1, 11) {
                r = Text(str(i), position=(i * pitch, 1 mm), size=5)
                l = Text(str(i), position=(-i * pitch, 1 mm), size=5)
            }
        }
        assert bar.width == 400 mm and bar.height == 32 mm, "beam 400 x 32"
        assert len(right) == 10 and len(left) == 10, "ten hook holes each side"
        assert right[9].c.center.x - pivot.c.center.x == 180 mm, "10th hole 180 mm out"
        assert pivot.c.center.y - bar.center.y == 8 mm, "pivot 8 mm above the centre line"
        assert bar.bb.right - right[9].c.center.x >= 10 mm, "last hole clear of the end"
        assert pivot.c.center.y - pointer.bb.bottom == tip_r, "pointer tip radius"
        assert numbers.r[0].bb.bottom > hole_y + 2 mm, "figures above the holes"
    }

    solid upright {
        body = Trapezoid(center=(0, up_h / 2), bottom_width=160 mm, top_width=30 mm, height=up_h)
        hole axle { c = Circle(center=(0, up_h - axle_down), diameter=6 mm) }
        lap = cross_halving(depth=20 mm, thickness=T, cx=0, cy=0, rotation=180 deg)
        drawing scale {
            for k in range(-4, 5) {
                tick = Line(polar((0, up_h - axle_down), tip_r + 2 mm, -90 deg + k * 5 deg),
                            polar((0, up_h - axle_down), tip_r + (10 mm if k == 0 else 7 mm),
                                  -90 deg + k * 5 deg))
            }
        }
        assert body.height == 220 mm, "220 mm tall"
        assert body.bb.top - axle.c.center.y == 15 mm, "dowel hole 15 mm below the top"
        assert len(scale.tick) == 9, "ticks every 5 deg to +-20"
    }

    solid foot {
        body = Rectangle(center=(0, 0), width=160 mm, height=40 mm)
        lap = cross_halving(depth=20 mm, thickness=T, cx=0, cy=20 mm)
        drawing label {
            t = Text("LEVER BALANCE", position=(0, -10 mm), size=6, valign="middle")
        }
        assert upright.lap.depth + lap.depth == body.height, "halvings add up to the foot"
        assert label.bb.top < body.bb.top - 20 mm, "label below the halving slot"
    }

    w1 = washer(outer=16 mm, inner=6.5 mm)
    w2 = washer(outer=16 mm, inner=6.5 mm)

    Above(beam, upright, gap=10)
    AlignLeft(beam, upright)
    RightOf(foot, upright, gap=10)
    AlignBottom(foot, upright)
    RightOf(w1, foot, gap=10)
    AlignBottom(w1, foot)
    RightOf(w2, w1, gap=5)
    AlignBottom(w2, w1)
}
