# Sign: "STUDIO" door sign cut from 3 mm acrylic, the letters themselves are the part:
# sans Bold outline letters, 40 mm cap height, standing on a rail 12 mm tall that runs 12 mm
# past the word at each end; the rail's top is 2 mm above the letters' baseline so every
# letter merges into it. A 4 mm screw hole in each end of the rail, 6 mm from the end,
# centred in the rail's height.

thickness 3 mm

solid sign {
    word = Text("STUDIO", (0, 0), size=40, font="sans:Bold")
    rail = Rectangle(center=(word.bb.center_x, -4), width=word.bb.width + 24, height=12)
    hole hang_l {
        c = Circle(center=(0, 0), diameter=4)
    }
    hole hang_r {
        c = Circle(center=(0, 0), diameter=4)
    }
    hang_l.c.center.x == rail.bb.left + 6 mm
    hang_l.c.center.y == rail.center.y
    hang_r.c.center.x == rail.bb.right - 6 mm
    hang_r.c.center.y == rail.center.y

    assert word.size == 40 mm, "40 mm letters"
    assert rail.height == 12 mm, "rail 12 mm tall"
    assert word.bb.left - rail.bb.left == 12 mm, "rail 12 mm past the word on the left"
    assert rail.bb.right - word.bb.right == 12 mm, "rail 12 mm past the word on the right"
    assert rail.bb.top - word.position.y == 2 mm, "rail's top 2 mm above the baseline"
    assert hang_l.c.diameter == 4 mm and hang_r.c.diameter == 4 mm, "4 mm screw holes"
    assert rail.bb.right - hang_r.c.center.x == 6 mm, "hole 6 mm from the end"
    assert hang_l.c.center.y == rail.center.y, "holes centred in the rail"
}
