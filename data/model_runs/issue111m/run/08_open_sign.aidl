# Signs: an "OPEN" sign that hangs in a shop window, 4 mm acrylic. The letters are the
# material: "OPEN" in the plain sans font (font="sans"), 50 mm cap height, hung from a
# top rail 10 mm tall that overlaps the letters' tops by 3 mm and runs 15 mm past the
# word at each end; a bottom rail 6 mm tall overlapping the letters' feet by 3 mm, as
# long as the word. Two 5 mm hanging holes in the top rail, 7.5 mm from its ends, on
# its centre line.

thickness 4 mm

param size = 50 mm, min = 30 mm, max = 80 mm

solid sign {
    word = Text("OPEN", (0, 0), size=size, font="sans")
    top_rail = Rectangle(center=(0, size), width=word.bb.width + 30, height=10)
    bottom_rail = Rectangle(center=(0, 0), width=word.bb.width, height=6)
    AlignCenterX(top_rail, word)
    AlignCenterX(bottom_rail, word)
    top_rail.bb.bottom == word.bb.top - 3 mm
    bottom_rail.bb.top == word.bb.bottom + 3 mm

    hole hang_l {
        c = Circle(center=(0, 0), diameter=5)
    }
    hole hang_r {
        c = Circle(center=(0, 0), diameter=5)
    }
    hang_l.c.center.x == top_rail.bb.left + 7.5 mm
    hang_r.c.center.x == top_rail.bb.right - 7.5 mm
    hang_l.c.center.y == top_rail.center.y
    hang_r.c.center.y == top_rail.center.y

    assert word.size == 50 mm, "50 mm letters"
    assert top_rail.height == 10 mm, "top rail 10 tall"
    assert word.bb.top - top_rail.bb.bottom == 3 mm, "top rail overlaps 3"
    assert top_rail.bb.right - word.bb.right == 15 mm and word.bb.left - top_rail.bb.left == 15 mm, "15 past each end"
    assert bottom_rail.height == 6 mm, "bottom rail 6 tall"
    assert bottom_rail.bb.top - word.bb.bottom == 3 mm, "bottom rail overlaps 3"
    assert bottom_rail.width == word.bb.width, "bottom rail as long as the word"
    assert hang_l.c.diameter == 5 mm and hang_r.c.diameter == 5 mm, "5 mm holes"
    assert hang_l.c.center.x - top_rail.bb.left == 7.5 mm, "left hole 7.5 from the end"
    assert top_rail.bb.right - hang_r.c.center.x == 7.5 mm, "right hole 7.5 from the end"
    assert hang_r.c.center.y == top_rail.center.y, "holes on the centre line"
}
