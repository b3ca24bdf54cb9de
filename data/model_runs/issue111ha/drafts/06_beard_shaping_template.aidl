# Request (bathroom): "A beard-shaping template from 3 mm acrylic to hold against my face
# while trimming. About 150 mm long: the top edge an S-shaped cheek line, the bottom edge a
# U-shaped neckline curve dipping 27 mm below its ends, the right end a straight edge with a
# comb of 8 slots (2 mm wide, 15 mm deep, 5 mm pitch) to lift the hairs, the left end a
# straight edge with a 0-45 mm scale engraved (a tick every 5 mm, numbered every 10). A 6 mm
# hole to hang it by the mirror, CHEEK LINE and NECK LINE engraved along their edges, and
# SHAPE UP in bold in the middle."

thickness 3 mm
min_wall 0.5 mm

param teeth = 8, min = 4, max = 9
param slot_w = 2 mm, min = 1.5 mm, max = 3 mm
param slot_depth = 15 mm, min = 8 mm, max = 20 mm
param comb_pitch = 5 mm, min = 4 mm, max = 6 mm

solid template {
    # counter-clockwise from the bottom-left corner; sharp at the four corners
    outline = Spline([(-75, -15), (-40, -35), (0, -42), (40, -35), (75, -15),
                      (75, 35), (40, 28), (0, 40), (-40, 30), (-75, 38)],
                     closed=true, corners=[0, 4, 5, 9])

    hole comb {
        s = Rectangle(bottom_left=(75 mm - slot_depth, -10 mm), width=slot_depth + 1 mm,
                      height=slot_w)
    }
    slots = LinearPattern(comb, teeth, (0, comb_pitch))

    hole hang {
        c = Circle(center=(-48, 8), diameter=6)
    }

    drawing scale {
        for i in range(10) {
            tick = Line((-75, -12 + i * 5), (-67 if i % 2 == 0 else -71, -12 + i * 5))
        }
        for j in range(5) {
            num = Text(str(j * 10), position=(-62, -12 + j * 10), size=3, anchor="start",
                       valign="middle")
        }
    }

    drawing labels {
        cheek = Text("CHEEK LINE", position=(0, 29), size=4, valign="middle")
        neck = Text("NECK LINE", position=(0, -31), size=4, valign="middle")
        brand = Text("SHAPE UP", position=(8, 0), size=9, font="sans:Bold", fill=true,
                     valign="middle")
    }

    assert outline.points[4].x - outline.points[0].x == 150 mm, "150 mm long"
    assert outline.points[0].y - outline.points[2].y == 27 mm, "neckline dips 27 mm"
    assert len(slots) == 8, "8 comb slots"
    assert comb.s.height == 2 mm and comb.s.bb.right - slot_depth - 1 mm == 60 mm, "2 mm slots, 15 mm deep"
    assert slots[1].s.bb.bottom - slots[0].s.bb.bottom == 5 mm, "5 mm pitch"
    assert slots[7].s.bb.top <= outline.points[5].y - 3 mm, "comb within the right edge"
    assert hang.c.diameter == 6 mm, "6 mm hanging hole"
    assert len(scale.tick) == 10 and len(scale.num) == 5, "0-45 mm ticks, numbered 0-40"
    assert distance(labels.brand, comb) >= 3 mm, "brand clear of the comb"
    assert distance(labels.brand, hang) >= 3 mm, "brand clear of the hanging hole"
    assert distance(scale, hang) >= 2 mm, "scale clear of the hanging hole"
}
