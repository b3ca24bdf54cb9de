# Request (electronics): a crystal radio set from 3 mm ply, three parts.
# - Baseboard 160 x 110 mm; its front edge finger-jointed (10 mm fingers) to the front panel.
#   M3 holes (3.4 mm): one for the coil's 25 mm standoff at (-30, 10) from the base's centre,
#   two 30 mm apart at x = 50 mm for the diode's tag strip. Engraved "COIL" and "DIODE".
# - Front panel 160 x 70 mm standing on the base's front edge: a 7 mm hole for the tuning
#   capacitor's shaft 38 mm up on the centre line, with two 2.7 mm M2.5 holes 13 mm apart
#   either side of it; an engraved dial round it: 11 ticks over the top half (every 18 deg),
#   numbered 0 to 10 from left to right; two 8 mm holes for 4 mm banana sockets at x = -60,
#   45 and 20 mm up, engraved "ANT" and "GND"; a 6 mm hole for the 3.5 mm phones jack at
#   x = 60, 30 mm up, engraved "PHONES"; "TUNING" under the dial.
# - Spiderweb coil former: a 90 mm disc with 9 radial slots 3 mm wide, open at the rim and
#   running in to 16 mm from the centre; a 3.4 mm centre hole, two 1.5 mm wire holes at 12 mm.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
base_w = 160 mm
base_d = 110 mm
panel_h = 70 mm
slots = 9

assembly crystal_radio {
    solid base {
        body = Rectangle(center=(0, 0), width=base_w, height=base_d)
        front = finger_edge(length=base_w, thickness=t, finger=10 mm, start="gap",
                            rotation=180 deg, cx=0 mm, cy=-base_d / 2)
        hole standoff { c = Circle(center=(-30, 10), diameter=3.4) }
        hole tags {
            a = Circle(center=(50, 25), diameter=3.4)
            b = Circle(center=(50, -5), diameter=3.4)
        }
        drawing labels {
            coil = Text("COIL", position=(-30, -42), size=6, valign="middle")
            diode = Text("DIODE", position=(50, 10), size=5, valign="middle")
        }
    }

    solid panel {
        # frame: the bottom edge (the fingers' tips) on y = 0
        body = Rectangle(center=(0, panel_h / 2), width=base_w, height=panel_h)
        bottom = finger_edge(length=base_w, thickness=t, finger=10 mm, start="tab",
                             rotation=180 deg, cx=0 mm, cy=0 mm)
        hole shaft { c = Circle(center=(0, 38), diameter=7) }
        hole cap_screws {
            l = Circle(center=(-6.5, 38), diameter=2.7)
            r = Circle(center=(6.5, 38), diameter=2.7)
        }
        hole sockets {
            ant = Circle(center=(-60, 45), diameter=8)
            gnd = Circle(center=(-60, 20), diameter=8)
        }
        hole jack { c = Circle(center=(60, 30), diameter=6) }
        drawing dial {
            ring = Circle(center=(0, 38), radius=23, construction=true)
            for k in range(11) {
                tick = Line((17 * cos((180 - 18 * k) * 1 deg), 38 + 17 * sin((180 - 18 * k) * 1 deg)),
                            (21 * cos((180 - 18 * k) * 1 deg), 38 + 21 * sin((180 - 18 * k) * 1 deg)))
                num = Text(str(k), along=ring, angle=(180 - 18 * k) * 1 deg, size=3)
            }
            tuning = Text("TUNING", position=(0, 10), size=5, valign="middle")
        }
        drawing labels {
            ant = Text("ANT", position=(-48, 45), size=5, anchor="start", valign="middle")
            gnd = Text("GND", position=(-48, 20), size=5, anchor="start", valign="middle")
            phones = Text("PHONES", position=(60, 45), size=5, valign="middle")
        }
    }

    solid coil {
        disc = Circle(center=(0, 0), diameter=90)
        hole centre { c = Circle(center=(0, 0), diameter=3.4) }
        hole wire {
            a = Circle(center=(12, 0), diameter=1.5)
            b = Circle(center=(-12, 0), diameter=1.5)
        }
        hole spokes {
            for k in range(slots) {
                s = Slot(start=(16 * cos((90 + 40 * k) * 1 deg), 16 * sin((90 + 40 * k) * 1 deg)),
                         end=(50 * cos((90 + 40 * k) * 1 deg), 50 * sin((90 + 40 * k) * 1 deg)),
                         width=3)
            }
        }
    }

    # on the sheet
    Above(panel, base, gap=8)
    AlignLeft(panel, base)
    RightOf(coil, base, gap=8)
    AlignBottom(coil, base)

    # assembled: the panel up on the base's front edge, its face to the front; the coil on
    # its standoff
    Place(base, position=(0, 0, 0))
    Place(panel, position=(0, -base_d / 2 + t, 0), face="front", up="up")
    Place(coil, position=(-30, 10, t + 25))

    assert base.body.width == 160 mm and base.body.height == 110 mm, "base 160 x 110"
    assert panel.body.width == 160 mm and panel.body.height == 70 mm, "panel 160 x 70"
    assert panel.shaft.c.center.y - panel.body.bb.bottom == 38 mm, "shaft 38 mm up"
    assert panel.cap_screws.r.center.x - panel.cap_screws.l.center.x == 13 mm, "screws 13 apart"
    assert len(panel.dial.num) == 11 and len(panel.dial.tick) == 11, "11 ticks, 0 to 10"
    assert coil.disc.diameter == 90 mm, "90 mm coil former"
    assert len(coil.spokes.s) == 9, "9 slots"
    assert base.tags.a.center.y - base.tags.b.center.y == 30 mm, "tag strip holes 30 apart"
}
