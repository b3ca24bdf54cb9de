# Request: an inclined plane for the school physics lab, 6 mm plywood. A ramp 400 x 80 hinges at
# its low end on a base 440 x 110 and can be set from 0 to 45 deg. Along one long edge of the
# ramp a fence 40 mm tall is glued in with four 20 mm tabs; the fence carries the pivot (an M6
# bolt, 6.5 mm hole, 14 mm above the ramp's top, straight above the ramp's low end, in a round
# boss r12) and 170 mm along from it an M6 locking bolt. Beside the fence, glued into the base
# with three 20 mm tabs, stands a quadrant plate (radius 215 about the pivot) with an arc slot
# of radius 170, 6.5 wide, from 0 to 45 deg, and on its outer face an engraved angle scale:
# ticks every 5 deg (8 mm long, 12 mm at each 10 deg) just outside the slot, labelled 0 to 40
# every 10 deg (5 mm), and "INCLINED PLANE" engraved 8 mm tall. The ramp's top has an engraved
# ruler for the rolling ball: ticks every 10 mm (4 mm long, 8 mm every 50 mm) from 20 mm in,
# labelled 0 to 35 cm (4 mm figures) and "cm" after the last.

import "std/joints.aidl"

thickness 6 mm
T = 6 mm
RAMP_L = 400 mm
RAMP_W = 80 mm
FENCE_H = 40 mm
PIVOT_Y = T + 14 mm      # pivot above the base's top (side view: base top y = 0, ramp 0..T)
LOCK_R = 170 mm
QUAD_R = 215 mm
MAX_ANGLE = 45 deg
SHOW = 20 deg            # the angle shown in the 3D view

def tilt_x(a) = (PIVOT_Y * sin(a))
def tilt_z(a) = (T + PIVOT_Y - PIVOT_Y * cos(a))

assembly incline {
    solid base {
        board = Rectangle(bottom_left=(-30, -10), width=440, height=110)
        quad_slots = tab_and_slot(part="slot", length=200 mm, thickness=T, tabs=3, tab=20 mm,
                                  screw=0, cx=100, cy=RAMP_W + 1 + T / 2)
        Fixed(board)
        assert board.bb.width == 440 mm and board.bb.height == 110 mm, "base 440 x 110"
    }

    solid ramp {
        board = Rectangle(bottom_left=(0, 0), width=RAMP_L, height=RAMP_W)
        fence_slots = tab_and_slot(part="slot", length=360 mm, thickness=T, tabs=4, tab=20 mm,
                                   screw=0, cx=RAMP_L / 2, cy=RAMP_W - T / 2)
        drawing ruler {
            for i in range(36) {
                tick = Line((20 + 10 * i, 4), (20 + 10 * i, 12 if i % 5 == 0 else 8))
            }
            for i in range(8) {
                num = Text(str(5 * i), position=(20 + 50 * i, 15), size=4)
            }
            unit = Text("cm", position=(380, 15), size=4, anchor="start")
        }
        Fixed(board)
        assert board.bb.width == 400 mm and board.bb.height == 80 mm, "ramp 400 x 80"
        assert ruler.tick[1].start.x - ruler.tick[0].start.x == 10 mm, "ruler ticks 10 mm"
        assert ruler.tick[0].start.x - board.bb.left == 20 mm, "ruler from 20 mm in"
    }

    solid fence {
        # side view: x along the ramp from its low end, y up from the base's top
        body = Rectangle(bottom_left=(0, T), width=RAMP_L, height=FENCE_H)
        boss = Circle(center=(0, PIVOT_Y), radius=12)
        strip = Rectangle(bottom_left=(20, 0), width=360, height=T)
        tabs = tab_and_slot(part="tab", length=360 mm, thickness=T, tabs=4, tab=20 mm, screw=0,
                            rotation=180 deg, cx=RAMP_L / 2, cy=0)
        hole pivot { c = Circle(center=(0, PIVOT_Y), diameter=6.5) }
        hole lock { c = Circle(center=(LOCK_R, PIVOT_Y), diameter=6.5) }
        Fixed(body)
        assert body.bb.height == 40 mm, "fence 40 tall"
        assert pivot.c.center.y - body.bb.bottom == 14 mm, "pivot 14 above the ramp top"
        assert pivot.c.center.x - body.bb.left == 0 mm, "pivot above the ramp's low end"
        assert lock.c.center.x - pivot.c.center.x == 170 mm, "lock bolt 170 along"
    }

    solid quadrant {
        # drawn as seen from outside: the ramp runs toward -x, its angle a lies at 180 deg - a
        disc = Circle(center=(0, PIVOT_Y), radius=QUAD_R, construction=true)
        box = Rectangle(bottom_left=(-QUAD_R, 0), width=QUAD_R + 20, height=185, construction=true)
        plate = Intersect(disc, box)
        strip = Rectangle(bottom_left=(-200, -T), width=200, height=T)
        feet = tab_and_slot(part="tab", length=200 mm, thickness=T, tabs=3, tab=20 mm, screw=0,
                            rotation=180 deg, cx=-100, cy=-T)
        hole pivot { c = Circle(center=(0, PIVOT_Y), diameter=6.5) }
        hole track {
            a = ArcSlot(center=(0, PIVOT_Y), radius=LOCK_R, start_angle=180 deg - MAX_ANGLE,
                        end_angle=180 deg, width=6.5)
        }
        drawing scale {
            ring = Circle(center=(0, PIVOT_Y), radius=196, construction=true)
            for a in range(0, 46, 5) {
                tick = Line((180 * cos(180 deg - a * 1 deg), PIVOT_Y + 180 * sin(180 deg - a * 1 deg)),
                            ((188 if a % 10 == 5 else 192) * cos(180 deg - a * 1 deg),
                             PIVOT_Y + (188 if a % 10 == 5 else 192) * sin(180 deg - a * 1 deg)))
            }
            for a in range(0, 41, 10) {
                label = Text(str(a), along=ring, angle=180 deg - a * 1 deg, size=5)
            }
            title = Text("INCLINED PLANE", position=(-100, 60), size=8, valign="middle")
        }
        Fixed(strip)
        assert track.a.radius == 170 mm, "arc slot radius 170"
        assert len(scale.tick) == 10 and len(scale.label) == 5, "ticks every 5, labels every 10"
    }

    # sheet
    Below(ramp, base, gap=8)
    AlignLeft(ramp, base)
    Below(fence, ramp, gap=8)
    AlignLeft(fence, ramp)
    RightOf(quadrant, base, gap=8)
    AlignTop(quadrant, base)

    # 3D: x along the ramp, y across, z up; the base's top at z = T; ramp and fence turned SHOW
    # about the pivot (x = 0, z = T + PIVOT_Y)
    Place(base, position=(0, 0, 0))
    Place(ramp, rotation=(0, -SHOW, 0), position=(tilt_x(SHOW), 0, tilt_z(SHOW)))
    Place(fence, rotation=(90 deg, -SHOW, 0), position=(tilt_x(SHOW), RAMP_W, tilt_z(SHOW)))
    Place(quadrant, rotation=(90 deg, 0, 180 deg), position=(0, RAMP_W + 1, T))
}
