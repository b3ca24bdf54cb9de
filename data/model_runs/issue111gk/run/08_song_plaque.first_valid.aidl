# Request: an anniversary gift, a "now playing" song plaque. A 3 mm clear acrylic plaque
# 150 x 200 mm (R6 corners) standing 6 mm deep in a slot (0.2 mm clearance, 150.4 long) in
# a two-layer base of 6 mm ply, each layer 180 x 50 mm (R5), the slot 5 mm behind the middle
# of the top layer, "14 . 02 . 2026" engraved 6 mm tall in front of it. Engraved on the
# plaque: a 120 mm square "cover" frame (R4) whose top is 10 mm below the plaque's top, with
# "A + J" in 28 mm filled serif bold in it; under it the title "Our Song" (9 mm filled sans
# bold) and the artist "Ella & Louis" (5.5 mm) from the frame's left edge, a filled heart
# 9 mm wide at the right; a 120 mm progress bar filled to 40 % with a 4 mm knob, "1:24"
# and "3:32" (3 mm) under its ends; and the controls: previous, pause in a 14 mm circle,
# next, all at least 3 mm above the base.

units mm
thickness 6 mm

assembly song_plaque {
    solid plaque {
        thickness 3 mm
        body = RoundedRectangle(center=(0, 0), width=150, height=200, corner_radius=6)
        drawing cover {
            frame = RoundedRectangle(center=(0, 30), width=120, height=120, corner_radius=4)
            initials = Text("A + J", position=(0, 30), size=28, font="serif:Bold",
                            valign="middle", fill=true)
        }
        drawing song {
            title = Text("Our Song", position=(-60, -44), size=9, anchor="start",
                         font="sans:Bold", fill=true)
            artist = Text("Ella & Louis", position=(-60, -53), size=5.5, anchor="start")
            heart_l = Hull(Circle(center=(53.25, -42.5), radius=2.25), Point(55.5, -48),
                           fill=true)
            heart_r = Hull(Circle(center=(57.75, -42.5), radius=2.25), Point(55.5, -48),
                           fill=true)
        }
        drawing progress {
            bar = Line((-60, -62), (60, -62))
            done = Rectangle(bottom_left=(-60, -62.75), width=48, height=1.5, fill=true)
            knob = Circle(center=(-12, -62), diameter=4, fill=true)
            t0 = Text("1:24", position=(-60, -69), size=3, anchor="start")
            t1 = Text("3:32", position=(60, -69), size=3, anchor="end")
        }
        drawing controls {
            ring = Circle(center=(0, -82), diameter=14)
            pause_l = Rectangle(center=(-2, -82), width=2, height=6, fill=true)
            pause_r = Rectangle(center=(2, -82), width=2, height=6, fill=true)
            prev = Triangle(center=(-24, -82), base=7, height=6, rotation=90, fill=true)
            prev_bar = Rectangle(center=(-28.5, -82), width=1.5, height=7, fill=true)
            next = Triangle(center=(24, -82), base=7, height=6, rotation=-90, fill=true)
            next_bar = Rectangle(center=(28.5, -82), width=1.5, height=7, fill=true)
        }
    }

    solid base_top {
        body = RoundedRectangle(center=(0, 0), width=180, height=50, corner_radius=5)
        hole slot { s = Rectangle(center=(0, 5), width=150.4, height=3.2) }
        drawing date { d = Text("14 . 02 . 2026", position=(0, -12), size=6, valign="middle") }
    }
    solid base_bottom {
        body = RoundedRectangle(center=(0, 0), width=180, height=50, corner_radius=5)
    }

    # on the sheet
    RightOf(base_top, plaque, gap=10)
    AlignTop(base_top, plaque)
    Below(base_bottom, base_top, gap=10)
    AlignLeft(base_bottom, base_top)

    # assembled: the base's layers on z = 0 and 6, the plaque standing in the slot on the
    # bottom layer, its engraving to the front
    Place(base_bottom, position=(0, 0, 0), face="up")
    Place(base_top, position=(0, 0, 6), face="up")
    Place(plaque, position=(0, 5 + 1.5, 6 + 100), face="front", up="up")

    assert plaque.body.width == 150 mm and plaque.body.height == 200 mm, "150 x 200 plaque"
    assert base_top.slot.s.width == 150 mm + 0.4 mm, "slot 150.4 long"
    assert base_top.slot.s.height - 3 mm == 0.2 mm, "0.2 mm clearance on 3 mm acrylic"
    assert base_top.slot.s.center.y - base_top.body.center.y == 5 mm, "slot 5 mm back"
    assert plaque.cover.frame.width == 120 mm and plaque.cover.frame.height == 120 mm,
        "a 120 mm cover"
    assert plaque.body.bb.top - plaque.cover.frame.bb.top == 10 mm, "cover 10 mm from the top"
    assert plaque.progress.bar.length == 120 mm, "120 mm bar"
    assert (plaque.progress.knob.center.x - plaque.progress.bar.start.x) /
        plaque.progress.bar.length == 0.4, "40 % played"
    assert plaque.song.title.position.x == plaque.cover.frame.bb.left, "title from the left"
    assert plaque.controls.bb.bottom - plaque.body.bb.bottom >= 6 mm + 3 mm,
        "controls 3 mm above the base"
    assert plaque.song.heart_l.bb.left - plaque.song.heart_r.bb.right == -9 mm,
        "heart 9 mm wide"
}
