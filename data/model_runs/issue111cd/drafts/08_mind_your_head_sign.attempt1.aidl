# Request (signs): a "MIND YOUR HEAD" sign for the low beam over my cellar stairs, 3 mm yellow
# acrylic, 300 x 100 mm, corners r8. Hazard stripes engraved filled (to paint black) in two
# bands 15 mm tall along the top and the bottom, 5 mm in from the edges: stripes 10 mm wide,
# 20 mm apart, leaning 45 deg, clipped square to the band. "MIND YOUR HEAD" engraved filled in
# bold between the bands, 24 mm letters but no wider than 230 mm. Two 4.5 mm holes for M4
# flat-head screws, countersunk 8 mm, on the centre line 10 mm in from each end.

thickness 3 mm
w = 300 mm
h = 100 mm
band_h = 15 mm
margin = 5 mm
stripe = 10 mm
pitch = 20 mm
n = 17          # enough stripes to cover the band's length, its ends clipped

solid sign {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=8)

    hole screws {
        l = Circle(center=(-w / 2 + 10 mm, 0), diameter=4.5)
        r = Circle(center=(w / 2 - 10 mm, 0), diameter=4.5)
    }
    Countersink(screws, diameter=8)

    drawing stripes {
        top_band = Rectangle(center=(0, h / 2 - margin - band_h / 2), width=w - 2 * margin,
                             height=band_h, construction=true)
        bot_band = Rectangle(center=(0, -h / 2 + margin + band_h / 2), width=w - 2 * margin,
                             height=band_h, construction=true)
        for i in range(n) {
            x0 = -w / 2 - band_h + i * pitch
            yt = h / 2 - margin - band_h
            yb = -h / 2 + margin
            st = Intersect(Polygon([(x0, yt), (x0 + stripe, yt), (x0 + stripe + band_h, yt + band_h),
                                    (x0 + band_h, yt + band_h)]), top_band, fill=true)
            sb = Intersect(Polygon([(x0, yb), (x0 + stripe, yb), (x0 + stripe + band_h, yb + band_h),
                                    (x0 + band_h, yb + band_h)]), bot_band, fill=true)
        }
    }

    drawing words {
        t = Text("MIND YOUR HEAD", (0, 0), size=24, font="sans:Bold", fill=true, valign="middle",
                 max_width=230 mm)
    }

    assert body.bb.width == 300 mm and body.bb.height == 100 mm, "sign 300 x 100"
    assert stripes.top_band.bb.height == 15 mm, "bands 15 tall"
    assert body.bb.top - stripes.top_band.bb.top == 5 mm, "bands 5 in from the edge"
    assert screws.r.center.x - screws.l.center.x == 280 mm, "screws 10 in from each end"
    assert words.t.bb.width <= 230 mm, "words no wider than 230"
    assert words.t.bb.top < stripes.top_band.bb.bottom and words.t.bb.bottom > stripes.bot_band.bb.top,
        "words between the bands"
    assert -w / 2 - band_h + (n - 1) * pitch >= w / 2 - margin, "stripes reach the band's far end"
}
