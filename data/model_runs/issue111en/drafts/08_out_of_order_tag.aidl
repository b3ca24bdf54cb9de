# Request: a reusable "OUT OF ORDER" tag to cable-tie onto broken machines in our makerspace,
# 3 mm red acrylic, 120 x 180 mm with R8 corners. Two 5 mm holes for a cable tie, 40 mm
# apart, 12 mm below the top edge. Under them a warning triangle (base 44, height 38, a 3.5 mm
# border filled-engraved round it) with a bold "!" 20 mm tall filled in it, centred 48 mm
# above the tag's middle. "OUT OF" and "ORDER" cut through as bold stencil letters 18 mm tall
# (baselines 8 mm above and 16 mm below the middle), then "DO NOT USE" filled-engraved 7 mm.
# At the bottom three write-on lines, 13 mm apart, the lowest 14 mm above the bottom edge,
# each with its label engraved at its left end: DATE, BY, FAULT (4 mm), lines to 10 mm from
# the right edge.

thickness 3 mm

W = 120 mm
H = 180 mm

solid tag {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=8)
    Fixed(body)
    hole tie {
        left = Circle(center=(-20, H / 2 - 12 mm), diameter=5)
        right = Circle(center=(20, H / 2 - 12 mm), diameter=5)
    }
    drawing symbol {
        # FIX after the first valid program: the triangle's border (down to 25.5 above the
        # middle) ran into the top of "OUT OF" (up to 26; W0505): triangle 40 x 34, centred
        # 52 up, so its border ends 31.5 up and 3 mm under the tie holes
        tri = Triangle(center=(0, 52), base=40, height=34, construction=true)
        border = Shell(tri, 3.5, fill=true)
        bang = Text("!", position=(0, 48), size=18, font="sans:Bold", valign="middle",
                    fill=true)
    }
    hole words {
        line1 = Text("OUT OF", position=(0, 8), size=18, font="sans:Bold", stencil=true)
        line2 = Text("ORDER", position=(0, -16), size=18, font="sans:Bold", stencil=true)
    }
    drawing notes {
        warn = Text("DO NOT USE", position=(0, -32), size=7, font="sans:Bold",
                    valign="middle", fill=true)
        for i in range(3) {
            y = -H / 2 + 14 mm + (2 - i) * 13 mm
            label = Text(["DATE", "BY", "FAULT"][i], position=(-W / 2 + 10 mm, y + 1 mm),
                         size=4, anchor="start")
            # FIX after the first valid program: FAULT's T touched its rule (no message):
            # rules start 30 mm from the left edge
            rule = Line((-W / 2 + 30 mm, y), (W / 2 - 10 mm, y))
        }
    }
    assert body.width == 120 mm and body.height == 180 mm
    assert tie.right.center.x - tie.left.center.x == 40 mm, "tie holes 40 apart"
    assert body.bb.top - tie.left.center.y == 12 mm, "12 below the top"
    assert symbol.tri.center.y - body.bb.center_y == 52 mm
    assert symbol.border.bb.bottom > words.line1.bb.top + 3 mm, "triangle clear of the words"
    assert tie.left.bb.bottom - symbol.border.bb.top >= 2 mm, "triangle clear of the ties"
    assert words.line1.position.y - body.bb.center_y == 8 mm
    assert body.bb.center_y - words.line2.position.y == 16 mm
    assert notes.rule[2].start.y - body.bb.bottom == 14 mm, "lowest line 14 up"
    assert notes.rule[0].start.y - notes.rule[1].start.y == 13 mm, "13 apart"
    assert body.bb.right - notes.rule[0].end.x == 10 mm
    assert words.bb.width <= W - 10 mm, "words fit across"
}
