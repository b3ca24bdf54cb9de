# Parties: lace cupcake wrapper cut from 0.5 mm card, rolled into a cone. Flat, it is a ring
# piece about one centre: inner radius 110 mm, outer radius 155 mm, 100 deg from 40 to 140 deg.
# Lace: 5 mm holes in two rows, 16 on R125 every 6 deg from 46 deg, 15 on R142 every 6 deg from
# 49 deg. Locking slits 22.5 mm long at each end: at 44 deg from the inner edge outward, at
# 136 deg from the outer edge inward. "HAPPY BIRTHDAY" engraved in 5 mm strokes along R113,
# over the top.

thickness 0.5 mm
min_wall 0.3 mm

solid wrapper {
    band = Sector(center=(0, 0), radius=155, start_angle=40 deg, end_angle=140 deg, inner_radius=110)

    hole lace {
        for i in range(16) {
            a = Circle(center=(125 * cos(46 deg + i * 6 deg), 125 * sin(46 deg + i * 6 deg)), diameter=5)
        }
        for j in range(15) {
            b = Circle(center=(142 * cos(49 deg + j * 6 deg), 142 * sin(49 deg + j * 6 deg)), diameter=5)
        }
    }

    cut slits {
        inner = Line((110 * cos(44 deg), 110 * sin(44 deg)), (132.5 * cos(44 deg), 132.5 * sin(44 deg)))
        outer = Line((155 * cos(136 deg), 155 * sin(136 deg)), (132.5 * cos(136 deg), 132.5 * sin(136 deg)))
    }

    drawing greeting {
        ring = Circle(center=(0, 0), radius=113, construction=true)
        t = Text("HAPPY BIRTHDAY", along=ring, size=5)
    }

    assert band.radius == 155 mm and band.inner_radius == 110 mm, "R110 - R155"
    assert len(lace.a) == 16 and len(lace.b) == 15, "16 + 15 lace holes"
    assert lace.a[0].diameter == 5 mm, "5 mm holes"
    assert slits.inner.length == 22.5 mm and slits.outer.length == 22.5 mm, "22.5 mm slits"
    assert greeting.t.size == 5 mm, "5 mm letters"
}
