"""Edges that two pieces of one cut part share, cut once.

Through-cuts that cut a part into pieces (docs/outputs.md, "Through-cuts") give each piece its
own exact outline, so a cut between two pieces is in both outlines: the laser, the knife or the
router would run along it twice (a 3 x 3 grid of 10 mm squares: 720 mm a pass instead of the
240 mm of the design).  :func:`cut_once` finds, among the parts a through-cut split
(:attr:`~.booleans.Drawing.split`: a part and its ``PART.pieceK``), the stretches of each
outline that an earlier part's outline (in the output's order) already runs along, and gives
the outline less those stretches: open chains, the rest of the loop in its own direction.
The cutting writers (SVG in the laser style, DXF, the PDF template, the toolpath of G-code,
LightBurn and HP-GL) cut :func:`loop_paths`; the parts themselves keep their closed outlines
(areas, the parts list, the 3D outputs, nesting).

A stretch is shared when both outlines have a segment on one carrier (the same line, circle,
spline or ellipse: :func:`_span`) whose parameter ranges overlap by more than
:data:`SHARED_TOL` mm.  Each carrier keeps the merged ranges cut so far, sorted, so each
segment costs O(log n): a 40 x 40 grid's 1,600 squares are 6,400 segments on 82 carriers.
Parts laid apart on a sheet share nothing, and so are cut whole.

The kerf and the router's tool offset (:func:`~..fabrication.layout.compensate`) leave the
stretches :func:`shared_edges` finds on their line (the same notion of shared, whatever the
order), offsetting only the rest (:func:`~...geometry.offset.offset_loop`'s ``keep``), so
the offset pieces still share them and the writers cut them once; :func:`shared_note` says
what each side loses.
"""
from __future__ import annotations

import bisect
import math

from ....geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Loop, Spline

SHARED_TOL = 1e-6      # mm: a stretch shorter than this is not shared (ends that only touch)
TWO_PI = 2 * math.pi


def cut_once(output) -> dict:
    """``{(part index, loop index): [(segments, closed), ...]}`` for each loop of
    ``output.parts`` that an earlier part of the same split family, or a through-cut of the
    split part left as a stroke (:attr:`~.part.Output.cuts`), already cuts in part:
    the loop's segments less the stretches cut before, as open chains (``closed`` False) in
    the loop's own direction (an empty list: the whole loop is cut already).  Loops not in it
    are cut whole.  Only the parts a through-cut split (``output.drawing.split``) are
    compared; on no such part the answer is ``{}``."""
    todo = _family(output)
    cover: dict = {}
    out: dict = {}
    # a through-cut left as a stroke (one that runs on past the outline) cuts its line first
    names = {output.parts[i].name for i in todo}
    for st in getattr(output, "cuts", ()):
        if st.part in names:
            for s in st.segments:
                _add(cover, _span(s))
    # row by row from the lowest left corner: which of two pieces cuts their edge is free,
    # and so each piece finds the edges below and left of it cut, and cuts the rest of its
    # outline in one run (in the output's order a piece could be left two stretches apart)
    corner = {i: _corner(output.parts[i]) for i in todo}
    for i in sorted(todo, key=lambda i: (corner[i][1], corner[i][0], i)):
        p = output.parts[i]
        spans = [[_span(s) for s in lp.segments] for lp in p.loops]
        for k, (lp, sp) in enumerate(zip(p.loops, spans)):
            kept = [_uncovered(cover, x) for x in sp]
            if all(len(r) == 1 and r[0] == (x[1], x[2]) for r, x in zip(kept, sp)):
                continue                 # nothing of it cut before: the loop whole
            out[(i, k)] = _chains(lp.segments, sp, kept)
        for sp in spans:                 # this part's outline is cut from now on
            for x in sp:
                _add(cover, x)
    return out


def loop_paths(once: dict, i: int, k: int, loop) -> list:
    """The paths that cut loop ``k`` of part ``i``: ``[(segments, closed)]`` from
    :func:`cut_once`'s answer ``once``, or the whole loop."""
    got = once.get((i, k))
    return [(list(loop.segments), True)] if got is None else got


def _corner(p) -> tuple:
    """The lower left corner ``(x0, y0)`` (mm) of part ``p``'s box, rounded to 1e-6 mm (a
    row's pieces share their ``y0``)."""
    boxes = [s.box() for lp in p.loops for s in lp.segments]
    return (round(min(b[0] for b in boxes), 6), round(min(b[1] for b in boxes), 6))


