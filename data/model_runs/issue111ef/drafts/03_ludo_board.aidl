# Request (toys): a Ludo board and its 16 counters, 3 mm plywood (laser bed 400 x 400).
# - Board 395 x 395 mm, corners R10. The track: 15 x 15 squares of 25 mm, centred; four
#   arms three squares wide and six long around a 3 x 3 centre square, engraved as lines.
# - The centre square crossed by its two diagonals.
# - Each home column (the five inner squares of an arm's middle row) marked with a filled
#   10 mm dot in each square.
# - Each start square (the arm's second square from the outside, on the row or column next
#   to the player's base) marked with a filled five-pointed star, radii 10 and 4.
# - Each 150 mm corner base engraved with a 130 mm circle, four 24 mm counter rings 60 mm
#   apart (centre to centre) about the base's centre, and the colour's name 54 mm below the
#   centre (7 mm): RED top left, GREEN top right, YELLOW bottom right, BLUE bottom left.
# - 16 counters, 20 mm discs, four of each colour, the colour's initial engraved filled
#   (bold sans, 10 mm), laid out beside the board.

thickness 3 mm

cell = 25 mm
names = ["RED", "GREEN", "YELLOW", "BLUE"]
initials = ["R", "G", "Y", "B"]
base_x = [-112.5, 112.5, 112.5, -112.5]
base_y = [112.5, 112.5, -112.5, -112.5]
star_x = [-150, 25, 150, -25]
star_y = [25, 150, -25, -150]

def counter(letter="R") -> solid {
    disc = Circle(center=(0, 0), diameter=20)
    drawing mark {
        t = Text(letter, position=(0, 0), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
}

assembly ludo {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=395, height=395, corner_radius=10)
        drawing track {
            for k in range(4) {
                hl = Line((-187.5, -37.5 + k * cell), (-37.5, -37.5 + k * cell))
                hr = Line((37.5, -37.5 + k * cell), (187.5, -37.5 + k * cell))
                vb = Line((-37.5 + k * cell, -187.5), (-37.5 + k * cell, -37.5))
                vt = Line((-37.5 + k * cell, 37.5), (-37.5 + k * cell, 187.5))
            }
            for k in range(7) {
                cl = Line((-187.5 + k * cell, -37.5), (-187.5 + k * cell, 37.5))
                cr = Line((37.5 + k * cell, -37.5), (37.5 + k * cell, 37.5))
                cb = Line((-37.5, -187.5 + k * cell), (37.5, -187.5 + k * cell))
                ct = Line((-37.5, 37.5 + k * cell), (37.5, 37.5 + k * cell))
            }
            d1 = Line((-37.5, -37.5), (37.5, 37.5))
            d2 = Line((-37.5, 37.5), (37.5, -37.5))
        }
        drawing homes {
            for k in range(5) {
                l = Circle(center=(-150 + k * cell, 0), diameter=10, fill=true)
                r = Circle(center=(150 - k * cell, 0), diameter=10, fill=true)
                t = Circle(center=(0, 150 - k * cell), diameter=10, fill=true)
                b = Circle(center=(0, -150 + k * cell), diameter=10, fill=true)
            }
        }
        drawing starts {
            for p in range(4) {
                s = Star(center=(star_x[p], star_y[p]), points=5, outer_radius=10,
                         inner_radius=4, fill=true)
            }
        }
        drawing bases {
            for p in range(4) {
                ring = Circle(center=(base_x[p], base_y[p]), diameter=130)
                s1 = Circle(center=(base_x[p] - 30, base_y[p] + 30), diameter=24)
                s2 = Circle(center=(base_x[p] + 30, base_y[p] + 30), diameter=24)
                s3 = Circle(center=(base_x[p] - 30, base_y[p] - 30), diameter=24)
                s4 = Circle(center=(base_x[p] + 30, base_y[p] - 30), diameter=24)
                name = Text(names[p], position=(base_x[p], base_y[p] - 54), size=7,
                            valign="middle")
            }
        }
    }

    for i in range(16) {
        c = counter(letter=initials[i // 4])
        c.disc.center.x == 222.5 + (i % 4) * 26
        c.disc.center.y == 150 - (i // 4) * 26
    }

    assert board.body.bb.width == 395 mm and board.body.bb.height == 395 mm, "395 x 395 board"
    assert board.track.cl[1].start.x - board.track.cl[0].start.x == 25 mm, "25 mm squares"
    assert board.track.cr[6].start.x - board.track.cl[0].start.x == 375 mm, "15 squares across"
    assert len(board.homes.l) == 5, "five squares in a home column"
    assert len(board.starts.s) == 4 and len(board.bases.ring) == 4, "four players"
    assert board.bases.s2[0].center.x - board.bases.s1[0].center.x == 60 mm, "rings 60 apart"
    assert len(c) == 16, "16 counters"
    assert c[0].disc.diameter == 20 mm, "20 mm counters"
    assert c[0].bb.left - board.body.bb.right >= 3 mm, "counters beside the board"
}
