"""Small array helpers for the solver.

:func:`unique` is ``np.unique`` for 1-D integer arrays without its masked-array test: NumPy's
``np.unique`` asks ``np.ma.is_masked`` and so imports ``numpy.ma`` (about 15 ms) on a cold
``aidl check``.

The garbage-collector pause the rows and the tape are built under is
:func:`aidl_lang.base.memory.gc_paused` (shared with the parser and the interpreter).
"""
from __future__ import annotations

import numpy as np


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
