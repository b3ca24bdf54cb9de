# Request: a round ball-track toy for my cat: a 40 mm ping-pong ball runs round a closed ring
# channel and the cat bats it through paw holes in the top. Glued stack of ply:
# - a 6 mm base disc, 260 mm across;
# - the channel walls in 12 mm ply, four layers high (48 mm, the ball is 40): an outer ring
#   260 / 230 mm and an inner ring 140 / 90 mm (cut 4 of each; the inner ring nests in the
#   outer ring's offcut), leaving a channel 45 mm wide;
# - a 6 mm top ring 260 / 90 mm with six oval paw holes 60 mm long (along the channel) and
#   34 mm wide (narrower than the ball, so it can't come out), centred over the channel, and
#   the cat's name MOCHI engraved round the rim at the bottom, 8 mm letters;
# - three 4 mm dowel holes through every layer on each wall (in the middle of the wall, at
#   120 deg) so the stack lines up when gluing.

units mm
thickness 6 mm

BALL = 40 mm
OUT_R = 130 mm
CH_OUT = 115 mm     # the channel's outer radius
CH_IN = 70 mm       # the channel's inner radius
IN_R = 45 mm        # the centre well
LAYER = 12 mm
LAYERS = 4
PIN_OUT = (OUT_R + CH_OUT) / 2
PIN_IN = (CH_IN + IN_R) / 2

def pin(r=50 mm) -> hole {
    c = Circle(center=(0, r), diameter=4)
}

assembly cat_track {
    solid base {
        disc = Circle(center=(0, 0), radius=OUT_R)
        po = pin(r=PIN_OUT)
        CircularPattern(po, 3, disc.center)
        pi_ = pin(r=PIN_IN)
        CircularPattern(pi_, 3, disc.center)
    }

    for i in range(LAYERS) {
        solid outer {
            thickness 12 mm
            edge = Circle(center=(0, 0), radius=CH_OUT, construction=true)
            wall = Shell(edge, OUT_R - CH_OUT)
            p = pin(r=PIN_OUT)
            CircularPattern(p, 3, edge.center)
        }
        solid inner {
            thickness 12 mm
            edge = Circle(center=(0, 0), radius=IN_R, construction=true)
            wall = Shell(edge, CH_IN - IN_R)
            p = pin(r=PIN_IN)
            CircularPattern(p, 3, edge.center)
        }
        Place(outer, position=(0, 0, 6 + LAYER * i))
        Place(inner, position=(0, 0, 6 + LAYER * i))
    }

    solid top {
        disc = Circle(center=(0, 0), radius=OUT_R)
        hole well {
            c = Circle(center=(0, 0), radius=IN_R)
        }
        hole paw {
            e = Ellipse(center=(0, (CH_OUT + CH_IN) / 2), rx=30, ry=17)
        }
        paws = CircularPattern(paw, 6, disc.center)
        po = pin(r=PIN_OUT)
        CircularPattern(po, 3, disc.center)
        pi_ = pin(r=PIN_IN)
        CircularPattern(pi_, 3, disc.center)
        drawing name {
            rim = Circle(center=(0, 0), radius=OUT_R - 3, construction=true)
            t = Text("MOCHI", along=rim, angle=270 deg, flip=true, size=8)
        }
    }

    # on the sheet: the rings in a row, each inner ring in its outer ring's middle;
    # base and top in a second row
    for i in range(1, LAYERS) {
        RightOf(outer[i], outer[i - 1], gap=10)
        AlignCenterY(outer[i], outer[i - 1])
    }
    for i in range(LAYERS) {
        AlignCenterX(inner[i], outer[i])
        AlignCenterY(inner[i], outer[i])
    }
    Below(base, outer[0], gap=10)
    AlignLeft(base, outer[0])
    RightOf(top, base, gap=10)
    AlignCenterY(top, base)

    # in 3D: the stack
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 6 + LAYER * LAYERS))

    # the request's numbers
    assert base.disc.diameter == 260 mm, "260 mm across"
    assert 2 * outer[0].edge.radius == 230 mm, "outer ring 260 / 230"
    assert 2 * inner[0].edge.radius == 90 mm, "inner ring 140 / 90"
    assert 2 * (inner[0].edge.radius + CH_IN - IN_R) == 140 mm, "inner ring 140"
    assert CH_OUT - CH_IN == 45 mm, "channel 45 wide"
    assert LAYER * LAYERS == 48 mm and LAYER * LAYERS > BALL, "walls 48 high, above the ball"
    assert len(outer) == 4 and len(inner) == 4, "four layers"
    assert len(top.paws) == 6, "six paw holes"
    assert 2 * top.paw.e.rx == 60 mm and 2 * top.paw.e.ry == 34 mm, "paw holes 60 x 34"
    assert 2 * top.paw.e.ry < BALL, "the ball cannot come out of a paw hole"
    assert top.paw.e.center.y - top.paw.e.ry > CH_IN and top.paw.e.center.y + top.paw.e.ry < CH_OUT,
        "paw holes over the channel"
    assert top.name.t.size == 8 mm, "8 mm letters"
}
