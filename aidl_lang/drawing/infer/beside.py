"""``aidl import --infer``: a part drawn beside another in one file (two brackets side by
side; issue 103, docs/import.md "What an edit means") placed from that part's near edge by a
gap param, so a wider first part moves the second along.  Used by :mod:`.infer`; lengths in
the drawing's unit."""
from __future__ import annotations

from .params import _r
from .shapes import EQUAL_TOL
from ..model import Drawing


def _beside(prev, d: Drawing, params, prefix: str, stats):
    """``(axis, shift)`` when the part ``d`` lies beside the part written before it,
    ``prev`` (``(name, Drawing, _Part)``), along x (else y): past its right (top) edge,
    their spans across overlapping (two brackets side by side in one file); the shift
    (program text, 0 as drawn) places ``d`` from that part's edge by a gap param
    (``<prefix>gap``), so that a wider first part moves the second along and keeps the gap
    (docs/import.md, "What an edit means"); else None."""
    if prev is None or prev[2] is None or prev[2].anchor is None:
        return None
    a, b = prev[1].box(), d.box()
    if a is None or b is None:
        return None
    for axis in (0, 1):
        lo, hi = axis, axis + 2
        other = 1 - axis
        gap = b[lo] - a[hi]
        if gap > EQUAL_TOL and min(a[other + 2], b[other + 2]) - max(a[other], b[other]) > 0:
            edge = prev[2].edge(axis, 1)
            g = params.add(prefix + "gap", gap, f"from {prev[0]}'s "
                                                f"{'right' if axis == 0 else 'top'} edge")
            stats.readings.append(f"`{prefix[:-1] or 'part'}` beside `{prev[0]}`: placed from "
                                  f"its {'right' if axis == 0 else 'top'} edge by `{g}`")
            shift = f"({edge} + {g} - {_r(b[lo])})"
            return axis, (shift, None) if axis == 0 else (None, shift)
    return None


def beside_order(items: list, parts: bool) -> list:
    """``items`` (``(kind, name, drawing, ...)``) with two or three plain solids drawn side
    by side (their spans along x, else along y, apart) written from the left (the bottom)
    one on, so each is placed beside the one before it by a gap param (:func:`_beside`; issue
    114: three plates in a row written largest first left the first without its gap); the
    names stay; else ``items`` as they are (a sheet of ``parts``, a drawing of texts)."""
    solids = [it for it in items if it[0] == "solid" and len(it) == 3]
    if parts or len(solids) != len(items) or not 2 <= len(solids) <= 3:
        return items
    boxes = [it[2].box() for it in solids]
    if any(b is None for b in boxes):
        return items
    for axis in (0, 1):
        spans = sorted((b[axis], b[axis + 2]) for b in boxes)
        if all(hi + EQUAL_TOL < lo for (_, hi), (lo, _) in zip(spans, spans[1:])):
            order = sorted(range(len(items)), key=lambda k: boxes[k][axis])
            return [items[k] for k in order]
    return items
