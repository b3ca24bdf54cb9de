"""The constructors of shapes given by a list of points: ``Polygon`` (its points checked: no
repeats, some area, no crossing edges), ``Polyline``, ``Spline`` (with its corners) and
``Bezier``.
"""
from __future__ import annotations

import math

from ..core.values import NUM, Q, type_name
from .primitives import PrimitiveError, _point_list, _polygon_edges, _size, _start_xy


def _build_Polygon(ctx, g, a):
    pts_in = a["points"]
    if len(pts_in) < 3:
        raise PrimitiveError(f"a Polygon needs at least 3 points, got {len(pts_in)}")
    _check_polygon_points(ctx, pts_in)
    pts = _point_list(ctx, g, pts_in, a)
    g.data["edges"] = _polygon_edges(ctx, g, pts)
    g.closed = True


def _build_Polyline(ctx, g, a):
    """An open chain of straight segments through the points (closed=true: a Polygon)."""
    if a.get("closed"):
        _build_Polygon(ctx, g, a)
        g.data["closed"] = True
        return
    pts_in = a["points"]
    if len(pts_in) < 2:
        raise PrimitiveError(f"an open Polyline needs at least 2 points, got {len(pts_in)}")
    xy = _start_xy(ctx, pts_in)
    if xy is not None:
        scale = _size(xy)
        for i in range(len(xy) - 1):
            (x0, y0), (x1, y1) = xy[i], xy[i + 1]
            if math.hypot(x1 - x0, y1 - y0) <= 1e-9 * scale:
                raise PrimitiveError(f"a Polyline's points[{i}] and points[{i + 1}] are the "
                                     f"same point ({x0:g}, {y0:g}): a segment of zero "
                                     f"length; remove one of them")
    pts = _point_list(ctx, g, pts_in, a)
    g.data["closed"] = False
    g.data["edges"] = _polygon_edges(ctx, g, pts)[:-1]
    g.closed = False


def _build_Spline(ctx, g, a):
    from .spline import SplineError, check_points
    pts_in = a["points"]
    closed = bool(a.get("closed", False))
    xy = _start_xy(ctx, pts_in)
    try:
        check_points(xy if xy is not None else [(0.0, float(i)) for i in range(len(pts_in))],
                     closed)
    except SplineError as ex:
        raise PrimitiveError(str(ex)) from None
    pts = _point_list(ctx, g, pts_in, a)
    g.data["closed"] = closed
    g.data["corners"] = _spline_corners(ctx, a.get("corners"), len(pts), closed)
    g.closed = closed


def _build_Bezier(ctx, g, a):
    """A chain of cubic Bézier segments: ``points`` are ``p0, c1, c2, p1, c3, c4, p2, ...``
    (``3 k + 1`` for ``k`` segments, each ``p_i, c, c, p_i+1``, mm); ``closed``: the last point
    is the first (held as one point) and the chain is an outline.  The curve is the control
    points' own cubics, exactly (the carrier is :class:`~.spline.CubicSpline`)."""
    pts_in = list(a["points"])
    closed = bool(a.get("closed", False))
    m = len(pts_in)
    if m < 4 or (m - 1) % 3:
        k = max(1, round((m - 1) / 3))
        raise PrimitiveError(
            f"a Bezier chain takes 3k+1 points (p0, c1, c2, p1, c3, c4, p2, ...: each cubic "
            f"segment two control points and an end point), got {m}: give "
            f"{3 * k + 1} points for {k} segment{'s' if k != 1 else ''}"
            + (" (the last repeating the first when closed)" if closed else ""))
    if m > 3 * 2000 + 1:
        raise PrimitiveError(f"a Bezier chain takes at most {3 * 2000 + 1} points, got {m}")
    xy = _start_xy(ctx, pts_in)
    if xy is not None:
        scale = _size(xy)
        if closed and math.dist(xy[0], xy[-1]) > 1e-9 * scale:
            raise PrimitiveError(
                f"a closed Bezier chain ends where it starts: its last point "
                f"({xy[-1][0]:g}, {xy[-1][1]:g}) is not its first ({xy[0][0]:g}, "
                f"{xy[0][1]:g}); repeat the first point at the end, or use closed=false")
        for i in range(0, m - 1, 3):
            if all(math.dist(xy[i], xy[i + j]) <= 1e-9 * scale for j in (1, 2, 3)):
                raise PrimitiveError(
                    f"a Bezier's segment {i // 3} (points[{i}] to points[{i + 3}]) is one "
                    f"point ({xy[i][0]:g}, {xy[i][1]:g}): remove it")
    keep = pts_in[:-1] if closed else pts_in
    pts = _point_list(ctx, g, keep, a)
    g.data["closed"] = closed
    g.data["bezier"] = True
    g.closed = closed


