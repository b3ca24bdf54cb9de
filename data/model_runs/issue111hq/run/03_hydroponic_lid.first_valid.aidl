# Request (garden): a Kratky (no-pump) hydroponic lid for a 35 l storage box in the
# greenhouse. 5 mm white acrylic, 400 x 280 mm with 20 mm corners, resting on the box's rim.
# Six 2-inch net pots (50 mm rim, 46 mm body) drop into 47 mm holes, 2 rows x 3, 120 mm
# apart both ways, the grid centred on the lid. Under each pot its plant is engraved 6 mm
# tall, 8 mm below the hole: BASIL, MINT, CHIVES (back row), LETTUCE, PARSLEY, ROCKET (front
# row). A 30 mm top-up hole centred 28 mm in from the right end on the centre line, with
# "FILL" engraved 5 mm tall 6 mm above it, closed by a plug of two glued discs: a 44 mm cap
# and a 29.5 mm spigot that sits in the hole.

thickness 5 mm

pitch = 120 mm
pot_hole = 47 mm
fill_d = 30 mm
plants = ["LETTUCE", "PARSLEY", "ROCKET", "BASIL", "MINT", "CHIVES"]

assembly kratky {
    solid lid {
        body = RoundedRectangle(center=(0, 0), width=400, height=280, corner_radius=20)
        Fixed(body)
        hole pot {
            c = Circle(center=(-pitch, -pitch / 2), diameter=pot_hole)
        }
        pots = GridPattern(pot, 2, 3, (pitch, pitch))
        hole fill {
            c = Circle(center=(200 - 28, 0), diameter=fill_d)
        }
        drawing names {
            for i in range(6) {
                t = Text(plants[i], (-pitch + (i % 3) * pitch,
                                     -pitch / 2 + (i // 3) * pitch - pot_hole / 2 - 8 mm),
                         size=6, valign="top")
            }
        }
        drawing fill_label {
            t = Text("FILL", (200 - 28, fill_d / 2 + 6 mm), size=5)
        }

        assert len(pots) == 6, "six net pots"
        assert pots[1].c.center.x - pots[0].c.center.x == 120 mm, "120 mm apart across"
        assert pots[3].c.center.y - pots[0].c.center.y == 120 mm, "120 mm apart front to back"
        assert pots[0].c.diameter == 47 mm, "47 mm holes for 2-inch net pots"
        assert abs(pots[0].c.center.x + pots[5].c.center.x) < 0.01 mm and
            abs(pots[0].c.center.y + pots[5].c.center.y) < 0.01 mm, "grid centred"
        assert body.bb.right - fill.c.center.x == 28 mm, "fill hole 28 mm in from the right end"
        assert distance(fill, pots) >= 8 mm, "acrylic between the fill hole and the pots"
        assert pots[0].c.bottom.y - names.t[0].bb.top >= 7.9 mm, "labels 8 mm below the holes"
        assert distance(names, pots) >= 7.9 mm, "labels clear every pot hole"
        assert names.t[3].text == "BASIL", "basil at the back left"
        assert fill_label.bb.bottom - fill.c.top.y == 6 mm, "FILL 6 mm above its hole"
        assert fill_label.bb.right <= body.bb.right - 3 mm, "FILL stays on the lid"
    }
    solid cap {
        c = Circle(center=(260, 0), diameter=44)
    }
    solid spigot {
        c = Circle(center=(260, -60), diameter=29.5)
    }
    assert cap.c.diameter > fill_d + 10 mm, "the cap covers the hole with 5 mm to spare"
    assert spigot.c.diameter < fill_d and spigot.c.diameter > fill_d - 1 mm,
        "the spigot slips into the hole without rattling"
}
