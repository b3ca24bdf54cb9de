"""Issue 26: classes of inputs that broke the compiler's promises (an internal error, a
compile beyond its budget, work that grows faster than the input), each with a time bound."""
from __future__ import annotations

import time

import pytest

from aidl_lang import registry
from aidl_lang.pipeline import compile_source

# one instance of every primitive (positional and keyword forms the registry documents)
PRIMS = {
    "Point": "Point((1, 2))", "Line": "Line((0, 0), (10, 1))",
    "Circle": "Circle(center=(0, 0), radius=3)",
    "Arc": "Arc(center=(0, 0), start=(5, 0), end=(0, 5))",
    "Rectangle": "Rectangle(center=(0, 0), width=10, height=5)",
    "RoundedRectangle": "RoundedRectangle(center=(0, 0), width=10, height=5, corner_radius=1)",
    "Triangle": "Triangle((0, 0), (5, 0), (0, 5))",
    "Trapezoid": "Trapezoid(center=(0, 0), bottom_width=10, top_width=5, height=4)",
    "Ellipse": "Ellipse(center=(0, 0), rx=5, ry=3)",
    "Polygon": "Polygon(points=[(0, 0), (5, 0), (0, 5)])",
    "RegularPolygon": "RegularPolygon(center=(0, 0), radius=5, sides=6)",
    "Slot": "Slot((0, 0), (10, 0), radius=2)",
}
CONSTRAINTS = [n for n in registry.ENTRIES if n not in PRIMS and n != "Text"]


def test_every_primitive_compiles_alone():
    for kind, call in PRIMS.items():
        c = compile_source(f"solid p {{ g = {call} }}\n", "p.aidl")
        assert c.ok, (kind, [(d.code, d.message) for d in c.sink.items])


@pytest.mark.parametrize("name", CONSTRAINTS)
def test_constraints_on_every_primitive_answer_with_diagnostics(name):
    """`Fixed(g)` of a Polygon or RegularPolygon raised AttributeError (an internal error):
    every constraint, given one or two geometries of each kind, answers with a model or a
    located diagnostic, never an exception."""
    t0 = time.perf_counter()
    cases = [(a, None) for a in PRIMS] + [(a, a) for a in PRIMS]
    for a, b in cases:
        body = f" g = {PRIMS[a]}\n" + (f" h = {PRIMS[b]}\n" if b else "")
        src = f"solid p {{\n{body} {name}({'g, h' if b else 'g'})\n}}\n"
        c = compile_source(src, "p.aidl")               # raises on an internal error
        for d in c.sink.items:
            if d.is_error and d.code not in ("E0401", "E0402"):
                assert d.span is not None, (src, d.code, d.message)
    assert time.perf_counter() - t0 < 20


@pytest.mark.parametrize("kind", ["Polygon", "RegularPolygon", "Rectangle", "Triangle"])
def test_fixed_polygon_holds_every_vertex(kind):
    c = compile_source(f"solid p {{\n g = {PRIMS[kind]}\n Fixed(g)\n}}\n", "p.aidl")
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    from aidl_lang.solver.diagnose import degrees_of_freedom
    assert sum(d.dof for d in degrees_of_freedom(c.solve.solver, floating=False)) == 0
