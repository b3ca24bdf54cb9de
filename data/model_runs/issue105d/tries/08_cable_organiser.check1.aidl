# Desk cable organiser: 120 x 40 mm plate, 4 mm rounded corners; four U-notches along
# the top edge, each 7 mm wide and 15 mm deep (round bottom), 25 mm apart, centred;
# two 4 mm screw holes 10 mm above the bottom edge, 12 mm in from the ends.
param w = 120 mm, min = 100 mm, max = 200 mm
param notch_w = 7 mm, min = 4 mm, max = 10 mm
param depth = 15 mm, min = 10 mm, max = 25 mm
thickness 3 mm

solid organiser {
    body = RoundedRectangle(center=(0, 0), width=w, height=40, corner_radius=4)
    hole notch {
        u = Slot(center=(-37.5, 10), length=depth + 5, width=notch_w, rotation=90)
    }
    notches = LinearPattern(notch, 4, (25, 0))
    # the U's bottom is depth below the top edge; the slot runs 5 mm past the edge
    notch.bb.bottom == body.bb.top - depth
    (notches[0].u.center.x + notches[3].u.center.x) / 2 == body.center.x
    hole screw_l { c = Circle(center=(-48, -10), diameter=4) }
    hole screw_r { c = Circle(center=(48, -10), diameter=4) }
    At(screw_l.c.center, body.bb.bottom_left, dx=12, dy=10)
    At(screw_r.c.center, body.bb.bottom_right, dx=-12, dy=10)
    assert len(notches) == 4, "four notches"
    assert body.bb.top - notches[2].bb.bottom == 15 mm, "15 mm deep"
    assert notches[1].u.center.x - notches[0].u.center.x == 25 mm, "25 mm apart"
}
