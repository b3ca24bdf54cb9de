# Science: a periodic-table tile for iron, 3 mm plywood (for a classroom wall set).
# Tile 60 x 60 mm, corner radius 5 mm. The symbol "Fe" in sans Bold, 24 mm tall, cut through
# as a stencil (the e's counter held by bridges), centred on the tile. Engraved, single-stroke:
# the atomic number "26" 5 mm tall in the top-left corner and the atomic mass "55.845" 5 mm
# tall in the top-right corner (both 4 mm in from the top and side edges); the name "IRON"
# 5 mm tall, centred, its baseline 7 mm above the bottom edge.

thickness 3 mm

solid tile {
    body = RoundedRectangle(center=(0, 0), width=60, height=60, corner_radius=5)

    hole symbol {
        t = Text("Fe", (0, 0), size=24, font="sans:Bold", valign="middle", stencil=true)
    }
    CenterInside(symbol, body)

    drawing info {
        number = Text("26", (-26, 26), size=5, anchor="start", valign="top")
        mass = Text("55.845", (26, 26), size=5, anchor="end", valign="top")
        name = Text("IRON", (0, -23), size=5)
    }

    assert body.width == 60 mm and body.height == 60 mm, "tile 60 x 60"
    assert symbol.t.size == 24 mm, "24 mm symbol"
    assert abs(symbol.bb.center_x - body.bb.center_x) < 0.01 mm, "symbol centred"
    assert info.number.bb.left - body.bb.left == 4 mm, "26: 4 mm from the left edge"
    assert body.bb.top - info.number.bb.top == 4 mm, "26: 4 mm from the top"
    assert body.bb.right - info.mass.bb.right == 4 mm, "mass: 4 mm from the right edge"
    assert body.bb.top - info.mass.bb.top == 4 mm, "mass: 4 mm from the top"
    assert info.name.position.y - body.bb.bottom == 7 mm, "IRON's baseline 7 mm up"
    assert info.number.size == 5 mm and info.mass.size == 5 mm and info.name.size == 5 mm, "5 mm text"
    assert symbol.bb.top < info.number.bb.bottom - 2 mm, "symbol clear of the top row"
    assert symbol.bb.bottom > info.name.bb.top + 2 mm, "symbol clear of the name"
}
