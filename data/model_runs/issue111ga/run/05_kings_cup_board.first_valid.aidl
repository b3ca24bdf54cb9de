# Request: a King's Cup party-game board, two 6 mm ply layers glued. Both are 380 mm round.
# The top layer has a 100 mm hole in the middle where the king's cup stands (the base shows
# through: a 6 mm deep pocket). Engraved on the top layer: an engraved circle at r 140 that
# the cards are spread inside; a rim band outside it split into 13 equal fields by radial
# lines, each with the card's rank (12 mm, at r 172) over its rule (6 mm, at r 152, no
# wider than 60 mm), Ace at the top and going clockwise; the fields in the lower half read
# the right way up from outside. "KING'S CUP" in bold filled letters over the pocket
# (r 58), "DRINK UP" under it.

t = 6 mm
thickness t

board_d = 380 mm
pocket_d = 100 mm
card_r = 140 mm
rank_r = 172 mm
rule_r = 152 mm
n = 13
ranks = ["A", "2", "3", "4", "5", "6", "7", "8", "9", "10", "J", "Q", "K"]
rules = ["WATERFALL", "YOU", "ME", "FLOOR", "GUYS", "CHICKS", "HEAVEN", "MATE", "RHYME",
         "CATEGORIES", "NEVER HAVE I", "QUESTIONS", "KING'S CUP"]

# the middle of field i, clockwise from the top
def field_a(i) = 90 deg - i * 360 deg / n
def lower(i) = sin(field_a(i)) < 0

assembly board {
    solid base {
        disc = Circle(center=(0, 0), diameter=board_d)
    }

    solid top {
        disc = Circle(center=(0, 0), diameter=board_d)
        hole pocket { c = Circle(center=(0, 0), diameter=pocket_d) }

        drawing marks {
            cards = Circle(center=(0, 0), radius=card_r)
            rank_ring = Circle(center=(0, 0), radius=rank_r, construction=true)
            rule_ring = Circle(center=(0, 0), radius=rule_r, construction=true)
            for i in range(n) {
                sep = Line(polar((0, 0), card_r, field_a(i) + 180 deg / n),
                           polar((0, 0), board_d / 2 - 4 mm, field_a(i) + 180 deg / n))
                rank = Text(ranks[i], along=rank_ring, angle=field_a(i), size=12,
                            valign="middle", flip=lower(i))
                rule = Text(rules[i], along=rule_ring, angle=field_a(i), size=6,
                            valign="middle", flip=lower(i), max_width=60 mm)
            }
        }
        drawing title {
            ring = Circle(center=(0, 0), radius=58 mm, construction=true)
            king = Text("KING'S CUP", along=ring, size=9, font="sans:Bold", valign="middle",
                        fill=true)
            drink = Text("DRINK UP", along=ring, size=9, font="sans:Bold", valign="middle",
                         flip=true, fill=true)
        }
        Concentric(pocket.c, disc)
    }

    # flat on the sheet: side by side; assembled: the top glued on the base
    RightOf(top, base, gap=6)
    AlignTop(top, base)
    Place(base, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, t), face="up")

    # the request's numbers
    assert base.disc.diameter == 380 mm and top.disc.diameter == 380 mm, "two 380 mm layers"
    assert top.pocket.c.diameter == 100 mm, "a 100 mm cup pocket"
    assert len(top.marks.rank) == 13 and len(top.marks.rule) == 13, "thirteen fields"
    assert len(top.marks.sep) == 13, "thirteen radial lines"
    assert top.marks.rule[9].size <= 6 mm, "rules at most 6 mm"
    assert distance(top.title, top.pocket) >= 2 mm, "the title clears the pocket"
}
