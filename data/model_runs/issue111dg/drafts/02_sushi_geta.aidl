# Request (kitchen): a sushi serving board (geta) from 6 mm bamboo ply, glued.
# The board is 300 x 150 with 10 mm corner radius. Two feet 130 long and 30 tall stand under
# it across its width, their outer faces 30 mm in from each short end, each glued into the
# board with two 20 mm tabs through mortises. Each foot has an arched relief in its
# underside 100 wide and 12 high so it stands on its two ends. On the board: "SUSHI"
# engraved filled (bold, 14 mm) at the lower right, 20 mm from the right and bottom edges,
# and three engraved maki rolls (18 mm discs with a 12 mm ring of rice and a 5 mm filling)
# in a row 25 mm apart at the upper left, 25 mm from the left and top edges.
# FIX after the first valid program: the maki at 25 mm from the left end and "SUSHI" at
# 20 mm from the right end sat on the feet's mortises (W0505), so the maki row now starts
# 50 mm from the left edge and the word ends 45 mm from the right edge; the rice ring is a
# Shell (a hole in a drawing does not hide a fill: W0526); the right foot is aligned with the
# left one on the sheet (it lay on the board: W0511).

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
foot_h = 30 mm
foot_l = 130 mm

def foot_part() -> solid {
    body = Rectangle(center=(0, 0), width=foot_l, height=foot_h + t)
    tabs = tab_and_slot(part="tab", length=foot_l, thickness=t, tabs=2, tab=20 mm, screw=0,
                        cx=0 mm, cy=(foot_h + t) / 2)
    hole relief {
        e = Ellipse(center=(0, -(foot_h + t) / 2), rx=50, ry=12)
    }
}

def maki() -> drawing {
    edge = Circle(center=(0, 0), diameter=18)
    nori = Shell(edge, -3, fill=true)
    filling = Circle(center=(0, 0), diameter=5, fill=true)
}

assembly geta {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=300, height=150, corner_radius=10)
        # mortises: the feet's middles stand 30 + t/2 in from the short ends
        m1 = tab_and_slot(part="slot", length=foot_l, thickness=t, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=-150 mm + 30 mm + t / 2, cy=0 mm)
        m2 = tab_and_slot(part="slot", length=foot_l, thickness=t, tabs=2, tab=20 mm, screw=0,
                          rotation=90 deg, cx=150 mm - 30 mm - t / 2, cy=0 mm)
        drawing label {
            w = Text("SUSHI", position=(0, 0), size=14, font="sans:Bold", fill=true)
        }
        label.bb.right == body.bb.right - 45
        label.bb.bottom == body.bb.bottom + 20

        roll = maki()
        rolls = LinearPattern(roll, 3, (25, 0))
        rolls[0].bb.left == body.bb.left + 50
        rolls[0].bb.top == body.bb.top - 25
    }

    left_foot = foot_part()
    right_foot = foot_part()

    Below(left_foot, board, gap=10)
    RightOf(right_foot, left_foot, gap=10)
    AlignLeft(left_foot, board)
    AlignTop(right_foot, left_foot)

    Place(board, position=(0, 0, foot_h), face="up")
    # each foot stands in the y-z plane; its drawing's x runs along the board's width
    Place(right_foot, position=(150 - 30 - t, 0, (foot_h + t) / 2), face="right", up="up")
    Place(left_foot, position=(-150 + 30 + t, 0, (foot_h + t) / 2), face="left", up="up")

    assert board.body.bb.width == 300 mm and board.body.bb.height == 150 mm, "300 x 150"
    assert board.body.bb.right - board.m2.slot[0].bb.right == 30 mm, "feet 30 mm in from the ends"
    assert board.m1.slot[0].bb.left - board.body.bb.left == 30 mm, "feet 30 mm in from the ends"
    assert left_foot.body.bb.height - t == 30 mm, "feet 30 tall"
    assert len(rolls) == 3, "three maki"
}
