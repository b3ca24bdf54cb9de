# Request: a "LOST SOCKS" board for the laundry room, 6 mm birch ply. A 400 x 260 mm board
# (corners R12) hangs on two screws by keyholes (9 mm head, 4.5 mm slot, 10 mm long, upward)
# at 165 mm left and right of the middle and 25 mm below the top edge. "LOST SOCKS" is
# engraved filled (sans Bold, 30 mm capitals) centred 40 mm below the top edge. Under it an
# engraved washing line sags from (-170, 55) through (0, 40) to (170, 55) (board centre at 0, 0),
# and six engraved 10 x 72 mm outlines hang from it, 60 mm apart and centred, to show where
# six wooden clothes pegs are glued. At the bottom a shelf for the odd socks: 360 x 70 mm
# (tabs included), its underside 20 mm above the board's bottom edge, held by three 40 mm
# glued tabs in mortises of the board (0.2 mm clearance), and a 360 x 40 mm front lip with
# three 40 mm tabs glued into mortises of the shelf, its mid-plane 8 mm in from the shelf's
# front edge.

thickness 6 mm
import "std/plates.aidl"
import "std/joints.aidl"

assembly lost_socks {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=400, height=260, corner_radius=12)
        hang_l = keyhole(head=9, slot_width=4.5, length=10, direction=90 deg, cx=-165, cy=105)
        hang_r = keyhole(head=9, slot_width=4.5, length=10, direction=90 deg, cx=165, cy=105)
        # mortises for the shelf's tabs: the shelf's mid-plane is 20 + 3 mm above the bottom
        shelf_mortise = tab_and_slot(part="slot", length=360, thickness=6, tabs=3, tab=40,
                                     screw=0, clearance=0.2, cx=0, cy=-130 + 23)
        drawing title {
            t = Text("LOST SOCKS", position=(0, 90), size=30, font="sans:Bold",
                     valign="middle", fill=true)
        }
        drawing line {
            l = Arc(start=(-170, 55), through=(0, 40), end=(170, 55))
            Fixed(l)
            for i in range(6) {
                p = Rectangle(center=(-150 + 60 * i, 4), width=10, height=72)
                Coincident(p.top.midpoint, l)
                p.center.x == -150 + 60 * i
            }
        }
        Fixed(body)
    }

    solid shelf {
        plate = Rectangle(center=(0, 0), width=360, height=70)
        back_tabs = tab_and_slot(part="tab", length=360, thickness=6, tabs=3, tab=40,
                                 screw=0, cx=0, cy=35)
        lip_mortise = tab_and_slot(part="slot", length=360, thickness=6, tabs=3, tab=40,
                                   screw=0, clearance=0.2, cx=0, cy=-35 + 8)
    }

    solid lip {
        plate = Rectangle(center=(0, 0), width=360, height=40)
        tabs = tab_and_slot(part="tab", length=360, thickness=6, tabs=3, tab=40,
                            screw=0, rotation=180 deg, cx=0, cy=-20)
    }

    # flat on the sheet: shelf and lip under the board
    Below(shelf, board, gap=10)
    AlignLeft(shelf, board)
    Below(lip, shelf, gap=10)
    AlignLeft(lip, shelf)

    # in 3D: the board on the wall facing front, the shelf's tabs through the board,
    # the lip standing in the shelf's mortises
    Place(board, position=(0, 0, 0), face="front", up="up")
    Place(shelf, position=(0, -35, -110), face="up")
    Place(lip, position=(0, -59, -90), face="front", up="up")

    assert board.body.bb.width == 400 mm and board.body.bb.height == 260 mm, "board 400 x 260"
    assert len(board.line.p) == 6, "six pegs"
    assert board.line.p[1].center.x - board.line.p[0].center.x == 60 mm, "pegs 60 apart"
    assert board.body.bb.top - board.title.t.position.y == 40 mm, "title 40 below the top"
    assert board.body.bb.top - board.hang_l.head_hole.center.y == 25 mm, "keyholes 25 below top"
    assert shelf.plate.bb.height == 70 mm and shelf.plate.bb.width == 360 mm, "shelf 360 x 70"
    assert lip.plate.bb.height == 40 mm, "lip 40 tall"
}
