"""``W0510``: a part whose topology changes under ``--set`` (or the live preview's sliders):
its pieces, openings, merged holes, holes that reach the outline, overlapping faces and the
pieces its through-cuts cut off, compared with the program's defaults (:func:`check_topology`,
run by the pipeline and the live preview when param values are overridden; :func:`topology`
is taken once for the defaults)."""
from __future__ import annotations

import re

import numpy as np

from ...base.records import Compared
from ...base.diagnostics import DiagnosticSink
from ..part.build.booleans import Drawing
from ..part.measure.nearby import box_pairs
from .common import _area, _part_of, _part_roots, _signed
from .holes.openings import _analyse

# ------------------------------------------------------------ topology under `--set` (W0510)
class Topology(Compared):
    """What W0510 compares of one solid part between the program's defaults and a `--set`."""
    __slots__ = ("span", "pieces", "openings", "merges", "notches", "contacts", "holes", "faces",
                 "freed", "loops")

    def __init__(self, span: object, pieces: int, openings: int, merges: set, notches: set,
                 contacts: set, holes: set, faces: set, freed: int = 0, loops: int | None = None):
        self.span = span
        self.pieces = pieces
        self.openings = openings
        self.merges = merges  # frozensets of two hole names that cut one opening
        self.notches = notches  # hole names that reach the outline
        self.contacts = contacts  # frozensets of two face names (different solids) that overlap
        self.holes = holes  # every hole name
        self.faces = faces  # every solid face name
        self.freed = freed  # pieces its through-cuts cut off (parts `PART.piece1`, ...)
        self.loops = loops  # the separate areas of its holes that reach no outline


STAGE = "the comparison with the defaults (W0510)"


def topology(d: Drawing, deadline=None) -> dict:
    """What W0510 compares, per solid part of ``d`` (:func:`_topology`); empty when the part
    is too dense to compare (more pairs than :data:`..nearby.MAX_PAIRS`: no W0510 then,
    never an unbounded list).  ``deadline`` (:class:`~aidl_lang.base.limits.Deadline`): looked at
    for each part and every 64 face pairs (raises :class:`~aidl_lang.base.limits.OutOfBudget`)."""
    from ..part.measure.nearby import TooManyPairs
    try:
        return _topology(d, deadline)
    except TooManyPairs:
        return {}


def _topology(d: Drawing, deadline=None) -> dict:
    """The :class:`Topology` of every solid part of ``d``, by part path: its pieces and
    openings (counter-clockwise and clockwise loops of its final shape), the holes that merge
    (:func:`_analyse` at the touching distance) or reach the outline, and the faces of
    different solid structures that overlap (candidates from :func:`.nearby.box_pairs`)."""
    def check(where, k=0):
        if deadline is not None and k % 64 == 0:
            deadline.check(STAGE, where)

    roots = _part_roots(d)
    freed = _freed(d)
    by_part: dict = {}
    for c in d.cuts:
        by_part.setdefault(_part_of(c.owner, roots), []).append(c)
    faces_of: dict = {}
    for st, own in d.own.items():
        if st.kind != "solid":
            continue
        part = _part_of(st, roots)
        if part is not None and part.kind == "solid":
            faces_of.setdefault(part, []).extend(
                (f"`{g.label}`", st, f) for g, f in own if f is not None and not f.is_empty())
    out = {}
    for s, shape in roots.items():
        if s.kind != "solid":
            continue
        check(s)
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
        pos = sum(_signed(p) > 0 for p in loops)
        a = _analyse(d, s, shape, by_part.get(s, []), 0.0, loops, tick=lambda ahead=0.0: check(s))
        faces = faces_of.get(s, [])
        contacts = set()
        if len(faces) > 1:
            boxes = [f.bounds() for _, _, f in faces]
            for k, (i, j) in enumerate(box_pairs(boxes)):
                check(s, k + 1)
                (ni, si, fi), (nj, sj, fj) = faces[i], faces[j]
                if si is not sj and _area(fi ^ fj) > 1e-6:
                    contacts.add(frozenset((ni, nj)))
        out[s.path] = Topology(s.span, pos, len(loops) - pos,
                               {frozenset((a.names[i], a.names[j])) for i, j, _, _ in a.merges},
                               {a.names[j] for j in a.notches}, contacts, set(a.names[1:]),
                               {n for n, _, _ in faces}, freed.get(s.path, 0),
                               sum(_outer_loops(c.region) for k, c in enumerate(a.cuts, 1)
                                   if k not in a.notches))
    return out


