"""The vocabulary: every synonym means its canonical entry with the right argument order, every
known hallucination gets its specific hint, `construction` is keyword-only, and partial programs
(empty structures, unconstrained parts) check and render."""
import json
import re

import numpy as np
import pytest

from aidl_lang.registry import ENTRIES, SWAPPED, SYNONYMS, canonical_args, lookup
from aidl_lang.output import render_model, to_svg
from aidl_lang.typecheck import HALLUCINATIONS

SETUP = """solid s {
    r1 = Rectangle(center=(0, 0), width=40, height=30)
    r2 = Rectangle(center=(50, 5), width=10, height=12)
    l1 = Line((0, -40), (10, -43))
    l2 = Line((20, -39), (28, -50))
    a1 = Arc((80, 0), (85, 0), (80, 5))
    a2 = Arc((100, 0), (103, 0), (100, 3))
    p = Point(5, 50)
    q = Point(9, 57)
    %s
}
"""

# canonical -> arguments of a sample call that changes the solution
SAMPLE = {
    "Perpendicular": "l1, l2", "Coincident": "l1.end, l2.start", "Fixed": "r2)\n    Above(r2, r1",
    "Equal": "l1, l2", "CenterInside": "r2, r1", "Above": "r2, r1", "Below": "r2, r1",
    "LeftOf": "r2, r1", "RightOf": "r2, r1", "Inside": "r2, r1, 2", "Midpoint": "p, l1",
    "Symmetric": "p, q, l1", "HorizontalDistance": "p, q, 10", "VerticalDistance": "p, q, 10",
    "AlignCenterX": "r2, r1", "AlignCenterY": "r2, r1", "OnLine": "p, l1", "OnCircle": "p, a1",
    # shapes made from shapes: the sample changes the drawn area, not the solution
    "Offset": "r2, 2", "Inset": "r1, 3", "Hull": "r1, r2",
    "Intersect": "r1, Circle(center=(20, 15), radius=10)",
    "Drawing2D": "\"std/drawings/pcb_board.dxf\", layer=\"Edge.Cuts\", at=(60, 0)",
    "Spline": "points=[(200, 0), (230, 0), (215, 25)], closed=true",
    "Polyline": "points=[(200, 0), (230, 0), (215, 25)], closed=true",
    "Bezier": "points=[(200, 0), (230, 0), (230, 25), (215, 25), (200, 25), (200, 0), "
              "(200, 0)], closed=true",
    "Sector": "center=(200, 0), radius=20, start_angle=0, end_angle=90",
    "Stroke": "l1, 2",
    # operations: a sample that makes no copies (the unknowns stay comparable)
    "GridPattern": "r2, 1, 1, 5)\n    Above(r2, r1", "CornerPattern": "p, at=[(60, 60)]",
    "At": "p, q, 3, 4", "Rigid": "p, q)\n    Midpoint(p, l1",
}
# canonical entries that change no solved value, or make copies (their synonyms are tested
# where they act: AllowOverlap's in tests/test_forms.py, the transforms' in
# tests/test_transform_scale.py, Countersink's and Counterbore's in tests/test_checks_sinks.py)
NO_SOLUTION = {"AllowOverlap", "Translate", "Translated", "Scale", "Scaled", "Countersink",
               "Counterbore"}
# the sample for a synonym whose arguments are swapped
SWAPPED_SAMPLE = {"Contains": "r1, r2, 2"}


def _solve(compile_text, call):
    c = compile_text(SETUP % call)
    assert c.ok, [d.message for d in c.sink.items]
    return c.model.xs()


def test_every_synonym_has_a_sample_and_a_canonical_entry():
    for syn, canon in SYNONYMS.items():
        assert canon in ENTRIES, syn
        assert syn not in ENTRIES, syn
        assert canon in SAMPLE or canon in NO_SOLUTION, f"add a sample call for {canon}"
    for syn in SWAPPED:
        assert syn in SYNONYMS and syn in SWAPPED_SAMPLE


@pytest.mark.parametrize("syn", sorted(s for s in SYNONYMS if SYNONYMS[s] not in NO_SOLUTION))
def test_synonym_means_its_canonical_constraint(compile_text, syn):
    canon = SYNONYMS[syn]
    if ENTRIES[canon].category == "primitive":
        from aidl_lang.output import area

        def drawn(call):
            c = compile_text(SETUP % call)
            assert c.ok, [d.message for d in c.sink.items]
            return area(render_model(c.model))
        want = drawn(f"o = {canon}({SAMPLE[canon]})")
        assert drawn(f"o = {syn}({SAMPLE[canon]})") == pytest.approx(want, rel=1e-12)
        assert drawn("") != pytest.approx(want, rel=1e-3)      # the sample does something
        return
    base = _solve(compile_text, "")
    want = _solve(compile_text, f"{canon}({SAMPLE[canon]})")
    got = _solve(compile_text, f"{syn}({SWAPPED_SAMPLE.get(syn, SAMPLE[canon])})")
    assert np.allclose(got, want, atol=1e-9)
    assert not np.allclose(base, want, atol=1e-6)     # the sample does something


