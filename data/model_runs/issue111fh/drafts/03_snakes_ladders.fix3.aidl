# Request (toys): a travel snakes & ladders set in 3 mm ply. The board is 324 mm square with
# 8 mm rounded corners and a 10 x 10 grid of 30 mm squares (300 mm, centred), numbered 1 to
# 100 back and forth from the bottom left (1-10 left to right, 11-20 right to left, ...),
# each number small in its square's top left corner. Four ladders (4-14, 9-31, 28-84, 71-91:
# two rails 10 mm apart with rungs about every 10 mm) and four snakes (17-7, 54-34, 62-19,
# 98-79: a wavy filled body 5 mm wide with a round 10 mm head) are engraved from square
# centre to square centre. "SNAKES & LADDERS" engraved in the 12 mm bottom margin.
# Two stand-up pawns 39 mm tall (24 mm base, 14 mm round head), each made of two halves of
# the same outline cross-halved together (one slotted 19.5 mm down from the top, the other
# 19.5 mm up from the bottom), numbered 1 and 2. In 3D: pawn 1 on square 1, pawn 2 on 2.

units mm
thickness 3 mm
import "std/joints.aidl"

T = 3 mm
SQ = 30 mm
BOARD = 324 mm
PAWN_H = 39 mm
LADDERS = [[4, 14], [9, 31], [28, 84], [71, 91]]
SNAKES = [[17, 7], [54, 34], [62, 19], [98, 79]]

def row(n) = (n - 1) // 10
def col(n) = (n - 1) % 10 if row(n) % 2 == 0 else 9 - (n - 1) % 10
def sx(n) = -4.5 * SQ + SQ * col(n)
def sy(n) = -4.5 * SQ + SQ * row(n)

def ladder(a=4, b=14) -> drawing {
    dx = sx(b) - sx(a)
    dy = sy(b) - sy(a)
    ln = sqrt(dx ** 2 + dy ** 2)
    px = -dy / ln * 5 mm
    py = dx / ln * 5 mm
    rail_l = Line((sx(a) + px, sy(a) + py), (sx(b) + px, sy(b) + py))
    rail_r = Line((sx(a) - px, sy(a) - py), (sx(b) - px, sy(b) - py))
    n = floor(ln / 10 mm)
    for k in range(1, n) {
        rung = Line((sx(a) + dx * k / n + px, sy(a) + dy * k / n + py),
                    (sx(a) + dx * k / n - px, sy(a) + dy * k / n - py))
    }
}

def snake(h=17, t=7) -> drawing {
    dx = sx(t) - sx(h)
    dy = sy(t) - sy(h)
    ln = sqrt(dx ** 2 + dy ** 2)
    pts = [(sx(h) + dx * k / 8 - dy / ln * 6 mm * sin(k * 90 deg),
            sy(h) + dy * k / 8 + dx / ln * 6 mm * sin(k * 90 deg)) for k in range(9)]
    body = Stroke(Spline(pts), width=5, fill=true)
}

def pawn_half(mouth="top", num=1) -> solid {
    head = Circle(center=(0, PAWN_H - 7 mm), diameter=14)
    waist = Trapezoid(center=(0, 13), bottom_width=20, top_width=8, height=26)
    foot = Rectangle(center=(0, 2), width=24, height=4)
    if mouth == "top" {
        halving = cross_halving(depth=PAWN_H / 2, thickness=T, cx=0, cy=PAWN_H)
    } else {
        halving = cross_halving(depth=PAWN_H / 2, thickness=T, rotation=180 deg, cx=0, cy=0)
    }
    # FIX after the first valid program: the number sat on the centre line, under the other
    # half where they cross (note W0532); now on one wing of the waist.
    drawing mark {
        t = Text(str(num), position=(5.5, 8), size=4, valign="middle")
    }
    Rigid(self)
}

assembly set {
    solid board {
        plate = RoundedRectangle(center=(0, 0), width=BOARD, height=BOARD, corner_radius=8)
        drawing grid {
            for i in range(11) {
                h = Line((-5 * SQ, -5 * SQ + i * SQ), (5 * SQ, -5 * SQ + i * SQ))
                v = Line((-5 * SQ + i * SQ, -5 * SQ), (-5 * SQ + i * SQ, 5 * SQ))
            }
            for n in range(1, 101) {
                num = Text(str(n), position=(sx(n) - 13 mm, sy(n) + 8 mm), size=5, anchor="start",
                           valign="middle")
            }
            title = Text("SNAKES & LADDERS", position=(0, -BOARD / 2 + 6 mm), size=6, valign="middle")
        }
        # FIX after the first valid program: ladders and snakes ran over 14 numbers (W0513);
        # they now stop short of each number: a hole in their drawing round every number.
        drawing art {
            for j in range(4) {
                lad = ladder(a=LADDERS[j][0], b=LADDERS[j][1])
                sn = snake(h=SNAKES[j][0], t=SNAKES[j][1])
            }
            hole knockout {
                for n in range(1, 101) {
                    k = Rectangle(bottom_left=(sx(n) - 14.5 mm, sy(n) + 4 mm),
                                  width=4.2 mm * len(str(n)) + 3 mm, height=8 mm)
                }
            }
        }
        # FIX (fix 3): with the knockout hole in the same drawing the filled head circles
        # vanished (no message); the heads now have a drawing of their own.
        drawing heads {
            for j in range(4) {
                hd = Circle(center=(sx(SNAKES[j][0]), sy(SNAKES[j][0])), diameter=10, fill=true)
            }
        }
        Fixed(plate)
    }

    p1a = pawn_half(mouth="top", num=1)
    p1b = pawn_half(mouth="bottom", num=1)
    p2a = pawn_half(mouth="top", num=2)
    p2b = pawn_half(mouth="bottom", num=2)

    # flat layout: the pawn halves in a column right of the board
    RightOf(p1a, board, gap=6)
    AlignTop(p1a, board)
    Below(p1b, p1a, gap=6)
    AlignLeft(p1b, p1a)
    Below(p2a, p1b, gap=6)
    AlignLeft(p2a, p1b)
    Below(p2b, p2a, gap=6)
    AlignLeft(p2b, p2a)

    # 3D: the board lies flat, each pawn's halves cross on its square's centre
    Place(board, position=(0, 0, 0), face="up", up="back")
    Place(p1a, position=(sx(1), sy(1) + T / 2, T), face="front", up="up")
    Place(p1b, position=(sx(1) - T / 2, sy(1), T), face="right", up="up")
    Place(p2a, position=(sx(2), sy(2) + T / 2, T), face="front", up="up")
    Place(p2b, position=(sx(2) - T / 2, sy(2), T), face="right", up="up")

    # the request's numbers
    assert board.plate.bb.width == 324 mm and board.plate.bb.height == 324 mm, "324 square"
    assert board.grid.v[10].start.x - board.grid.v[0].start.x == 300 mm, "300 mm grid"
    assert len(board.grid.num) == 100, "numbers 1-100"
    assert len(board.art.lad) == 4 and len(board.art.sn) == 4, "four ladders, four snakes"
    assert sx(11) == sx(10) and sy(11) - sy(10) == 30 mm, "11 above 10 (back and forth)"
    assert sx(100) == sx(81), "100 at the top left"
    assert p1a.bb.height == 39 mm, "pawns 39 mm tall"
    assert p1a.halving.depth + p1b.halving.depth == 39 mm, "halvings meet"
}
