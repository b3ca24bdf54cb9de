# Pencil-holder front: a 110 x 60 mm panel with 3 mm rounded corners and three
# round holes in a row on its horizontal center line: 10 mm (pencils),
# 16 mm (markers) and 24 mm (scissors) across, with 12 mm of material between
# neighbouring holes, the row centered left-to-right on the panel.

param gap = 12 mm, min = 5 mm, max = 20 mm

solid front {
    panel = RoundedRectangle(center=(0, 0), width=110, height=60, corner_radius=3)
    hole small { c = Circle(center=(-25, 0), diameter=10) }
    hole medium { c = Circle(center=(0, 0), diameter=16) }
    hole large { c = Circle(center=(25, 0), diameter=24) }
    LeftOf(small, medium, gap=gap)
    LeftOf(medium, large, gap=gap)
    AlignCenterY(small, panel)
    AlignCenterY(medium, panel)
    AlignCenterY(large, panel)
    # the row as a whole centered on the panel
    (small.bb.left + large.bb.right) / 2 == panel.bb.center_x

    assert medium.bb.left - small.bb.right == 12 mm, "12 mm between small and medium"
    assert large.bb.left - medium.bb.right == 12 mm, "12 mm between medium and large"
    assert small.c.diameter == 10 mm and medium.c.diameter == 16 mm and large.c.diameter == 24 mm, "hole sizes"
}
