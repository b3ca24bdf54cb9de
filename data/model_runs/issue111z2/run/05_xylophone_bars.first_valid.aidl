# Music: the 8 bars of a toy xylophone (C major scale C5..C6), 6 mm maple plywood. Each bar
# 30 mm wide with 3 mm corner radii; the longest (C5) 200 mm, each other bar 200 mm x
# 2^(-s/24) for its semitones s above C5 (0 2 4 5 7 9 11 12: C6 is 200 / sqrt(2) = 141.4 mm).
# Two 4 mm node holes on the bar's centre line at 22.4 % of its length from each end. The note
# name ("C5", "D5", ... "C6") engraved in the middle in sans outline letters 10 mm high,
# filled, centred. Bars laid out for cutting with their left ends aligned, 8 mm apart
# (rows 38 mm apart), C5 at the top.

units mm
thickness 6 mm

notes = ["C5", "D5", "E5", "F5", "G5", "A5", "B5", "C6"]
steps = [0, 2, 4, 5, 7, 9, 11, 12]

param longest = 200 mm, min = 150, max = 300

def bar(length=200 mm, note="C5") -> solid {
    body = RoundedRectangle(center=(0, 0), width=length, height=30, corner_radius=3)
    hole nodes {
        n1 = Circle(center=(-length / 2 + 0.224 * length, 0), diameter=4)
        n2 = Circle(center=(length / 2 - 0.224 * length, 0), diameter=4)
    }
    drawing label {
        t = Text(note, position=(0, 0), size=10, font="sans", fill=true, valign="middle")
    }
}

assembly xylophone {
    for i in range(8) {
        b = bar(length=longest * 2 ** (-steps[i] / 24), note=notes[i])
        b.bb.left == 0
        b.bb.center_y == -38 * i
    }

    assert len(b) == 8, "8 bars"
    assert b[0].body.bb.width == 200 mm, "C5 is 200 mm"
    assert abs(b[7].body.bb.width - 141.4 mm) < 0.05 mm, "C6 is 141.4 mm"
    assert b[0].body.bb.height == 30 mm, "30 mm wide bars"
    assert abs(b[0].nodes.n1.center.x - b[0].body.bb.left - 0.224 * 200 mm) < 0.01 mm, "node at 22.4 %"
    assert b[0].bb.center_y - b[1].bb.center_y == 38 mm, "rows 38 mm apart"
}
