# Request: a macrame project board that stands upright on the craft table, 6 mm ply.
# Board 300 x 420 mm, R10 corners. Along the top edge 13 cord-lock notches on a 20 mm
# pitch, centred: each a V 6 mm wide at the edge narrowing over 5 mm to a 1.5 mm slit that
# runs 15 mm down from the edge in all, so a cord pressed in stays put. A centimetre ruler
# engraved down both long edges from the top edge: a tick every 10 mm (4 mm long, 8 mm every
# 50 mm), numbers 5 .. 40 (3.5 mm) beside the long ticks. A light guide grid engraved: 5
# vertical lines 50 mm apart, centred, from 30 mm below the top to 40 mm above the bottom,
# and horizontal lines 50 mm apart from 50 mm below the top, as long as the grid is wide.
# "MACRAMÉ" in serif letters 10 mm tall engraved filled, centred, its baseline 15 mm above
# the bottom edge. Two feet 160 x 40 mm (R5 top corners) cross-halved onto the board's
# bottom edge 100 mm either side of the middle, each slot 20 mm deep, so the board stands.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
w = 300 mm
h = 420 mm
notches = 13
pitch = 20 mm
ticks = 41          # 0 .. 40 cm

def notch(x=0 mm, top=0 mm) -> hole {
    v = Polygon([(x - 3 mm, top + 1 mm), (x + 3 mm, top + 1 mm), (x + 0.75 mm, top - 5 mm),
                 (x + 0.75 mm, top - 15 mm), (x - 0.75 mm, top - 15 mm), (x - 0.75 mm, top - 5 mm)])
}

assembly macrame {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=10 mm)
        for i in range(notches) {
            n = notch(x=(i - (notches - 1) / 2) * pitch, top=h / 2)
        }
        foot_l = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=-100 mm, cy=-h / 2)
        foot_r = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=100 mm, cy=-h / 2)
        drawing ruler {
            # FIX after the first valid program: the 0 cm tick lay on the top edge, over the R10
            # corner, off the material (W0505): the edge itself is 0, the ticks start at 1 cm
            for i in range(1, ticks) {
                tl = Line((-w / 2, h / 2 - i * 10 mm),
                          (-w / 2 + (8 mm if i % 5 == 0 else 4 mm), h / 2 - i * 10 mm))
                tr = Line((w / 2, h / 2 - i * 10 mm),
                          (w / 2 - (8 mm if i % 5 == 0 else 4 mm), h / 2 - i * 10 mm))
                if i % 5 == 0 and i > 0 {
                    nl = Text(str(i), position=(-w / 2 + 10 mm, h / 2 - i * 10 mm), size=3.5 mm,
                              anchor="start", valign="middle")
                    nr = Text(str(i), position=(w / 2 - 10 mm, h / 2 - i * 10 mm), size=3.5 mm,
                              anchor="end", valign="middle")
                }
            }
        }
        drawing grid {
            for i in range(5) {
                v = Line(((i - 2) * 50 mm, h / 2 - 30 mm), ((i - 2) * 50 mm, -h / 2 + 40 mm))
            }
            for j in range(7) {
                hl = Line((-100 mm, h / 2 - 50 mm - j * 50 mm), (100 mm, h / 2 - 50 mm - j * 50 mm))
            }
        }
        drawing name {
            word = Text("MACRAMÉ", position=(0, -h / 2 + 15 mm), size=10 mm, font="serif", fill=true)
        }
    }

    def foot() -> solid {
        body = RoundedRectangle(center=(0, 20 mm), width=160 mm, height=40 mm,
                                corner_radii=[5 mm, 5 mm, 0, 0])
        slot = cross_halving(depth=20 mm, thickness=t, cx=0 mm, cy=40 mm)
    }
    left_foot = foot()
    right_foot = foot()

    RightOf(left_foot, board, gap=5 mm)
    AlignBottom(left_foot, board)
    Above(right_foot, left_foot, gap=5 mm)
    AlignLeft(right_foot, left_foot)

    # assembled: the board upright, its engraved face to the front, bottom edge on the table;
    # the feet square to it, slotted together
    Place(board, position=(0, t / 2, h / 2), face="front", up="up")
    Place(left_foot, position=(-100 mm - t / 2, 0, 0), face="right", up="up")
    Place(right_foot, position=(100 mm - t / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert board.body.bb.width == 300 mm and board.body.bb.height == 420 mm, "300 x 420"
    assert len(board.n) == 13, "13 notches"
    assert board.n[1].bb.center_x - board.n[0].bb.center_x == 20 mm, "20 mm pitch"
    assert board.n[0].bb.center_x + board.n[12].bb.center_x == 2 * board.body.bb.center_x,
        "notches centred"
    assert board.body.bb.top - board.n[0].bb.bottom == 15 mm, "notch 15 mm deep"
    assert len(board.ruler.tl) == 40, "ticks 1 .. 40 cm"
    assert len(board.grid.v) == 5 and len(board.grid.hl) == 7, "grid 5 x 7 lines"
    assert board.grid.v[4].start.x - board.grid.v[0].start.x == 4 * 50 mm, "grid 50 mm"
    assert board.grid.hl[6].start.y - board.body.bb.bottom >= 40 mm, "grid stays off the feet"
    assert board.name.word.position.y - board.body.bb.bottom == 15 mm, "name 15 mm up"
    assert board.foot_r.cut.bb.center_x - board.foot_l.cut.bb.center_x == 200 mm, "feet at +-100"
    assert left_foot.body.bb.width == 160 mm and left_foot.body.bb.height == 40 mm, "feet 160 x 40"
    # the engraving stays clear of the notches and the halving slots
    assert board.n[0].bb.bottom - board.grid.v[0].start.y >= 10 mm, "grid under the notches"
    assert board.name.bb.bottom - board.body.bb.bottom >= 3 mm, "name above the edge"
}
