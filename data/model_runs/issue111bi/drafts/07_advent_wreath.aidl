# Request: an advent wreath base for the dining table, for four 22 mm taper candles; I'll lay
# greenery round it and stand a glass bowl in the middle. 6 mm birch ply, glued.
# - two rings of the same outline: a 280 mm disc with 24 round scallops (7 mm radius, centred
#   on its edge) and a 170 mm opening in the middle;
# - the top ring has four 22.5 mm candle holes on a 240 mm circle, at 12, 3, 6 and 9 o'clock,
#   numbered 1 to 4 clockwise from the top (10 mm bold numbers engraved filled, on the 192 mm
#   circle, inside each hole), and eight small 5-point stars (16 mm across) engraved filled
#   halfway between each candle and the next spacer;
# - the candles go through the top ring and stand on the bottom ring, 40 mm below it;
# - four radial spacers 40 x 40 mm, between the candles (at 45 deg to them), each with one
#   20 mm tenon into a mortise in each ring.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
R_OUT = 140 mm
R_IN = 85 mm
R_CANDLE = 120 mm
GAP = 40 mm          # between the rings
SP_LEN = 40 mm       # a spacer's radial length

def ring(candles=false) -> solid {
    disc = Circle(center=(0, 0), radius=R_OUT)
    solid scallop {
        c = Circle(center=(0, R_OUT), radius=7)
    }
    scallops = CircularPattern(scallop, 24, disc.center)
    hole middle {
        c = Circle(center=(0, 0), radius=R_IN)
    }
    for k in range(4) {
        m = tab_and_slot(part="slot", length=SP_LEN, thickness=T, tabs=1, tab=20, screw=0,
                         rotation=45 deg + k * 90 deg,
                         cx=R_CANDLE * cos(45 deg + k * 90 deg),
                         cy=R_CANDLE * sin(45 deg + k * 90 deg))
    }
    if candles {
        for k in range(4) {
            hole candle {
                c = Circle(center=(R_CANDLE * cos(90 deg - k * 90 deg),
                                   R_CANDLE * sin(90 deg - k * 90 deg)), diameter=22.5)
            }
        }
        drawing deco {
            for k in range(4) {
                n = Text(str(k + 1), position=(96 * cos(90 deg - k * 90 deg),
                                               96 * sin(90 deg - k * 90 deg)),
                         size=10, font="sans:Bold", valign="middle", fill=true)
            }
            for m in range(8) {
                s = Star(center=(R_CANDLE * cos(22.5 deg + m * 45 deg),
                                 R_CANDLE * sin(22.5 deg + m * 45 deg)),
                         points=5, outer_radius=8, inner_radius=3.5, fill=true)
            }
        }
    }
}

# a spacer: x along the radius (its middle on the candle circle), y up
def spacer() -> solid {
    body = Rectangle(center=(0, 0), width=SP_LEN, height=GAP + 2 * T)
    top = tab_and_slot(part="tab", length=SP_LEN, thickness=T, tabs=1, tab=20, screw=0,
                       cx=0, cy=GAP / 2 + T)
    bottom = tab_and_slot(part="tab", length=SP_LEN, thickness=T, tabs=1, tab=20, screw=0,
                          rotation=180 deg, cx=0, cy=-(GAP / 2 + T))
}

assembly advent_wreath {
    top_ring = ring(candles=true)
    bottom_ring = ring(candles=false)
    for k in range(4) {
        sp = spacer()
        Place(sp, position=(R_CANDLE * cos(45 deg + k * 90 deg) - T / 2 * sin(45 deg + k * 90 deg),
                            R_CANDLE * sin(45 deg + k * 90 deg) + T / 2 * cos(45 deg + k * 90 deg),
                            T + GAP / 2),
              rotation=(90 deg, 0, 45 deg + k * 90 deg))
    }

    # on the sheet
    RightOf(bottom_ring, top_ring, gap=10)
    AlignCenterY(bottom_ring, top_ring)
    Below(sp[0], top_ring, gap=10)
    AlignLeft(sp[0], top_ring)
    for k in range(1, 4) {
        RightOf(sp[k], sp[k - 1], gap=10)
        AlignBottom(sp[k], sp[k - 1])
    }

    # in 3D
    Place(bottom_ring, position=(0, 0, 0))
    Place(top_ring, position=(0, 0, T + GAP))

    # the request's numbers
    assert top_ring.disc.diameter == 280 mm and top_ring.scallop.c.radius == 7 mm, "280 disc, r7 scallops"
    assert len(top_ring.scallops) == 24, "24 scallops"
    assert top_ring.middle.c.diameter == 170 mm, "170 opening"
    assert len(top_ring.candle) == 4, "four candles"
    assert top_ring.candle[0].c.diameter == 22.5 mm, "22.5 mm candle holes"
    assert distance(top_ring.candle[0].c.center, top_ring.candle[2].c.center) == 240 mm,
        "candles on a 240 circle"
    assert top_ring.candle[0].c.center.y - top_ring.disc.center.y == 120 mm, "candle 1 at the top"
    assert top_ring.candle[1].c.center.x - top_ring.disc.center.x == 120 mm, "candle 2 at 3 o'clock"
    assert distance(top_ring.deco.n[0].position, top_ring.disc.center) == 96 mm, "numbers on the 192 circle"
    assert len(top_ring.deco.s) == 8, "eight stars"
    assert sp[0].body.bb.width == 40 mm and sp[0].body.bb.height - 2 * T == 40 mm, "spacers 40 x 40"
    assert len(sp) == 4, "four spacers"
}
