# Request (toys): a spirograph set cut from 3 mm clear acrylic, module 1 mm gears. A fixed
# ring with 96 inward teeth (8 mm rim past the roots) and three ears, each with a 2 mm hole
# for a push pin to hold the ring on the paper, "96" engraved on the rim; two rolling wheels,
# 52 and 30 teeth, each with 3 mm pen holes on a spiral (52: 8 holes at radii 7-21 mm; 30: 4
# holes at radii 5-11 mm) and its tooth count engraved at its centre. 0.1 mm backlash on the
# wheels so they roll freely.

import "std/gears.aidl"

thickness 3 mm
kerf 0.15 mm
# FIX after the first valid program: `aidl check` said ok, but `aidl render` stopped with
# "kerf 0.15 mm on part `spirograph.big`: the arc from (131.031, 5.24382) is too short for an
# offset of 0.075 mm: its neighbours' offsets cover it": the 52-tooth wheel is cut without
# kerf offset (kerf 0 in it; its 0.1 mm backlash stays; the ring and the 30-tooth wheel
# render with kerf 0.15 mm, tried after the first valid program). And the spirals now start at 90 deg
# (above the label), since the first pen hole sat 0.3 mm from the "30" (and close to "52").

M = 1 mm
ring_t = 96
big_t = 52
small_t = 30
pen_d = 3 mm

assembly spirograph {
    solid ring {
        g = ring_gear(teeth=ring_t, module=M, rim=8 mm, pinion=small_t, cx=0, cy=0)
        for i in range(3) {
            ear = Circle(center=polar((0, 0), 63 mm, 90 deg + i * 120 deg), radius=8 mm)
            Fillet([g.body, ear], 3 mm)
        }
        hole pins {
            for i in range(3) {
                p = Circle(center=polar((0, 0), 65 mm, 90 deg + i * 120 deg), diameter=2 mm)
            }
        }
        drawing label {
            track = Circle(center=(0, 0), radius=53.25 mm, construction=true)
            t = Text("96", along=track, angle=30 deg, size=3.5, valign="middle")
        }
        assert g.teeth == 96, "96 teeth"
        assert g.body.radius - (ring_t * M / 2 + 1.25 * M) == 8 mm, "8 mm rim"
        assert len(pins.p) == 3, "three push-pin ears"
    }

    solid big {
        kerf 0 mm
        g = spur_gear(teeth=big_t, module=M, backlash=0.1 mm, cx=130, cy=30)
        hole pens {
            for i in range(8) {
                c = Circle(center=polar((130, 30), 7 mm + i * 2 mm, 90 deg + i * 137.5 deg),
                           diameter=pen_d)
            }
        }
        drawing label {
            t = Text("52", position=(130, 30), size=4, valign="middle")
        }
        assert g.teeth == 52, "52 teeth"
        assert len(pens.c) == 8, "8 pen holes"
        # the outermost pen hole stays inside the tooth roots with 2 mm to spare
        assert 21 mm + pen_d / 2 <= big_t * M / 2 - 1.25 * M - 2 mm, "pen holes inside the roots"
    }

    solid small {
        g = spur_gear(teeth=small_t, module=M, backlash=0.1 mm, cx=130, cy=-35)
        hole pens {
            for i in range(4) {
                c = Circle(center=polar((130, -35), 5 mm + i * 2 mm, 90 deg + i * 137.5 deg),
                           diameter=pen_d)
            }
        }
        drawing label {
            t = Text("30", position=(130, -35), size=3, valign="middle")
        }
        assert g.teeth == 30, "30 teeth"
        assert len(pens.c) == 4, "4 pen holes"
        assert 11 mm + pen_d / 2 <= small_t * M / 2 - 1.25 * M, "pen holes inside the roots"
    }
    # both wheels roll inside the ring
    assert big_t < ring_t and small_t < ring_t, "wheels smaller than the ring"
}
