# Request (crafts): a jewellery wire-wrapping jig. A 130 x 90 mm top plate of 6 mm clear
# acrylic (5 mm corner radius) with a grid of 3.2 mm holes for 3 mm steel pegs, 11 columns by
# 8 rows at 8 mm pitch; the columns lettered A to K above the grid and the rows numbered 1 to
# 8 on its left (4 mm engraved letters) so a design can be written down; a 60 x 14 mm
# rounded tray slot on the right for the loose pegs; "WIRE JIG" engraved under the grid. A
# 130 x 90 mm bottom plate of 3 mm acrylic glued underneath closes the holes and the tray.

thickness 3 mm

cols = 11
rows = 8
pitch = 8 mm
letters = ["A", "B", "C", "D", "E", "F", "G", "H", "I", "J", "K"]
x0 = -45 mm          # the first column
y0 = -30 mm          # the first row (row 1, at the bottom)

assembly jig {
    solid top {
        thickness 6 mm
        plate = RoundedRectangle(center=(0, 0), width=130, height=90, corner_radius=5)
        hole peg { c = Circle(center=(x0, y0), diameter=3.2) }
        pegs = GridPattern(peg, rows, cols, (pitch, pitch))
        hole tray { s = Slot(center=(50, -2), length=60, width=14, rotation=90 deg) }
        drawing labels {
            for i in range(cols) {
                col = Text(letters[i], position=(x0 + i * pitch, y0 + rows * pitch + 2), size=4,
                           valign="middle")
            }
            for j in range(rows) {
                row = Text(str(j + 1), position=(x0 - 10, y0 + j * pitch), size=4, valign="middle")
            }
            title = Text("WIRE JIG", position=(x0 + (cols - 1) * pitch / 2, -39), size=5,
                         valign="middle")
        }
    }
    solid bottom {
        plate = RoundedRectangle(center=(0, 0), width=130, height=90, corner_radius=5)
    }

    top.plate.center == (0, 0)
    RightOf(bottom, top, gap=5)
    AlignCenterY(bottom, top)

    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, 3 mm))

    assert len(top.pegs) == 88, "11 x 8 holes"
    assert top.pegs[1].c.center.x - top.pegs[0].c.center.x == 8 mm, "8 mm pitch across"
    assert top.pegs[cols].c.center.y - top.pegs[0].c.center.y == 8 mm, "8 mm pitch up"
    assert top.plate.bb.width == 130 mm and top.plate.bb.height == 90 mm, "130 x 90"
    assert top.tray.s.length == 60 mm and top.tray.s.width == 14 mm, "tray 60 x 14"
    # the tray and the labels stay clear of the grid
    assert top.tray.bb.left - top.pegs[cols - 1].c.center.x > 5 mm, "tray clear of the grid"
    assert top.tray.bb.right < top.plate.bb.right - 5 mm, "tray inside the plate"
}
