"""The one output model: exact lines, arcs and circles per part, from the booleans' result.

Every face handed to Manifold was an exact outline (:mod:`aidl_lang.geometry.shapes.curves`), and the
booleans' :class:`~.exact.Provenance` knows which exact curve each polygon edge came from.
:func:`build` puts each part's polygons back on those curves (docs/outputs.md, "Exact
geometry"): each run of edges on one carrier is one :class:`Line`, :class:`Arc` or
:class:`Circle`, and each vertex where two curves meet is their exact intersection (or the
touching point of a tangent join), so slots, rounded rectangles, fillets and every union or
cut of them come out as the program meant them, to floating-point accuracy; a spline that a
cut crosses is its exact piece (de Casteljau at the crossing positions), and an ellipse's
pieces are :class:`EllipticArc` s of it (between the parameters of their exact ends).

The result, :class:`Output`, holds :class:`PartOutline` s (name, kind, loops, thickness, and
the loops tessellated once more for meshes) and engraving strokes (text as one polyline per
pen stroke); every writer (SVG, DXF, PNG, STL/3MF, STEP) reads it.  All lengths are in
millimetres, angles in radians, y up.
"""
from __future__ import annotations

import math

import numpy as np

from ...base.records import Compared
from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Loop, Segment, Spline, sample_xy
from ...base.limits import OutOfBudget, OutOfMemory, is_out_of_memory
from ...base.memory import gc_paused
from .build.booleans import Drawing

__all__ = ["Arc", "Circle", "EllipticArc", "Line", "Loop", "Segment", "Spline", "Output", "PartOutline", "Stroke",
           "OutputError", "MissingDependency", "build"]

Point = tuple[float, float]
# The parts' colours, in order, in every view (the SVG preview, the assembled GLB, STEP and
# picture): Okabe and Ito's palette for colour-blind readers, with black moved last.
PALETTE = ("#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#b8a200",
           "#000000")


class OutputError(RuntimeError):
    """A writer cannot produce this file from this part (for example a PNG larger than the
    rasteriser allows); the message says why and what to change.  ``budget``: the
    :class:`~aidl_lang.base.limits.OutOfBudget` behind it when bounded work ran out (its ``where``
    names the structure), so that a front end with the compile's diagnostics can report it as
    a located ``E0304`` (:func:`aidl_lang.pipeline.report_out_of_budget`); else ``None``."""

    def __init__(self, message: str, budget=None):
        super().__init__(message)
        self.budget = budget


class MissingDependency(OutputError):
    """An optional output library is not installed; the message says how to install it."""


class PartOutline(Compared):
    """One part: its name (structure path), kind (``solid``, or ``hole`` for a hole with no
    solid to cut), outline loops (outer ones counter-clockwise, holes clockwise) and thickness
    (mm, for 3D outputs)."""
    __slots__ = ("name", "kind", "loops", "thickness")

    def __init__(self, name: str, kind: str, loops: list[Loop], thickness: float | None = None):
        self.name = name
        self.kind = kind
        self.loops = loops
        self.thickness = thickness

    @property
    def shape(self):
        """A manifold3d CrossSection of the exact loops cut into chords within
        ``CHORD_TOL``, every vertex on its curve (what STL/3MF extrude); made on first use."""
        got = self.__dict__.get("_shape")
        if got is None:
            got = self.__dict__["_shape"] = _mesh_section(self.loops)
        return got

    @property
    def area(self) -> float:
        return sum(lp.area for lp in self.loops)

    @property
    def perimeter(self) -> float:
        return sum(lp.perimeter for lp in self.loops)


class Stroke(Compared):
    """Engraving, or a through-cut: an open or closed chain of segments (``style`` drawing |
    open: engraved or scored; ``fill``: a closed loop of an area engraved filled,
    :func:`fill_regions`; ``cut``: a ``cut`` structure's curve, cut through the part
    along the line as written, zero width), each segment ending where the next starts (a
    laser runs it without lifting).  ``part``: the
    name of the part whose structure (or an ancestor of it) holds the engraving, "" for one
    at assembly level outside every part (a cutting layout moves it with that part)."""
    __slots__ = ("segments", "style", "closed", "source", "part")

    def __init__(self, segments: list[Segment], style: str = "drawing", closed: bool = False,
                 source: str = "", part: str = ""):
        self.segments = segments
        self.style = style
        self.closed = closed
        self.source = source
        self.part = part


