# Pets: a "has the dog had dinner?" dial for the kitchen wall, 3 mm ply, three parts:
# - a round back plate 160 mm across, hung on a screw by a keyhole (8 mm head, 4 mm slot,
#   10 mm long, upward) whose head is 35 mm above the centre; the seven days MON..SUN
#   engraved 7 mm tall round a 62 mm radius, MON at the top, clockwise; the dog's name
#   "BUDDY" engraved filled in bold letters 12 mm tall, 38 mm below the centre; a 4.3 mm
#   hole at the centre for the M4 pivot bolt;
# - a pointer turned to the day once the dog is fed: a 18 mm hub, a tip 58 mm from the
#   pivot (reaching the day names' baseline minus 4 mm) and a 14 mm finger knob 18 mm
#   behind the pivot, with the same 4.3 mm pivot hole;
# - a spacer washer 12 mm outside, 4.3 mm bore, between plate and pointer.

units mm
thickness 3 mm

import "std/plates.aidl"
import "std/shapes.aidl"

plate_d = 160 mm
day_r = 62 mm
day_size = 7 mm
pivot_d = 4.3 mm
tip_r = 58 mm
days = ["MON", "TUE", "WED", "THU", "FRI", "SAT", "SUN"]

assembly dinner_dial {
    solid plate {
        disc = Circle(center=(0, 0), diameter=plate_d)
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
        hang = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=0, cy=35)
        drawing days_ring {
            ring = Circle(center=(0, 0), radius=day_r, construction=true)
            for i in range(7) {
                d = Text(days[i], along=ring, angle=90 deg - i * 360 deg / 7, size=day_size)
            }
        }
        drawing name {
            n = Text("BUDDY", position=(0, -38), size=12, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }

    solid pointer {
        hub = Circle(center=(0, 0), diameter=18)
        knob = Circle(center=(0, -18), diameter=14)
        arm = Hull(hub, knob, Point(0, tip_r))
        hole pivot { c = Circle(center=(0, 0), diameter=pivot_d) }
    }

    spacer = washer(outer=12 mm, inner=pivot_d)

    RightOf(pointer, plate, gap=10)
    AlignCenterY(pointer, plate)
    RightOf(spacer, pointer, gap=10)
    AlignCenterY(spacer, plate)

    assert plate.disc.diameter == 160 mm, "plate 160 mm"
    assert len(plate.days_ring.d) == 7, "seven days"
    assert plate.days_ring.ring.radius == 62 mm, "days on a 62 mm radius"
    assert plate.hang.head_hole.center.y - plate.disc.center.y == 35 mm, "keyhole 35 mm up"
    assert plate.name.n.position.y - plate.disc.center.y == -38 mm, "name 38 mm below"
    assert pointer.arm.bb.top - pointer.hub.center.y == 58 mm, "tip 58 mm from the pivot"
    assert pointer.hub.center.y - pointer.knob.center.y == 18 mm, "knob 18 mm behind"
    assert spacer.ring.diameter == 12 mm, "12 mm spacer"
}
