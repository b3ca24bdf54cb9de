"""The bounding-box rows are built faster (frame offsets looked up once per structure and
frame, min/max made without lifting its arguments) but are the same expressions: the same
terms in the same order, on a generated hierarchy and on the bundled examples."""
from __future__ import annotations

import pathlib

import pytest

from aidl_lang.geometry.relations import bbox
from aidl_lang.geometry.core.expr import Lin, Nl, func
from aidl_lang.pipeline import compile_source
from benchmarks.solver.families import hierarchy

ROOT = pathlib.Path(__file__).resolve().parents[1]


def _model(src: str):
    c = compile_source(src, "t.aidl", do_solve=False)
    assert c.ok, [d.message for d in c.sink.items]
    return c.model


def _same(a, b) -> bool:
    """Structurally equal expressions, dict order of every Lin's terms included."""
    if isinstance(a, Lin):
        return isinstance(b, Lin) and list(a.terms.items()) == list(b.terms.items()) \
            and a.const == b.const
    return isinstance(b, Nl) and a.op == b.op and len(a.args) == len(b.args) and \
        all(_same(p, q) for p, q in zip(a.args, b.args))


@pytest.mark.parametrize("src", [hierarchy(15, seed=5).source,
                                 (ROOT / "examples/telephone.aidl").read_text()])
def test_points_in_every_ancestor_frame_equal_in_frame(src):
    m = _model(src)
    offs: dict = {}
    n = 0
    for s in m.structures:
        frames = [None]
        f = s
        while f is not None:
            frames.append(f)
            f = f.parent
        for g in s.geometry:
            for p in g.points.values():
                for fr in frames:
                    a, b = bbox._in_frame(p, fr, offs), p.in_frame(fr)
                    assert _same(a[0], b[0]) and _same(a[1], b[1])
                    n += 1
    assert n > 50


@pytest.mark.parametrize("src", [hierarchy(15, seed=5).source,
                                 (ROOT / "examples/telephone.aidl").read_text()])
def test_box_sides_equal_the_lifted_min_max(src):
    m = _model(src)
    x = m.xs()
    cache: dict = {}
    checked = 0
    for s in m.structures:
        for side in bbox.SIDES:
            e = bbox.side_expr(s, side, s, x, set(), cache)
            xs, ys = bbox.candidates(s, s, x, set())
            cands = xs if side in ("left", "right") else ys
            if len(cands) > 1:
                want = func("min" if side in ("left", "bottom") else "max", *cands)
                assert _same(e, want)
                checked += 1
    assert checked > 10
