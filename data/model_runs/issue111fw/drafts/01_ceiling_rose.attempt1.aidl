# REQUEST (home): a decorative ceiling rose to go round the canopy of a pendant light, two
# layers of birch ply glued together. Back layer, 6 mm: 240 mm across, a scalloped edge of
# 16 round lobes 30 mm across whose centres lie on a 210 mm circle (the body is a 210 mm
# disc); an 80 mm centre opening for the light's canopy; 16 teardrop piercings pointing out
# at the lobes, each 10 mm wide, from 65 mm out from the centre to its tip 92 mm out; four
# countersunk holes for 4 mm wood screws (4.5 mm through, 9 mm heads) on a 110 mm circle at
# 45 deg. Front layer, 3 mm: a 12-pointed star, points on a 150 mm circle and notches on a
# 124 mm circle, tips rounded R4, the same 80 mm opening; it is glued on last and must hide
# the screw heads. Shown stacked as in use.

units mm

solid back {
    thickness 6 mm
    disc = Circle(center=(0, 0), diameter=210)
    solid lobe {
        c = Circle(center=(105, 0), diameter=30)
    }
    lobes = CircularPattern(lobe, 16, (0, 0))

    hole opening {
        c = Circle(center=(0, 0), diameter=80)
    }
    hole drop {
        h = Hull(Circle(center=(70, 0), radius=5), Point(92, 0))
    }
    drops = CircularPattern(drop, 16, (0, 0))

    hole screw {
        c = Circle(center=(55 * cos(45 deg), 55 * sin(45 deg)), diameter=4.5)
    }
    screws = CircularPattern(screw, 4, (0, 0))
    Countersink(screws, diameter=9)
}

solid front {
    thickness 3 mm
    star = Star(center=(0, 0), points=12, outer_radius=75, inner_radius=62, tip_radius=4)
    hole opening {
        c = Circle(center=(0, 0), diameter=80)
    }
}

assembly rose {
    b = back
    f = front
    Place(b, position=(0, 0, 0))
    Place(f, on=b, position=(0, 0))
}

# the request's numbers
assert back.bb.width == 240 mm, "240 mm across the lobes"
assert back.disc.diameter == 210 mm, "the body is a 210 mm disc"
assert len(back.lobes) == 16, "16 lobes"
assert back.lobe.c.diameter == 30 mm, "lobes 30 mm across"
assert len(back.drops) == 16, "16 teardrops"
assert back.drop.h.bb.left == 65 mm, "teardrops start 65 mm out"
assert back.drop.h.bb.right == 92 mm, "teardrop tips 92 mm out"
assert back.drop.h.bb.height == 10 mm, "teardrops 10 mm wide"
assert len(back.screws) == 4, "four screws"
assert distance(back.screws[0].c.center, back.screws[2].c.center) == 110 mm, "screws on a 110 mm circle"
assert back.opening.c.diameter == 80 mm and front.opening.c.diameter == 80 mm, "80 mm openings"
assert front.star.outer_radius == 75 mm and front.star.inner_radius == 62 mm, "star 150 / 124"
# the front hides the screw heads: each 9 mm head lies inside the star's notch circle
assert 110 mm / 2 + 9 mm / 2 < front.star.inner_radius, "front hides the screw heads"
