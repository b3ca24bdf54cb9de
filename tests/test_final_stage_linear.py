"""The final-part stage stays linear in the number of holes (issue 74), counted, not timed.

* :func:`aidl_lang.output.part.measure.nearby.close_pairs` pairs the boundaries of whole-loop
  features (a plate's holes) run by run: the candidate (vertex, segment) pairs it measures
  per hole are the same at 2,000 and 20,000 holes, none within one hole (the grid over the
  vertices listed each hole's own neighbours, ~450 candidates per hole, and searched them
  again at every halving of a chunk); the pairs and their order are those of the grid.
* W0501's neighbourhood of a hole (:class:`..checks.openings._Near`) is bounded when the
  holes overlap in a row (one opening of 5,000 circles): each hole was intersected with the
  whole row's loop (quadratic, past 60 s); now with the part's shape within the holes.
* A circle's polygon is built from one table of cosines per chord count, the same floats as
  one ``math.cos`` per vertex (the bytes of every output stay the same).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from aidl_lang.geometry.shapes.curves import Circle, Loop
from aidl_lang.output.checks.holes import openings
from aidl_lang.output.part.measure import nearby
from aidl_lang.output.part.edges.exact import Provenance
from aidl_lang.pipeline import compile_source


def _plate(nx: int, ny: int, pitch: float, r: float, k: int = 24):
    """A plate's outline (feature 0) and nx * ny round holes (features 1..) as
    :func:`nearby.boundary` gives them: ``(V, vfeat, A, B, sfeat)``."""
    t = np.linspace(0.0, 2 * math.pi, k, endpoint=False)
    unit = np.column_stack([np.cos(t), np.sin(t)])
    W, H = nx * pitch, ny * pitch
    parts = [nearby.boundary([np.array([[0, 0], [W, 0], [W, H], [0, H]], float)], 0)]
    f = 1
    for i in range(nx):
        for j in range(ny):
            c = (pitch / 2 + i * pitch, pitch / 2 + j * pitch)
            parts.append(nearby.boundary([c + r * unit], f))
            f += 1
    return [np.concatenate([p[m] for p in parts]) for m in range(5)]


def _count_candidates(monkeypatch) -> list:
    seen: list = []
    measure = nearby._measure

    def counting(V, A, B, vfeat, sfeat, v, s, dist):
        seen.append(len(v))
        return measure(V, A, B, vfeat, sfeat, v, s, dist)
    monkeypatch.setattr(nearby, "_measure", counting)
    return seen


@pytest.mark.parametrize("pitch,r,dist", [(10.0, 2.0, 0.5), (1.0, 0.45, 0.2)])
def test_close_pairs_candidates_per_hole_do_not_grow(monkeypatch, pitch, r, dist):
    """Candidates per hole at 2,000 and 20,000 holes within 10 % (a panel 10 mm apart: none
    but the outline's neighbours; holes 0.1 mm apart: their facing sides)."""
    seen = _count_candidates(monkeypatch)
    per_hole = []
    for nx, ny in ((40, 50), (100, 200)):
        seen.clear()
        V, vf, A, B, sf = _plate(nx, ny, pitch, r)
        v, s, d, _ = nearby.close_pairs(V, vf, A, B, sf, dist)
        assert (vf[v] != sf[s]).all() and (d < dist).all()
        per_hole.append(sum(seen) / (nx * ny))
    assert per_hole[1] <= 1.1 * per_hole[0] + 1, per_hole
    if pitch == 10.0:
        assert per_hole[1] < 5          # only the holes by the outline, against its sides
    else:
        assert 0 < per_hole[1] < 400    # the grid listed every hole's own vertices too


def test_close_pairs_run_pairs_are_the_grids_pairs_in_its_order(monkeypatch):
    """The run-by-run pairs (features of whole loops) equal the grid's (a feature per vertex
    forces it), as arrays, in the same order: distances, feet and all."""
    rng = np.random.default_rng(7)
    V, vf, A, B, sf = _plate(30, 10, 1.0, 0.45)
    V = V + rng.normal(scale=0.01, size=V.shape)
    A = V
    B = np.concatenate([np.roll(V[sf == f], -1, axis=0) for f in np.unique(sf)])
    got = nearby.close_pairs(V, vf, A, B, sf, 0.3)
    monkeypatch.setattr(nearby, "_changes", lambda feat: len(feat))     # the grid's path
    want = nearby.close_pairs(V, vf, A, B, sf, 0.3)
    assert len(got[0]) > 1000
    for g, w in zip(got, want):
        assert np.array_equal(g, w)


def _row(n: int, r: float) -> str:
    return f"""solid row {{
  body = Rectangle(center=({(n - 1) / 2} mm, 0 mm), width={n + 2} mm, height=4 mm)
  for i in range({n}) {{
    hole h {{ c = Circle(center=(i * 1 mm, 0 mm), radius={r} mm) }}
  }}
}}
"""


def _nested_row(n: int, r: float) -> str:
    """:func:`_row` with the plate and its holes in a solid ``strip`` inside ``row``: the
    holes cut ``strip``, so W0501 asks whether anything of ``row`` refills them (a part's
    own holes are not asked: nothing between them and the part could)."""
    body = _row(n, r).replace("solid row {", "solid strip {")
    return "solid row {\n" + "\n".join("  " + ln for ln in body.splitlines()) + "\n}\n"


def test_overlapping_row_refill_check_is_local(monkeypatch):
    """300 holes r 0.6 mm 1 mm apart (one opening) of a solid in the part: each hole's
    W0501 test meets a shape of a few vertices, not the row's loop of ~9,000; the same
    W0508 as before."""
    sizes: list = []
    local = openings._Near.local

    def recording(self, part, region):
        shape = local(self, part, region)
        sizes.append(shape.num_vert())
        return shape
    monkeypatch.setattr(openings._Near, "local", recording)
    c = compile_source(_nested_row(300, 0.6), "row.aidl")
    codes = [d.code for d in c.sink.items]
    assert codes.count("W0508") == 299 and "W0501" not in codes
    assert len(sizes) == 300
    assert max(sizes) < 200, max(sizes)


def test_circle_polygon_is_the_same_floats():
    """The table-built polygon of a circle equals ``cx + r * math.cos(t)`` vertex for vertex
    (either way round, any centre and radius), with its chords on one carrier."""
    p = Provenance()
    for (cx, cy, r, ccw) in [(0.1, -3.7, 2.0, True), (123.456, 7.0, 0.4, False),
                             (-1e4 / 3, 1e3 / 7, 37.5, True), (5, 5, 0.004, True)]:
        P = p.polygon(Loop([Circle((cx, cy), r, ccw)]))
        n = len(P)
        sg = 1.0 if ccw else -1.0
        t = [sg * 2 * math.pi * i / n for i in range(n)]
        want = np.column_stack([[cx + r * math.cos(a) for a in t],
                                [cy + r * math.sin(a) for a in t]])
        assert np.array_equal(P, want)
    # (a circle's carrier: one id for all its chords, exact._circle)
    assert len(set(np.concatenate([np.atleast_1d(c) for c in p._c]).tolist())) == 4
