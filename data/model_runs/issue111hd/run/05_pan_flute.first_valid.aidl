# Request (music): "A laser-cut pan flute in C major, one octave C5 to C6 (8 stopped
# pipes), glued up from five layers of 3 mm ply: three identical channel layers (so each
# bore is 9 x 9 mm) between a plain back cover and a front cover with the note names
# engraved 14 mm below the mouth edge (5 mm letters) and PAN FLUTE IN C engraved
# (6 mm). Bores on 13 mm centres, open at the straight top edge (the mouth), closed at
# the bottom; each bore's length L = 343000 / (4 f) - 3 mm (f in Hz: 523.25, 587.33,
# 659.26, 698.46, 783.99, 880, 987.77, 1046.5), longest on the left. The plates are 108 mm
# wide; the bottom edge is a smooth curve leaving at least 6 mm of wood under every
# bore."

thickness 3 mm

freqs = [523.25, 587.33, 659.26, 698.46, 783.99, 880, 987.77, 1046.5]
notes = ["C", "D", "E", "F", "G", "A", "B", "C"]
pitch = 13 mm
bore = 9 mm
wall = 6 mm
plate_w = 108 mm
L = [343000 mm / (4 * f) - 3 mm for f in freqs]
xs = [(i - 3.5) * pitch for i in range(8)]

def outline(x0) = Spline([(x0 - 54 mm, 0 mm), (x0 + 54 mm, 0 mm), (x0 + 54 mm, -(L[7] + wall))] +
                         [(x0 + xs[7 - k] + bore / 2, -(L[7 - k] + wall)) for k in range(8)] +
                         [(x0 - 54 mm, -(L[0] + wall))],
                         closed=true, corners=[0, 1, 2, -1])

def channel_layer(x0=0 mm) -> solid {
    edge = outline(x0)
    hole bores {
        for i in range(8) {
            b = Rectangle(bottom_left=(x0 + xs[i] - bore / 2, -L[i]), width=bore, height=L[i] + 1 mm)
        }
    }
}

def cover(x0=0 mm, front=false) -> solid {
    edge = outline(x0)
    if front {
        drawing names {
            for i in range(8) {
                n = Text(notes[i], position=(x0 + xs[i], -14), size=5, valign="middle")
            }
            title = Text("PAN FLUTE IN C", position=(x0, -55), size=6, valign="middle")
        }
    }
}

assembly pan_flute {
    front = cover(x0=0 mm, front=true)
    for j in range(3) {
        layer = channel_layer(x0=(j + 1) * 120 mm)
    }
    back = cover(x0=480 mm)

    assert len(layer) == 3 and len(layer[0].bores.b) == 8, "3 channel layers of 8 bores"
    assert layer[0].bores.b[0].width == 9 mm, "9 mm bores"
    assert layer[0].bores.b[1].center.x - layer[0].bores.b[0].center.x == 13 mm, "13 mm centres"
    assert abs(layer[0].bores.b[0].bb.bottom - 0 mm + (343000 mm / (4 * 523.25) - 3 mm)) < 0.01 mm, "C5 bore length"
    assert abs(layer[0].bores.b[7].bb.bottom - 0 mm + (343000 mm / (4 * 1046.5) - 3 mm)) < 0.01 mm, "C6 bore length"
    assert layer[0].edge.points[1].x - layer[0].edge.points[0].x == 108 mm, "plates 108 wide"
    assert distance(front.names.n[0], front.edge) >= 0 mm, "names on the cover"
}
