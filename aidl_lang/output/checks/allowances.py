"""``W0523``: an ``AllowOverlap`` statement that allows nothing, because no two of the things
it names overlap (or touch) in the final drawing, so no warning is silenced by it: the names
are of other shapes than meant (a pattern's original where its copies overlap), or the
overlap was moved away by an edit.

An ``AllowOverlap`` concerns a hole (a hole structure, or a shape in one) and each other
thing it names (W0501 a refill, W0508 two holes that cut one opening, W0512 the shapes of
one hole that merge), shapes of one solid (W0515: used when they silenced a warning about
the opening they enclose), or two solid parts (W0511, and W0517 once assembled: a program that
places its parts in 3D is left alone, the 3D collision not being a flat overlap).  It is
found where it is written (``Structure.allowances``, kept by
:func:`aidl_lang.geometry.derived.operations._allow_overlap`); the shapes are the booleans'
(:attr:`Drawing.own` for a shape, :attr:`Drawing.shapes` for a structure)."""
from __future__ import annotations

import manifold3d as mf
import numpy as np

from ...base.diagnostics import DiagnosticSink
from ...geometry.core.model import Structure
from ..part.build.booleans import Drawing
from ..part.measure.nearby import box_pairs
from .common import _area
from .holes.openings import TOUCH as MERGE_TOUCH

TOUCH = 1e-3        # mm: two shapes this close touch (W0508 merges touching holes)
MAX_PAIRS = 20_000  # pairs of named shapes compared per statement, past which it is not judged


def _tops(d: Drawing) -> list:
    tops = {}
    for s in d.shapes:
        while s.parent is not None:
            s = s.parent
        tops[id(s)] = s
    return list(tops.values())


def _shape(d: Drawing, o, faces: dict):
    if isinstance(o, Structure):
        return d.shapes.get(o)
    return faces.get(id(o))


def _hole(o):
    owner = o if isinstance(o, Structure) else o.owner
    node = owner
    while node is not None:
        if node.kind == "hole":
            return node
        node = node.parent
    return None


def _drawn(o) -> bool:
    """``o`` is an engraving: a drawing structure, or a shape or structure inside one."""
    return (o if isinstance(o, Structure) else o.owner).in_drawing()


def _part(o) -> bool:
    return isinstance(o, Structure) and o.kind == "solid" \
        and not any(a.kind == "solid" for a in o.ancestors())


def _one_solid(a, b) -> bool:
    """Two shapes of one solid structure: named together, the opening they enclose is meant
    (W0515), which needs them to overlap or touch."""
    return not isinstance(a, Structure) and not isinstance(b, Structure) \
        and a.owner is b.owner and a.owner.kind == "solid"


def _enclosed(a, objs) -> bool:
    """The shapes of ``a``'s solid among ``objs`` silenced a W0515: the window they
    enclose was said to be meant (:func:`.holes.voids._report_enclosed` keeps the sets used)."""
    named = frozenset(o for o in objs if not isinstance(o, Structure) and o.owner is a.owner)
    return named in getattr(a.owner, "enclosure_used", ())


def _meets(a, b) -> bool:
    """Whether two shapes overlap or touch as W0508 judges it: within its ``TOUCH`` (run ce's
    papel picado: circles 25 mm apart touching at a point were one opening for W0508, and the
    `AllowOverlap` its fix writes "allowed nothing")."""
    if a is None or b is None or a.is_empty() or b.is_empty():
        return False
    if _area(a ^ b) > 1e-9:
        return True
    if (a + b).num_contour() < a.num_contour() + b.num_contour():     # they touch
        return True
    return _area(a.offset(MERGE_TOUCH, mf.JoinType.Round) ^ b) > 1e-9


