# Parties: one pennant of a letter bunting, 3 mm card-thick plywood: a triangle 200 mm
# wide along the top edge, its point 240 mm below; two 5 mm string holes 15 mm in from
# each top corner and 8 mm below the top edge; the letter "A" cut through as a stencil
# (sans Bold, 70 mm tall), centred across, the centre of its letter box 70 mm below the top.

thickness 3 mm

solid pennant {
    flag = Triangle(center=(0, 0), base=200, height=240, rotation=180)

    hole string_left { c = Circle(center=(-85, 112), diameter=5) }
    hole string_right { c = Circle(center=(85, 112), diameter=5) }
    string_left.c.center.x == flag.bb.left + 15
    string_right.c.center.x == flag.bb.right - 15
    string_left.c.center.y == flag.bb.top - 8
    string_right.c.center.y == flag.bb.top - 8

    hole letter {
        glyph = Text("A", (0, 50), size=70, font="sans:Bold", stencil=true, valign="middle")
    }
    AlignCenterX(letter, flag)
    letter.bb.center_y == flag.bb.top - 70

    assert flag.bb.width == 200 mm, "200 wide"
    assert flag.bb.height == 240 mm, "240 deep"
    assert flag.c.y == flag.bb.bottom, "point down"
    assert string_left.c.diameter == 5 mm and string_right.c.diameter == 5 mm, "5 mm holes"
    assert string_left.c.center.x - flag.bb.left == 15 mm, "15 in from the left corner"
    assert flag.bb.right - string_right.c.center.x == 15 mm, "15 in from the right corner"
    assert flag.bb.top - string_left.c.center.y == 8 mm, "8 below the top"
    assert letter.glyph.size == 70 mm, "70 mm letter"
    assert abs(letter.bb.center_x - flag.bb.center_x) < 0.01 mm, "centred"
    assert flag.bb.top - letter.bb.center_y == 70 mm, "70 below the top"
    assert letter.bb.top < flag.bb.top - 10 mm, "letter clear of the top edge"
}
