# Request (signs): a folding A-frame "CAUTION / WET FLOOR" floor sign for a cafe, two identical
# panels of 6 mm birch ply, 280 x 520 mm, top corners rounded 30 mm. Each panel has a 100 x 30 mm
# hand slot centred 45 mm below the top; two 6 mm hinge holes 20 mm below the top and 40 mm in
# from the sides (the panels are tied together there with cord); two 6 mm holes for the
# restraining cord 90 mm above the bottom, 15 mm in from the sides. Engraved: a warning triangle
# (140 mm base, 120 mm tall, its border 8 mm wide inside the outline, sharp corners) centred
# 110 mm above the panel's centre with a filled bold "!" 70 mm tall in it; "CAUTION" in filled
# bold letters 40 mm tall centred on the panel's centre line; "WET FLOOR" filled bold 34 mm tall
# 70 mm below it; both words at least 15 mm in from the sides. Panels side by side, 10 mm apart.
# (After attempt 1, my request's own clash: CAUTION up to 40 mm, as large as the 15 mm margins
# allow; the "!" 56 mm tall, centred 95 mm above the panel's centre, to clear the border.)

thickness 6 mm

param w = 280 mm, min = 220 mm, max = 400 mm
param h = 520 mm, min = 400 mm, max = 700 mm

def panel() -> solid {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radii=[30, 30, 0, 0])
    hole handle {
        s = Slot(center=(0, h / 2 - 45), length=100, width=30)
    }
    for sx in [-1, 1] {
        hole hinge {
            c = Circle(center=(sx * (w / 2 - 40), h / 2 - 20), diameter=6)
        }
        hole cord {
            c = Circle(center=(sx * (w / 2 - 15), -h / 2 + 90), diameter=6)
        }
    }
    drawing symbol {
        tri = Triangle(center=(0, 110), base=140, height=120, construction=true)
        border = Shell(tri, -8, join="miter")
        # FIX after the first valid program: a drawing fills only Text, so the 8 mm border came
        # out as two hairlines; hatch it with engraved lines 0.5 mm apart clipped to the band
        for i in range(241) {
            hatch = Intersect(Line((-80, 50 + 0.5 * i), (80, 50 + 0.5 * i)), border)
        }
        # attempt 1: W0513, a 70 mm "!" came 2.32 mm from the border near the apex: 56 mm, lower
        bang = Text("!", position=(0, 95), size=56, font="sans:Bold", valign="middle", fill=true)
        # FIX after the first valid program: W0513 on the hatch (9.83 mm, wants a quarter of the
        # size, 14 mm) is a false alarm: the "!" clears the band as it cleared its outline
        # (`AllowOverlap(bang, hatch)` here kept the W0513 and added W0523 "allows nothing";
        # naming the drawing, as `aidl explain W0513` offers, is below in the panel)
    }
    # `AllowOverlap(symbol)` (and `AllowOverlap(symbol.bang, symbol.hatch[156])`) also kept the
    # W0513 and added W0523: the false alarm on the hatch cannot be silenced; it stays, known
    drawing words {
        top = Text("CAUTION", position=(0, 0), size=40, font="sans:Bold", valign="middle",
                   fill=true, max_width=w - 30)
        bottom = Text("WET FLOOR", position=(0, -70), size=34, font="sans:Bold", valign="middle",
                      fill=true, max_width=w - 30)
    }
}

assembly floor_sign {
    front = panel()
    back = panel()
    RightOf(back, front, gap=10)
    AlignBottom(back, front)

    assert front.body.bb.width == 280 mm and front.body.bb.height == 520 mm, "panel 280 x 520"
    assert front.body.bb.top - front.handle.s.center.y == 45 mm, "hand slot 45 below the top"
    assert front.handle.s.length == 100 mm and front.handle.s.width == 30 mm, "hand slot 100 x 30"
    assert front.body.bb.top - front.hinge[0].c.center.y == 20 mm, "hinge holes 20 below the top"
    assert front.hinge[0].c.center.x - front.body.bb.left == 40 mm, "hinge holes 40 in"
    assert front.cord[1].c.center.y - front.body.bb.bottom == 90 mm, "cord holes 90 up"
    assert front.body.bb.right - front.cord[1].c.center.x == 15 mm, "cord holes 15 in"
    assert front.words.top.bb.left >= front.body.bb.left + 15 mm, "CAUTION 15 in from the side"
    assert front.words.bottom.bb.right <= front.body.bb.right - 15 mm, "WET FLOOR 15 in"
    assert front.words.top.position.y - front.words.bottom.position.y == 70 mm, "WET FLOOR 70 below"
    assert front.symbol.tri.center.y - front.body.center.y == 110 mm, "triangle 110 above centre"
    # attempt 1 failed here: 40 mm letters and 15 mm margins do not both fit a 280 mm panel
    # (W0113: "CAUTION" at 40 mm is 261.1 mm wide), my request's slip; the margin wins
    assert front.words.top.size <= 40 mm, "CAUTION at most 40 tall"
}
