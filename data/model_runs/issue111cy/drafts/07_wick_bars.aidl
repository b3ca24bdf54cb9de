# Request (crafts, candle making): a set of 3 wick-centering bars, 3 mm acrylic, for jars of
# 70, 85 and 100 mm rim diameter. Each bar is 16 mm wide with round ends and 30 mm longer than
# its jar is wide. In its middle a closed slit 12 mm long and 1.5 mm wide holds the wick. On
# the underside two notches 5 mm wide and 4 mm deep catch the jar's rim so the bar cannot
# slide: each notch's outer side 0.5 mm outside the rim (jar / 2 + 0.5 mm from the middle).
# Each bar has its jar size engraved ("70 mm"), 5 mm letters starting 10 mm right of the
# middle, and a 4 mm hole for hanging it up, its centre jar / 2 + 8 mm left of the middle.
# The three are cut as separate pieces.

thickness 3 mm

jars = [70 mm, 85 mm, 100 mm]

def wick_bar(jar=70 mm) -> solid {
    body = Slot(center=(0, 0), length=jar + 30 mm, width=16 mm)
    hole wick {
        s = Slot(center=(0, 0), length=12 mm, width=1.5 mm)
    }
    hole notches {
        left = Rectangle(center=(-(jar / 2 + 0.5 mm - 2.5 mm), -8 mm), width=5 mm, height=8 mm)
        right = Rectangle(center=(jar / 2 + 0.5 mm - 2.5 mm, -8 mm), width=5 mm, height=8 mm)
    }
    hole hang {
        c = Circle(center=(-(jar / 2 + 8 mm), 0), diameter=4 mm)
    }
    drawing label {
        t = Text(f"{jar:.0f} mm", position=(10 mm, 0), size=5 mm, anchor="start",
                 valign="middle")
    }
}

assembly wick_bars {
    for i in range(3) {
        bar = wick_bar(jar=jars[i])
    }
    Below(bar[1], bar[0], gap=6 mm)
    Below(bar[2], bar[1], gap=6 mm)
    AlignLeft(bar[1], bar[0])
    AlignLeft(bar[2], bar[0])

    # the request's numbers
    assert len(bar) == 3, "3 bars"
    assert bar[0].body.length == 100 mm and bar[1].body.length == 115 mm and
        bar[2].body.length == 130 mm, "30 mm longer than the jar"
    assert bar[0].body.width == 16 mm, "16 mm wide"
    assert bar[2].wick.s.length == 12 mm and bar[2].wick.s.width == 1.5 mm, "12 x 1.5 slit"
    assert abs(bar[2].wick.s.center.x - bar[2].body.center.x) < 0.01 mm, "slit in the middle"
    assert bar[0].notches.right.bb.right - bar[0].body.center.x == 35.5 mm and
        bar[0].body.center.x - bar[0].notches.left.bb.left == 35.5 mm, "70 mm jar's notches"
    assert bar[2].notches.right.bb.right - bar[2].body.center.x == 50.5 mm, "100 mm jar's"
    assert bar[1].body.bb.bottom - bar[1].notches.left.bb.top == -4 mm, "notches 4 mm deep"
    assert bar[1].notches.left.bb.width == 5 mm, "notches 5 mm wide"
    assert bar[1].body.center.x - bar[1].hang.c.center.x == 85 mm / 2 + 8 mm, "hang hole"
    assert bar[1].hang.c.diameter == 4 mm, "4 mm hang hole"
    assert bar[0].label.t.position.x - bar[0].body.center.x == 10 mm, "label 10 mm right"
    assert bar[0].label.t.bb.left > bar[0].wick.s.bb.right + 2 mm, "label clear of the slit"
    assert bar[2].label.t.bb.right < bar[2].body.bb.right - 8 mm, "label on the bar"
}
