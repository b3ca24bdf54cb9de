"""``aidl import --snap TOL``: cubic Béziers that are circles and arcs within ``TOL`` taken
as the true circles and arcs (issue 71; docs/import.md, "Snapping Bézier circles").

Writers such as Boxes.py draw every circle and arc as cubic Béziers with numbers rounded to 3
decimals, so no curve of theirs is exactly round and an exact-only import keeps them as
splines.  :func:`snap_drawing` replaces, in a :class:`~.model.Drawing` read from a file:

* a closed loop made only of Bézier pieces that lies within ``TOL`` of one circle by a
  :class:`~aidl_lang.geometry.shapes.curves.Circle` (the drawing's ``circles``);
* a run of Bézier pieces in a loop or an open path that lies within ``TOL`` of one arc by an
  :class:`~aidl_lang.geometry.shapes.curves.Arc` through the run's own two ends (the loop stays
  closed, its neighbours untouched); a run that is no one arc is cut where it stops being
  one (a burn corner of 0.1 mm, then a straight piece, ...).

Radii within ``TOL`` of each other are then made one (a hole size drawn 1.499 and 1.501 is
3 mm across both times): the shortest decimal within every member's tolerance, kept only
where every curve so changed stays within ``TOL`` of its Béziers; a circle's centre likewise
the shortest decimal within it.  Deviation is the largest distance of the Béziers from the
snapped curve, taken at :data:`SAMPLES` points of each Bézier span (a span this short that is
within ``TOL`` at those points is within it between them for any arc under a half turn per
span); what is not within ``TOL`` stays the exact spline.

In: the drawing (mm) and ``TOL`` (mm, > 0).  Out: the drawing changed in place and a
:class:`SnapReport` (counts, the largest deviation) for the import's header and a note.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from ...geometry.shapes.curves import Arc, Circle, Spline
from ..model import Drawing

SAMPLES = 16        # points per Bézier span at which the deviation is taken
MAX_SNAP = 10.0     # mm: the largest tolerance --snap takes


@dataclass
class SnapReport:
    """What :func:`snap_drawing` did: circles and arcs made from Béziers, radius groups made
    one, and the largest distance (mm) of a replaced Bézier from its snapped curve."""
    circles: int = 0
    arcs: int = 0
    groups: int = 0
    deviation: float = 0.0
    radii: list = field(default_factory=list)


def header_line(reports: list, tol: float) -> str:
    """The program header's line of what the layers' :func:`snap_drawing` did."""
    c, a = sum(r.circles for r in reports), sum(r.arcs for r in reports)
    if not (c or a):
        return f"snapped (--snap {tol:g} mm): nothing, no Bézier curve is a circle or an arc " \
               f"within it"
    return (f"snapped (--snap {tol:g} mm): {c} Bézier circles and {a} Bézier arcs taken as "
            f"true ones, {sum(r.groups for r in reports)} groups of near-equal radii made one; "
            f"largest deviation {max(r.deviation for r in reports):.3g} mm")


def _bez(b, t: float):
    s = 1 - t
    return (s * s * s * b[0][0] + 3 * s * s * t * b[1][0] + 3 * s * t * t * b[2][0] + t * t * t * b[3][0],
            s * s * s * b[0][1] + 3 * s * s * t * b[1][1] + 3 * s * t * t * b[2][1] + t * t * t * b[3][1])


def _samples(pieces: list) -> list:
    """Points of Bézier pieces in order (each span at :data:`SAMPLES` steps)."""
    pts = []
    for p in pieces:
        for b in p.spans:
            pts += [_bez(b, i / SAMPLES) for i in range(SAMPLES)]
    pts.append(pieces[-1].end)
    return pts


def _fit(pts: list):
    """The least-squares circle (Kåsa) of ``pts``: ``(centre, radius)`` or None."""
    n = len(pts)
    mx = sum(p[0] for p in pts) / n
    my = sum(p[1] for p in pts) / n
    suu = svv = suv = suuu = svvv = suvv = svuu = 0.0
    for x, y in pts:
        u, v = x - mx, y - my
        suu += u * u
        svv += v * v
        suv += u * v
        suuu += u * u * u
        svvv += v * v * v
        suvv += u * v * v
        svuu += v * u * u
    det = suu * svv - suv * suv
    if abs(det) <= 1e-18 * max(1.0, suu * svv):
        return None
    a, b = (suuu + suvv) / 2, (svvv + svuu) / 2
    uc = (a * svv - b * suv) / det
    vc = (b * suu - a * suv) / det
    r = math.sqrt(uc * uc + vc * vc + (suu + svv) / n)
    return (mx + uc, my + vc), r


def _dev(pts: list, c, r: float) -> float:
    return max(abs(math.dist(p, c) - r) for p in pts)


def _turn(pts: list, c) -> float:
    """The signed angle the points go round ``c`` (radians, > 0 counter-clockwise)."""
    tot = 0.0
    for p, q in zip(pts, pts[1:]):
        a = math.atan2(p[1] - c[1], p[0] - c[0])
        b = math.atan2(q[1] - c[1], q[0] - c[0])
        tot += (b - a + math.pi) % (2 * math.pi) - math.pi
    return tot


def _short(v: float, lo: float, hi: float) -> float:
    """The number of fewest decimals in ``[lo, hi]`` nearest ``v``."""
    for digits in range(10):
        r = round(v, digits)
        if lo <= r <= hi:
            return r
        step = 10.0 ** -digits
        for q in (math.floor(v / step) * step, math.ceil(v / step) * step):
            if lo <= q <= hi:
                return round(q, digits)
    return v


def _arc_through(a, b, pts: list, tol: float, r_want: float | None = None):
    """The arc from ``a`` to ``b`` nearest ``pts`` (its centre on their bisector; radius
    ``r_want`` when given), its deviation: ``(Arc, deviation)`` or None."""
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    half = math.dist(a, b) / 2
    if half <= 1e-9:
        return None
    nx, ny = -(b[1] - a[1]) / (2 * half), (b[0] - a[0]) / (2 * half)
    fit = _fit(pts)
    if fit is None:
        return None
    (cx, cy), r = fit
    s = (cx - mid[0]) * nx + (cy - mid[1]) * ny          # the fit's centre on the bisector
    if r_want is not None:
        if r_want < half:
            return None
        h = math.sqrt(r_want * r_want - half * half)
        s = h if s >= 0 else -h
    c = (mid[0] + s * nx, mid[1] + s * ny)
    r = math.dist(c, a)
    turn = _turn(pts, c)
    if abs(turn) < 1e-9 or abs(turn) >= 2 * math.pi - 1e-9:
        return None
    a0 = math.atan2(a[1] - c[1], a[0] - c[0])
    a1 = math.atan2(b[1] - c[1], b[0] - c[0])
    sweep = (a1 - a0) % (2 * math.pi) if turn > 0 else -((a0 - a1) % (2 * math.pi))
    if abs(sweep - turn) > 1e-3:
        return None
    return Arc(c, r, a0, sweep), _dev(pts, c, r)


def _snap_run(pieces: list, tol: float, rep: SnapReport) -> list:
    """The pieces of one run with each longest stretch that is one arc within ``tol`` an
    :class:`Arc` (greedy from the start), the rest as they were."""
    out, i = [], 0
    while i < len(pieces):
        best = None
        for j in range(i + 1, len(pieces) + 1):
            pts = _samples(pieces[i:j])
            got = _arc_through(pieces[i].start, pieces[j - 1].end, pts, tol)
            if got is None or got[1] > tol:
                break
            best = (j, got, pts)
        if best is None:
            out.append(pieces[i])
            i += 1
            continue
        j, (arc, dev), pts = best
        out.append(_Snapped(arc, pts))
        rep.arcs += 1
        rep.deviation = max(rep.deviation, dev)
        i = j
    return out


class _Snapped:
    """An arc made from Béziers and the Bézier points it must stay within ``tol`` of."""

    def __init__(self, arc: Arc, pts: list) -> None:
        self.arc, self.pts = arc, pts


def _snap_segments(segs: list, cyclic: bool, tol: float, rep: SnapReport) -> list:
    """``segs`` with each run of Bézier pieces snapped (:func:`_snap_run`); a loop
    (``cyclic``) first turned to start on a piece that is no Bézier, so no run wraps."""
    if cyclic and not all(isinstance(x, Spline) for x in segs):
        k = next(i for i, x in enumerate(segs) if not isinstance(x, Spline))
        segs = segs[k:] + segs[:k]
    out, i = [], 0
    while i < len(segs):
        if not isinstance(segs[i], Spline):
            out.append(segs[i])
            i += 1
            continue
        j = i
        while j < len(segs) and isinstance(segs[j], Spline):
            j += 1
        out += _snap_run(segs[i:j], tol, rep)
        i = j
    return out


def _whole_circle(segs: list, tol: float):
    """A loop of Bézier pieces alone that is one circle within ``tol``: ``(centre, radius,
    points)`` or None."""
    if not segs or not all(isinstance(s, Spline) for s in segs):
        return None
    pts = _samples(segs)
    fit = _fit(pts)
    if fit is None:
        return None
    c, r = fit
    if _dev(pts, c, r) > tol or abs(abs(_turn(pts, c)) - 2 * math.pi) > 1e-3:
        return None
    return c, r, pts


def snap_drawing(d: Drawing, tol: float) -> SnapReport:
    """Snap the Bézier circles and arcs of ``d`` (and of its engraving) within ``tol`` mm
    (the module's docstring); returns what was done."""
    rep = SnapReport()
    circles: list = []          # (index in d.circles, Bézier points)
    arcs: list = []             # (container list, index, _Snapped)
    for dd in [d] + ([d.engrave] if d.engrave is not None else []):
        keep = []
        for o in dd.outlines:
            got = _whole_circle(o.segments, tol)
            if got is None:
                o.segments = _snap_segments(o.segments, True, tol, rep)
                keep.append(o)
                continue
            c, r, pts = got
            dd.circles.append(Circle(c, r, _turn(pts, c) > 0))
            circles.append((dd.circles, len(dd.circles) - 1, pts))
            rep.circles += 1
            rep.deviation = max(rep.deviation, _dev(pts, c, r))
        dd.outlines = keep
        for p in dd.paths:
            p.segments = _snap_segments(p.segments, False, tol, rep)
        for holder in list(dd.outlines) + list(dd.paths):
            for i, s in enumerate(holder.segments):
                if isinstance(s, _Snapped):
                    arcs.append((holder.segments, i, s))
    _group(circles, arcs, tol, rep)
    for segs, i, s in arcs:
        if isinstance(segs[i], _Snapped):
            segs[i] = segs[i].arc
    return rep


def _group(circles: list, arcs: list, tol: float, rep: SnapReport) -> None:
    """Radii within ``tol`` of each other made one (the shortest decimal every member takes
    within ``tol`` of its Béziers); circle centres the shortest decimals within ``tol``."""
    items = [("c", r) for r in circles] + [("a", a) for a in arcs]
    radius = [c[0][c[1]].radius if k == "c" else c[2].arc.radius for k, c in items]
    order = sorted(range(len(items)), key=lambda i: radius[i])
    groups, cur = [], []
    for i in order:
        if cur and radius[i] - radius[cur[0]] > tol:
            groups.append(cur)
            cur = []
        cur.append(i)
    if cur:
        groups.append(cur)
    for g in groups:
        lo = max(radius[i] for i in g) - tol
        hi = min(radius[i] for i in g) + tol
        mid = sorted(radius[i] for i in g)[len(g) // 2]
        want = _short(mid, lo, hi) if lo <= hi else None
        if want is None:
            continue
        made = []
        for i in g:
            kind, it = items[i]
            if kind == "c":
                segs, k, pts = it
                c0 = segs[k]
                c = tuple(_short(v, v - tol / 4, v + tol / 4) for v in c0.center)
                if _dev(pts, c, want) > tol:
                    c = c0.center
                if _dev(pts, c, want) > tol:
                    made = None
                    break
                made.append((i, Circle(c, want, c0.ccw), _dev(pts, c, want)))
            else:
                segs, k, s = it
                got = _arc_through(s.arc.start, s.arc.end, s.pts, tol, want)
                if got is None or got[1] > tol:
                    made = None
                    break
                made.append((i, _Snapped(got[0], s.pts), got[1]))
        if made is None:
            continue
        if len({radius[i] for i in g}) > 1:
            rep.groups += 1
        rep.radii.append((want, len(g)))
        for i, new, dev in made:
            kind, it = items[i]
            it[0][it[1]] = new
            rep.deviation = max(rep.deviation, dev)
