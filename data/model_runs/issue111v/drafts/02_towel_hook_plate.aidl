# Bathroom: a child's towel-hook backplate, 6 mm plywood, 160 x 60 mm with 10 mm corner
# radius. The name "MIA" in sans Bold, 18 mm cap height, engraved filled, centred
# 10 mm above the plate's centre. Two 12 mm holes for wooden dowel pegs, 80 mm apart,
# 14 mm below the centre. Two 4 mm screw holes 12 mm in from each end on the centre
# line, countersunk 8.5 mm.
thickness 6 mm

param name_size = 18 mm, min = 10 mm, max = 22 mm

solid plate {
    body = RoundedRectangle(center=(0, 0), width=160, height=60, corner_radius=10)

    hole peg { c = Circle(center=(-40, -14), diameter=12) }
    pegs = LinearPattern(peg, 2, (80, 0))
    peg.c.center.x == body.center.x - 40 mm
    peg.c.center.y == body.center.y - 14 mm

    hole screw { c = Circle(center=(-68, 0), diameter=4) }
    screws = LinearPattern(screw, 2, (136, 0))
    screw.c.center.x == body.bb.left + 12 mm
    AlignCenterY(screw, body)
    Countersink(screw, diameter=8.5 mm)

    drawing name { t = Text("MIA", (0, 10), size=name_size, valign="middle", font="sans:Bold", fill=true) }
    AlignCenterX(name, body)
    name.t.position.y == body.center.y + 10 mm

    assert body.width == 160 mm and body.height == 60 mm, "plate 160 x 60"
    assert distance(pegs[0].c.center, pegs[1].c.center) == 80 mm, "pegs 80 apart"
    assert pegs[0].c.diameter == 12 mm, "12 mm pegs"
    assert body.bb.right - screws[1].c.center.x == 12 mm, "right screw 12 in"
    assert len(screws) == 2, "two screws"
    assert pegs[0].c.center.x + pegs[1].c.center.x == 2 * body.center.x, "pegs centred"
}
