# Office letter sorter, 3 mm plywood, cross-halved: four upright dividers 160 wide x
# 120 tall with 20 mm radii on their top corners, each with two slots 25 mm deep up
# from its bottom edge at x = +-50 from its middle; two base rails 240 long x 40 tall,
# each with four slots 15 mm deep down from its top edge, 60 mm apart and centred
# (x = -90, -30, 30, 90); slots 3 mm wide (25 + 15 = the rail's 40 mm). The dividers'
# names "IN", "OUT", "FILE", "READ" engraved 10 mm tall, 20 mm below their tops.

import "std/joints.aidl"

thickness 3 mm

param t = 3 mm, min = 2.5 mm, max = 6 mm
names = ["IN", "OUT", "FILE", "READ"]

def divider(label="IN") -> solid {
    body = RoundedRectangle(center=(0, 60), width=160, height=120, corner_radii=[20, 20, 0, 0])
    left_slot = cross_halving(depth=25 mm, thickness=t, rotation=180 deg, cx=-50 mm, cy=0 mm)
    right_slot = cross_halving(depth=25 mm, thickness=t, rotation=180 deg, cx=50 mm, cy=0 mm)
    drawing name {
        word = Text(label, (0, 100), size=10)
    }
}

def rail() -> solid {
    body = Rectangle(center=(0, 20), width=240, height=40)
    for i in range(4) {
        slot = cross_halving(depth=15 mm, thickness=t, cx=(i - 1.5) * 60 mm, cy=40 mm)
    }
}

assembly sorter {
    for i in range(4) {
        d = divider(label=names[i])
        d.body.bb.center == (i * 175, 80)
    }
    for j in range(2) {
        r = rail()
        r.body.bb.center == (j * 260 + 130, -20)
    }

    assert len(d) == 4, "four dividers"
    assert d[0].body.width == 160 mm and d[0].body.height == 120 mm, "dividers 160 x 120"
    assert d[0].left_slot.cut.bb.height == 25 mm, "divider slots 25 deep"
    assert d[0].right_slot.cut.bb.center_x - d[0].body.center.x == 50 mm, "divider slots at +-50"
    assert d[0].left_slot.cut.bb.bottom == d[0].body.bb.bottom, "divider slots from the bottom"
    assert d[0].left_slot.cut.bb.width == 3 mm, "slots 3 wide"
    assert len(r) == 2, "two rails"
    assert r[0].body.width == 240 mm and r[0].body.height == 40 mm, "rails 240 x 40"
    assert r[0].slot[0].cut.bb.height == 15 mm, "rail slots 15 deep"
    assert r[0].slot[0].cut.bb.top == r[0].body.bb.top, "rail slots from the top"
    assert r[0].slot[1].cut.bb.center_x - r[0].slot[0].cut.bb.center_x == 60 mm, "rail slots 60 apart"
    assert r[0].slot[0].cut.bb.center_x - r[0].body.center.x == -90 mm, "first rail slot at -90"
    assert d[1].name.word.size == 10 mm, "names 10 tall"
    assert d[1].body.bb.top - d[1].name.word.position.y == 20 mm, "names 20 below the top"
}