def _family(output) -> list:
    """The indices of ``output.parts`` that a through-cut split (``output.drawing.split``:
    a part and its ``PART.pieceK``), solid and with loops."""
    split = getattr(getattr(output, "drawing", None), "split", None) or ()
    if not split:
        return []
    return [i for i, p in enumerate(output.parts)
            if p.name in split and p.kind == "solid" and p.loops]


def shared_edges(output) -> dict:
    """The edges the pieces of a cut part share, for the kerf and the router's tool offset
    (:func:`~..fabrication.layout.compensate`): part index -> one ``(loop, keep,
    neighbours)`` per loop of that part, the loop with its segments split where a stretch
    another piece runs along starts or ends (each piece of it shared whole or not at all),
    the indices of its shared segments and, for each of them in order, the index of the part
    on the other side.  Parts sharing nothing are left out.  Shared is as in :func:`cut_once`
    (one carrier, ranges overlapping by more than :data:`SHARED_TOL` mm), with any other
    piece of the same split, whatever the order; each carrier's ranges are cut into its
    elementary stretches once, sorted, so a sheet of n pieces costs O(n log n)."""
    todo = _family(output)
    if len(todo) < 2:
        return {}
    spans = {i: [[_span(s) for s in lp.segments] for lp in output.parts[i].loops] for i in todo}
    marks: dict = {}                 # carrier -> [(lo, hi, part)], a wrapping one 3 times
    for i in todo:
        for sp in spans[i]:
            for key, lo, hi, _, tol, wrap in sp:
                if key is not None and hi - lo > tol:
                    for d in ((-TWO_PI, 0.0, TWO_PI) if wrap else (0.0,)):
                        marks.setdefault(key, []).append((lo + d, hi + d, i))
    table = {}                       # carrier -> (breaks, the parts over each stretch)
    for key, rs in marks.items():
        breaks = sorted({v for lo, hi, _ in rs for v in (lo, hi)})
        over: list = [set() for _ in breaks]
        for lo, hi, i in rs:
            for k in range(bisect.bisect_left(breaks, lo), bisect.bisect_left(breaks, hi)):
                over[k].add(i)
        table[key] = (breaks, over)
    out: dict = {}
    for i in todo:
        loops, hit = [], False
        for lp, sp in zip(output.parts[i].loops, spans[i]):
            segs, keep, nbs = [], [], []
            for s, x in zip(lp.segments, sp):
                for lo, hi, j in _stretches(table, x, i):
                    if j is not None:
                        keep.append(len(segs))
                        nbs.append(j)
                    segs.append(_piece(s, x, lo, hi))
            loops.append((Loop(segs), frozenset(keep), nbs))
            hit = hit or bool(keep)
        if hit:
            out[i] = loops
    return out


def _stretches(table: dict, x: tuple, i: int) -> list:
    """Span ``x`` of part ``i`` as ``[(lo, hi, j)]`` in its direction: its stretches with
    the part ``j`` on the other side (None: not shared), neighbouring ones with the same
    ``j`` merged; one stretch, the whole span, when nothing of it is shared."""
    key, lo, hi, fwd, tol, _ = x
    got = table.get(key)
    if key is None or got is None:
        return [(lo, hi, None)]
    breaks, over = got
    out: list = []
    k = max(bisect.bisect_right(breaks, lo + tol) - 1, 0)
    while k < len(breaks) - 1 and breaks[k] < hi - tol:
        a, b = max(breaks[k], lo), min(breaks[k + 1], hi)
        if b - a > tol:
            others = over[k] - {i}
            j = min(others) if others else None
            if out and out[-1][2] == j:
                out[-1] = (out[-1][0], b, j)
            else:
                out.append((a, b, j))
        k += 1
    if not out or all(j is None for *_, j in out):
        return [(lo, hi, None)]
    out[0] = (lo, *out[0][1:])           # the span's own ends exactly
    out[-1] = (out[-1][0], hi, out[-1][2])
    return out if fwd else out[::-1]


