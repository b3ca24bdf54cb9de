# Garden: a sunflower fence-post topper, 6 mm exterior plywood. A head of 16 petals (ellipses
# 56 x 22 mm, their centres 55 mm from the flower's centre, so the head is 166 mm across)
# round a 70 mm disc; the disc's edge engraved as a circle and its seeds engraved as 60 small
# circles 2 mm across in a sunflower spiral (radius 4.2 mm x sqrt(i), 137.5 deg apart). A
# stem 16 mm wide and 200 mm long (R8 ends) from 25 mm below the centre, two leaves (ellipses
# 48 x 18 mm at 30 deg) either side at 150 mm below the centre, and 2 screw holes 4.5 mm
# countersunk 9 mm in the stem, 120 and 200 mm below the centre.
thickness 6 mm
# After the first valid check: W0519 (a 0.2 mm slit at the tip of one petal notch) is the sharp V
# between two petals, meant; accepted with min_wall as the prompt says, no size changed.
min_wall 0.2 mm

petals = 16
seeds = 60

solid sunflower {
    disc = Circle(center=(0, 0), diameter=70)
    petal = Ellipse(center=(55, 0), rx=28, ry=11)
    ring = CircularPattern(petal, petals, disc.center)

    stem = RoundedRectangle(center=(0, -125), width=16, height=200, corner_radius=8)
    leaf_r = Ellipse(center=(22, -150), rx=24, ry=9, rotation=30 deg)
    leaf_l = Ellipse(center=(-22, -150), rx=24, ry=9, rotation=-30 deg)

    hole screw {
        a = Circle(center=(0, -120), diameter=4.5)
        b = Circle(center=(0, -200), diameter=4.5)
    }
    Countersink(screw, diameter=9)

    drawing face {
        edge = Circle(center=(0, 0), diameter=70)
        for i in range(1, seeds + 1) {
            s = Circle(center=polar((0, 0), 4.2 mm * sqrt(i), i * 137.5 deg), diameter=2)
        }
    }

    assert len(ring) == 16, "16 petals"
    assert petal.rx * 2 == 56 mm and petal.ry * 2 == 22 mm, "petals 56 x 22"
    assert ring[4].bb.top - ring[12].bb.bottom == 166 mm, "head 166 across"
    assert disc.diameter == 70 mm, "disc 70"
    assert len(face.s) == 60, "60 seeds"
    assert stem.width == 16 mm and stem.height == 200 mm, "stem 16 x 200"
    assert disc.center.y - stem.bb.top == 25 mm, "stem from 25 below the centre"
    assert disc.center.y - screw.a.center.y == 120 mm and disc.center.y - screw.b.center.y == 200 mm, "screws at 120 and 200"
}
