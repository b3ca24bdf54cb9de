# A wall plaque for a bike shed: a rounded plate with a bicycle cut through it
# (the wheels are openings) and its frame and a name engraved; two screw holes.
# Wanted: the same plaque 30 % smaller (a 140 x 80 design made 98 x 56 mm).
units mm

solid plaque {
    body = RoundedRectangle(center=(0, 0), width=140, height=80, corner_radius=10)
    hole back_wheel { c = Circle(center=(-38, -10), radius=20) }
    hole front_wheel { c = Circle(center=(38, -10), radius=20) }
    hole screw_l { c = Circle(center=(-60, 30), radius=2.5) }
    hole screw_r { c = Circle(center=(60, 30), radius=2.5) }
    drawing frame {
        chain = Line(start=(-38, -10), end=(0, -10))
        seat_tube = Line(start=(0, -10), end=(-12, 18))
        top_tube = Line(start=(-12, 18), end=(28, 18))
        down_tube = Line(start=(28, 18), end=(0, -10))
        stay = Line(start=(-12, 18), end=(-38, -10))
        fork = Line(start=(28, 18), end=(38, -10))
        bars = Line(start=(24, 26), end=(34, 26))
        stem = Line(start=(28, 18), end=(29, 26))
        saddle = Line(start=(-18, 22), end=(-6, 22))
        post = Line(start=(-12, 18), end=(-12, 22))
        name = Text("BIKE SHED", position=(0, -34), size=6, valign="middle")
    }
    Fixed(body.center)
}

Scale(plaque, 0.7)