def shared_note(output, width, what: str = "the kerf") -> list[str]:
    """The notes on the shared edges of ``output`` (:func:`shared_edges`) cut with ``width``
    mm (a kerf or a router's tool diameter: mm, or a dict part name -> mm): a shared edge is
    cut once on its line, so each side loses half of ``width`` there.  One note per cut part:
    its pair of pieces by name, or how many shared cuts between how many pieces.  ``what``:
    how the width is named ("the kerf", "the bit")."""
    d = output.drawing
    pairs: dict = {}                 # the cut part's path -> {(a, b)}
    for i, loops in shared_edges(output).items():
        for _, _, nbs in loops:
            for j in nbs:
                a, b = sorted((output.parts[i].name, output.parts[j].name))
                s = d.part_of.get(output.parts[i].name)
                pairs.setdefault(s.path if s is not None else a, set()).add((a, b))
    out = []
    for name, got in sorted(pairs.items()):
        names = {n for pair in got for n in pair}
        w = max(width.get(n, 0.0) for n in names) if isinstance(width, dict) else width
        if not w:
            continue
        loss = f"each side loses {w / 2:g} mm (half {what}, {w:g} mm) along " + \
            ("it" if len(got) == 1 else "each")
        if len(got) == 1:
            ((a, b),) = got
            out.append(f"note: the shared cut between `{a}` and `{b}` is cut once along its "
                       f"line; {loss}")
        else:
            out.append(f"note: the {len(got)} shared cuts between the {len(names)} pieces of "
                       f"`{name}` are each cut once along their line; {loss}")
    return out


# ------------------------------------------------------------------ carriers and ranges
def _span(s) -> tuple:
    """``(key, lo, hi, forward, tol, wrap)``: the carrier of segment ``s`` (``key``; None: a
    segment never shared), the range ``lo < hi`` of the carrier's parameter it covers (mm
    along a line, radians round a circle or an ellipse, the position along a spline), whether
    ``s`` runs from ``lo`` to ``hi``, the parameter's :data:`SHARED_TOL` and whether it wraps
    round at 2 pi."""
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        L = math.hypot(x1 - x0, y1 - y0)
        if L == 0:
            return (None, 0.0, 0.0, True, SHARED_TOL, False)
        ux, uy = (x1 - x0) / L, (y1 - y0) / L
        rx, ry = round(ux, 9) + 0.0, round(uy, 9) + 0.0
        if rx < 0 or (rx == 0 and ry < 0):
            # (the rounded direction decides: a line 1e-13 mm off vertical is the vertical's
            # carrier, run either way)
            ux, uy, rx, ry = -ux, -uy, -rx + 0.0, -ry + 0.0
        key = ("L", rx, ry, round(ux * y0 - uy * x0, 7) + 0.0)
        t0, t1 = ux * x0 + uy * y0, ux * x1 + uy * y1
        return (key, min(t0, t1), max(t0, t1), t1 >= t0, SHARED_TOL, False)
    if isinstance(s, (Arc, Circle)):
        (cx, cy), r = s.center, s.radius
        key = ("C", round(cx, 7) + 0.0, round(cy, 7) + 0.0, round(r, 7) + 0.0)
        tol = SHARED_TOL / max(r, SHARED_TOL)
        if isinstance(s, Circle):
            return (key, 0.0, TWO_PI, s.ccw, tol, True)
        a, b = sorted((s.start_angle, s.start_angle + s.sweep))
        a0 = a % TWO_PI
        return (key, a0, a0 + (b - a), s.sweep > 0, tol, True)
    if isinstance(s, Spline):
        return (("S", id(s.curve)), min(s.u0, s.u1), max(s.u0, s.u1), s.u1 >= s.u0, 1e-7,
                False)
    if isinstance(s, EllipticArc):
        a, b = sorted((s.start_param, s.start_param + s.sweep))
        a0 = a % TWO_PI
        tol = SHARED_TOL / max(min(s.curve.rx, s.curve.ry), SHARED_TOL)
        return (("E", id(s.curve)), a0, a0 + (b - a), s.sweep > 0, tol, True)
    return (None, 0.0, 0.0, True, SHARED_TOL, False)


def _add(cover: dict, x: tuple) -> None:
    """Record the range of span ``x`` as cut (a wrapping one also one turn round, so that a
    range asked anywhere in [0, 4 pi) finds it)."""
    key, lo, hi, _, tol, wrap = x
    if key is None or hi - lo <= tol:
        return
    ranges = cover.setdefault(key, ([], []))
    for d in ((-TWO_PI, 0.0, TWO_PI) if wrap else (0.0,)):
        if hi + d > 0 or not wrap:
            _merge(ranges, lo + d, hi + d)


