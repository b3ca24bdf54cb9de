# Request (holidays): a Lunar New Year door decoration from 3 mm red acrylic: a diamond (a
# 220 mm square stood on its corner, corners rounded R8) with the character 福 (fortune)
# cut through as a stencil, 110 mm, upside down as the custom is ("fortune arrives"), in the
# middle (font: Droid Sans Fallback, which has the CJK glyphs). A border engraved 16 mm in from the edges (corners R4). A 6 mm hanging hole 10 mm
# below the top tip and a 4 mm tassel hole 10 mm above the bottom tip.

thickness 3 mm

side = 220 mm
border_in = 16 mm

solid fu {
    body = RoundedRectangle(center=(0, 0), width=side, height=side, corner_radius=8,
                            rotation=45 deg)
    Fixed(body)

    hole word {
        ch = Text("福", position=(0, 0), size=110, font="Droid Sans Fallback", valign="middle",
                  rotation=180 deg, stencil=true, max_width=110 mm)
    }
    CenterInside(word, body)

    hole hang {
        c = Circle(center=(0, 140), diameter=6)
    }
    AlignCenterX(hang, body)
    hang.c.center.y == body.bb.top - 10 mm

    hole tassel {
        c = Circle(center=(0, -140), diameter=4)
    }
    AlignCenterX(tassel, body)
    tassel.c.center.y == body.bb.bottom + 10 mm

    drawing border {
        line = RoundedRectangle(center=(0, 0), width=side - 2 * border_in,
                                height=side - 2 * border_in, corner_radius=4, rotation=45 deg)
    }
    CenterInside(border, body)

    assert body.width == 220 mm, "220 square"
    assert body.bb.width == body.bb.height, "stood on its corner"
    assert hang.c.diameter == 6 mm and tassel.c.diameter == 4 mm, "hole sizes"
    assert body.bb.top - hang.c.center.y == 10 mm, "hanging hole 10 below the tip"
    assert tassel.c.center.y - body.bb.bottom == 10 mm, "tassel hole 10 above the tip"
    assert distance(word, border) >= 4 mm, "character inside the border"
    assert distance(hang, border) >= 2 mm, "hanging hole clear of the border"
    assert distance(tassel, border) >= 2 mm, "tassel hole clear of the border"
    assert word.ch.bb.height >= 90 mm, "character big"
    assert word.ch.bb.width <= 110 mm + 1 mm, "character 110 across"
}
