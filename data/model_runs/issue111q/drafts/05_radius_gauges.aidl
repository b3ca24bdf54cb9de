# Music (luthiery): a set of four fretboard radius gauges, 3 mm acrylic, each a card 80 x 35 mm
# whose top edge is cut concave to the fretboard radius over a 70 mm chord (5 mm flat at each
# end): 7.25, 9.5, 12 and 16 inch radius. Each engraved "R 7.25 in" etc. 6 mm high, centred
# 12 mm above the bottom edge, and a 5 mm hanging hole 7 mm in from the bottom-left corner.
# The four laid in a row 5 mm apart.

thickness 3 mm

def radius_gauge(r=241.3 mm, label="9.5") -> solid {
    body = Rectangle(center=(0, 0), width=80, height=35)
    hole cut {
        c = Circle(center=(0, 0), radius=r)
    }
    # sagitta of a 70 mm chord
    VerticalDistance(cut.c.bottom, body.top.midpoint, r - sqrt(r * r - 35 mm * 35 mm))
    cut.c.center.x == body.center.x
    hole hang {
        h = Circle(center=(0, 0), diameter=5)
    }
    At(hang.h.center, body.bottom_left, dx=7, dy=7)
    drawing name {
        t = Text(f"R {label} in", (0, 0), size=6, valign="middle")
    }
    At(name.t.position, body.bottom.midpoint, dy=12)
}

assembly gauges {
    g1 = radius_gauge(r=7.25 in, label="7.25")
    g2 = radius_gauge(r=9.5 in, label="9.5")
    g3 = radius_gauge(r=12 in, label="12")
    g4 = radius_gauge(r=16 in, label="16")
    RightOf(g2.body, g1.body, gap=5)
    RightOf(g3.body, g2.body, gap=5)
    RightOf(g4.body, g3.body, gap=5)
    AlignBottom(g2.body, g1.body)
    AlignBottom(g3.body, g1.body)
    AlignBottom(g4.body, g1.body)

    assert g1.body.bb.width == 80 mm and g1.body.bb.height == 35 mm, "card 80 x 35"
    assert g1.cut.c.radius == 7.25 in, "7.25 in radius"
    assert g2.cut.c.radius == 9.5 in, "9.5 in radius"
    assert g3.cut.c.radius == 12 in, "12 in radius"
    assert g4.cut.c.radius == 16 in, "16 in radius"
    assert g2.body.bb.left - g1.body.bb.right == 5 mm, "5 mm apart"
    assert g1.hang.h.center.x - g1.body.bb.left == 7 mm, "hang hole 7 in"
}
