# Request (sport): grade tags for the bouldering wall in our garage, one per problem, cut
# from 3 mm coloured acrylic: V0 to V8 (nine tags). Each tag is an arrow that points at the
# start hold: a 40 x 26 mm body with 4 mm rounded corners and a point 10 mm long on its left
# (50 mm overall). The grade is cut right through in 14 mm bold letters (stencil, so the
# "0", "6", "8" and "9" keep their middles), its middle 5.5 mm left of the body's centre; one
# countersunk hole for a 4 mm wood screw (4.5 mm, 9 mm head) 13 mm right of the body's centre.
# Lay the nine out in 3 rows of 3, 60 mm apart across and 35 mm down.

units mm
thickness 3 mm

def tag(g="V0") -> solid {
    body = Hull(RoundedRectangle(center=(0, 0), width=40, height=26, corner_radius=4),
                Point(-30, 0))
    hole grade {
        t = Text(g, position=(-5.5, 0), size=14, font="sans:Bold", valign="middle", stencil=true)
    }
    hole screw { c = Circle(center=(13, 0), diameter=4.5) }
    Countersink(screw, diameter=9)
    assert distance(grade, screw) >= 3 mm, "grade clear of the screw hole"
    assert grade.bb.left >= -20 mm + 2 mm, "grade on the body, not the point"
}

assembly tags {
    for i in range(9) {
        tg = tag(g=f"V{i}")
        tg.bb.center == ((i % 3) * 60, -(i // 3) * 35)
    }
    assert len(tg) == 9, "nine tags, V0 to V8"
    assert tg[0].body.bb.width == 50 mm, "50 mm overall"
    assert tg[0].body.bb.height == 26 mm, "26 mm tall"
    assert tg[8].grade.t.text == "V8", "the last is V8"
}
