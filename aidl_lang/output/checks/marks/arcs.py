"""W0505's fix for an engraved Circle or Arc that crosses its part's outline or a hole: the
arcs of it on the material (issue 105; one per clear run since issue 111's round thirteen)."""
from __future__ import annotations

import math

import numpy as np

from ..common import _edges, _inside


ARC_STEPS = 1440          # samples of an engraved circle when W0505 offers the arc on the material
ARC_LEAST = math.radians(30)    # the arc offered is at least this long
MAX_ARCS = 8              # arcs offered at most (run ez: a ring through 8 peg holes, 4 offered)


def arc_on_material(g, items, shape, within, clear_of: float, part=None) -> str | None:
    """W0505's fix for an engraved Circle (or Arc) that crosses its part's outline or a hole
    (a ring that meets a notch in the rim, issue 105): the arcs of it on the material
    (one per clear run, the longest first, at most :data:`MAX_ARCS`), clear of the cut by ``2 clear_of``, as the ``Arc(center=, radius=,
    start_angle=, end_angle=)`` that replaces it (mm and degrees, counter-clockwise, ends
    rounded inward to 0.1 deg); None for another shape, or when no such arc of at least
    :data:`ARC_LEAST` is left.  ``within(points, edges, d)``: which points lie within ``d``
    mm of the edges; ``clear_of``: how far a mark keeps from the cut (mm)."""
    kind = getattr(g, "kind", None)
    if len(items) != 1 or (kind, items[0][0]) not in (("Circle", "circle"), ("Arc", "arc")):
        return None
    (cx, cy), r = items[0][1], float(items[0][2])
    if not r > 0:
        return None
    whole = kind == "Circle"
    a0, sweep = (0.0, 2 * math.pi) if whole else \
        (float(items[0][3]), (float(items[0][4]) - float(items[0][3])) % (2 * math.pi) or 2 * math.pi)
    loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    edges = _edges(loops)
    steps = ARC_STEPS if whole else max(8, int(ARC_STEPS * sweep / (2 * math.pi)) + 1)
    t = a0 + np.arange(steps) * (sweep / (ARC_STEPS if whole else steps - 1))
    pts = np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])
    clear = _inside(pts, edges) & ~within(pts, edges, 2 * clear_of)
    if clear.all() or not clear.any():
        return None
    k0 = int(np.argmin(clear)) if whole else 0       # a circle: start at an off sample
    order = np.roll(np.arange(steps), -k0)
    runs, run, start = [], 0, 0          # every clear run: (length, start)
    for i, k in enumerate(order):
        if clear[k]:
            if run == 0:
                start = i
            run += 1
        elif run:
            runs.append((run, start))
            run = 0
    if run:
        runs.append((run, start))
    runs = [(n, s) for n, s in runs if n >= 2 and (n - 1) * 2 * math.pi / ARC_STEPS >= ARC_LEAST]
    if not runs:
        return None

    def ok(th: float) -> bool:
        p = np.array([[cx + r * math.cos(th), cy + r * math.sin(th)]])
        return bool(_inside(p, edges)[0] and not within(p, edges, 2 * clear_of)[0])

    def edge(good: float, bad: float) -> float:
        """The clear end between a clear angle and a blocked one (bisected to 1e-9 rad)."""
        for _ in range(40):
            m = (good + bad) / 2
            good, bad = (m, bad) if ok(m) else (good, m)
        return good
    step = sweep / (ARC_STEPS if whole else steps - 1)
    name = str(getattr(g, "label", "")).rsplit(".", 1)[-1] or "mark"
    from ..common import written
    wx, wy = written(part, cx, cy)     # where the program writes it (run ez: the layout's 360 mm)
    arcs = []
    # each clear run an arc (run cs's feeder: a ring across two mortises was offered the
    # longer half only, and the arc pasted dropped the other), the longest first
    for k, (n, s) in enumerate(sorted(runs, key=lambda q: (-q[0], q[1]))[:MAX_ARCS]):
        lo, hi = t[order[s]], t[order[s + n - 1]]
        if hi < lo:
            hi += 2 * math.pi
        if whole or s > 0:             # a blocked sample before the run (a circle: always)
            lo = edge(lo, lo - step)
        if whole or s + n < steps:
            hi = edge(hi, hi + step)
        a1 = math.degrees(lo) % 360
        a2 = a1 + math.degrees(hi - lo)
        a1, a2 = math.ceil(a1 * 10 - 1e-6) / 10, math.floor(a2 * 10 + 1e-6) / 10
        arcs.append(f"`{name if k == 0 else f'{name}_{k + 1}'} = Arc(center=({wx:.6g} mm, "
                    f"{wy:.6g} mm), radius={r:.6g} mm, start_angle={a1:g} deg, "
                    f"end_angle={a2:g} deg)`")
    what = "circle" if whole else "arc"
    return (f"to stop the {what} at the cut, engrave "
            + (f"the arc on the material instead: {arcs[0]}" if len(arcs) == 1 else
               f"the {len(arcs)} arcs on the material instead: " + ", ".join(arcs[:-1])
               + f" and {arcs[-1]}")
            + f" (the {what}'s center and radius, counter-clockwise, "
            f"{2 * clear_of:g} mm clear of the cut)")