class SinkStroke(Stroke):
    """The head of a countersink or counterbore (issue 102): its circle, of style
    ``countersink`` or ``counterbore``, and ``sink``, the booleans' record of it
    (:class:`~.build.result.SinkAt`: the hole, the sizes), which a layout's moves keep."""
    __slots__ = ("sink",)

    def __init__(self, segments, style, closed, source, part, sink):
        super().__init__(segments, style, closed, source, part)
        self.sink = sink

    def moved(self, segments: list) -> "SinkStroke":
        """This head with ``segments`` (moved by a layout)."""
        return SinkStroke(segments, self.style, self.closed, self.source, self.part, self.sink)


class Output(Compared):
    """What the writers get: exact part outlines and engraving strokes (mm); the strokes of
    style ``cut`` are through-cuts (:attr:`cuts`), cut through the material, not engraved."""
    __slots__ = ("parts", "engrave", "title", "drawing", "page", "stray")

    def __init__(self, parts: list[PartOutline] | None = None, engrave: list[Stroke] | None = None,
                 title: str = "", drawing: Drawing | None = None, page: tuple | None = None):
        self.parts = [] if parts is None else parts
        self.engrave = [] if engrave is None else engrave
        self.title = title
        self.drawing = drawing  # the booleans' result (debug layers, checks)
        # (x0, y0, x1, y1) mm: a fixed page (a cutting layout's sheet) instead of the extent
        self.page = page
        # the holes declared in an assembly (W0109: they cut nothing), not among the parts: no
        # output cuts them; the preview SVG draws them dashed where they lie
        self.stray: list[PartOutline] = []

    @property
    def cuts(self) -> list:
        """The through-cuts: the strokes of style ``cut`` (exact open or closed paths)."""
        return [st for st in self.engrave if st.style == "cut"]

    @property
    def area(self) -> float:
        """Total area (mm^2) of the solid parts."""
        return sum(p.area for p in self.parts if p.kind == "solid")

    def bounds(self) -> tuple[float, float, float, float]:
        """(x0, y0, x1, y1) in mm: the extent of every loop's and stroke's :meth:`Loop.points`
        (and each open stroke's last end), or (0, 0, 1, 1) when there is nothing."""
        xs: list = []
        ys: list = []
        for p in self.parts:
            for lp in p.loops:
                sample_xy(lp.segments, xs, ys)
        for st in self.engrave:
            sample_xy(st.segments, xs, ys)
            for s in st.segments:
                if not isinstance(s, Circle):
                    e = s.end
                    xs.append(e[0])
                    ys.append(e[1])
        if not xs:
            return (0.0, 0.0, 1.0, 1.0)
        return (min(xs), min(ys), max(xs), max(ys))


# ------------------------------------------------------------------ build
def _t(p) -> Point:
    return (float(p[0]), float(p[1]))


def _stroke(item, exact, style: str, source: str) -> Stroke | None:
    kind = item[0]
    if kind == "line":
        return Stroke([Line(_t(item[1]), _t(item[2]))], style, False, source)
    if kind == "arc":
        _, c, r, a1, a2 = item
        sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
        return Stroke([Arc(_t(c), float(r), float(a1), float(sweep))], style, False, source)
    if kind == "circle":
        return Stroke([Circle(_t(item[1]), float(item[2]))], style, True, source)
    if kind in ("spline", "ellipse_arc"):
        return Stroke([item[1]], style, item[1].whole, source)
    lp = item[2] if len(item) > 2 else exact.recover(item[1])
    return Stroke(list(lp.segments), style, True, source) if lp.segments else None


