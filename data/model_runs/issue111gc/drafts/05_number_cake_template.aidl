# REQUEST (05, parties): number-cake templates for a 30th birthday. 3 mm clear acrylic.
# The digits "3" and "0" in a bold sans, 300 mm cap height (about 300 mm tall), laid on a
# slab of sponge to cut round with a knife; the "0" keeps its counter (the cake's hole).
# Each has an 8 mm hole to hang it up, centred on the digit and 20 mm below its top.
# Laid 20 mm apart on the sheet; the whole must fit a 600 x 400 mm bed.

thickness 3 mm

cap = 300 mm
hang_d = 8 mm

def digit(ch) -> solid {
    d = Text(ch, position=(0, 0), size=cap, font="sans:Bold")
    hole hang { c = Circle(center=(0, 0), diameter=hang_d) }
    AlignCenterX(hang.c, d)
    hang.c.center.y == d.bb.top - 20 mm
}

assembly cake_templates {
    three = digit(ch="3")
    zero = digit(ch="0")
    RightOf(zero, three, gap=20)
    AlignBottom(zero, three)

    assert abs(three.d.bb.height - 300 mm) <= 9 mm and abs(zero.d.bb.height - 300 mm) <= 9 mm,
        "about 300 tall"
    assert three.d.bb.top - three.hang.c.center.y == 20 mm, "hang hole 20 below the top"
    assert zero.d.bb.top - zero.hang.c.center.y == 20 mm, "hang hole 20 below the top"
    assert zero.bb.left - three.bb.right == 20 mm, "20 apart"
    assert zero.bb.right - three.bb.left <= 600 mm and three.bb.height <= 400 mm, "fits the bed"
}
