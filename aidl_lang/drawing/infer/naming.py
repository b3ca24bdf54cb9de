"""``aidl import --infer``: the names of the parts (:func:`_named_parts`, :func:`_short_names`)
and the program's head saying what was recognised (:func:`_summary`) and the far edges
features follow (:func:`_far`); used by
:func:`~.infer.to_program_inferred`."""
from __future__ import annotations

from collections import Counter

from ...geometry.shapes.curves import Loop
from .shapes import EQUAL_TOL, ROUND_TOL, circular, recognise
from ..write.writer import _ident
from ..write.units import UNIT


# layer names that say nothing of the part on them (CAD's layer 0, a laser's CUT layer)
_GENERIC = {"l_0", "cut_", "cut", "part", "outline", "outlines", "contour", "profile",
            "default", "layer1", "layer_1", "l_1"}


def _named_parts(items: list) -> list:
    """``items`` with a solid on a layer whose name says nothing (:data:`_GENERIC`) named
    for what its body is: ``plate`` (a rectangle or polygon), ``disc`` (a circle), else
    ``part``; each name once."""
    used = {it[1] for it in items}
    out = []
    for it in items:
        kind, name, d = it[:3]
        if kind != "solid" or name.lower() not in _GENERIC:
            out.append(it)
            continue
        loops = [circular(o.segments) for o in d.outlines] + [[c] for c in d.circles]
        big = max(loops, key=lambda s: abs(Loop(list(s)).area), default=None)
        sh = recognise(big) if big is not None else None
        word = "part" if sh is None else "disc" if sh.kind == "Circle" else "plate"
        used.discard(name)
        new = _ident(word, used)
        out.append((kind, new, d) + tuple(it[3:]))
    return out


def _short_names(names: list) -> dict:
    """Each part's name for its params: the last word of its name (``cut_kit_plate``:
    ``plate``) when no other part's ends so, else the whole name."""
    last = {n: (n.rsplit("_", 1)[-1] if "_" in n else n) for n in names}
    count = Counter(last.values())
    # (a name that ends in "_", a keyword made a name such as `cut_`, keeps its whole name)
    return {n: (v if v and count[v] == 1 and not v[0].isdigit() else n)
            for n, v in last.items()}


def _summary(st) -> list[str]:
    """The header lines saying what was recognised and the tolerances."""
    shapes = ", ".join(f"{n} {k}" for k, n in sorted(st.kinds.items(), key=lambda x: -x[1]))
    pats = ", ".join(f"{n} {k}" for k, n in st.patterns.items())
    out = [f"recognised: {st.in_shapes} of {st.pieces} pieces of outlines and holes in "
           f"{sum(st.kinds.values())} shapes ({shapes or 'none'})"]
    if pats:
        out.append(f"patterns: {pats}")
    u = UNIT.get()
    out.append(f"equal within {EQUAL_TOL:g} {u}, numbers rounded within {ROUND_TOL:g} {u}; "
               f"the rest stays exact Line/Arc chains")
    return out


def _far(stats) -> list:
    """The head's line naming the edges that move (the far ones from the corner the plate grows
    from) that features were placed from, so that a maker reads that a new width or height
    keeps them at their distance from that edge (issue 103)."""
    if not stats.far:
        return []
    names = {(0, -1): "left", (0, 1): "right", (1, -1): "bottom", (1, 1): "top"}
    edges = [names[k] for k in sorted(stats.far)]
    sizes = " or ".join(dict.fromkeys("width" if a == 0 else "height" for a, _ in sorted(stats.far)))
    return [f"features by the far {' and '.join(edges)} edge{'s' if len(edges) > 1 else ''} are "
            f"placed from {'them' if len(edges) > 1 else 'it'}: a new {sizes} keeps their "
            f"distance to that edge"]
