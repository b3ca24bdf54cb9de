# Request: labels for my consumer unit (fuse box), cut from 1.6 mm white-on-black engraving
# laminate: a strip under the breakers and a legend card that hangs inside the door.
# - Strip: 180 x 26 mm (ten 18 mm modules), corners R2. Engraved: a divider line between
#   cells (9 lines, 20 mm long), and in each cell the circuit number (4 mm tall) at the top,
#   its name in one or two lines (3 mm tall, at most 15 mm wide) in the middle and its rating
#   (3 mm) at the bottom.
# - Card: 110 x 150 mm, corners R4, a 5 mm hanging hole centred 8 mm from the top. Title
#   "CIRCUIT LEGEND" in bold filled letters, 8 mm tall, fitted within 96 mm, its middle 22 mm
#   under the top, a rule 30 mm under the top; then the ten circuits in rows 11 mm apart
#   (the first 40 mm under the top): number, name (4 mm, at most 60 mm wide), rating at the
#   right.
# - Circuits: 1 MAIN SWITCH 100A, 2 LIGHTS UP B6, 3 LIGHTS DOWN B6, 4 SOCKETS UP B32,
#   5 SOCKETS DOWN B32, 6 KITCHEN RING B32, 7 COOKER B40, 8 SHOWER B40, 9 BOILER B6,
#   10 GARAGE B16.

thickness 1.6 mm

circuits = [["MAIN", "SWITCH", "100A"], ["LIGHTS", "UP", "B6"], ["LIGHTS", "DOWN", "B6"],
            ["SOCKETS", "UP", "B32"], ["SOCKETS", "DOWN", "B32"], ["KITCHEN", "RING", "B32"],
            ["COOKER", "", "B40"], ["SHOWER", "", "B40"], ["BOILER", "", "B6"],
            ["GARAGE", "", "B16"]]
cell = 18 mm
cells = 10
strip_w = cells * cell
strip_h = 26 mm
card_w = 110 mm
card_h = 150 mm
name_size = 2.3 mm

def cell_x(i) = -strip_w / 2 + cell / 2 + i * cell

assembly fuse_labels {
    solid strip {
        body = RoundedRectangle(center=(0, 0), width=strip_w, height=strip_h, corner_radius=2)
        # FIX after the first valid program: max_width shrank each long name to its own size
        # (2.37 to 3 mm, notes W0113), so the cells read unevenly; all names now at one size
        # that fits the longest ("SOCKETS", 15 mm at 2.37 mm), checked by an assert.
        drawing legend {
            for i in range(cells - 1) {
                div = Line((-strip_w / 2 + (i + 1) * cell, -10), (-strip_w / 2 + (i + 1) * cell, 10))
            }
            for i in range(cells) {
                num = Text(str(i + 1), position=(cell_x(i), 8), size=4, valign="middle")
                if circuits[i][1] == "" {
                    name = Text(circuits[i][0], position=(cell_x(i), 0), size=name_size,
                                valign="middle")
                } else {
                    name = Text(circuits[i][0], position=(cell_x(i), 2), size=name_size,
                                valign="middle")
                    name2 = Text(circuits[i][1], position=(cell_x(i), -2.5), size=name_size,
                                 valign="middle")
                }
                rating = Text(circuits[i][2], position=(cell_x(i), -8.5), size=3, valign="middle")
            }
        }
    }

    solid card {
        body = RoundedRectangle(center=(0, 0), width=card_w, height=card_h, corner_radius=4)
        hole hang {
            c = Circle(center=(0, card_h / 2 - 8), diameter=5)
        }
        drawing title {
            t = Text("CIRCUIT LEGEND", position=(0, card_h / 2 - 22), size=8, valign="middle",
                     font="sans:Bold", fill=true, max_width=96)
        }
        drawing table {
            rule = Line((-card_w / 2 + 7, card_h / 2 - 30), (card_w / 2 - 7, card_h / 2 - 30))
            for i in range(cells) {
                n = Text(str(i + 1), position=(-card_w / 2 + 14, card_h / 2 - 40 - 11 * i), size=4,
                         anchor="end", valign="middle")
                w = Text(f"{circuits[i][0]} {circuits[i][1]}",
                         position=(-card_w / 2 + 19, card_h / 2 - 40 - 11 * i), size=4,
                         anchor="start", valign="middle", max_width=60)
                r = Text(circuits[i][2], position=(card_w / 2 - 7, card_h / 2 - 40 - 11 * i),
                         size=4, anchor="end", valign="middle")
            }
        }
    }

    Below(card, strip, gap=6)
    AlignLeft(card, strip)

    assert strip.body.bb.width == 180 mm and strip.body.bb.height == 26 mm, "strip 180 x 26"
    assert len(strip.legend.div) == 9, "nine dividers"
    assert max([strip.legend.name[i].bb.width for i in range(10)]) <= 15 mm, "names at most 15 wide"
    assert len(strip.legend.num) == 10 and len(circuits) == 10, "ten circuits"
    assert card.body.bb.width == 110 mm and card.body.bb.height == 150 mm, "card 110 x 150"
    assert card.body.bb.top - card.hang.c.center.y == 8 mm, "hole 8 mm from the top"
    assert card.title.t.bb.width <= 96 mm, "title within 96"
    assert card.table.n[9].position.y - card.body.bb.bottom >= 5 mm, "last row on the card"
    assert distance(card.title, card.hang) >= 2 mm, "title clear of the hole"
    assert distance(card.title, card.table) >= 1 mm, "title clear of the rule"
    assert strip.legend.bb.left >= strip.body.bb.left + 1 mm and strip.legend.bb.right <= strip.body.bb.right - 1 mm, "legend on the strip"
    assert strip.legend.bb.top <= strip.body.bb.top - 1 mm and strip.legend.bb.bottom >= strip.body.bb.bottom + 1 mm, "legend on the strip"
}