def test_contains_swaps_its_arguments_positionally_and_by_keyword(compile_text):
    def bbox(call):
        c = compile_text(SETUP % call)
        assert c.ok
        x = c.model.xs()
        g = {g.name: g for g in c.model.all_geometry()}
        pts = lambda n: np.array([[x[p.ix], x[p.iy]] for p in g[n].points.values()])
        return pts("r1"), pts("r2")
    for call in ("Contains(r1, r2, 2)", "Contains(a=r1, b=r2, margin=2)",
                 "Contains(b=r2, a=r1, margin=2)"):
        r1, r2 = bbox(call)
        assert r2[:, 0].min() >= r1[:, 0].min() + 2 - 1e-6, call      # r2 inside r1
        assert r2[:, 0].max() <= r1[:, 0].max() - 2 + 1e-6, call
        assert r2[:, 1].max() <= r1[:, 1].max() - 2 + 1e-6, call
    # the wrong order would ask the 40 x 30 box to fit inside the 10 x 12 one
    c = compile_text(SETUP % "Inside(r1, r2)")
    assert not c.ok and c.sink.items[0].code == "E0401"
    assert canonical_args("Contains", {"a": 1, "b": 2, "margin": 3}) == {"a": 2, "b": 1, "margin": 3}
    assert canonical_args("Within", {"a": 1, "b": 2}) == {"a": 1, "b": 2}


def test_gap_is_the_space_between_boxes_on_either_side(compile_text):
    for first, second in (("b2, box", "box, b2"), ("box, b2", "b2, box")):
        src = f"""solid s {{
    box = Rectangle(center=(0, 0), width=40, height=30)
    b2 = Rectangle(center=(60, 0), width=10, height=10)
    c1 = Circle((0, 60), 5)
    Fixed(box)
    Gap({first}, 7)
    Gap(c1, box, 3, "y")
}}
"""
        c = compile_text(src)
        assert c.ok, [d.message for d in c.sink.items]
        x = c.model.xs()
        g = {g.name: g for g in c.model.all_geometry()}
        assert x[g["b2"].points["bottom_left"].ix] == pytest.approx(27.0, abs=1e-6)
        cy = x[g["c1"].points["center"].iy]
        assert cy - 5 == pytest.approx(15 + 3, abs=1e-6)


def test_collinear_lines_and_points(compile_text):
    c = compile_text(SETUP % "Collinear(l1, l2)\n    Collinear(p, q, r2.center)")
    assert c.ok
    x = c.model.xs()
    g = {g.name: g for g in c.model.all_geometry()}
    P = lambda pt: np.array([x[pt.ix], x[pt.iy]])
    s, e = P(g["l1"].points["start"]), P(g["l1"].points["end"])
    d = (e - s) / np.linalg.norm(e - s)
    for pt in g["l2"].points.values():
        v = P(pt) - s
        assert abs(d[0] * v[1] - d[1] * v[0]) < 1e-6
    p, q = P(g["p"].points["p"]), P(g["q"].points["p"])
    r = np.mean([P(pt) for pt in g["r2"].points.values()], axis=0)
    assert np.linalg.norm(p - q) > 1 and np.linalg.norm(r - p) > 1     # not collapsed
    u, w = q - p, r - p
    assert abs(u[0] * w[1] - u[1] * w[0]) / np.linalg.norm(w) < 1e-6


@pytest.mark.parametrize("name", sorted(HALLUCINATIONS))
def test_hallucination_gets_its_hint(compile_text, name):
    c = compile_text(f"solid s {{\n    body = Rectangle(center=(0, 0), width=10, height=5)\n"
                     f"    {name}(body, 30)\n}}\n")
    d = [d for d in c.sink.items if d.code == "E0103"]
    assert len(d) == 1 and d[0].hint == HALLUCINATIONS[name]
    assert d[0].fix is None
    assert not re.search(r"\b(delete|remove|drop)\b", d[0].hint, re.I)


def test_hallucination_hints_name_only_real_vocabulary():
    for name, hint in HALLUCINATIONS.items():
        assert lookup(name) is None, f"{name} is in the registry: its hint is never shown"
        for used in re.findall(r"`([A-Z]\w*)\(", hint):
            assert lookup(used) is not None, f"hint for {name} mentions unknown {used}"


