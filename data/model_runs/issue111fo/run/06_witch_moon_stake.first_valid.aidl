# Request: a Halloween yard stake in 6 mm exterior ply: a full moon 360 mm across with a witch
# on a broomstick (flying right, about 260 mm from bristles to broom tip) cut out of it so
# the night shows through, three 40 mm bats and two 20 mm stars cut out around her,
# "HAPPY HALLOWEEN" engraved filled (bold sans, 16 mm) round the top inside the rim, a few
# engraved craters, and a 40 mm wide stake from the moon's bottom reaching 340 mm below it
# with a 60 mm point (one piece with the moon).

thickness 6 mm

MOON_D = 360 mm
# a bat's right half, from the top of the head to the bottom of the body (40 mm wingspan)
BAT = [(0, 2), (2, 6), (3.5, 2), (8, 4), (15, 8), (20, 5), (17, 1), (14, 3), (11, -1.5),
       (8, 0.5), (5, -3), (2, -2), (0, -5)]
BAT_AT = [(75, 70), (120, 35), (40, 105)]
STAR_AT = [(-120, 60), (-140, 10)]

def bat() -> hole {
    s = Polygon(BAT, mirror="y")
}

solid yard_stake {
    moon = Circle(center=(0, 0), diameter=MOON_D)
    shaft = Rectangle(bottom_left=(-20, -460), width=40, height=340)
    tip = Triangle(center=(0, -490), base=40, height=60, rotation=180 deg)

    hole witch {
        broom = Rectangle(center=(0, -20), width=200, height=8, rotation=8 deg)
        bristles = Polygon([(-95, -29), (-95, -39), (-150, -62), (-158, -44), (-150, -24)])
        cloak = Polygon([(-60, -34), (25, -22), (15, 30), (0, 42), (-20, 38), (-35, 5), (-75, -15)])
        head = Circle(center=(8, 55), radius=13)
        nose = Triangle((16, 58), (30, 52), (18, 50))
        brim = Rectangle(center=(6, 66), width=44, height=5, rotation=-10 deg)
        cone = Triangle((-8, 68), (20, 66), (-25, 115))
        arm = Polygon([(10, 20), (40, -8), (48, -2), (18, 28)])
        boot = Polygon([(10, -20), (40, -40), (52, -36), (48, -30), (18, -14)])
    }

    for p in BAT_AT {
        bats = bat()
        bats.s.center.x == p[0]
        bats.s.center.y == p[1]
    }

    hole stars {
        for p in STAR_AT {
            s = Star(center=p, points=5, outer_radius=10, inner_radius=4)
        }
    }

    drawing words {
        ring = Circle(center=(0, 0), radius=148, construction=true)
        t = Text("HAPPY HALLOWEEN", along=ring, size=16, font="sans:Bold", fill=true)
    }

    drawing craters {
        c1 = Circle(center=(120, -80), radius=15)
        c2 = Circle(center=(60, -110), radius=10)
        c3 = Circle(center=(-60, -120), radius=8)
    }

    assert moon.diameter == 360 mm, "a 360 mm moon"
    assert moon.bb.bottom - tip.bb.bottom == 340 mm, "stake reaches 340 below the moon"
    assert tip.bb.height == 60 mm, "60 mm point"
    assert shaft.bb.width == 40 mm, "40 mm stake"
    assert witch.bb.right - witch.bb.left >= 250 mm, "witch about 260 long"
    assert witch.bb.left >= moon.bb.left + 12 mm, "witch inside the moon"
    assert len(bats) == 3, "three bats"
    assert bats[0].s.bb.width == 40 mm, "40 mm bats"
    assert distance(words, witch) >= 5 mm, "words clear of the witch"
    assert distance(words, bats) >= 5 mm, "words clear of the bats"
    assert distance(witch, bats) >= 8 mm, "bats clear of the witch"
    assert distance(witch, stars) >= 8 mm, "stars clear of the witch"
}
