# Request (workshop): a sink bridge for sharpening. It holds a 180 x 60 x 25 mm whetstone over a
# 300 mm wide sink. 6 mm birch ply. Two rails 420 x 40 mm (corners r5) span the sink, 40 mm apart
# centre to centre; the stone lies on them. Two cross bars 110 x 50 mm (top corners r3) halve into
# the rails (rails slotted 20 mm down from the top, bars 20 mm up from the bottom, 0.2 mm
# clearance), so each bar stands 10 mm proud of the rails as an end stop; the stops' inner faces
# are 180 mm + 1 mm play apart. Each rail has an 8 mm hanging hole 15 mm from its left end and the
# grits "1000 | 6000" engraved 5 mm tall near its right end.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
stone = 180 mm
play = 1 mm
rail_len = 420 mm
rail_h = 40 mm
bar_len = 110 mm
bar_h = 50 mm
rail_gap = 40 mm           # rails centre to centre
depth = 20 mm
cl = 0.2 mm
stop_x = (stone + play + t) / 2   # bar centre from the bridge centre

def rail() -> solid {
    body = RoundedRectangle(center=(0, 0), width=rail_len, height=rail_h, corner_radius=5)
    s1 = cross_halving(depth=depth, thickness=t, clearance=cl, cx=-stop_x, cy=rail_h / 2)
    s2 = cross_halving(depth=depth, thickness=t, clearance=cl, cx=stop_x, cy=rail_h / 2)
    hole hang { c = Circle(center=(-rail_len / 2 + 15, 0), diameter=8) }
    drawing grits { g = Text("1000 | 6000", position=(150, 0), size=5, valign="middle") }
}

def bar() -> solid {
    body = RoundedRectangle(center=(0, 0), width=bar_len, height=bar_h, corner_radii=[3, 3, 0, 0])
    s1 = cross_halving(depth=depth, thickness=t, clearance=cl, rotation=180, cx=-rail_gap / 2,
                       cy=-bar_h / 2)
    s2 = cross_halving(depth=depth, thickness=t, clearance=cl, rotation=180, cx=rail_gap / 2,
                       cy=-bar_h / 2)
}

assembly bridge {
    rail_a = rail()
    rail_b = rail()
    bar_a = bar()
    bar_b = bar()

    # flat on the sheet
    Above(rail_b, rail_a, gap=5)
    AlignCenterX(rail_b, rail_a)
    Above(bar_a, rail_b, gap=5)
    RightOf(bar_b, bar_a, gap=5)
    AlignCenterY(bar_b, bar_a)
    AlignLeft(bar_a, rail_b)

    # assembled: rails stood up along x, bars stood up along y
    Place(rail_a, rotation=(90 deg, 0, 0), position=(0, -rail_gap / 2 + t / 2, rail_h / 2))
    Place(rail_b, rotation=(90 deg, 0, 0), position=(0, rail_gap / 2 + t / 2, rail_h / 2))
    Place(bar_a, rotation=(90 deg, 0, 90 deg), position=(-stop_x - t / 2, 0, bar_h / 2))
    Place(bar_b, rotation=(90 deg, 0, 90 deg), position=(stop_x - t / 2, 0, bar_h / 2))

    # the request's numbers
    assert rail_a.body.bb.width == 420 mm and rail_a.body.bb.height == 40 mm, "rail size"
    assert bar_a.body.bb.width == 110 mm and bar_a.body.bb.height == 50 mm, "bar size"
    assert rail_a.s2.cut.bb.center_x - rail_a.s1.cut.bb.center_x - t == 180 mm + 1 mm,
        "stops' inner faces: stone + play apart"
    assert bar_a.s2.cut.bb.center_x - bar_a.s1.cut.bb.center_x == 40 mm, "rails 40 apart"
    assert rail_a.body.bb.top - rail_a.s1.cut.bb.bottom == 20 mm, "rail slot 20 deep"
    assert bar_a.s1.cut.bb.top - bar_a.body.bb.bottom == 20 mm, "bar slot 20 deep"
    assert (bar_a.body.bb.height - (bar_a.s1.cut.bb.top - bar_a.body.bb.bottom)) -
        (rail_a.body.bb.height - (rail_a.body.bb.top - rail_a.s1.cut.bb.bottom)) == 10 mm,
        "bar stands 10 proud"
    assert rail_a.s1.cut.bb.width == 6.2 mm, "slot 6 + 0.2 wide"
    assert rail_a.hang.c.center.x - rail_a.body.bb.left == 15 mm, "hang hole 15 from the end"
}
