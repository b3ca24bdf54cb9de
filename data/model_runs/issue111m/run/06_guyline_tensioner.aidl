# Camping: guy-line tensioners, 4 mm acrylic, a set of four cut together, 8 mm apart
# in a column. Each: a tapered plate, the convex hull of a R11 circle and a R8 circle
# whose centres are 40 mm apart (59 mm long overall: 11 + 40 + 8); a 7 mm hole at the big end's
# centre and a 5 mm hole at the small end's centre; between them a 3 mm wide slit, 14 mm
# long, along the axis, centred between the holes (the line pinches in it); "TENT"
# engraved 3 mm tall under the slit, baseline 5 mm below the axis.

thickness 4 mm

def tensioner() -> solid {
    big = Circle(center=(-20, 0), radius=11, construction=true)
    small = Circle(center=(20, 0), radius=8, construction=true)
    plate = Hull(big, small)
    hole eye_big {
        c = Circle(center=(-20, 0), diameter=7)
    }
    hole eye_small {
        c = Circle(center=(20, 0), diameter=5)
    }
    hole pinch {
        s = Slot(center=(0, 0), length=14, width=3)
    }
    drawing mark {
        word = Text("TENT", (0, -5), size=3, valign="top")
    }
}

assembly set {
    for i in range(4) {
        t = tensioner()
        t.bb.center == (0, -i * (22 + 8))
    }

    assert len(t) == 4, "four tensioners"
    assert t[0].bb.width == 59 mm, "59 mm long"
    assert t[0].bb.height == 22 mm, "22 mm at the big end"
    assert t[0].small.radius == 8 mm, "R8 small end"
    assert distance(t[0].eye_big.c.center, t[0].eye_small.c.center) == 40 mm, "holes 40 apart"
    assert t[0].eye_big.c.diameter == 7 mm and t[0].eye_small.c.diameter == 5 mm, "7 and 5 mm holes"
    assert t[0].pinch.s.length == 14 mm and t[0].pinch.s.width == 3 mm, "slit 14 x 3"
    assert t[0].pinch.s.center.x == (t[0].eye_big.c.center.x + t[0].eye_small.c.center.x) / 2, "slit centred"
    assert t[0].bb.bottom - t[1].bb.top == 8 mm, "8 mm apart"
    assert t[0].mark.word.size == 3 mm, "TENT 3 tall"
}