def check_allowances(d: Drawing, sink: DiagnosticSink, tick=lambda: None) -> None:
    """W0523 for each ``AllowOverlap`` statement of the program (once per statement, the
    calls of a template's body counted together) none of whose concerned pairs overlaps or
    touches (:func:`_meets`).  ``tick()``: before each statement's comparisons."""
    faces = {id(g): f for fs in d.own.values() for g, f in fs}
    placed = bool(getattr(d, "placement", None))
    by_span: dict = {}
    for top in _tops(d):
        for s in top.subtree():
            for span, objs in getattr(s, "allowances", ()):
                by_span.setdefault(span, []).append(objs)
    for span, calls in by_span.items():
        if span is None:
            continue
        tick()
        used = judged = False
        for objs in calls:
            if placed and sum(map(_part, objs)) > 1:
                used = True                # a 3D fit may need it (W0517)
                break
            drawn = [o for o in objs if _drawn(o)]
            if drawn and any(getattr(o if isinstance(o, Structure) else o.owner, "text_used",
                                     False) for o in drawn):
                used = True                # labels close as meant (W0513)
                break
            if drawn:                      # an engraving off its part on purpose (W0505)
                if not getattr(d, "engravings_judged", False) or any(
                        id(o) in getattr(o if isinstance(o, Structure) else o.owner,
                                         "engrave_used", ()) for o in drawn):
                    used = True
                    break
                judged = True
                if all(_drawn(o) or (o if isinstance(o, Structure) else o.owner).kind == "solid"
                       for o in objs):
                    continue               # nothing else in it to allow
            objs = list({id(o): o for o in objs}.values())
            shapes = [_shape(d, o, faces) for o in objs]
            idx = [k for k, sh in enumerate(shapes) if sh is not None and not sh.is_empty()]
            if len(idx) < 2:
                continue
            boxes = np.array([shapes[k].bounds() for k in idx], dtype=float)
            pairs = box_pairs(boxes, pad=TOUCH)
            if len(pairs) > MAX_PAIRS:
                used = True
                break
            judged = True
            for p, q in map(tuple, pairs):
                a, b = objs[idx[p]], objs[idx[q]]
                ha, hb = _hole(a), _hole(b)
                if _one_solid(a, b):
                    if _enclosed(a, objs):
                        used = True                   # it said a window is meant (W0515)
                        break
                    continue
                if ha is None and hb is None and not (_part(a) and _part(b)):
                    continue                          # two solids' shapes: nothing to allow
                if ha is not None and ha is hb and (isinstance(a, Structure)
                                                    or isinstance(b, Structure)):
                    continue                          # a hole and its own shape
                if _meets(shapes[idx[p]], shapes[idx[q]]):
                    used = True
                    break
            if used:
                break
        if used or not judged:
            continue
        names = ", ".join(dict.fromkeys(_label(o) for o in calls[0]))
        if all(map(_drawn, calls[0])):
            sink.warning("W0523", f"`AllowOverlap` allows nothing: {names}: no two of the texts "
                         "and marks named come close enough to be warned about (W0513)", span,
                         hint="delete the statement")
            continue
        if any(map(_drawn, calls[0])):
            sink.warning("W0523", f"`AllowOverlap` allows nothing: {names}: the engraving lies "
                         "on its part's material, so it silences no warning (W0505)", span,
                         hint="delete the statement")
            continue
        if all(not isinstance(o, Structure) and o.owner.kind == "solid" for o in calls[0]):
            sink.warning("W0523", f"`AllowOverlap` allows nothing: {names} enclose no opening "
                         "that is warned about (W0515), so it silences no warning", span,
                         hint="name every shape around the window (the W0515 hint writes the "
                              "call), or delete the statement")
            continue
        sink.warning("W0523", f"`AllowOverlap` allows nothing: no two of {names} overlap or "
                     "touch, so it silences no warning", span,
                     hint="name the shapes that do overlap (the hole and what refills it, "
                          "the two holes, or the two parts a warning named: its hint writes "
                          "the call), or delete the statement")


def _label(o) -> str:
    return f"`{o.path}`" if isinstance(o, Structure) else f"`{o.label}`"
