# Request: party-bag bubble wands for a child's birthday, three different ones cut from 3 mm
# acrylic. Each is a frame that holds the soap film on a 200 mm handle, 12 mm wide, with a
# round end and a 4 mm ribbon hole whose centre is 8 mm from that end; the handle meets the
# frame with r4 fillets. Wand 1: a ring 60 mm across, 6 mm wide. Wand 2: a five-point star,
# 38 mm tips / 18 mm notches, tips rounded r3, 5 mm wide frame. Wand 3: a heart 60 mm wide,
# 5 mm wide frame. The guests' names MIA, LEO and AVA engraved along the handles
# (5 mm letters, reading up). Laid out side by side, 10 mm apart.

thickness 3 mm

param handle_l = 200 mm, min = 120, max = 260
param frame_w = 60 mm, min = 40, max = 80

def wand(kind="ring", name="MIA") -> solid {
    # the handle runs from 200 mm below the frame's lowest point up into its rim (for the
    # star: up into the band at its bottom notch, 18 mm below the centre)
    handle = RoundedRectangle(bottom_left=(-6, -30 - handle_l), width=12,
                              height=handle_l + (16 if kind == "star" else 4),
                              corner_radii=[0, 0, 6, 6])
    if kind == "ring" {
        rim = Circle(center=(0, 0), diameter=frame_w)
        frame = Shell(rim, -6 mm)
        Fillet([handle, rim], 4 mm)
    } else {
        if kind == "star" {
            rim = Star(center=(0, 0), points=5, outer_radius=38, inner_radius=18, tip_radius=3)
            frame = Shell(rim, -5 mm)
            Fillet([handle, rim], 4 mm)
        } else {
            # (no fillet here: a fillet cannot end on a spline, E0407)
            rim = Spline([(0, 16), (14, 27), (27, 22), (30, 8), (20, -10), (0, -30),
                          (-20, -10), (-30, 8), (-27, 22), (-14, 27)], closed=true,
                         corners=[0, 5])
            frame = Shell(rim, -5 mm)
        }
    }
    hole ribbon {
        c = Circle(center=(0, -30 - handle_l + 8), diameter=4)
    }
    drawing label {
        n = Text(name, position=(0, -30 - handle_l / 2), size=5, rotation=90 deg,
                 valign="middle")
    }
}

assembly favours {
    a = wand(kind="ring", name="MIA")
    b = wand(kind="star", name="LEO")
    c = wand(kind="heart", name="AVA")
    RightOf(b, a, gap=10)
    RightOf(c, b, gap=10)
    AlignBottom(b, a)
    AlignBottom(c, a)

    assert a.rim.diameter == 60 mm, "ring 60 across"
    assert b.rim.outer_radius == 38 mm and b.rim.inner_radius == 18 mm, "star 38 / 18"
    assert c.rim.points[3].x - c.rim.points[7].x == 60 mm, "heart 60 wide"
    assert a.rim.bb.bottom - a.handle.bb.bottom == 200 mm, "200 mm handle"
    assert c.rim.points[5].y - c.handle.bb.bottom == 200 mm, "200 mm handle (heart)"
    assert a.handle.bb.width == 12 mm, "12 mm handle"
    assert a.ribbon.c.center.y - a.handle.bb.bottom == 8 mm, "ribbon hole 8 from the end"
}
