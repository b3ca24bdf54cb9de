# Request (toys): a table-top bagatelle (pin-ball) board, 3 mm plywood, for 16 mm marbles.
# Outline 240 mm wide, straight sides 240 mm, a semicircular top (R120): 360 tall.
# A base board and three identical frame layers glued on it (9 mm high walls): each layer is
# a 10 mm rim round the outline plus a 4 mm lane divider whose right face is 20 mm from the
# rim (a 20 mm launch lane up the right side), from the rim up to 250 mm above the bottom
# edge, and a 10 mm notch in the bottom rim in the middle of the lane for the cue stick.
# The base has 1.4 mm pilot holes for panel pins: a staggered field of 6 rows x 7 pins,
# 26 mm apart in a row, rows 24 mm apart, the lowest row 110 mm up, its first pin 96 mm left
# of the centre line; four scoring cups, horseshoes of 7 pins on an R11 circle (every 30 deg
# from 0 to -180, open at the top), centred 70 mm up at x = -70, -30, 10, 50 mm, scored
# 10, 50, 100, 20 (6 mm strokes in each cup); "BAGATELLE" engraved filled (sans bold 12 mm)
# centred 25 mm up.

thickness 3 mm

cup_x = [-70, -30, 10, 50]
scores = ["10", "50", "100", "20"]

# one frame layer: the rim, the lane divider, the cue notch
def frame_layer() -> solid {
    outline = Hull(Rectangle(center=(0, 120), width=240, height=240),
                   Circle(center=(0, 240), radius=120), construction=true)
    rim = Shell(outline, -10)
    divider = Rectangle(bottom_left=(86, 5), width=4, height=245)
    hole cue {
        r = Rectangle(center=(100, 4), width=10, height=12, overrun=true)
    }
}

assembly bagatelle {
    solid base {
        outline = Hull(Rectangle(center=(0, 120), width=240, height=240),
                       Circle(center=(0, 240), radius=120))
        hole pin {
            c = Circle(center=(-96, 110), diameter=1.4)
        }
        field = GridPattern(pin, rows=6, cols=7, col_spacing=26, row_spacing=24, stagger=true)
        hole cups {
            for k in range(4) {
                for j in range(7) {
                    p = Circle(center=(cup_x[k] + 11 * cos(-j * 30 deg),
                                       70 + 11 * sin(-j * 30 deg)), diameter=1.4)
                }
            }
        }
        drawing marks {
            for k in range(4) {
                s = Text(scores[k], position=(cup_x[k], 70), size=6, valign="middle")
            }
            title = Text("BAGATELLE", position=(0, 25), size=12, font="sans:Bold",
                         valign="middle", fill=true)
        }
    }
    f1 = frame_layer()
    f2 = frame_layer()
    f3 = frame_layer()

    # laid out flat for cutting
    RightOf(f1, base, gap=5)
    AlignBottom(f1, base)
    RightOf(f2, f1, gap=5)
    AlignBottom(f2, base)
    RightOf(f3, f2, gap=5)
    AlignBottom(f3, base)

    # assembled: the base flat, the frame layers stacked on it
    Place(base, position=(0, 0, 0), face="up")
    Place(f1, position=(0, 0, 3), face="up")
    Place(f2, position=(0, 0, 6), face="up")
    Place(f3, position=(0, 0, 9), face="up")

    # the request's numbers
    assert base.bb.width == 240 mm and base.bb.height == 360 mm, "outline 240 x 360"
    assert f1.bb.width == 240 mm and f1.bb.height == 360 mm, "frame layers match the base"
    assert len(base.field) == 6 * 7, "6 rows of 7 pins"
    assert len(base.cups.p) == 4 * 7, "four cups of 7 pins"
    assert base.field[1].c.center.x - base.field[0].c.center.x == 26 mm, "pins 26 apart"
    assert base.field[7].c.center.y - base.field[0].c.center.y == 24 mm, "rows 24 apart"
    # a 16 mm marble passes between neighbouring cups and beside the last one
    assert (cup_x[1] - 11) - (cup_x[0] + 11) - 1.4 >= 16 + 1, "marble passes between cups"
    assert (f1.divider.bb.left) - (cup_x[3] + 11 + 0.7) >= 16 + 1, "marble passes right cup"
    assert f1.rim.bb.right - 10 mm - f1.divider.bb.right == 20 mm, "launch lane 20 wide"
    assert f1.divider.bb.top == 250 mm, "divider 250 up"
    assert base.field[41].c.center.x + 0.7 <= f1.divider.bb.left - 5 mm, "pins left of the lane"
    assert distance(base.marks.title, base.cups) >= 3 mm, "title clear of the cups"
}
