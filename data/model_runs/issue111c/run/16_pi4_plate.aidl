# Raspberry Pi 4 mounting plate: a 110 x 75 mm plate with R5 corners; the board
# (85 x 56 mm) centered on it, its outline engraved; four 2.7 mm holes for M2.5
# standoffs at the board's holes: 3.5 mm in from the board's left and bottom
# edges, on a 58 x 49 mm rectangle; four 4.2 mm wall-screw holes 6 mm in from
# the plate's corners; a 40 x 8 mm stadium cable slot centered under the board
# between it and the plate's bottom edge? no room (9.5 mm): put it to the
# board's right instead? no: 12.5 mm strip, slot 8 x 40 vertical, centered
# in that strip; "PI 4" engraved 5 mm high in the board outline's middle.
thickness 3 mm

solid plate {
    body = RoundedRectangle(center=(0, 0), width=110, height=75, corner_radius=5)
    drawing board {
        outline = Rectangle(center=(0, 0), width=85, height=56)
        label = Text("PI 4", position=(0, 0), size=5, valign="middle")
    }
    CenterInside(board, body)
    hole standoff {
        c = Circle(center=(-39, -24.5), diameter=2.7)
    }
    At(standoff.c.center, board.outline.bottom_left, dx=3.5, dy=3.5)
    standoffs = GridPattern(standoff, 2, 2, col_spacing=58, row_spacing=49)
    hole wall {
        c = Circle(center=(-49, -31.5), diameter=4.2)
    }
    walls = CornerPattern(wall, body, inset=6 mm)
    hole cable {
        s = Slot(center=(49, 0), length=40, width=8, rotation=90 deg)
    }
    AlignCenterY(cable, body)
    cable.s.center.x == (board.outline.bb.right + body.bb.right) / 2
}

assert plate.body.bb.width == 110 mm and plate.body.bb.height == 75 mm, "110 x 75"
assert plate.board.outline.bb.width == 85 mm and plate.board.outline.bb.height == 56 mm, "Pi 4 85 x 56"
assert plate.standoff.c.center.x - plate.board.outline.bb.left == 3.5 mm, "3.5 mm in"
assert plate.standoff.c.center.y - plate.board.outline.bb.bottom == 3.5 mm, "3.5 mm in"
assert len(plate.standoffs) == 4, "four standoffs"
assert plate.standoffs[3].c.center.x - plate.standoff.c.center.x == 58 mm, "58 mm apart"
assert plate.standoffs[3].c.center.y - plate.standoff.c.center.y == 49 mm, "49 mm apart"
assert plate.wall.c.center.x - plate.body.bb.left == 6 mm, "wall screw 6 mm in"
assert len(plate.walls) == 4, "four wall screws"
assert plate.cable.bb.height == 40 mm and plate.cable.bb.width == 8 mm, "40 x 8 slot"
assert plate.cable.bb.left > plate.board.outline.bb.right, "slot clear of the board"
