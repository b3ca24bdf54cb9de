# Request: "Four hexagonal coasters for our coffee table, cut from 4 mm walnut ply.
# Each is 100 mm across the flats with its six corners rounded R5. Engrave a honeycomb
# of small hexagons, 8 mm across flats on a 10 mm pitch (so 2 mm between cells), filling
# the ring between a plain 26 mm centre disc and a 64 mm circle; every cell whole, none
# cut off by either circle. In the plain centre, one initial per coaster - H, O, L, M -
# fill-engraved, bold, 14 mm tall. An engraved circle 70 mm across frames the honeycomb.
# Lay the four out in a row with 5 mm gaps; kerf 0.15 mm."

units mm
thickness 4 mm
kerf 0.15 mm

across = 100 mm          # coaster across flats
corner_r = 5 mm
cell_af = 8 mm           # honeycomb cell across flats
pitch = 10 mm            # centre to centre of neighbouring cells
plain_d = 26 mm          # plain centre disc
comb_d = 64 mm           # honeycomb outer circle
frame_d = 70 mm          # engraved frame circle
letter_h = 14 mm
letters = ["H", "O", "L", "M"]

cell_r = cell_af / sqrt(3)        # centre to vertex of a cell
row_h = pitch * sqrt(3) / 2       # row spacing of a honeycomb

# a 9 x 9 lattice, index k: column k % 9, row k // 9, both centred on 0
def col(k) = k % 9 - 4
def row(k) = k // 9 - 4
def cx(k) = col(k) * pitch + (pitch / 2 if row(k) % 2 == 1 else 0 mm)
def cy(k) = row(k) * row_h
def rad(k) = sqrt(cx(k) ** 2 + cy(k) ** 2)
cells = [k for k in range(81) if rad(k) + cell_r <= comb_d / 2 and rad(k) - cell_r >= plain_d / 2]

def coaster(letter="H") -> solid {
    body = RegularPolygon(center=(0, 0), across_flats=across, sides=6)
    drawing comb {
        for k in cells {
            cell = RegularPolygon(center=(cx(k), cy(k)), across_flats=cell_af, sides=6, rotation=30 deg)
        }
        frame = Circle(center=(0, 0), diameter=frame_d)
    }
    drawing mark {
        t = Text(letter, position=(0, 0), size=letter_h, font="sans:Bold", valign="middle", fill=true)
    }
    Fillet(corner_r)
}

assembly coasters {
    for i in range(4) {
        c = coaster(letter=letters[i])
    }
    for i in range(1, 4) {
        RightOf(c[i], c[i - 1], gap=5 mm)
        AlignCenterY(c[i], c[0])
    }

    # the request's numbers
    assert len(c) == 4, "four coasters"
    assert c[0].body.bb.height == 100 mm, "100 mm across flats"
    assert c[1].bb.left - c[0].bb.right == 5 mm, "5 mm gaps"
    assert c[0].mark.t.bb.height <= 26 mm and c[0].mark.t.bb.width <= 26 mm, "initial within the plain disc"
    assert c[3].mark.t.bb.width <= 26 mm, "the widest initial, M, within the plain disc"
    assert len(cells) >= 12, "a honeycomb, not a few cells"
}

# every cell whole inside the ring (request: none cut off)
assert max([rad(k) for k in cells]) + cell_r <= 64 mm / 2, "cells inside the 64 mm circle"
assert min([rad(k) for k in cells]) - cell_r >= 26 mm / 2, "cells clear of the 26 mm plain disc"
assert 70 mm / 2 - 64 mm / 2 >= 2 mm, "frame clear of the honeycomb"
