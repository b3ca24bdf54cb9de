# Request (science, school project): a hair hygrometer, 3 mm ply. A back plate
# 120 x 200 mm (R8) hangs on two keyholes 35 mm either side of the centre, 20 mm
# below the top. A 3 mm axle (3.2 mm hole) 110 mm up carries a pulley (12 mm disc,
# 3.2 mm bore, a 1.5 mm hole 4 mm off centre to tie the hair) with the pointer
# glued on it. The hair runs straight up from the pulley's right edge to an M3
# tension screw 190 mm up, over a 10 mm wide ventilation slot from 125 to 180 mm
# up. The dial hangs below the axle: an engraved arc of radius 60 from 210 deg
# (0 %) to 330 deg (100 %), ticks every 5 % (4 mm, 7 mm every 10 %), the numbers
# 0-100 every 10 % inside at radius 48 (4 mm strokes), DRY and WET at radius 30
# beside the ends, "% RH" under the axle; "HYGROMETER" engraved filled (7 mm)
# 25 mm up. The pointer: a 10 mm hub with the 3.2 mm bore, a needle to 56 mm
# (1 mm tip radius) and a 14 mm counterweight disc 20 mm behind the axle.

import "std/plates.aidl"
import "std/fasteners.aidl"

units mm
thickness 3 mm

AXLE = 3.2 mm
PIVOT_Y = 110 mm
R_ARC = 60 mm
A0 = 210 deg          # 0 %
SPAN = 120 deg        # 0 to 100 %
def ang(p) = A0 + SPAN * p / 100
def tick_in(p) = R_ARC - (7 mm if p % 10 == 0 else 4 mm)

assembly hygrometer {
    solid plate {
        body = RoundedRectangle(center=(0, 100), width=120, height=200, corner_radius=8)
        Fixed(body)
        k1 = keyhole(cx=-35 mm, cy=180 mm)
        k2 = keyhole(cx=35 mm, cy=180 mm)
        hole axle {
            c = Circle(center=(0, PIVOT_Y), diameter=AXLE)
        }
        hole vent {
            s = Slot(start=(6, 125 + 5), end=(6, 180 - 5), width=10)
        }
        anchor = clearance_hole(size=3, cx=6 mm, cy=190 mm)
        drawing dial {
            arc = Arc(center=(0, PIVOT_Y), radius=R_ARC, start_angle=A0, end_angle=A0 + SPAN)
            for i in range(21) {
                t = Line((tick_in(5 * i) * cos(ang(5 * i)), PIVOT_Y + tick_in(5 * i) * sin(ang(5 * i))),
                         (R_ARC * cos(ang(5 * i)), PIVOT_Y + R_ARC * sin(ang(5 * i))))
            }
            # FIX after the first valid program: "100" came within 0.67 mm of its tick
            # (W0513): the numbers move in from radius 48 to 46
            for j in range(11) {
                n = Text(str(10 * j), position=(46 * cos(ang(10 * j)), PIVOT_Y + 46 * sin(ang(10 * j))),
                         size=4, valign="middle")
            }
            dry = Text("DRY", position=(30 * cos(A0 + 10 deg), PIVOT_Y + 30 * sin(A0 + 10 deg)),
                       size=3, valign="middle")
            wet = Text("WET", position=(30 * cos(A0 + SPAN - 10 deg), PIVOT_Y + 30 * sin(A0 + SPAN - 10 deg)),
                       size=3, valign="middle")
            rh = Text("% RH", position=(0, PIVOT_Y - 25), size=5, valign="middle")
        }
        drawing title {
            t = Text("HYGROMETER", position=(0, 25), size=7, valign="middle", font="sans:Bold",
                     fill=true)
        }
    }

    solid pulley {
        disc = Circle(center=(0, 0), diameter=12)
        Fixed(disc)
        hole bore { c = Circle(center=(0, 0), diameter=AXLE) }
        hole tie { c = Circle(center=(4, 0), diameter=1.5) }
    }

    solid pointer {
        hub = Circle(center=(0, 0), diameter=10)
        Fixed(hub)
        needle = Hull(Circle(center=(0, 0), radius=2.5), Circle(center=(0, -56), radius=1))
        tail = Hull(Circle(center=(0, 0), radius=2.5), Circle(center=(0, 20), radius=7))
        hole bore { c = Circle(center=(0, 0), diameter=AXLE) }
    }

    # flat on the sheet
    RightOf(pointer, plate, gap=5)
    AlignTop(pointer, plate)
    RightOf(pulley, pointer, gap=5)
    AlignTop(pulley, plate)

    # on the wall: plate, then the pulley on the axle, the pointer glued on it
    Place(plate, position=(0, 0, 0), face="front", up="up")
    Place(pulley, position=(0, -3, PIVOT_Y), face="front", up="up")
    Place(pointer, position=(0, -6, PIVOT_Y), face="front", up="up")

    # the request's numbers
    assert plate.body.bb.width == 120 mm and plate.body.bb.height == 200 mm, "plate 120 x 200"
    assert plate.axle.c.center.y - plate.body.bb.bottom == 110 mm, "axle 110 up"
    assert plate.k2.head_hole.center.x - plate.k1.head_hole.center.x == 70 mm, "keyholes 35 either side"
    assert plate.body.bb.top - plate.k1.head_hole.center.y == 20 mm, "keyholes 20 below the top"
    assert plate.vent.s.bb.bottom - plate.body.bb.bottom == 125 mm and
        plate.vent.s.bb.top - plate.body.bb.bottom == 180 mm, "vent 125 to 180"
    assert plate.anchor.c.center.y - plate.body.bb.bottom == 190 mm, "anchor 190 up"
    assert plate.anchor.c.center.x - plate.axle.c.center.x == 6 mm, "hair straight up from the pulley's edge"
    assert len(plate.dial.t) == 21 and len(plate.dial.n) == 11, "ticks every 5, numbers every 10"
    assert pointer.needle.bb.bottom == -57 mm, "needle to 56 + 1 mm tip"
    assert 56 mm + 1 mm <= 60 mm and 56 mm + 1 mm >= 60 mm - 7 mm, "the needle's tip reaches the ticks"
    assert distance(plate.dial, plate.title) >= 3 mm, "dial clear of the title"
    assert distance(plate.dial, plate.axle) >= 3 mm, "dial clear of the axle"
    assert distance(plate.vent, plate.anchor) >= 3 mm, "vent clear of the anchor"
}
