# Request (sport): a floor rack for three pairs of vinyl dumbbells (1, 2 and 3 kg), 9 mm ply.
# Two side plates 300 mm long, 60 mm tall at the front rising in a straight slope to 160 mm at
# the back, top corners r10. Each side has three round cradles r16 (for the 30 mm handles)
# centred on the sloping edge at 60, 150 and 240 mm from the front, and an arch cut from the
# bottom (a circle r80 centred 60 mm below the bottom edge, in the middle) to stand on two feet.
# The handles rest across both sides, so the sides stand 100 mm apart inside (the handles are
# 120 mm long between the heads). Two stretchers 50 mm tall join the sides, 30 mm from the
# front and 30 mm from the back, 8 mm off the floor, each glued through both sides by two
# 15 mm tabs at each end. On the left side's outer face "1 kg", "2 kg", "3 kg" engraved 30 mm
# under their cradles (8 mm letters) and "HOME GYM" (10 mm) low in the middle.

import "std/joints.aidl"

thickness 9 mm
ply = 9 mm
inner = 100 mm
cradle_x = [60 mm, 150 mm, 240 mm]
def edge_y(x) = 60 mm + x * 100 / 300       # the sloping top edge
stretch_x = [30 mm, 270 mm]
stretch_cy = 8 mm + 25 mm

def side(labels=false) -> solid {
    # frame: x from the front, y up from the floor
    outline = Polygon([(0, 0), (300, 0), (300, 160), (0, 60)])
    Fillet(outline.points[2], 10)
    Fillet(outline.points[3], 10)
    hole cradle {
        for i in range(3) { c = Circle(center=(cradle_x[i], edge_y(cradle_x[i])), radius=16) }
    }
    hole arch { c = Circle(center=(150, -60), radius=80) }
    for k in range(2) {
        m = tab_and_slot(part="slot", length=50 mm, thickness=ply, tabs=2, tab=15 mm, screw=0,
                         rotation=90 deg, cx=stretch_x[k], cy=stretch_cy)
    }
    if labels {
        drawing kg {
            for i in range(3) {
                t = Text(f"{i + 1} kg", (cradle_x[i], edge_y(cradle_x[i]) - 30 mm), size=8,
                         valign="middle")
            }
            title = Text("HOME GYM", (190, 45), size=10, valign="middle")
        }
    }
}

def stretcher() -> solid {
    # frame: x across the rack (tabs' tips flush with the sides' outer faces), y up
    body = Rectangle(center=(0, stretch_cy), width=inner + 2 * ply, height=50)
    tl = tab_and_slot(part="tab", length=50 mm, thickness=ply, tabs=2, tab=15 mm, screw=0,
                      rotation=90 deg, cx=-(inner / 2 + ply), cy=stretch_cy)
    tr = tab_and_slot(part="tab", length=50 mm, thickness=ply, tabs=2, tab=15 mm, screw=0,
                      rotation=-90 deg, cx=inner / 2 + ply, cy=stretch_cy)
}

assembly rack {
    left = side(labels=true)
    right = side()
    front = stretcher()
    back = stretcher()

    # 3D: sides in the x-z plane ((x, y, z) -> (x, -z, y)), stretchers in the y-z plane
    Place(left, position=(0, -inner / 2, 0), rotation=(90 deg, 0, 0))
    Place(right, position=(0, inner / 2 + ply, 0), rotation=(90 deg, 0, 0))
    Place(front, position=(stretch_x[0] - ply / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(back, position=(stretch_x[1] - ply / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    # on the sheet
    Above(right, left, gap=6)
    AlignLeft(right, left)
    RightOf(front, left, gap=6)
    AlignBottom(front, left)
    RightOf(back, front, gap=6)
    AlignBottom(back, front)

    assert left.outline.bb.width == 300 mm, "sides 300 long"
    assert left.outline.bb.height == 160 mm, "160 tall at the back"
    assert left.cradle.c[1].center.x - left.cradle.c[0].center.x == 90 mm, "cradles at 60, 150, 240"
    assert left.cradle.c[0].radius == 16 mm, "cradles r16"
    assert 2 * left.cradle.c[0].radius > 30 mm, "a 30 mm handle drops into a cradle"
    assert front.body.bb.width - 2 * ply == 100 mm, "sides 100 apart inside"
    assert inner < 120 mm, "the sides fit between a dumbbell's heads"
}
