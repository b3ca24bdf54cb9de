# Request: an aeolian (wind) harp to sit in a sash window, from 4 mm birch ply. A closed
# finger-jointed soundbox 560 x 120 x 60 outside with 12 mm fingers. The lid is the
# soundboard: two 50 mm sound holes 220 apart about the middle, each ringed by an engraved
# 62 mm circle and twelve filled 3 mm dots on a 72 mm circle; eight strings 12 mm apart
# across the middle, 2.5 mm hitch-pin holes 25 mm from one end and 4.6 mm zither-pin holes
# 25 mm from the other; two bridges 100 long standing 14 mm above the lid, 30 mm inside the
# pin rows, each on two 20 x 4 tenons through the lid, with a 1.6 mm round string notch over
# each string. "AEOLIAN HARP" engraved filled, 16 mm tall, centred on the front.

import "std/joints.aidl"

thickness 4 mm

T = 4 mm
L = 560 mm
PITCH = 12 mm
PIN_X = L / 2 - 25 mm
BRIDGE_X = PIN_X - 30 mm

def bridge() -> solid {
    body = Rectangle(bottom_left=(-50, T), width=100, height=14)
    for y in [-25, 25] {
        tab = Rectangle(center=(y, (T + 1 mm) / 2), width=20, height=T + 1 mm)
    }
    hole notch {
        for i in range(8) {
            v = Circle(center=(-3.5 * PITCH + i * PITCH, T + 14 mm), diameter=1.6)
        }
    }
}

assembly harp {
    box = finger_box(length=L, depth=120 mm, height=60 mm, thickness=T, finger=12 mm,
                     closed=true)

    hole lid_cuts {
        mid = Point(0, 0, construction=true)
        for i in range(8) {
            hitch = Circle(center=(-PIN_X, -3.5 * PITCH + i * PITCH), diameter=2.5)
        }
        for i in range(8) {
            tune = Circle(center=(PIN_X, -3.5 * PITCH + i * PITCH), diameter=4.6)
        }
        for x in [-110, 110] {
            sound = Circle(center=(x, 0), diameter=50)
        }
        for x in [-BRIDGE_X, BRIDGE_X] {
            for y in [-25, 25] {
                mortise = Rectangle(center=(x, y), width=T, height=20)
            }
        }
    }
    Coincident(lid_cuts.mid, box.lid.outline.center)
    CutInto(lid_cuts, box.lid)

    drawing rose {
        mid = Point(0, 0, construction=true)
        for x in [-110, 110] {
            ring = Circle(center=(x, 0), diameter=62)
            for k in range(12) {
                dot = Circle(center=(x + 36 * cos(k * 30 deg), 36 * sin(k * 30 deg)), diameter=3,
                             fill=true)
            }
        }
    }
    Coincident(rose.mid, box.lid.outline.center)
    CutInto(rose, box.lid)

    drawing title {
        t = Text("AEOLIAN HARP", position=(0, 0), size=16, font="serif:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(title, box.front.core)
    CutInto(title, box.front)

    b1 = bridge()
    b2 = bridge()
    RightOf(b1, box, gap=10)
    AlignBottom(b1, box)
    Above(b2, b1, gap=8)
    AlignLeft(b2, b1)

    # in 3D: standing across the strings on the lid (top at z = 60)
    Place(b1, position=(-BRIDGE_X - T / 2, 0, 60 mm - T), face="right", up="up")
    Place(b2, position=(BRIDGE_X - T / 2, 0, 60 mm - T), face="right", up="up")

    assert box.lid.outline.bb.width == 560 mm and box.lid.outline.bb.height == 120 mm, "560 x 120"
    assert box.front.outline.bb.height == 60 mm, "60 deep"
    assert len(lid_cuts.hitch) == 8 and len(lid_cuts.tune) == 8, "eight strings"
    assert lid_cuts.hitch[1].center.y - lid_cuts.hitch[0].center.y == 12 mm, "12 mm apart"
    assert lid_cuts.sound[1].center.x - lid_cuts.sound[0].center.x == 220 mm, "holes 220 apart"
    assert box.lid.bb.right - lid_cuts.tune[0].center.x == 25 mm, "pins 25 from the end"
    assert lid_cuts.tune[0].center.x - lid_cuts.mortise[1][0].center.x == 30 mm,
        "bridge 30 inside the pins"
    assert b1.notch.v[7].center.x - b1.notch.v[0].center.x ==
        lid_cuts.hitch[7].center.y - lid_cuts.hitch[0].center.y, "notches over the strings"
    assert b1.body.bb.height == 14 mm, "bridge 14 above the lid"
}
