# Kitchen pan-lid rack, 3 mm plywood. Two rails 240 x 30 (stand on edge, 60 mm apart), three
# dividers 90 wide x 120 tall with R15 top corners and a 40 x 14 finger slot 35 above centre.
# Cross halving: each rail slotted 15 mm deep from its top edge at x = -80, 0, 80 (80 apart);
# each divider slotted 15 mm deep from its bottom edge 30 mm either side of its centre
# (60 apart, the rails' spacing); slots 3 mm + 0.1 mm clearance. "LIDS" engraved 8 mm on the
# front rail.
import "std/joints.aidl"

thickness 3 mm
param t = 3 mm, min = 2 mm, max = 6 mm
param clr = 0.1 mm, min = 0 mm, max = 0.4 mm

def rail(word="") -> solid {
    body = Rectangle(center=(0, 0), width=240, height=30)
    for i in range(3) {
        s = cross_halving(depth=15 mm, thickness=t, clearance=clr, cx=(i - 1) * 80 mm, cy=15 mm)
    }
    if word != "" {
        drawing label {
            w = Text(word, (40, -10), size=8)
        }
    }
}

def divider() -> solid {
    body = RoundedRectangle(center=(0, 0), width=90, height=120, corner_radii=[15, 15, 0, 0])
    left = cross_halving(depth=15 mm, thickness=t, clearance=clr, rotation=180 deg, cx=-30 mm, cy=-60 mm)
    right = cross_halving(depth=15 mm, thickness=t, clearance=clr, rotation=180 deg, cx=30 mm, cy=-60 mm)
    hole grip {
        g = Slot(center=(0, 35), length=40, width=14)
    }
}

assembly rack {
    front = rail(word="LIDS")
    back = rail()
    for i in range(3) {
        d = divider()
    }
    Below(back, front, gap=6)
    AlignLeft(back, front)
    Above(d[0], front, gap=6)
    AlignLeft(d[0], front)
    RightOf(d[1], d[0], gap=6)
    RightOf(d[2], d[1], gap=6)
    AlignBottom(d[1], d[0])
    AlignBottom(d[2], d[0])

    assert len(d) == 3, "three dividers"
    assert front.body.bb.width == 240 mm and front.body.bb.height == 30 mm, "rail 240 x 30"
    assert d[0].body.bb.width == 90 mm and d[0].body.bb.height == 120 mm, "divider 90 x 120"
    assert front.s[1].cut.bb.center_x - front.s[0].cut.bb.center_x == 80 mm, "rail slots 80 apart"
    assert front.body.bb.top - front.s[0].cut.bb.bottom == 15 mm, "rail slot 15 deep"
    assert d[0].right.cut.bb.center_x - d[0].left.cut.bb.center_x == 60 mm, "divider slots 60 apart"
    assert d[0].left.cut.bb.top - d[0].body.bb.bottom == 15 mm, "divider slot 15 deep"
}
