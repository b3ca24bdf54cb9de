# Figure of docs/language.md: a pie slice and an annulus segment (Sector), and a dial with
# numbers laid along a circle by Text(along=, angle=).
# Drawn by `python docs/make_pictures.py` to docs/images/sector_text_along.png.

assembly sectors {
    solid pie {
        s = Sector(center=(-60, -15), radius=30, start_angle=30 deg, end_angle=110 deg)
    }
    solid ring {
        s = Sector(center=(2, -15), radius=28, inner_radius=18, start_angle=-30 deg,
                   end_angle=210 deg)
    }
    solid dial {
        body = Circle(center=(70, 0), radius=28)
        Fixed(body)
        drawing numbers {
            ring = Circle(center=(70, 0), radius=20, construction=true)
            for a in range(0, 360, 45) {
                n = Text(str(a), along=ring, angle=a * 1 deg, size=4)
            }
            title = Text("DIAL", position=(70, -2), size=4)
        }
        Coincident(numbers.ring.center, body.center)
    }
}
