# Request: a stroboscope disc for checking a record deck's speed under mains light,
# cut from 3 mm white acrylic with the bars engraved filled (then painted black).
# - A 180 mm disc with a 7.3 mm spindle hole.
# - Four rings of radial bars, each 10 mm deep, bars and gaps of equal angle:
#   outermost 216 bars (33 1/3 rpm at 60 Hz) from r 78 to 88; then 180 bars
#   (33 1/3 at 50 Hz) from r 64 to 74; 160 bars (45 at 60 Hz) from r 50 to 60;
#   133 bars (45 at 50 Hz, reads 45.1) from r 36 to 46.
# - In the 4 mm gap just inside each ring, its label engraved 2 mm high along the
#   circle: "^ 33 1/3 RPM  60 Hz ^" and so on.
# - "SPEED CHECK" engraved 4 mm high in the middle, above the spindle hole.
# Bars per ring: 2 x mains Hz x 60 / rpm (flashes per minute / revolutions per minute).

units mm
thickness 3 mm
kerf 0.1 mm

def bars(n, r_in, r_out) -> drawing {
    half = 360 deg / (4 * n)       # a bar is half a pitch wide
    for i in range(n) {
        a = i * 360 deg / n
        bar = Polygon([(r_in * cos(a - half), r_in * sin(a - half)),
                       (r_out * cos(a - half), r_out * sin(a - half)),
                       (r_out * cos(a + half), r_out * sin(a + half)),
                       (r_in * cos(a + half), r_in * sin(a + half))], fill=true)
    }
}

def label(words, r) -> drawing {
    track = Circle(center=(0, 0), radius=r, construction=true)
    t = Text(words, along=track, size=2 mm, valign="middle")
}

solid strobe {
    disc = Circle(center=(0, 0), diameter=180 mm)
    hole spindle { c = Circle(center=(0, 0), diameter=7.3 mm) }
    Fixed(disc)
    Fixed(spindle)

    ring60_33 = bars(n=216, r_in=78 mm, r_out=88 mm)
    ring50_33 = bars(n=180, r_in=64 mm, r_out=74 mm)
    ring60_45 = bars(n=160, r_in=50 mm, r_out=60 mm)
    ring50_45 = bars(n=133, r_in=36 mm, r_out=46 mm)

    # the labels sit 0.3 mm out from the gap's middle: the "/" reaches below the baseline
    tag60_33 = label(words="^ 33 1/3 RPM  60 Hz ^", r=76.3 mm)
    tag50_33 = label(words="^ 33 1/3 RPM  50 Hz ^", r=62.3 mm)
    tag60_45 = label(words="^ 45 RPM  60 Hz ^", r=48.3 mm)
    tag50_45 = label(words="^ 45 RPM  50 Hz ^", r=34.3 mm)

    drawing title {
        t = Text("SPEED CHECK", position=(0, 12 mm), size=4 mm, valign="middle")
    }
    Fixed(title)

    # the request's numbers: bars = 2 x Hz x 60 / rpm
    assert len(ring60_33.bar) == 216 and round(2 * 60 * 60 / (100 / 3)) == 216
    assert len(ring50_33.bar) == 180 and round(2 * 50 * 60 / (100 / 3)) == 180
    assert len(ring60_45.bar) == 160 and round(2 * 60 * 60 / 45) == 160
    assert len(ring50_45.bar) == 133 and round(2 * 50 * 60 / 45) == 133
    assert disc.diameter == 180 mm and spindle.c.diameter == 7.3 mm
    assert ring60_33.bb.right <= disc.bb.right - 1 mm, "outer ring on the disc"
    assert ring60_33.bb.width <= 2 * 88 mm and distance(tag60_33, ring50_33) >= 0.5 mm
    assert distance(title, spindle) >= 3 mm and distance(title, ring50_45) >= 2 mm
    assert distance(tag50_45, spindle) >= 3 mm
}
