# Request: "Freestanding 'RESERVED' signs for our café tables, 4 mm oak ply: a 200 x 70 mm
# board, top corners r12, with RESERVED cut right through in bold serif stencil letters
# (20 mm tall, at most 170 mm wide, centred 38 mm up), and 'PLEASE WAIT TO BE SEATED' engraved
# small (4.5 mm) 12 mm above the bottom edge. It stands on two feet 80 mm deep and 30 mm tall
# (top corners r12), 60 mm either side of the middle, that cross-halve with the board: the
# board slotted 15 mm up from its bottom edge, each foot 15 mm down from its top, 0.1 mm
# clearance."

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
fit = 0.1 mm
board_w = 200 mm
board_h = 70 mm
foot_x = 60 mm
foot_d = 80 mm
foot_h = 30 mm

def foot() -> solid {
    body = RoundedRectangle(bottom_left=(-foot_d / 2, 0), width=foot_d, height=foot_h,
                            corner_radii=[12, 12, 0, 0])
    slot = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, cx=0, cy=foot_h)
}

assembly sign {
    solid board {
        body = RoundedRectangle(bottom_left=(-board_w / 2, 0), width=board_w, height=board_h,
                                corner_radii=[12, 12, 0, 0])
        hole word {
            w = Text("RESERVED", position=(0, 38), size=20, font="serif:Bold", stencil=true,
                     valign="middle", max_width=170 mm)
        }
        drawing note {
            n = Text("PLEASE WAIT TO BE SEATED", position=(0, 12), size=4.5)
        }
        ls = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, rotation=180 deg,
                           cx=-foot_x, cy=0)
        rs = cross_halving(depth=foot_h / 2, thickness=t, clearance=fit, rotation=180 deg,
                           cx=foot_x, cy=0)
    }
    left = foot()
    right = foot()

    # on the sheet
    Below(left, board, gap=5)
    AlignLeft(left, board)
    RightOf(right, left, gap=5)
    AlignBottom(right, left)

    # in 3D: the board upright across x, the feet across it along y
    Place(board, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-foot_x - t / 2, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(foot_x - t / 2, 0, 0))

    assert board.body.bb.width == 200 mm and board.body.bb.height == 70 mm, "200 x 70 board"
    assert board.word.w.bb.width <= 170 mm, "RESERVED at most 170 mm wide"
    assert board.word.w.position.y - board.body.bb.bottom == 38 mm, "centred 38 mm up"
    assert board.note.n.position.y - board.body.bb.bottom == 12 mm, "note 12 mm up"
    assert board.ls.depth + left.slot.depth == 30 mm, "slots add up to the foot's height"
    assert left.body.bb.width == 80 mm and left.body.bb.height == 30 mm, "80 x 30 feet"
    assert board.rs.cut.bb.center_x - board.ls.cut.bb.center_x == 120 mm, "feet 60 mm either side"
}
