"""Tessellation of circles and arcs: how many chords keep the chord deviation (sagitta) below
``CHORD_TOL`` (0.005 mm: a 100 mm circle deviates less than 0.01 mm from the true curve).

Used by the booleans (:mod:`aidl_lang.output.part.build.booleans`) and by fillets
(:mod:`aidl_lang.geometry.derived.operations`).
"""
from __future__ import annotations

import math

CHORD_TOL = 0.005


def segments_for(radius: float, sweep: float = 2 * math.pi, tol: float = CHORD_TOL,
                 least: int = 3) -> int:
    """Chords for an arc of ``radius`` (mm) over ``sweep`` (radians) whose sagitta stays below
    ``tol`` (mm; :data:`CHORD_TOL` unless a coarser view asks for fewer): at least ``least``
    (3: a circle stays a polygon), at most 20000."""
    r = abs(radius)
    if r <= tol:
        return max(least, int(8 * sweep / (2 * math.pi)))
    step = 2 * math.acos(max(-1.0, 1 - tol / r)) if r < 1e9 else 0.0
    if step <= 0.0 or not math.isfinite(step):
        step = 2 * math.sqrt(2 * tol / r) if math.isfinite(r) else 2 * math.pi / 20000
    return max(least, min(20000, int(math.ceil(sweep / step))))
