"""The example program of each `aidl docs` topic (:mod:`aidl_lang.library.reference` shows it under the
topic's text; ``tests/test_reference.py`` compiles every one, clean): a shape, a constraint, an
operation or a statement, each in the smallest part that shows it; and the arguments or whole
programs of the stdlib templates' examples where the default one would mislead.  Plain
strings, nothing compiled here."""
from __future__ import annotations

from ..geometry.derived.scaling import EXAMPLE_LINES as _TRANSFORM_LINES


def _indent(text: str, pad: str) -> str:
    return "\n".join(pad + ln if ln.strip() else ln for ln in text.splitlines())


_PLATE2 = """solid plate {{
    body = Rectangle(center=(0, 0), width=60, height=30)
    hole left {{ c = Circle(center=(-15, 0), radius=4) }}
    hole right {{ c = Circle(center=(15, 3), radius=4) }}
    Fixed(body)
    {line}
}}
"""
_QUAD = """solid quad {{
    a = Line((0, 0), (40, 0))
    b = Line(start=a.end, end=(45, 20))
    c = Line(start=b.end, end=(0, 25))
    d = Line(start=c.end, end=a.start)
    Fixed(a.start)
    {line}
}}
"""
_SIGN = """solid sign {{
    solid post {{ r = Rectangle(center=(0, 0), width=6, height=40) }}
    solid board {{ r = Rectangle(center=(0, 30), width=50, height=20) }}
    Fixed(post)
    {line}
}}
"""
_HOLES = """solid plate {{
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole h {{ c = Circle(center=(-20, -10), radius=2) }}
    axis = Line((0, -20), (0, 20), construction=true)
    Fixed(body)
    {line}
}}
"""


def _solid(body: str, name: str = "part") -> str:
    return f"solid {name} {{\n" + _indent(body.strip("\n"), "    ") + "\n}\n"


