# Request: a set of four spoons for a children's party egg-and-spoon race, cut from 6 mm
# ply. Each spoon is 300 mm long overall: a round head 72 mm across with a 38 mm hole the egg
# sits in (a hen's egg is about 43 mm across, so it rests in the hole and cannot fall
# through), and a handle that tapers from 18 mm wide at the head to 28 mm at the grip end,
# the joins rounded R6. A 6 mm hanging hole 12 mm from the handle's end. Each handle is
# engraved "TEAM 1" .. "TEAM 4" (7 mm strokes, reading along the handle) and carries as many
# 6 mm filled engraved dots as its number, so small children can find their spoon.

thickness 6 mm

spoons = 4
length = 300 mm
head_d = 72 mm
egg_hole = 38 mm

def spoon(n=1) -> solid {
    head = Circle(center=(0, 0), diameter=head_d)
    neck = Circle(center=(0, -head_d / 2 - 4 mm), diameter=18 mm)
    grip = Circle(center=(0, head_d / 2 - length + 14 mm), diameter=28 mm)
    handle = Hull(neck, grip)
    Fillet(6 mm)
    hole egg {
        c = Circle(center=(0, 0), diameter=egg_hole)
    }
    hole hang {
        c = Circle(center=(0, head_d / 2 - length + 12 mm), diameter=6 mm)
    }
    drawing team {
        t = Text(f"TEAM {n:.0f}", position=(0, -130 mm), size=7 mm, valign="middle",
                 rotation=90 deg)
        for k in range(n) {
            d = Circle(center=(0, -195 mm - k * 10 mm), diameter=6 mm, fill=true)
        }
    }
}

assembly egg_race {
    for i in range(spoons) {
        s = spoon(n=i + 1)
        s.bb.left == i * (head_d + 8 mm)
        s.bb.top == 0
    }

    # the request's numbers
    assert len(s) == 4, "four spoons"
    assert s[0].bb.height == 300 mm, "300 mm long"
    assert s[0].head.diameter == 72 mm and s[0].egg.c.diameter == 38 mm, "head and egg hole"
    assert 43 mm - s[0].egg.c.diameter >= 3 mm, "the egg cannot fall through"
    assert s[0].neck.diameter == 18 mm and s[0].grip.diameter == 28 mm, "taper 18 to 28"
    assert s[0].hang.c.center.y - s[0].bb.bottom == 12 mm, "hanging hole 12 mm from the end"
    assert len(s[3].team.d) == 4 and len(s[0].team.d) == 1, "dots = team number"
    # the dots and the word stay on the handle, clear of the hanging hole
    assert s[3].team.bb.bottom - s[3].hang.bb.top >= 5 mm, "dots clear of the hanging hole"
}
