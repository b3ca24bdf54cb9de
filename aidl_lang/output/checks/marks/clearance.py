"""W0516 for letters against the cut edge: an engraved text whose strokes (or, with a font,
outlines) come within :data:`TEXT_CLEAR` of its part's outline or a hole's edge, where the
laser's engraving meets its cut (issue 111, run l's toothpaste squeezer: "SQUEEZE" centred
between a slot's and a hanging hole's centres, its Q's tail 0.024 mm from the hole, and no
message).  Other marks have their own rule (:func:`.engravings._check_meets_cut`, 0.5 mm);
letters are often set tight beside a hole on purpose, so only a near touch is warned.
Near-linear: the strokes' and edges' boxes paired by
:func:`~aidl_lang.output.part.measure.nearby.box_pairs_between`."""
from __future__ import annotations

import math

import numpy as np

from .engravings import _copy_label, _mark_segments
from .segments import _edge_arrays, _pair_gap
from ..common import written

TEXT_CLEAR = 0.2         # mm: letters closer to the cut edge run into it


def _hole_at(part, shapes: dict, x: float, y: float) -> str:
    """The hole of ``part`` whose edge point (``x``, ``y``) is on, as the program names it
    (the outermost hole structure whose shape's box holds the point: a template instance,
    `left_end.divider`, before its own slots), or "a hole" (run fc: a name engraved over a
    tab_and_slot's mortise, "(a hole)" with no word of which)."""
    best = None
    for s in part.subtree():
        if s.kind != "hole" or s is part:
            continue
        sh = shapes.get(s)
        if sh is None or sh.is_empty():
            continue
        x0, y0, x1, y1 = sh.bounds()
        if x0 - 0.3 <= x <= x1 + 0.3 and y0 - 0.3 <= y <= y1 + 0.3 and (
                best is None or s.depth < best.depth):
            best = s
    if best is None:
        return "a hole"
    rel = best.path[len(part.parent.path) + 1:] if part.parent is not None else best.path
    return f"the hole `{rel}`"


def check_text_near_cut(texts: list, roots: dict, loops: dict | None, sink,
                        shapes: dict | None = None) -> None:
    """W0516 for each text of ``texts`` (``[(part, [(text, stroke items)])]``, those no
    W0505 or W0516 reported) that comes within :data:`TEXT_CLEAR` of its part's cut edge
    (``roots[part]``'s loops): the gap in mm, which edge (a hole named from ``shapes``, the
    drawing's Structure -> CrossSection), where (x, y), and how far to move it; one warning
    per statement (a loop's copies named with it)."""
    from ...part.measure.nearby import box_pairs_between
    for part, geoms in texts or ():
        if not geoms:
            continue
        edges = _edge_arrays(roots[part], (loops or {}).get(part))
        if edges is None:
            continue
        E0, E1, hole = edges
        segs = [_mark_segments(items) for _, items in geoms]
        S0 = np.concatenate([a for a, _ in segs])
        S1 = np.concatenate([b for _, b in segs])
        owner = np.repeat(np.arange(len(segs)), [len(a) for a, _ in segs])
        pairs = box_pairs_between(np.column_stack([np.minimum(S0, S1), np.maximum(S0, S1)]),
                                  np.column_stack([np.minimum(E0, E1), np.maximum(E0, E1)]),
                                  TEXT_CLEAR / 2)
        if not len(pairs):
            continue
        d, pa, _ = _pair_gap(S0[pairs[:, 0]], S1[pairs[:, 0]], E0[pairs[:, 1]],
                             E1[pairs[:, 1]])
        mk = owner[pairs[:, 0]]
        order = np.lexsort((d, mk))                 # each text's nearest pair first
        first = order[np.r_[True, mk[order][1:] != mk[order][:-1]]]
        by_statement: dict = {}
        for j in first[d[first] < TEXT_CLEAR - 1e-6].tolist():
            g = geoms[int(mk[j])][0]
            by_statement.setdefault(g.span or g, []).append(
                (float(d[j]), g, pa[j], bool(hole[pairs[j, 1]])))
        for group in by_statement.values():
            group.sort(key=lambda f: f[0])
            gap, g, pm, in_hole = group[0]
            how = "touches" if gap <= 0.05 else f"comes {gap:.2f} mm from"
            more = ""
            if len(group) > 1:
                more = f"; {len(group) - 1} more cop{'ies' if len(group) > 2 else 'y'} of " \
                       "this statement as close: " + ", ".join(
                           f"`{_copy_label(f[1], short=True)}` ({f[0]:.2f} mm)"
                           for f in group[1:4]) + (", ..." if len(group) > 4 else "")
            wx, wy = written(part, *pm)
            edge = _hole_at(part, shapes or {}, float(pm[0]), float(pm[1])) if in_hole \
                else "the outline"
            sink.warning(
                "W0516", f"engraving `{_copy_label(g)}` (text \"{g.data.get('text', '')}\") "
                f"{how} the cut edge of `{part.path}` "
                f"({edge}) at ({wx:.2f}, {wy:.2f}): "
                f"the letters meet the cut (text needs {TEXT_CLEAR} mm clear of the edge){more}",
                g.span, hint=f"keep `{g.label}` {math.ceil((TEXT_CLEAR - gap) * 100) / 100:.2f} "
                "mm or more further from the edge (move it, or make it smaller), or move the "
                "hole")
