"""Issue 109, law 6's case: a `Fillet` (or `Chamfer`) of size 0 rounds nothing, so a maker's
edit of an imported profile's `fillet` param to 0 gives the sharp-cornered part
(docs/import.md, "What an edit means"; it was E0108 "Fillet needs a positive size", drawn at
random by test_infer_profiles.py on a fresh machine: `gen_profiles.random_profile(
random.Random(1059), "t_bracket")`, a T-bracket in inches).

Laws: an L plate with a rectangular hole whose `Fillet`/`Chamfer` (whole outline, or corners
chosen with `at`) is given size 0 writes the DXF of the same program without the operation,
entity for entity (read back by ezdxf), and size 2 does not (it rounds); a chosen corner that
is none is still E0408 at size 0, a negative size still E0108, both located at the call.
Cost: about 14 compiles and one inferred drawing edited twice, about 4 s CPU."""
from __future__ import annotations

import random

import pytest

import gen_profiles as gp
from benchmarks.imports import infer_edits as bench
from test_exact_formats import dxf_doc, output

PLATE = """units mm
param r = {r}
solid plate {{
    body = Polygon([(0, 0), (60, 0), (60, 15), (25, 15), (25, 40), (0, 40)])
    hole slot {{
        s = Rectangle(center=(10, 8), width=12, height=6)
    }}
    {op}
}}
"""
OPS = ("Fillet(r)", "Chamfer(r)", "Fillet(at=[body.edges[2], body.edges[3]], radius=r)",
       "Chamfer(at=body, distance=r)", "Fillet(body, r)")


def _entities(o) -> list:
    """Every entity of the DXF of ``o`` as ezdxf reads it back: (type, layer, its vertices
    with bulges, or its centre and radius), to 1e-9 mm, sorted."""
    out = []
    for e in dxf_doc(o).modelspace():
        t = e.dxftype()
        if t == "LWPOLYLINE":
            geo = tuple(tuple(round(v, 9) for v in p) for p in e.get_points("xyb"))
        elif t in ("CIRCLE", "ARC"):
            geo = (round(e.dxf.center.x, 9), round(e.dxf.center.y, 9), round(e.dxf.radius, 9))
        elif t == "LINE":
            geo = tuple(round(v, 9) for v in (*e.dxf.start, *e.dxf.end))
        else:
            geo = (t,)
        out.append((t, e.dxf.layer, geo))
    return sorted(out)


@pytest.mark.parametrize("op", OPS)
def test_size_zero_is_the_part_without_the_operation(op, compile_text):
    """Size 0 writes the DXF of the program without the call, exactly; size 2 rounds (cuts)
    some corner, so the comparison can fail."""
    sharp = _entities(output(compile_text, PLATE.format(r=0, op="")))
    assert _entities(output(compile_text, PLATE.format(r=0, op=op))) == sharp
    c = compile_text(PLATE.format(r=0, op=op))
    assert not c.sink.items, [(d.code, d.message) for d in c.sink.items]
    rounded = _entities(output(compile_text, PLATE.format(r=2, op=op)))
    assert rounded != sharp
    bulges = [b for t, _, geo in rounded if t == "LWPOLYLINE" for *_, b in geo if b]
    assert bulges if op.startswith("Fillet") else len(rounded) >= len(sharp)


def test_size_zero_still_checks_the_chosen_corners_and_refuses_a_negative_size(compile_text):
    """`at` naming parallel edges is E0408 whatever the size; -1 mm is E0108; both at the
    call's line and column."""
    for op, code, words in (
            ("Fillet(at=[body.edges[0], body.edges[4]], radius=r)", "E0408",
             "they are parallel"),
            ("Fillet(-1)", "E0108", "needs a size of 0 or more")):
        c = compile_text(PLATE.format(r=0, op=op))
        got = [d for d in c.sink.items if d.code == code]
        assert not c.ok and len(got) == 1, [(d.code, d.message) for d in c.sink.items]
        assert words in got[0].message, got[0].message
        assert (got[0].span.line, got[0].span.col) == (8, 5), got[0].span


def test_the_t_bracket_of_seed_1059_edits_its_fillet_to_0(tmp_path):
    """The issue's drawing: a 2.5 x 3.5 in T-bracket, 0.5 in walls, 0.125 in inside fillets;
    its inferred program's `fillet` edited to 0 gives the T drawn with sharp corners (and
    `height` to 4.5 in the T drawn so), compared by exact loop signatures."""
    rng = random.Random(1059)
    d = gp.random_profile(rng, "t_bracket")
    assert (d.units, d.P["ri"], d.P["W"], d.P["H"]) == ("in", 0.125, 2.5, 3.5), d.describe()
    r = bench.run_drawing(d, tmp_path, rng, 2)
    assert r["exact"] and not r["error"], r["program"]
    assert "param fillet = 0.125 in" in r["program"], r["program"]
    edits = {e.label.split()[-1]: (o, dt) for e, o, dt in r["edits"]}
    assert edits.get("fillet", ("",))[0] == "meant", (edits, r["program"])
    assert all(o == "meant" for o, _ in edits.values()), edits
