# Figure of docs/language.md 4.5: Rigid and AllowOverlap. Left, a windmill whose spar a
# constraint pulls down 15 mm onto the tower leaves its sail behind; middle, the same with
# Rigid(spar, sail) moves both; right, a star meant to overlap a crescent's bite.
# Drawn by `python docs/make_pictures.py` to docs/images/overlap_rigid.png.
# render: --png-width 560

assembly figure {
    solid loose {
        tower = Rectangle(bottom_left=(-5, 0), width=10, height=60)
        Fixed(tower)
        spar = Rectangle(center=(0, 100), width=4, height=50)
        sail = Rectangle(center=(9, 130), width=14, height=30)
        Coincident(spar.bottom.midpoint, tower.top.midpoint)
    }
    solid rigid {
        tower = Rectangle(bottom_left=(55, 0), width=10, height=60)
        Fixed(tower)
        spar = Rectangle(center=(60, 100), width=4, height=50)
        sail = Rectangle(center=(69, 130), width=14, height=30)
        Rigid(spar, sail)
        Coincident(spar.bottom.midpoint, tower.top.midpoint)
    }
    solid badge {
        solid moon {
            body = Circle(center=(130, 70), radius=30)
            Fixed(body)
            hole bite { c = Circle(center=(145, 80), radius=24) }
        }
        solid star { s = Star(center=(124, 80), points=5, outer_radius=12, inner_radius=5) }
        Fixed(star.s)
        AllowOverlap(moon.bite, star)
    }
    drawing labels {
        a = Text("no Rigid", (0, -12), size=6)
        b = Text("Rigid(spar, sail)", (60, -12), size=6)
        c = Text("AllowOverlap(moon.bite, star)", (150, 28), size=5)
    }
}
