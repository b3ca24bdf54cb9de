"""A warning never makes a right design wrong, and what models reach for exists: the program's
own `min_wall`, `RegularPolygon(side=)`, `CornerPattern(inset=(dx, dy))`, `polar()`, and a
check line that says what was settled before Newton (docs/language.md 2.1c, 5; docs/codes.md
W0507)."""
import json
import math
import subprocess
import sys

import pytest

from aidl_lang.api import compile as aidl_compile


def _codes(c):
    return [d.code for d in c.sink.items]


def _point(c, path):
    """The solved coordinates (mm) of the point named by the dotted ``path``."""
    (v,) = [v for v in c.values_matching([path]) if v.name == path]
    return tuple(v.value)


TRIANGLE = """units mm
{statement}
solid tri {{
    body = Triangle((0, 0), (95.149, 0), (40, 15.482))
}}
"""


NEEDLE = TRIANGLE.replace("(40, 15.482)", "(90, 4)")        # a 2.5-degree corner at (0, 0)


# ------------------------------------------------------------------ min_wall
def test_a_requested_sharp_triangle_warns_without_min_wall_and_not_with_it():
    assert "W0507" in _codes(aidl_compile(NEEDLE.format(statement="")))
    c = aidl_compile(NEEDLE.format(statement="min_wall 0"))
    assert c.ok and "W0507" not in _codes(c), _codes(c)
    # a corner sharper than about 11 degrees burns at any minimum (the sliver scales with it)
    assert "W0507" in _codes(aidl_compile(NEEDLE.format(statement="min_wall 0.005 mm")))


def test_min_wall_in_a_structure_covers_that_part_only():
    src = """units mm
assembly kit {
    solid a {
        min_wall 0
        body = Triangle((0, 0), (95.149, 0), (90, 4))
    }
    solid b {
        body = Triangle((0, 40), (95.149, 40), (90, 44))
    }
}
"""
    c = aidl_compile(src)
    walls = [d for d in c.sink.items if d.code == "W0507"]
    assert len(walls) == 1 and "kit.b" in walls[0].message, [d.message for d in walls]


def test_the_command_line_min_wall_overrides_the_statement():
    src = NEEDLE.format(statement="min_wall 0")
    assert "W0507" not in _codes(aidl_compile(src))
    assert "W0507" in _codes(aidl_compile(src, min_wall=0.5))
    assert "W0507" not in _codes(aidl_compile(NEEDLE.format(statement=""), min_wall=0))


def test_min_wall_must_be_a_length_not_negative():
    c = aidl_compile(TRIANGLE.format(statement="min_wall -1"))
    assert not c.ok and _codes(c)[0] == "E0109"
    assert "or 0" in c.sink.items[0].message


def test_min_wall_written_as_a_constant_is_w0108_with_the_statement_as_fix():
    c = aidl_compile(TRIANGLE.format(statement="min_wall = 0.3 mm"))
    (d,) = [d for d in c.sink.items if d.code == "W0108"]
    assert d.fix is not None and d.fix.replacement == "min_wall 0.3 mm"
    fixed = TRIANGLE.format(statement=d.fix.replacement)
    assert "W0507" not in _codes(aidl_compile(fixed)) and "W0108" not in _codes(aidl_compile(fixed))


def test_min_wall_stays_an_ordinary_name_elsewhere():
    c = aidl_compile("""units mm
param min_wall = 2
solid p { body = Rectangle(center=(0, 0), width=10 * min_wall, height=min_wall * 5) }
""")
    assert c.ok, _codes(c)


# ------------------------------------------------------------------ what models reach for
def test_regular_polygon_by_its_side_length():
    c = aidl_compile("""units mm
solid nut { body = RegularPolygon(center=(3, 4), side=1.5, sides=6, rotation=10 deg) }
""")
    assert c.ok, _codes(c)
    pts = [_point(c, f"nut.body.p{k}") for k in range(6)]
    for k in range(6):
        assert math.dist(pts[k], pts[(k + 1) % 6]) == pytest.approx(1.5, abs=1e-9)
    c7 = aidl_compile("solid s { body = RegularPolygon(center=(0, 0), side_length=10, sides=7) }")
    p0, p1 = _point(c7, "s.body.p0"), _point(c7, "s.body.p1")
    assert math.dist(p0, p1) == pytest.approx(10, abs=1e-9)
    assert math.hypot(*p0) == pytest.approx(10 / 2 / math.sin(math.pi / 7), abs=1e-9)


