"""Parts nearer each other than the tool is wide (issue 109, law 1: the machine makes what
was drawn; docs/machines.md, "What the tool leaves").

A router's bit runs its centre a radius off each part's outline and cuts to a whole
diameter off it; a laser's kerf likewise.  Two parts drawn (or laid out) nearer each other
than that lose material to each other's cut: the mounting plate's washers, 3 mm apart, lost
0.175 mm each to the 3.175 mm bit, with no word.  :func:`near_parts` finds such pairs
(candidate pairs from their boxes, the exact gap between their outlines:
:func:`~...part.measure.gaps.gap`); :func:`tool_gap_warnings` says each as W0531, located at
the second part (parts that touch too: a knight drawn standing on its base; not the pieces a
cut freed, whose shared edge is cut once); parts over each other are E0501's.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...part.measure.gaps import gap, pieces
from ...part.measure.nearby import box_pairs

# mm: a gap this much under the tool's width is rounding, not a cut into the neighbour
GAP_TOL = 1e-9


@dataclass(frozen=True)
class NearParts:
    """Parts ``a`` and ``b`` lie ``gap`` mm apart, nearest at ``at`` (x, y mm), less than
    the tool's ``width`` mm: each one's cut takes ``width - gap`` mm of the other."""
    a: str
    b: str
    gap: float
    at: tuple
    width: float


def near_parts(output, width) -> list[NearParts]:
    """The pairs of ``output``'s solid parts nearer each other than ``width`` (mm, or a
    callable part name -> mm: the tool's width there, a router's bit or a laser's kerf), in
    the parts' order; touching too, unless both are pieces a through-cut freed
    (``output.drawing.split``: their shared edge is cut once)."""
    width_of = width if callable(width) else (lambda name, w=float(width or 0.0): w)
    parts = [p for p in output.parts if p.kind == "solid" and p.loops]
    if len(parts) < 2:
        return []
    ws = [width_of(p.name) or 0.0 for p in parts]
    if not max(ws) > 0:
        return []
    split = getattr(getattr(output, "drawing", None), "split", None) or ()
    boxes = np.array([_box(p) for p in parts])
    out = []
    for i, j in box_pairs(boxes, max(ws)):
        a, b = parts[int(i)], parts[int(j)]
        w = max(ws[int(i)], ws[int(j)])
        if not w > 0:
            continue
        d, p, q = gap(pieces([s for lp in a.loops for s in lp.segments]),
                      pieces([s for lp in b.loops for s in lp.segments]))
        if d <= GAP_TOL and a.name in split and b.name in split:
            continue
        if d < w - GAP_TOL:
            out.append(NearParts(a.name, b.name, d, ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2), w))
    return out


def _box(p) -> tuple:
    xs, ys = [], []
    for lp in p.loops:
        for s in lp.segments:
            x0, y0, x1, y1 = s.box()
            xs += [x0, x1]
            ys += [y0, y1]
    return (min(xs), min(ys), max(xs), max(ys))


def tool_gap_warnings(drawing, output, width, router: bool, sink) -> set:
    """W0531 in ``sink`` for each pair of :func:`near_parts` of ``output`` (what the machine
    cuts) with a tool of ``width`` mm (a router's bit, ``router``; else a laser's kerf),
    located at the second part's structure; the names of the parts said."""
    said = set()
    part_of = getattr(drawing, "part_of", None) or {}
    for n in near_parts(output, width):
        tool = (f"the router's bit ({n.width:g} mm across)" if router else
                f"the laser's kerf ({n.width:g} mm)")
        node = part_of.get(n.b) or part_of.get(n.a)
        apart = "touching" if n.gap <= GAP_TOL else f"{n.gap:.4g} mm apart"
        sink.warning("W0531", f"{tool} runs between parts `{n.a}` and `{n.b}`, "
                     f"{apart} near ({n.at[0]:.2f}, {n.at[1]:.2f}): its cut round "
                     f"each takes {n.width - n.gap:.3g} mm of the other",
                     node.span if node is not None else None,
                     hint=f"draw the parts at least {n.width:g} mm apart, or lay them out for "
                          f"cutting with a gap above {n.width:g} mm (`aidl render --layout sheet "
                          f"--gap {math.floor(n.width) + 1}mm`)")
        said |= {n.a, n.b}
    return said


__all__ = ["NearParts", "near_parts", "tool_gap_warnings"]
