# Request (music): a note-value puzzle for a children's music class, 3 mm ply. A tray of two
# layers 200 x 90 mm (4 mm rounded corners): a plain base and a frame with a 161 x 61 mm pocket
# in its middle. In the pocket four rows of bars 15 mm tall fill a 160 mm line: one whole
# note bar (160 mm), two half-note bars (80 mm), four quarter-note bars (40 mm) and eight
# eighth-note bars (20 mm), each 0.2 mm short of its share and 14.8 mm tall, with 1 mm rounded
# corners. Each bar has its note engraved at its middle: a whole note (hollow oval head), a half
# note (hollow head with a stem), a quarter (filled head with a stem), an eighth (filled head,
# stem and flag); head 6 x 4 mm tilted 20 deg, stem 9.5 mm up from the head's right side. The
# frame's left border names the rows (1, 1/2, 1/4, 1/8, 5 mm strokes) and its top border has
# "NOTE VALUES" (6 mm strokes).

units mm
thickness 3 mm

kinds = [1, 2, 4, 8]
row_names = ["1", "1/2", "1/4", "1/8"]

def bar(kind=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=160 / kind - 0.2, height=14.8, corner_radius=1)
    drawing note {
        if kind == 1 {
            head = Ellipse(center=(0, 0), rx=3.5, ry=2.3, rotation=20)
        } elif kind == 2 {
            head = Ellipse(center=(-1, -3.5), rx=3, ry=2, rotation=20)
            stem = Line((1.8, -2.8), (1.8, 6))
        } else {
            head = Ellipse(center=(-1, -3.5), rx=3, ry=2, rotation=20, fill=true)
            stem = Line((1.8, -2.8), (1.8, 6))
            if kind == 8 {
                flag = Spline([(1.8, 6), (4.6, 3.2), (4.0, 0.4)])
            }
        }
    }
}

assembly puzzle {
    solid base {
        body = Rectangle(center=(0, 0), width=200, height=90)
        Fillet(body, 4)
    }
    base.bb.center == (0, 110)
    Place(base, position=(0, 0, 0))

    solid frame {
        body = Rectangle(center=(0, 0), width=200, height=90)
        Fillet(body, 4)
        hole pocket { r = Rectangle(center=(0, 0), width=161, height=61) }
        drawing labels {
            for r in range(4) {
                row = Text(row_names[r], position=(-90, 22.5 - 15 * r), size=5, valign="middle")
            }
            title = Text("NOTE VALUES", position=(0, 38), size=6, valign="middle")
        }
    }
    Place(frame, position=(0, 0, 3))

    for r in range(4) {
        for i in range(kinds[r]) {
            b = bar(kind=kinds[r])
            # flat: in the same order as in the tray, below it
            b.bb.center == (-80 + (i + 0.5) * 160 / kinds[r], 22.5 - 15 * r - 110)
            # in 3D: in the pocket, on the base
            Place(b, position=(-80 + (i + 0.5) * 160 / kinds[r], 22.5 - 15 * r, 3))
        }
    }

    # the request's numbers
    assert frame.pocket.r.width == 161 mm and frame.pocket.r.height == 61 mm, "pocket 161 x 61"
    assert len(b) == 4 and len(b[0]) == 1 and len(b[1]) == 2 and len(b[2]) == 4 and len(b[3]) == 8,
        "1, 2, 4 and 8 bars"
    assert b[0][0].body.width == 160 mm - 0.2 mm, "whole bar"
    assert b[1][0].body.width == 80 mm - 0.2 mm, "half bar"
    assert b[2][0].body.width == 40 mm - 0.2 mm, "quarter bar"
    assert b[3][0].body.width == 20 mm - 0.2 mm, "eighth bar"
    assert 8 * (b[3][0].body.width + 0.2 mm) == 160 mm, "eight eighths fill the line"
    assert 4 * b[0][0].body.height < frame.pocket.r.height, "four rows fit the pocket"
    assert b[3][0].note.bb.top <= b[3][0].body.bb.top - 1 mm and b[3][0].note.bb.bottom >= b[3][0].body.bb.bottom + 1 mm,
        "the eighth note inside its bar"
    assert b[3][0].note.bb.right <= b[3][0].body.bb.right - 1 mm, "the flag inside its bar"
    assert frame.labels.row[3].bb.right <= frame.pocket.r.bb.left - 1 mm, "row names on the border"
    assert frame.labels.title.bb.bottom >= frame.pocket.r.bb.top + 1 mm, "title on the top border"
}
