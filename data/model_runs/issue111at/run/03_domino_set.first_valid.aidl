# Request (toys): a double-six domino set cut from 3 mm birch ply: all 28 tiles, each 48 x 24 mm
# with 3 mm rounded corners, an engraved dividing line across the middle (18 mm long), and the
# pips cut right through as 4 mm holes on a 6.5 mm grid in each 24 mm square half (1: centre;
# 2 and 3: a diagonal; 4: corners; 5: corners and centre; 6: two rows of three). Tiles laid out
# as a triangle for cutting: tile (i, j) in row i, column j, on a 52 x 28 mm pitch.

thickness 3 mm

param pip = 4 mm, min = 3 mm, max = 5 mm
param pitch = 6.5 mm, min = 5.5 mm, max = 7 mm

P = [[], [[0, 0]], [[-1, 1], [1, -1]], [[-1, 1], [0, 0], [1, -1]],
     [[-1, 1], [1, 1], [-1, -1], [1, -1]], [[-1, 1], [1, 1], [0, 0], [-1, -1], [1, -1]],
     [[-1, 1], [0, 1], [1, 1], [-1, -1], [0, -1], [1, -1]]]

def tile(a, b) -> solid {
    body = RoundedRectangle(center=(0, 0), width=48, height=24, corner_radius=3)
    drawing divider {
        l = Line((0, -9), (0, 9))
    }
    for k in range(len(P[a])) {
        hole pa {
            c = Circle(center=(-12 + P[a][k][0] * pitch, P[a][k][1] * pitch), diameter=pip)
        }
    }
    for k in range(len(P[b])) {
        hole pb {
            c = Circle(center=(12 + P[b][k][0] * pitch, P[b][k][1] * pitch), diameter=pip)
        }
    }
}

assembly dominoes {
    for i in range(7) {
        for j in range(i, 7) {
            t = tile(i, j)
            t.body.center.x == j * 52 mm
            t.body.center.y == -i * 28 mm
        }
    }
    assert sum([len(row) for row in t]) == 28, "a double-six set has 28 tiles"
    assert len(t) == 7, "seven rows: 0 to 6"
    assert t[0][0].body.bb.width == 48 mm and t[0][0].body.bb.height == 24 mm, "tile 48 x 24"
    assert len(t[6][0].pa) == 6 and len(t[6][0].pb) == 6, "double six has 6 + 6 pips"
    assert len(t[2][3].pb) == 5, "tile 2|5 has 5 pips on its right half"
}
