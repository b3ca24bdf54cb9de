"""Line fill (issue 112): an area engraved filled (``Text(..., font=, fill=true)``, the output's
strokes of style ``fill``, :func:`~..part.part.fill_regions`) as the parallel lines a laser or
pen runs across it, for the machine writers that draw no area themselves (G-code, HPGL).

The lines are horizontal (along x), ``interval`` mm apart (the machine profile's
``fill.interval``), the rows centred on the area's height so that its top and bottom margin
are equal (at most half an interval).  Each row is cut where it crosses the loops and keeps
the spans where they wind non-zero (the letters, not their counters); the loops are their
polylines within ``CHORD_TOL`` (0.005 mm) of the exact curves, so each line ends within that
of the letter's edge.  The area is filled piece by piece (each outer loop with the counters
inside it: a letter), left to right, on the area's one grid of rows; within a piece the rows
alternate direction (left to right, then right to left: a boustrophedon), so the head travels
one interval between rows and never across the gap between two letters mid-letter.  Lengths
in mm.
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
    clockwise, none crossing another).  Raises :class:`~..part.part.OutputError` for an
    interval that is not a positive length or that gives more than :data:`MAX_ROWS` rows."""
    if not (interval > 0 and math.isfinite(interval)):
        raise OutputError(f"a fill's interval is a length above 0 mm, got {interval!r}")
    polys = [P for P in (Loop(list(segs)).points() for segs in loops) if len(P) >= 3]
    if not polys:
        return []
    y0 = min(float(P[:, 1].min()) for P in polys)
    y1 = max(float(P[:, 1].max()) for P in polys)
    n = max(1, math.ceil((y1 - y0) / interval - 1e-9))
    if n > MAX_ROWS:
        raise OutputError(f"a fill {y1 - y0:.4g} mm tall at an interval of {interval:g} mm "
                          f"would run {n:,} lines; at most {MAX_ROWS:,}: raise the machine "
                          "profile's `fill.interval`")
    first = y0 + ((y1 - y0) - (n - 1) * interval) / 2
    out = []
    for piece in sorted(_pieces(polys), key=lambda ps: float(ps[0][:, 0].min())):
        lo = max(0, math.ceil((float(piece[0][:, 1].min()) - first) / interval - 1e-9))
        hi = min(n - 1, math.floor((float(piece[0][:, 1].max()) - first) / interval + 1e-9))
        out += _rows(piece, [first + k * interval for k in range(lo, hi + 1)])
    return out


def _pieces(polys: list) -> list[list]:
    """The loops grouped into pieces: each outer loop (one at an even depth: inside an even
    number of the others) with the counters directly inside it, the outer loop first."""
    boxes = [(P[:, 0].min(), P[:, 1].min(), P[:, 0].max(), P[:, 1].max()) for P in polys]
    areas = [abs(_area(P)) for P in polys]
    inside = []                                  # for each loop, the loops around it
    for i, P in enumerate(polys):
        x, y = float(P[0, 0]), float(P[0, 1])
        inside.append([j for j, b in enumerate(boxes) if j != i and b[0] <= x <= b[2]
                       and b[1] <= y <= b[3] and _contains(polys[j], x, y)])
    depth = [len(a) for a in inside]
    pieces = {i: [polys[i]] for i in range(len(polys)) if depth[i] % 2 == 0}
    for i in range(len(polys)):
        if depth[i] % 2:
            around = [j for j in inside[i] if depth[j] == depth[i] - 1]
            if around:
                pieces[min(around, key=lambda j: areas[j])].append(polys[i])
    return list(pieces.values())


def _area(P) -> float:
    x, y = P[:, 0], P[:, 1]
    return 0.5 * float((x * np.roll(y, -1) - np.roll(x, -1) * y).sum())


def _contains(P, x: float, y: float) -> bool:
    """Whether closed polyline ``P`` holds the point (even-odd)."""
    a, b = P, np.roll(P, -1, axis=0)
    hit = (a[:, 1] > y) != (b[:, 1] > y)
    if not hit.any():
        return False
    t = (y - a[hit, 1]) / (b[hit, 1] - a[hit, 1])
    return int((a[hit, 0] + t * (b[hit, 0] - a[hit, 0]) > x).sum()) % 2 == 1


def _rows(polys: list, ys: list) -> list[tuple[tuple, tuple]]:
    """The spans of rows ``ys`` where closed polylines ``polys`` wind non-zero, the rows
    alternately left to right and right to left."""
    if not ys:
        return []
    a = np.concatenate(polys)
    b = np.concatenate([np.roll(p, -1, axis=0) for p in polys])
    ya, yb = a[:, 1], b[:, 1]
    lo, hi = np.minimum(ya, yb), np.maximum(ya, yb)
    keep = hi > lo                                  # horizontal edges cross no row
    ax, ay, bx, by = a[keep, 0], ya[keep], b[keep, 0], yb[keep]
    lo, hi, wind = lo[keep], hi[keep], np.where(yb[keep] > ya[keep], 1, -1)
    out = []
    back = False
    for y in ys:
        hit = (lo <= y) & (y < hi)                  # half-open: a vertex counts once
        if not hit.any():
            continue
        t = (y - ay[hit]) / (by[hit] - ay[hit])
        xs = ax[hit] + t * (bx[hit] - ax[hit])
        order = np.argsort(xs, kind="stable")
        spans = []
        w, start = 0, None
        for x, dw in zip(xs[order].tolist(), wind[hit][order].tolist()):
            before, w = w, w + dw
            if before == 0 and w != 0:
                start = x
            elif before != 0 and w == 0 and start is not None and x > start:
                spans.append((start, x))
        if back:
            spans = [(x1, x0) for x0, x1 in reversed(spans)]
        back = not back if spans else back
        out += [((x0, y), (x1, y)) for x0, x1 in spans]
    return out
