# Request: a vertical bakeware organiser for a kitchen cupboard, cut from 6 mm birch ply.
# A base board 300 x 220 mm (corners r8) with four dividers standing upright on it, running
# front to back, 72 mm apart centre to centre and centred on the base, so baking trays,
# cooling racks and chopping boards stand on edge between them. Each divider is 220 mm deep,
# stands 200 mm above the base at the back and slopes down to 120 mm at the front; its two
# top corners are rounded r10. Each divider is glued into the base with two 30 mm tabs
# (closed slots, 0.1 mm clearance). "BAKEWARE" engraved on the base's front strip.

import "std/joints.aidl"

thickness 6 mm

param base_w = 300 mm, min = 240, max = 400
param base_d = 220 mm, min = 180, max = 300
param back_h = 200 mm, min = 150, max = 260
param front_h = 120 mm, min = 80, max = 180
param pitch = 72 mm, min = 55, max = 90

t = 6 mm
n = 4

# one divider, drawn on its side: x along the depth (+x is the back), y up; y = 0 is the
# top face of the base, the tabs reach down to y = -t through the base
def divider() -> solid {
    body = Polygon([(-base_d / 2, -t), (base_d / 2, -t), (base_d / 2, back_h),
                    (-base_d / 2, front_h)])
    Fillet([body.points[2], body.points[3]], 10 mm)
    tabs = tab_and_slot(part="tab", length=base_d, thickness=t, tabs=2, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0, cy=-t)
}

def xpos(i) = (i - (n - 1) / 2) * pitch

assembly rack {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=base_w, height=base_d, corner_radius=8)
        for i in range(n) {
            slots = tab_and_slot(part="slot", length=base_d, thickness=t, tabs=2, tab=30 mm,
                                 screw=0, clearance=0.1 mm, rotation=90 deg, cx=xpos(i), cy=0)
        }
        drawing label {
            word = Text("BAKEWARE", position=(0, -base_d / 2 + 10), size=8)
        }
    }
    Place(base, position=(0, 0, 0))

    for i in range(n) {
        d = divider()
        # stood up along the depth: divider x -> world y, y -> z, thickness -> x
        Place(d, rotation=(90 deg, 0, 90 deg), position=(xpos(i) - t / 2, 0, t))
    }
    # on the sheet: the dividers in a column right of the base
    RightOf(d[0], base, gap=10)
    AlignTop(d[0], base)
    for i in range(1, n) {
        Below(d[i], d[i - 1], gap=10)
        AlignLeft(d[i], d[0])
    }

    assert len(d) == 4, "four dividers"
    assert base.board.bb.width == 300 mm and base.board.bb.height == 220 mm, "base 300 x 220"
    assert d[0].body.bb.width == 220 mm, "dividers 220 deep"
    assert d[0].body.points[2].y - d[0].body.points[1].y == 200 mm + t, "200 above the base at the back"
    assert d[0].body.points[3].y - d[0].body.points[0].y == 120 mm + t, "120 above the base at the front"
    assert base.slots[1].bb.center_x - base.slots[0].bb.center_x == 72 mm, "72 mm apart"
}
