# Request (a woodturner, workshop): bowl-blank marking templates from 3 mm clear acrylic.
# Four discs, 125, 175, 225 and 275 mm across, cut as separate parts in a row 5 mm apart.
# Each disc has:
# - a 2.5 mm centre hole for an awl point;
# - a 6 mm hanging hole centred 8 mm in from the edge at the top;
# - engraved concentric circles every 25 mm of diameter, from 50 mm up to 25 mm under the
#   disc's own size (the 275 has 50, 75, ... 250: nine circles), each labelled with its
#   diameter in 3 mm figures, just inside its circle, 1.2 mm above the horizontal hairline;
# - engraved hairlines along the horizontal and vertical axes, from 1 mm outside the centre
#   hole out to the largest engraved circle;
# - its own size ("275 mm") engraved 6 mm tall along the bottom of the rim, readable, its
#   baseline 3 mm in from the edge.

units mm
thickness 3 mm

sizes = [125 mm, 175 mm, 225 mm, 275 mm]

def blank_template(d=125 mm) -> solid {
    body = Circle(center=(0, 0), diameter=d)
    hole awl { c = Circle(center=(0, 0), diameter=2.5) }
    hole hang { c = Circle(center=(0, d / 2 - 8), diameter=6) }
    drawing rings {
        for k in range(2, round(d / 25 mm)) {
            ring = Circle(center=(0, 0), diameter=k * 25 mm)
            tag = Text(str(k * 25), position=(k * 12.5 mm - 1.5 mm, 1.2), size=3, anchor="end")
        }
        right = Line((2.25, 0), (d / 2 - 12.5 mm, 0))
        left = Line((-2.25, 0), (-(d / 2 - 12.5 mm), 0))
        up = Line((0, 2.25), (0, d / 2 - 12.5 mm))
        down = Line((0, -2.25), (0, -(d / 2 - 12.5 mm)))
    }
    drawing size_label {
        path = Circle(center=(0, 0), radius=d / 2 - 3, construction=true)
        t = Text(f"{round(d / 1 mm)} mm", along=path, size=6, flip=true)
    }
}

assembly bowl_templates {
    for i in range(4) {
        t = blank_template(d=sizes[i])
    }
    for i in range(1, 4) {
        RightOf(t[i], t[i - 1], gap=5)
        AlignBottom(t[i], t[i - 1])
    }

    # the request's numbers
    assert len(t) == 4, "four discs"
    assert t[0].body.diameter == 125 mm and t[1].body.diameter == 175 mm and
        t[2].body.diameter == 225 mm and t[3].body.diameter == 275 mm, "125, 175, 225, 275"
    assert len(t[3].rings.ring) == 9, "the 275 has nine circles"
    assert len(t[0].rings.ring) == 3, "the 125 has 50, 75, 100"
    for i in range(4) {
        assert t[i].awl.c.diameter == 2.5 mm, "awl hole 2.5"
        assert t[i].hang.c.diameter == 6 mm, "hanging hole 6"
        assert t[i].body.bb.top - t[i].hang.c.center.y == 8 mm, "hanging hole 8 in from the top edge"
        assert distance(t[i].rings, t[i].hang) >= 1 mm, "hairline clear of the hanging hole"
        assert distance(t[i].rings, t[i].awl) >= 0.9 mm, "hairlines start 1 mm out from the awl hole"
    }
    for i in range(1, 4) {
        assert t[i].bb.left - t[i - 1].bb.right == 5 mm, "5 mm apart"
    }
}
