# Request: A double-six set of dominoes for the kids, from 3 mm plywood: all 28 tiles (every
# pair of 0..6 once), each 24 x 48 mm with 3 mm rounded corners. Engrave a 16 mm line across the
# middle of each tile and the pips as 4 mm circles, laid out like a die's faces in each 24 mm
# half (6.5 mm from the half's centre to the outer pips; the six as two columns of three).
# Lay the set out in rows by the smaller number, 6 mm apart, for cutting.

units mm
thickness 3 mm

param tile_w = 24 mm, min = 20 mm, max = 30 mm
param pip_d = 4 mm, min = 3 mm, max = 5 mm

D = 6.5 mm
# the pips' offsets from the centre of a half, for 0..6
PIPS = [[],
        [(0, 0)],
        [(-D, D), (D, -D)],
        [(-D, D), (0, 0), (D, -D)],
        [(-D, D), (D, D), (-D, -D), (D, -D)],
        [(-D, D), (D, D), (0, 0), (-D, -D), (D, -D)],
        [(-D, D), (-D, 0), (-D, -D), (D, D), (D, 0), (D, -D)]]

def domino(top=0, bottom=0, w=24 mm, pip=4 mm) -> solid {
    body = RoundedRectangle(center=(0, 0), width=w, height=2 * w, corner_radius=3)
    drawing face {
        divider = Line((-8, 0), (8, 0))
        for p in PIPS[top] {
            up = Circle(center=(p[0], w / 2 + p[1]), diameter=pip)
        }
        for p in PIPS[bottom] {
            down = Circle(center=(p[0], -w / 2 + p[1]), diameter=pip)
        }
    }
    # FIX after the first valid program: `CenterInside(face, body)` centred the face's box, which
    # on an unbalanced tile (0-1, 2-6, ...) is not the tile's middle: divider and pips slid off
    # their halves. The face is drawn about the body's centre and stays where written on it.
    assert abs(face.divider.midpoint.y - body.center.y) < 0.001 mm and
        abs(face.divider.midpoint.x - body.center.x) < 0.001 mm, "divider across the middle"
    if top > 0 {
        assert min([c.center.y for c in face.up]) - body.center.y > pip / 2, "top pips in the top half"
        assert abs(sum([c.center.x for c in face.up]) / top - body.center.x) < 0.001 mm,
            "top pips centred across the tile"
    }
    if bottom > 0 {
        assert body.center.y - max([c.center.y for c in face.down]) > pip / 2, "bottom pips in the bottom half"
        assert abs(sum([c.center.x for c in face.down]) / bottom - body.center.x) < 0.001 mm,
            "bottom pips centred across the tile"
    }
}

assembly dominoes {
    for a in range(7) {
        for b in range(a, 7) {
            tile = domino(top=a, bottom=b, w=tile_w, pip=pip_d)
            tile.body.center == (b * (tile_w + 6 mm), -a * (2 * tile_w + 6 mm))
        }
    }
    assert sum([len(row) for row in tile]) == 28, "28 tiles"
    assert abs(tile[0][0].body.width - 24 mm) < 0.001 mm and abs(tile[0][0].body.height - 48 mm) < 0.001 mm,
        "tiles 24 x 48"
    assert sum([len(PIPS[i]) for i in range(7)]) * 8 == 168, "168 pips in a double-six set"
}