def _freed(d: Drawing) -> dict:
    """Part path -> how many pieces its through-cuts cut off: the parts of ``d`` made from
    its structure under another name (``PART.piece1``, ... :meth:`..booleans.Renderer.part`;
    a piece enclosed by the part falls out as an opening, counted there)."""
    out: dict = {}
    for p in d.parts:
        s = d.part_of.get(p.name)
        if s is not None and p.name != s.path:
            out[s.path] = out.get(s.path, 0) + 1
    return out


def _count(n: int, what: str) -> str:
    return f"{n} {what}" + ("" if n == 1 else "s")


def _family(hole: str) -> str:
    """A hole's name with its indices left out: ``"p.halving[]"`` for ``"p.halving[4]"``."""
    return re.sub(r"\[\d+\]", "[]", hole)


def _outer_loops(region) -> int:
    """How many separate areas a hole's region is (a tab-and-slot's one hole: its slots and
    its screw holes)."""
    return sum(_signed(np.asarray(p, dtype=float)) > 0 for p in region.to_polygons())


def _apart(t: Topology) -> int:
    """The openings ``t``'s holes would cut each on its own: the separate areas of every
    hole that does not reach the outline (a tab-and-slot's one hole: its slots and screw
    holes; not the part's own inner edges, which no hole cut: a spur gear's bore slider from
    0 made "1 opening instead of 0"), less one per pair of holes that merges."""
    if t.loops is not None:
        return t.loops - len(t.merges)
    holes = [h for h in t.holes if not h.startswith("an inner edge of")]
    return len(holes) - len(t.notches) - len(t.merges)


def topology_changes(base: Topology, new: Topology) -> list[str]:
    """What changed from ``base`` (the defaults) to ``new``, in words, most telling first."""
    out = []
    if new.pieces != base.pieces:
        out.append(f"{_count(new.pieces, 'piece')} instead of {base.pieces}")
    # a hole a count or a field's fill added or took away cuts its own opening (unless it
    # reaches the outline or merges, said below): what the param is for (`--set n=5` on a
    # row of 3 holes: 5 openings instead of 3), no change
    if new.openings != base.openings and \
            new.openings - base.openings != _apart(new) - _apart(base):
        out.append(f"{_count(new.openings, 'opening')} instead of {base.openings}")
    if new.freed != base.freed:
        out.append(f"its through-cuts cut it into {_count(new.freed + 1, 'part')} instead "
                   f"of {base.freed + 1}")
    for m in sorted(new.merges - base.merges, key=sorted):
        a, b = sorted(m)
        out.append(f"{a} merges with {b}")
    for m in sorted(base.merges - new.merges, key=sorted):
        if m <= new.holes:
            a, b = sorted(m)
            out.append(f"{a} and {b} no longer merge")
    # a hole a count added (`halving[4]` of 5 where the defaults made 3) is judged by its
    # siblings: one more of a family of notches that reach the outline by design is no change
    notching = {_family(h) for h in base.notches}
    for h in sorted(new.notches - base.notches):
        if h in base.holes or _family(h) not in notching:
            out.append(f"{h} now breaks through the outline")
    for h in sorted(base.notches - new.notches):
        if h in new.holes:
            out.append(f"{h} no longer reaches the outline")
    for c in sorted(new.contacts - base.contacts, key=sorted):
        if c <= base.faces:
            a, b = sorted(c)
            out.append(f"{a} now overlaps {b}")
    for c in sorted(base.contacts - new.contacts, key=sorted):
        if c <= new.faces:
            a, b = sorted(c)
            out.append(f"{a} no longer overlaps {b}")
    return out


def check_topology(base: Drawing | dict, d: Drawing, values: dict, sink: DiagnosticSink,
                   deadline=None) -> None:
    """W0510 for each solid part of ``d`` (compiled with the param ``values``) whose
    topology differs from ``base`` (the same program with its defaults: a Drawing, or its
    :func:`topology` already taken); ``deadline`` as for :func:`topology`."""
    if not values:
        return
    before = base if isinstance(base, dict) else topology(base, deadline)
    now = topology(d, deadline)
    with_ = ", ".join(f"{k}={v}" for k, v in values.items())
    for path, t in now.items():
        b = before.get(path)
        if b is None:
            continue
        what = topology_changes(b, t)
        if not what:
            continue
        sink.warning("W0510", f"with {with_}, part `{path}` changes: " + "; ".join(what[:4])
                     + ("; ..." if len(what) > 4 else "") + " (not so with the defaults)",
                     t.span,
                     hint="such a change is rarely what the param is for: choose another "
                          "value, derive the spacing from the param so that the design follows "
                          "it, or declare the param's `min=`/`max=` to keep values that fit")
