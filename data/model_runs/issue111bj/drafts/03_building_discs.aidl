# Request: "A starter set of slot-together building pieces for the kids, 3 mm plywood, slots
# 3 mm wide and 12 mm deep (snug, no clearance): three 80 mm discs with 8 slots evenly round
# the rim and a 6 mm axle hole in the middle (they double as wheels on a dowel); two hexagons
# 60 mm across the flats with a slot in the middle of every flat and a 5-pointed star window
# (24 mm tip to tip) in the middle; two 120 x 30 mm bars with r5 corners, a slot in each end,
# two in each long side 60 mm apart, and a 6 mm hole in the middle."

import "std/joints.aidl"

thickness 3 mm

param slot_d = 12 mm, min = 8 mm, max = 20 mm
t = 3 mm

def disc(d=80 mm) -> solid {
    rim = Circle(center=(0, 0), diameter=d)
    s = cross_halving(depth=slot_d, thickness=t, cx=0, cy=d / 2)
    slots = CircularPattern(s, 8, (0, 0))
    hole axle { c = Circle(center=(0, 0), diameter=6) }
}

def hexagon(af=60 mm) -> solid {
    hex = RegularPolygon(center=(0, 0), across_flats=af, sides=6)
    for k in range(6) {
        s = cross_halving(depth=slot_d, thickness=t, rotation=k * 60 deg - 60 deg,
                          cx=af / 2 * cos(30 deg + k * 60 deg), cy=af / 2 * sin(30 deg + k * 60 deg))
    }
    hole window { st = Star(center=(0, 0), points=5, outer_radius=12, inner_radius=5) }
}

def bar(len=120 mm, w=30 mm) -> solid {
    body = RoundedRectangle(center=(0, 0), width=len, height=w, corner_radius=5)
    # FIX after the first valid program: W0502 (end slots ran outward, cut nothing, left 1 mm
    # nicks): a slot runs toward -y turned by rotation, so the east end is -90, the west +90
    east = cross_halving(depth=slot_d, thickness=t, rotation=-90 deg, cx=len / 2, cy=0)
    west = cross_halving(depth=slot_d, thickness=t, rotation=90 deg, cx=-len / 2, cy=0)
    for x in [-30 mm, 30 mm] {
        top = cross_halving(depth=slot_d, thickness=t, cx=x, cy=w / 2)
        bottom = cross_halving(depth=slot_d, thickness=t, rotation=180 deg, cx=x, cy=-w / 2)
    }
    hole axle { c = Circle(center=(0, 0), diameter=6) }
}

assembly kit {
    for i in range(3) {
        d = disc()
    }
    for i in range(2) {
        h = hexagon()
        b = bar()
    }
    # a row of discs, the hexagons under them, the bars under those
    RightOf(d[1], d[0], gap=4)
    RightOf(d[2], d[1], gap=4)
    AlignCenterY(d[1], d[0])
    AlignCenterY(d[2], d[0])
    Below(h[0], d[0], gap=4)
    AlignLeft(h[0], d[0])
    RightOf(h[1], h[0], gap=4)
    AlignCenterY(h[1], h[0])
    Below(b[0], h[0], gap=4)
    AlignLeft(b[0], h[0])
    RightOf(b[1], b[0], gap=4)
    AlignCenterY(b[1], b[0])

    assert len(d) == 3 and len(h) == 2 and len(b) == 2, "3 discs, 2 hexagons, 2 bars"
    assert d[0].rim.diameter == 80 mm, "80 mm discs"
    assert len(d[0].slots) == 8, "8 slots round a disc"
    assert d[0].axle.c.diameter == 6 mm and b[0].axle.c.diameter == 6 mm, "6 mm axle holes"
    assert h[0].hex.bb.height == 60 mm, "hexagon 60 mm across the flats"
    assert len(h[0].s) == 6, "a slot in every flat"
    assert h[0].window.st.bb.height <= 24 mm, "star about 24 mm"
    assert b[0].body.bb.width == 120 mm and b[0].body.bb.height == 30 mm, "120 x 30 bars"
    assert b[0].top[1].cut.bb.center_x - b[0].top[0].cut.bb.center_x == 60 mm, "side slots 60 apart"
    assert d[0].s.depth == 12 mm and d[0].s.thickness == 3 mm, "slots 3 x 12"
}