EXAMPLES: dict[str, str] = {
    "Point": _solid("body = Rectangle(center=(0, 0), width=20, height=10)\n"
                    "p = Point(5, 2)\nCoincident(p, body.top_right)"),
    "Line": _solid("a = Line((0, 0), (40, 0))\nb = Line(start=a.end, end=(0, 20))\n"
                   "c = Line(start=b.end, end=a.start)    # three lines close a triangle",
                   "wedge"),
    "Circle": _solid("c = Circle(center=(0, 0), diameter=20)", "disc"),
    "Arc": _solid("a = Arc(center=(0, 0), radius=20, start_angle=0 deg, end_angle=90 deg)\n"
                  "l1 = Line(start=a.center, end=a.start)\nl2 = Line(start=a.end, "
                  "end=a.center)    # a quarter disc", "fan"),
    "Rectangle": _solid("r = Rectangle(center=(0, 0), width=40, height=20, rotation=15 deg)",
                        "plate"),
    "RoundedRectangle": _solid("r = RoundedRectangle(center=(0, 0), width=40, height=20, "
                               "corner_radius=4)", "plate"),
    "Triangle": _solid("t = Triangle(center=(0, 0), base=30, height=20)   # apex up", "sign"),
    "Trapezoid": _solid("t = Trapezoid(center=(0, 0), bottom_width=40, top_width=20, "
                        "height=15)", "block"),
    "Ellipse": _solid("e = Ellipse(center=(0, 0), rx=20, ry=10, rotation=30 deg)", "egg"),
    "Polygon": _solid("p = Polygon([(0, 0), (30, 0), (30, 10), (10, 20)])   # rigid: keeps "
                      "its shape", "bracket"),
    "Spline": _solid("s = Spline([(0, 0), (20, 10), (40, 0), (20, -10)], closed=true)\n"
                     "tip = Spline([(30, 0), (50, 10), (70, 0), (50, -10)], closed=true, "
                     "corners=[0, 2])    # pointed at points 0 and 2", "leaf"),
    "Bezier": _solid("b = Bezier(points=[(0, -20), (20, -5), (25, 15), (12, 18), (5, 20), "
                     "(0, 15), (0, 10),\n               (0, 15), (-5, 20), (-12, 18), (-25, 15), "
                     "(-20, -5), (0, -20)],\n               closed=true)    # 4 cubic "
                     "segments: a heart", "heart"),
    "mirror": _solid("half = [(0, -20), (12, -15), (15, 5), (6, 18), (0, 20)]\n"
                     "p = Polygon(mirror(half, about=\"y\"))    # symmetric left and right",
                     "vase"),
    "Polyline": _solid("body = Rectangle(center=(0, 0), width=40, height=20)\nFixed(body)\n"
                       "drawing zigzag {\n    z = Polyline([(-15, -5), (-5, 5), (5, -5), "
                       "(15, 5)])\n}\nCoincident(zigzag.z.start, (-15, -5))", "plate"),
    "Sector": _solid("pie = Sector(center=(0, 0), radius=30, start_angle=0 deg, end_angle=120 deg)\n"
                     "Fixed(pie)\nhole window {\n    w = Sector(center=(0, 0), radius=24, "
                     "inner_radius=12, start_angle=20 deg, end_angle=100 deg)\n}\n"
                     "Coincident(window.w.center, pie.center)", "fan"),
    "Stroke": _solid("a = Arc(center=(0, 8), radius=8, start_angle=-90 deg, end_angle=90 deg)\n"
                     "b = Arc(center=(0, -8), radius=8, start_angle=90 deg, end_angle=270 deg)\n"
                     "s = Stroke([a, b], width=3)    # an S, 3 mm wide, round ends", "hook"),
    "Drawing2D": _solid("board = Drawing2D(\"std/drawings/pcb_board.dxf\", layer=\"Edge.Cuts\", "
                        "construction=true)\nbody = Offset(board.outlines[0], 3)   # the "
                        "outline + 3 mm\nfor c in board.circles {\n    hole h { p = Circle("
                        "center=(0, 0), radius=1.7) }\n    Concentric(h.p, c)\n}", "lid"),
    "RegularPolygon": _solid("nut = RegularPolygon(center=(0, 0), across_flats=13, sides=6)\n"
                             "# or by its edge: RegularPolygon(center=(0, 0), side=7.5, sides=6)",
                             "hexagon"),
    "Slot": _solid("body = Rectangle(center=(0, 0), width=50, height=20)\n"
                   "hole slot { s = Slot(center=(0, 0), length=30, width=6) }", "plate"),
    "ArcSlot": _solid("disc = Circle(center=(0, 0), radius=30)\n"
                      "hole track { a = ArcSlot(center=(0, 0), radius=20, start_angle=30 deg, "
                      "end_angle=150 deg, width=5) }\nFixed(disc)\ntrack.a.center == disc.center", "dial"),
    "Star": _solid("s = Star(center=(0, 0), points=5, outer_radius=20, inner_radius=8)",
                   "badge"),
    "Offset": _solid("s = Star(center=(0, 0), points=5, outer_radius=20, inner_radius=8)\n"
                     "o = Offset(s, 3)    # the star grown by 3 mm, rounded", "badge"),
    "Inset": _solid("body = Rectangle(center=(0, 0), width=40, height=30)\n"
                    "hole window {\n    r = Rectangle(center=(0, 0), width=40, height=30)\n"
                    "    w = Inset(r, 5)\n    Fixed(r)\n}\nFixed(body)", "frame"),
    "Shell": _solid("c = Circle(center=(0, 0), radius=20)\nw = Shell(c, 3)    # a ring 3 mm "
                    "wide around the circle", "ring"),
    "Hull": _solid("a = Circle(center=(0, 0), radius=10)\nb = Circle(center=(30, 0), "
                   "radius=5)\nh = Hull(a, b)", "cam"),
    "Intersect": _solid("a = Circle(center=(0, 0), radius=30)\nb = Circle(center=(30, 0), "
                        "radius=30)\nk = Intersect(a, b)    # the lens both circles cover",
                        "lens"),
    "Text": _solid("body = RoundedRectangle(center=(0, 0), width=50, height=20, "
                   "corner_radius=3)\ndrawing label {\n    t = Text(\"AIDL\", position=(0, -3), "
                   "size=7, valign=\"middle\")\n    ring = Circle(center=(0, -46), radius=49, "
                   "construction=true)\n    top = Text(\"TOP\", along=ring, size=3)    # on "
                   "the circle's top, upright\n}\nFixed(body)\nCenterInside(label, body)",
                   "tag"),
    # geometric constraints
    "Coincident": _solid("a = Rectangle(center=(0, 0), width=20, height=10)\n"
                         "b = Rectangle(center=(25, 5), width=10, height=10)\n"
                         "Fixed(a)\nCoincident(b.bottom_left, a.bottom_right)", "step"),
    "Horizontal": _PLATE2.format(line="Fixed(left)\n    Horizontal(left.c.center, right.c.center)    "
                                 "# right moves to y = 0\n    Distance(left.c.center, right.c.center, 30)"),
    "Vertical": _PLATE2.format(line="Fixed(right)\n    Vertical(left.c.center, right.c.center)    "
                               "# left moves to x = 15\n    Distance(left.c.center, right.c.center, 10)"),
    "Fixed": _PLATE2.format(line="Fixed(left)    # holds a point, shape or structure"),
    "Distance": _PLATE2.format(line="Fixed(left)\n    Distance(left.c.center, right.c.center, 36)\n"
                               "    Horizontal(left.c.center, right.c.center)"),
    "HorizontalDistance": _PLATE2.format(
        line="Fixed(left)\n    HorizontalDistance(left.c.center, right.c.center, 30)\n"
             "    VerticalDistance(left.c.center, right.c.center, 5)"),
    "VerticalDistance": _PLATE2.format(
        line="Fixed(left)\n    VerticalDistance(left.c.center, right.c.center, 5)    # "
             "right 5 mm higher\n    HorizontalDistance(left.c.center, right.c.center, 30)"),
    "At": _PLATE2.format(line="Fixed(left)\n    At(right.c.center, left.c.center, dx=30, dy=0)"),
    "Length": _QUAD.format(line="Length(a, 50)"),
    "Radius": _solid("a = Arc(center=(0, 0), start=(20, 0), end=(0, 20))\n"
                     "l1 = Line(start=a.center, end=a.start)\nl2 = Line(start=a.end, "
                     "end=a.center)\nFixed(a.center)\nRadius(a, 25)", "fan"),
    "Diameter": _solid("a = Arc(center=(0, 0), start=(20, 0), end=(0, 20))\n"
                       "l1 = Line(start=a.center, end=a.start)\nl2 = Line(start=a.end, "
                       "end=a.center)\nFixed(a.center)\nDiameter(a, 50)", "fan"),
    "Equal": _QUAD.format(line="Equal(a, c)    # same length"),
    "Parallel": _QUAD.format(line="Parallel(a, c)"),
    "Perpendicular": _QUAD.format(line="Perpendicular(a, d)"),
    "Tangent": _solid("c = Circle(center=(0, 0), radius=10)\n"
                      "r = Rectangle(center=(0, 0), width=30, height=10)\n"
                      "Fixed(c)\nTangent(r.bottom, c)    # r's bottom edge touches the circle's "
                      "bottom\nAlignCenterX(r, c)", "cam"),
    "Symmetric": _PLATE2.format(line="axis = Line((0, -15), (0, 15), construction=true)\n"
                                "    Fixed(left)\n    Symmetric(left.c.center, right.c.center, "
                                "axis)    # right moves to (15, 0)"),
    "Midpoint": _HOLES.format(line="Midpoint(h.c.center, body.bottom)    # a notch"),
    "OnLine": _HOLES.format(line="OnLine(h.c.center, axis)    # h moves to x = 0\n"
                           "    h.c.center.y == -10"),
    "OnCircle": _HOLES.format(line="pitch = Circle(center=(0, 0), radius=12, "
                              "construction=true)\n    OnCircle(h.c.center, pitch)\n"
                              "    h.c.center.y == -10"),
    "Collinear": _PLATE2.format(line="Fixed(left)\n    Collinear(left.c.center, right.c.center, "
                                "body.center)\n    HorizontalDistance(left.c.center, right.c.center, 30)"),
    "Concentric": _solid("disc = Circle(center=(0, 0), diameter=60)\n"
                         "hole bore { c = Circle(center=(3, 2), diameter=20) }\n"
                         "Concentric(bore.c, disc)", "flange"),
    "Angle": _QUAD.format(line="Angle(a, d, 80 deg)"),
    # structural relations
    "Above": _SIGN.format(line="Above(board, post)\n    AlignCenterX(board, post)"),
    "Below": _SIGN.format(line="Below(post, board)\n    AlignCenterX(board, post)"),
    "LeftOf": _SIGN.format(line="LeftOf(board, post, gap=-5)   # overlapping by 5 mm\n"
                           "    AlignTop(board, post)"),
    "RightOf": _SIGN.format(line="RightOf(board, post, gap=-5)\n    AlignTop(board, post)"),
    "Gap": "assembly kit {\n    solid a { r = Rectangle(center=(0, 0), width=20, height=20) }\n"
           "    solid b { r = Rectangle(center=(30, 0), width=20, height=20) }\n"
           "    Fixed(a)\n    Gap(a, b, 5)    # 5 mm of space along x\n    AlignCenterY(a, b)\n}\n",
    "Inside": _HOLES.format(line="Inside(h, body, margin=5)"),
    "CenterInside": _HOLES.format(line="CenterInside(h, body)"),
    "Taller": _SIGN.format(line="Above(board, post)\n    AlignCenterX(board, post)\n    "
                           "Taller(post, board)"),
    "Wider": _SIGN.format(line="Above(board, post)\n    AlignCenterX(board, post)\n    "
                          "Wider(board, post)"),
    "AlignCenterX": _SIGN.format(line="Above(board, post)\n    AlignCenterX(board, post)"),
    "AlignCenterY": _SIGN.format(line="RightOf(board, post, gap=-3)\n    "
                                 "AlignCenterY(board, post)"),
    "AlignLeft": _SIGN.format(line="Above(board, post)\n    AlignLeft(board, post)"),
    "AlignRight": _SIGN.format(line="Above(board, post)\n    AlignRight(board, post)"),
    "AlignTop": _SIGN.format(line="RightOf(board, post, gap=-3)\n    AlignTop(board, post)"),
    "AlignBottom": _SIGN.format(line="RightOf(board, post, gap=-3)\n    "
                                "AlignBottom(board, post)"),
    # operations
    "assembled": "import \"std/joints.aidl\"\n\nthickness 3 mm\n\n# aidl render FILE --assembled "
                 "-o box.3mf: the six panels folded up\nassembly kit {\n    box = finger_box("
                 "length=120 mm, depth=80 mm, height=50 mm, thickness=3 mm)\n}\n",
    "Place": "thickness 3 mm\n\nassembly kit {\n    solid base { r = Rectangle(center=(0, 0), "
             "width=60, height=40) }\n    solid wall { r = Rectangle(center=(0, 15), width=60, "
             "height=30) }\n    # stood up on the base's back edge, its top face (engraving, "
             "countersinks) to the front\n    Place(wall, position=(0, 20, 3), face=\"front\", "
             "up=\"up\")\n    # the same: rotation=(90 deg, 0, 0)\n}\n",
    "Bend": "thickness 3 mm\n\nassembly kit {\n    solid base { r = Rectangle(center=(0, 0), "
            "width=60, height=40) }\n    solid wall { r = Rectangle(center=(10, 60), width=80, "
            "height=30) }\n    # stood on the base's front edge, its top face inward\n"
            "    Place(wall, rotation=(90 deg, 0, 180 deg), position=(0, -20, -42))\n"
            "    # assembled, bent inward by 90 deg at x = 20 round a 2 mm inside radius\n"
            "    Bend(wall, at=20, angle=90 deg, radius=2)\n}\n",
    "Mirrored": _HOLES.format(line="m = Mirrored(h, axis)    # a copy at (20, -10)"),
    **{k: _HOLES.format(line=v) for k, v in _TRANSFORM_LINES.items()},   # Scale, Translate...
    "CutInto": "import \"std/joints.aidl\"\n\nthickness 3 mm\n\nassembly kit {\n"
               "    box = finger_box(length=80 mm, depth=80 mm, height=50 mm)\n"
               "    hole lid_hole { c = Circle(center=(0, 0), diameter=20) }\n"
               "    CenterInside(lid_hole, box.lid)\n"
               "    CutInto(lid_hole, box.lid)    # the lid comes out with the hole\n}\n",
    "LinearPattern": _HOLES.format(line="row = LinearPattern(h, 5, (10, 0))"),
    "CircularPattern": _solid("disc = Circle(center=(0, 0), diameter=60)\n"
                              "hole bolt { c = Circle(center=(20, 0), diameter=5) }\n"
                              "Fixed(disc)\nFixed(bolt)\n"
                              "ring = CircularPattern(bolt, 6, (0, 0))", "flange"),
    "GridPattern": _HOLES.format(line="grid = GridPattern(h, 3, 5, (10, 10))"),
    "CornerPattern": _solid("body = Rectangle(center=(0, 0), width=60, height=40)\n"
                            "hole h { c = Circle(center=(0, 0), radius=2) }\nFixed(body)\n"
                            "corners = CornerPattern(h, body, 5)", "plate"),
    "Countersink": _solid("body = Rectangle(center=(0, 0), width=60, height=40)\n"
                          "hole h { c = Circle(center=(0, 0), diameter=4.5) }\nFixed(body)\n"
                          "corners = CornerPattern(h, body, 8)\n"
                          "Countersink(corners, diameter=9)    # M4 flat heads: 90 deg cones",
                          "plate"),
    "Counterbore": _solid("body = Rectangle(center=(0, 0), width=60, height=40)\n"
                          "hole h { c = Circle(center=(0, 0), diameter=4.5) }\nFixed(body)\n"
                          "corners = CornerPattern(h, body, 8)\n"
                          "Counterbore(corners, diameter=8, depth=2)    # M4 socket heads",
                          "plate"),
    "Rigid": _solid("body = Rectangle(center=(0, 0), width=40, height=20)\n"
                    "hole pins {\n    a = Circle(center=(-10, 0), radius=3)\n"
                    "    b = Circle(center=(10, 0), radius=3)\n    Rigid(a, b)    # shapes: "
                    "moved together\n}\nFixed(body)\n"
                    "pins.a.center == (-12, 2)    # b moves with a: to (8, 2)\n"
                    "assert pins.b.center == (8, 2)",
                    "plate"),
    "AllowOverlap": _solid("body = Rectangle(center=(0, 0), width=60, height=30)\n"
                           "solid tab {\n    r = Rectangle(center=(30, 0), width=10, "
                           "height=10)\n    hole pin { c = Circle(center=(30, 0), radius=2) }\n"
                           "}\nFixed(body)\nFixed(tab)\n"
                           "AllowOverlap(tab.pin, body)    # body refills half of the pin hole",
                           "plate"),
    "Fillet": _solid("a = Rectangle(center=(0, 0), width=10, height=60)\nb = Rectangle(center=(20, -25"
                     "), width=50, height=10)\nFillet([a.right, b.top], 6)   # the L's inside corner", "hook"),
    "Chamfer": _solid("body = Rectangle(center=(0, 0), width=40, height=20)\nChamfer(3)",
                      "plate"),
    # statements
    "units": "units in\n" + _solid("r = Rectangle(center=(0, 0), width=4, height=2)   "
                                   "# 4 in x 2 in\nhole h { c = Circle(center=(0, 0), "
                                   "radius=5 mm) }", "plate"),
    "import": "import \"std/shapes.aidl\" as shapes\n\n" + _solid(
        "disc = Circle(center=(0, 0), diameter=60)\nbolts = shapes.bolt_circle(count=4, "
        "pcd=45 mm, hole_d=5 mm)\nFixed(disc)\nCenterInside(bolts, self)", "flange"),
    "param": "param width = 40 mm, min=20 mm, max=80 mm, step=1 mm\n\n"
             + _solid("body = Rectangle(center=(0, 0), width=width, height=width / 2)",
                      "plate"),
    "def": "def wheel(r=10 mm, bore=3 mm) -> solid {\n    rim = Circle(center=(0, 0), "
           "radius=r)\n    hole axle { c = Circle(center=(0, 0), radius=bore) }\n"
           "    Concentric(axle.c, rim)\n}\n\nassembly cart {\n    left = wheel(r=12 mm)\n"
           "    right = wheel(8 mm, 2 mm)\n    LeftOf(left, right, gap=5)\n"
           "    AlignCenterY(left, right)\n    left.rim.center == (0, 0)\n}\n",
    "assert": "param width = 280 mm\n\n" + _solid(
        "body = Rectangle(center=(0, 0), width=width, height=100)\nhole bore { c = "
        "Circle(center=(0, 0), radius=4) }\nCenterInside(bore, body)\n"
        "assert body.width <= 300 mm, \"fits the laser bed\"", "plate"),
    "machine": "# aidl render plate.aidl -o plate.gcode --machine router.toml\n"
               "kerf 0.15 mm\nthickness 6 mm\n\n" + _solid(
                   "r = Rectangle(center=(0, 0), width=60, height=40)\n"
                   "hole bore { c = Circle(center=(0, 0), radius=5) }", "plate"),
    "outputs": "# aidl render plate.aidl -o plate.pdf --page A4\n\n"
               + _solid("r = Rectangle(center=(0, 0), width=60, height=40)", "plate"),
    "fonts": _solid("body = Rectangle(center=(0, 0), width=90, height=30)\ndrawing word {    "
                    "# engraved: the letters' area\n    t = Text(\"Ωmega\", position=(0, 0), "
                    "size=14, font=\"sans:Bold\", valign=\"middle\", fill=true)\n}\n"
                    "AlignCenterX(word, body)", "sign"),
    "kerf": "kerf 0.15 mm\n\n" + _solid("r = Rectangle(center=(0, 0), width=60, height=40)",
                                        "plate"),
    "min_wall": "min_wall 0.3 mm    # the tip below is meant sharp\n\n" + _solid(
        "body = Triangle((0, 0), (95.149, 0), (40, 15.482))", "wedge"),
    "lbrn2": "# aidl render plate.aidl -o plate.lbrn2\nkerf 0.15 mm\n\n" + _solid(
        "r = Rectangle(center=(0, 0), width=60, height=40)\nhole bore { c = Circle(center=(0, "
        "0), radius=5) }", "plate"),
    "hpgl": "# aidl render sticker.aidl -o sticker.plt\n\n" + _solid(
        "s = Star(center=(0, 0), points=5, outer_radius=30, inner_radius=12)", "sticker"),
    "thickness": "thickness 3 mm\n\nassembly kit {\n    solid plate { r = Rectangle(center=(0, "
                 "0), width=60, height=40) }\n    solid spacer {\n        thickness 6 mm\n"
                 "        c = Circle(center=(50, 0), radius=8)\n    }\n}\n",
    "solid": "solid plate {\n    body = Rectangle(center=(0, 0), width=60, height=30)\n"
             "    solid boss { c = Circle(center=(-15, 10), radius=8) }  # plate's child: bore "
             "cuts it too\n    hole bore { c = Circle(center=(-15, 10), radius=4) }  # an "
             "opening through body and boss\n}\n",
    "hole": "solid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
            "    hole bore { c = Circle(center=(0, 0), radius=5) }\n"
            "    CenterInside(bore, self)\n}\n",
    "cut": _solid("body = Rectangle(center=(0, 0), width=60, height=30)\n"
                  "cut slits {\n    a = Line((-20, 0), (20, 0))   # a slit, cut once\n"
                  "    b = Line((20, 15), (30, 5))   # edge to edge: the corner is a part\n}\n"
                  "Fixed(body)", "panel"),
    "drawing": _solid("body = Rectangle(center=(0, 0), width=50, height=20)\n"
                      "drawing mark {\n    t = Text(\"A-1\", position=(0, 0), size=6, "
                      "valign=\"middle\")\n    l = Line((-20, -7), (20, -7))\n}\nFixed(body)",
                      "tag"),
    "assembly": "assembly kit {\n    solid base { r = Rectangle(center=(0, 0), width=40, "
                "height=20) }\n    solid lid { r = Rectangle(center=(0, 30), width=40, "
                "height=10) }\n    Above(lid, base, gap=5)\n    AlignCenterX(lid, base)\n}\n",
    "for": _solid("body = Rectangle(center=(0, 0), width=70, height=20)\n"
                  "for i in range(5) {\n    hole vent { s = Slot(center=(-24 + 12 * i, 0), "
                  "length=12, width=3, rotation=90 deg) }\n}\nFixed(body)\n"
                  "vent[0].s.center == (-24, 0)", "grille"),
    "if": "param rounded = true\n\n" + _solid(
        "if rounded {\n    body = RoundedRectangle(center=(0, 0), width=40, height=20, "
        "corner_radius=5)\n} else {\n    body = Rectangle(center=(0, 0), width=40, "
        "height=20)\n}", "plate"),
    "equations": _solid("r = Rectangle(center=(5, 5), width=30, height=8)\n"
                        "c = Circle(center=(30, 3), radius=6)\nr.bottom_left == (0, 0)\n"
                        "c.center == r.bottom_right + (0, 4)\nself.bb.width <= 60", "bracket"),
    "bb": _solid("body = Rectangle(center=(0, 0), width=40, height=20)\n"
                 "hole notch { c = Circle(center=(20, 0), radius=5) }   # pokes out 5 mm\n"
                 "Fixed(body)\nFixed(notch)\n"
                 "assert self.bb.right == 25 mm and body.bb.right == 20 mm", "plate"),
    "comments": "# a plate with a bore\n" + _solid(
        "body = Rectangle(center=(0, 0), width=80 / 3, height=10)   # 26.667 mm wide\n"
        "n = 7 // 2    # floor division: 3, a count\nfor i in range(n) {\n    hole bore { "
        "c = Circle(center=(-8 + 8 * i, 0), radius=2) }\n}\nFixed(body)\n"
        "Fixed(bore[0])\nFixed(bore[1])\nFixed(bore[2])", "plate"),
    "pi": "tilt = 10 deg\n" + _solid("body = Rectangle(center=(0, 0), width=60, height=30, "
                                      "rotation=tilt + pi / 2)   # 100 deg\nfor k in range(6) {\n"
                                      "    hole bolt { c = Circle(center=(10 * cos(k * tau / 6), "
                                      "10 * sin(k * tau / 6)), radius=2) }\n}\nFixed(body)\n"
                                      "Fixed(bolt[0])", "plate"),
    "functions": _solid("for i in range(6) {\n    hole bolt { c = Circle(center=(20 * "
                        "cos(i * 60 deg), 20 * sin(i * 60 deg)), radius=max(2, sqrt(9))) }\n}\n"
                        "disc = Circle(center=(0, 0), radius=30)\nFixed(disc)\n"
                        "Fixed(bolt[0])", "flange"),
}


