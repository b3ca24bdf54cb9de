# Checkerboard for a small laser bed: 160 x 160 mm, cut as two 80 x 160 mm
# halves locked along the vertical center seam by a sliding dovetail (3 tails,
# 8 mm deep, 10 deg, 0.1 mm clearance; tails on the left half). An 8 x 8 grid of
# 18 mm squares (144 mm) engraved, centered on the board; the seam falls on its
# middle line. The halves are laid out 20 mm apart for cutting.
import "std/joints.aidl"

thickness 3 mm

sq = 18 mm
S = 100 mm   # where the right half's seam sits on the sheet (0 when assembled)

assembly board {
    solid left {
        body = Rectangle(corner=(-80, -80), opposite=(8, 80))
        d = dovetail(part="tail", length=160 mm, depth=8 mm, tails=3, angle=10 deg,
                     clearance=0.1 mm, rotation=-90 deg, cx=0 mm, cy=0 mm)
        drawing grid {
            for i in range(4) {
                v = Line((-4 * sq + i * sq, -4 * sq), (-4 * sq + i * sq, 4 * sq))
            }
            for j in range(9) {
                h = Line((-4 * sq, -4 * sq + j * sq), (8, -4 * sq + j * sq))
            }
        }
    }
    solid right {
        body = Rectangle(corner=(S, -80), opposite=(S + 80, 80))
        d = dovetail(part="socket", length=160 mm, depth=8 mm, tails=3, angle=10 deg,
                     clearance=0.1 mm, rotation=-90 deg, cx=S, cy=0 mm)
        drawing grid {
            for i in range(1, 5) {
                v = Line((S + i * sq, -4 * sq), (S + i * sq, 4 * sq))
            }
            for j in range(9) {
                h = Line((S, -4 * sq + j * sq), (S + 4 * sq, -4 * sq + j * sq))
            }
        }
    }
}

assert board.right.body.bb.right - S - board.left.body.bb.left == 160 mm, "160 mm wide assembled"
assert board.left.body.bb.height == 160 mm and board.right.body.bb.height == 160 mm, "160 mm tall"
assert board.right.body.bb.width == 80 mm, "right half 80 mm"
assert board.left.body.bb.right == 8 mm, "tails 8 mm deep past the seam"
assert board.right.body.bb.left - board.left.body.bb.right >= 20 mm - 8 mm, "laid out apart"
assert len(board.left.grid.h) == 9 and len(board.left.grid.v) + len(board.right.grid.v) == 8, "8 x 8 squares"