@pytest.mark.parametrize("rotation", [0, 30])
def test_corner_pattern_with_an_inset_per_axis(rotation):
    c = aidl_compile(f"""units mm
solid plate {{
    body = Rectangle(center=(0, 0), width=60, height=40, rotation={rotation} deg)
    hole h {{ c = Circle(center=(0, 0), radius=2) }}
    Fixed(body)
    corners = CornerPattern(h, body, inset=(5, 8))
}}
""")
    assert c.ok, _codes(c)
    a = math.radians(rotation)
    u, v = (math.cos(a), math.sin(a)), (-math.sin(a), math.cos(a))
    want = (-25 * u[0] - 12 * v[0], -25 * u[1] - 12 * v[1])    # the bottom-left corner, inset
    got = _point(c, "plate.h.c.center")
    assert got == pytest.approx(want, abs=1e-9)


def test_corner_pattern_inset_of_the_wrong_kind_is_a_clear_error():
    c = aidl_compile("""solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole h { c = Circle(center=(0, 0), radius=2) }
    corners = CornerPattern(h, body, inset="a lot")
}
""")
    assert not c.ok
    assert any("inset" in d.message for d in c.sink.items if d.severity == "error"), \
        [d.message for d in c.sink.items]


@pytest.mark.parametrize("start", [(10, 10), (10, -10)])
def test_polar_places_a_point_at_a_radius_and_angle_with_no_mirror_image(start):
    """Started at the mirror image of where it belongs (below the x axis), the point still
    ends at +30 degrees: polar() is one point, not a distance and an angle."""
    c = aidl_compile(f"""units mm
solid flange {{
    disc = Circle(center=(0, 0), radius=30)
    hole bolt {{ c = Circle(center={start}, radius=2) }}
    disc.center == (5, 5)
    Coincident(bolt.c.center, polar(disc.center, 20, 30 deg))
    p = Point(at=polar(disc.center, 10, 120))
}}
""")
    assert c.ok, _codes(c)
    assert _point(c, "flange.bolt.c.center") == pytest.approx(
        (5 + 20 * math.cos(math.pi / 6), 5 + 20 * math.sin(math.pi / 6)), abs=1e-9)
    assert _point(c, "flange.p.p") == pytest.approx(
        (5 + 10 * math.cos(2 * math.pi / 3), 5 + 10 * math.sin(2 * math.pi / 3)), abs=1e-9)


def test_polar_needs_a_point_a_length_and_an_angle():
    c = aidl_compile("solid s { p = Point(at=polar((0, 0), 5)) }")
    assert not c.ok and _codes(c)[0] == "E0104"


# ------------------------------------------------------------------ the check line
HULL = """units mm
solid plate {
    a = Circle(center=(0, 0), radius=5, construction=true)
    b = Circle(center=(30, 0), radius=5, construction=true)
    body = Hull(a, b)
    Fixed(a)
    HorizontalDistance(a.center, b.center, 30)
    Horizontal(a.center, b.center)
}
"""


def test_the_check_line_says_what_was_settled_before_newton(tmp_path):
    f = tmp_path / "hull.aidl"
    f.write_text(HULL)
    out = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(f)],
                         capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "4 unknowns, all 4 settled directly by their constraints" in out.stdout, out.stdout
    assert "0 unknowns" not in out.stdout
    js = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", "--json", str(f)],
                        capture_output=True, text=True, cwd=tmp_path, timeout=120)
    doc = json.loads(js.stdout)
    assert doc["solve"]["settled"] == 4 and doc["solve"]["unknowns"] == 0


def test_solve_text_without_anything_settled_is_the_old_line():
    from aidl_lang.solver import SolveResult, solve_text
    r = SolveResult(True, 2, 1, n_unknowns=20, n_equations=20)
    assert solve_text(r) == "20 unknowns, 20 equations, solved in 2 Newton steps"
    r = SolveResult(True, 3, 1, n_unknowns=26, n_equations=26, n_settled=4)
    assert solve_text(r) == ("30 unknowns: 4 settled directly by their constraints, 26 solved "
                             "by Newton from 26 equations in 3 steps")