def _spline_corners(ctx, v, m: int, closed: bool) -> tuple[int, ...]:
    """``corners=[i, ...]``: indices (0 .. m - 1) of a Spline's points where it turns sharply;
    an open spline's first and last points are ends already."""
    if v is None:
        return ()
    items = list(v) if isinstance(v, (list, tuple)) else [v]
    out = []
    for q in items:
        c = q.const() if isinstance(q, Q) and q.dim == NUM else None
        if c is None or abs(c - round(c)) > 1e-9:
            raise PrimitiveError(f"a Spline's corners are indices of its points (whole numbers "
                                 f"0 to {m - 1}), got {type_name(q) if c is None else f'{c:g}'}")
        i = int(round(c))
        if i < 0:
            i += m                                  # corners=[-1]: the last point, as lists
        if not 0 <= i < m:
            raise PrimitiveError(f"a Spline's corner {int(round(c))} is not one of its points "
                                 f"(indices 0 to {m - 1})")
        if not closed and i in (0, m - 1):
            raise PrimitiveError(f"corner {i} is an end of the open Spline, where it stops "
                                 f"anyway: name inner points (1 to {m - 2}), or use "
                                 f"closed=true")
        out.append(i)
    return tuple(sorted(set(out)))


def _check_polygon_points(ctx, pts) -> None:
    """Starting points: no two consecutive ones equal (a zero-length edge), not all on one
    line (no area)."""
    xy = _start_xy(ctx, pts)
    if xy is None:
        return
    n = len(xy)
    scale = _size(xy)
    for i in range(n):
        (x0, y0), (x1, y1) = xy[i], xy[(i + 1) % n]
        if math.hypot(x1 - x0, y1 - y0) <= 1e-9 * scale:
            raise PrimitiveError(f"a Polygon's points[{i}] and points[{(i + 1) % n}] are the "
                                 f"same point ({x0:g}, {y0:g}): an edge of zero length")
    area = sum(xy[i][0] * xy[(i + 1) % n][1] - xy[(i + 1) % n][0] * xy[i][1] for i in range(n))
    if abs(area) <= 1e-9 * scale * scale:
        _no_area(xy, scale)


def _no_area(xy, scale: float) -> None:
    """The E0108 of a Polygon whose starting points ``xy`` enclose no area: two edges that
    cross (a "bowtie" whose two halves cancel), with the points' order around their centre
    as the fix when that order does not cross; else all on one line, or an outline that goes
    out and back along itself."""
    crossing = _first_crossing(xy)
    if crossing is not None:
        i, j, (x, y) = crossing
        n = len(xy)
        hint = "reorder the points so that they go once around the outline without crossing"
        order = sorted(range(n), key=lambda k: math.atan2(xy[k][1] - sum(p[1] for p in xy) / n,
                                                          xy[k][0] - sum(p[0] for p in xy) / n))
        if _first_crossing([xy[k] for k in order]) is None:
            hint += (": " + ", ".join(f"points[{k}]" for k in order) + " ("
                     + ", ".join(f"({xy[k][0]:g}, {xy[k][1]:g})" for k in order) + ")")
        raise PrimitiveError(
            f"a Polygon's edges cross: edge {i} (points[{i}] to points[{(i + 1) % n}]) crosses "
            f"edge {j} (points[{j}] to points[{(j + 1) % n}]) at ({x:g}, {y:g}); the outline "
            "is self-intersecting (a bowtie) and its two halves cancel: it has no area",
            hint=hint)
    x0, y0 = xy[0]
    far = max(xy, key=lambda p: math.hypot(p[0] - x0, p[1] - y0))
    L = math.hypot(far[0] - x0, far[1] - y0)
    if all(abs((p[0] - x0) * (far[1] - y0) - (p[1] - y0) * (far[0] - x0)) <= 1e-9 * scale * L
           for p in xy):
        raise PrimitiveError("a Polygon's points are all on one line: it has no area")
    raise PrimitiveError("a Polygon's outline goes out and comes back along itself: it "
                         "encloses no area", hint="give it points that go once around an "
                         "inside, in order")


def _first_crossing(xy) -> tuple | None:
    """``(i, j, point)``: the first two edges ``i < j`` of the closed polygon ``xy`` (its
    points in order, mm) that cross each other properly (each edge's ends strictly on both
    sides of the other), or None; edges sharing a point are not compared.  None too past
    2,000 points (n^2 pairs, a check not worth its time there)."""
    import numpy as np            # only on this error's path
    n = len(xy)
    if n > 2000:
        return None
    P = np.asarray(xy, dtype=float)
    Q = np.roll(P, -1, axis=0)
    D = Q - P
    for i in range(n - 2):
        j = np.arange(i + 2, n - (1 if i == 0 else 0))
        if not len(j):
            continue
        a = D[i, 0] * (P[j, 1] - P[i, 1]) - D[i, 1] * (P[j, 0] - P[i, 0])
        b = D[i, 0] * (Q[j, 1] - P[i, 1]) - D[i, 1] * (Q[j, 0] - P[i, 0])
        c = D[j, 0] * (P[i, 1] - P[j, 1]) - D[j, 1] * (P[i, 0] - P[j, 0])
        d = D[j, 0] * (Q[i, 1] - P[j, 1]) - D[j, 1] * (Q[i, 0] - P[j, 0])
        hit = np.flatnonzero((a * b < 0) & (c * d < 0))
        if len(hit):
            k = int(j[hit[0]])
            u = float(c[hit[0]] / (c[hit[0]] - d[hit[0]]))
            x, y = P[i] + u * D[i]
            return i, k, (round(float(x), 9) + 0.0, round(float(y), 9) + 0.0)
    return None
