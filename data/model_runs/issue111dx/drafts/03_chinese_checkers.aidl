# Request (toys): a Chinese checkers board for 14 mm marbles, two layers of 3 mm ply glued.
# - Top: a 390 mm disc with the 121 marble holes (11 mm) of a six-pointed star on a
#   triangular grid of 22 mm pitch; points of the star to the left and right (0, 60, 120...
#   degrees). The star's outline engraved 12 mm outside the hole centres (a hexagram,
#   outer radius = tip hole + 24 mm). "CHINESE CHECKERS" engraved in 10 mm serif letters
#   over the top of the rim, "THE OKAFOR FAMILY" under the bottom, reading upright.
# - Bottom: the same 390 mm disc, plain; it closes the holes.
# It must fit a 400 x 400 mm bed.

thickness 3 mm

pitch = 22 mm
hole_d = 11 mm
board_d = 390 mm
N = 17                       # grid of N x N cube coordinates, -8 .. 8
def q_of(k) = k // N - 8
def r_of(k) = k % N - 8
def s_of(k) = -q_of(k) - r_of(k)
def up_tri(k) = q_of(k) >= -4 and r_of(k) >= -4 and s_of(k) >= -4
def down_tri(k) = q_of(k) <= 4 and r_of(k) <= 4 and s_of(k) <= 4
def in_star(k) = up_tri(k) or down_tri(k)
# grid to the plane: tips of the star at 0, 60, 120 ... degrees
def hx(k) = pitch * r_of(k) * sqrt(3) / 2
def hy(k) = pitch * (q_of(k) + r_of(k) / 2)
cells = [k for k in range(N * N) if in_star(k)]
tip_r = 12 * pitch / sqrt(3)          # centre to the tip hole
star_r = tip_r + 24 mm                # the engraved hexagram's tips

assembly board {
    solid top {
        disc = Circle(center=(0, 0), diameter=board_d)
        for k in cells {
            hole cup { c = Circle(center=(hx(k), hy(k)), diameter=hole_d) }
        }
        drawing marks {
            star = Star(center=(0, 0), points=6, outer_radius=star_r, inner_radius=star_r / sqrt(3),
                        rotation=90 deg)
            rim = Circle(center=(0, 0), radius=star_r - 8 mm, construction=true)
            title = Text("CHINESE CHECKERS", along=rim, size=10, font="serif", fill=true)
            family = Text("THE OKAFOR FAMILY", along=rim, size=10, font="serif", fill=true,
                          flip=true)
        }
        Fixed(disc)
        Concentric(marks.star, disc)
    }

    solid bottom {
        disc = Circle(center=(0, 0), diameter=board_d)
    }
    Place(bottom, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, 3 mm), face="up")
    RightOf(bottom, top, gap=10)
    AlignTop(bottom, top)

    assert len(cells) == 121, "121 holes"
    assert len(top.cup) == 121, "121 holes cut"
    assert board_d <= 400 mm, "fits the 400 mm bed"
    assert norm((hx(cells[0]), hy(cells[0]))) <= tip_r + 0.01 mm, "a tip hole is the farthest"
    assert star_r + 5 mm <= board_d / 2, "the star stays on the board"
    assert pitch - hole_d >= 8 mm, "14 mm marbles in neighbouring holes do not touch"
}
