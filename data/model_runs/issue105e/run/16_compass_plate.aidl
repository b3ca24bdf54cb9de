# Square plate with an engraved compass rose: a 100 x 100 mm plate with 4 mm
# rounded corners; engraved at its center a four-pointed star (tips 36 mm from
# the center, notches 9 mm, first tip pointing up/north), a smaller
# four-pointed star turned 45 degrees (tips 22 mm, notches 6 mm), a 28 mm
# radius circle, and the letters N, E, S, W, 6 mm tall, centered 43 mm from
# the center on the four main directions.
# Fix after the first render: the small star and the circle pass behind the
# main star (their lines hidden inside it) instead of crossing it.

param r = 36 mm, min = 25 mm, max = 38 mm

solid plaque {
    body = RoundedRectangle(center=(0, 0), width=100, height=100, corner_radius=4)
    drawing rose {
        main = Star(center=(0, 0), points=4, outer_radius=r, inner_radius=r / 4)
        n = Text("N", position=(0, 43), size=6, valign="middle")
        e = Text("E", position=(43, 0), size=6, valign="middle")
        s = Text("S", position=(0, -43), size=6, valign="middle")
        w = Text("W", position=(-43, 0), size=6, valign="middle")
        At(n.position, main.center, dy=r + 7 mm)
        At(e.position, main.center, dx=r + 7 mm)
        At(s.position, main.center, dy=-(r + 7 mm))
        At(w.position, main.center, dx=-(r + 7 mm))
    }
    drawing behind {
        minor = Star(center=(0, 0), points=4, outer_radius=22, inner_radius=6, rotation=45 deg)
        ring = Circle(center=(0, 0), radius=28)
        Concentric(ring, minor)
        hole mask {
            m = Star(center=(0, 0), points=4, outer_radius=r, inner_radius=r / 4)
        }
        Concentric(mask.m, minor)
    }
    Concentric(rose.main, body)
    Concentric(behind.minor, rose.main)

    assert rose.bb.top < body.bb.top - 3 mm and rose.bb.right < body.bb.right - 3 mm, "rose inside the plate with a 3 mm margin"
    assert rose.main.outer_radius == 36 mm, "main tips 36 mm"
}
