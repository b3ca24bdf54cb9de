# Pasta portion measure (kitchen). Full sizes: a plate 190 x 60 mm with 10 mm corner radii,
# 3 mm birch ply. Four round holes for 1, 2, 3 and 4 portions of spaghetti: 20, 28, 34 and
# 40 mm diameter, in a row from left to right, their centres 5 mm above the plate's
# horizontal middle; the first hole's left edge 10 mm from the plate's left edge and 8 mm of
# material between neighbouring holes. Under each hole its number of portions ("1" to "4")
# engraved 6 mm high, centred under the hole, all on one baseline 8 mm above the plate's
# bottom edge. An 8 mm hanging hole centred 12 mm from the right edge on the middle line.

units mm
thickness 3 mm

solid measure {
    plate = RoundedRectangle(center=(0, 0), width=190, height=60, corner_radius=10)

    hole portions {
        p1 = Circle(center=(-75, 5), diameter=20)
        p2 = Circle(center=(-43, 5), diameter=28)
        p3 = Circle(center=(-4, 5), diameter=34)
        p4 = Circle(center=(41, 5), diameter=40)
        RightOf(p2, p1, gap=8)
        RightOf(p3, p2, gap=8)
        RightOf(p4, p3, gap=8)
    }
    portions.p1.bb.left == plate.bb.left + 10
    portions.p1.center.y == plate.center.y + 5
    portions.p2.center.y == portions.p1.center.y
    portions.p3.center.y == portions.p1.center.y
    portions.p4.center.y == portions.p1.center.y

    hole hang {
        c = Circle(center=(83, 0), diameter=8)
    }
    hang.c.center.x == plate.bb.right - 12
    hang.c.center.y == plate.center.y

    drawing numbers {
        n1 = Text("1", position=(-75, -22), size=6)
        n2 = Text("2", position=(-43, -22), size=6)
        n3 = Text("3", position=(-4, -22), size=6)
        n4 = Text("4", position=(41, -22), size=6)
    }
    AlignCenterX(numbers.n1, portions.p1)
    AlignCenterX(numbers.n2, portions.p2)
    AlignCenterX(numbers.n3, portions.p3)
    AlignCenterX(numbers.n4, portions.p4)
    numbers.n1.position.y == plate.bb.bottom + 8
    numbers.n2.position.y == numbers.n1.position.y
    numbers.n3.position.y == numbers.n1.position.y
    numbers.n4.position.y == numbers.n1.position.y

    assert plate.bb.width == 190 mm, "plate 190 mm wide"
    assert plate.bb.height == 60 mm, "plate 60 mm high"
    assert portions.p1.diameter == 20 mm and portions.p2.diameter == 28 mm, "1 and 2 portions"
    assert portions.p3.diameter == 34 mm and portions.p4.diameter == 40 mm, "3 and 4 portions"
    assert portions.p1.bb.left - plate.bb.left == 10 mm, "first hole 10 mm from the left edge"
    assert portions.p2.bb.left - portions.p1.bb.right == 8 mm, "8 mm between holes 1 and 2"
    assert portions.p3.bb.left - portions.p2.bb.right == 8 mm, "8 mm between holes 2 and 3"
    assert portions.p4.bb.left - portions.p3.bb.right == 8 mm, "8 mm between holes 3 and 4"
    assert portions.p4.center.y - plate.bb.center_y == 5 mm, "row 5 mm above the middle"
    assert plate.bb.right - hang.c.center.x == 12 mm, "hang hole 12 mm from the right edge"
    assert hang.c.diameter == 8 mm, "8 mm hang hole"
    assert numbers.n3.position.y - plate.bb.bottom == 8 mm, "numbers' baseline 8 mm up"
    assert numbers.n4.size == 6 mm, "numbers 6 mm high"
    assert hang.bb.left > portions.p4.bb.right, "hang hole clear of the 40 mm hole"
}
