# Request (toys): a yo-yo from 3 mm ply, glued up from a stack: two 56 mm side discs
# with a 6 mm axle hole and six 8 mm lightening holes on a 36 mm circle (kept
# symmetric so it spins true), a 5-point star (outer 10, inner 4) engraved in the
# centre of each; and two 20 mm spacer washers with a 6 mm bore that go between them
# on a 6 mm dowel to make the string gap.
import "std/shapes.aidl"
thickness 3 mm
kerf 0.15 mm

def side_disc() -> solid {
    disc = Circle(center=(0, 0), diameter=56)
    hole axle { c = Circle(center=(0, 0), diameter=6) }
    hole light { l = Circle(center=(18, 0), diameter=8) }
    ring = CircularPattern(light, 6, disc.center)
    drawing mark { s = Star(center=(0, 0), points=5, outer_radius=10, inner_radius=4) }
}

assembly yoyo {
    left = side_disc()
    right = side_disc()
    RightOf(right, left, gap=5)
    AlignCenterY(right, left)
    s1 = washer(outer=20 mm, inner=6 mm)
    s2 = washer(outer=20 mm, inner=6 mm)
    RightOf(s1, right, gap=5)
    RightOf(s2, s1, gap=5)
    AlignCenterY(s1, right)
    AlignCenterY(s2, right)
    assert left.disc.diameter == 56 mm, "56 mm discs"
    assert len(left.ring) == 6, "six lightening holes"
}
