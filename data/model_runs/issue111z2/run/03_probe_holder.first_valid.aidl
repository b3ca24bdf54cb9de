# Electronics bench: an oscilloscope-probe holder, 4 mm acrylic, screwed flat under a shelf so
# its front edge sticks out. A plate 160 x 60 mm with 4 mm corner radii. Along the front
# (bottom) edge: 4 notches for the probe cables, 5 mm wide and 25 mm deep from the edge (round
# end), 35 mm apart, the row centred on the plate; the notches' mouth corners rounded R1.
# "CH1".."CH4" engraved (5 mm stroke text) above each notch, baselines 2 mm above the plate's
# centre line. Two M4 countersunk screw holes (4.5 mm through, 9 mm countersink) 12 mm from
# the back (top) edge and 15 mm from the side edges.

units mm
thickness 4 mm

param pitch = 35 mm, min = 25, max = 38
param depth = 25 mm, min = 15, max = 30

solid holder {
    plate = RoundedRectangle(center=(0, 0), width=160, height=60, corner_radius=4)

    hole notch {
        s = Slot(start=(-1.5 * pitch, -33), end=(-1.5 * pitch, -30 + depth - 2.5), width=5)
    }
    notches = LinearPattern(notch, 4, (pitch, 0))

    hole screw {
        c = Circle(center=(-80 + 15, 30 - 12), diameter=4.5)
    }
    screws = LinearPattern(screw, 2, (130, 0))
    Countersink(screw, diameter=9)

    drawing labels {
        for i in range(4) {
            t = Text(f"CH{i + 1}", position=(-1.5 * pitch + i * pitch, 2), size=5)
        }
    }

    Fillet(1)

    assert plate.bb.width == 160 mm and plate.bb.height == 60 mm, "plate 160 x 60"
    assert len(notches) == 4, "4 notches"
    assert notch.s.width == 5 mm, "5 mm wide notches"
    assert notch.s.bb.top - plate.bb.bottom == 25 mm, "25 mm deep from the edge"
    assert notches[1].s.center.x - notches[0].s.center.x == 35 mm, "35 mm apart"
    assert notches[0].s.center.x + notches[3].s.center.x == 0 mm, "row centred"
    assert plate.bb.top - screw.c.center.y == 12 mm, "screws 12 mm from the back edge"
    assert screw.c.center.x - plate.bb.left == 15 mm and plate.bb.right - screws[1].c.center.x == 15 mm, "15 mm from the sides"
}
