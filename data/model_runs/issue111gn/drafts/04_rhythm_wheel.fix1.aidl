# Request (music): a rhythm wheel for teaching a rock groove, 3 mm ply. A 220 mm base disc with
# the 16 steps numbered 1-16 round its rim (6 mm numbers, step 1 at the top, clockwise). On a
# central M6 pivot (6.4 mm holes in every part) three discs turn over it: KICK 180 mm, SNARE
# 140 mm and HAT 100 mm. Each disc has 16 step places round its visible band: a hit is a round
# hole cut through, a rest an engraved ring of the same size (KICK and SNARE 8 mm on radii 78 and
# 58 mm, HAT 7 mm on radius 38 mm). The groove: KICK on steps 1, 9, 11; SNARE on 5 and 13; HAT on
# every odd step (1, 3, ... 15). Under each disc's holes the part below is engraved with a filled
# 10 mm band, so a hit shows dark. Each disc's name engraved along its rim outside its holes
# (3 mm letters); "RHYTHM" / "WHEEL" engraved on the HAT disc's centre.

units mm
thickness 3 mm

def step_angle(i) = 90 deg - i * 22.5 deg

def disc(r=90 mm, ring_r=78 mm, d=8 mm, hits=[0], name="KICK", band_r=0 mm) -> solid {
    body = Circle(center=(0, 0), radius=r)
    hole pivot { c = Circle(center=(0, 0), diameter=6.4) }
    hole hit {
        for i in hits {
            c = Circle(center=polar((0, 0), ring_r, step_angle(i)), diameter=d)
        }
    }
    drawing marks {
        for i in [k for k in range(16) if len([h for h in hits if h == k]) == 0] {
            rest = Circle(center=polar((0, 0), ring_r, step_angle(i)), diameter=d)
        }
        rim = Circle(center=(0, 0), radius=ring_r + d / 2 + 2.5 mm, construction=true)
        label = Text(name, along=rim, size=3)
        if band_r > 0 mm {
            band = Shell(Circle(center=(0, 0), radius=band_r - 5 mm), 10 mm, fill=true)
        }
    }
}

assembly rhythm_wheel {
    solid base {
        body = Circle(center=(0, 0), radius=110)
        hole pivot { c = Circle(center=(0, 0), diameter=6.4) }
        drawing numbers {
            rim = Circle(center=(0, 0), radius=96, construction=true)
            # FIX after the first valid program: the lower half's numbers read the right way up
            # (step 9 at the bottom read as a 6), hanging inside a circle 6 mm further out
            low_rim = Circle(center=(0, 0), radius=102, construction=true)
            for i in range(16) {
                if i >= 5 and i <= 11 {
                    n = Text(str(i + 1), along=low_rim, angle=step_angle(i), size=6, flip=true)
                } else {
                    n = Text(str(i + 1), along=rim, angle=step_angle(i), size=6)
                }
            }
            band = Shell(Circle(center=(0, 0), radius=73), 10 mm, fill=true)
        }
    }
    kick = disc(r=90 mm, ring_r=78 mm, d=8 mm, hits=[0, 8, 10], name="KICK", band_r=58 mm)
    snare = disc(r=70 mm, ring_r=58 mm, d=8 mm, hits=[4, 12], name="SNARE", band_r=38 mm)
    hat = disc(r=50 mm, ring_r=38 mm, d=7 mm, hits=[0, 2, 4, 6, 8, 10, 12, 14], name="HAT")
    drawing title {
        t1 = Text("RHYTHM", position=(0, 14), size=5, valign="middle")
        t2 = Text("WHEEL", position=(0, -14), size=5, valign="middle")
    }
    CutInto(title, hat)
    # FIX after the first valid program: the title was left where written, off the HAT disc
    CenterInside(title, hat)

    # flat on the sheet side by side; stacked on the pivot in 3D
    RightOf(kick, base, gap=10)
    RightOf(snare, kick, gap=10)
    RightOf(hat, snare, gap=10)
    AlignCenterY(kick, base)
    AlignCenterY(snare, base)
    AlignCenterY(hat, base)
    Place(base, position=(0, 0, 0), face="up")
    Place(kick, position=(0, 0, 3), face="up")
    Place(snare, position=(0, 0, 6), face="up")
    Place(hat, position=(0, 0, 9), face="up")

    assert base.body.diameter == 220 mm, "base 220 mm"
    assert kick.body.diameter == 180 mm and snare.body.diameter == 140 mm and hat.body.diameter == 100 mm, "discs 180 / 140 / 100"
    assert len(base.numbers.n) == 16, "16 steps"
    assert len(kick.hit.c) == 3 and len(snare.hit.c) == 2 and len(hat.hit.c) == 8, "3 kicks, 2 snares, 8 hats"
    assert len(kick.marks.rest) == 13, "13 kick rests"
    assert kick.pivot.c.diameter == 6.4 mm and hat.pivot.c.diameter == 6.4 mm, "M6 pivot"
    assert kick.hit.c[0].diameter == 8 mm and hat.hit.c[0].diameter == 7 mm, "hole sizes"
    assert abs(distance(kick.hit.c[0].center, kick.body.center) - 78 mm) < 0.01 mm, "kick radius 78"
    assert abs(distance(snare.hit.c[0].center, snare.body.center) - 58 mm) < 0.01 mm, "snare radius 58"
    assert abs(distance(hat.hit.c[0].center, hat.body.center) - 38 mm) < 0.01 mm, "hat radius 38"
    assert kick.marks.rim.radius + 3 mm < kick.body.radius, "KICK inside its rim"
    assert snare.marks.rim.radius + 3 mm < snare.body.radius, "SNARE inside its rim"
    assert hat.marks.rim.radius + 3 mm < hat.body.radius, "HAT inside its rim"
}
