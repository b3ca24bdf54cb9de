# Request: a desk divider screen for a shared office desk, 5 mm frosted acrylic. A panel
# 450 wide x 300 tall with R20 top corners (square bottom corners on the desk), a cable
# notch 60 wide and 25 tall (R10 top corners) in the middle of its bottom edge, four 6 mm
# holes for note clips 25 mm below the top edge, 100 mm apart, centred, and "DESK 4"
# engraved (8 mm letters) 20 mm in from the bottom-right corner. It stands on two feet,
# 200 long x 40 tall with R15 top corners, crossing the panel at 175 mm either side of its
# middle, cross-halved: the panel slotted 20 up from its bottom edge, each foot 20 down
# from the middle of its top edge, so the feet sit centred on the panel.

import "std/joints.aidl"

thickness 5 mm

t = 5 mm

def foot() -> solid {
    blade = RoundedRectangle(center=(0, 20), width=200, height=40, corner_radii=[15, 15, 0, 0])
    halving = cross_halving(depth=20 mm, thickness=t, cx=0, cy=40)
}

assembly divider {
    solid panel {
        sheet = RoundedRectangle(center=(0, 150), width=450, height=300,
                                 corner_radii=[20, 20, 0, 0])
        left_halving = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=-175, cy=0)
        right_halving = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=175, cy=0)
        hole cable {
            # its lower corners below the edge, so only the top ones show
            n = RoundedRectangle(center=(0, 7.5), width=60, height=35, corner_radius=10)
        }
        hole clips {
            for i in range(4) {
                c = Circle(center=(-150 + i * 100, 300 - 25), diameter=6)
            }
        }
        drawing label {
            w = Text("DESK 4", position=(225 - 20, 20), size=8, anchor="end")
        }
    }

    left_foot = foot()
    right_foot = foot()

    # flat layout
    Below(left_foot, panel, gap=8)
    Below(right_foot, panel, gap=8)
    AlignLeft(left_foot, panel)
    AlignRight(right_foot, panel)

    # 3D: the panel upright facing front, its mid-plane at y = -2.5; the feet across it
    Place(panel, position=(0, 0, 0), face="front", up="up")
    Place(left_foot, position=(-175 + t / 2, -t / 2, 0), face="left", up="up")
    Place(right_foot, position=(175 + t / 2, -t / 2, 0), face="left", up="up")

    # the request's numbers
    assert panel.sheet.bb.width == 450 mm and panel.sheet.bb.height == 300 mm, "panel 450 x 300"
    assert panel.cable.n.bb.width == 60 mm, "cable notch 60 wide"
    assert panel.cable.n.bb.top - panel.sheet.bb.bottom == 25 mm, "cable notch 25 tall"
    assert len(panel.clips.c) == 4, "four clip holes"
    assert panel.clips.c[1].center.x - panel.clips.c[0].center.x == 100 mm, "100 apart"
    assert panel.sheet.bb.top - panel.clips.c[0].center.y == 25 mm, "25 below the top"
    assert left_foot.blade.bb.width == 200 mm and left_foot.blade.bb.height == 40 mm, "feet 200 x 40"
    assert left_foot.halving.depth + panel.left_halving.depth == 40 mm, "halvings meet"
    assert panel.right_halving.cut.bb.center_x - panel.sheet.bb.center_x == 175 mm, "feet 175 from the middle"
}
