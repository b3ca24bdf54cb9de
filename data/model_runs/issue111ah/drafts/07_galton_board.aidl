# Request (science): a Galton board (bean machine) for a maths classroom, 240 x 420 mm, for
# 5 mm steel balls, three layers held by eight M3 screws (3.4 mm holes 8 mm in from the
# edges: the four corners and the middle of each long side). Back: 3 mm ply with 78 peg holes
# 3.0 mm for 3 mm dowel pegs in 12 staggered rows forming a triangle (row 1: 1 peg, row 12:
# 12 pegs), pegs 16 mm apart in a row, rows 14 mm apart, the first row 310 mm above the
# bottom. Middle: 6 mm ply spacer: a 16 mm frame, a funnel at the top (two walls from the
# sides down to a 12 mm opening 12 mm above the first peg), and 12 divider fingers 3 mm wide
# rising 120 mm above the bottom rail under the 12 pegs of the last row, making 13 bins
# 16 mm wide. Front: 3 mm clear acrylic with "GALTON BOARD" engraved 12 mm high across the
# top and the binomial bell curve (12 rows, sigma = sqrt(3) bins) engraved over the bins,
# 110 mm high at its peak.

thickness 3 mm

board_w = 240 mm
board_h = 420 mm
wall = 16 mm
rows = 12
pitch = 16 mm
row_step = 14 mm
first_row_y = 310 mm
bin_h = 120 mm
finger_w = 3 mm
funnel_gap = 12 mm
e = 2.718281828
sigma = sqrt(3) * 16  # a plain number: the exponent must be unitless
screw_at = [(-112, 8), (112, 8), (-112, 210), (112, 210), (-112, 412), (112, 412)]

def screws() -> hole {
    for p in screw_at {
        c = Circle(center=p, diameter=3.4)
    }
}

def bell(x) = wall + 110 * e ** (-(x * x) / (2 * sigma * sigma))

assembly galton {
    solid back {
        plate = Rectangle(bottom_left=(-board_w / 2, 0), width=board_w, height=board_h)
        fix = screws()
        hole pegs {
            for i in range(rows) {
                for j in range(i + 1) {
                    c = Circle(center=((j - i / 2) * pitch, first_row_y - i * row_step),
                               diameter=3.0)
                }
            }
        }
        assert len(pegs.c) == 12 and len(pegs.c[11]) == 12, "12 rows, 12 pegs in the last"
        assert sum([len(r) for r in pegs.c]) == 78, "78 pegs"
    }

    solid spacer {
        thickness 6 mm
        outline = Rectangle(bottom_left=(-board_w / 2, 0), width=board_w, height=board_h,
                            construction=true)
        frame = Shell(outline, -wall, join="miter")
        funnel_l = Polygon([(-board_w / 2 + wall - 1, 385), (-funnel_gap / 2, first_row_y + 12 + 10),
                            (-funnel_gap / 2, first_row_y + 12), (-board_w / 2 + wall - 1, 370)])
        funnel_r = Polygon([(board_w / 2 - wall + 1, 385), (funnel_gap / 2, first_row_y + 12 + 10),
                            (funnel_gap / 2, first_row_y + 12), (board_w / 2 - wall + 1, 370)])
        for k in range(rows) {
            finger = Rectangle(center=((k - (rows - 1) / 2) * pitch, wall + bin_h / 2 - 1),
                               width=finger_w, height=bin_h + 2)
        }
        fix = screws()
        assert len(finger) == 12, "12 dividers, 13 bins"
        assert finger[0].bb.top - wall == 120 mm - 1 mm + 1 mm, "dividers 120 above the rail"
    }

    solid front {
        plate = Rectangle(bottom_left=(-board_w / 2, 0), width=board_w, height=board_h)
        fix = screws()
        drawing art {
            title = Text("GALTON BOARD", position=(0, 390), size=12, valign="middle")
            curve = Spline([(x, bell(x)) for x in range(-104, 105, 8)])
        }
    }

    RightOf(spacer, back, gap=10)
    RightOf(front, spacer, gap=10)
    AlignBottom(spacer, back)
    AlignBottom(front, back)

    # the last row's pegs stand right above the dividers
    assert back.pegs.c[11][0].center.x - back.plate.bb.center_x ==
        spacer.finger[0].center.x - spacer.outline.bb.center_x, "dividers under the last pegs"
    assert board_w - 2 * wall == 13 * pitch, "13 bins of 16 mm fill the frame"
}
