# Request (science): a rock-salt (NaCl) crystal model for a chemistry class. Three layers of
# 3 mm clear acrylic, 90 x 90 mm with 5 mm corners, each engraved with a 3 x 3 grid of atoms
# 28 mm apart: chlorine as a 16 mm ring marked "Cl", sodium as a 10 mm ring marked "Na",
# alternating like a chessboard, and bond lines from ring to ring between neighbours. The
# middle layer is the other way round (Na at the corners), so every atom sits over its
# opposite. The layers stand 28 mm apart (the atoms' pitch, so the cells are cubes) on M4
# standoffs through 4.3 mm holes 5 mm in from each corner. Base: 6 mm ply 120 wide x 160
# deep, 10 mm corners, the stack's footprint 15 mm in from its back and sides, the same
# 4.3 mm holes under the layers' holes; in front of the stack, engraved: "NaCl  ROCK SALT"
# 9 mm bold, "face-centred cubic, 1 Na⁺ : 1 Cl⁻" 4.5 mm, and a legend of one 16 mm ring
# "Cl⁻ chloride" and one 10 mm ring "Na⁺ sodium".

pitch = 28 mm
gap = 28 mm

def rad(r, c, k) = 8 if (r + c + k) % 2 == 0 else 5

def layer(k=0) -> solid {
    thickness 3 mm
    plate = RoundedRectangle(center=(0, 0), width=90, height=90, corner_radius=5)
    hole h { c = Circle(center=(0, 0), diameter=4.3) }
    holes = CornerPattern(h, plate, inset=5)
    drawing atoms {
        for r in range(3) {
            for c in range(3) {
                ring = Circle(center=((c - 1) * 28, (r - 1) * 28), radius=rad(r, c, k))
                sym = Text("Cl" if (r + c + k) % 2 == 0 else "Na",
                           position=((c - 1) * 28, (r - 1) * 28),
                           size=5 if (r + c + k) % 2 == 0 else 3.5, valign="middle",
                           font="sans:Bold")
            }
        }
        for r in range(3) {
            for c in range(2) {
                hb = Line(((c - 1) * 28 + rad(r, c, k), (r - 1) * 28),
                          (c * 28 - rad(r, c + 1, k), (r - 1) * 28))
            }
        }
        for c in range(3) {
            for r in range(2) {
                vb = Line(((c - 1) * 28, (r - 1) * 28 + rad(r, c, k)),
                          ((c - 1) * 28, r * 28 - rad(r + 1, c, k)))
            }
        }
    }
    Fixed(plate)
}

assembly model {
    solid base {
        thickness 6 mm
        board = RoundedRectangle(center=(0, 0), width=120, height=160, corner_radius=10)
        hole h { c = Circle(center=(0, 0), diameter=4.3) }
        holes = CornerPattern(h, at=[(-40, -20), (40, -20), (40, 60), (-40, 60)])
        drawing legend {
            title = Text("NaCl  ROCK SALT", position=(0, -38), size=9, font="sans:Bold",
                         fill=true)
            sub = Text("face-centred cubic, 1 Na⁺ : 1 Cl⁻", position=(0, -50), size=4.5,
                       font="sans")
            cl = Circle(center=(-50, -68), diameter=16)
            cl_t = Text("Cl⁻ chloride", position=(-41, -68), size=5, anchor="start",
                        valign="middle", font="sans")
            na = Circle(center=(8, -68), diameter=10)
            na_t = Text("Na⁺ sodium", position=(16, -68), size=5, anchor="start",
                        valign="middle", font="sans")
        }
        Fixed(board)
    }

    bottom = layer(k=0)
    middle = layer(k=1)
    top = layer(k=0)
    RightOf(bottom, base, gap=10)
    AlignTop(bottom, base)
    RightOf(middle, bottom, gap=10)
    AlignTop(middle, bottom)
    Below(top, bottom, gap=10)
    AlignLeft(top, bottom)

    Place(base, position=(0, 0, 0))
    Place(bottom, position=(0, 20, 6 + gap - 3))
    Place(middle, position=(0, 20, 6 + 2 * gap - 3))
    Place(top, position=(0, 20, 6 + 3 * gap - 3))

    # the request's numbers
    assert bottom.plate.bb.width == 90 mm and bottom.plate.bb.height == 90 mm, "layers 90 x 90"
    assert len(bottom.atoms.ring) == 3 and len(bottom.atoms.ring[0]) == 3, "3 x 3 atoms"
    assert bottom.atoms.ring[0][1].center.x - bottom.atoms.ring[0][0].center.x == 28 mm,
        "atoms 28 apart"
    assert bottom.atoms.ring[0][0].diameter == 16 mm and bottom.atoms.ring[0][1].diameter == 10 mm,
        "Cl 16, Na 10, alternating"
    assert middle.atoms.ring[0][0].diameter == 10 mm, "middle layer the other way round"
    assert gap == pitch, "cubic cells"
    assert bottom.holes[0].c.center.x - bottom.plate.bb.left == 5 mm, "holes 5 in from the corner"
    assert distance(bottom.atoms.ring[0][0], bottom.holes[0]) >= 4 mm, "standoff clear of the atoms"
    assert base.board.bb.width == 120 mm and base.board.bb.height == 160 mm, "base 120 x 160"
    assert base.board.bb.top - (20 mm + 45 mm) == 15 mm, "stack 15 in from the back"
    assert base.board.bb.right - 45 mm == 15 mm, "stack 15 in from the sides"
    assert base.holes[2].c.center.y - base.holes[0].c.center.y ==
        bottom.holes[2].c.center.y - bottom.holes[0].c.center.y, "base holes under the layers'"
    assert distance(base.legend.title, base.holes[0]) >= 4 mm, "title clear of the standoffs"
    assert (20 mm - 45 mm) - base.legend.title.bb.top >= 2 mm, "title in front of the stack"
    assert base.legend.cl.bb.bottom - base.board.bb.bottom >= 3 mm, "legend on the base"
    assert base.legend.na_t.bb.right <= base.board.bb.right - 3 mm, "legend inside the base"
    assert base.legend.cl.bb.left >= base.board.bb.left + 3 mm, "legend inside the base"
    assert distance(base.legend.cl_t, base.legend.na) >= 3 mm, "legend entries apart"
}