# arguments of the examples of stdlib templates (the defaults otherwise)
TEMPLATE_ARGS = {"spur_gear": "teeth=24, module=1.5 mm, bore=8 mm",
                 "gear_pair": "teeth1=12, teeth2=24, module=2 mm, bore1=5 mm, bore2=8 mm",
                 "clearance_hole": "size=4", "nut_trap": "size=3",
                 "t_slot": "size=3", "text_on_arc": "text=\"HELLO\", radius=30 mm",
                 "finger_box": "length=80 mm, depth=50 mm, height=40 mm",
                 "mounting_plate": "width=80 mm, height=50 mm, screw=3"}


# the joints hold themselves where (cx, cy) and `rotation` put them, on a panel's edge: their
# examples place them so, never by constraints (which would repeat the template's `Fixed(self)`);
# a t_slot too opens an edge from its mouth at (cx, cy), so its example is not a centred hole
TEMPLATE_EXAMPLES = {
    # the boxes: a hole of the user's own cut into the lid (CutInto; issue 61)
    "finger_box": ("thickness 3 mm\n\nassembly kit {\n"
                   "    box = finger_box(length=80 mm, depth=80 mm, height=50 mm)\n"
                   "    hole lid_hole { c = Circle(center=(0, 0), diameter=20) }\n"
                   "    CenterInside(lid_hole, box.lid)\n"
                   "    CutInto(lid_hole, box.lid)    # a 20 mm hole in the middle of the lid\n}\n"),
    "lid_box": ("thickness 3 mm\n\nassembly kit {\n"
                "    box = lid_box(length=100 mm, width=70 mm, height=40 mm)\n"
                "    hole knob { c = Circle(center=(0, 0), diameter=6) }\n"
                "    CenterInside(knob, box.lid)\n"
                "    CutInto(knob, box.lid)    # a hole for a knob's screw in the lid\n}\n"),
    "cross_halving": ("solid panel {\n    body = Rectangle(center=(0, 0), width=120, height=60)\n"
                      "    # from the middle of the top edge (y = 30), 30 mm down into the panel\n"
                      "    h = cross_halving(depth=30 mm, thickness=3 mm, cx=0 mm, cy=30 mm)\n}\n"),
    "finger_edge": ("solid panel {\n    body = Rectangle(center=(0, 0), width=100, height=60)\n"
                    "    # the top edge (y = 30) cut into fingers; the panel lies below it\n"
                    "    f = finger_edge(length=100 mm, thickness=3 mm, cx=0 mm, cy=30 mm)\n}\n"),
    "tab_and_slot": ("solid panel {\n    body = Rectangle(center=(0, 0), width=60, height=40)\n"
                     "    # two tabs and a captive-nut T-slot on the top edge (y = 20)\n"
                     "    t = tab_and_slot(part=\"tab\", length=60 mm, cx=0 mm, cy=20 mm)\n}\n"),
    "t_slot": ("solid panel {\n    body = Rectangle(center=(0, 0), width=60, height=40)\n"
               "    # from the middle of the top edge (y = 20), 12 mm down into the panel\n"
               "    s = t_slot(size=3, cx=0 mm, cy=20 mm)\n    Fixed(body)\n}\n"),
    "dovetail": ("solid panel {\n    body = Rectangle(center=(0, -10), width=60, height=40)\n"
                 "    # tails over the band y = 0 .. 10 at the top of the panel\n"
                 "    d = dovetail(part=\"tail\", length=60 mm, depth=10 mm, cx=0 mm, cy=0 mm)\n}\n"),
}
