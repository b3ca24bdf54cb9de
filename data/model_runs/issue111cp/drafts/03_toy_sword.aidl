# Request (toys): a toy katana for a 7-year-old, from 6 mm poplar ply, 580 mm overall.
# - Blade: 455 mm from the guard's shoulder to the tip, 32 mm wide at the guard tapering to
#   25 mm at 400 mm, curving up gently (the back rises about 17 mm by the tip), the tip
#   rounded (2 mm) for safety; an engraved fuller line 6 mm in from the back; the name
#   "SIR OSCAR" engraved filled in serif bold, 8 mm, along the blade at 200 mm.
# - Handle (tang): 125 mm long, 28 mm wide, round end; two 4 mm holes for rivets at 33 and
#   103 mm from the shoulder.
# - Tsuba (guard): a 76 x 66 mm oval with a 28.4 x 6.3 mm slot for the handle and four
#   kidney-shaped openings (a circular pattern) round it; it slides on from the handle's end.
# - Two grip scales glued on either face of the handle: 115 mm long from the handle's end,
#   28 mm wide, round end, the same two rivet holes, engraved with a row of 8 diamonds
#   (14 x 10 mm) like a cord wrap, the rivets in the 2nd and 7th.

units mm
thickness 6 mm
t = 6 mm

def grip() -> solid {
    body = RoundedRectangle(center=(-67.5, 0), width=115, height=28,
                            corner_radii=[14, 0, 0, 14])
    hole rivets {
        a = Circle(center=(-33, 0), diameter=4)
        b = Circle(center=(-103, 0), diameter=4)
    }
    drawing wrap {
        d = Polygon([(-7, 0), (0, 5), (7, 0), (0, -5)])
        ds = LinearPattern(d, 8, (14, 0))
    }
    At(wrap.d.center, (-117, 0))
}

assembly katana {
    solid blade {
        # frame: the guard's shoulder at x = 0, the blade toward +x
        # the tip rounded within the spline itself (E0407's hint): a short run of three
        # points between two corners, about 2 mm in radius
        edge = Spline([(0, 16), (130, 17.4), (265, 21.85), (400, 29.3), (453, 33.0),
                       (455, 31.8), (454.4, 29.6), (435, 12.5), (400, 4.3), (265, -5.5),
                       (130, -12.3), (0, -16)],
                      closed=true, corners=[0, 4, 6, 11])
        tang = RoundedRectangle(center=(-60, 0), width=130, height=28,
                                corner_radii=[14, 0, 0, 14])
        hole rivets {
            a = Circle(center=(-33, 0), diameter=4)
            b = Circle(center=(-103, 0), diameter=4)
        }
        drawing fuller {
            f = Spline([(25, 10), (130, 11.4), (265, 15.85), (380, 22)])
        }
        drawing name {
            n = Text("SIR OSCAR", position=(200, 3), size=8, font="serif:Bold", fill=true,
                     valign="middle", rotation=1.9 deg)
        }
    }

    solid tsuba {
        oval = Ellipse(center=(0, 0), rx=38, ry=33)
        hole mortise { m = Rectangle(center=(0, 0), width=28.4, height=6.3) }
        hole kidney { k = ArcSlot(center=(0, 0), radius=24, start_angle=20 deg, end_angle=70 deg, width=6) }
        openings = CircularPattern(kidney, 4, oval.center)
    }

    left = grip()
    right = grip()

    # on the sheet
    Below(left, blade, gap=6)
    AlignLeft(left, blade)
    RightOf(right, left, gap=6)
    AlignTop(right, left)
    RightOf(tsuba, right, gap=6)
    AlignTop(tsuba, left)

    # assembled: blade flat, a scale on each face of the handle, the tsuba across at the shoulder
    Place(blade, position=(0, 0, 0))
    Place(right, position=(0, 0, t))
    Place(left, position=(0, 0, 0), face="down", up="front")
    Place(tsuba, position=(-t, 0, t / 2), face="right", up="up")

    assert abs(blade.bb.width - 580 mm) < 0.5 mm, "580 mm overall (a spline bulges a little past its points)"
    assert blade.edge.points[5].x - blade.edge.points[0].x == 455 mm, "455 mm shoulder to tip"
    assert blade.edge.points[0].y - blade.edge.points[11].y == 32 mm, "32 mm wide at the guard"
    assert blade.tang.height == 28 mm and blade.tang.bb.left == -125 mm, "handle 125 x 28"
    assert tsuba.oval.bb.width == 76 mm and tsuba.oval.bb.height == 66 mm, "tsuba 76 x 66"
    assert len(tsuba.openings) == 4, "four openings"
    assert left.body.width == 115 mm and left.body.height == 28 mm, "scales 115 x 28"
    assert len(left.wrap.ds) == 8, "8 diamonds"
    assert blade.rivets.b.center.x - blade.rivets.a.center.x == -70 mm, "rivets at 33 and 103"
}