def _join(strokes: list[Stroke]) -> list[Stroke]:
    """The open strokes of one source (a text's pen strokes, a drawing's lines) joined into
    runs: wherever exactly two open ends meet, the two strokes become one (one is turned
    round when needed), so a laser runs each run without lifting; a run that comes back to
    its start is a closed stroke.  Strokes of other sources, closed ones and circles stay."""
    from ...geometry.shapes.curves import reverse
    out: list[Stroke] = []
    groups: dict = {}
    for st in strokes:
        if st.closed or not st.segments or any(isinstance(g, Circle) or
                                               (isinstance(g, (Spline, EllipticArc))
                                                and g.whole)
                                               for g in st.segments):
            out.append(st)
            continue
        key = (st.source, st.style, st.part)
        if key not in groups:
            groups[key] = []
            out.append(key)              # the group's place in the drawing order
        groups[key].append(list(st.segments))
    result = []
    for item in out:
        if isinstance(item, Stroke):
            result.append(item)
            continue
        source, style, part = item
        for chain, closed in _runs_of(groups[item], reverse):
            result.append(Stroke(chain, style, closed, source, part))
    return result


def _end_key(p) -> tuple:
    return (round(p[0], 9), round(p[1], 9))


def _runs_of(chains: list[list], reverse) -> list[tuple[list, bool]]:
    """Join open chains of segments at every point where exactly two chain ends meet."""
    chains = [c for c in chains]
    alive = [True] * len(chains)
    ends: dict = {}
    for i, c in enumerate(chains):
        ends.setdefault(_end_key(c[0].start), []).append(i)
        ends.setdefault(_end_key(c[-1].end), []).append(i)
    changed = True
    while changed:
        changed = False
        for key, at in list(ends.items()):
            live = [i for i in at if alive[i]]
            if len(live) != 2 or live[0] == live[1]:
                continue
            i, j = live
            a, b = chains[i], chains[j]
            # orient so that a ends and b starts at this point
            if _end_key(a[-1].end) != key:
                a = [reverse(g) for g in reversed(a)]
            if _end_key(b[0].start) != key:
                b = [reverse(g) for g in reversed(b)]
            chains[i] = a + b
            alive[j] = False
            ends[key] = []
            for k in (_end_key(chains[i][0].start), _end_key(chains[i][-1].end)):
                ends[k] = [i if x == j else x for x in ends.get(k, [])]
            changed = True
    out = []
    for i, c in enumerate(chains):
        if alive[i]:
            closed = len(c) > 2 and _end_key(c[0].start) == _end_key(c[-1].end)
            out.append((c, closed))
    return out


def build(drawing: Drawing, title: str = "", thickness=None, deadline=None) -> Output:
    """The exact :class:`Output` of a booleans :class:`Drawing`.  ``thickness`` maps a part's
    name to its thickness in mm (or is one number for all parts); by default the program's
    (``thickness 3 mm``, :attr:`Drawing.thickness`).  ``deadline``: the compile's
    :class:`~aidl_lang.base.limits.Deadline` (``aidl render``), or None for no wall-time bound.
    Raises :class:`OutputError` (with its ``budget``) when the exact outlines cannot be
    recovered within bounded work (thousands of curves on top of each other) or before the
    deadline.  The collector is paused meanwhile (:func:`~aidl_lang.base.memory.gc_paused`)."""
    with gc_paused():
        return _build(drawing, title, thickness, deadline)


