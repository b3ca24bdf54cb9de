# Request (garden): a rolling trolley for a heavy patio pot, in 9 mm exterior ply. A round
# deck 300 mm across with eight 12 mm drain holes on a 180 mm circle, set between the
# runners (the first 22.5 deg off the x axis). Four swivel castors (top plate 50 x 50,
# four M6 holes on a 38 x 38 square, 50 mm tall) screwed up through the deck with M6
# countersunk bolts (12 mm heads), their centres 110 mm out on the diagonals. Under the
# deck two cross-halved runners 280 long, 40 deep below the deck, stiffen it; each is
# glued up into the deck by two 20 mm through tenons. Three parts.

import "std/joints.aidl"

thickness 9 mm

param deck_d = 300 mm, min = 240 mm, max = 400 mm
castor_r = 110 mm
castor_h = 50 mm
runner_len = 280 mm
runner_depth = 40 mm

# the four bolt holes of one castor's top plate
def castor_mount() -> hole {
    for i in range(4) {
        c = Circle(center=(19 * (1 if i % 2 == 0 else -1), 19 * (1 if i < 2 else -1)),
                   diameter=6.6)
    }
}

# a runner seen from the side: its bottom edge at y = 0, the deck's underside at y = 40,
# the tenons' tips at 49 (through the deck); `from_top` says where its halving slot opens
def runner(from_top=true) -> solid {
    body = Rectangle(bottom_left=(-runner_len / 2, 0), width=runner_len,
                     height=runner_depth + 9 mm)
    tenons = tab_and_slot(part="tab", length=runner_len, thickness=9 mm, tabs=2, tab=20 mm,
                          screw=0, rotation=0 deg, cx=0 mm, cy=runner_depth + 9 mm)
    if from_top {
        halving = cross_halving(depth=20 mm, thickness=9 mm, rotation=0 deg, cx=0 mm,
                                cy=runner_depth)
    } else {
        halving = cross_halving(depth=20 mm, thickness=9 mm, rotation=180 deg, cx=0 mm,
                                cy=0 mm)
    }
}

assembly trolley {
    solid deck {
        disc = Circle(center=(0, 0), diameter=deck_d)
        hole drain {
            c = Circle(center=(90 * cos(22.5 deg), 90 * sin(22.5 deg)), diameter=12)
        }
        drains = CircularPattern(drain, 8, disc.center)
        castor = castor_mount()
        castor.bb.center_x == castor_r * cos(45 deg)
        castor.bb.center_y == castor_r * sin(45 deg)
        castors = CircularPattern(castor, 4, disc.center)
        Countersink(castor, diameter=12 mm)
        along_x = tab_and_slot(part="slot", length=runner_len, thickness=9 mm, tabs=2,
                               tab=20 mm, screw=0, rotation=0 deg, cx=0 mm, cy=0 mm)
        along_y = tab_and_slot(part="slot", length=runner_len, thickness=9 mm, tabs=2,
                               tab=20 mm, screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
    }
    runner_x = runner(from_top=true)
    runner_y = runner(from_top=false)

    # flat on the sheet: the runners beside the deck
    RightOf(runner_x, deck, gap=10)
    AlignTop(runner_x, deck)
    RightOf(runner_y, deck, gap=10)
    Below(runner_y, runner_x, gap=10)

    # in 3D: the deck on its castors, the runners under it, tenons through it
    Place(deck, position=(0, 0, castor_h), face="up")
    Place(runner_x, position=(0, 4.5, castor_h - runner_depth), face="front", up="up")
    Place(runner_y, position=(-4.5, 0, castor_h - runner_depth), face="right", up="up")

    assert deck.disc.diameter == 300 mm, "deck 300 across"
    assert len(deck.drains) == 8, "eight drain holes"
    assert deck.drain.c.diameter == 12 mm, "drain holes 12"
    assert distance(deck.drain.c.center, deck.disc.center) == 180 mm / 2, "on a 180 circle"
    assert len(deck.castors) == 4, "four castors"
    assert distance(deck.castor.bb.center, deck.disc.center) == 110 mm, "castors 110 out"
    assert deck.castor.c[1].center.x - deck.castor.c[0].center.x == -38 mm, "38 square"
    assert runner_x.body.bb.width == 280 mm, "runners 280 long"
    assert castor_h - runner_depth >= 5 mm, "runners clear the floor"
    assert deck.along_x.slot[0].bb.width == 20 mm, "20 mm tenons"
}
