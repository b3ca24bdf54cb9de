# Request: a hand-turned Geneva drive for the school science club, 4 mm ply, on 6 mm
# steel axles 60 mm apart: four stops of the wheel per turn of the crank.
# - Base 170 x 130 (R5), drive axle hole 55 mm in from its left edge on the centre
#   line, wheel axle hole 60 mm to its right (both 6.2 mm), four M4 foot holes (medium
#   fit) 6 mm in from the edges; "GENEVA DRIVE - 4 STOPS PER TURN" engraved 5 mm high,
#   8 mm above the bottom edge, centred between the axles.
# - Crank: a disc reaching 7 mm past the drive pin (pin on a radius of C sin 45 = 42.4
#   from its axle), a 6 mm press-fit hole for the steel drive pin, a 6 mm hole for a
#   handle dowel 40 mm from the axle opposite the pin, a 3 mm alignment hole 15 mm from
#   the axle at right angles to the pin.
# - Locking disc, 60 mm across, glued on the crank (same 3 mm alignment hole), with the
#   clearance cut facing the pin: a circle of the wheel's radius + 1 mm centred 60 mm
#   from the axle toward the pin.
# - Geneva wheel, radius C cos 45 = 42.4: 4 slots 6.4 wide (pin 6 + 0.4) from the rim to
#   0.2 mm past the pin's deepest point (C - 42.4 from the wheel axle), 4 concave arcs of
#   the locking disc's radius + 0.5 between them, centred 60 mm out; the numbers 1-4
#   engraved 5 mm high 24 mm out, one on each arc's bisector.
# - A spacer washer 14 / 6.2 lifts the wheel to the locking disc's level.

units mm
t = 4 mm
thickness t
kerf 0.15 mm

import "std/fasteners.aidl"
import "std/shapes.aidl"

C = 60 mm              # axle to axle
n = 4                  # slots
crank_r = C * sin(180 deg / n)    # drive pin radius
wheel_r = C * cos(180 deg / n)    # Geneva wheel radius
pin_d = 6 mm
slot_w = pin_d + 0.4 mm
lock_r = 30 mm
axle_d = 6.2 mm

