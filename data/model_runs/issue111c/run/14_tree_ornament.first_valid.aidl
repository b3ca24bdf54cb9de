# Christmas-tree ornament: three stacked triangular tiers (bases 70, 55 and
# 40 mm, each 28 mm tall, each overlapping the one below by 8 mm), a 10 x 10 mm
# trunk under the bottom tier, a five-pointed star (outer radius 9 mm) on top
# overlapping the top tier's tip by 3 mm, and a 3 mm hanging hole in the
# star's center; six 4 mm round "baubles" cut out of the tiers.
thickness 3 mm

solid tree {
    t1 = Triangle(center=(0, 14), base=70, height=28)
    t2 = Triangle(center=(0, 34), base=55, height=28)
    t3 = Triangle(center=(0, 54), base=40, height=28)
    trunk = Rectangle(center=(0, -5), width=10, height=10)
    star = Star(center=(0, 70), points=5, outer_radius=9, inner_radius=4)
    Below(trunk, t1)
    AlignCenterX(trunk, t1)
    VerticalDistance(t1.a, t2.a, 20)
    VerticalDistance(t2.a, t3.a, 20)
    AlignCenterX(t2, t1)
    AlignCenterX(t3, t1)
    star.bb.bottom == t3.c.y - 3 mm
    AlignCenterX(star, t1)
    hole hang {
        c = Circle(center=(0, 70), diameter=3)
    }
    Concentric(hang.c, star.center)
    hole baubles {
        b1 = Circle(center=(-15, 6), diameter=4)
        b2 = Circle(center=(12, 10), diameter=4)
        b3 = Circle(center=(-8, 27), diameter=4)
        b4 = Circle(center=(9, 30), diameter=4)
        b5 = Circle(center=(-4, 47), diameter=4)
        b6 = Circle(center=(5, 51), diameter=4)
    }
}

assert tree.t1.bb.width == 70 mm and tree.t2.bb.width == 55 mm and tree.t3.bb.width == 40 mm, "tier bases"
assert tree.t1.bb.top - tree.t2.bb.bottom == 8 mm, "tiers overlap 8 mm"
assert tree.t2.bb.top - tree.t3.bb.bottom == 8 mm, "tiers overlap 8 mm"
assert tree.trunk.bb.width == 10 mm and tree.trunk.bb.height == 10 mm, "10 x 10 trunk"
assert tree.t3.bb.top - tree.star.bb.bottom == 3 mm, "star overlaps 3 mm"
assert tree.star.outer_radius == 9 mm, "star r 9"
