# Request: a cocktail recipe wheel for a home bar, two discs of 3 mm birch ply on a 5 mm
# Chicago screw. The back disc, 176 mm across, carries six recipes 60 deg apart, engraved in
# single-stroke letters: the name 5 mm tall 66 mm from the centre, three ingredient lines
# 3 mm tall at 57, 49 and 41 mm, each recipe turned so it reads upright when it is at the top;
# its rim has 36 half-round finger notches 4 mm across. The front disc, 156 mm across, has a
# window 54 deg wide from 36 to 72 mm out, centred at the top, through which one recipe shows
# at a time; "COCKTAIL WHEEL" engraved 6 mm tall round its lower rim and "MEASURES IN ML"
# 3.5 mm tall inside that. Names no wider than 48 mm, lines no wider than 34 mm (shrink to
# fit), so the showing recipe stays inside the window.

thickness 3 mm

names = ["MARGARITA", "DAIQUIRI", "NEGRONI", "MOJITO", "GIMLET", "COSMOPOLITAN"]
recs = [["50 TEQUILA", "25 LIME", "20 TRIPLE SEC"],
        ["60 RUM", "25 LIME", "15 SYRUP"],
        ["30 GIN", "30 CAMPARI", "30 VERMOUTH"],
        ["50 RUM", "25 LIME + MINT", "TOP WITH SODA"],
        ["60 GIN", "20 LIME", "15 SYRUP"],
        ["40 VODKA", "15 TRIPLE SEC", "30 CRANBERRY"]]
radii = [57 mm, 49 mm, 41 mm]

def ang(i) = (90 + 60 * i) * 1 deg

assembly cocktail_wheel {
    solid back {
        disc = Circle(center=(0, 0), diameter=176)
        hole pivot {
            c = Circle(center=(0, 0), diameter=5)
        }
        hole notch {
            n = Circle(center=(88, 0), diameter=4)
        }
        notches = CircularPattern(notch, 36, disc.center)
        drawing recipes {
            for i in range(6) {
                name = Text(names[i], position=(66 * cos(ang(i)), 66 * sin(ang(i))), size=5,
                            rotation=ang(i) - 90 deg, valign="middle", max_width=48 mm)
                for j in range(3) {
                    line = Text(recs[i][j],
                                position=(radii[j] * cos(ang(i)), radii[j] * sin(ang(i))),
                                size=3, rotation=ang(i) - 90 deg, valign="middle",
                                max_width=34 mm)
                }
            }
        }
    }

    solid front {
        disc = Circle(center=(0, 0), diameter=156)
        hole pivot {
            c = Circle(center=(0, 0), diameter=5)
        }
        hole window {
            w = Sector(center=(0, 0), radius=72, inner_radius=36, start_angle=63 deg,
                       end_angle=117 deg)
        }
        drawing title {
            ring = Circle(center=(0, 0), radius=62, construction=true)
            t = Text("COCKTAIL WHEEL", along=ring, size=6, flip=true)
            ring2 = Circle(center=(0, 0), radius=52, construction=true)
            m = Text("MEASURES IN ML", along=ring2, size=3.5, flip=true)
        }
    }

    RightOf(front, back, gap=8)
    AlignCenterY(front, back)

    Place(back, position=(0, 0, 0), face="up")
    Place(front, position=(0, 0, 3), face="up")

    # the request's numbers
    assert back.disc.diameter == 176 mm and front.disc.diameter == 156 mm, "discs 176 / 156"
    assert back.pivot.c.diameter == 5 mm and front.pivot.c.diameter == 5 mm, "5 mm pivot"
    assert len(names) == 6 and len(recs) == 6, "six recipes"
    assert len(back.notches) == 36 and back.notch.n.diameter == 4 mm, "36 notches 4 mm"
    assert front.window.w.radius == 72 mm and front.window.w.inner_radius == 36 mm,
        "window 36 to 72"
    assert front.title.t.size == 6 mm and front.title.m.size == 3.5 mm, "title sizes"
    assert distance(front.title, front.window) >= 2 mm, "title clear of the window"
    # the recipe at the top (i = 0) lies inside the window, 1.5 mm in
    assert back.recipes.name[0].bb.top <= 72 mm - 1.5 mm, "name inside the window's rim"
    assert back.recipes.line[0][2].bb.bottom >= 36 mm + 1.5 mm, "last line above the hub"
    assert atan2(back.recipes.name[0].bb.bottom, back.recipes.name[0].bb.right) >= 63 deg + 2 deg,
        "name inside the window's side"
    assert atan2(back.recipes.line[0][2].bb.bottom, back.recipes.line[0][2].bb.right) >= 63 deg + 2 deg,
        "last line inside the window's side"
}
