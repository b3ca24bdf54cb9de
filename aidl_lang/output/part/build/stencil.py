"""Text cut as a stencil (issue 95): ``Text("HELLO", ..., stencil=true)`` in a hole.

The letters' single strokes are swept by a disc (half the ``weight`` across: each stroke a
stadium, exact lines and arcs), united, and the counters (the islands inside an O, an A, a B,
which would fall out of the sheet) are held by **bridges**: a band ``bridge`` wide, upright in
the text's own frame, through each counter and across the whole line of text, is left uncut.
A band through a point inside a counter reaches the sheet above and below the letter, so the
cut has no hole left, i.e. no island: the function checks it, and tries the counter's box
centre when its centroid did not free it.
"""
from __future__ import annotations

import math

import manifold3d as mf

from ....geometry.shapes.curves import Line, Loop
from ....geometry.derived.offset import sweep_loops
from ....geometry.shapes.text import text_strokes


def stencil_section(R, g, position) -> mf.CrossSection | None:
    """The cut of stencil Text ``g`` placed at ``position`` (x, y), for the booleans' renderer
    ``R`` (exact sections and loops), or None when it has no strokes."""
    size = g.data["size"]
    w = g.data.get("weight") or size / 6
    b = g.data.get("bridge") or size / 10
    rot = g.data.get("rotation", 0.0)
    segs = text_strokes(g.data["text"], size, g.data["anchor"],
                        g.data.get("valign", "baseline"), 0.0)
    if not len(segs):
        return None
    cs, sn = math.cos(rot), math.sin(rot)
    px, py = float(position[0]), float(position[1])

    def place(x, y):
        return (px + cs * x - sn * y, py + sn * x + cs * y)
    loops = []
    for (ax, ay), (bx, by) in segs:
        loops += sweep_loops(Line(place(ax, ay), place(bx, by)), w / 2)
    letters = R.union([R.exact.face(lp) for lp in loops])
    ys = [v[1] for s in segs for v in s]
    lo, hi = min(ys) - w, max(ys) + w
    bars: list = []
    for attempt in range(3):        # counters a band did not free get one at their box centre
        cut = letters - R.union(bars) if bars else letters
        holes = [lp for lp in R.exact.loops(cut) if lp.area < 0]
        if not holes:
            return cut
        for lp in holes:
            xs = [_unplace(p, px, py, cs, sn)[0] for p in lp.points()]
            x = sum(xs) / len(xs) if attempt == 0 else (min(xs) + max(xs)) / 2
            corners = [place(x - b / 2, lo), place(x + b / 2, lo), place(x + b / 2, hi),
                       place(x - b / 2, hi)]
            bars.append(R.exact.face(Loop([Line(corners[i], corners[(i + 1) % 4])
                                           for i in range(4)])))
    return letters - R.union(bars)


def _unplace(p, px, py, cs, sn):
    """A point of the placed text back in the text's own frame."""
    x, y = p[0] - px, p[1] - py
    return (cs * x + sn * y, -sn * x + cs * y)
