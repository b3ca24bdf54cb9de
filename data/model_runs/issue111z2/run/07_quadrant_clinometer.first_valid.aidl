# Science: a quadrant clinometer (angles of elevation, with a plumb line), 3 mm acrylic. The
# pivot (a 3 mm hole for the plumb line) is the centre of a quarter disc of radius 120 mm
# that fills the quarter below and left of it; an 8 mm strip runs along the top (y 0..8, from
# x = -120 to 8) and down the right side (x 0..8, from y = -120 to 8), so the pivot has
# material round it; a sighting straw is glued along the top edge. The three outer corners
# rounded R3. Engraved scale: 0 deg straight down from the pivot to 90 deg at the left;
# 1 deg ticks from r 110 to 116, every 5 deg from r 107, every 10 deg from r 104; numbers 0..90
# every 10 deg, 4 mm stroke letters hanging inside r 101, readable from the pivot.
# "CLINOMETER" in sans outline letters (not filled), 6 mm, centred at (-45, -30).

units mm
thickness 3 mm

param r = 120 mm, min = 80, max = 200

solid quadrant {
    face = Sector(center=(0, 0), radius=r, start_angle=180, end_angle=270)
    top = Rectangle(bottom_left=(-r, 0), width=r + 8, height=8)
    side = Rectangle(bottom_left=(0, -r), width=8, height=r)

    hole pivot {
        c = Circle(center=(0, 0), diameter=3)
    }

    drawing scale {
        for a in range(91) {
            r1 = 104 if a % 10 == 0 else (107 if a % 5 == 0 else 110)
            tick = Line(polar((0, 0), r1, (270 - a) * 1 deg), polar((0, 0), 116, (270 - a) * 1 deg))
        }
        ring = Circle(center=(0, 0), radius=101, construction=true)
        for k in range(10) {
            num = Text(str(k * 10), along=ring, angle=(270 - k * 10) * 1 deg, size=4, flip=true)
        }
        title = Text("CLINOMETER", position=(-45, -30), size=6, font="sans", valign="middle")
    }

    Fillet(3)

    assert face.radius == 120 mm, "quarter disc of radius 120"
    assert len(scale.tick) == 91, "a tick every degree 0..90"
    assert len(scale.num) == 10, "numbers every 10 deg"
    assert top.bb.height == 8 mm and side.bb.width == 8 mm, "8 mm strips"
    assert pivot.c.diameter == 3 mm, "3 mm plumb-line hole"
}
