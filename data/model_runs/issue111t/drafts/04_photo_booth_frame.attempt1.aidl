# Parties: photo-booth frame, 5 mm plywood. Outer 400 x 300 mm, corners R20. Window 320 x 200
# mm, corners R10, centred left-right, its top 25 mm below the frame's top. In the band below
# the window: "PARTY TIME" in sans Bold 30 mm tall, engraved as letter outlines, centred in
# the band; a five-point star cut-out (outer radius 14 mm, inner 6 mm) on each side, its
# centre 30 mm in from the frame's side, centred in the band's height.
thickness 5 mm

solid frame {
    body = RoundedRectangle(center=(0, 0), width=400, height=300, corner_radius=20)
    hole window {
        w = RoundedRectangle(center=(0, 0), width=320, height=200, corner_radius=10)
    }
    AlignCenterX(window, body)
    window.bb.top == body.bb.top - 25 mm

    band = Rectangle(corner=(-200, -150), opposite=(200, -75), construction=true)
    drawing words {
        t = Text("PARTY TIME", (0, -112.5), size=30, valign="middle", font="sans:Bold")
    }
    CenterInside(words, band)

    hole stars {
        l = Star(center=(-170, -112.5), points=5, outer_radius=14, inner_radius=6)
        r = Star(center=(170, -112.5), points=5, outer_radius=14, inner_radius=6)
    }
    AlignCenterY(stars, band)

    assert body.bb.width == 400 mm and body.bb.height == 300 mm, "400 x 300"
    assert window.w.bb.width == 320 mm and window.w.bb.height == 200 mm, "window 320 x 200"
    assert body.bb.top - window.bb.top == 25 mm, "window 25 below the top"
    assert band.bb.top == window.bb.bottom, "band is below the window"
    assert words.t.size == 30 mm, "30 mm letters"
    assert stars.l.center.x - body.bb.left == 30 mm, "star 30 in from the side"
    assert body.bb.right - stars.r.center.x == 30 mm, "star 30 in from the side"
    assert words.bb.left > stars.l.bb.right and words.bb.right < stars.r.bb.left, "text clears the stars"
}
