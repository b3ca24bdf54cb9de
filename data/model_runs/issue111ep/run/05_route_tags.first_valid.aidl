# Request (sport): start tags for the five graded circuits on our club's bouldering wall,
# 3 mm acrylic, one tag per circuit, bolted on under the start hold. Each tag: a 60 x 40 mm
# block with a round top (R15) centred above it, an 11 mm hole in the round top for the
# M10 hold bolt (centre 22 mm above the block's middle line... the block's middle is 8 mm
# below the origin), the grade cut right through in bold letters 16 mm high (stencil, so the
# centre of an O or 0 stays), "START" engraved 4 mm high between the bolt hole and the grade,
# and "SET BY <name>" engraved 3.5 mm high under it. Grades and setters:
# V0 MO, V1 JEN, V2 ALEX, V3 SAM, V4 PRIYA. Every letter at least 3 mm inside the edge.

units mm
thickness 3 mm
kerf 0.1 mm

grades = ["V0", "V1", "V2", "V3", "V4"]
setters = ["MO", "JEN", "ALEX", "SAM", "PRIYA"]

def tag(grade="V0", setter="MO") -> solid {
    block = Rectangle(center=(0, -8), width=60, height=40)
    top = Circle(center=(0, 22), radius=15)
    body = Hull(block, top)
    hole bolt { c = Circle(center=(0, 22), diameter=11) }
    hole letters {
        g = Text(grade, position=(0, -6), size=16, font="sans:Bold", valign="middle", stencil=true)
    }
    drawing marks {
        start = Text("START", position=(0, 9), size=4, valign="middle")
        by = Text(f"SET BY {setter}", position=(0, -22), size=3.5, valign="middle")
    }
}

assembly tags {
    for i in range(len(grades)) {
        t = tag(grade=grades[i], setter=setters[i])
    }
    for i in range(1, len(grades)) {
        RightOf(t[i], t[i - 1], gap=5)
        AlignTop(t[i], t[0])
    }

    # the request's numbers
    assert len(t) == 5
    assert t[0].block.width == 60 mm and t[0].block.height == 40 mm
    assert t[0].top.radius == 15 mm
    assert t[0].bolt.c.diameter == 11 mm
    assert t[0].letters.g.size == 16 mm
    # every letter 3 mm inside the edge, on every tag
    for i in range(len(grades)) {
        assert t[i].letters.bb.left - t[i].block.bb.left >= 3 mm
        assert t[i].block.bb.right - t[i].letters.bb.right >= 3 mm
        assert t[i].marks.by.bb.left - t[i].block.bb.left >= 3 mm
        assert t[i].marks.by.bb.bottom - t[i].block.bb.bottom >= 3 mm
        # the engraving stays off the cut letters and the bolt hole
        assert distance(t[i].marks.start, t[i].letters) >= 1.5 mm
        assert distance(t[i].marks.by, t[i].letters) >= 1.5 mm
        assert distance(t[i].marks.start, t[i].bolt) >= 1.5 mm
    }
}
