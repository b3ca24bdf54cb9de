# Sport: a ski and snowboard wax scraper from 4 mm acrylic.
# 130 x 60 mm; the bottom long edge straight with sharp square corners (the scraping
# edge); the top corners rounded R8; a thumb dip in the top edge: an arc 70 mm across
# (chord), 6 mm deep at the middle, its ends rounded R3; a 6 mm hanging hole 10 mm in
# from the left edge and 12 mm down from the top; "SKI WAX" in bold sans 12 mm high,
# filled engraving, centred 25 mm above the scraping edge.

thickness 4 mm

param dip_w = 70 mm, min = 40 mm, max = 100 mm
param dip_d = 6 mm, min = 2 mm, max = 12 mm

solid scraper {
    edge = Line((-65, 0), (65, 0))
    right = Line((65, 0), (65, 60))
    top_r = Line((65, 60), (dip_w / 2, 60))
    dip = Arc(start=(dip_w / 2, 60), through=(0, 60 - dip_d), end=(-dip_w / 2, 60))
    top_l = Line((-dip_w / 2, 60), (-65, 60))
    left = Line((-65, 60), (-65, 0))
    Fixed(edge)

    Fillet(right.end, 8)
    Fillet(left.start, 8)
    Fillet(top_r.end, 3)
    Fillet(top_l.start, 3)

    hole hang {
        c = Circle(center=(-55, 48), diameter=6)
    }

    drawing label {
        t = Text("SKI WAX", position=(0, 25), size=12, font="sans:Bold", valign="middle", fill=true)
    }

    assert self.bb.width == 130 mm and self.bb.height == 60 mm, "130 x 60"
    assert edge.length == 130 mm, "straight scraping edge the full length"
    assert self.bb.top - dip.through.y == 6 mm, "dip 6 mm deep"
    assert distance(dip.start, dip.end) == 70 mm, "dip 70 mm across"
    assert hang.c.center.x - self.bb.left == 10 mm and self.bb.top - hang.c.center.y == 12 mm, "hole 10 / 12 mm in"
    assert label.t.position.y - edge.start.y == 25 mm, "label 25 mm above the edge"
}
