# Request (pets): a foraging wheel for Kiwi the cockatiel, in 4 mm birch ply. A 200 x 200 mm
# base plate (10 mm corners) that cable-ties to the cage floor grid through four 5 mm holes
# 12 mm in from the corners; on it a glued pocket ring, a 160 mm disc with eight 26 mm treat
# pockets on a 110 mm circle; on top a spinner that turns on an M6 bolt through the centre
# (6.5 mm hole in base and ring, 7 mm in the spinner). The spinner is a 156 mm disc with
# sixteen 12 mm round lugs on its rim (centres on a 156 mm circle) for the beak to pull,
# two 26 mm windows opposite each other over the pockets' circle, "KIWI" engraved filled in
# bold 14 mm tall above the bolt and "TURN ME" in 5 mm strokes below it.

thickness 4 mm

pocket_circle = 110 mm
pocket_d = 26 mm

assembly foraging_wheel {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=200, height=200, corner_radius=10)
        Fixed(plate)
        hole tie { c = Circle(center=(0, 0), diameter=5) }
        ties = CornerPattern(tie, plate, inset=12)
        hole bolt { c = Circle(center=(0, 0), diameter=6.5) }
        assert plate.bb.width == 200 mm and plate.bb.height == 200 mm, "base 200 x 200"
        assert ties[0].c.center.x - plate.bb.left == 12 mm, "ties 12 mm in"
        assert ties[0].c.center.y - plate.bb.bottom == 12 mm, "ties 12 mm in"
    }

    solid pockets {
        disc = Circle(center=(0, 0), diameter=160)
        Fixed(disc)
        hole pocket { c = Circle(center=(pocket_circle / 2, 0), diameter=pocket_d) }
        ring = CircularPattern(pocket, 8, (0, 0))
        hole bolt { c = Circle(center=(0, 0), diameter=6.5) }
        assert len(ring) == 8, "eight pockets"
        assert distance(ring[3].c.center, disc.center) == pocket_circle / 2, "on a 110 mm circle"
        assert distance(ring, disc.center) > 0 mm, "pockets clear of the middle"
    }

    solid spinner {
        disc = Circle(center=(0, 0), diameter=156)
        Fixed(disc)
        lug = Circle(center=(78, 0), diameter=12)
        lugs = CircularPattern(lug, 16, (0, 0))
        hole window { c = Circle(center=(pocket_circle / 2, 0), diameter=pocket_d) }
        windows = CircularPattern(window, 2, (0, 0))
        hole bolt { c = Circle(center=(0, 0), diameter=7) }
        drawing name {
            t = Text("KIWI", (0, 22), size=14, font="sans:Bold", fill=true)
        }
        drawing hint {
            t = Text("TURN ME", (0, -30), size=5)
        }
        assert len(lugs) == 16, "sixteen lugs"
        assert distance(windows[1].c.center, disc.center) == pocket_circle / 2,
            "windows over the pockets' circle"
        assert distance(windows[0].c.center, windows[1].c.center) == pocket_circle,
            "windows opposite each other"
        assert distance(name, windows) >= 3 mm and distance(name, bolt) >= 3 mm,
            "the name clears the windows and the bolt"
        assert distance(hint, windows) >= 3 mm and distance(hint, bolt) >= 3 mm,
            "the hint clears the windows and the bolt"
    }

    RightOf(pockets, base, gap=6)
    AlignTop(pockets, base)
    Below(spinner, pockets, gap=6)
    AlignLeft(spinner, pockets)

    Place(base, position=(0, 0, 0))
    Place(pockets, position=(0, 0, 4))
    Place(spinner, position=(0, 0, 8))

    assert pockets.disc.diameter < base.plate.bb.width, "the ring sits on the base"
    assert spinner.disc.diameter + 12 mm > pockets.disc.diameter, "the lugs stand past the ring"
    assert spinner.bolt.c.diameter > base.bolt.c.diameter, "the spinner turns on the bolt"
}