def _build(drawing: Drawing, title: str, thickness, deadline) -> Output:
    from .edges.exact import Provenance
    exact = drawing.exact if drawing.exact is not None else Provenance()
    out = Output(title=title, drawing=drawing)
    if thickness is None:
        thickness = drawing.thickness
    parts = [p for p in drawing.parts if not p.shape.is_empty()]
    try:
        try:
            part_loops = exact.loops_of([p.shape for p in parts], deadline)
        except (MemoryError, SystemError) as ex:
            if not is_out_of_memory(ex):
                raise
            part_loops = None
        if part_loops is None:          # raised here, once the failed frames are gone
            raise OutOfMemory("the exact outlines")
    except OutOfBudget as ex:
        # the part with the most result vertices: where the curves lie on top of each other
        biggest = max(parts, key=lambda p: p.shape.num_vert())
        ex.where = drawing.part_of.get(biggest.name)
        fix = ("build less" if isinstance(ex, OutOfMemory) else
               "draw fewer curves on top of each other" if ex.hint else
               "build less or raise the budget (`--budget 2`)")
        raise OutputError(f"cannot recover the exact outlines: {ex.what}; {fix}", ex) from None
    for p, loops in zip(parts, part_loops):
        if not loops:
            continue
        t = thickness.get(p.name) if isinstance(thickness, dict) else thickness
        s = drawing.part_of.get(p.name)
        stray = p.kind == "hole" and s is not None and s.parent is not None \
            and s.parent.kind == "assembly"
        (out.stray if stray else out.parts).append(PartOutline(p.name, p.kind, loops, t))
    strokes = []
    owner: dict = {}
    for name, s in drawing.part_of.items():     # a split part's pieces: its own name
        if name == s.path or s not in owner:
            owner[s] = name
    for style, item, g in drawing.strokes:
        st = _stroke(item, exact, style, g.label if g is not None else "")
        if st is not None:
            st.part = _part_of(g, owner)
            strokes.append(st)
    split = getattr(drawing, "split", ())
    if split:
        strokes = _off_outlines(strokes, [p for p in out.parts if p.name in split])
        _onto_pieces(strokes, [p for p in out.parts if p.name in split])
    out.engrave = _join(_cut_once(strokes, out.parts))
    # the head of each countersink and counterbore: its circle, on a layer of its own
    out.engrave += [SinkStroke([Circle(sk.center, sk.diameter / 2)], sk.kind, True, sk.hole,
                               sk.part, sk) for sk in getattr(drawing, "sinks", ())]
    return out


def fill_regions(strokes) -> list[tuple[str, str, list[list]]]:
    """The areas engraved filled (issue 112: a ``Text(..., font=, fill=true)`` in a drawing,
    its strokes of style ``fill``), one per source and part, in drawing order: ``(source,
    part, [each closed loop's segments])``, outer loops counter-clockwise and their holes (a
    letter's counters) clockwise, none crossing another (the letters' union): an area filled
    by the even-odd rule and by the non-zero rule alike."""
    out: dict = {}
    for st in strokes:
        if st.style == "fill" and st.segments:
            out.setdefault((st.source, st.part), []).append(list(st.segments))
    return [(src, part, loops) for (src, part), loops in out.items()]


def sink_heads(output: Output) -> list[tuple]:
    """The countersinks and counterbores of ``output`` where its head strokes are (moved
    with their parts by a layout): ``[(centre, SinkAt)]`` (:class:`SinkStroke`)."""
    return [(tuple(st.segments[0].center), st.sink) for st in output.engrave
            if isinstance(st, SinkStroke) and st.segments]


def sink_tools(heads: list, t: float) -> list:
    """The solids a part ``t`` mm thick loses to its ``heads`` (:func:`sink_heads`): a
    countersink's cone from the hole's diameter up to the head's at the top face, a
    counterbore's cylinder down its depth; each reaching 0.01 mm above the top
    (``manifold3d.Manifold``, mm)."""
    import manifold3d as mf
    e = 0.01
    out = []
    for (x, y), r in heads:
        depth = r.cone_depth()
        if depth <= 0:
            continue
        # the hole's own polygon (its chords, as the part's section has them), scaled: the
        # tool's rings have the hole's vertices' angles, so no edge of it crosses the hole's
        # wall between two of them (near-equal vertices that a reader's merge would break)
        ring = Loop([Circle((0.0, 0.0), r.hole_d / 2)]).points()
        section = mf.CrossSection([ring.tolist()])
        if r.kind == "countersink":
            # the cone begun e below its seat, narrower than the hole there: it crosses the
            # hole's wall at the seat instead of meeting it ring on ring (rings 1e-10 mm
            # apart, which an STL reader merges into a torn mesh: issue 109, law 2);
            k = math.tan(r.angle / 2)
            lo = (r.hole_d / 2 - e * k) / (r.hole_d / 2)
            # its edges a third of the way between the wall's: each crossing transversal, and
            # no two mirrored heads' edges meeting on their mirror plane (at a half step, or
            # none, the vertex angles are symmetric: edge met edge 1e-8 mm apart)
            third = 120.0 / len(ring)
            tool = mf.Manifold.extrude(section.rotate(third).scale([lo, lo]), depth + 2 * e, 0,
                                       0.0,
                                       [(r.diameter / 2 + e * k) / (r.hole_d / 2 - e * k)] * 2)
            out.append(tool.translate([x, y, t - depth - e]))
            continue
        s_ = r.diameter / r.hole_d
        tool = mf.Manifold.extrude(section.scale([s_, s_]), depth + e)
        out.append(tool.translate([x, y, t - depth]))
    return out