def test_hint_and_suggestions_in_json(tmp_path):
    from aidl_lang.cli import main
    import contextlib
    import io
    p = tmp_path / "t.aidl"
    p.write_text("solid s {\n    body = Rectangle(center=(0, 0), width=10, height=5)\n"
                 "    Rotate(body, 30 deg)\n    c = Circl((0, 0), 3)\n}\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        rc = main(["check", str(p), "--json"])
    assert rc == 1
    doc = json.loads(out.getvalue())
    rot, circ = doc["diagnostics"]
    assert rot["code"] == "E0103" and rot["hint"] == HALLUCINATIONS["Rotate"]
    assert rot["span"]["line"] == 3 and rot["span"]["column"] == 5
    assert circ["code"] == "E0103" and circ["suggestions"][0] == "Circle"
    assert circ["fix"]["replacement"] == "Circle"
    for d in doc["diagnostics"]:
        assert {"code", "message", "span", "hint", "suggestions"} <= set(d)


def test_construction_is_keyword_only(compile_text):
    c = compile_text("solid s {\n    c = Circle((0, 0), 5, true)\n}\n")
    assert [d.code for d in c.sink.items] == ["E0104"]
    assert "at most 2" in c.sink.items[0].message
    c = compile_text("solid s {\n    c = Circle((0, 0), 5, construction=true)\n"
                     "    r = Rectangle((0, 0), 30, 20)\n}\n")
    assert c.ok
    assert "*, construction" in ENTRIES["Circle"].signature()


PARTIAL = [
    "solid top {\n}\n",
    "solid top {\n    solid left {\n    }\n    hole bore {\n    }\n    Above(left, bore)\n}\n",
    "solid top {\n    base = Rectangle(center=(0, 0), width=30, height=10)\n"
    "    solid arm {\n    }\n    hole slot {\n        s = Slot((0, 0), (10, 0), 2)\n    }\n}\n",
    "assembly a {\n    solid p1 {\n        c = Circle((0, 0), 4)\n    }\n    solid p2 {\n    }\n"
    "    drawing notes {\n    }\n}\n",
    "solid top {\n    l = Line((0, 0), (10, 3))\n    a = Arc((0, 0), (5, 0), (0, 5))\n}\n",
]


@pytest.mark.parametrize("src", PARTIAL)
def test_partial_programs_check_and_render(compile_text, src):
    c = compile_text(src)
    assert c.ok, [d.message for d in c.sink.items]
    svg = to_svg(render_model(c.model), title=c.model.root.name)
    assert svg.startswith("<svg") or "<svg" in svg


def test_mirror_with_two_arguments_points_to_the_operation(compile_text):
    c = compile_text("solid s {\n    a = Circle((0, 0), 1)\n    l = Line((2, 0), (2, 1))\n"
                     "    Mirror(a, l)\n}\n")
    d = c.sink.items[0]
    assert d.code == "E0106" and "Mirrored(target, about=line)" in d.hint


# ------------------------------------------------------------------ template keywords
WHEEL = """def wheel(radius = 10 mm, teeth = 8, bore = 2 mm) -> solid {
    rim = Circle(center=(0, 0), radius=radius)
    hole axle { c = Circle(center=(0, 0), radius=bore) }
}
assembly cart {
    w = wheel(CALL)
}
"""


@pytest.mark.parametrize("call,radius,teeth", [
    ("r=12 mm", 12.0, 8), ("num_teeth=14", 10.0, 14), ("n_teeth=15", 10.0, 15),
    ("number_of_teeth=16", 10.0, 16), ("teeth_count=17, r=7 mm", 7.0, 17),
])
def test_template_keywords_take_the_synonyms_of_built_in_shapes(compile_text, call, radius, teeth):
    """A template's parameters answer to the synonyms an LLM would guess (`r`, `num_teeth`...)
    as the built-in shapes' arguments do, in the checker and the interpreter alike."""
    import aidl_lang
    r = aidl_lang.compile(source=WHEEL.replace("CALL", call + ", bore=1 mm"))
    assert r.ok, [d.message for d in r.diagnostics]
    assert r.value("cart.w.rim.radius").value == pytest.approx(radius, abs=1e-12)
    src = WHEEL.replace("CALL", call).replace("radius=bore", "radius=teeth / 4")
    r = aidl_lang.compile(source=src)
    assert r.ok and r.value("cart.w.axle.c.radius").value == pytest.approx(teeth / 4, abs=1e-12)


@pytest.mark.parametrize("call,message", [
    ("num_teeth=14, teeth=12", "`wheel`: `teeth` is given twice"),
    ("teeth=12, n_teeth=14", "`wheel`: `teeth` is given twice (`n_teeth` is another name for it)"),
    ("num_spokes=3", "`wheel` has no parameter `num_spokes`"),
])
def test_template_keyword_errors(compile_text, call, message):
    c = compile_text(WHEEL.replace("CALL", call))
    (d,) = [d for d in c.sink.items if d.code == "E0105"]
    assert d.message == message
