# Request: a hand-cranked coil winding jig for small transformer and inductor bobbins,
# 6 mm ply. A base 220 x 120 mm with four M4 clearance holes 10 mm in from the corners
# (to screw it to the bench) and "COIL WINDER  M8 SPINDLE" engraved. Two uprights 100 mm
# wide with a round top (R50), standing 140 mm apart (inside faces) on two 20 mm tenons
# each, with an 8.5 mm hole for an M8 threaded-rod spindle 70 mm above the base.
# A crank disc 80 mm across on the spindle outside the right upright: 8.5 mm centre hole,
# a 6.5 mm hole for a dowel handle 30 mm out, and a turn dial engraved round it: ten ticks
# 36 degrees apart (33 to 38 mm out) numbered 0-9 (4 mm figures on a 22 mm circle).

units mm
thickness 6 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

T = 6 mm
BASE_L = 220 mm
BASE_W = 120 mm
UP_W = 100 mm
INSIDE = 140 mm
SPINDLE_H = 70 mm
CRANK_D = 80 mm

# an upright drawn with the base's top face at y = 0, its tenons below
def upright() -> solid {
    body = Rectangle(bottom_left=(-UP_W / 2, -T), width=UP_W, height=60 mm + T)
    top = Circle(center=(0, 60 mm), radius=50 mm)
    tenons = tab_and_slot(part="tab", length=UP_W, thickness=T, tabs=2, tab=20 mm,
                          screw=0, rotation=180 deg, cx=0, cy=-T)
    hole bearing {
        c = Circle(center=(0, SPINDLE_H), diameter=8.5 mm)
    }
}

assembly coil_winder {
    solid base {
        body = Rectangle(center=(0, 0), width=BASE_L, height=BASE_W)
        for s in [-1, 1] {
            mortise = tab_and_slot(part="slot", length=UP_W, thickness=T, tabs=2, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=s * (INSIDE / 2 + T / 2), cy=0)
        }
        for p in [(-1, -1), (1, -1), (-1, 1), (1, 1)] {
            screw = clearance_hole(size=4, cx=p[0] * (BASE_L / 2 - 10 mm), cy=p[1] * (BASE_W / 2 - 10 mm))
        }
        drawing label {
            t1 = Text("COIL WINDER", position=(0, 8), size=8)
            t2 = Text("M8 SPINDLE", position=(0, -12), size=5)
        }
        assert body.bb.width == 220 mm and body.bb.height == 120 mm, "base 220 x 120"
    }

    left_upright = upright()
    right_upright = upright()

    solid crank {
        disc = Circle(center=(0, 0), diameter=CRANK_D)
        hole spindle { c = Circle(center=(0, 0), diameter=8.5 mm) }
        hole handle { c = Circle(center=(30 mm * cos(18 deg), 30 mm * sin(18 deg)), diameter=6.5 mm) }
        drawing dial {
            ring = Circle(center=(0, 0), radius=22 mm, construction=true)
            for i in range(10) {
                tick = Line((33 mm * cos(i * 36 deg), 33 mm * sin(i * 36 deg)),
                            (38 mm * cos(i * 36 deg), 38 mm * sin(i * 36 deg)))
                num = Text(str(i), along=ring, angle=i * 36 deg, size=4, valign="middle")
            }
        }
        assert distance(handle.c.center, spindle.c.center) == 30 mm, "handle 30 mm out"
        assert len(dial.tick) == 10, "ten ticks"
    }

    # flat layout
    RightOf(left_upright, base, gap=10)
    AlignTop(left_upright, base)
    RightOf(right_upright, left_upright, gap=10)
    AlignTop(right_upright, base)
    Below(crank, base, gap=10)
    AlignLeft(crank, base)

    # 3D: base on the bench, the uprights on it, the crank against the right upright
    Place(base, position=(0, 0, 0), face="up")
    Place(left_upright, position=(-INSIDE / 2 - T, 0, T), face="+x", up="up")
    Place(right_upright, position=(INSIDE / 2, 0, T), face="+x", up="up")
    Place(crank, position=(INSIDE / 2 + T, 0, T + SPINDLE_H), face="+x", up="up")

    assert right_upright.bearing.c.center.y == 70 mm, "spindle 70 above the base"
    assert left_upright.body.bb.width == 100 mm, "uprights 100 wide"
    assert crank.disc.diameter == 80 mm, "crank 80 across"
}
