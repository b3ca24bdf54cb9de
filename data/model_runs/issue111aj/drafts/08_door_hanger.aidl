# Request (signs): a "DO NOT DISTURB" door hanger, 3 mm ply. 95 x 240 mm, the top a half
# circle (R47.5), bottom corners R10. A 38 mm hole for the door knob, concentric with the
# round top, and a 4 mm slit from the hole out through the right edge (for lever handles).
# The words cut through as stencil letters (bold sans, bridged counters): "DO NOT" with its
# middle 140 mm up from the bottom and "DISTURB" at 112 mm, 16 mm high, each at most 80 mm
# wide. Below them, engraved: a crescent moon (tips at x -14, 12 mm either side of y 55,
# outer edge through x -34, inner through x -24) and three five-point stars (R7, R5, R4).

thickness 3 mm

param w = 95 mm, min = 80 mm, max = 120 mm
h = 240 mm
knob_d = 38 mm

solid hanger {
    body = RoundedRectangle(bottom_left=(-w / 2, 0), width=w, height=h - w / 2,
                            corner_radii=[0, 0, 10, 10])
    top = Circle(center=(0, h - w / 2), radius=w / 2)
    hole knob {
        c = Circle(center=(0, h - w / 2), diameter=knob_d)
        slit = Rectangle(start=(0, h - w / 2), end=(w / 2 + 1, h - w / 2), width=4)
    }
    hole words {
        a = Text("DO NOT", position=(0, 140), size=16, valign="middle", font="sans:Bold",
                 stencil=true, max_width=80)
        b = Text("DISTURB", position=(0, 112), size=16, valign="middle", font="sans:Bold",
                 stencil=true, max_width=80)
    }
    drawing art {
        outer = Arc(start=(-14, 67), through=(-34, 55), end=(-14, 43))
        inner = Arc(start=(-14, 67), through=(-24, 55), end=(-14, 43))
        s1 = Star(center=(12, 62), points=5, outer_radius=7, inner_radius=3)
        s2 = Star(center=(30, 46), points=5, outer_radius=5, inner_radius=2)
        s3 = Star(center=(8, 36), points=5, outer_radius=4, inner_radius=1.7)
    }
    assert body.bb.width == 95 mm and top.bb.top - body.bb.bottom == 240 mm, "95 x 240"
    assert knob.c.diameter == 38 mm, "38 mm knob hole"
    assert words.a.bb.width <= 80 mm and words.b.bb.width <= 80 mm, "words at most 80 wide"
    assert knob.c.center.y - knob.c.radius - words.a.bb.top >= 10 mm, "the words clear the knob hole"
}
