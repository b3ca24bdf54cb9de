# Request: a pretend rotary telephone for my 3-year-old, all 6 mm birch ply, glued, no screws.
# - Base: 200 x 150 mm, corners R20, lying flat. An 8 mm hole 10 mm in front of its centre
#   for the dial's dowel axle, the digits 1 2 3 4 5 6 7 8 9 0 engraved
#   under the dial's finger holes (so they show through them at rest), and a 6 mm hole for
#   the dowel finger stop 56 mm from the axle, 20 degrees round from the "1".
# - Dial: a 100 mm disc turning on the dowel (8.5 mm hole), ten 14 mm finger holes on a 72 mm
#   circle, 30 degrees apart, "1" at 60 degrees and going anticlockwise to "0"; the child's name
#   "MAX" engraved filled in the middle.
# - Two cradle uprights standing on the base 70 mm either side of the centre, 90 mm deep, 50 mm
#   tall above the base, top corners R12, each with two 20 mm glued tabs into slots in the
#   base, flush with the base's back edge; a square notch 26 wide and 10 deep in each top,
#   20 mm back from the upright's middle, for the handset to lie in.
# FIX after the first valid program: the uprights stood under the handset's cups (W0517), so
#   they move in to 55 mm either side of the centre (still clear of the 100 mm dial) and the
#   notch widens to 28 mm; "MAX" sat over the axle hole (W0505), so it moves up 15 mm.
# - Handset: 214 mm long, two 44 mm ear / mouth cups, a handle 22 mm wide curving up 14 mm in
#   the middle, seven 4 mm speaker holes in each cup, "HELLO" engraved filled on the handle.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
dial_y = -10 mm          # the axle's y on the base
hole_r = 36 mm           # finger-hole circle radius (72 mm circle)
def finger_angle(k) = 60 deg + k * 30 deg

def upright() -> solid {
    body = RoundedRectangle(corner=(-45, 0), opposite=(45, 56), corner_radii=[12, 12, 0, 0])
    feet = tab_and_slot(part="tab", length=90, thickness=t, tabs=2, tab=20, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    hole notch { r = Rectangle(corner=(20 - 14, 46), opposite=(20 + 14, 60)) }
}

assembly phone {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=20)
        hole axle { c = Circle(center=(0, dial_y), diameter=8) }
        hole stop { c = Circle(center=polar((0, dial_y), 56, finger_angle(0) - 20 deg), diameter=6) }
        left_slots = tab_and_slot(part="slot", length=90, thickness=t, tabs=2, tab=20, screw=0,
                                  rotation=90 deg, cx=-55, cy=30)
        right_slots = tab_and_slot(part="slot", length=90, thickness=t, tabs=2, tab=20, screw=0,
                                   rotation=90 deg, cx=55, cy=30)
        drawing digits {
            for k in range(10) {
                d = Text(str((k + 1) % 10), position=polar((0, dial_y), hole_r, finger_angle(k)),
                         size=7, valign="middle")
            }
        }
    }

    solid dial {
        disc = Circle(center=(0, 0), diameter=100)
        hole axle { c = Circle(center=(0, 0), diameter=8.5) }
        hole fingers {
            for k in range(10) {
                c = Circle(center=polar((0, 0), hole_r, finger_angle(k)), diameter=14)
            }
        }
        drawing name {
            n = Text("MAX", position=(0, 15), size=8, font="sans:Bold", valign="middle", fill=true)
        }
    }

    left = upright()
    right = upright()

    solid handset {
        handle_path = Arc(start=(-85, -8), through=(0, 6), end=(85, -8))
        handle = Stroke(handle_path, width=22)
        ear = Circle(center=(-85, -8), diameter=44)
        mouth = Circle(center=(85, -8), diameter=44)
        hole speaker {
            for e in [-85, 85] {
                mid = Circle(center=(e, -8), diameter=4)
                for j in range(6) {
                    ring = Circle(center=(e + 9 * cos(j * 60 deg), -8 + 9 * sin(j * 60 deg)), diameter=4)
                }
            }
        }
        drawing word {
            w = Text("HELLO", position=(0, 5), size=9, font="sans:Bold", valign="middle", fill=true)
        }
    }

    # flat on the sheet
    RightOf(dial, base, gap=10)
    AlignTop(dial, base)
    Below(handset, base, gap=10)
    AlignLeft(handset, base)
    RightOf(left, dial, gap=10)
    AlignTop(left, base)
    Below(right, left, gap=10)
    AlignLeft(right, left)

    # assembled: base flat, dial on it, uprights standing on their tabs, handset in the notches
    Place(base, position=(0, 0, 0))
    Place(dial, on=base, position=(0, dial_y))
    Place(left, on=base, position=(-55 - t / 2, 30, 0), face="right", up="up")
    Place(right, on=base, position=(55 - t / 2, 30, 0), face="right", up="up")
    Place(handset, on=base, position=(0, 49.77, 46))

    # the request's numbers
    assert base.plate.width == 200 mm and base.plate.height == 150 mm, "base 200 x 150"
    assert dial.disc.diameter == 100 mm, "100 mm dial"
    assert len(dial.fingers.c) == 10, "ten finger holes"
    assert dial.fingers.c[0].diameter == 14 mm, "14 mm finger holes"
    assert abs(distance(dial.fingers.c[3].center, dial.disc.center) - 72 mm / 2) < 0.01 mm,
        "finger holes on a 72 mm circle"
    assert distance(dial.fingers, dial.axle) >= 4 mm, "wood between the holes and the axle"
    assert dial.disc.diameter / 2 - (72 mm / 2 + 14 mm / 2) >= 5 mm, "a rim round the holes"
    assert len(base.digits.d) == 10, "ten digits"
    assert abs(distance(base.stop.c.center, base.axle.c.center) - 56 mm) < 0.01 mm, "stop 56 mm out"
    assert distance(base.stop.c.center, base.axle.c.center) - 6 mm / 2 >= 100 mm / 2 + 1 mm,
        "the stop stands outside the dial"
    assert left.body.bb.height == 56 mm, "50 mm above the base plus the 6 mm tabs"
    assert left.notch.r.width == 28 mm, "28 mm notch"
    assert distance(dial.name, dial.fingers) >= 2 mm and distance(dial.name, dial.axle) >= 2 mm,
        "MAX clear of the holes"
    assert base.right_slots.slot[0].bb.left - 100 mm / 2 >= 2 mm, "uprights clear of the dial"
    assert left.body.bb.top - left.notch.r.bb.bottom == 10 mm, "10 mm deep notch"
    assert handset.bb.width == 214 mm, "214 mm handset"
    assert len(handset.speaker.mid) == 2 and len(handset.speaker.ring[0]) + 1 == 7 and
        len(handset.speaker.ring[1]) + 1 == 7, "seven speaker holes in each cup"
    assert distance(handset.word, handset.speaker) >= 3 mm, "HELLO clear of the speaker holes"
    assert base.plate.bb.top - base.right_slots.bb.top >= 5 mm, "wood behind the slots"
}
