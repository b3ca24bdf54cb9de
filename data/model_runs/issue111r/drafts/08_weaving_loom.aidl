# Crafts: a frame loom for weaving, 6 mm plywood, 200 x 260 mm outside, corners R8;
# a 150 x 180 mm window centred, corners R5; warp notches in the top and bottom edges:
# 29 each, 2 mm wide and 6 mm deep, 5 mm apart, centred left-right (140 mm from first
# to last); "WEAVE" engraved 6 mm tall, centred in the bottom rail (baseline 12 mm
# above the bottom edge).
thickness 6 mm

param notches = 29, min = 11, max = 35
param pitch = 5 mm, min = 4 mm, max = 8 mm

solid loom {
    body = RoundedRectangle(center=(0, 0), width=200, height=260, corner_radius=8)

    hole window {
        w = RoundedRectangle(center=(0, 0), width=150, height=180, corner_radius=5)
    }
    CenterInside(window, body)

    hole top_notch {
        r = Rectangle(center=(0, 0), width=2, height=6)
    }
    tops = LinearPattern(top_notch, notches, (pitch, 0))
    top_notch.r.center.x == body.center.x - (notches - 1) * pitch / 2
    top_notch.r.top.midpoint.y == body.bb.top

    hole bottom_notch {
        r = Rectangle(center=(0, 0), width=2, height=6)
    }
    bottoms = LinearPattern(bottom_notch, notches, (pitch, 0))
    bottom_notch.r.center.x == body.center.x - (notches - 1) * pitch / 2
    bottom_notch.r.bottom.midpoint.y == body.bb.bottom

    drawing label {
        t = Text("WEAVE", (0, 0), size=6)
    }
    AlignCenterX(label, body)
    label.t.position.y == body.bb.bottom + 12 mm

    assert body.bb.width == 200 mm and body.bb.height == 260 mm, "200 x 260 frame"
    assert window.w.width == 150 mm and window.w.height == 180 mm, "150 x 180 window"
    assert len(tops) == 29 and len(bottoms) == 29, "29 notches top and bottom"
    assert tops[28].r.center.x - tops[0].r.center.x == 140 mm, "140 first to last"
    assert top_notch.r.height == 6 mm and top_notch.r.width == 2 mm, "2 x 6 notches"
    assert window.bb.bottom - body.bb.bottom == 40 mm, "40 mm rails"
}
