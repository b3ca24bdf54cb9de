# Request (music): a truss rod cover for my partscaster's headstock, 1.5 mm black/white
# engraving laminate. A bell-ish outline 34 wide and 40 tall: the hull of a 7 mm radius round
# top (its centre 33 mm above the bottom) and two 6 mm radius bottom corners 22 mm apart.
# Three 2.2 mm holes for the #2 screws at those three centres, countersunk 4.2 mm. Engraved:
# a border line 1.5 mm inside the edge and "MAYA" in bold serif letters, filled, centred
# 18 mm above the bottom and at most 18 mm wide.

thickness 1.5 mm

solid cover {
    outline = Hull(Circle(center=(0, 33), radius=7), Circle(center=(-11, 6), radius=6),
                   Circle(center=(11, 6), radius=6))
    hole screws {
        top = Circle(center=(0, 33), diameter=2.2)
        left = Circle(center=(-11, 6), diameter=2.2)
        right = Circle(center=(11, 6), diameter=2.2)
    }
    Countersink(screws, diameter=4.2)

    drawing trim {
        border = Inset(Hull(Circle(center=(0, 33), radius=7), Circle(center=(-11, 6), radius=6),
                            Circle(center=(11, 6), radius=6)), 1.5)
        name = Text("MAYA", position=(0, 18), size=5, font="serif:Bold", valign="middle",
                    max_width=18, fill=true)
    }
    Fixed(outline)

    assert outline.bb.width == 34 mm and outline.bb.height == 40 mm, "34 wide, 40 tall"
    assert screws.right.center.x - screws.left.center.x == 22 mm, "bottom screws 22 apart"
    assert screws.top.center.y - outline.bb.bottom == 33 mm, "top screw 33 up"
    assert trim.name.bb.width <= 18 mm, "name at most 18 wide"
}
