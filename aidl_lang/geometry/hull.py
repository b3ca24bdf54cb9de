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

from .curves import Arc, Circle, Line, Loop, simplify
from .tessellate import segments_for

TWO_PI = 2 * math.pi


def tangent_normal(a: tuple, b: tuple) -> float | None:
    """The angle of the outward normal of the outer tangent from site ``a`` to site ``b``
    (``(cx, cy, r)``), both on its left (the hull runs counter-clockwise); None when one
    contains the other (no outer tangent)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    D = math.hypot(dx, dy)
    if D <= abs(a[2] - b[2]) or D == 0.0:
        return None
    return math.atan2(dy, dx) - math.acos((a[2] - b[2]) / D)


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
    """The sites of the outlines (``(cx, cy, r, lo, sweep)``: a point has r 0, a circle the
    whole turn, an arc its counter-clockwise angular range) and the samples
    ``(x, y, site)``."""
    sites: list = []
    index: dict = {}
    samples: list = []

    def point(p):
        key = (round(p[0], 9), round(p[1], 9))
        k = index.get(key)
        if k is None:
            k = index[key] = len(sites)
            sites.append((float(p[0]), float(p[1]), 0.0, 0.0, TWO_PI))
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
            k = len(sites)
            sites.append((float(s.center[0]), float(s.center[1]), float(s.radius), lo, sw))
            n = 4 * segments_for(s.radius, sw)
            first, last = (0, n) if isinstance(s, Circle) else (1, n - 1)
            for i in range(first, last + (0 if isinstance(s, Circle) else 1)):
                t = lo + sw * i / n
                samples.append((s.center[0] + s.radius * math.cos(t),
                                s.center[1] + s.radius * math.sin(t), k))
    return sites, samples


def _in_range(site, phi: float, tol: float = 1e-9) -> bool:
    if site[4] >= TWO_PI - 1e-12:
        return True
    return (phi - site[3] + tol) % TWO_PI <= site[4] + 2 * tol


def _support(site, phi: float) -> float:
    return site[0] * math.cos(phi) + site[1] * math.sin(phi) + site[2]


def hull_loop(loops: list[Loop]) -> Loop | None:
    """The exact convex hull (a counter-clockwise :class:`~.curves.Loop`) of the outlines
    ``loops`` (any orientation); None when it encloses no area (all points on one line)."""
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
            if phis[i] is None or phis[j] is None:
                bad = ("drop", j if sites[seq[j]][2] <= sites[seq[(j + 1) % n]][2] else k)
                break
            s = sites[seq[j]]
            if s[2] > 0 and not (_in_range(s, phis[i]) and _in_range(s, phis[j])):
                bad = ("split", j)
                break
            if n > 2:                            # j must reach past the tangent from i to k
                phi = tangent_normal(sites[seq[i]], sites[seq[k]])
                if phi is not None and _support(s, phi) <= _support(sites[seq[i]], phi) + tol:
                    bad = ("drop", j)
                    break
        if bad is None:
            break
        what, j = bad
        s = sites[seq[j]]
        if what == "split":
            ends = []
            for t in (s[3], s[3] + s[4]):
                p = (s[0] + s[2] * math.cos(t), s[1] + s[2] * math.sin(t))
                ends.append(next((m for m, q in enumerate(sites) if q[2] == 0.0
                                  and abs(q[0] - p[0]) <= tol and abs(q[1] - p[1]) <= tol), None))
            seq[j:j + 1] = [e for e in ends if e is not None]
        else:
            del seq[j]
        seq = [k for i, k in enumerate(seq) if k != seq[i - 1]] or seq[:1]
    if len(seq) == 1:
        s = sites[seq[0]]
        return Loop([Circle((s[0], s[1]), s[2])]) if s[2] > 0 and s[4] >= TWO_PI - 1e-12 else None
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
