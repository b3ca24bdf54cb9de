# Garden: weather-vane arrow in 3 mm aluminium-composite, 400 mm overall. A shaft 300 x 12 mm;
# an arrow head 60 mm across its base and 70 mm long, pointing +x, overlapping the shaft by
# 5 mm; a swallow-tail fin 60 mm long and 90 mm tall at the other end; an 8 mm pivot hole
# 170 mm from the tip on the shaft's axis; four 5 mm lightening holes along the shaft, 25 mm
# apart, the first 40 mm left of the pivot.

thickness 3 mm

solid vane {
    shaft = Rectangle(center=(0, 0), width=300, height=12)
    head = Triangle(center=(180, 0), base=60, height=70, rotation=-90 deg)
    tail = Polygon([(-185, 45), (-125, 6), (-125, -6), (-185, -45), (-165, 0)])
    head.bb.left == shaft.bb.right - 5 mm
    AlignCenterY(head, shaft)

    hole pivot {
        c = Circle(center=(45, 0), diameter=8)
    }
    HorizontalDistance(pivot.c.center, head.c, 170)
    AlignCenterY(pivot, shaft)

    hole light {
        c = Circle(center=(5, 0), diameter=5)
    }
    row = LinearPattern(light, 4, (-25, 0))
    HorizontalDistance(light.c.center, pivot.c.center, 40)
    AlignCenterY(light, shaft)

    assert vane.bb.width == 400 mm, "400 mm overall"
    assert shaft.width == 300 mm and shaft.height == 12 mm, "shaft 300 x 12"
    assert head.bb.height == 60 mm and head.bb.width == 70 mm, "head 60 x 70"
    assert tail.bb.width == 60 mm and tail.bb.height == 90 mm, "tail 60 x 90"
    assert head.c.x - pivot.c.center.x == 170 mm, "pivot 170 mm from the tip"
    assert len(row) == 4, "four lightening holes"
}
