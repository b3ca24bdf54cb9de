# Request: a jeweller's bench pin that hooks over the front edge of my workbench, for
# piercing-saw and file work. 9 mm birch ply. The pin is a board 200 mm long x 80 mm wide;
# 60 mm of it lies on the bench (two countersunk M4 wood screws, 8.5 mm heads, hold it
# down, 25 mm from the back edge and 25 mm either side of the centre line) and 140 mm
# overhangs. A V notch in the front end: 40 mm wide at the front edge, 60 mm deep, ending in
# a 10 mm relief hole at its apex. Front corners rounded R6, the V's mouth corners eased R1.5.
# Under the pin at the bench's front edge a stop plate (80 wide, 50 mm deep below the pin)
# hooks over the bench front; two 16 mm tenons on its top go through mortises in the pin.
# Two triangular gussets (legs 50 mm) brace the stop to the overhang, 30 mm either side of
# the centre line, each with one 20 mm tenon into the pin and one into the stop.
# Engraved: "BENCH PIN" across the back part, and an 80 mm ruler along one long edge of the
# overhang (ticks every 5 mm, numbers every 10 mm).

units mm
thickness 9 mm

import "std/joints.aidl"
import "std/fasteners.aidl"

T = 9 mm
PIN_L = 200 mm
PIN_W = 80 mm
ON_BENCH = 60 mm
STOP_H = 50 mm
LEG = 50 mm
GUSSET_Y = 30 mm
STOP_X = ON_BENCH + T / 2          # the stop's mid-plane, under the pin

# a gusset drawn with the stop's front face at x = 0 and the pin's underside at y = 0;
# the top strip (y 0..T) and the left strip (x -T..0) are cut down to one tenon each
def gusset() -> solid {
    body = Polygon([(0, T), (LEG, T), (LEG, 0), (0, -LEG), (-T, -LEG), (-T, 0), (0, 0)])
    top_tenon = tab_and_slot(part="tab", length=LEG, thickness=T, tabs=1, tab=20 mm,
                             screw=0, cx=LEG / 2, cy=T)
    side_tenon = tab_and_slot(part="tab", length=LEG, thickness=T, tabs=1, tab=20 mm,
                              screw=0, rotation=90 deg, cx=-T, cy=-LEG / 2)
}

assembly bench_pin {
    solid pin {
        body = Rectangle(bottom_left=(0, -PIN_W / 2), width=PIN_L, height=PIN_W)
        hole vee {
            v = Polygon([(PIN_L - 60 mm, 0), (PIN_L + 1 mm, 20 mm + 1 mm / 3), (PIN_L + 1 mm, -20 mm - 1 mm / 3)])
            relief = Circle(center=(PIN_L - 60 mm + 3 mm, 0), diameter=10 mm)
        }
        stop_mortise = tab_and_slot(part="slot", length=PIN_W, thickness=T, tabs=2, tab=16 mm,
                                    screw=0, rotation=90 deg, cx=STOP_X, cy=0)
        for s in [-1, 1] {
            gusset_mortise = tab_and_slot(part="slot", length=LEG, thickness=T, tabs=1,
                                          tab=20 mm, screw=0, cx=ON_BENCH + T + LEG / 2,
                                          cy=s * GUSSET_Y)
        }
        for s in [-1, 1] {
            screw = clearance_hole(size=4, cx=25 mm, cy=s * 25 mm)
        }
        Countersink(screw, diameter=8.5 mm)
        Fillet([body.top_right, body.bottom_right], 6 mm)
        Fillet([body, vee.v], 1.5 mm)

        drawing label {
            name = Text("BENCH PIN", position=(45, 0), size=6, valign="middle", rotation=90 deg)
        }
        drawing ruler {
            for i in range(17) {
                tick = Line((110 + 5 * i, -PIN_W / 2), (110 + 5 * i, -PIN_W / 2 + (6 if i % 2 == 0 else 3)))
            }
            for k in range(9) {
                num = Text(str(10 * k), position=(110 + 10 * k, -32), size=2.5)
            }
        }
        assert body.bb.width == 200 mm, "pin 200 long"
        assert body.bb.height == 80 mm, "pin 80 wide"
        assert body.bb.right - vee.v.points[0].x == 60 mm, "V 60 deep"
        assert vee.relief.diameter == 10 mm, "10 mm relief hole"
    }

    solid stop {
        body = Rectangle(bottom_left=(-PIN_W / 2, -STOP_H), width=PIN_W, height=STOP_H + T)
        tenons = tab_and_slot(part="tab", length=PIN_W, thickness=T, tabs=2, tab=16 mm,
                              screw=0, cx=0, cy=T)
        for s in [-1, 1] {
            gusset_mortise = tab_and_slot(part="slot", length=LEG, thickness=T, tabs=1,
                                          tab=20 mm, screw=0, rotation=90 deg,
                                          cx=s * GUSSET_Y, cy=-LEG / 2)
        }
        assert body.bb.height - T == 50 mm, "stop reaches 50 below the pin"
    }

    left_gusset = gusset()
    right_gusset = gusset()

    # flat layout for cutting
    Below(stop, pin, gap=10)
    AlignLeft(stop, pin)
    RightOf(left_gusset, stop, gap=10)
    AlignTop(left_gusset, stop)
    RightOf(right_gusset, left_gusset, gap=10)
    AlignTop(right_gusset, stop)

    # 3D: the pin's top face at z = 0, the bench's front face at x = ON_BENCH
    Place(pin, position=(0, 0, -T), face="up")
    Place(stop, position=(ON_BENCH, 0, -T), face="+x", up="up")
    Place(left_gusset, position=(ON_BENCH + T, GUSSET_Y + T / 2, -T), face="front", up="up")
    Place(right_gusset, position=(ON_BENCH + T, -GUSSET_Y + T / 2, -T), face="front", up="up")

    assert len(pin.screw) == 2, "two screws"
}
