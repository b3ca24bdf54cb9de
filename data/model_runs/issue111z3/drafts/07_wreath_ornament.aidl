# Holiday wreath ornament, 3 mm birch ply: a ring 100 mm across outside and 70 mm inside, with 20
# oval leaves (14 x 7 mm) evenly round it, centred on a 48 mm radius and tilted 45 deg to the rim so
# the edge looks leafy. "NOEL" across the opening in sans Bold letters 14 mm high (material), their
# middle on the ring's centre, standing on a 4 mm rail that runs from one side of the ring to the
# other. A bow at the bottom of the ring: two triangular loops 14 mm long and 16 mm tall and a 7 mm
# knot. A hanging tab at the top: a 12 mm disc centred 54 mm above the ring's centre with a 4 mm hole.

units mm
thickness 3 mm

param leaves = 20, min = 12, max = 28

solid wreath {
    solid ring {
        outer = Circle(center=(0, 0), diameter=100)
        hole opening {
            c = Circle(center=(0, 0), diameter=70)
        }
    }

    leaf = Ellipse(center=(48, 0), rx=7, ry=3.5, rotation=45 deg)
    all_leaves = CircularPattern(leaf, leaves, ring.outer.center)

    word = Text("NOEL", position=(0, 0), size=14, font="sans:Bold", valign="middle")
    rail = Rectangle(center=(0, -8), width=72, height=4)

    # fix after the first picture: with the knot on the rim (y -50) the loops' upper halves were
    # buried in the ring and the bow read as a notched tab. The bow now hangs below the rim (knot
    # at y -55), and a filler joins it to the rim so no sliver is left between the loops and the ring
    knot = Circle(center=(0, -55), diameter=7)
    loop_l = Triangle((0, -55), (-14, -47), (-14, -63))
    loop_r = Triangle((0, -55), (14, -47), (14, -63))
    filler = Rectangle(center=(0, -51), width=22, height=8)

    tab = Circle(center=(0, 54), diameter=12)
    hole hanger {
        c = Circle(center=(0, 54), diameter=4)
    }

    assert ring.outer.diameter == 100 mm and ring.opening.c.diameter == 70 mm, "ring 100 / 70"
    assert len(all_leaves) == 20, "20 leaves"
    assert leaf.rx * 2 == 14 mm and leaf.ry * 2 == 7 mm, "leaves 14 x 7"
    assert word.size == 14 mm, "letters 14 high"
    assert word.position.y == ring.outer.center.y, "the word's middle on the centre"
    assert rail.bb.height == 4 mm, "rail 4"
    assert rail.bb.width > ring.opening.c.diameter, "the rail reaches the ring on both sides"
    assert loop_r.bb.width == 14 mm and loop_r.bb.height == 16 mm, "bow loops 14 x 16"
    assert knot.diameter == 7 mm, "7 mm knot"
    assert tab.center.y - ring.outer.center.y == 54 mm, "tab 54 above the centre"
    assert hanger.c.diameter == 4 mm and tab.diameter == 12 mm, "12 mm tab, 4 mm hole"
}
