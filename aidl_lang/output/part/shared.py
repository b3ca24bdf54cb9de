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

With a kerf (:func:`~..fabrication.layout.compensate`), :func:`kerf_pieces` re-cuts the
pieces of each cut part from the part offset by half the kerf, so that a shared edge stays
one cut on its line (carried on across the offset band) instead of two cuts a kerf apart;
:func:`kerf_note` is the note that says each piece is half a kerf short along the cuts.
"""
from __future__ import annotations

import bisect
import math

from ...geometry.curves import Arc, Circle, EllipticArc, Line, Loop, Spline, reverse, tangent_at

SHARED_TOL = 1e-6      # mm: a stretch shorter than this is not shared (ends that only touch)
TWO_PI = 2 * math.pi


def cut_once(output) -> dict:
    """``{(part index, loop index): [(segments, closed), ...]}`` for each loop of
    ``output.parts`` that an earlier part of the same split family already cuts in part:
    the loop's segments less the stretches cut before, as open chains (``closed`` False) in
    the loop's own direction (an empty list: the whole loop is cut already).  Loops not in it
    are cut whole.  Only the parts a through-cut split (``output.drawing.split``) are
    compared; on no such part the answer is ``{}``."""
    split = getattr(getattr(output, "drawing", None), "split", None) or ()
    if not split:
        return {}
    cover: dict = {}
    out: dict = {}
    todo = [i for i, p in enumerate(output.parts)
            if p.name in split and p.kind == "solid" and p.loops]
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


def kerf_pieces(output, parts: list, kerf) -> list:
    """``parts`` (the kerf-offset outlines of ``output.parts``, in their order; ``kerf``: mm,
    or a dict part name -> mm) with the pieces of each cut part re-cut from their offset
    union: the part offset by half the kerf (the union of its pieces' offsets), less its
    through-cuts, each end on the outline carried on along its tangent across the offset band
    (:func:`_carried`).  Each outline offset on its own ran its side of a shared edge half a
    kerf into the neighbour, so the two cuts, a kerf apart, took a whole kerf off each piece
    there (a 3 x 3 grid of 10 mm squares at kerf 0.2 mm: the middle square 9.6 mm, with no
    word); re-cut, a shared edge is one cut on the line (:func:`cut_once`), each piece half a
    kerf short there (:func:`kerf_note` says so), offset outward everywhere else, and the cut
    runs on straight across the band to the offset outline.  Parts not offset, and parts
    that are not pieces of a cut part, are returned as they are."""
    import manifold3d as mf

    from .booleans import SLIT_GROW, SLIT_HALF, _chain_points, _meeting, _quad
    from .exact import Provenance
    from .part import PartOutline
    d = getattr(output, "drawing", None)
    split = getattr(d, "split", None) or ()
    if not split:
        return parts
    family: dict = {}
    for i, (p, c) in enumerate(zip(output.parts, parts)):
        if p.name in split and p.kind == "solid" and c is not p and p.loops:
            family.setdefault(d.part_of.get(p.name), []).append(i)
    parts = list(parts)
    for s, idx in family.items():
        k = kerf.get(output.parts[idx[0]].name, 0.0) if isinstance(kerf, dict) else kerf
        if len(idx) < 2 or not k:
            continue
        prov = Provenance()
        grown = [prov.section(parts[i].loops) for i in idx]
        drawn = [prov.section(output.parts[i].loops) for i in idx]
        band = mf.CrossSection.batch_boolean(grown, mf.OpType.Add)
        # each piece in its connected pieces (a part may be many: a sheet's), each asked only
        # of what meets its box: a sheet of n pieces costs O(n log n), not n^2
        held = [(j, c) for j, sec in enumerate(drawn) for c in sec.decompose()]
        near_g = [c for sec in grown for c in sec.decompose()]
        bands = []
        chains = [th.segments for th in d.through
                  if th.part is s and not th.on_outline and th.segments]
        for segs in _carried(chains, [c for _, c in held], 4 * k):
            prov.polygon(Loop(segs + [reverse(x) for x in reversed(segs)]))
            pts = _chain_points(segs)
            bands += [_quad(pts[j], pts[j + 1], SLIT_HALF) for j in range(len(pts) - 1)]
        if not bands:
            continue
        comps = (band - mf.CrossSection.batch_boolean(bands, mf.OpType.Add)).decompose()
        owner = _meeting(comps, [c for _, c in held])
        got: dict = {}
        for c, near in zip(comps, owner):     # each piece of the band to the piece it holds
            best, most = None, 0.0
            for n in near:
                a = (c ^ held[n][1]).area()
                if a > most:
                    best, most = held[n][0], a
            if best is not None:
                got.setdefault(best, []).append(c.offset(SLIT_GROW, mf.JoinType.Miter))
        todo = sorted(got)
        pieces = [c for j in todo for c in got[j]]
        # within the offset part (exact there): the offset pieces whose boxes meet its own
        local = _meeting(pieces, near_g)
        cut = [c ^ mf.CrossSection.batch_boolean([near_g[i] for i in near], mf.OpType.Add)
               for c, near in zip(pieces, local)]
        at = 0
        shapes = []
        for j in todo:
            shapes.append(mf.CrossSection.batch_boolean(cut[at:at + len(got[j])], mf.OpType.Add))
            at += len(got[j])
        for j, loops in zip(todo, prov.loops_of(shapes)):
            c = parts[idx[j]]
            parts[idx[j]] = PartOutline(c.name, c.kind, loops, c.thickness)
    return parts


def _carried(chains: list, shapes: list, length: float) -> list:
    """Each chain of ``chains`` (through-cuts, exact segments) with each end that lies on the
    outline of the region ``shapes`` cover (disjoint CrossSections: a small square round the
    end not wholly inside them) carried on ``length`` mm along its tangent, as a
    :class:`Line` (a line's own carrier: the line made longer).  All ends are asked of the
    shapes their boxes meet at once (:func:`~.booleans._meeting`)."""
    import manifold3d as mf

    from .booleans import _meeting
    h = 1e-5
    ends = [(c, at_end) for c in range(len(chains)) for at_end in (False, True)]
    squares = []
    for c, at_end in ends:
        p = chains[c][-1].end if at_end else chains[c][0].start
        squares.append(mf.CrossSection([[(p[0] - h, p[1] - h), (p[0] + h, p[1] - h),
                                         (p[0] + h, p[1] + h), (p[0] - h, p[1] + h)]]))
    out = [list(segs) for segs in chains]
    for (c, at_end), sq, near in zip(ends, squares, _meeting(squares, shapes)):
        if sum((shapes[i] ^ sq).area() for i in near) >= sq.area() * (1 - 1e-6):
            continue                          # it ends inside the material: left as it is
        segs = out[c]
        s = segs[-1] if at_end else segs[0]
        p = s.end if at_end else s.start
        tx, ty = tangent_at(s, at_end)
        # a line carried on is one longer line (two chords on one carrier would be one edge
        # of the booleans' result, which the exact recovery matches to a single chord)
        if at_end:
            q = (p[0] + length * tx, p[1] + length * ty)
            if isinstance(s, Line):
                segs[-1] = Line(segs[-1].start, q)
            else:
                segs.append(Line(p, q))
        else:
            q = (p[0] - length * tx, p[1] - length * ty)
            if isinstance(s, Line):
                segs[0] = Line(q, segs[0].end)
            else:
                segs.insert(0, Line(q, p))
    return out


def kerf_note(output, cut) -> str:
    """The note when the kerf offset (``cut``: :func:`~..fabrication.layout.for_cutting`
    of ``output``) met pieces of a cut part: their shared edges are cut once on the line,
    not offset; "" when there is nothing to say."""
    d = getattr(output, "drawing", None)
    split = getattr(d, "split", None) or ()
    if cut is output or not split:
        return ""
    names = sorted({d.part_of[p.name].path for p, c in zip(output.parts, cut.parts)
                    if p.name in split and c is not p and p.name in d.part_of})
    if not names:
        return ""
    which = ", ".join(f"`{n}`" for n in names[:3]) + (" ..." if len(names) > 3 else "")
    return (f"note: the kerf offset cuts the edges the pieces of {which} share once, on the "
            "cut: each piece comes out half a kerf short there (one cut cannot be offset "
            "for the pieces on both sides)")


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
        if ux < 0 or (ux == 0 and uy < 0):
            ux, uy = -ux, -uy
        key = ("L", round(ux, 9) + 0.0, round(uy, 9) + 0.0, round(ux * y0 - uy * x0, 7) + 0.0)
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


__all__ = ["cut_once", "kerf_note", "kerf_pieces", "loop_paths", "SHARED_TOL"]