def _onto_pieces(strokes: list[Stroke], pieces: list[PartOutline]) -> None:
    """Each stroke of a part a cut split (``pieces``: the part ``P`` and its ``P.pieceK``)
    given to the piece whose material holds it (the middle of its first segment; even-odd
    over the piece's loops), not to ``P`` whatever piece it lies on: a slit on a freed piece
    was laid out with the other piece, in the scrap beside it (`--layout sheet`)."""
    import re
    families: dict = {}             # P -> (its pieces, their boxes, their loops' points and boxes)
    for p in pieces:
        m = re.search(r"\.piece\d+$", p.name)
        families.setdefault(p.name[:m.start()] if m else p.name, [[], [], []])[0].append(p)
    for st in strokes:
        fam = families.get(st.part)
        if fam is None or len(fam[0]) < 2 or not st.segments:
            continue
        if not len(fam[1]):         # the pieces' and their loops' boxes, once per family
            for p in fam[0]:
                lps = [lp.points() for lp in p.loops]
                fam[2].append((lps, np.array([(*P.min(0), *P.max(0)) for P in lps])
                               .reshape(-1, 4)))
            fam[1] = np.array([(*b[:, :2].min(0), *b[:, 2:].max(0)) for _, b in fam[2]]) \
                .reshape(-1, 4)
        xs, ys = [], []
        sample_xy(st.segments[:1], xs, ys)
        end = getattr(st.segments[0], "end", None)
        if end is not None:
            xs.append(end[0])
            ys.append(end[1])
        k = len(xs) // 2
        x, y = ((xs[k - 1] + xs[k]) / 2, (ys[k - 1] + ys[k]) / 2) if len(xs) > 1 else \
            (xs[0], ys[0])
        box = fam[1]
        for j in np.flatnonzero((box[:, 0] <= x) & (x <= box[:, 2]) & (box[:, 1] <= y)
                                & (y <= box[:, 3])):
            if _holds(*fam[2][j], (x, y)):
                st.part = fam[0][j].name
                break


def _holds(points: list, boxes, at) -> bool:
    """Point ``at`` lies inside the loops whose chord points are ``points`` (even-odd over
    their chords); ``boxes``: their boxes (n x 4).  Only a loop whose box holds the point can
    hold it, so only those are crossed (a sheet of 2,000 holes: each stroke asked of every
    hole's loop made the build quadratic, 0.9 -> 116 s)."""
    x, y = at
    inside = False
    for k in np.flatnonzero((boxes[:, 0] <= x) & (x <= boxes[:, 2]) & (boxes[:, 1] <= y)
                            & (y <= boxes[:, 3])):
        P = points[k]
        Q = np.roll(P, -1, axis=0)
        cross = (P[:, 1] > y) != (Q[:, 1] > y)
        if not cross.any():
            continue
        t = (y - P[cross, 1]) / (Q[cross, 1] - P[cross, 1])
        inside ^= bool(np.count_nonzero(P[cross, 0] + t * (Q[cross, 0] - P[cross, 0]) > x) % 2)
    return inside


ONCE = ("cut", "drawing", "score")     # the styles whose strokes :func:`_cut_once` runs once


