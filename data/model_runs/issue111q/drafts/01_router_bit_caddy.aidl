# Workshop: a router-bit caddy top plate, 240 x 90 mm, 6 mm plywood, corners R5.
# Front row: eight 6.6 mm holes (1/4" shanks) 25 mm apart, centred, 30 mm above the bottom edge.
# Back row: six 12.9 mm holes (1/2" shanks) 35 mm apart, centred, 25 mm below the top edge.
# Labels "1/4" and "1/2" 4 mm high, ending 6 mm left of each row's first hole.
# Title "ROUTER BITS" 5 mm, centred between the rows.
# Two 4.5 mm screw holes countersunk 9 mm, 12 mm in from each end, at mid height.

thickness 6 mm

param small_n = 8, min = 2, max = 9
param large_n = 6, min = 2, max = 6

solid caddy {
    plate = RoundedRectangle(center=(0, 0), width=240, height=90, corner_radius=5)

    hole small {
        c = Circle(center=(-87.5, -15), diameter=6.6)
    }
    smalls = LinearPattern(small, small_n, (25, 0))

    hole large {
        c = Circle(center=(-87.5, 20), diameter=12.9)
    }
    larges = LinearPattern(large, large_n, (35, 0))

    hole screw {
        c = Circle(center=(-108, 0), diameter=4.5)
    }
    axis = Line((0, -50), (0, 50), construction=true)
    Vertical(axis)
    Midpoint(plate.center, axis)
    screw2 = Mirrored(screw, about=axis)
    Countersink([screw, screw2], diameter=9)

    # rows centred on the plate and at their heights
    (smalls[0].c.center.x + smalls[small_n - 1].c.center.x) / 2 == plate.center.x
    (larges[0].c.center.x + larges[large_n - 1].c.center.x) / 2 == plate.center.x
    VerticalDistance(plate.bottom.midpoint, smalls[0].c.center, 30)
    VerticalDistance(larges[0].c.center, plate.top.midpoint, 25)
    HorizontalDistance(plate.left.midpoint, screw.c.center, 12)
    AlignCenterY(screw, plate)

    drawing labels {
        t_small = Text("1/4", (-100, -15), size=4, anchor="end", valign="middle")
        t_large = Text("1/2", (-100, 20), size=4, anchor="end", valign="middle")
        title = Text("ROUTER BITS", (0, 0), size=5, valign="middle")
    }
    At(labels.t_small.position, smalls[0].c.center, dx=-(3.3 + 6))
    At(labels.t_large.position, larges[0].c.center, dx=-(6.45 + 6))
    labels.title.position.x == plate.center.x
    labels.title.position.y == (smalls[0].c.center.y + larges[0].c.center.y) / 2

    assert plate.bb.width == 240 mm, "plate 240 wide"
    assert plate.bb.height == 90 mm, "plate 90 tall"
    assert len(smalls) == 8, "eight 1/4 holes"
    assert len(larges) == 6, "six 1/2 holes"
    assert smalls[1].c.center.x - smalls[0].c.center.x == 25 mm, "1/4 pitch 25"
    assert larges[1].c.center.x - larges[0].c.center.x == 35 mm, "1/2 pitch 35"
    assert smalls[0].c.center.y - plate.bb.bottom == 30 mm, "front row 30 above bottom"
    assert plate.bb.top - larges[0].c.center.y == 25 mm, "back row 25 below top"
    assert screw.c.center.x - plate.bb.left == 12 mm, "screw 12 in"
    assert plate.bb.right - screw2.c.center.x == 12 mm, "screw 12 in (right)"
}
