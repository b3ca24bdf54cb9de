# Request: a St Lucia crown for my daughter's Lucia procession (13 December), in 3 mm birch
# ply, to paint. A flat ring that sits round her head: inner diameter 165, outer 230, with
# 21 lingonberry leaves (ovals 26 x 11, tilted 60 degrees off the radius) sticking out round
# the outer edge, each with an engraved vein, three between each two candles. Seven candles
# stand evenly round the ring on its centre line (radius 99), facing out: each 18 wide and
# 110 tall above the ring, with a flame on top (a teardrop, R7, its tip 26 above the candle),
# held by one 10 mm tenon through a mortise in the ring (glued).

units mm
thickness 3 mm

import "std/joints.aidl"

T = 3 mm
R_IN = 165 mm / 2
R_OUT = 230 mm / 2
R_MID = 99 mm
N = 7
CANDLE_W = 18 mm
CANDLE_H = 110 mm

def candle_piece() -> solid {
    body = Rectangle(center=(0, (CANDLE_H - T) / 2), width=CANDLE_W, height=CANDLE_H + T)
    flame = Hull(Circle(center=(0, CANDLE_H + 6), radius=7), Point(0, CANDLE_H + 26))
    tenon = tab_and_slot(part="tab", length=CANDLE_W, thickness=T, tabs=1, tab=10 mm, screw=0,
                         rotation=180 deg, cx=0, cy=-T)
}

assembly lucia_crown {
    solid ring {
        outer = Circle(center=(0, 0), radius=R_OUT)
        for k in range(3 * N) {
            a = 90 deg + 360 deg / (6 * N) + k * 360 deg / (3 * N)
            leaf = Ellipse(center=(118 * cos(a), 118 * sin(a)), rx=13, ry=5.5, rotation=a + 60 deg)
        }
        hole head { c = Circle(center=(0, 0), radius=R_IN) }
        for i in range(N) {
            m = tab_and_slot(part="slot", length=CANDLE_W, thickness=T, tabs=1, tab=10 mm, screw=0,
                             rotation=90 deg + i * 360 deg / N + 90 deg,
                             cx=R_MID * cos(90 deg + i * 360 deg / N),
                             cy=R_MID * sin(90 deg + i * 360 deg / N))
        }
        drawing veins {
            for k in range(3 * N) {
                b = 90 deg + 360 deg / (6 * N) + k * 360 deg / (3 * N)
                v = Line((118 * cos(b) - 10 * cos(b + 60 deg), 118 * sin(b) - 10 * sin(b + 60 deg)),
                         (118 * cos(b) + 10 * cos(b + 60 deg), 118 * sin(b) + 10 * sin(b + 60 deg)))
            }
        }
    }

    for i in range(N) {
        candle = candle_piece()
        candle.bb.left == ring.bb.right + 10 mm + i * (CANDLE_W + 8 mm)
        AlignBottom(candle, ring)
        Place(candle, position=((R_MID - T / 2) * cos(90 deg + i * 360 deg / N),
                                (R_MID - T / 2) * sin(90 deg + i * 360 deg / N), T),
              face=(cos(90 deg + i * 360 deg / N), sin(90 deg + i * 360 deg / N), 0), up="up")
    }
    Place(ring, position=(0, 0, 0), face="up")

    assert ring.head.c.diameter == 165 mm, "inner diameter 165"
    assert ring.outer.diameter == 230 mm, "outer diameter 230"
    assert len(ring.leaf) == 21, "21 leaves"
    assert len(candle) == 7 and len(ring.m) == 7, "seven candles"
    assert candle[0].body.bb.top - (candle[0].tenon.gap[0].bb.top) == 110 mm, "110 above the ring"
    assert distance(ring.m[0].slot[0].bb.center, (0, 0)) == 99 mm, "candles on radius 99"
    assert candle[0].flame.bb.top - candle[0].body.bb.top == 26 mm, "flame tip 26 above the candle"
}