# ------------------------------------------------------------------ the model is told
def test_the_prompt_answers_what_models_asked():
    from aidl_lang.llm.prompt import system_prompt
    text = " ".join(system_prompt(examples=False).split())
    assert "min_wall 0.3 mm" in text and "never change a requested size" in text
    assert "polar(c.center, 20, 30 deg)" in text
    assert "param h = w / 2" in text
    assert "stays exactly where it is written" in text
    assert "RegularPolygon(center, side, sides" in text
    assert "(dx, dy)" in text


# ------------------------------------------------------------------ the description
NOTCHED = """units mm
thickness 4 mm
kerf 0.2 mm
assembly kit {
    solid plate {
        body = Rectangle(center=(0, 0), width=60, height=30)
        hole a { c = Circle(center=(-15, 15), radius=4) }
        hole b { c = Circle(center=(10, 5), radius=3) }
        hole slot { r = Rectangle(center=(30, -5), width=10, height=6) }
        Fixed(body)
        Fixed(a)
        Fixed(b)
        Fixed(slot)
    }
    solid spacer {
        thickness 6 mm
        c = Circle(center=(100, 0), radius=8)
    }
}
"""


def test_the_description_states_thickness_kerf_and_the_notches_holes_cut():
    c = aidl_compile(NOTCHED)
    assert c.ok, _codes(c)
    parts = {p["name"]: p for p in c.description["parts"]}
    plate, spacer = parts["kit.plate"], parts["kit.spacer"]
    assert (plate["thickness"], plate["thickness_set"], plate["kerf"]) == (4.0, True, 0.2)
    assert spacer["thickness"] == 6.0
    assert [o["kind"] for o in plate["openings"]] == ["circle"]       # b only
    got = {n["hole"]: (n["edge"], n["width"], n["depth"], n["center"]) for n in plate["notches"]}
    assert got == {"kit.plate.a": ("top", 8.0, 4.0, [-15.0, 13.0]),
                   "kit.plate.slot": ("right", 6.0, 5.0, [27.5, -5.0])}
    text = c.describe()
    assert "material: 4 mm thick, kerf 0.2 mm" in text
    assert "material: 6 mm thick" in text
    assert "notch in the top edge: 8 wide, 4 deep, at (-15, 13), cut by hole `kit.plate.a`" in text


def test_the_description_says_when_the_thickness_is_only_the_default():
    c = aidl_compile("solid p { body = Rectangle(center=(0, 0), width=10, height=5) }")
    (p,) = c.description["parts"]
    assert (p["thickness"], p["thickness_set"], p["kerf"], p["notches"]) == (3.0, False, None, [])
    assert "3 mm thick (no `thickness` stated: the default), no kerf" in c.describe()


# ------------------------------------------------------------------ W0507 says what it measured
def test_w0507_states_the_measured_width_and_length_of_a_thin_leg_and_its_fix_clears_it():
    """An angle profile with 0.34 mm legs (as requested): the width measured across the leg
    (not the 0.5 mm threshold), over the legs' centre line; the offered fix states the wall."""
    src = """solid angle {
    body = Polygon([(0, 0), (40, 0), (40, 0.34), (0.34, 0.34), (0.34, 25.4), (0, 25.4)])
}
"""
    c = aidl_compile(src)
    (w,) = [d for d in c.sink.items if d.code == "W0507"]
    assert "is 0.34 mm wide, thinner than 0.5 mm (over 65.1 mm" in w.message, w.message
    assert w.fix is not None and w.fix.replacement.startswith("min_wall 0.33 mm")
    fixed = src[:w.fix.span.start] + w.fix.replacement + src[w.fix.span.end:]
    c2 = aidl_compile(fixed)
    assert c2.ok and "W0507" not in _codes(c2), [d.message for d in c2.sink.items]
    # the measured width follows the drawing: 0.21 mm legs read 0.21
    c3 = aidl_compile(src.replace("0.34", "0.21"))
    (w3,) = [d for d in c3.sink.items if d.code == "W0507"]
    assert "is 0.21 mm wide" in w3.message


def test_w0507_is_quiet_on_a_requested_obtuse_triangle():
    """Base 95.149, height 15.482: corners of 18 and 16 degrees, each cut clean (the old
    message joined the three corners' slivers over the whole base and blamed the 144-degree
    apex); a triangle sharp enough to burn names the corner and its angle."""
    assert "W0507" not in _codes(aidl_compile(TRIANGLE.format(statement="")))
    c = aidl_compile("solid needle { body = Triangle((0, 0), (95.149, 0), (90, 4)) }")
    (w,) = [d for d in c.sink.items if d.code == "W0507"]
    import re
    m = re.search(r"its corner at \(([-\d.]+), ([-\d.]+)\) is ([\d.]+) degrees", w.message)
    assert m, w.message
    x, y, angle = map(float, m.groups())
    assert (x, y) == (0.0, 0.0)
    assert angle == pytest.approx(math.degrees(math.atan2(4, 90)), abs=0.05)


