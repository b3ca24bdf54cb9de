"""Line fill (issue 112): an area engraved filled (``Text(..., font=, fill=true)``, the output's
strokes of style ``fill``, :func:`~..part.part.fill_regions`) as the parallel lines a laser or
pen runs across it, for the machine writers that draw no area themselves (G-code, HPGL).

The lines are horizontal (along x), ``interval`` mm apart (the machine profile's
``fill.interval``), the rows centred on the area's height so that its top and bottom margin
are equal (at most half an interval).  Each row is cut where it crosses the area's loops and
keeps the spans where the loops wind non-zero (the letters, not their counters); the loops are
their polylines within ``CHORD_TOL`` (0.005 mm) of the exact curves, so each line ends within
that of the letter's edge.  The rows alternate direction (left to right, then right to left:
a boustrophedon), so the head travels one interval between rows.  Lengths in mm.
"""
from __future__ import annotations

import math

import numpy as np

from ...geometry.shapes.curves import Loop
from ..part.part import OutputError

MAX_ROWS = 200_000          # rows of one area: past it the interval is refused


def hatch_lines(loops: list[list], interval: float) -> list[tuple[tuple, tuple]]:
    """The fill lines of one area, in the order they are run: ``[((x0, y), (x1, y))]`` mm.
    ``loops``: each closed loop's exact segments (outer loops counter-clockwise, counters
    clockwise).  Raises :class:`~..part.part.OutputError` for an interval that is not a
    positive length or that gives more than :data:`MAX_ROWS` rows."""
    if not (interval > 0 and math.isfinite(interval)):
        raise OutputError(f"a fill's interval is a length above 0 mm, got {interval!r}")
    polys = [Loop(list(segs)).points() for segs in loops]
    polys = [p for p in polys if len(p) >= 3]
    if not polys:
        return []
    a = np.concatenate(polys)
    b = np.concatenate([np.roll(p, -1, axis=0) for p in polys])
    y0, y1 = float(a[:, 1].min()), float(a[:, 1].max())
    n = max(1, math.ceil((y1 - y0) / interval - 1e-9))
    if n > MAX_ROWS:
        raise OutputError(f"a fill {y1 - y0:.4g} mm tall at an interval of {interval:g} mm "
                          f"would run {n:,} lines; at most {MAX_ROWS:,}: raise the machine "
                          "profile's `fill.interval`")
    first = y0 + ((y1 - y0) - (n - 1) * interval) / 2
    ya, yb = a[:, 1], b[:, 1]
    up = yb > ya
    lo, hi = np.minimum(ya, yb), np.maximum(ya, yb)
    keep = hi > lo                                  # horizontal edges cross no row
    ax, ay, bx, by = a[keep, 0], ya[keep], b[keep, 0], yb[keep]
    lo, hi, wind = lo[keep], hi[keep], np.where(up[keep], 1, -1)
    out = []
    for k in range(n):
        y = first + k * interval
        hit = (lo <= y) & (y < hi)                  # half-open: a vertex counts once
        if not hit.any():
            continue
        t = (y - ay[hit]) / (by[hit] - ay[hit])
        xs = ax[hit] + t * (bx[hit] - ax[hit])
        order = np.argsort(xs, kind="stable")
        xs, ws = xs[order], wind[hit][order]
        spans = []
        w = 0
        start = None
        for x, dw in zip(xs.tolist(), ws.tolist()):
            before = w
            w += dw
            if before == 0 and w != 0:
                start = x
            elif before != 0 and w == 0 and start is not None and x > start:
                spans.append((start, x))
        if k % 2:
            spans = [(x1, x0) for x0, x1 in reversed(spans)]
        out += [((x0, y), (x1, y)) for x0, x1 in spans]
    return out
