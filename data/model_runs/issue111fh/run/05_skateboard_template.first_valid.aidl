# Request (sport): a half-length shaping template for an 8.0" x 31.75" popsicle skateboard
# deck, cut from 6 mm MDF (the deck is symmetric nose to tail: trace one end, flip the
# template on the centre line for the other). The template runs from the deck's middle
# (its straight left edge) to the nose: 31.75" / 2 long, 8.0" wide, straight sides that
# run tangent into a half-elliptical nose 110 mm long. Drill guides (5 mm) for the trucks in
# the "new school" pattern, 1-5/8" across by 2-1/8" along, the inner pair 7.125" from the
# middle (a 14.25" wheelbase). A 100 x 30 mm hand hole centred on the centre line 100 mm
# from the middle. Engraved: the centre line (broken at the hand hole), "8.0 x 31.75" and
# "WB 14.25" either side of the hand hole, and "NOSE / TAIL" near the nose.

units mm
thickness 6 mm

WIDTH = 8.0 in
HALF = 31.75 in / 2
NOSE = 110 mm
ACROSS = 1.625 in
ALONG = 2.125 in
INNER = 7.125 in

solid template {
    sides = Rectangle(bottom_left=(0, -WIDTH / 2), width=HALF - NOSE, height=WIDTH)
    nose = Ellipse(center=(HALF - NOSE, 0), rx=NOSE, ry=WIDTH / 2)

    hole trucks {
        a = Circle(center=(INNER, ACROSS / 2), diameter=5)
        b = Circle(center=(INNER, -ACROSS / 2), diameter=5)
        c = Circle(center=(INNER + ALONG, ACROSS / 2), diameter=5)
        d = Circle(center=(INNER + ALONG, -ACROSS / 2), diameter=5)
    }
    hole hand {
        s = Slot(center=(100, 0), length=100, width=30, rotation=0)
    }
    drawing marks {
        cl_a = Line((0, 0), (45, 0))
        cl_b = Line((155, 0), (HALF - 3 mm, 0))
        size = Text("8.0 x 31.75", position=(100, -45), size=8, valign="middle")
        wb = Text("WB 14.25", position=(100, 45), size=8, valign="middle")
        end = Text("NOSE / TAIL", position=(330, -40), size=7, valign="middle")
    }
    Fixed(sides)

    # the request's numbers
    assert self.bb.width == 31.75 in / 2, "half of 31.75 in"
    assert self.bb.height == 8.0 in, "8.0 in wide"
    assert trucks.c.center.x - trucks.a.center.x == 2.125 in, "2-1/8 along"
    assert trucks.a.center.y - trucks.b.center.y == 1.625 in, "1-5/8 across"
    assert 2 * (trucks.a.center.x - sides.bb.left) == 14.25 in, "14.25 wheelbase"
    assert hand.s.length == 100 mm and hand.s.width == 30 mm, "hand hole"
    assert distance(marks, hand) >= 2 mm, "centre line clear of the hand hole"
}
