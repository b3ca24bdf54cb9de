"""``aidl import --infer``: loops on a layer of their own named for holes (``HOLES`` beside
``OUTLINE``, as PCB and panel programs export) moved into the part whose outline holds them
(used by :func:`~.infer.to_program_inferred`; docs/import.md, "Inferring the design").
"""
from __future__ import annotations

import re

from ...geometry.curves import Loop
from ...geometry.drawing2d import _inside
from ..model import Drawing
from ..write.program import _containers
from .shapes import circular


# a layer whose name says it holds holes (HOLES, Drill, NPTH, CUTOUTS, Inner, Mounting)
_HOLE_LAYER = re.compile(r"hole|drill|npth|pth|cut_?outs?|inner|interior|mount", re.I)


def _hole_layers(layers: list[tuple[str, Drawing]], deadline=None) -> tuple[list, list[str]]:
    """``layers`` with each layer named for holes (:data:`_HOLE_LAYER`) of loops alone (no
    paths, texts or engravings) whose every loop lies inside an outer loop of one other
    layer's drawing (a ``HOLES`` layer beside ``OUTLINE``, as PCB and panel programs
    export) moved into that layer: its loops become
    that part's holes, not a solid of their own.  Returns the layers and a line for the
    program's head per move (``holes: layer `HOLES` in `OUTLINE```)."""
    import numpy as np
    from ..write.program import _probe

    def loops(d):
        return [circular(o.segments) for o in d.outlines] + [[c] for c in d.circles]
    cand = [k for k, (ly, d) in enumerate(layers)
            if not ly.upper().startswith("ENGRAVE") and (d.outlines or d.circles)]
    if len(cand) < 2:
        return layers, []
    # only a layer named for holes moves (a POCKET or SCORE layer inside the outline is not
    # a through-hole: it stays a part of its own, as `aidl import` writes it)
    holey = {k for k in cand if _HOLE_LAYER.search(layers[k][0])}
    outer = {}
    for k in cand:
        ls = loops(layers[k][1])
        outer[k] = [np.asarray(Loop(list(s)).points(), dtype=float)
                    for s, c in zip(ls, _containers(ls, deadline)) if not c]
    into: dict = {}
    for k in sorted(holey):
        d = layers[k][1]
        if d.paths or d.texts or (d.engrave is not None and not d.engrave.empty):
            continue
        probes = [_probe(s) for s in loops(d)]
        for j in cand:
            if j == k or j in into or j in holey:
                continue
            if deadline is not None:
                deadline.check("finding the layers of holes")
            if all(any(len(P) >= 3 and _inside(q, P) for P in outer[j]) for q in probes):
                into[k] = j
                break
    if not into:
        return layers, []
    from dataclasses import replace
    out = {k: d for k, (_, d) in enumerate(layers)}
    for k, j in into.items():
        src, dst = out[k], out[j]
        out[j] = replace(dst, outlines=dst.outlines + src.outlines,
                         circles=dst.circles + src.circles, ellipses=dst.ellipses + src.ellipses,
                         notes=dst.notes)
    head = [f"holes: layer `{layers[k][0]}` in `{layers[j][0]}`" for k, j in into.items()]
    return [(ly, out[k]) for k, (ly, _) in enumerate(layers) if k not in into], head
