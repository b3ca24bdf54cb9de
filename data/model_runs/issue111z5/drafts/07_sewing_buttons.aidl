# Crafts: a sheet of wooden sewing buttons, 3 mm birch plywood, 12 separate buttons. 6 round
# buttons 25 mm across with 4 thread holes 2 mm across on a 7 mm square round the centre and an
# engraved rim ring 21 mm across; 6 flower buttons: a 6-point star, outer radius 13 mm, inner
# radius 10 mm, tips rounded R3, with 2 thread holes 2 mm across 5 mm apart (side by side) and an
# engraved circle 8 mm across round them. Each kind in 2 rows of 3 on a 30 mm grid; the flowers'
# first button 100 mm right of the first round one.
thickness 3 mm

def round_button() -> solid {
    disc = Circle(center=(0, 0), diameter=25)
    hole threads {
        for i in range(4) {
            c = Circle(center=(-3.5 + 7 * (i % 2), -3.5 + 7 * (i // 2)), diameter=2)
        }
    }
    drawing rim { r = Circle(center=(0, 0), diameter=21) }
}

def flower_button() -> solid {
    s = Star(center=(0, 0), points=6, outer_radius=13, inner_radius=10, tip_radius=3)
    hole threads {
        a = Circle(center=(-2.5, 0), diameter=2)
        b = Circle(center=(2.5, 0), diameter=2)
    }
    drawing ring { r = Circle(center=(0, 0), diameter=8) }
}

assembly buttons {
    first_round = round_button()
    rounds = GridPattern(first_round, 2, 3, 30)
    first_flower = flower_button()
    flowers = GridPattern(first_flower, 2, 3, 30)
    # after the first valid check: `first_flower.s.center == (100, 0)` moved the star alone, off
    # its holes and ring (W0502, W0505); `first_flower.bb.center == (100, 0)` moved the star alone
    # too (E0405: 193 mm): make each instance one rigid body and place it by its main shape
    Rigid(first_round)
    Rigid(first_flower)
    first_round.disc.center == (0 mm, 0 mm)
    first_flower.s.center == (100 mm, 0 mm)

    assert len(rounds) + len(flowers) == 12, "12 buttons"
    assert len(rounds) == 6 and len(flowers) == 6, "6 of each"
    assert first_round.disc.diameter == 25 mm, "round 25 mm"
    assert first_round.threads.c[0].diameter == 2 mm, "2 mm holes"
    assert first_round.threads.c[1].center.x - first_round.threads.c[0].center.x == 7 mm, "7 mm square"
    assert first_round.threads.c[2].center.y - first_round.threads.c[0].center.y == 7 mm, "7 mm square"
    assert first_round.rim.r.diameter == 21 mm, "rim ring 21"
    assert first_flower.s.outer_radius == 13 mm and first_flower.s.inner_radius == 10 mm, "star 13 / 10"
    assert first_flower.threads.b.center.x - first_flower.threads.a.center.x == 5 mm, "5 mm apart"
    assert rounds[1].disc.center.x - rounds[0].disc.center.x == 30 mm, "30 mm grid"
    assert first_flower.s.center.x - first_round.disc.center.x == 100 mm, "flowers 100 right"
}
