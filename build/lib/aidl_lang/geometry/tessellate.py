"""Tessellation of circles and arcs: how many chords keep the chord deviation (sagitta) below
``CHORD_TOL`` (0.005 mm: a 100 mm circle deviates less than 0.01 mm from the true curve).

Used by the booleans (:mod:`aidl_lang.output.booleans`) and by fillets
(:mod:`aidl_lang.geometry.operations`).
"""
from __future__ import annotations

import math

CHORD_TOL = 0.005


def segments_for(radius: float, sweep: float = 2 * math.pi) -> int:
    """Chords for an arc of ``radius`` (mm) over ``sweep`` (radians): at least 3, at most 20000."""
    r = abs(radius)
    if r <= CHORD_TOL:
        return max(3, int(8 * sweep / (2 * math.pi)))
    step = 2 * math.acos(max(-1.0, 1 - CHORD_TOL / r)) if r < 1e9 else 0.0
    if step <= 0.0 or not math.isfinite(step):
        step = 2 * math.sqrt(2 * CHORD_TOL / r) if math.isfinite(r) else 2 * math.pi / 20000
    return max(3, min(20000, int(math.ceil(sweep / step))))
