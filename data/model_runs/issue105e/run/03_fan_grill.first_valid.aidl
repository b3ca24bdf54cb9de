# 80 mm fan grill: an 80 x 80 mm plate with 5 mm rounded corners, four 4.3 mm
# screw holes on the fan's 71.5 mm square pattern, and the air opening: nine
# parallel horizontal bars 4 mm tall at a 7.5 mm pitch, each clipped to a
# 72 mm circle centered on the plate (so 3.5 mm ribs stay between bars).

param size = 80 mm, min = 60 mm, max = 140 mm
param pitch = 7.5 mm, min = 6 mm, max = 12 mm
bars = 9

solid grill_plate {
    body = RoundedRectangle(center=(0, 0), width=size, height=size, corner_radius=5)
    hole screw { c = Circle(center=(-35.75, -35.75), diameter=4.3) }
    CornerPattern(screw, body, inset=(size - 71.5 mm) / 2)

    hole air {
        disc = Circle(center=(0, 0), diameter=72, construction=true)
        for i in range(bars) {
            bar = Intersect(disc, Rectangle(center=(0, (i - (bars - 1) / 2) * pitch), width=80, height=4))
        }
    }
    CenterInside(air, body)

    assert body.bb.width == size and body.bb.height == size, "plate size"
    assert len(air.bar) == 9, "nine bars"
}
