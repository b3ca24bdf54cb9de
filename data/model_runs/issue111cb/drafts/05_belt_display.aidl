# Request (sport): a wall display for my son's karate belts, 6 mm birch ply.
# - Back board 420 x 170 mm, corners r8, screwed to the wall by two countersunk 4.5 mm
#   holes (9 mm heads, 90 deg), 15 mm in from each end, at mid height.
# - "SAM'S BELTS" engraved filled in bold across the top, 18 mm high, at most 300 mm wide,
#   its middle 62 mm above the board's centre.
# - Five pegs 80 mm apart, centred on the board, their middles 25 mm below the board's
#   centre: each peg is 24 mm tall and stands 70 mm out from the board, with a 10 x 10 mm
#   lip turned up at its end so the belt cannot slide off; glued in by one 16 mm tenon
#   through a mortise in the board.
# - Above each peg its belt engraved 8 mm high, 20 mm above the board's centre:
#   WHITE, YELLOW, ORANGE, GREEN, BLUE.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
belts = ["WHITE", "YELLOW", "ORANGE", "GREEN", "BLUE"]
n = len(belts)
pitch = 80 mm
peg_y = -25 mm

# a peg in its own frame: x out from the board's face (tenon tip at x = -t), y up
def peg() -> solid {
    arm = Rectangle(bottom_left=(-t, -12), width=70 + t, height=24)
    lip = Rectangle(bottom_left=(60, 11), width=10, height=11)
    tenon = tab_and_slot(part="tab", length=24 mm, thickness=t, tabs=1, tab=16 mm, screw=0,
                         rotation=90 deg, cx=-t, cy=0 mm)
    Fixed(arm)
}

assembly display {
    solid board {
        panel = RoundedRectangle(center=(0, 0), width=420, height=170, corner_radius=8)
        hole screw { c = Circle(center=(-195, 0), diameter=4.5) }
        screws = LinearPattern(screw, 2, (390, 0))
        Countersink(screws, diameter=9)
        for i in range(n) {
            mortise = tab_and_slot(part="slot", length=24 mm, thickness=t, tabs=1, tab=16 mm,
                                   screw=0, rotation=90 deg, cx=(i - 2) * pitch, cy=peg_y)
        }
        drawing title {
            word = Text("SAM'S BELTS", position=(0, 62), size=18, valign="middle",
                        font="sans:Bold", fill=true, max_width=300)
        }
        drawing names {
            for i in range(n) {
                name = Text(belts[i], position=((i - 2) * pitch, 20), size=8, valign="middle")
            }
        }
        Fixed(panel)
    }

    for i in range(n) {
        p = peg()
    }
    # flat: the pegs in a row under the board
    Below(p[0], board, gap=8)
    AlignLeft(p[0], board)
    for i in range(1, n) {
        RightOf(p[i], p[i - 1], gap=6)
        AlignBottom(p[i], p[0])
    }

    # 3D: the board stands in the wall plane (front face y = -6, its y up as z); each peg's
    # x runs out from the wall (-y), its y up (z), its thickness along x: (x, y, z) -> (-z, -x, y)
    Place(board, rotation=(90 deg, 0, 0), position=(0, 0, 0))
    for i in range(n) {
        Place(p[i], rotation=(90 deg, 0, -90 deg), position=((i - 2) * pitch + t / 2, -t, peg_y))
    }

    assert board.panel.width == 420 mm and board.panel.height == 170 mm
    assert board.screws[0].c.center.x - board.panel.bb.left == 15 mm
    assert board.panel.bb.right - board.screws[1].c.center.x == 15 mm
    assert len(p) == 5 and len(board.mortise) == 5
    assert board.mortise[1].slot[0].bb.center_x - board.mortise[0].slot[0].bb.center_x == 80 mm
    assert p[0].arm.bb.right - (p[0].arm.bb.left + t) == 70 mm, "stands 70 mm out"
    assert p[0].arm.height == 24 mm
    assert p[0].lip.bb.top - p[0].arm.bb.top == 10 mm and p[0].lip.width == 10 mm
    assert board.title.word.bb.width <= 300 mm
    assert board.names.name[3].position.x - board.names.name[2].position.x == 80 mm
}
