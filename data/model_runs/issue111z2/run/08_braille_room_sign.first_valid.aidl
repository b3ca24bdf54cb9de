# Signs: a door sign "ROOM 204" with braille, 3 mm acrylic. A plate 150 x 100 mm with 6 mm
# corner radii. "ROOM 204" in sans Bold outline letters, filled engraving, 18 mm high, centred
# horizontally with the capitals' middle 15 mm above the plate's centre. Below it the grade-1
# braille "ROOM #204" (R O O M, a blank cell, the number sign, 2 0 4: 9 cells, 25 dots) as
# 1.6 mm holes for raster-braille acrylic balls: dots 2.5 mm apart within a cell, cells
# 6.2 mm apart, the dot block centred horizontally with its middle row 18 mm below the plate's
# centre. Two 4 mm screw holes countersunk 8 mm, on the centre line 13 mm in from the left and
# right edges. An engraved border line 4 mm inside the edge (radius 2 mm at its corners).

units mm
thickness 3 mm

# braille dots of each cell (1 2 3 down the left column, 4 5 6 down the right)
cells = [[1, 2, 3, 5], [1, 3, 5], [1, 3, 5], [1, 3, 4], [], [3, 4, 5, 6], [1, 2], [2, 4, 5], [1, 4, 5]]

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=150, height=100, corner_radius=6)

    drawing label {
        word = Text("ROOM 204", position=(0, 15), size=18, font="sans:Bold", valign="middle",
                    fill=true)
        frame = RoundedRectangle(center=(0, 0), width=142, height=92, corner_radius=2)
    }

    hole braille {
        for i in range(len(cells)) {
            for d in cells[i] {
                dot = Circle(center=(i * 6.2 + (0 if d <= 3 else 2.5), -((d - 1) % 3) * 2.5),
                             diameter=1.6)
            }
        }
    }
    AlignCenterX(braille, plate)
    braille.bb.center_y == plate.center.y - 18 mm

    hole screw {
        c = Circle(center=(-75 + 13, 0), diameter=4)
    }
    screws = Mirrored(screw, Line((0, -50), (0, 50), construction=true))
    Countersink([screw, screws], diameter=8)

    assert plate.bb.width == 150 mm and plate.bb.height == 100 mm, "plate 150 x 100"
    assert len(cells) == 9, "9 braille cells"
    assert sum([len(c) for c in cells]) == 25, "25 dots"
    assert braille.bb.width == 8 * 6.2 mm + 2.5 mm + 1.6 mm, "cells 6.2 apart, dots 2.5 apart"
    assert screw.c.center.x - plate.bb.left == 13 mm, "screws 13 mm in"
    assert label.word.position.y - plate.center.y == 15 mm, "text middle 15 mm above centre"
}
