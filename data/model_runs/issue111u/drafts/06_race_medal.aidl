# Sport: a fun-run finisher's medal, 3 mm birch. Disc 70 mm across. A five-pointed star cut
# through the middle (tips on 30 mm, notches on 13 mm, a tip up). A ribbon slot 25 x 4 mm (round
# ends) centred 27.5 mm above the centre. Engraved: a border circle 66 mm across; "CITY RUN 2026"
# 4.5 mm along the top on a 42 mm circle; "10 KM" 4.5 mm along the bottom, readable.

thickness 3 mm

param d = 70 mm, min = 60 mm, max = 90 mm

solid medal {
    disc = Circle(center=(0, 0), diameter=d)

    hole star {
        s = Star(center=(0, 0), points=5, outer_radius=15, inner_radius=6.5)
    }

    hole ribbon {
        r = Slot(center=(0, 27.5), length=25, width=4)
    }

    drawing art {
        border = Circle(center=(0, 0), diameter=66)
        ring = Circle(center=(0, 0), diameter=38, construction=true)
        top = Text("CITY RUN 2026", along=ring, size=4.5)
        bottom = Text("10 KM", along=ring, size=4.5, flip=true)
    }

    assert disc.diameter == 70 mm, "70 mm disc"
    assert star.s.outer_radius * 2 == 30 mm and star.s.inner_radius * 2 == 13 mm, "star 30 / 13"
    assert ribbon.bb.width == 25 mm and ribbon.bb.height == 4 mm, "ribbon slot 25 x 4"
    assert ribbon.r.center.y - disc.center.y == 27.5 mm, "slot 27.5 up"
    assert art.border.diameter == 66 mm, "border 66"
}
