# Request (signs): a tsunami evacuation route sign for the path up from our harbour, cut from
# 3 mm two-colour laminate (blue over white: engraving shows white). A 400 x 300 mm plate,
# 15 mm corner radius, four 6.5 mm screw holes 20 mm in from the corners, a solid 4 mm
# border 8 mm in from the edge. Left: a 170 x 170 mm pictogram frame (10 mm corners) with a
# filled breaking wave curling to the left and a filled hill rising to the right with a
# filled arrow pointing up the slope; under it "TO HIGH GROUND", 12 mm. Right: "TSUNAMI"
# bold, 32 mm high (at most 180 mm wide), "EVACUATION" and "ROUTE" 18 mm high, and a big
# filled arrow pointing right, 155 mm long and 60 mm high. All lettering bold sans, filled.

units mm
thickness 3 mm

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=400, height=300, corner_radius=15)
    hole screw {
        c = Circle(center=(0, 0), diameter=6.5)
    }
    screws = CornerPattern(screw, plate, inset=20)

    drawing border {
        b = Shell(RoundedRectangle(center=(0, 0), width=384, height=284, corner_radius=7),
                  -4, fill=true)
    }

    drawing picto {
        frame = RoundedRectangle(center=(-95, 20), width=170, height=170, corner_radius=10)
        wave = Spline([(-173, -35), (-75, -35), (-90, 0), (-100, 40), (-120, 70), (-150, 68),
                       (-165, 50), (-150, 45), (-135, 50), (-125, 35), (-140, 15), (-165, -5)],
                      closed=true, corners=[0, 1, 6], fill=true)
        hill = Polygon([(-80, -35), (-17, -35), (-17, 25)], fill=true)
        shaft = Rectangle(start=(-75, -8), end=(-43, 24), width=6, fill=true)
        head = Polygon([(-34.5, 32.5), (-48.7, 29.7), (-37.3, 18.3)], fill=true)
        under = Text("TO HIGH GROUND", (-95, -100), size=12, font="sans:Bold", valign="middle",
                     fill=true)
    }

    drawing words {
        title = Text("TSUNAMI", (95, 70), size=32, font="sans:Bold", max_width=180, fill=true)
        l1 = Text("EVACUATION", (95, 25), size=18, font="sans:Bold", max_width=180, fill=true)
        l2 = Text("ROUTE", (95, -5), size=18, font="sans:Bold", fill=true)
        arrow = Polygon([(25, -60), (130, -60), (130, -45), (180, -75), (130, -105), (130, -90),
                         (25, -90)], fill=true)
    }
    Fixed(plate)

    # the request's numbers
    assert plate.width == 400 mm and plate.height == 300 mm, "400 x 300"
    assert len(screws) == 4 and screw.c.diameter == 6.5 mm, "four 6.5 mm holes"
    assert screw.c.center.x - plate.bb.left == 20 mm and screw.c.center.y - plate.bb.bottom == 20 mm,
        "holes 20 mm in"
    assert border.b.bb.left - plate.bb.left == 8 mm, "border 8 mm in"
    assert picto.frame.width == 170 mm and picto.frame.height == 170 mm, "170 mm frame"
    assert words.arrow.bb.width == 155 mm and words.arrow.bb.height == 60 mm, "arrow 155 x 60"
    assert words.title.bb.width <= 180 mm, "title at most 180 mm"
    # everything inside the border, clear of the holes and of each other
    assert distance(words, screws) >= 5 mm and distance(picto, screws) >= 5 mm, "clear of the screws"
    assert distance(words, picto.frame) >= 5 mm, "words clear of the pictogram"
    assert distance(picto.under, picto.frame) >= 4 mm, "caption under the frame"
    assert words.bb.right <= border.b.bb.right - 4 mm - 4 mm, "words inside the border"
    assert distance(picto.wave, picto.hill) >= 2 mm, "wave apart from the hill"
}
