# Request (science): a "proof without words" tray puzzle for Pythagoras' theorem (Bhaskara's
# dissection), for a maths classroom, in 3 mm ply.
# - Four right-triangle pieces with legs a = 60 mm and b = 80 mm (so c = 100 mm), each engraved
#   with a right-angle mark in the right-angle corner and the letters a, b, c by their sides.
# - One 20 x 20 mm square piece (b - a), engraved "b-a".
# - A frame 130 mm wide and 145 mm tall with a square opening c x c plus 0.4 mm clearance, 15 mm
#   from the bottom edge and centred left-right; "a² + b² = c²" engraved filled, 8 mm tall, in the
#   strip above the opening. A plain base of the same outline is glued under the frame.
# - The four triangles and the square fill the opening exactly (hypotenuses on its sides).

thickness 3 mm

param u = 20 mm, min = 10 mm, max = 30 mm
param fit = 0.4 mm, min = 0 mm, max = 1 mm
a = 3 * u
b = 4 * u
c = 5 * u
ow = c + fit
fw = 130 mm
fh = 145 mm
ob = -fh / 2 + 15 mm

def triangle() -> solid {
    t = Polygon([(0, 0), (b, 0), (0, a)])
    drawing marks {
        corner = Polyline([(0, 8), (8, 8), (8, 0)])
        lb = Text("b", (b / 2, 4), size=6)
        la = Text("a", (6, a / 2), size=6, valign="middle")
        # FIX after the first valid program: "c" sat 18 mm in from the hypotenuse, not by it;
        # now 6 mm in from its midpoint, turned along it
        lc = Text("c", (b / 2 - 6 * 3 / 5, a / 2 - 6 * 4 / 5), size=6, valign="middle",
                  rotation=-atan2(3, 4))
    }
}

def inner_square() -> solid {
    s = Rectangle(center=(0, 0), width=b - a, height=b - a)
    drawing mark { w = Text("b-a", (0, 0), size=5, valign="middle") }
}

assembly pythagoras {
    solid frame {
        body = Rectangle(center=(0, 0), width=fw, height=fh)
        hole opening { sq = Rectangle(bottom_left=(-ow / 2, ob), width=ow, height=ow) }
        drawing title {
            eq = Text("a² + b² = c²", (0, (ob + ow + fh / 2) / 2), size=8, font="sans",
                      valign="middle", fill=true)
        }
    }
    solid base {
        body = Rectangle(center=(0, 0), width=fw, height=fh)
    }
    t1 = triangle()
    t2 = triangle()
    t3 = triangle()
    t4 = triangle()
    sq = inner_square()

    # flat for cutting
    RightOf(base, frame, gap=8)
    AlignBottom(base, frame)
    Above(t1, frame, gap=8)
    AlignLeft(t1, frame)
    RightOf(t2, t1, gap=6)
    AlignBottom(t2, t1)
    Above(t3, t1, gap=6)
    AlignLeft(t3, t1)
    RightOf(t4, t3, gap=6)
    AlignBottom(t4, t3)
    RightOf(sq, t4, gap=6)
    AlignBottom(sq, t4)

    # assembled: base, frame on it, the pieces in the opening (Bhaskara's arrangement: each right
    # angle at the inner square's corner, legs b then a toward the square's corners)
    x0 = -c / 2
    y0 = ob + fit / 2
    Place(base, position=(0, 0, 0))
    Place(frame, position=(0, 0, 3))
    Place(t1, position=(x0 + 64 / 100 * c, y0 + 48 / 100 * c, 3), rotation=(0, 0, atan2(-3, -4)))
    Place(t2, position=(x0 + 52 / 100 * c, y0 + 64 / 100 * c, 3), rotation=(0, 0, atan2(-3, -4) + 90 deg))
    Place(t3, position=(x0 + 36 / 100 * c, y0 + 52 / 100 * c, 3), rotation=(0, 0, atan2(-3, -4) + 180 deg))
    Place(t4, position=(x0 + 48 / 100 * c, y0 + 36 / 100 * c, 3), rotation=(0, 0, atan2(-3, -4) + 270 deg))
    # FIX after the first valid program: the inner square's sides run along the legs, at
    # atan2(3, 4) (36.87 deg), not atan2(4, 3) (W0517: it collided with all four triangles)
    Place(sq, position=(0, y0 + c / 2, 3), rotation=(0, 0, atan2(3, 4)))

    # the request's numbers
    assert a == 60 mm and b == 80 mm, "legs 60 and 80"
    assert abs(distance(t1.t.points[1], t1.t.points[2]) - 100 mm) < 0.001 mm, "hypotenuse 100"
    assert sq.s.width == 20 mm, "20 mm square"
    assert frame.opening.sq.width == 100 mm + 0.4 mm, "opening c + 0.4"
    assert frame.body.bb.width == 130 mm and frame.body.bb.height == 145 mm, "frame 130 x 145"
    assert frame.opening.sq.bb.bottom - frame.body.bb.bottom == 15 mm, "opening 15 from the bottom"
    assert 4 * (a * b / 2) + (b - a) ** 2 == c ** 2, "the pieces fill the square"
}
