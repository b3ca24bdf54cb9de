"""``aidl import`` (plain and ``--infer``): loops on a layer of their own named for holes (``HOLES`` beside
``OUTLINE``, as PCB and panel programs export) moved into the part whose outline holds them
(used by :func:`~..write.program.to_program` and :func:`~..infer.infer.to_program_inferred`; docs/import.md,
"Roles by layer or colour" and "Inferring the design").
"""
from __future__ import annotations

import re

from ..model import Drawing
from .chain import circular
from .containment import _containers


# a layer whose name says it holds holes (HOLES, Drill, NPTH, CUTOUTS, Inner, Mounting)
_HOLE_LAYER = re.compile(r"hole|drill|npth|pth|cut_?outs?|inner|interior|mount", re.I)
# a layer of the top circles of countersinks or counterbores (COUNTERSINK, CSK, C-BORE,
# Spotface): machined after the cut, about a hole
_SINK_LAYER = re.compile(r"c(ou)?nte?r[-_ ]?(sink|bore)|\bc[-_]?sk\b|^csk|c[-_]?bore|"
                         r"spot[-_ ]?face", re.I)


def engraved_layer(name: str, d: Drawing) -> bool:
    """Whether layer ``name`` (its drawing ``d``) is marked, not cut: a layer named
    ``ENGRAVE...`` or ``FILL`` (as ``aidl render`` writes them: ``FILL`` the HATCH of filled
    engraved letters, read as their outlines), or a countersink or counterbore layer of
    circles alone (:data:`_SINK_LAYER`: the cone's top circle about a hole; cut as drawn it
    would be a hole of the countersink's size, or a solid of discs)."""
    return name.upper().startswith("ENGRAVE") or name.upper() == "FILL" or bool(
        _SINK_LAYER.search(name) and d.circles and not (d.outlines or d.paths or d.texts
                                                         or d.ellipses))


def _hole_layers(layers: list[tuple[str, Drawing]], deadline=None) -> tuple[list, list[str]]:
    """``layers`` with each layer named for holes (:data:`_HOLE_LAYER`) of loops alone (no
    paths, texts or engravings) whose every loop lies inside an outer loop of one other
    layer's drawing (a ``HOLES`` layer beside ``OUTLINE``, as PCB and panel programs
    export) moved into that layer: its loops become that part's holes, not a solid of their
    own (which `--kerf` would grow and `--layout` nest apart from the plate).  Returns the
    layers and a line for the program's head per move (``holes: layer `HOLES` in
    `OUTLINE```).  Which loops lie inside which is found once for all layers
    (:func:`~.containment._containers`: a grid of boxes, O(n log n) in the loops)."""
    def loops(d):
        return [circular(o.segments) for o in d.outlines] + [[c] for c in d.circles]
    cand = [k for k, (ly, d) in enumerate(layers)
            if not engraved_layer(ly, d) and (d.outlines or d.circles)]
    # only a layer named for holes moves (a POCKET or SCORE layer inside the outline is not
    # a through-hole: it stays a part of its own, as `aidl import` writes it)
    holey = [k for k in cand if _HOLE_LAYER.search(layers[k][0]) and not (
        layers[k][1].paths or layers[k][1].texts or
        (layers[k][1].engrave is not None and not layers[k][1].engrave.empty))]
    sinks = [f"countersinks: layer `{ly}` ({len(d.circles)} circles) marked, not cut (a "
             "`drawing`: machine them after the cut)"
             for ly, d in layers if not ly.upper().startswith("ENGRAVE") and ly.upper() != "FILL"
             and engraved_layer(ly, d)]
    if len(cand) < 2 or not holey:
        return layers, sinks
    every, owner = [], []                   # every candidate layer's loops, and their layer
    for k in cand:
        ls = loops(layers[k][1])
        every += ls
        owner += [k] * len(ls)
    inside = _containers(every, deadline)
    into: dict = {}
    for k in holey:
        # each loop of layer k lies inside exactly one loop of one other layer (its outer
        # outline, not one of its holes), the same layer for all
        dest: set = set()
        for i in (i for i, o in enumerate(owner) if o == k):
            by = [owner[j] for j in inside[i] if owner[j] != k]
            dest |= set(by) if len(by) == 1 and by[0] not in holey else {None}
            if None in dest or len(dest) > 1:
                break
        if len(dest) == 1 and None not in dest:
            into[k] = dest.pop()
    if not into:
        return layers, sinks
    from dataclasses import replace
    out = {k: d for k, (_, d) in enumerate(layers)}
    for k, j in into.items():
        src, dst = out[k], out[j]
        out[j] = replace(dst, outlines=dst.outlines + src.outlines,
                         circles=dst.circles + src.circles, ellipses=dst.ellipses + src.ellipses,
                         notes=dst.notes)
    head = [f"holes: layer `{layers[k][0]}` in `{layers[j][0]}`" for k, j in into.items()]
    head += sinks
    return [(ly, out[k]) for k, (ly, _) in enumerate(layers) if k not in into], head
