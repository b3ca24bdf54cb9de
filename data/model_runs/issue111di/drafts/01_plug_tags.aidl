# Request (home): cable ID tags for the power strip behind the TV, so I can tell which plug is
# which. Five tags in 3 mm white acrylic, each 55 x 18 mm with R4 corners. The left end is a
# clip: a 6 mm hole for the 5.5 mm mains cable, its centre 7 mm from the left end on the
# tag's centre line, open to the bottom edge by a 4.5 mm wide throat so the cable pushes in.
# The name is engraved filled in bold sans, 8 mm tall at most and at most 34 mm wide,
# centred in the 40 mm right part of the tag. Names: TV, ROUTER, LAMP, SPEAKER, CHARGER.
# Lay them out in a column 5 mm apart for cutting.

thickness 3 mm

names = ["TV", "ROUTER", "LAMP", "SPEAKER", "CHARGER"]

def tag(name="TV") -> solid {
    body = RoundedRectangle(center=(0, 0), width=55, height=18, corner_radius=4)
    hole clip {
        c = Circle(center=(-27.5 + 7, 0), diameter=6)
        # from the hole's centre down past the bottom edge
        throat = Rectangle(center=(-27.5 + 7, -5), width=4.5, height=10)
    }
    drawing label {
        t = Text(name, position=(-27.5 + 15 + 20, 0), size=8, font="sans:Bold",
                 valign="middle", fill=true, max_width=34)
    }
    assert body.bb.width == 55 mm, "tag 55 long"
    assert body.bb.height == 18 mm, "tag 18 high"
    assert clip.c.center.x - body.bb.left == 7 mm, "cable hole 7 mm from the left end"
    assert label.t.bb.width <= 34 mm, "name at most 34 wide"
    assert label.t.bb.left >= body.bb.left + 15 mm, "name in the right 40 mm"
    assert label.t.bb.right <= body.bb.right, "name on the tag"
}

assembly plug_tags {
    for i in range(5) {
        t = tag(name=names[i])
    }
    for i in range(1, 5) {
        Below(t[i], t[i - 1], gap=5)
        AlignLeft(t[i], t[i - 1])
    }
    assert len(t) == 5, "five tags"
}
