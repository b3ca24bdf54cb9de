# Raspberry Pi Zero mounting plate: 85 x 45 mm plate, 4 mm rounded corners; the board's
# four M2.5 holes (2.7 mm diameter) on a 58 x 23 mm rectangle, centred on the plate;
# four 3.4 mm screw holes to fix the plate, 5 mm in from each corner; the text "Pi Zero"
# engraved 4 mm tall, centred between the board holes.
param w = 85 mm, min = 75 mm, max = 120 mm
param h = 45 mm, min = 38 mm, max = 80 mm
thickness 3 mm

solid plate {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=4)
    pattern = Rectangle(center=(0, 0), width=58, height=23, construction=true)
    CenterInside(pattern, body)
    hole pi_hole { c = Circle(center=(-29, -11.5), diameter=2.7) }
    pi_holes = CornerPattern(pi_hole, pattern)
    hole fix { c = Circle(center=(-37.5, -17.5), diameter=3.4) }
    fixes = CornerPattern(fix, body, inset=5)
    drawing tag {
        t = Text("Pi Zero", (0, 0), size=4, valign="middle")
    }
    At(tag.t.position, body.center)
    assert len(pi_holes) == 4 and len(fixes) == 4, "four and four holes"
    assert pi_holes[1].c.center.x - pi_holes[0].c.center.x == 58 mm or pi_holes[2].c.center.x - pi_holes[0].c.center.x == 58 mm, "58 mm apart"
    assert abs(pi_holes[3].c.center.y - pi_holes[0].c.center.y) == 23 mm or abs(pi_holes[2].c.center.y - pi_holes[0].c.center.y) == 23 mm, "23 mm apart"
}
