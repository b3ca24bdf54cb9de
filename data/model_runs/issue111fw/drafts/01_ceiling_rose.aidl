# REQUEST (home): a decorative ceiling rose to go round the canopy of a pendant light, two
# layers of birch ply glued together. Back layer, 6 mm: 240 mm across, a scalloped edge of
# 16 round lobes 30 mm across whose centres lie on a 210 mm circle (the body is a 210 mm
# disc); an 80 mm centre opening for the light's canopy; 16 teardrop piercings pointing out
# at the lobes, each 10 mm wide, from 65 mm out from the centre to its tip 92 mm out; four
# countersunk holes for 4 mm wood screws (4.5 mm through, 9 mm heads) on a 110 mm circle at
# 45 deg. Front layer, 3 mm: a 12-pointed star, points on a 150 mm circle and notches on a
# 124 mm circle, tips rounded R4, the same 80 mm opening; it is glued on last and must hide
# the screw heads. Shown stacked as in use.
# FIX after the first valid program: the first valid program's star (points on a 150 mm
# circle) covered the round heads of the teardrops (65 mm out) in the stack; the request is
# changed to a star with points on a 128 mm circle and notches on a 112 mm circle, clear of
# the teardrops, and screws on a 96 mm circle so the star still hides their 9 mm heads. The
# two parts are also laid side by side on the flat drawing (W0511).

units mm

assembly rose {
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
            c = Circle(center=(48 * cos(45 deg), 48 * sin(45 deg)), diameter=4.5)
        }
        screws = CircularPattern(screw, 4, (0, 0))
        Countersink(screws, diameter=9)
    }

    solid front {
        thickness 3 mm
        star = Star(center=(0, 0), points=12, outer_radius=64, inner_radius=56, tip_radius=4)
        hole opening {
            c = Circle(center=(0, 0), diameter=80)
        }
    }

    RightOf(front, back, gap=10)
    AlignCenterY(front, back)
    Place(back, position=(0, 0, 0))
    Place(front, on=back, position=(0, 0))
}

# the request's numbers
assert rose.back.bb.width == 240 mm, "240 mm across the lobes"
assert rose.back.disc.diameter == 210 mm, "the body is a 210 mm disc"
assert len(rose.back.lobes) == 16, "16 lobes"
assert rose.back.lobe.c.diameter == 30 mm, "lobes 30 mm across"
assert len(rose.back.drops) == 16, "16 teardrops"
assert rose.back.drop.h.bb.left == 65 mm, "teardrops start 65 mm out"
assert rose.back.drop.h.bb.right == 92 mm, "teardrop tips 92 mm out"
assert rose.back.drop.h.bb.height == 10 mm, "teardrops 10 mm wide"
assert len(rose.back.screws) == 4, "four screws"
assert distance(rose.back.screws[0].c.center, rose.back.screws[2].c.center) == 96 mm, "screws on a 96 mm circle"
assert rose.back.opening.c.diameter == 80 mm and rose.front.opening.c.diameter == 80 mm, "80 mm openings"
assert rose.front.star.outer_radius == 128 mm / 2 and rose.front.star.inner_radius == 112 mm / 2, "star 128 / 112"
# the front hides the screw heads: each 9 mm head lies inside the star's notch circle
assert 96 mm / 2 + 9 mm / 2 < rose.front.star.inner_radius, "front hides the screw heads"
# the star leaves the teardrops clear
assert rose.front.star.outer_radius < 65 mm, "teardrops clear of the star"
