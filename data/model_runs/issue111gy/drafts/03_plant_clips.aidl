# Request: a sheet of 12 plant clips to hold tomato stems to 10 mm bamboo canes, cut from 2 mm
# polypropylene. Each clip is a figure-eight: a small ring (10 mm bore, 3 mm wall) that snaps
# onto the cane through an 8 mm mouth, joined by a solid bridge to a big ring (22 mm bore,
# 3 mm wall) that holds the stem loosely, with a 3 mm entry gap on the far side that the stem
# is pushed through. 3 rows of 4, 6 mm apart on the sheet.

units mm
thickness 2 mm
kerf 0.1 mm

cane = 10 mm
stem = 22 mm
w = 3 mm

def clip() -> solid {
    cane_ring = Circle(center=(0, 0), diameter=cane + 2 * w)
    stem_ring = Circle(center=(cane / 2 + w + stem / 2 + w, 0), diameter=stem + 2 * w)
    bridge = Rectangle(center=(cane / 2 + w, 0), width=2 * w, height=8)
    hole cane_bore {
        c = Circle(center=(0, 0), diameter=cane)
        # the snap mouth: an 8 mm chord of the bore, open to the left
        mouth = Rectangle(center=(-cane / 2 - 1, 0), width=2 * w + 2, height=8)
    }
    hole stem_bore {
        c = Circle(center=(cane / 2 + w + stem / 2 + w, 0), diameter=stem)
        gap = Rectangle(center=(cane / 2 + w + stem + w + w / 2, 0), width=2 * w + 2, height=3)
    }
    assert cane_bore.mouth.height == 8 mm, "8 mm snap mouth"
    assert stem_bore.gap.height == 3 mm, "3 mm entry gap"
    assert stem_ring.diameter - stem_bore.c.diameter == 2 * 3 mm, "3 mm wall on the stem ring"
    assert cane_ring.diameter - cane_bore.c.diameter == 2 * 3 mm, "3 mm wall on the cane ring"
}

assembly clips {
    first = clip()
    all = GridPattern(first, 3, 4, (first.bb.width + 6 mm, first.bb.height + 6 mm))
    assert len(all) == 12, "12 clips"
}