assembly geneva {
    solid base {
        body = RoundedRectangle(center=(C / 2, 0), width=170 mm, height=130 mm, corner_radius=5 mm)
        hole axles {
            drive = Circle(center=(0, 0), diameter=axle_d)
            wheel = Circle(center=(C, 0), diameter=axle_d)
        }
        f1 = clearance_hole(size=4, cx=C / 2 - 85 mm + 6 mm, cy=-65 mm + 6 mm)
        f2 = clearance_hole(size=4, cx=C / 2 + 85 mm - 6 mm, cy=-65 mm + 6 mm)
        f3 = clearance_hole(size=4, cx=C / 2 + 85 mm - 6 mm, cy=65 mm - 6 mm)
        f4 = clearance_hole(size=4, cx=C / 2 - 85 mm + 6 mm, cy=65 mm - 6 mm)
        drawing title {
            words = Text("GENEVA DRIVE - 4 STOPS PER TURN", position=(C / 2, -65 mm + 8 mm), size=5 mm)
        }
        Fixed(body)
        Fixed(axles)
        Fixed(f1)
        Fixed(f2)
        Fixed(f3)
        Fixed(f4)
        Fixed(title)
    }

    solid crank {
        disc = Circle(center=(0, 0), radius=crank_r + 7 mm)
        hole holes {
            axle = Circle(center=(0, 0), diameter=axle_d)
            pin = Circle(center=(crank_r, 0), diameter=pin_d)
            handle = Circle(center=(-40 mm, 0), diameter=6 mm)
            align = Circle(center=(0, 15 mm), diameter=3 mm)
        }
        Fixed(disc)
        Fixed(holes)
    }

    solid lock {
        disc = Circle(center=(0, 0), radius=lock_r)
        hole clearance { c = Circle(center=(C, 0), radius=wheel_r + 1 mm) }
        hole holes {
            axle = Circle(center=(0, 0), diameter=axle_d)
            align = Circle(center=(0, 15 mm), diameter=3 mm)
        }
        Fixed(disc)
        Fixed(clearance)
        Fixed(holes)
    }

    solid wheel {
        disc = Circle(center=(0, 0), radius=wheel_r)
        hole axle { c = Circle(center=(0, 0), diameter=axle_d) }
        for k in range(n) {
            # slots on 45 + 90k deg, concave arcs on 90k deg (locked: an arc faces the drive)
            hole slot {
                s = Slot(start=((C - crank_r) * cos(45 deg + k * 90 deg), (C - crank_r) * sin(45 deg + k * 90 deg)),
                         end=((wheel_r + 5 mm) * cos(45 deg + k * 90 deg), (wheel_r + 5 mm) * sin(45 deg + k * 90 deg)),
                         width=slot_w)
            }
            hole arc {
                c = Circle(center=(C * cos(k * 90 deg), C * sin(k * 90 deg)), radius=lock_r + 0.5 mm)
            }
            Fixed(slot)
            Fixed(arc)
        }
        drawing numbers {
            for k in range(n) {
                num = Text(str(k + 1), position=(24 mm * cos(k * 90 deg), 24 mm * sin(k * 90 deg)),
                           size=5 mm, valign="middle")
            }
        }
        Fixed(disc)
        Fixed(axle)
        Fixed(numbers)
    }

    spacer = washer(outer=14 mm, inner=axle_d)

    # flat layout
    RightOf(crank, base, gap=5)
    AlignTop(crank, base)
    Below(lock, crank, gap=5)
    AlignLeft(lock, crank)
    RightOf(wheel, crank, gap=5)
    AlignTop(wheel, crank)
    RightOf(spacer, lock, gap=5)
    AlignTop(spacer, lock)

    # 3D, locked: the pin points away from the wheel, the locking disc sits in the arc
    Place(base, position=(0, 0, 0))
    Place(crank, position=(0, 0, t), rotation=(0, 0, 180 deg))
    Place(lock, position=(0, 0, 2 * t), rotation=(0, 0, 180 deg))
    Place(spacer, position=(C, 0, t))
    Place(wheel, position=(C, 0, 2 * t))

    # the request's numbers
    assert base.body.width == 170 mm and base.body.height == 130 mm
    assert base.axles.drive.center.x - base.body.bb.left == 55 mm
    assert base.axles.wheel.center.x - base.axles.drive.center.x == 60 mm
    assert base.body.bb.right - base.f3.c.center.x == 6 mm and base.body.bb.top - base.f3.c.center.y == 6 mm
    assert base.title.words.position.y - base.body.bb.bottom == 8 mm
    assert abs(crank_r - 42.43 mm) < 0.01 mm and abs(wheel_r - 42.43 mm) < 0.01 mm
    assert crank.disc.radius - crank_r == 7 mm
    assert crank.holes.pin.diameter == 6 mm and crank.holes.handle.center.x == -40 mm
    assert lock.disc.diameter == 60 mm
    assert len(wheel.slot) == 4 and len(wheel.arc) == 4 and len(wheel.numbers.num) == 4
    assert wheel.slot[0].s.width == 6.4 mm
    # the slot's inner end 0.2 mm past the pin's deepest point
    assert (C - crank_r) - norm(wheel.slot[0].s.start) == 0 mm and slot_w / 2 - pin_d / 2 == 0.2 mm
    assert wheel.arc[0].c.radius == lock.disc.radius + 0.5 mm
    # the wheel's tips between a slot and an arc are solid, not slivers
    assert distance(wheel.slot[0], wheel.arc[0]) >= 3 mm and distance(wheel.slot[0], wheel.arc[1]) >= 3 mm
    # the title clears the crank's sweep and the wheel (seen from above)
    assert base.title.bb.top <= -(crank_r + 7 mm) - 1 mm
    assert distance(base.title, base.f1) >= 2 mm and distance(base.title, base.f2) >= 2 mm
    # the handle dowel clears the locking disc
    assert 40 mm - 3 mm >= lock_r + 2 mm
}
