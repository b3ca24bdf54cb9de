# Ukulele chord card (music): a 90 x 110 mm card of 2 mm acrylic, corners R5, with a 5 mm
# hanging hole centred across, its centre 7 mm below the top. Two engraved chord charts, C
# (frets 0 0 0 3, strings G C E A left to right) and Am (2 0 0 0): 4 strings 8 mm apart, 4
# frets 12 mm apart under a double nut line (1 mm apart); finger dots 5 mm circles centred
# halfway between frets, open strings 3 mm circles 3 mm above the nut; the chord name 8 mm
# high in sans Bold (filled), centred, baseline 6 mm above the nut. The nut lines start 15 mm
# (C) and 51 mm (Am) from the card's left edge, 40 mm below its top. "UKULELE GCEA" engraved
# 4 mm high, centred, baseline 10 mm above the bottom.
units mm
thickness 2 mm

def chord(name="C", frets=[0, 0, 0, 3]) -> drawing {
    nut = Line((0, 0), (24, 0))
    nut2 = Line((0, -1), (24, -1))
    for i in range(4) {
        string = Line((i * 8, 0), (i * 8, -48))
    }
    for j in range(1, 5) {
        fret = Line((0, -12 * j), (24, -12 * j))
    }
    title = Text(name, (12, 6), size=8, font="sans:Bold", fill=true)
    for i in range(4) {
        if frets[i] > 0 {
            dot = Circle(center=(i * 8, -12 * frets[i] + 6), diameter=5)
        } else {
            open = Circle(center=(i * 8, 3), diameter=3)
        }
    }
}

solid card {
    body = RoundedRectangle(bottom_left=(0, 0), width=90, height=110, corner_radius=5)
    hole hang { c = Circle(center=(45, 103), diameter=5) }

    c_chart = chord(name="C", frets=[0, 0, 0, 3])
    am_chart = chord(name="Am", frets=[2, 0, 0, 0])
    At(c_chart.nut.start, body.top_left, dx=15, dy=-40)
    At(am_chart.nut.start, body.top_left, dx=51, dy=-40)

    drawing footer {
        t = Text("UKULELE GCEA", (45, 10), size=4)
    }

    assert body.bb.width == 90 mm and body.bb.height == 110 mm, "card 90 x 110"
    assert body.bb.top - hang.c.center.y == 7 mm, "hole 7 mm below the top"
    assert c_chart.nut.start.x - body.bb.left == 15 mm, "C chart 15 in"
    assert am_chart.nut.start.x - body.bb.left == 51 mm, "Am chart 51 in"
    assert body.bb.top - c_chart.nut.start.y == 40 mm, "nut 40 below the top"
    assert c_chart.dot[0].center.y == c_chart.nut.start.y - 30 mm, "C: 3rd fret dot halfway between frets 2 and 3"
    assert footer.t.position.y - body.bb.bottom == 10 mm, "footer 10 above the bottom"
}
