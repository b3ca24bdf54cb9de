# Request (electronics): end plates for a 4S3P battery pack of twelve 18650 cells
# (18.4 mm x 65 mm), cut from 3 mm clear acrylic, held together by four M3 threaded rods.
# - Every plate is 100 x 80 mm, corners r4, with an M3 clearance hole (3.2 mm) 5 mm in from
#   each corner.
# - The cells stand in 3 rows x 4 columns at 19.5 mm pitch, the grid centred on the plate.
# - Each end has two layers: an inner plate with 18.6 mm holes the cells slide through, and
#   an outer plate with 14 mm windows (the cell stops, open for spot-welding the nickel strip).
# - The outer plates are engraved on their outside face: the polarity of each column above
#   it, 5 mm high, 34.5 mm above the centre (top end "+ - + -", bottom end "- + - +", the
#   columns in series), and on the top end "4S3P 18650 14.8V" 4 mm high below the grid.
# - Shown stacked: outer, inner, the 65 mm cells' space, inner, outer.

thickness 3 mm

pitch = 19.5 mm
cell_len = 65 mm

def end_plate(hole_d=18.6 mm, marks=[], title="") -> solid {
    body = RoundedRectangle(center=(0, 0), width=100, height=80, corner_radius=4)
    hole cell { c = Circle(center=(-1.5 * pitch, -pitch), diameter=hole_d) }
    cells = GridPattern(cell, 3, 4, pitch)
    hole rod { c = Circle(center=(-45, -35), diameter=3.2) }
    rods = CornerPattern(rod, body, inset=5)
    if len(marks) > 0 {
        drawing polarity {
            for i in range(len(marks)) {
                m = Text(marks[i], position=(-1.5 * pitch + i * pitch, 34.5), size=5,
                         valign="middle")
            }
        }
    }
    if title != "" {
        drawing name {
            t = Text(title, position=(0, -34.5), size=4, valign="middle")
        }
    }
    Fixed(body)
}

assembly pack {
    top_outer = end_plate(hole_d=14 mm, marks=["+", "-", "+", "-"], title="4S3P 18650 14.8V")
    top_inner = end_plate(hole_d=18.6 mm)
    bottom_inner = end_plate(hole_d=18.6 mm)
    bottom_outer = end_plate(hole_d=14 mm, marks=["-", "+", "-", "+"])

    RightOf(top_inner, top_outer, gap=5)
    RightOf(bottom_inner, top_inner, gap=5)
    RightOf(bottom_outer, bottom_inner, gap=5)
    AlignBottom(top_inner, top_outer)
    AlignBottom(bottom_inner, top_outer)
    AlignBottom(bottom_outer, top_outer)

    # stacked along z: the bottom outer plate turned over so its engraving faces down
    Place(bottom_outer, position=(0, 0, 3), rotation=(180 deg, 0, 0))
    Place(bottom_inner, position=(0, 0, 3))
    Place(top_inner, position=(0, 0, 3 + cell_len - 3))
    Place(top_outer, position=(0, 0, 3 + cell_len))

    assert len(top_inner.cells) == 12, "twelve cells"
    assert top_inner.cells[1].c.center.x - top_inner.cells[0].c.center.x == 19.5 mm
    assert top_inner.cells[4].c.center.y - top_inner.cells[0].c.center.y == 19.5 mm
    assert top_inner.body.width == 100 mm and top_inner.body.height == 80 mm
    assert top_inner.rods[0].c.center.x - top_inner.body.bb.left == 5 mm
    assert top_inner.rods[0].c.center.y - top_inner.body.bb.bottom == 5 mm
    # the grid centred on the plate
    assert (top_inner.cells[0].c.center.x + top_inner.cells[11].c.center.x) / 2 == top_inner.body.center.x
    assert (top_inner.cells[0].c.center.y + top_inner.cells[11].c.center.y) / 2 == top_inner.body.center.y
    assert top_inner.cells[0].c.diameter == 18.6 mm and top_outer.cells[0].c.diameter == 14 mm
}
