# Request (signs): a "NO BALL GAMES" sign for our courtyard wall, 5 mm white acrylic,
# 300 mm wide x 400 mm tall with 15 mm round corners, fixed by four countersunk screws
# (5 mm holes, 10 mm heads) 15 mm in from each side at the corners. A prohibition symbol
# engraved filled (to paint red): a ring 200 mm outside, 20 mm wide, centred 70 mm above
# the sign's middle, and a 20 mm bar across it from top-left to bottom-right. Inside it a
# football 80 mm across: its outline, a filled pentagon in the middle (14 mm to its
# corners) and five seams out to the rim, hidden where the bar crosses. Under the symbol
# "NO BALL" over "GAMES" in bold letters 40 mm high, engraved filled, centred 80 and
# 140 mm below the middle, and "ELM COURT RESIDENTS" 7 mm high under them, 175 mm below
# the middle.

units mm
thickness 5 mm

cy = 70 mm   # symbol centre above the sign's middle

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=300, height=400, corner_radius=15)

    hole screw { c = Circle(center=(-135, -185), diameter=5) }
    screws = CornerPattern(screw, plate, inset=15)
    Countersink(screws, diameter=10 mm)

    drawing symbol {
        rim = Circle(center=(0, cy), radius=100, construction=true)
        ring = Shell(rim, -20, fill=true)
        bar = Rectangle(center=(0, cy), width=170, height=20, rotation=-45 deg, fill=true)
    }

    drawing ball {
        outline = Circle(center=(0, cy), radius=40)
        patch = RegularPolygon(center=(0, cy), radius=14, sides=5, rotation=90 deg, fill=true)
        for k in range(5) {
            seam = Line((14 * cos(90 deg + k * 72 deg), cy + 14 * sin(90 deg + k * 72 deg)),
                        (40 * cos(90 deg + k * 72 deg), cy + 40 * sin(90 deg + k * 72 deg)))
        }
        hole under_bar {
            r = Rectangle(center=(0, cy), width=170, height=20, rotation=-45 deg)
        }
    }

    drawing words {
        l1 = Text("NO BALL", position=(0, -80), size=40, font="sans:Bold", valign="middle",
                  fill=true)
        l2 = Text("GAMES", position=(0, -140), size=40, font="sans:Bold", valign="middle",
                  fill=true)
        l3 = Text("ELM COURT RESIDENTS", position=(0, -175), size=7, valign="middle")
    }

    Fixed(plate)
    assert plate.width == 300 mm and plate.height == 400 mm, "300 x 400"
    assert screws[0].c.center.x - plate.bb.left == 15 mm, "screws 15 mm in"
    assert screws[0].c.center.y - plate.bb.bottom == 15 mm, "screws 15 mm up"
    assert len(screws) == 4, "four screws"
    assert symbol.rim.center.y - plate.center.y == 70 mm, "symbol 70 mm above the middle"
    assert words.l1.bb.width <= 270 mm, "words fit inside the screws"
    assert distance(words, symbol) >= 10 mm, "words clear of the symbol"
    assert plate.bb.top - symbol.bb.top >= 20 mm, "symbol clear of the top"
}