def _merge(ranges, lo: float, hi: float) -> None:
    """Insert ``[lo, hi]`` into the sorted disjoint ranges ``(starts, ends)``, merged."""
    starts, ends = ranges
    i = bisect.bisect_left(ends, lo)            # the first range ending at or after lo
    j = bisect.bisect_right(starts, hi)         # past the last range starting by hi
    if i < j:
        lo, hi = min(lo, starts[i]), max(hi, ends[j - 1])
    starts[i:j] = [lo]
    ends[i:j] = [hi]


def _uncovered(cover: dict, x: tuple) -> list:
    """The pieces ``[(lo, hi)]`` (ascending) of span ``x``'s range not yet cut; a piece
    shorter than its tolerance is left out, and so is an overlap that short."""
    key, lo, hi, _, tol, _ = x
    ranges = cover.get(key)
    if key is None or ranges is None:
        return [(lo, hi)]
    starts, ends = ranges
    out, at = [], lo
    i = bisect.bisect_right(ends, lo + tol)
    while i < len(starts) and starts[i] < hi - tol:
        if ends[i] - max(starts[i], lo) > tol:      # an overlap, not a touch
            if starts[i] - at > tol:
                out.append((at, starts[i]))
            at = max(at, ends[i])
        i += 1
    if hi - at > tol:
        out.append((at, hi))
    if len(out) == 1 and abs(out[0][0] - lo) <= tol and abs(out[0][1] - hi) <= tol:
        return [(lo, hi)]
    return out


# ------------------------------------------------------------------ the loop less its stretches
def _piece(s, x: tuple, lo: float, hi: float):
    """Segment ``s`` (span ``x``) between its parameters ``lo`` < ``hi``, in its direction;
    an end at the segment's own end is that end exactly."""
    _, a, b, fwd, tol, _ = x
    if abs(lo - a) <= tol and abs(hi - b) <= tol:
        return s
    if isinstance(s, Line):
        (x0, y0), (x1, y1) = s.start, s.end
        ta, tb = (a, b) if fwd else (b, a)          # the parameters of start and end

        def at(t):
            if abs(t - ta) <= tol:
                return s.start
            if abs(t - tb) <= tol:
                return s.end
            f = (t - ta) / (tb - ta)
            return (x0 + f * (x1 - x0), y0 + f * (y1 - y0))
        return Line(at(lo), at(hi)) if fwd else Line(at(hi), at(lo))
    if isinstance(s, Circle):
        return Arc(s.center, s.radius, lo, hi - lo) if s.ccw else \
            Arc(s.center, s.radius, hi, lo - hi)
    if isinstance(s, Arc):
        base = s.start_angle if fwd else s.start_angle + s.sweep   # the angle at ``a``
        p, q = base + (lo - a), base + (hi - a)
        return Arc(s.center, s.radius, p, q - p) if fwd else Arc(s.center, s.radius, q, p - q)
    if isinstance(s, Spline):
        return Spline(s.curve, lo, hi) if fwd else Spline(s.curve, hi, lo)
    base = s.start_param if fwd else s.start_param + s.sweep
    p, q = base + (lo - a), base + (hi - a)
    return EllipticArc(s.curve, p, q - p) if fwd else EllipticArc(s.curve, q, p - q)


def _chains(segs: list, spans: list, kept: list) -> list:
    """The open chains of a loop's segments ``segs`` keeping only the ranges ``kept`` of each
    (``spans``: theirs), in the loop's direction, joined across the loop's start."""
    items: list = []                 # segments, None where a stretch is left out
    for s, x, pieces in zip(segs, spans, kept):
        _, a, b, fwd, tol, _ = x
        if not fwd:
            pieces = [(lo, hi) for lo, hi in reversed(pieces)]
        if not pieces:
            items.append(None)
            continue
        first, last = (pieces[0][0], pieces[-1][1]) if fwd else (pieces[0][1], pieces[-1][0])
        if abs(first - (a if fwd else b)) > tol:
            items.append(None)
        for n, (lo, hi) in enumerate(pieces):
            if n:
                items.append(None)
            items.append(_piece(s, x, lo, hi))
        if abs(last - (b if fwd else a)) > tol:
            items.append(None)
    if None not in items:
        return [(list(segs), True)]
    k = items.index(None)
    items = items[k:] + items[:k]    # from a gap round the loop: no chain split at its start
    chains, run = [], []
    for it in items + [None]:
        if it is None:
            if run:
                chains.append((run, False))
            run = []
        else:
            run.append(it)
    return chains


__all__ = ["cut_once", "loop_paths", "shared_edges", "shared_note", "SHARED_TOL"]