def test_w0507_of_a_long_spike_says_how_much_of_it_is_thin():
    c = aidl_compile("""solid spike {
    body = Rectangle(center=(0, 0), width=20, height=10)
    solid s { t = Triangle(a=(10, -3), b=(10, 3), c=(160, 0)) }
}
""")
    (w,) = [d for d in c.sink.items if d.code == "W0507"]
    angle = 2 * math.degrees(math.atan2(3, 150))
    last = 0.25 / math.tan(math.radians(angle) / 2)
    assert f"is {angle:.1f} degrees, narrower than 0.5 mm over its last {last:.2f} mm" \
        in w.message, w.message
    assert "over 150" not in w.message


def test_bolt_circle_holes_sit_at_their_angles_and_cannot_slide_round():
    """std bolt_circle placed its holes by OnCircle alone: each could slide round the pitch
    circle (6 free degrees no Fixed removed, a model run found); now by polar() at its angle."""
    c = aidl_compile("""import "std/shapes.aidl"
solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    bolts = bolt_circle(count=6, pcd=40, hole_d=4.5, start=15 deg)
    Concentric(bolts.pitch, body)
    body.center == (3, 2)
}
""")
    assert c.ok and not c.sink.items, [d.message for d in c.sink.items]
    from aidl_lang.solver.diagnosis.freedom import degrees_of_freedom
    dofs = degrees_of_freedom(c.compiled.solve.solver, floating=False)
    assert all(d.dof == 0 for d in dofs if d.structure.path.startswith("plate.bolts")), \
        [(d.structure.path, d.dof) for d in dofs]
    for i in range(6):
        a = math.radians(15 + 60 * i)
        assert _point(c, f"plate.bolts.bolt[{i}].center") == pytest.approx(
            (3 + 20 * math.cos(a), 2 + 20 * math.sin(a)), abs=1e-9)


def test_parts_meant_to_share_material_when_assembled_say_so_with_allow_overlap():
    src = """thickness 3 mm
assembly kit {
    solid base { r = Rectangle(center=(0, 0), width=40, height=40) }
    solid wall { r = Rectangle(center=(0, 0), width=40, height=20) }
    Place(wall, rotation=(90 deg, 0, 0), position=(0, 0, 12))
}
"""
    (w,) = [d for d in aidl_compile(src).sink.items if d.code == "W0517"]
    assert "`AllowOverlap(base, wall)`" in w.hint
    meant = src.replace("    Place(wall", "    AllowOverlap(base, wall)\n    Place(wall")
    c = aidl_compile(meant)
    assert c.ok and "W0517" not in _codes(c), _codes(c)


def test_the_thin_wall_and_the_notch_through_the_command_line(tmp_path):
    """`aidl check --json` carries W0507's measured width and its fix, `--describe --json` the
    thickness, kerf and notches: what a model reads."""
    angle = tmp_path / "angle.aidl"
    angle.write_text("""solid angle {
    body = Polygon([(0, 0), (40, 0), (40, 0.34), (0.34, 0.34), (0.34, 25.4), (0, 25.4)])
}
""")
    out = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", "--json", str(angle)],
                         capture_output=True, text=True, cwd=tmp_path, timeout=120)
    (w,) = [d for d in json.loads(out.stdout)["diagnostics"] if d["code"] == "W0507"]
    assert "0.34 mm wide" in w["message"] and w["fix"]["replacement"].startswith("min_wall 0.33")
    plate = tmp_path / "notched.aidl"
    plate.write_text(NOTCHED)
    out = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", "--describe", "--json",
                          str(plate)], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    parts = {p["name"]: p for p in json.loads(out.stdout)["describe"]["parts"]}
    assert parts["kit.plate"]["thickness"] == 4.0 and parts["kit.plate"]["kerf"] == 0.2
    assert [(n["edge"], n["width"], n["depth"]) for n in parts["kit.plate"]["notches"]] == \
        [("top", 8.0, 4.0), ("right", 6.0, 5.0)]
    text = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", "--describe",
                           str(plate)], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert "notch in the top edge: 8 wide, 4 deep" in text.stdout
