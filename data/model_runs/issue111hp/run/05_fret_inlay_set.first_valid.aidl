# Request (music): fret-marker inlays for a guitar neck I am building, and the router
# templates to pocket them. Inlays cut from 1.5 mm pearl acrylic (kerf 0.1 mm): four 6 mm
# dots (frets 3, 5, 7, 9) and a 5-point star for fret 12, its sharp tips on a 14 mm circle,
# notches on a 6 mm circle, its tips rounded to the 1/8 in (3.175 mm) bit's radius so it
# fits the routed pocket. Templates in 6 mm clear acrylic, 80 x 50 mm with 5 mm corners,
# one for the dots and one for the star, for a trim router with a 7.94 mm guide bush and the
# 1/8 in bit: each opening is its inlay grown by (7.94 - 3.175) / 2 mm, in the middle of
# the plate. Engraved on each template: the fretboard's centre line (stopping 4 mm short of
# the opening and of the plate's ends), a tick on the opening's centre above it, and a
# label saying the inlay, bush and bit, 3.5 mm tall, at most 70 mm wide.

kerf 0.1 mm

bush = 7.94 mm
bit = 3.175 mm
grow = (bush - bit) / 2

def dot() -> solid {
    thickness 1.5 mm
    c = Circle(center=(0, 0), diameter=6)
}

def star_inlay() -> solid {
    thickness 1.5 mm
    s = Star(center=(0, 0), points=5, outer_radius=7, inner_radius=3, tip_radius=bit / 2)
}

def router_template(star=false, label="6 MM DOT") -> solid {
    thickness 6 mm
    plate = RoundedRectangle(center=(0, 0), width=80, height=50, corner_radius=5)
    hole opening {
        if star {
            s = Star(center=(0, 0), points=5, outer_radius=7, inner_radius=3,
                     tip_radius=bit / 2, construction=true)
            o = Offset(s, grow)
        } else {
            c = Circle(center=(0, 0), diameter=6, construction=true)
            o = Offset(c, grow)
        }
    }
    drawing marks {
        r = 7 + grow + 4 if star else 3 + grow + 4
        left = Line((-36, 0), (-r, 0))
        right = Line((r, 0), (36, 0))
        tick = Line((0, r), (0, 22))
        words = Text(label + " / BUSH 7.94 / BIT 1/8", position=(0, -20), size=3.5,
                     max_width=70)
    }
}

assembly inlay_kit {
    for i in range(4) {
        d = dot()
        d.bb.center == (i * 10, 0)
    }
    st = star_inlay()
    st.bb.center == (50, 0)

    dot_tpl = router_template(star=false, label="6 MM DOT")
    star_tpl = router_template(star=true, label="STAR 14")
    dot_tpl.bb.center == (20, -45)
    star_tpl.bb.center == (110, -45)

    # the request's numbers
    assert len(d) == 4, "four dots"
    assert d[0].c.diameter == 6 mm, "6 mm dots"
    assert st.s.outer_radius == 14 mm / 2 and st.s.inner_radius == 6 mm / 2, "star 14 / 6"
    assert st.s.tip_radius == 3.175 mm / 2, "star tips at the bit's radius"
    assert dot_tpl.plate.bb.width == 80 mm and dot_tpl.plate.bb.height == 50 mm, "templates 80 x 50"
    assert dot_tpl.opening.bb.width == 6 mm + 7.94 mm - 3.175 mm, "dot opening grown for bush and bit"
    assert star_tpl.opening.o.bb.width - st.s.bb.width == 7.94 mm - 3.175 mm,
        "star opening grown for bush and bit"
    assert abs(dot_tpl.opening.bb.center_x - dot_tpl.plate.bb.center_x) < 0.01 mm and
        abs(dot_tpl.opening.bb.center_y - dot_tpl.plate.bb.center_y) < 0.01 mm,
        "opening in the middle"
    assert dot_tpl.marks.words.bb.width <= 70 mm, "label at most 70 wide"
    assert distance(dot_tpl.marks.words, dot_tpl.opening) >= 2 mm, "label clear of the opening"
    assert distance(star_tpl.marks.words, star_tpl.opening) >= 2 mm, "label clear of the star"
    assert distance(star_tpl.marks.left, star_tpl.opening) >= 3.9 mm, "centre line 4 short"
}
