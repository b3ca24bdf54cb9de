# Eurorack 3U module front panel, 8 HP: 40.3 x 128.5 mm, 2 mm aluminium composite.
# Mounting: two oblong slots 5.5 mm long (horizontal) x 3.2 mm wide, centred 7.5 mm from the
# left edge and 3 mm from the top edge and from the bottom edge.
# Two pot holes 7.5 mm diameter on the vertical centre line, 30 mm and 55 mm below the top edge.
# An LED hole 3 mm diameter on the centre line, 75 mm below the top edge.
# Three jack holes 6 mm diameter, 105 mm below the top edge, 12 mm apart, the middle one on the
# centre line.
# Engraved single-stroke labels 3 mm high: "FREQ" centred 11 mm below pot 1's centre, "RES"
# 11 mm below pot 2's, "IN", "CV", "OUT" centred 7 mm above the jacks (left to right); the
# title "VCF" 5 mm high, centred on the centre line with its baseline 16 mm below the top edge.
units mm
thickness 2 mm

hp_w = 40.3 mm
panel_h = 128.5 mm

solid panel {
    body = Rectangle(bottom_left=(0, -panel_h), width=hp_w, height=panel_h)
    Fixed(body)

    hole mount {
        upper = Slot(center=(7.5, -3), length=5.5, width=3.2)
        lower = Slot(center=(7.5, 3 - panel_h), length=5.5, width=3.2)
    }
    hole pots {
        freq = Circle(center=(hp_w / 2, -30), diameter=7.5)
        res = Circle(center=(hp_w / 2, -55), diameter=7.5)
    }
    hole led {
        c = Circle(center=(hp_w / 2, -75), diameter=3)
    }
    hole jack {
        c = Circle(center=(hp_w / 2 - 12, -105), diameter=6)
    }
    jacks = LinearPattern(jack, 3, (12, 0))

    drawing labels {
        title = Text("VCF", position=(hp_w / 2, -16), size=5)
        freq = Text("FREQ", position=(hp_w / 2, -30 - 11), size=3, valign="middle")
        res = Text("RES", position=(hp_w / 2, -55 - 11), size=3, valign="middle")
        names = ["IN", "CV", "OUT"]
        for i in range(3) {
            j = Text(names[i], position=(hp_w / 2 - 12 + 12 * i, -105 + 7), size=3,
                     valign="middle")
        }
    }

    # the request's numbers
    assert body.width == 40.3 mm and body.height == 128.5 mm, "8 HP x 3U"
    assert mount.upper.center.x - body.left.midpoint.x == 7.5 mm, "slot 7.5 mm from the left edge"
    assert body.top.midpoint.y - mount.upper.center.y == 3 mm, "upper slot 3 mm from the top"
    assert mount.lower.center.y - body.bottom.midpoint.y == 3 mm, "lower slot 3 mm from the bottom"
    assert mount.upper.length == 5.5 mm and mount.upper.width == 3.2 mm, "slot size"
    assert body.top.midpoint.y - pots.freq.center.y == 30 mm, "pot 1 30 mm down"
    assert body.top.midpoint.y - pots.res.center.y == 55 mm, "pot 2 55 mm down"
    assert pots.freq.diameter == 7.5 mm and led.c.diameter == 3 mm, "pot and LED holes"
    assert body.top.midpoint.y - led.c.center.y == 75 mm, "LED 75 mm down"
    assert len(jacks) == 3, "three jacks"
    assert jacks[2].c.center.x - jacks[1].c.center.x == 12 mm, "jacks 12 mm apart"
    assert jacks[1].c.center.x == body.center.x, "middle jack on the centre line"
    assert body.top.midpoint.y - jacks[0].c.center.y == 105 mm, "jacks 105 mm down"
    assert jacks[0].c.diameter == 6 mm, "jack holes 6 mm"
    assert labels.title.position.y == body.top.midpoint.y - 16 mm, "title baseline 16 mm down"
}
