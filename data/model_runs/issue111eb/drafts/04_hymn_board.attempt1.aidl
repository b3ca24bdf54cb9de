# Request: a church hymn board. The board is 6 mm oak-faced ply, 260 mm wide, straight
# sides 380 mm tall, topped by an equilateral pointed (gothic) arch: two arcs of radius
# 260 mm, each centred on the other side's springing point. Three ledges 260 x 24 mm stand
# out from the front, glued by two 30 mm through tenons each (mortises 0.1 mm clearance),
# their top faces 30, 140 and 250 mm above the bottom edge. Two keyholes (8 mm head, 4 mm
# slot 10 mm up) at 90 mm either side of the centre, 362 mm up. "HYMNS" engraved filled in
# bold serif 30 mm capitals, baseline 430 mm up, and a filled Latin cross above it (upright
# 12 x 60 mm centred 540 mm up, arm 40 x 12 mm centred 552 mm up). Ten number tiles in
# 3 mm ply, 60 x 90 mm (R4), the digits 0 to 9 cut through as 65 mm bold sans stencil
# figures, to stand on the ledges against the board (assembled: 104, 258, 3697).

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/plates.aidl"

BW = 260 mm     # board width = arch radius
SH = 380 mm     # straight sides
ledge_y = [30, 140, 250]

def ledge() -> solid {
    body = RoundedRectangle(center=(0, -15), width=260, height=30, corner_radii=[0, 0, 3, 3])
    tenons = tab_and_slot(part="tab", length=260, thickness=6, tabs=2, tab=30, screw=0,
                          cx=0, cy=0)
}

def tile(d="0") -> solid {
    thickness 3 mm
    body = RoundedRectangle(center=(0, 0), width=60, height=90, corner_radius=4)
    hole digit {
        t = Text(d, position=(0, 0), size=65, font="sans:Bold", valign="middle", stencil=true)
    }
}

assembly hymns {
    solid board {
        bottom = Line((-BW / 2, 0), (BW / 2, 0))
        right = Line((BW / 2, 0), (BW / 2, SH))
        rarc = Arc(center=(-BW / 2, SH), radius=BW, start_angle=0 deg, end_angle=60 deg)
        larc = Arc(center=(BW / 2, SH), radius=BW, start_angle=120 deg, end_angle=180 deg)
        left = Line((-BW / 2, SH), (-BW / 2, 0))

        for r in range(3) {
            m = tab_and_slot(part="slot", length=260, thickness=6, tabs=2, tab=30, screw=0,
                             clearance=0.1, cx=0, cy=ledge_y[r] - 3)
        }
        kl = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=-90, cy=362)
        kr = keyhole(head=8, slot_width=4, length=10, direction=90 deg, cx=90, cy=362)

        drawing title {
            t = Text("HYMNS", position=(0, 430), size=30, font="serif:Bold", fill=true)
        }
        drawing cross {
            upright = Rectangle(center=(0, 540), width=12, height=60, fill=true)
            arm = Rectangle(center=(0, 552), width=40, height=12, fill=true)
        }
    }

    ledges = [ledge() for r in range(3)]
    for i in range(10) {
        t = tile(d=str(i))
    }

    # flat on the sheet: ledges in a column right of the board, tiles in a row below
    RightOf(ledges[0], board, gap=10)
    AlignTop(ledges[0], board)
    Below(ledges[1], ledges[0], gap=5)
    AlignLeft(ledges[1], ledges[0])
    Below(ledges[2], ledges[1], gap=5)
    AlignLeft(ledges[2], ledges[1])
    Below(t[0], board, gap=10)
    AlignLeft(t[0], board)
    for i in range(1, 10) {
        RightOf(t[i], t[i - 1], gap=5)
        AlignTop(t[i], t[i - 1])
    }

    # assembled: the board upright, its front to the front; the ledges level, their tenons
    # flush with the back; the tiles on the ledges against the board
    Place(board, position=(0, 0, 0), face="front", up="up")
    for r in range(3) {
        Place(ledges[r], position=(0, 0, ledge_y[r] - 6), rotation=(0, 0, 0))
    }
    rows = [[1, 0, 4], [2, 5, 8], [3, 6, 9, 7]]
    for r in range(3) {
        for k in range(len(rows[2 - r])) {
            Place(t[rows[2 - r][k]], position=(-97.5 + 65 * k, -6, ledge_y[r] + 45),
                  face="front", up="up")
        }
    }

    # the request's numbers
    assert board.bottom.length == 260 mm and board.right.length == 380 mm, "260 wide, sides 380"
    assert board.bb.height == 380 mm + 260 mm * sin(60 deg), "equilateral arch on top"
    assert len(board.m) == 3 and len(ledges) == 3, "three ledges"
    assert board.m[1].slot[0].bb.center_y - board.bottom.start.y == 140 mm - 3 mm, "middle ledge at 140"
    assert board.m[0].slot[0].bb.width == 30.1 mm and board.m[0].slot[0].bb.height == 6.1 mm, "mortise 30 + 0.1"
    assert ledges[0].body.bb.height - 6 mm == 24 mm and ledges[0].body.bb.width == 260 mm, "ledge 260 x 24 proud"
    assert board.kr.head_hole.center.x - board.kl.head_hole.center.x == 180 mm, "keyholes 90 either side"
    assert board.kl.head_hole.center.y - board.bottom.start.y == 362 mm, "keyholes 362 up"
    assert board.title.t.size == 30 mm and board.title.t.position.y == 430 mm, "HYMNS 30 mm at 430"
    assert len(t) == 10, "ten tiles"
    assert t[0].body.bb.width == 60 mm and t[0].body.bb.height == 90 mm, "tiles 60 x 90"
    assert t[8].digit.t.size == 65 mm, "65 mm figures"
    assert distance(board.title, board.kl) >= 5 mm and distance(board.title, board.kr) >= 5 mm, "title clear of keyholes"
    assert distance(board.title, board.cross) >= 5 mm, "title clear of the cross"
}