def _cut_once(strokes: list[Stroke], parts: list[PartOutline]) -> list[Stroke]:
    """``strokes`` with each ``cut`` stroke less the stretches already cut: those along the
    outline of a part (the outline is cut anyway) and those along an earlier ``cut`` stroke
    (two slits drawn over each other), so every cutting output cuts each place once a pass
    (docs/outputs.md, "Through-cuts").  Exact, on every kind of segment alike (a Polyline's
    side on the plate's edge, a Line part of whose length runs along a notch's side, an Arc
    over another of one circle): shared as between the pieces of a cut part
    (:func:`.shared._span`: one carrier, parameter ranges overlapping by more than
    :data:`.shared.SHARED_TOL` mm); the rest of a segment is its own piece
    (:func:`.shared._piece`).  Each carrier's ranges are kept sorted: O(n log n).  Other
    strokes, and cut strokes that share nothing, are kept as they are (the same objects).
    An engraving (``drawing``) or ``score`` stroke is engraved once the same way: less the
    stretches of an earlier stroke of its style (two handles drawn along one line, law 5 of
    docs/laws.md: the DXF drew it twice and the laser burnt it twice)."""
    from .edges.shared import _add, _piece, _span, _uncovered
    if not any(st.style in ONCE for st in strokes):
        return strokes
    covers: dict = {"cut": {}}
    for p in parts:
        for lp in p.loops:
            for seg in lp.segments:
                _add(covers["cut"], _span(seg))
    out = []
    for st in strokes:
        if st.style not in ONCE:
            out.append(st)
            continue
        cover = covers.setdefault(st.style, {})
        spans = [_span(seg) for seg in st.segments]
        kept = [_uncovered(cover, x) for x in spans]
        if all(len(r) == 1 and r[0] == (x[1], x[2]) for r, x in zip(kept, spans)):
            out.append(st)
        else:
            run: list = []              # the stroke's pieces left, each run without a gap
            for seg, x, pieces in zip(st.segments, spans, kept):
                _, a, b, fwd, tol, _ = x
                for lo, hi in (pieces if fwd else pieces[::-1]):
                    piece = _piece(seg, x, lo, hi)
                    if run and not _joins(run[-1].end, piece.start):
                        out.append(Stroke(run, st.style, False, st.source, st.part))
                        run = []
                    run.append(piece)
            if run:
                closed = st.closed and len(run) == len(st.segments) and run[0] is st.segments[0]
                out.append(Stroke(run, st.style, closed, st.source, st.part))
        for x in spans:                 # this stroke cuts its line from now on
            _add(cover, x)
    return out


def _joins(p, q) -> bool:
    return abs(p[0] - q[0]) <= 1e-9 and abs(p[1] - q[1]) <= 1e-9


ON_OUTLINE = 0.02     # mm: a through-cut this near a split part's outline is that outline


