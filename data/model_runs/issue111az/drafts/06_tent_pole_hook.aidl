# Request: clip-on hooks for the 10 mm aluminium poles inside my dome tent, to hang a
# headlamp or a small lantern. Cut from 3 mm acetal (POM), four at once, 40 mm apart.
# Each hook: a C-clip round the pole (bore 10.2 mm, 4 mm wall, a mouth 8 mm wide at the
# top that snaps over the pole), a stem 6 mm wide running 40 mm down from the clip's
# bottom, and a J-hook at its foot: a 6 mm band along an arc of 12 mm radius (to its
# middle) from the stem round the bottom and up to 30 degrees past level on the far side,
# with a round tip. Every corner rounded 1 mm (no sharp edges to cut the tent).

thickness 3 mm

bore_d = 10.2 mm
wall = 4 mm
mouth = 8 mm
stem_w = 6 mm
stem_len = 40 mm
hook_r = 12 mm

assembly hooks {
    solid hook {
        ring = Circle(center=(0, 0), radius=bore_d / 2 + wall)
        stem = Rectangle(bottom_left=(-stem_w / 2, -(bore_d / 2 + wall) - stem_len),
                         width=stem_w, height=stem_len + 1 mm)
        path = Arc(center=(hook_r, -(bore_d / 2 + wall) - stem_len), radius=hook_r,
                   start_angle=180 deg, end_angle=30 deg)
        j = Stroke(path, width=stem_w)
        # FIX after the first valid program: the mouth stopped 1 mm inside the bore, leaving a
        # 1 mm ledge each side where its walls met the bore (W0508 flagged the 1 mm overlap,
        # and its hint would have closed the mouth); now the mouth runs from the bore's
        # centre and both shapes are one hole
        hole bore {
            c = Circle(center=(0, 0), diameter=bore_d)
            m = Rectangle(bottom_left=(-mouth / 2, 0), width=mouth, height=bore_d / 2 + wall + 1 mm)
        }
        Fillet(1 mm)
    }
    row = LinearPattern(hook, 4, (40 mm, 0))

    # the request's numbers
    assert len(row) == 4, "four hooks"
    assert hook.bore.c.diameter == 10.2 mm, "10.2 mm bore"
    assert hook.ring.radius - hook.bore.c.radius == 4 mm, "4 mm wall"
    assert hook.bore.m.width == 8 mm, "8 mm mouth"
    assert hook.ring.bottom.y - hook.stem.bb.bottom == 40 mm, "40 mm stem"
    assert hook.path.radius == 12 mm, "12 mm hook radius"
    assert row[1].bb.left - row[0].bb.left == 40 mm, "40 mm apart"
}
