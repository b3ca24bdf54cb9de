"""``aidl import --infer``: equal holes on rings about one centre (issue 85, bolt circles):
two bolt circles of one hole size about a flange's centre (5 on a 60 mm circle, 8 on a
32 mm one), or a bolt circle and a lone hole of its size, are no one pattern and too far
apart for :func:`~.patterns._features` to split; about the body's centre or a feature's
(a bore), split by their distance from it, each ring of three or more evenly spaced a bolt
circle of its own; and :func:`start_angle`, how a bolt circle's first hole is written so
that a new count keeps its meaning.  Coordinates in mm."""
from __future__ import annotations

import itertools
import math

from .find import _polar
from ..shapes import EQUAL_TOL

MAX_RINGS = 2000    # holes: more are a grille's, not rings about a centre


def rings(centers: list, about: list) -> list[list[int]] | None:
    """``centers`` split into rings about the first point of ``about`` they fit: each group
    of holes at one distance from it (within EQUAL_TOL), when every group of three or more
    is evenly round that point (:func:`~.patterns._polar`) and there are at least two
    groups, one of them such a ring; else None.  Groups of one or two are left to be
    written on their own, but for two left in all, in line with each other: one pair."""
    if len(centers) < 4 or len(centers) > MAX_RINGS:
        return None
    for c in about:
        by: dict = {}
        for i, p in enumerate(sorted(range(len(centers)),
                                     key=lambda k: math.dist(c, centers[k]))):
            d = math.dist(c, centers[p])
            last = max(by) if by else None
            if last is not None and d - by[last][0] <= EQUAL_TOL:
                by[last][1].append(p)
            else:
                by[i] = (d, [p])
        groups = [g for _, g in by.values()]
        if len(groups) < 2:
            continue
        big = [g for g in groups if len(g) >= 3]
        if big and all((pol := _polar([centers[k] for k in g])) is not None
                       and math.dist(pol[0], c) <= EQUAL_TOL for g in big):
            # the holes left one or two at a distance: a bolt circle of its own about
            # another centre when they are evenly round one (a second flange's)
            small = sorted(k for g in groups if len(g) < 3 for k in g)
            if len(small) >= 3 and _polar([centers[k] for k in small]) is not None:
                return [sorted(g) for g in big] + [small]
            # two left in line with each other (two holes by the far edge beside a motor's
            # four round its bore): one pair, a pattern of its own (issue 103)
            if len(small) == 2 and any(abs(centers[small[0]][a] - centers[small[1]][a])
                                       <= EQUAL_TOL for a in (0, 1)):
                return [sorted(g) for g in big] + [small]
            return [sorted(g) for g in groups]
    return None


MAX_SCATTER = 16    # holes: a ring sought among scattered holes by their triples (n^4)


def ring_in_scatter(centers: list) -> list[list[int]] | None:
    """Equal holes of no pattern that hold a bolt circle about a centre nothing marks (a
    flange's holes beside a board's of their size): ``[the ring, the rest]``, the ring the
    most holes evenly round one centre (three of them fix it), else None."""
    n = len(centers)
    if n < 4 or n > MAX_SCATTER:
        return None
    best: list = []
    for i, j, k in itertools.combinations(range(n), 3):
        c = _circumcentre(centers[i], centers[j], centers[k])
        if c is None:
            continue
        R = math.dist(c, centers[i])
        ring = [m for m in range(n) if abs(math.dist(c, centers[m]) - R) <= EQUAL_TOL]
        if len(best) < len(ring) < n:
            pol = _polar([centers[m] for m in ring])
            if pol is not None and math.dist(pol[0], c) <= EQUAL_TOL:
                best = ring
    if not best:
        return None
    return [best, [m for m in range(n) if m not in best]]


def _circumcentre(a, b, c) -> tuple | None:
    d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
    if abs(d) <= EQUAL_TOL:
        return None
    sa, sb, sc = (p[0] ** 2 + p[1] ** 2 for p in (a, b, c))
    return ((sa * (b[1] - c[1]) + sb * (c[1] - a[1]) + sc * (a[1] - b[1])) / d,
            (sa * (c[0] - b[0]) + sb * (a[0] - c[0]) + sc * (b[0] - a[0])) / d)


def _start(a0: float, n: int) -> float:
    """The angle (radians) of hole 0 of a bolt circle of ``n`` holes at ``a0 + k 360/n``, by
    the spec (docs/import.md, "What an edit means": a new count keeps the first hole where
    it is): a hole on the x axis (0), else one at the top (90 deg), else ``a0``, the first
    hole's drawn angle (issue 103: four holes at 45 deg keep one at 45 deg when they become
    six; they were read as straddling the x axis, the first then at 30 deg, 6.2 mm off on a
    47.5 mm circle).  Where two readings draw the same holes the x axis wins, then the top
    (4 or 8 holes with one at the top have one on the x axis; 6 at 30 deg have one at the
    top)."""
    step = 2 * math.pi / n

    def on(angle: float) -> bool:
        k = (angle - a0) / step
        return abs(k - round(k)) * step * 1e3 <= 1e-6      # 1e-9 rad at 1 m
    for angle in (0.0, math.pi / 2):
        if on(angle):
            return angle
    return a0


def start_angle(part, hn: str, a0: float, n: int, cnt: str) -> str:
    """The angle of hole ``i`` of a bolt circle ``hn`` of ``n`` (the param ``cnt``) whose
    holes are at ``a0 + k 360/n`` (radians), from a param ``<hn>_angle`` (issue 93: its first
    hole's angle, one word to turn the pattern): ``angle + i * 360 deg / n`` from the first
    hole's angle (:func:`_start`: on the x axis 0, at the top 90, else as drawn), so that a
    new count keeps the first hole where it is."""
    start = _start(a0, n)
    ang = part.p(f"{hn}_angle", math.degrees(start), "its first hole's, from the x axis",
                 unit="deg")
    return f"{ang} + i * 360 deg / {cnt}"
