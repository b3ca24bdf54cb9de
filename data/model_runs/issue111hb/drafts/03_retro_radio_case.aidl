# Request (electronics): a retro-look case for my FM radio kit, 3 mm ply, a closed
# finger-jointed box 200 wide x 90 deep x 120 high outside (10 mm fingers).
# Front: a speaker grille for the 77 mm speaker: a 5 mm centre hole and rings of 5 mm
# holes at 10, 20 and 30 mm radius (6, 12 and 18 holes), centred 50 mm from the front's
# left edge at mid-height, with four 3.4 mm speaker screw holes on a 66 mm square round
# it. A dial window 70 x 24 mm (3 mm corners) centred 45 mm right of the middle and 25 mm
# up, with an engraved FM scale over it: a tick every MHz from 88 to 108 across 64 mm,
# long ticks and numbers every 4 MHz, "MHz" at its right. Two 7 mm pot holes 40 mm apart
# centred under the window, 20 mm below mid-height, labelled TUNING and VOLUME under them.
# Back: an 8 mm hole for the DC jack and a 6 mm antenna hole, 30 mm apart, with "9V DC"
# over the jack. Lid: a carrying slot 90 x 22 mm in the middle.

units mm
thickness 3 mm

import "std/joints.aidl"

gx = -50 mm   # grille centre from the front's centre
wx = 45 mm    # window centre
wy = 25 mm
sx0 = wx - 32 mm   # 88 MHz tick
step = 64 mm / 20  # mm per MHz

assembly radio {
    box = finger_box(length=200 mm, depth=90 mm, height=120 mm, thickness=3 mm,
                     finger=10 mm, closed=true)

    hole front_cut {
        centre = Circle(center=(gx, 0), diameter=5)
        for k in range(1, 4) {
            for j in range(6 * k) {
                g = Circle(center=(gx + 10 mm * k * cos(j * 60 deg / k),
                                   10 mm * k * sin(j * 60 deg / k)), diameter=5)
            }
        }
        for m in range(4) {
            sp = Circle(center=(gx + 33 mm * (1 if m % 2 == 1 else -1),
                                33 mm * (1 if m >= 2 else -1)), diameter=3.4)
        }
        window = RoundedRectangle(center=(wx, wy), width=70, height=24, corner_radius=3)
        tune = Circle(center=(wx - 20 mm, -20), diameter=7)
        vol = Circle(center=(wx + 20 mm, -20), diameter=7)
    }
    At(front_cut.centre.center, box.front.bb.center, dx=gx)
    CutInto(front_cut, box.front)

    drawing dial {
        for f in range(21) {
            tick = Line((sx0 + f * step, wy + 14 mm),
                        (sx0 + f * step, wy + 14 mm + (5 mm if f % 4 == 0 else 3 mm)))
        }
        for q in range(6) {
            n = Text(str(88 + 4 * q), position=(sx0 + 4 * q * step, wy + 21 mm), size=3.5)
        }
        mhz = Text("MHz", position=(wx + 44 mm, wy + 14 mm), size=3)
        tl = Text("TUNING", position=(wx - 20 mm, -34), size=4)
        vl = Text("VOLUME", position=(wx + 20 mm, -34), size=4)
    }
    At(dial.tl.position, box.front.bb.center, dx=wx - 20 mm, dy=-34 mm)
    CutInto(dial, box.front)

    hole back_cut {
        jack = Circle(center=(-15, -20), diameter=8)
        ant = Circle(center=(15, -20), diameter=6)
    }
    At(back_cut.jack.center, box.back.bb.center, dx=-15 mm, dy=-20 mm)
    CutInto(back_cut, box.back)
    drawing back_mark {
        dc = Text("9V DC", position=(-15, -8), size=4)
    }
    At(back_mark.dc.position, box.back.bb.center, dx=-15 mm, dy=-8 mm)
    CutInto(back_mark, box.back)

    hole handle {
        s = Slot(center=(0, 0), length=90, width=22)
    }
    CenterInside(handle, box.lid)
    CutInto(handle, box.lid)

    assert len(front_cut.g) == 3, "three rings"
    assert len(front_cut.g[0]) == 6 and len(front_cut.g[1]) == 12 and len(front_cut.g[2]) == 18,
        "6, 12 and 18 holes"
    assert front_cut.centre.center.x - box.front.bb.left == 50 mm, "grille 50 mm from the left edge"
    assert front_cut.vol.center.x - front_cut.tune.center.x == 40 mm, "pots 40 mm apart"
    assert front_cut.sp[1].center.x - front_cut.sp[0].center.x == 66 mm, "66 mm square"
    assert dial.tick[20].start.x - dial.tick[0].start.x == 64 mm, "scale 64 mm long"
    assert back_cut.ant.center.x - back_cut.jack.center.x == 30 mm, "30 mm apart"
    assert distance(dial, front_cut.window) >= 1 mm, "scale clear of the window"
    assert handle.s.length == 90 mm and handle.s.width == 22 mm, "handle slot 90 x 22"
}
