# Request (sport): a knock-down tabletop stand for a 200 x 200 x 50 mm foam archery target
# (kids' bows), from 6 mm ply, four parts:
# - Backboard 240 x 280 mm leaning back 15 degrees; the target strapped to it through four
#   26 x 4 mm strap slots at x = +-110 mm, 80 and 180 mm up; an 80 x 25 mm carry-handle slot
#   centred 255 mm up; "ARCHERY" engraved 15 mm up.
# - Two feet (identical triangles): front edge 220 mm long leaning back 15 degrees, 150 mm
#   along the ground, a 50 mm lightening hole; the front edge joins the backboard with a
#   screwed tab-and-slot joint (two 20 mm tabs, an M3 screw and captive nut between them),
#   the feet at x = +-90 mm on the board.
# - A crossbar 220 x 40 mm joining the feet by cross-halvings (20 mm deep each) 110 mm back
#   from the feet's front corner.

import "std/joints.aidl"

units mm
thickness 6 mm
t = 6 mm
lean = 15 deg
edge_len = 220 mm
foot_x = 90 mm
bar_at = 110 mm

def foot() -> solid {
    body = Polygon([(0, 0), (150, 0), (edge_len * sin(lean), edge_len * cos(lean))])
    front = tab_and_slot(part="tab", length=edge_len, thickness=t, tabs=2, tab=20 mm,
                         screw=3, rotation=90 deg - lean,
                         cx=edge_len / 2 * sin(lean), cy=edge_len / 2 * cos(lean))
    halving = cross_halving(depth=20 mm, thickness=t, rotation=180 deg, cx=bar_at, cy=0 mm)
    hole lighten { c = Circle(center=(69, 52.9), diameter=50) }
}

assembly target_stand {
    solid board {
        # frame: the bottom edge's middle at (0, 0)
        body = Rectangle(center=(0, 140), width=240, height=280)
        for s in [-1, 1] {
            m = tab_and_slot(part="slot", length=edge_len, thickness=t, tabs=2, tab=20 mm,
                             screw=3, rotation=90 deg, cx=s * foot_x, cy=edge_len / 2)
        }
        hole straps {
            for p in [(-110, 80), (110, 80), (-110, 180), (110, 180)] {
                s = Slot(center=p, length=26, width=4, rotation=90 deg)
            }
        }
        hole handle { h = Slot(center=(0, 255), length=80, width=25) }
        drawing label { word = Text("ARCHERY", position=(0, 15), size=10, valign="middle") }
    }

    left = foot()
    right = foot()

    solid crossbar {
        # frame: the bottom edge's middle at (0, 0)
        body = Rectangle(center=(0, 20), width=220, height=40)
        for s in [-1, 1] {
            h = cross_halving(depth=20 mm, thickness=t, cx=s * foot_x, cy=40 mm)
        }
    }

    # on the sheet
    RightOf(left, board, gap=8)
    AlignBottom(left, board)
    RightOf(right, left, gap=8)
    AlignBottom(right, board)
    Above(crossbar, left, gap=8)
    AlignLeft(crossbar, left)

    # assembled: x across, y back, z up; the board leans back 15 deg on the feet's front edges
    Place(board, position=(0, t * cos(lean), -t * sin(lean)), rotation=(90 deg - lean, 0, 0))
    Place(left, position=(-foot_x - t / 2, 0, 0), face="right", up="up")
    Place(right, position=(foot_x - t / 2, 0, 0), face="right", up="up")
    Place(crossbar, position=(0, bar_at + t / 2, 0), face="front", up="up")

    assert board.body.width == 240 mm and board.body.height == 280 mm, "board 240 x 280"
    assert len(board.straps.s) == 4, "four strap slots"
    assert board.straps.s[1].center.x - 100 mm > 5 mm, "straps clear of the 200 mm target"
    assert board.handle.h.center.y == 255 mm, "handle 255 mm up"
    assert abs(distance(left.body.points[0], left.body.points[2]) - 220 mm) < 0.001 mm, "front edge 220"
    assert left.body.points[1].x - left.body.points[0].x == 150 mm, "150 mm along the ground"
    assert crossbar.body.width == 220 mm and crossbar.body.height == 40 mm, "crossbar 220 x 40"
    assert left.halving.depth + crossbar.h[0].depth == crossbar.body.height, "halvings meet"
    assert len(board.m) == 2 and len(board.m[0].slot) == 2, "two joints of two tabs"
}
