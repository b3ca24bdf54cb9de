"""The part of each hole that cuts its solid, made only when read.

:attr:`.booleans.Drawing.hole_outlines`: a list of N x 2 arrays (mm, the drawing's frame) as
read; only the SVG writer's ``--show holes`` reads them, so the booleans record each solid's
shape and its holes' union (Manifold ``CrossSection`` objects) and the symmetric difference
is taken on the first read (20,000 holes: 0.5 s of every compile saved).
"""
from __future__ import annotations

import numpy as np

from .scanwork import TURN


class HoleOutlines:
    """Recorded ``(shape, holes, turned)`` cuts, then the outlines' arrays once read."""
    __slots__ = ("_items",)

    def __init__(self):
        self._items: list = []          # (shape, holes, turned) not yet made, then arrays

    def cut(self, shape, holes=None, turned: bool = False) -> None:
        """``shape ^ holes`` (``holes`` None: the whole ``shape`` is a hole's part);
        ``turned``: both are a quarter turn from the drawing (:data:`.scanwork.TURN` back,
        exact), as a row along x is united."""
        self._items.append((shape, holes, turned))

    def _made(self) -> list:
        if any(isinstance(x, tuple) for x in self._items):
            self._items = [np.asarray(q) for x in self._items
                           for q in (_polygons(*x) if isinstance(x, tuple) else [x])]
        return self._items

    def __iter__(self):
        return iter(self._made())

    def __len__(self) -> int:
        return len(self._made())

    def __getitem__(self, i):
        return self._made()[i]

    def __eq__(self, other):
        return list(self) == list(other)


def _polygons(shape, holes, turned: bool) -> list:
    part = shape if holes is None else shape ^ holes
    return (part.transform(TURN) if turned else part).to_polygons()
