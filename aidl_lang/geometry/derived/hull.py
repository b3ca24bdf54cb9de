"""Exact convex hull of shapes made of lines, arcs and circles (``Hull(a, b, ...)``).

The hull of such shapes is bounded by pieces of their circles (arcs turning
counter-clockwise about their centers) and by the lines tangent to two consecutive ones
(:func:`tangent_normal`: the outer tangent of two circles, a point being a circle of radius
0).  Which circles, arcs and corner points lie on the hull, and in which order, is found on a
fine sampling of the outlines (Andrew's monotone chain, each sample labelled with the site it
came from); the hull itself is then built from the sites' exact centers and radii, so it
does not depend on the sampling: a belt around pulleys of radii r1 and r2 whose centers are
D apart has straight runs of sqrt(D^2 - (r1 - r2)^2) touching both circles exactly.

Source: the convex hull of disks (Rappaport, "A convex hull algorithm for discs", 1992)
reduced to its boundary's bitangents; all lengths mm, angles radians.
"""
from __future__ import annotations

import math

from ..shapes.curves import Arc, Circle, Line, Loop, simplify
from ..shapes.tessellate import segments_for

TWO_PI = 2 * math.pi
TOUCH = 1e-12          # relative: two sites this close to touching inside touch


def tangent_normal(a: tuple, b: tuple) -> float | None:
    """The angle of the outward normal of the outer tangent from site ``a`` to site ``b``
    (``(cx, cy, r)``), both on its left (the hull runs counter-clockwise); None when one
    contains the other (no outer tangent)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    D = math.hypot(dx, dy)
    dr = a[2] - b[2]
    gap = D - abs(dr)
    if D == 0.0 or gap < -TOUCH * max(1.0, D):
        return None
    if gap <= TOUCH * max(1.0, D):     # touching inside (an arc's end point on its circle):
        c = 1.0 if dr > 0 else -1.0    # acos is ill-conditioned there (1e-15 -> 4e-8 rad)
    else:
        c = dr / D
    return math.atan2(dy, dx) - math.acos(c)


def _touching(a: tuple, b: tuple) -> bool:
    """Whether sites ``a`` and ``b`` touch inside (one on the other's circle, or the same
    circle): their outer tangent has no length."""
    D = math.hypot(b[0] - a[0], b[1] - a[1])
    return abs(D - abs(a[2] - b[2])) <= TOUCH * max(1.0, D)


def _cross(o, a, b) -> float:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _monotone_chain(pts: list) -> list:
    """Indices of the convex hull of ``pts`` ((x, y, label)), counter-clockwise, collinear
    points left out (Andrew 1979)."""
    order = sorted(range(len(pts)), key=lambda i: (pts[i][0], pts[i][1]))
    lower: list = []
    for i in order:
        while len(lower) >= 2 and _cross(pts[lower[-2]], pts[lower[-1]], pts[i]) <= 0:
            lower.pop()
        lower.append(i)
    upper: list = []
    for i in reversed(order):
        while len(upper) >= 2 and _cross(pts[upper[-2]], pts[upper[-1]], pts[i]) <= 0:
            upper.pop()
        upper.append(i)
    return lower[:-1] + upper[:-1]


def _sites(loops: list[Loop]):
    """The sites of the outlines (``(cx, cy, r, ranges)``: a point has r 0, a circle the
    whole turn, the arcs of one circle their counter-clockwise angular ranges
    ``[(lo, sweep), ...]``) and the samples ``(x, y, site)``."""
    sites: list = []
    index: dict = {}
    samples: list = []

    def point(p):
        key = (round(p[0], 9), round(p[1], 9))
        k = index.get(key)
        if k is None:
            k = index[key] = len(sites)
            sites.append((float(p[0]), float(p[1]), 0.0, [(0.0, TWO_PI)]))
            samples.append((float(p[0]), float(p[1]), k))
        return k

    for lp in loops:
        for s in lp.segments:
            if isinstance(s, Line):
                point(s.start)
                point(s.end)
                continue
            if isinstance(s, Circle):
                lo, sw = 0.0, TWO_PI
            else:
                point(s.start)
                point(s.end)
                lo, sw = (s.start_angle, s.sweep) if s.sweep > 0 else (s.end_angle, -s.sweep)
            key = ("C",) + tuple(round(float(v), 9) for v in (*s.center, s.radius))
            k = index.get(key)
            if k is None:                      # arcs of one circle: one site, their ranges
                k = index[key] = len(sites)
                sites.append((float(s.center[0]), float(s.center[1]), float(s.radius), []))
            if (lo, sw) in sites[k][3]:
                continue
            sites[k][3].append((lo, sw))
            n = 4 * segments_for(s.radius, sw)
            first, last = (0, n - 1) if isinstance(s, Circle) else (1, n - 1)
            for i in range(first, last + 1):
                t = lo + sw * i / n
                samples.append((s.center[0] + s.radius * math.cos(t),
                                s.center[1] + s.radius * math.sin(t), k))
    return sites, samples


def _in_range(site, phi: float, tol: float = 1e-9) -> bool:
    return any(sw >= TWO_PI - 1e-12 or (phi - lo + tol) % TWO_PI <= sw + 2 * tol
               for lo, sw in site[3])


def _support(site, phi: float) -> float:
    return site[0] * math.cos(phi) + site[1] * math.sin(phi) + site[2]


def hull_loop(loops: list[Loop]) -> Loop | None:
    """The exact convex hull (a counter-clockwise :class:`~.curves.Loop`) of the outlines
    ``loops`` (any orientation); None when it encloses no area (all points on one line).
    Outlines holding elliptic arcs go to :func:`envelope_hull`."""
    from ..shapes.curves import EllipticArc
    if any(isinstance(s, EllipticArc) for lp in loops for s in lp.segments):
        return envelope_hull(loops)
    sites, samples = _sites(loops)
    if len(samples) < 3:
        return None
    seq = [samples[i][2] for i in _monotone_chain(samples)]
    seq = [k for i, k in enumerate(seq) if k != seq[i - 1]] or seq[:1]
    scale = max(1.0, max(abs(v) for s in sites for v in s[:3]))
    tol = 1e-9 * scale
    for _ in range(4 * len(seq) + 8):           # drop or split sites the exact hull refuses
        if len(seq) == 1:
            break
        n = len(seq)
        phis = [tangent_normal(sites[seq[i]], sites[seq[(i + 1) % n]]) for i in range(n)]
        bad = None
        for j in range(n):
            i, k = (j - 1) % n, (j + 1) % n
            if phis[i] is None or phis[j] is None:      # one of a pair holds the other
                a, b = (i, j) if phis[i] is None else (j, k)
                bad = ("drop", a if sites[seq[a]][2] <= sites[seq[b]][2] else b)
                break
            s = sites[seq[j]]
            if s[2] > 0 and not (_in_range(s, phis[i]) and _in_range(s, phis[j])):
                bad = ("split", j)
                break
            if n > 2 and not _touching(sites[seq[i]], sites[seq[k]]):
                # j must reach past the tangent from i to k (a point on i's circle, an arc's
                # end, has a tangent of no length: it says nothing of j, issue 109)
                phi = tangent_normal(sites[seq[i]], sites[seq[k]])
                if phi is not None and all(q[2] == 0 or _in_range(q, phi)
                                           for q in (sites[seq[i]], sites[seq[k]])) \
                        and _support(s, phi) < _support(sites[seq[i]], phi) - tol:
                    # (strictly inside: a site on the tangent's line may lie past its end)
                    bad = ("drop", j)
                    break
        if bad is None:
            # a site the sampling missed (an arc bulging past a tangent by less than the
            # samples' spacing): the one reaching farthest past a tangent goes in there
            best = None
            for i in range(n):
                if phis[i] is None:
                    continue
                ref = _support(sites[seq[i]], phis[i]) + tol
                for m, q in enumerate(sites):
                    if m in (seq[i], seq[(i + 1) % n]) or (q[2] > 0 and not _in_range(q, phis[i])):
                        continue
                    out = _support(q, phis[i]) - ref
                    if out > 0 and (best is None or out > best[0]):
                        best = (out, i, m)
            if best is None:
                break
            seq.insert(best[1] + 1, best[2])
            continue
        what, j = bad
        s = sites[seq[j]]
        if what == "split":                     # the arcs' ends instead, in turn from phi_in
            start = phis[(j - 1) % n] or 0.0
            ends = []
            for lo, sw in s[3]:
                for t in (lo, lo + sw):
                    p = (s[0] + s[2] * math.cos(t), s[1] + s[2] * math.sin(t))
                    m = next((m for m, q in enumerate(sites) if q[2] == 0.0
                              and abs(q[0] - p[0]) <= tol and abs(q[1] - p[1]) <= tol), None)
                    if m is not None and m not in ends:
                        ends.append(((t - start) % TWO_PI, m))
            seq[j:j + 1] = [m for _, m in sorted(ends)]
        else:
            del seq[j]
        seq = [k for i, k in enumerate(seq) if k != seq[i - 1]] or seq[:1]
    if len(seq) == 1:
        s = sites[seq[0]]
        whole = s[2] > 0 and sum(sw for _, sw in s[3]) >= TWO_PI - 1e-9
        return Loop([Circle((s[0], s[1]), s[2])]) if whole else None
    n = len(seq)
    phis = [tangent_normal(sites[seq[i]], sites[seq[(i + 1) % n]]) for i in range(n)]
    segs: list = []
    for j in range(n):
        s = sites[seq[j]]
        a_in, a_out = phis[j - 1], phis[j]
        if s[2] > 0:
            sw = (a_out - a_in) % TWO_PI
            if sw > 1e-12:
                segs.append(Arc((s[0], s[1]), s[2], a_in, sw))
        t = sites[seq[(j + 1) % n]]
        p = (s[0] + s[2] * math.cos(a_out), s[1] + s[2] * math.sin(a_out))
        q = (t[0] + t[2] * math.cos(a_out), t[1] + t[2] * math.sin(a_out))
        segs.append(Line(p, q))
    lp = Loop(simplify(segs, scale))
    return lp if lp.segments and lp.area > tol else None


# ------------------------------------------------------------ hulls with ellipses
ENVELOPE_SAMPLES = 2048     # directions where the first guess of the supporting site is made
SNAP = 1e-6                 # rad: a turn this close to an arc's end is its end


def _ellipse_support(e, phi: float):
    """``(h, t)``: the support of ellipse ``e`` in the direction ``phi`` and the parameter of
    its point there (where its outward normal points along ``phi``)."""
    a = phi - e.rotation
    nx, ny = math.cos(a), math.sin(a)
    t = math.atan2(e.ry * ny, e.rx * nx)
    return (e.center[0] * math.cos(phi) + e.center[1] * math.sin(phi)
            + math.hypot(e.rx * nx, e.ry * ny)), t


def _in_ranges(ranges, a: float) -> bool:
    return any(sw >= TWO_PI - 1e-12 or (a - lo + 1e-12) % TWO_PI <= sw + 2e-12
               for lo, sw in ranges)


class _Site:
    """One piece the hull may run along: a point (``kind`` "P"), a circle ("C": ranges of the
    outward normal's angle) or an ellipse ("E": ranges of its parameter)."""
    __slots__ = ("kind", "data", "ranges")

    def __init__(self, kind, data, ranges):
        self.kind, self.data, self.ranges = kind, data, ranges

    def support(self, phi: float) -> float:
        c, s = math.cos(phi), math.sin(phi)
        if self.kind == "P":
            return self.data[0] * c + self.data[1] * s
        if self.kind == "C":
            if not _in_ranges(self.ranges, phi):
                return -math.inf
            cx, cy, r = self.data
            return cx * c + cy * s + r
        h, t = _ellipse_support(self.data, phi)
        return h if _in_ranges(self.ranges, t) else -math.inf

    def param(self, phi: float) -> float:
        """The angle (circle) or parameter (ellipse) of the site's point supporting ``phi``,
        snapped to the end of a range within :data:`SNAP`."""
        a = phi if self.kind == "C" else _ellipse_support(self.data, phi)[1]
        for lo, sw in self.ranges:
            if sw >= TWO_PI - 1e-12:
                continue
            for end in (lo, lo + sw):
                d = (a - end + math.pi) % TWO_PI - math.pi
                if abs(d) <= SNAP:
                    return a - d
        return a

    def point(self, phi: float):
        if self.kind == "P":
            return self.data
        a = self.param(phi)
        if self.kind == "C":
            cx, cy, r = self.data
            return (cx + r * math.cos(a), cy + r * math.sin(a))
        return self.data.at(a)


def _envelope_sites(loops: list[Loop]) -> list[_Site]:
    from ..shapes.curves import EllipticArc
    sites: list[_Site] = []
    index: dict = {}

    def add(key, kind, data, rng):
        k = index.get(key)
        if k is None:
            k = index[key] = len(sites)
            sites.append(_Site(kind, data, []))
        if rng is not None and rng not in sites[k].ranges:
            sites[k].ranges.append(rng)

    for lp in loops:
        for s in lp.segments:
            if not isinstance(s, Circle) and not (isinstance(s, EllipticArc) and s.whole):
                for p in (s.start, s.end):
                    add(("P", round(p[0], 9), round(p[1], 9)), "P", (float(p[0]), float(p[1])),
                        None)
            if isinstance(s, Line):
                continue
            if isinstance(s, EllipticArc):
                e = s.curve
                rng = (0.0, TWO_PI) if s.whole else \
                    ((s.start_param, s.sweep) if s.sweep > 0 else (s.end_param, -s.sweep))
                add(("E", round(e.center[0], 9), round(e.center[1], 9), round(e.rx, 9),
                     round(e.ry, 9), round(e.rotation, 12)), "E", e, rng)
                continue
            if isinstance(s, Circle):
                rng = (0.0, TWO_PI)
            else:
                rng = (s.start_angle, s.sweep) if s.sweep > 0 else (s.end_angle, -s.sweep)
            add(("C",) + tuple(round(float(v), 9) for v in (*s.center, s.radius)), "C",
                (float(s.center[0]), float(s.center[1]), float(s.radius)), rng)
    return sites


def _best(sites, phi: float) -> int:
    best, k = -math.inf, 0
    for i, s in enumerate(sites):
        h = s.support(phi)
        if h > best:
            best, k = h, i
    return k


def _switches(sites, a: float, ia: int, b: float, ib: int, out: list, depth: int = 0) -> None:
    """Append ``(phi, site)`` for every change of the supporting site between directions
    ``a`` (site ``ia``) and ``b`` (site ``ib``), found by bisection to the last bit."""
    while True:
        m = 0.5 * (a + b)
        if m <= a or m >= b:
            break
        im = _best(sites, m)
        if im == ia:
            a = m
        elif im == ib:
            b = m
        else:
            if depth < 64:
                _switches(sites, a, ia, m, im, out, depth + 1)
                _switches(sites, m, im, b, ib, out, depth + 1)
                return
            a = m
    out.append((b, ib))


def envelope_hull(loops: list[Loop]) -> Loop | None:
    """The exact convex hull of outlines holding elliptic arcs (and lines, arcs, circles):
    the upper envelope of the pieces' support functions over the direction ``phi`` of the
    outward normal.  Each piece's share is found on :data:`ENVELOPE_SAMPLES` directions and
    its ends by bisection to the last bit (a piece that beats both sides at a switching
    direction, missed between two samples, is sampled there and the envelope found again); the hull runs along each supporting piece (an
    :class:`~.curves.EllipticArc` of its own ellipse, an :class:`~.curves.Arc` of its own
    circle) and along the line tangent to two consecutive ones at the switching direction,
    whose ends lie on the two curves.  None when the hull encloses no area."""
    from ..shapes.curves import EllipticArc
    sites = _envelope_sites(loops)
    if not sites:
        return None
    N = ENVELOPE_SAMPLES
    phis = [TWO_PI * k / N for k in range(N)]
    scale = max(1.0, max(abs(v) for lp in loops for s in lp.segments for v in s.box()))
    tol = 1e-9 * scale
    for _ in range(8):
        lab = [_best(sites, p) for p in phis]
        sw: list = []
        for k in range(len(phis)):
            a = phis[k]
            b = phis[k + 1] if k + 1 < len(phis) else phis[0] + TWO_PI
            ia, ib = lab[k], lab[(k + 1) % len(phis)]
            if ia != ib:
                _switches(sites, a, ia, b, ib, sw)
        # a site the sampling missed (a point or small circle past a tangent line by less
        # than the samples' spacing) wins at a switching direction: sample it there, again
        missed = [phi for phi, k in sw if sites[_best(sites, phi)].support(phi)
                  > sites[k].support(phi) + tol]
        if not missed:
            break
        phis = sorted(set(phis) | {m % TWO_PI for m in missed})
    if not sw:
        s = sites[lab[0]]
        if s.kind == "E":
            return Loop([EllipticArc(s.data, 0.0, TWO_PI)])
        if s.kind == "C":
            return Loop([Circle(s.data[:2], s.data[2])])
        return None
    segs: list = []
    n = len(sw)
    for j in range(n):
        phi_in, k = sw[j - 1]
        phi_out, nxt = sw[j]
        s = sites[k]
        turn = (phi_out - phi_in) % TWO_PI
        if s.kind == "C" and turn > 1e-12:
            a0 = s.param(phi_in)
            a1 = s.param(phi_out)
            segs.append(Arc(s.data[:2], s.data[2], a0, (a1 - a0) % TWO_PI or TWO_PI))
        elif s.kind == "E" and turn > 1e-12:
            t0, t1 = s.param(phi_in), s.param(phi_out)
            segs.append(EllipticArc(s.data, t0, (t1 - t0) % TWO_PI or TWO_PI))
        p, q = s.point(phi_out), sites[nxt].point(phi_out)
        if math.dist(p, q) > tol:
            segs.append(Line(p, q))
    lp = Loop(simplify(segs, scale))
    return lp if lp.segments and lp.area > tol else None