def _off_outlines(strokes: list[Stroke], parts: list[PartOutline]) -> list[Stroke]:
    """``strokes`` less the through-cut (``cut``) segments that run along the outline of a
    part they split (a piece cut off: the laser cuts that stretch once, as the outlines of
    the two pieces): five points of every chord of the segment (2 %, 25 %, 50 %, 75 %, 98 %)
    within :data:`ON_OUTLINE` of a loop of ``parts``.  A segment only partly on an outline
    stays whole (that stretch is cut twice).

    Each sample point is measured only against the outline edges near it: the points go into
    a grid (:class:`.nearby._Grid`) and each edge, cut into stretches of at most
    :data:`_STRETCH` mm, asks for the points in its stretches' boxes grown by
    :data:`ON_OUTLINE` (a point within that distance of an edge is within it of one of its
    stretches, so inside that stretch's grown box); the distance is then to the whole edge, as
    before.  Every point against every edge cost points x edges: 11 s for a plate with 2,000
    closed cuts."""
    from .build.booleans import _chain_points
    from .measure.nearby import TooManyPairs, _Grid
    edges = []
    for p in parts:
        for lp in p.loops:
            P = np.asarray(lp.points(), dtype=float).reshape(-1, 2)
            if len(P):
                edges.append((P, np.roll(P, -1, axis=0)))
    cuts = [(k, seg) for k, st in enumerate(strokes) if st.style == "cut" for seg in st.segments]
    if not edges or not cuts:
        return strokes
    A = np.vstack([a for a, _ in edges])
    B = np.vstack([b for _, b in edges])
    D = B - A
    L2 = np.maximum((D * D).sum(axis=1), 1e-300)
    samples, of = [], []
    for n, (_, seg) in enumerate(cuts):
        pts = _chain_points([seg])
        a, b = pts[:-1], pts[1:]
        m = np.vstack([a + f * (b - a) for f in (0.02, 0.25, 0.5, 0.75, 0.98)])
        samples.append(m)
        of.append(np.full(len(m), n))
    M = np.vstack(samples)
    owner = np.concatenate(of)
    # each edge's stretches (pieces of at most _STRETCH mm) and their boxes grown by the distance
    count = np.maximum(np.ceil(np.sqrt(L2) / _STRETCH), 1).astype(np.intp)
    edge = np.repeat(np.arange(len(A)), count)
    k = np.arange(len(edge)) - np.repeat(np.cumsum(count) - count, count)
    t0 = (k / count[edge])[:, None]
    t1 = ((k + 1) / count[edge])[:, None]
    S0, S1 = A[edge] + t0 * D[edge], A[edge] + t1 * D[edge]
    pad = ON_OUTLINE * (1 + 1e-9) + 1e-12
    near = np.full(len(M), np.inf)
    grid = _Grid(M, _STRETCH)
    todo = [(lo, min(lo + _QUERY, len(edge))) for lo in range(0, len(edge), _QUERY)]
    while todo:                         # at most _CANDIDATES (point, edge) pairs at a time
        lo, hi = todo.pop()
        try:
            q, i = grid.in_boxes(np.minimum(S0[lo:hi], S1[lo:hi]) - pad,
                                 np.maximum(S0[lo:hi], S1[lo:hi]) + pad,
                                 limit=_CANDIDATES if hi - lo > 1 else len(M))
        except TooManyPairs:
            todo += [(lo, (lo + hi) // 2), ((lo + hi) // 2, hi)]
            continue
        e = edge[lo:hi][q]
        m = M[i]
        t = np.clip(((m - A[e]) * D[e]).sum(axis=1) / L2[e], 0.0, 1.0)
        d = np.hypot(*(A[e] + t[:, None] * D[e] - m).T)
        np.minimum.at(near, i, d)
    off = np.bincount(owner, weights=near > ON_OUTLINE, minlength=len(cuts)) > 0
    kept: dict = {}
    for (k_, seg), keep in zip(cuts, off):
        if keep:
            kept.setdefault(k_, []).append(seg)
    out = []
    for k_, st in enumerate(strokes):
        if st.style != "cut":
            out.append(st)
        elif k_ in kept:
            out.append(Stroke(kept[k_], st.style, st.closed, st.source, st.part))
    return out


_STRETCH = 1.0        # mm: the longest piece of an outline edge asked for the points near it
_QUERY = 65_536       # stretches asked at once ...
_CANDIDATES = 1_000_000   # ... and the (point, stretch) candidates measured at once (halved past it)


def _part_of(g, owner: dict) -> str:
    """The part holding geometry ``g``: the nearest structure of ``g``'s owner and its
    ancestors that is a part ("" when none is); a drawing that ``CutInto`` gives to a solid
    is that solid's."""
    s = getattr(g, "owner", None)
    if s is None:
        return ""
    for a in s.held_by():
        if a in owner:
            return owner[a]
    return ""


def _mesh_section(loops: list[Loop]):
    """A CrossSection of exact ``loops`` whose every vertex lies on its curve (for meshes)."""
    import manifold3d as mf
    polys = [lp.points().tolist() for lp in loops]
    polys = [p for p in polys if len(p) >= 3]
    return mf.CrossSection(polys, mf.FillRule.NonZero) if polys else mf.CrossSection()
