"""``aidl import --infer``: equal holes on rings about one centre (issue 85, bolt circles):
two bolt circles of one hole size about a flange's centre (5 on a 60 mm circle, 8 on a
32 mm one), or a bolt circle and a lone hole of its size, are no one pattern and too far
apart for :func:`~.patterns._features` to split; about the body's centre or a feature's
(a bore), split by their distance from it, each ring of three or more evenly spaced a bolt
circle of its own.  Coordinates in mm."""
from __future__ import annotations

import math

from .patterns import _polar
from .shapes import EQUAL_TOL

MAX_RINGS = 2000    # holes: more are a grille's, not rings about a centre


def rings(centers: list, about: list) -> list[list[int]] | None:
    """``centers`` split into rings about the first point of ``about`` they fit: each group
    of holes at one distance from it (within EQUAL_TOL), when every group of three or more
    is evenly round that point (:func:`~.patterns._polar`) and there are at least two
    groups, one of them such a ring; else None.  Groups of one or two are left to be
    written on their own."""
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
            return [sorted(g) for g in groups]
    return None
