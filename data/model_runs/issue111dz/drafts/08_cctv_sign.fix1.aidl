# Request: a "CCTV IN OPERATION" sign for the workshop door, 3 mm acrylic, 200 x 150 mm with
# R8 corners, screwed up with four M4 countersunk screws (9 mm heads) 12 mm in from each edge.
# Engraved (filled): a CCTV camera icon at the top - a 46 x 20 mm body tilted 15 deg down to the
# left, a lens hood 10 mm long widening from 16 to 24 mm at its front, an arm 5 mm wide up to
# a 6 x 26 mm wall plate on the right; "CCTV" bold 28 mm; "IN OPERATION" bold 11 mm;
# "IMAGES ARE BEING RECORDED" 6 mm. An engraved border line 5 mm in from the edge (R5).
# Nothing engraved within 3 mm of a screw head.

import "std/fasteners.aidl"

thickness 3 mm

solid sign {
    plate = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=8)

    screw = clearance_hole(size=4)
    screws = CornerPattern(screw, plate, inset=12)
    Countersink(screws, diameter=9 mm)

    drawing border {
        line = RoundedRectangle(center=(0, 0), width=190, height=140, corner_radius=5)
    }

    drawing icon {
        # FIX after the first valid program: rotation -15 deg lowered the body's RIGHT end, so
        # the camera looked up to the left; +15 deg lowers its front (left) end as requested,
        # the hood turned with it (its wide top toward 195 deg) and the arm moved up
        body = Rectangle(center=(5, 40), width=46, height=20, rotation=15 deg, fill=true)
        hood = Trapezoid(center=(-22, 32.75), bottom_width=16, top_width=24, height=10,
                         rotation=105 deg, fill=true)
        arm = Stroke(Polyline([(8, 49), (24, 64), (44, 64)]), width=5, fill=true)
        wall = Rectangle(center=(46, 64), width=6, height=26, fill=true)
        Rigid(self)
    }
    AlignCenterX(icon, plate)
    icon.bb.top == plate.bb.top - 14 mm

    drawing words {
        cctv = Text("CCTV", position=(0, -8), size=28, font="sans:Bold", fill=true,
                    valign="middle")
        op = Text("IN OPERATION", position=(0, -35), size=11, font="sans:Bold", fill=true,
                  valign="middle")
        rec = Text("IMAGES ARE BEING RECORDED", position=(0, -54), size=6, font="sans",
                   fill=true, valign="middle")
    }

    # the request's numbers
    assert plate.bb.width == 200 mm and plate.bb.height == 150 mm, "200 x 150"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - plate.bb.left == 12 mm, "12 mm in from the side"
    assert screws[0].c.center.y - plate.bb.bottom == 12 mm, "12 mm in from the bottom"
    assert plate.bb.right - border.line.bb.right == 5 mm, "border 5 mm in"
    # distance() takes one shape or structure (a list: E0108); the head's rim is
    # (9 - 4.5) / 2 mm outside the hole's edge
    assert min([distance(words, s) for s in screws]) >= (9 mm - 4.5 mm) / 2 + 3 mm,
        "text clear of the screw heads"
    assert min([distance(icon, s) for s in screws]) >= (9 mm - 4.5 mm) / 2 + 3 mm,
        "icon clear of the screw heads"
    assert distance(icon, words) >= 3 mm, "icon clear of the words"
}
