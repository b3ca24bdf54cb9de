# A wall plaque for a bike shed: a rounded plate with a bicycle engraved (wheels,
# frame) and a name; two screw holes. (First try: the wheels cut as openings, the
# frame's lines ran across them from the hubs: W0505, so the wheels are engraved.)
# Wanted: the same plaque 30 % smaller (a 140 x 80 design made 98 x 56 mm).
# Before issue 95 (no Scale): every number multiplied by k by hand.
units mm

k = 0.7

solid plaque {
    body = RoundedRectangle(center=(k * 0, k * 0), width=k * 140, height=k * 80, corner_radius=k * 10)
    hole screw_l { c = Circle(center=(k * -60, k * 30), radius=k * 2.5) }
    hole screw_r { c = Circle(center=(k * 60, k * 30), radius=k * 2.5) }
    drawing frame {
        back_wheel = Circle(center=(k * -38, k * -10), radius=k * 20)
        front_wheel = Circle(center=(k * 38, k * -10), radius=k * 20)
        chain = Line(start=(k * -38, k * -10), end=(k * 0, k * -10))
        seat_tube = Line(start=(k * 0, k * -10), end=(k * -12, k * 18))
        top_tube = Line(start=(k * -12, k * 18), end=(k * 28, k * 18))
        down_tube = Line(start=(k * 28, k * 18), end=(k * 0, k * -10))
        stay = Line(start=(k * -12, k * 18), end=(k * -38, k * -10))
        fork = Line(start=(k * 28, k * 18), end=(k * 38, k * -10))
        bars = Line(start=(k * 24, k * 26), end=(k * 34, k * 26))
        stem = Line(start=(k * 28, k * 18), end=(k * 29, k * 26))
        saddle = Line(start=(k * -18, k * 22), end=(k * -6, k * 22))
        post = Line(start=(k * -12, k * 18), end=(k * -12, k * 22))
        name = Text("BIKE SHED", position=(k * 0, k * -34), size=k * 6, valign="middle")
    }
    Fixed(body.center)
}
