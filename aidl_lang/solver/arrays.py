"""Small array helpers for the solver.

:func:`unique` is ``np.unique`` for 1-D integer arrays without its masked-array test: NumPy's
``np.unique`` asks ``np.ma.is_masked`` and so imports ``numpy.ma`` (about 15 ms) on a cold
``aidl check``.

:func:`gc_paused` holds Python's cyclic garbage collector off while the rows and the tape are
built: those phases allocate hundreds of thousands of small acyclic objects (expression nodes,
tuples, dicts), and each allocation burst triggered full collections that traversed the whole
model (measured: about half of ``build_rows`` on the 500-structure model, ``docs/solver.md``);
on leaving, what it built goes straight to the oldest generation.
"""
from __future__ import annotations

import gc
from contextlib import contextmanager

import numpy as np


@contextmanager
def gc_paused():
    """Disable the cyclic garbage collector inside the block (reference counting still frees
    everything acyclic); restores the previous state, also on an exception.  Nested use is
    fine: only the outermost block re-enables it.

    What the block built and kept (a model's rows: tens of thousands of expression nodes) is
    long-lived, so on leaving, the tracked objects are moved straight to the oldest generation
    (``gc.freeze()`` then ``gc.unfreeze()``) instead of being traversed by the next young
    collection and again by a middle one (12-18 ms, and up to ~70 ms, on the 500-structure
    model).  Nothing is kept from the collector: the next full collection sees them all
    (young garbage cycles made elsewhere just before are collected then too, not at the next
    young collection).  Only when the block left at least ``PROMOTE_MIN`` young objects (a
    small compile promotes nothing), and never when someone else holds objects frozen
    (``gc.get_freeze_count()``)."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            if gc.get_count()[0] >= PROMOTE_MIN and not gc.get_freeze_count():
                gc.freeze()
                gc.unfreeze()
            gc.enable()


PROMOTE_MIN = 10_000     # young objects left by a paused block before they are promoted


def unique(a) -> np.ndarray:
    """The sorted distinct values of the 1-D array ``a`` (shape ``(k,)``, ``a``'s dtype), equal
    to ``np.unique(a)``."""
    a = np.sort(np.asarray(a).ravel())
    if a.size < 2:
        return a
    keep = np.empty(a.size, dtype=bool)
    keep[0] = True
    np.not_equal(a[1:], a[:-1], out=keep[1:])
    return a[keep]
