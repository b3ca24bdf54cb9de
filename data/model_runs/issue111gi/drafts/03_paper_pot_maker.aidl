# Request: a newspaper seed-pot maker ("pot roller"), 6 mm ply discs glued up.
# - Former: a 50 mm cylinder 66 mm tall: eleven 50 mm discs threaded on an 8 mm dowel
#   (8.2 mm holes); the bottom disc has a 22 mm hole instead, the hollow the paper's folded
#   bottom is pressed into. The pots come out 50 mm across and up to 60 mm tall.
# - Handle: three grip discs glued on the dowel above the former: two 36 mm discs and a top
#   6-point flower (tips at 20 mm radius, notches at 15 mm, tips rounded R4) with a seedling
#   (a stem and two leaves) engraved.
# - Press base: an 80 mm bottom disc, an 80 mm ring on it with a 53 mm hole (the former plus
#   two layers of newspaper) and a 20 mm boss disc glued in the middle of the bottom disc that
#   pushes the paper into the former's hollow; "PAPER POTS" engraved round the ring's top face.

thickness 6 mm

def disc(d=50 mm, bore=8.2 mm) -> solid {
    c = Circle(center=(0, 0), diameter=d)
    hole b { h = Circle(center=(0, 0), diameter=bore) }
}

assembly pot_maker {
    # the former: the bottom disc with the hollow, then ten on the dowel
    former_bottom = disc(d=50 mm, bore=22 mm)
    for i in range(10) {
        former = disc(d=50 mm, bore=8.2 mm)
        former.bb.center == (-60 + 60 * i, -70)
        Place(former, position=(0, 0, 12 + 6 * i), face="up")
    }
    grip_low = disc(d=36 mm, bore=8.2 mm)
    grip_mid = disc(d=36 mm, bore=8.2 mm)

    solid grip_top {
        flower = Star(center=(0, 0), points=6, outer_radius=20, inner_radius=15, tip_radius=4)
        drawing seedling {
            stem = Line((0, -9), (0, 4))
            leaf_l = Ellipse(center=(-4, 6), rx=5, ry=2.5, rotation=-30 deg)
            leaf_r = Ellipse(center=(4, 7), rx=5, ry=2.5, rotation=30 deg)
        }
        Fixed(flower)
    }

    solid base_bottom {
        c = Circle(center=(0, 0), diameter=80)
    }
    solid base_ring {
        c = Circle(center=(0, 0), diameter=80)
        hole well { h = Circle(center=(0, 0), diameter=53) }
        drawing words {
            ring = Circle(center=(0, 0), radius=33, construction=true)
            t = Text("PAPER POTS", along=ring, size=6, valign="middle")
        }
        Fixed(c)
    }
    solid boss {
        c = Circle(center=(0, 0), diameter=20)
    }

    # flat on the sheet: a row of base parts, a row of former discs
    base_bottom.bb.center == (0, 0)
    base_ring.bb.center == (90, 0)
    boss.bb.center == (150, 0)
    former_bottom.bb.center == (190, 0)
    grip_low.bb.center == (245, 0)
    grip_mid.bb.center == (290, 0)
    grip_top.flower.center == (340, 0)

    # in 3D: the former stands in the base, as when pressing a pot's bottom
    Place(base_bottom, position=(0, 0, 0), face="up")
    Place(base_ring, position=(0, 0, 6), face="up")
    Place(boss, position=(0, 0, 6), face="up")
    Place(former_bottom, position=(0, 0, 6), face="up")
    Place(grip_low, position=(0, 0, 72), face="up")
    Place(grip_mid, position=(0, 0, 78), face="up")
    Place(grip_top, position=(0, 0, 84), face="up")

    assert len(former) + 1 == 11, "eleven former discs"
    assert (len(former) + 1) * 6 mm == 66 mm, "former 66 tall"
    assert 66 mm >= 60 mm, "taller than the pot"
    assert former[0].c.diameter == 50 mm and former_bottom.c.diameter == 50 mm, "former 50"
    assert base_ring.well.h.diameter == 53 mm, "ring hole 53"
    assert boss.c.diameter == 20 mm and former_bottom.b.h.diameter == 22 mm, "boss in the hollow"
    assert base_bottom.c.diameter == 80 mm and base_ring.c.diameter == 80 mm, "base 80"
}
