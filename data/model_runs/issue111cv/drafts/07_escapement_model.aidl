# Request: a wall-hung anchor (recoil) escapement demonstrator for a physics class, 3 mm ply.
# Backplate 160 mm wide, from 215 mm below the escape wheel's axle to an arched top (R80
# about a point 60 mm above the axle), a keyhole to hang it 120 mm above the axle, and
# "ANCHOR ESCAPEMENT" engraved across the arch. Escape wheel: 30 saw teeth, tip R50, root R42
# (each tooth a slope over 10 deg and a radial locking face), five spoke windows between R12
# and R34, a 4.2 mm bore for a 4 mm axle. Anchor on the same plane, its pivot 71 mm above
# the wheel's axle, arms 8 mm wide to the pallets at +-45 deg 55 mm from the wheel's axle;
# the right pallet reaches in to R46 between two teeth, the left rests just clear of the
# tips. Pendulum: a 12 mm rod bolted to the anchor (two M4 bolts, 8 mm apart, the upper in
# the pivot) and a 50 mm bob 150 mm below the wheel's axle, a pointer under the bob over an
# engraved +-10 deg amplitude scale (ticks every 2 deg, numbers at 0, 5, 10). Spacers 3 mm:
# a 14 mm washer behind the wheel and behind the anchor, a 16 mm wide spacer between anchor
# and pendulum so the rod clears the wheel's face by 3 mm.

import "std/shapes.aidl"
import "std/plates.aidl"

thickness 3 mm

t = 3 mm
bore = 4.2 mm
pivot_y = 71 mm
lock_y = pivot_y - 8 mm
phase = 7.5 deg        # turns the wheel so the right pallet sits in a gap
tip_r = 50 mm
root_r = 42 mm
def tooth_r(k) = tip_r if k % 3 == 1 else root_r
def tooth_a(k) = phase + (k // 3) * 12 deg + (0 deg if k % 3 == 0 else 10 deg)
scale_r = 255 mm       # inner end of the amplitude ticks, about the pivot

assembly escapement {
    solid backplate {
        lower = Rectangle(bottom_left=(-80, -215), width=160, height=275)
        arch = Circle(center=(0, 60), radius=80)
        hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=0 mm, cy=120 mm)
        hole axle { c = Circle(center=(0, 0), diameter=bore) }
        hole pivot { c = Circle(center=(0, pivot_y), diameter=bore) }
        drawing title {
            words = Text("ANCHOR ESCAPEMENT", position=(0, 102), size=6, valign="middle")
        }
        drawing amplitude {
            ring = Circle(center=(0, pivot_y), radius=scale_r + 13, construction=true)
            for a in range(-10, 11, 2) {
                tick = Line(polar((0, pivot_y), scale_r, (270 + a) * 1 deg),
                            polar((0, pivot_y), scale_r + (7 if a % 10 == 0 else 4),
                                  (270 + a) * 1 deg))
            }
            for a in [-10, -5, 0, 5, 10] {
                num = Text(str(abs(a)), along=ring, angle=(270 + a) * 1 deg, size=4, flip=true)
            }
        }
        Fixed(lower)
    }

    solid wheel {
        teeth = Polygon([(tooth_r(k) * cos(tooth_a(k)), tooth_r(k) * sin(tooth_a(k)))
                         for k in range(90)])
        hole bore_hole { c = Circle(center=(0, 0), diameter=bore) }
        for s in range(5) {
            hole window { w = Sector(center=(0, 0), radius=34, inner_radius=12,
                                     start_angle=s * 72 deg + 11 deg,
                                     end_angle=s * 72 deg + 61 deg) }
        }
    }

    solid anchor {
        arms = Stroke(Polyline([(-55 * cos(45 deg), 55 * sin(45 deg)), (0, pivot_y),
                                (55 * cos(45 deg), 55 * sin(45 deg))]), width=8)
        boss = Circle(center=(0, pivot_y), radius=9)
        stem = Rectangle(center=(0, 66), width=12, height=16)
        pallet = Rectangle(center=(50.5 * cos(45 deg), 50.5 * sin(45 deg)), width=9, height=5,
                           rotation=45 deg)
        hole pivot { c = Circle(center=(0, pivot_y), diameter=bore) }
        hole lock { c = Circle(center=(0, lock_y), diameter=bore) }
    }

    solid pendulum {
        rod = Slot(start=(0, -150), end=(0, 80), width=12)
        bob = Circle(center=(0, -150), diameter=50)
        pointer = Triangle(center=(0, -177), base=8, height=10, rotation=180 deg)
        hole pivot { c = Circle(center=(0, pivot_y), diameter=bore) }
        hole lock { c = Circle(center=(0, lock_y), diameter=bore) }
    }

    wheel_spacer = washer(outer=14 mm, inner=bore)
    anchor_spacer = washer(outer=14 mm, inner=bore)
    solid stem_spacer {
        s = Slot(start=(0, lock_y), end=(0, pivot_y), width=16)
        hole pivot { c = Circle(center=(0, pivot_y), diameter=bore) }
        hole lock { c = Circle(center=(0, lock_y), diameter=bore) }
    }

    # flat on the sheet
    RightOf(wheel, backplate, gap=10)
    AlignTop(wheel, backplate)
    Below(anchor, wheel, gap=10)
    AlignLeft(anchor, wheel)
    RightOf(pendulum, wheel, gap=10)
    AlignTop(pendulum, backplate)
    Below(wheel_spacer, anchor, gap=10)
    AlignLeft(wheel_spacer, anchor)
    RightOf(anchor_spacer, wheel_spacer, gap=10)
    AlignTop(anchor_spacer, wheel_spacer)
    RightOf(stem_spacer, anchor_spacer, gap=10)
    AlignTop(stem_spacer, wheel_spacer)

    # assembled: the wheel's axle at the origin, layers toward the front (-y)
    # FIX after the first valid program: the backplate was placed at y = 3t + 4t - t/2
    # (16.5..19.5), 1.5 mm into both spacers (W0517 x2, real, my arithmetic): it sits behind
    # the spacers, 18..21
    Place(backplate, position=(0, 7 * t, 0), face="front", up="up")
    Place(wheel_spacer, position=(0, 6 * t, 0), face="front", up="up")
    Place(anchor_spacer, position=(0, 6 * t, pivot_y), face="front", up="up")
    Place(wheel, position=(0, 5 * t, 0), face="front", up="up")
    Place(anchor, position=(0, 5 * t, 0), face="front", up="up")
    Place(stem_spacer, position=(0, 4 * t, 0), face="front", up="up")
    Place(pendulum, position=(0, 3 * t, 0), face="front", up="up")

    assert len(wheel.teeth.points) == 90, "30 teeth"
    assert wheel.teeth.bb.width <= 2 * 50 mm
    assert len(wheel.window) == 5
    assert anchor.pivot.c.center.y - wheel.bore_hole.c.center.y == 71 mm
    assert anchor.pivot.c.center.y - anchor.lock.c.center.y == 8 mm
    assert pendulum.bob.center.y - wheel.bore_hole.c.center.y == -150 mm
    assert pendulum.bob.diameter == 50 mm and pendulum.rod.width == 12 mm
    assert backplate.lower.width == 160 mm
    assert backplate.lower.bb.bottom - backplate.axle.c.center.y == -215 mm
    assert backplate.arch.radius == 80 mm
    assert backplate.hang.head_hole.center.y - backplate.axle.c.center.y == 120 mm
    assert len(backplate.amplitude.tick) == 11
    assert len(backplate.amplitude.num) == 5
}
