# Request (music): a tailpiece for my 5-string open-back banjo, cut from 5 mm acrylic.
# A tapered plate 94 mm long: a 7 mm round end at the hoop (with a 4 mm hole for the
# tailpiece wire, centred on that end's arc), widening to two 8 mm rounded corners at the
# string end, 52 mm across. Five 1.2 mm string holes (the loop ends catch behind them) in a
# straight row 8 mm apart, 80 mm from the wire hole. A heart window, 17 mm across, centred
# 45 mm from the wire hole, and the owner's name "Grace" engraved filled in italic serif
# (5 mm), running along the tailpiece between the wire hole and the heart.

units mm
thickness 5 mm

strings = 5
pitch = 8 mm
row_y = 80 mm

solid tailpiece {
    # the corners' centres 1 mm short of the string row keep the whole length at 94 mm
    body = Hull(Circle(center=(0, 0), radius=7), Circle(center=(-18, row_y - 1), radius=8),
                Circle(center=(18, row_y - 1), radius=8))
    hole wire { c = Circle(center=(0, 0), diameter=4) }
    hole string { c = Circle(center=(-(strings - 1) * pitch / 2, row_y), diameter=1.2) }
    strings_row = LinearPattern(string, strings, (pitch, 0))
    hole heart {
        l = Hull(Circle(center=(-4, 48), radius=4.5), Point(0, 37))
        r = Hull(Circle(center=(4, 48), radius=4.5), Point(0, 37))
    }
    drawing name {
        t = Text("Grace", position=(0, 21), size=5, rotation=90, font="serif:Italic",
                 valign="middle", fill=true)
    }

    assert len(strings_row) == 5, "five strings"
    assert strings_row[1].c.center.x - strings_row[0].c.center.x == 8 mm, "8 mm apart"
    assert strings_row[0].c.center.y - wire.c.center.y == 80 mm, "row 80 mm from the wire"
    assert body.bb.height == 94 mm, "94 long"
    assert body.bb.width == 52 mm, "52 across"
    assert heart.bb.width == 17 mm, "heart 17 across"
    assert distance(heart, strings_row[2]) >= 3 mm, "heart clear of the strings"
    assert distance(name, heart) >= 2 mm, "name clear of the heart"
    assert distance(name, wire) >= 2 mm, "name clear of the wire hole"
}
