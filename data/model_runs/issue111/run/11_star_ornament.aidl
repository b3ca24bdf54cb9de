# Christmas star ornament: a five-pointed star 90 mm tip circle (45 mm outer radius), 20 mm
# inner radius, tips rounded 3 mm, first tip up; a 4 mm hanging hole 8 mm below the top
# tip's point; "2026" engraved across the middle, 9 mm letters.

solid star {
    shape = Star(center=(0, 0), points=5, outer_radius=45, inner_radius=20, tip_radius=3)
    hole hang {
        c = Circle(center=(0, 37), diameter=4)
    }
    hang.c.center.y == shape.center.y + 45 mm - 8 mm
    AlignCenterX(hang, shape)
    drawing year {
        t = Text("2026", position=(0, 0), size=9, valign="middle")
    }
    CenterInside(year, shape)
    assert shape.outer_radius == 45 mm and shape.inner_radius == 20 mm, "star 45 / 20 mm"
    assert hang.c.diameter == 4 mm, "4 mm hole"
    assert year.bb.width < 2 * 20 mm, "year inside the star's body"
}
