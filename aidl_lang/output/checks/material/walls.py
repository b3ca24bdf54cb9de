"""``W0507``: a wall thinner than ``min_wall`` (default :data:`.common.MIN_WALL`, 0.5 mm):
what a morphological opening of the part by a disc of that diameter removes (the erosion by
``min_wall / 2`` then the dilation back, Manifold offsets with round joins), in pieces of at
least ``2 min_wall^2`` (so that sharp corners, which every opening rounds, do not count); the
warning names the holes and the outer edge the wall lies between, and, for a wall of the
outline alone, the shape that makes it (:func:`_maker`; "blunt the tip" when it tapers to a
point there).  Walls between two
features already measured by :mod:`..holes.openings` are not reported twice.  The opening of a
large part is taken tile by tile (:func:`_thin`), and the steps the deadline cannot
interrupt are refused when their vertex counts say they would end past it.

A neck between two members is :mod:`.necks`' (W0507 too); a slit of empty space, the dual,
is :mod:`.slits`' (W0519)."""
from __future__ import annotations

import manifold3d as mf
import numpy as np

from ....base.diagnostics import Diagnostic, DiagnosticSink, Fix, Span
from ....geometry.core.model import Structure
from ...part.build.booleans import Drawing
from ...part.measure.nearby import _median, box_pairs
from ...part.measure.nearby import components as _components
from ...part.build.scanwork import turned, turned_back
from ..common import _area, _loop_boxes, _solids_within, _union, below, written

def _check_walls(d: Drawing, s: Structure, shape, t: float, cuts, sink: DiagnosticSink,
                 quick: bool = True, covered: set = frozenset(), loops=None,
                 tick=lambda ahead=0.0: None) -> None:
    """W0507 for part ``s`` (its final ``shape``, its ``cuts``) at minimum wall ``t`` mm: one
    warning per piece of at least ``2 t^2`` that the opening removes.  ``quick=False`` skips
    the whole-area bound below (the reference for its test); ``covered``: name pairs already
    reported with their measured width (:func:`_report_openings`), whose pieces are skipped;
    ``tick(ahead)`` is called before each step (the compile's deadline; ``ahead``: the
    seconds a step that cannot be interrupted is expected to take, from its vertex count)."""
    if shape.is_empty():
        return
    segs = 16
    pieces = _thin(shape, t, loops, tick=tick, least=2 * t * t)
    # The pieces partition what the opening removes, so none reaches 2 t^2 when the whole does
    # not (the same polygon areas summed in another order: the margin is far above the
    # rounding).  On a part without thin walls the opening removes only corner slivers (the
    # telephone: 391 of them, 0.1 mm^2 in all against 0.5 mm^2), which are then not measured.
    areas = [_area(p) for p in pieces]
    if not pieces or quick and sum(areas) < 2 * t * t * (1 - 1e-9):
        return
    holes = [c for c in cuts if c.hole in d.shapes and not d.shapes[c.hole].is_empty()]
    hb = np.array([d.shapes[c.hole].bounds() for c in holes], dtype=float).reshape(-1, 4)
    filled = None
    for piece, a in _separate(pieces, areas, t):
        tick()
        if filled is None:
            filled = _union([shape] + [d.shapes[c.hole] for c in holes])
        near = piece.offset(t, mf.JoinType.Round, 2.0, segs)
        nx0, ny0, nx1, ny1 = near.bounds()
        close = np.flatnonzero((hb[:, 0] <= nx1) & (hb[:, 2] >= nx0) & (hb[:, 1] <= ny1)
                               & (hb[:, 3] >= ny0))
        names = [f"hole `{holes[k].hole.path}`" for k in close
                 if _area(near ^ d.shapes[holes[k].hole]) > 1e-9]
        if _area(near - filled) > 1e-9:
            names.append(f"the outer edge of `{s.path}`")
        names = list(dict.fromkeys(names))
        if names and (any(set(names) <= c for c in covered)
                      or len(names) >= 2 and frozenset(names[:2]) in covered):
            continue            # said already (the two it would name: a hole beside a notch
                                # meets the outer edge too, run z1's palette said it twice)
        x0, y0, x1, y1 = piece.bounds()
        between = (" between " + " and ".join(names[:2])) if len(names) >= 2 else (
            f" beside {names[0]}" if names else "")
        span = next((c.hole.span for c in holes if f"hole `{c.hole.path}`" in names), s.span)
        maker = None if any(n.startswith("hole ") for n in names) else _maker(d, s, piece)
        width, length, (px, py) = _measure(piece, a, t, loops if loops is not None else
                                           [np.asarray(P, dtype=float)
                                            for P in shape.to_polygons()])
        made, fix = "", f"move or shrink the feature so that at least {t:g} mm of material is left"
        meant = ("; if the request asks for this thin wall, say so: `min_wall 0` in "
                 f"`{s.path}` (not cut by a laser or router) or a smaller `min_wall` at the top")
        edit = None
        if maker is not None:
            g, tip = maker
            what = f"{g.kind} `{g.label}`" if g.name else g.label
            span = g.span or g.owner.span or span
            if tip is not None:
                (vx, vy), angle = tip
                vx, vy = written(s, vx, vy)
                last = t / 2 / np.tan(np.radians(angle) / 2)
                sink.warning(
                    "W0507", f"a wall of `{s.path}` at the tip of {what}{between}: its corner "
                    f"at ({vx:.2f}, {vy:.2f}) is {angle:.1f} degrees, narrower than {t:g} mm "
                    f"over its last {last:.2f} mm (the laser burns the point away)", span,
                    hint=f"blunt the tip of {what} to at least {t:g} mm: end it in a flat or a "
                         f"round {t:g} mm across instead of a point (a corner of "
                         f"{_CLEAN_ANGLE:g} degrees or more passes); if the request asks "
                         f"for this sharp tip, say so: `min_wall 0` in `{s.name}` (no wall "
                         "check for this part)")
                continue
            made = f" made by {what}"
            fix = f"widen {what} (or move it) so that at least {t:g} mm of material is left"
            if g.kind == "Text" and g.data.get("font"):     # a letter's stroke (issue 112)
                from ..letters import letter_at
                made += letter_at(d, g, px, py)
                fix = (f"draw {what} heavier (a bolder style: `font=\"sans:Bold\"`) or "
                       f"larger, so that its strokes are at least {t:g} mm wide")
            stated = np.floor((width - 1e-3) * 100) / 100
            if stated > 0 and (g.span is not None or s.span is not None):
                # the wall is one shape as the program states it: accepting it is one statement
                at = s.span
                edit = Fix(Span(at.file, at.line, at.col, at.line, at.col, at.start, at.start),
                           f"min_wall {stated:g} mm\n{' ' * (at.col - 1)}")
                meant = (f"; if the request asks for a wall this thin, state it: `min_wall "
                         f"{stated:g} mm` before `{s.name}` (the fix)")
        wx, wy = written(s, px, py)
        sink.add(Diagnostic(
            "W0507", f"a wall of `{s.path}`{made}{between} is {below(width, t)} mm wide, thinner "
            f"than {t:g} mm (over {length:.1f} mm, near ({wx:.1f}, {wy:.1f}))", span, "warning",
            hint=f"{fix} (a laser or router cannot hold a thinner wall){meant}; the minimum is "
                 "set by `min_wall` or --min-wall", fix=edit))


# the angle (degrees) above which a corner's sliver stays under W0507's 2 t^2 at any minimum:
# the opening by a disc of radius r removes r^2 (cot(a/2) - (pi - a)/2) at a corner of angle
# a, which reaches 8 r^2 = 2 t^2 at about 11 degrees
_CLEAN_ANGLE = 12


def _separate(pieces: list, areas: list, t: float):
    """``(piece, area)`` of every piece of at least ``2 t^2``, each split where it hangs
    together only by hairlines (the opening leaves seams of ~1e-9 mm along straight edges that
    join the slivers of a triangle's three corners into one "piece" over its whole base): a
    sliver of ``1e-4 t`` is shaved off and the rest decomposed, and only parts that still
    weigh ``2 t^2`` are measured (a requested 18-degree corner is then no wall)."""
    least = 2 * t * t
    eps = 1e-4 * t
    for piece, a in zip(pieces, areas):
        if a < least or not a > 0.0:      # no area is no wall (2 t^2 underflows to 0 below
            continue                      # t = 1e-162 mm: min_wall 1e-300 mm)
        shaved = piece.offset(-eps, mf.JoinType.Miter, 2.0, 16).offset(eps, mf.JoinType.Miter,
                                                                       2.0, 16)
        parts = shaved.decompose()
        if len(parts) <= 1:
            yield piece, a
            continue
        for p in parts:
            pa = _area(p)
            if pa >= least and pa > 0.0:
                yield p, pa


def _measure(piece, a: float, t: float, loops: list):
    """What a thin ``piece`` (area ``a``) of the part whose outline is ``loops`` measures:
    ``(width, length, place)`` in mm.  The width is the least distance across the material
    between two stretches of the outline that face each other (a vertex and a segment whose
    directions differ by more than 120 degrees: the two sides of a wall, not two neighbours of
    one curve), over the vertices in the piece's box (:func:`.nearby.close_pairs`); the length
    is the piece's area over that width (its centre line), the place the middle of the
    thinnest pair.  With no facing pair (a wall that bends away), the piece's area over its
    longest side, never above ``t``, at the vertex of the piece nearest its box's centre."""
    from ...part.measure.nearby import close_pairs
    x0, y0, x1, y1 = piece.bounds()
    pad = 1e-3 + 1e-6 * max(abs(x0), abs(y0), abs(x1), abs(y1))
    near_loops = [P for P in loops if len(P) >= 2
                  and not (P[:, 0].min() > x1 + t or P[:, 0].max() < x0 - t
                           or P[:, 1].min() > y1 + t or P[:, 1].max() < y0 - t)]
    best = None
    if near_loops:
        V, nxt, prv = _ring(near_loops)
        B = V[nxt]
        near = (np.minimum(V, B) <= (x1 + t, y1 + t)).all(axis=1) & \
            (np.maximum(V, B) >= (x0 - t, y0 - t)).all(axis=1)
        inside = ((V >= (x0 - pad, y0 - pad)) & (V <= (x1 + pad, y1 + pad))).all(axis=1)
        segs, verts = np.flatnonzero(near), np.flatnonzero(inside)
        if len(segs) and len(verts):
            v, sg, dist, foot = close_pairs(V[verts], verts, V[segs], B[segs], segs, t)
            v, sg = verts[v], segs[sg]
            ok = (v != nxt[sg]) & (dist > 1e-9) & _facing(V, nxt, prv, v, sg, 0.5)
            if ok.any():
                k = np.flatnonzero(ok)[int(np.argmin(dist[ok]))]
                best = (float(dist[k]), (V[v[k]] + foot[k]) / 2)
    if best is not None:
        width, mid = best
        return width, max(a / max(width, 1e-9), width), (float(mid[0]), float(mid[1]))
    length = max(x1 - x0, y1 - y0, 1e-9)
    return min(t, a / length), length, _point_of(piece, ((x0 + x1) / 2, (y0 + y1) / 2))


def _ring(loops: list) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The vertices of ``loops`` (each k x 2, mm) in one array, and for each the index of the
    next and of the previous vertex of its own loop (vertex ``i``'s edge runs to
    ``V[nxt[i]]``)."""
    V = np.concatenate(loops)
    sizes = np.array([len(P) for P in loops])
    start = np.repeat(np.cumsum(sizes) - sizes, sizes)
    size = np.repeat(sizes, sizes)
    idx = np.arange(len(V))
    return V, start + (idx - start + 1) % size, start + (idx - start - 1) % size


def _facing(V, nxt, prv, v, sg, cos_max: float) -> np.ndarray:
    """Which pairs of vertex ``v[k]`` and edge ``sg[k]`` (from ``V[sg]`` to ``V[nxt[sg]]``) of
    :func:`_ring`'s loops face each other across the material or a gap: the edge runs against
    either edge at the vertex, the cosine of their angle below ``-cos_max`` (the two sides of
    a wall or a slit, not two neighbours of one curve)."""
    seg = V[nxt[sg]] - V[sg]
    facing = np.zeros(len(v), dtype=bool)
    for tan in (V[nxt[v]] - V[v], V[v] - V[prv[v]]):
        with np.errstate(divide="ignore", invalid="ignore"):
            cos = np.einsum("ij,ij->i", tan, seg) / np.maximum(
                np.hypot(*tan.T) * np.hypot(*seg.T), 1e-300)
        facing |= cos < -cos_max
    return facing


SHARP = 60.0      # degrees: a corner of a face sharper than this, in a thin piece, is a tip


def _maker(d: Drawing, s: Structure, piece):
    """The shape of solid ``s`` (its own or a solid descendant's, :attr:`Drawing.own`) that
    makes the thin ``piece``: the face covering most of it, as ``(geometry, tip)``; ``tip`` is
    ``((x, y), angle)`` (mm, degrees) of the sharpest corner of that face sharper than
    :data:`SHARP` degrees that lies in the piece (an outline that tapers to a point), else
    None.  None when no face covers any of it."""
    best, most = None, 1e-9
    x0, y0, x1, y1 = piece.bounds()
    for t, faces in _solids_within(d, s):
        for g, f in faces:
            a, b, c, e = f.bounds()
            if a > x1 or c < x0 or b > y1 or e < y0:
                continue
            got = _area(piece ^ f)
            if got > most:
                best, most = (g, f), got
    if best is None:
        return None
    g, f = best
    near = piece.offset(1e-3, mf.JoinType.Miter, 2.0, 16)
    sharpest = None
    for P in f.to_polygons():
        P = np.asarray(P, dtype=float)
        u, w = np.roll(P, 1, axis=0) - P, np.roll(P, -1, axis=0) - P
        cos = np.einsum("ij,ij->i", u, w) / np.maximum(
            np.hypot(*u.T) * np.hypot(*w.T), 1e-300)
        convex = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0] < 0       # counter-clockwise loops
        for k in np.flatnonzero(convex & (cos > np.cos(np.radians(SHARP)))):
            q = mf.CrossSection.square((2e-3, 2e-3)).translate((P[k, 0] - 1e-3, P[k, 1] - 1e-3))
            if _area(near ^ q) > 0:
                angle = float(np.degrees(np.arccos(np.clip(cos[k], -1.0, 1.0))))
                if sharpest is None or angle < sharpest[1]:
                    sharpest = ((float(P[k, 0]), float(P[k, 1])), angle)
    return g, sharpest


def _point_of(piece, near) -> tuple[float, float]:
    """The vertex of ``piece`` (what the opening removed: a thin wall) nearest to ``near``
    (its box's centre): a point on the wall itself, where the box's centre of a curved or
    L-shaped wall lies off it."""
    P = np.concatenate([np.asarray(p, dtype=float) for p in piece.to_polygons()])
    k = int(np.argmin(np.hypot(P[:, 0] - near[0], P[:, 1] - near[1])))
    return float(P[k, 0]), float(P[k, 1])


UNION_GROUP = 16       # tile pieces united in one uninterruptible call by _join
TILE_VERTS = 2000      # W0507's opening is taken tile by tile above this many vertices ...
WHOLE_LOOPS = 2        # ... and loops: an outline and one hole (a gear and its bore) are opened
WHOLE_VERTS = 10_000   # whole up to this many vertices, since clipping a loop into tiles costs
                       # more than opening it (not beyond: what the opening removes is split
                       # into its pieces at once, and Manifold's decompose crashes on 70,000)
# the least time per vertex of the steps the deadline cannot interrupt (measured on the 2-core
# machine: the opening ~60 us, decomposing what it removes ~24 us, uniting the tiles' parts
# ~18 us per vertex; half of that, so that only steps sure to overrun are refused before they
# start)
THIN_SECONDS_PER_VERTEX = 30e-6
DECOMPOSE_SECONDS_PER_VERTEX = 12e-6
UNION_SECONDS_PER_VERTEX = 9e-6     # seed 791: the tiles' last union, 515,225 vertices, 9.3 s


def _open(shape, t: float):
    segs = 16
    return shape.offset(-t / 2, mf.JoinType.Round, 2.0, segs).offset(t / 2, mf.JoinType.Round,
                                                                     2.0, segs)


TURN_ASPECT = 4.0      # a shape this many times wider than tall is opened turned (_removed)


def _removed(shape, t: float):
    """What the opening of ``shape`` by a disc of diameter ``t`` removes (``shape`` minus
    :func:`_open`), a CrossSection.  Clipper2's offset scans along y, its work about the
    edges that each scan line crosses, so a shape more than :data:`TURN_ASPECT` times wider
    than tall (a tile of a long row of holes) is opened turned a quarter turn and turned back
    (exact, :mod:`..part.scanwork`): a tile of 600 vertices of 5,000 circles in a row opens in
    1 ms instead of 3 ms, the whole row of 160,000 vertices in 0.18 s instead of 15 s."""
    x0, y0, x1, y1 = shape.bounds()
    if x1 - x0 > TURN_ASPECT * (y1 - y0):
        s = turned([shape])[0]
        return turned_back(s - _open(s, t))
    return shape - _open(shape, t)


def _thin(shape, t: float, loops=None, tile: int = TILE_VERTS, tick=lambda ahead=0.0: None,
          least: float = 0.0, whole_loops: int = WHOLE_LOOPS) -> list:
    """The connected pieces of what the opening of ``shape`` by a disc of diameter ``t``
    removes (a list of CrossSections; pieces of area below ``least`` mm^2 may come in bits).

    Clipper2's offset runs a sweep whose cost grows faster than the vertex count (on a grid of
    holes about as n^1.5: 12 ms at 100 holes, 256 ms at 900), so a shape of more than ``tile``
    vertices is cut into tiles: whether a point survives the opening depends only on the shape
    within ``t`` of it, so each tile is opened with a margin of ``2 t`` around it (the shape
    clipped to the grown tile) and what the opening removes inside the tile itself is kept.
    The tiles come from halving the box along its longer side while the clipped shape has more
    than ``tile`` vertices (each half clipped from its parent's piece): O(n log n) whatever the
    shape.  A grid of tiles over the bounding box cost tiles x vertices for one long loop (a
    diagonal chain of 10 000 circles: 81 tiles, each clipping the whole 150 000-vertex loop,
    20 s).  A shape of at most ``whole_loops`` loops and :data:`WHOLE_VERTS` vertices is
    opened whole: each tile clips the loops that cross it, and for one long loop that costs
    more than the opening itself (one wavy loop of 2,520 vertices: 11.6 ms in tiles, 7.0 ms
    whole; of 42,000: 883 and 193 ms; a diagonal chain of 1,000 circles, one loop of 16,000
    vertices: 591 and 149 ms), up to a size where what the opening removes could come in
    more pieces than Manifold's ``decompose`` survives (the chain of 10,000 circles, one loop
    of 160,000 vertices: 3.5 s in tiles; whole, the opening takes 1.0 s and decomposing its
    140,000 slivers crashes the process, as 70,000 do; 35,000 do not).

    When all of it weighs less than ``least``, the tiles' parts are returned as they are;
    else each is split into its pieces, and only the pieces that meet across a tile's edge
    (their boxes touch) and weigh at least ``least`` together are united (:func:`_join`).
    Uniting every tile's part into one shape first cost one uninterruptible Manifold call over
    all of them (fuzz seeds 791 and 1542: 5,000 circles, 515,225 vertices of corner slivers,
    9-25 s).  ``loops`` is accepted for the callers' convenience (unused); ``tick(ahead)`` is
    called before each tile and each union (the compile's deadline).

    The tiles are cut from the shape's loops (:func:`_clip_loops`: only the loops that cross a
    tile's edge are clipped), and a loop that lies alone (:func:`_isolated_loops`) is opened
    by itself, once per shape of loop (:func:`_thin_of_loop`): a plate of 5,000 equal round
    holes 2 mm apart opens one hole, its outline's edge and the holes beside it
    (``check_drawing`` 3.65 s -> 0.82 s)."""
    n = shape.num_vert()
    if n <= tile or n <= WHOLE_VERTS and shape.num_contour() <= whole_loops:
        tick(n * THIN_SECONDS_PER_VERTEX)         # one opening of the whole: uninterruptible
        thin = _removed(shape, t)
        if _area(thin) < least:
            return [thin]
        tick(thin.num_vert() * DECOMPOSE_SECONDS_PER_VERTEX)
        return thin.decompose()
    m = 2 * t
    out: list = []           # what the opening removes in each tile

    def box(a, b, c, e):
        return mf.CrossSection.square((c - a, e - b)).translate((a, b))

    def split(loops, boxes, a, b, c, e):
        tick()
        if not loops:
            return
        small = max(c - a, e - b) <= 8 * t          # halving no longer sheds the margin
        if sum(len(p) for p in loops) <= tile or small:
            piece = mf.CrossSection(loops, mf.FillRule.Positive)
            part = _removed(piece, t) ^ box(a, b, c, e)
            if not part.is_empty():
                out.append(part)
            return
        if c - a >= e - b:
            mid = (a + c) / 2
            halves = [(a, b, mid, e), (mid, b, c, e)]
        else:
            mid = (b + e) / 2
            halves = [(a, b, c, mid), (a, mid, c, e)]
        for h in halves:
            split(*_clip_loops(loops, boxes, h[0] - m, h[1] - m, h[2] + m, h[3] + m), *h)

    loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    boxes = _loop_boxes(loops)
    alone = _isolated_loops(loops, boxes, t)
    for part in _thin_of_alone(loops, np.flatnonzero(alone), t, tick, least):
        out.append(part)
    rest = [loops[k] for k in np.flatnonzero(~alone)]
    x0, y0, x1, y1 = shape.bounds()
    split(rest, boxes[~alone], x0, y0, max(x1, x0 + 1e-9), max(y1, y0 + 1e-9))
    if sum(_area(p) for p in out) < least:        # corner slivers only: nothing to measure
        return out
    pieces = []
    for k, part in enumerate(out):
        tick(part.num_vert() * DECOMPOSE_SECONDS_PER_VERTEX)
        pieces.extend((k, p) for p in part.decompose())
    return _join(pieces, least, tick)


def _isolated_loops(loops: list, boxes: np.ndarray, t: float) -> np.ndarray:
    """Which ``loops`` (with their ``boxes``) lie farther than ``1.5 t`` from every other loop
    and enclose none (a boolean array; a sufficient test, by boxes: a loop said not isolated
    may still be).  What the opening by a disc of diameter ``t`` removes lies within ``t / 2``
    of the boundary, and whether a point there is removed depends on the shape within ``t``
    of it, so near an isolated loop it depends on that loop alone (:func:`_thin_of_loop`),
    and the other loops' part is the same without it.  Large loops (a plate's outline) are
    tested by their edges' boxes, so that the holes inside them are not all near them."""
    n = len(loops)
    if n < 2:
        return np.zeros(n, dtype=bool)
    diag = np.hypot(boxes[:, 2] - boxes[:, 0], boxes[:, 3] - boxes[:, 1])
    big = diag > max(4 * _median(diag), 8 * t)
    owner = [np.flatnonzero(~big)]
    items = [boxes[~big]]
    for k in np.flatnonzero(big):            # a large loop: one box per edge
        P = loops[k]
        Q = np.roll(P, -1, axis=0)
        items.append(np.hstack([np.minimum(P, Q), np.maximum(P, Q)]))
        owner.append(np.full(len(P), k))
    owner = np.concatenate(owner)
    pairs = box_pairs(np.concatenate(items), pad=0.75 * t * (1 + 1e-6) + 1e-9)
    near = owner[pairs]
    near = near[near[:, 0] != near[:, 1]]
    alone = ~big
    alone[near.ravel()] = False
    return alone


def _thin_of_alone(loops: list, ks, t: float, tick=lambda ahead=0.0: None,
                   least: float = 0.0) -> list:
    """:func:`_thin_of_loop` of each of ``loops[k]`` for ``k`` in ``ks`` (ascending; loops
    :func:`_isolated_loops` found alone), the parts that are not None, in that order: the
    loops of one vertex count keyed at once (their vertices less their box's corner, to 1e-9
    mm, in one array), each shape opened once (by its first loop), and a shape whose opening
    removes nothing costs its loops nothing more (19,000 round holes: 0.3 s keyed one by
    one).  Nor does one that removes less than ``least`` mm^2 (a round hole's Clipper
    slivers, 2.5e-8 mm^2, each moved to its 19,000 holes): what the opening removes near a
    lone loop lies within ``t / 2`` of it, more than ``t / 2`` from any other loop's, so it
    joins no other piece and weighs what it weighs alone, below what is measured."""
    by_count: dict = {}
    for k in ks:
        by_count.setdefault(len(loops[k]), []).append(int(k))
    found: dict = {}               # k -> its part (None: nothing removed)
    cache: dict = {}
    for n, group in by_count.items():
        S = np.stack([loops[k] for k in group])             # (m, n, 2)
        lo = S.min(axis=1)
        rel = np.ascontiguousarray(np.round(S - lo[:, None, :], 9).reshape(len(group), -1))
        keys = rel.view(np.dtype((np.void, rel.dtype.itemsize * rel.shape[1]))).ravel()
        _, first, inv, counts = np.unique(keys, return_index=True, return_inverse=True,
                                          return_counts=True)
        order = np.argsort(inv.ravel(), kind="stable")      # each shape's loops, ascending
        ends = np.cumsum(counts)
        for u, f in enumerate(first):
            tick()
            thin = _thin_of_loop(loops[group[f]], t, cache)
            members = order[ends[u] - counts[u]:ends[u]]
            if thin is None or least > 0 and _area(thin) < least:
                found.update(dict.fromkeys((group[m] for m in members), None))
                continue
            for m in members:
                if m != f:
                    tick()
                found[group[m]] = thin if m == f else thin.translate(
                    (float(lo[m, 0] - lo[f, 0]), float(lo[m, 1] - lo[f, 1])))
    return [found[int(k)] for k in ks if found[int(k)] is not None]


def _thin_of_loop(loop: np.ndarray, t: float, cache: dict):
    """What the opening by a disc of diameter ``t`` removes near ``loop`` (an (n, 2) array,
    counter-clockwise for an outline, clockwise for a hole) when no other loop lies within
    ``1.5 t`` of it (:func:`_isolated_loops`), a CrossSection, or None when it is empty: from
    the loop alone (a hole in a square of material ``2 t`` wider than its box).  Computed once
    per shape: ``cache`` holds what is removed near each loop seen, by its vertices relative
    to its box's corner (to 1e-9 mm), so a grid of 5,000 equal holes is opened once; the
    others take its result moved (Clipper rounds to its grid where the loop lies: the slivers
    of a moved circle differ by ~1e-8 mm^2)."""
    lo = loop.min(axis=0)
    key = (len(loop), np.round(loop - lo, 9).tobytes())
    seen = cache.get(key)
    if seen is None:              # opened where it lies (Clipper rounds to its own grid)
        (x0, y0), (x1, y1) = lo, loop.max(axis=0)
        own = mf.CrossSection([loop], mf.FillRule.Positive)
        if own.is_empty():                    # clockwise: a hole in the material around it
            own = (mf.CrossSection.square((x1 - x0 + 4 * t, y1 - y0 + 4 * t))
                   .translate((x0 - 2 * t, y0 - 2 * t))
                   - mf.CrossSection([loop[::-1]], mf.FillRule.Positive))
        near = (mf.CrossSection.square((x1 - x0 + 2 * t, y1 - y0 + 2 * t))
                .translate((x0 - t, y0 - t)))
        seen = cache[key] = ((own - _open(own, t)) ^ near, lo)
    thin, at = seen
    if thin.is_empty():
        return None
    return thin if at is lo else thin.translate((float(lo[0] - at[0]), float(lo[1] - at[1])))


def _clip_loops(loops: list, boxes: np.ndarray, a: float, b: float, c: float, e: float):
    """The loops of a shape (outer loops counter-clockwise, holes clockwise, as
    ``CrossSection.to_polygons`` gives them, with their ``boxes``) clipped to the box
    ``a <= x <= c, b <= y <= e``: (loops, boxes) with the same winding number at every point
    inside the box.  A loop whose box lies inside the box is kept whole and one whose box
    misses it is dropped; only the loops whose boxes cross its edge are clipped, in arrays
    (:func:`_clip_ring`), in work proportional to their vertices and without a boolean.  On a
    plate of 5,000 round holes this clips a few hundred vertices per tile where clipping the
    whole shape cost its 225,000 vertices at each of the halving's 7 levels; on one long
    opening (5,000 overlapping holes in a row, 90,000 vertices in one loop) the halving's 126
    clips took 2 s as Clipper booleans (CPU, in-process), 0.2 s in arrays."""
    inside = (boxes[:, 0] > a) & (boxes[:, 1] > b) & (boxes[:, 2] < c) & (boxes[:, 3] < e)
    meets = (boxes[:, 0] <= c) & (boxes[:, 2] >= a) & (boxes[:, 1] <= e) & (boxes[:, 3] >= b)
    keep = [loops[k] for k in np.flatnonzero(inside)]
    cross = np.flatnonzero(meets & ~inside)
    if len(cross) == 0:
        return keep, boxes[inside]
    cut_loops = _clip_ring([loops[k] for k in cross], a, b, c, e)
    return keep + cut_loops, np.concatenate([boxes[inside], _loop_boxes(cut_loops)])


def _clip_ring(loops: list, a: float, b: float, c: float, e: float) -> list:
    """``loops`` ((n, 2) arrays, mm) projected onto the box ``a <= x <= c, b <= y <= e``:
    each edge is cut where it crosses one of the box's four lines, then every vertex is moved
    to its nearest point of the box (a clamp).  Each piece of an edge then lies in one of the
    nine regions the lines make, where the projection is affine, so the clamped vertices
    trace the projection of the loop exactly; moving every point of the loop straight to its
    projection never crosses a point inside the box, so the winding number of every point
    inside is the loop's, and of every point outside 0.  The stretches that end up on the
    box's edges (what lay outside) are then shortened: repeated vertices and the middle ones
    of three on one edge line are dropped (a back-and-forth along the box's edge encloses
    nothing); loops left with no area are dropped.  A list of (m, 2) arrays; the loops that
    remain may run along the box's edges and touch themselves there, which a
    ``CrossSection`` built from them with ``FillRule.Positive`` resolves."""
    V = np.concatenate(loops)
    owner = np.repeat(np.arange(len(loops)), [len(P) for P in loops])
    # a vertex outside the box between two of the same region outside it (beyond one edge
    # line, or one corner: a convex region) is dropped before anything else: the chord
    # between its neighbours stays in that region and projects onto the same edge line (or
    # corner), so a long stretch outside costs two passes and no Python below
    V, owner = _outside_dropped(V, owner, a, b, c, e)
    if not len(V):
        return []
    nxt = _neighbours(owner)[1]
    D = V[nxt] - V
    T = np.full((len(V), 4), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for j, (axis, at) in enumerate(((0, a), (0, c), (1, b), (1, e))):
            u = (at - V[:, axis]) / D[:, axis]
            T[:, j] = np.where((u > 0) & (u < 1), u, np.inf)
    T.sort(axis=1)
    count = 1 + np.isfinite(T).sum(axis=1)              # the vertex, then its crossings
    edge = np.repeat(np.arange(len(V)), count)
    k = np.arange(len(edge)) - np.repeat(np.cumsum(count) - count, count)
    u = np.where(k == 0, 0.0, T[edge, np.maximum(k - 1, 0)])
    P, owner = _outside_dropped(V[edge] + u[:, None] * D[edge], owner[edge], a, b, c, e)
    P[:, 0] = np.clip(P[:, 0], a, c)
    P[:, 1] = np.clip(P[:, 1], b, e)
    out = []
    for start, stop in zip(*_runs(owner)):
        Q = _shorten(P[start:stop], a, b, c, e)
        if len(Q) >= 3 and (_within(Q, a, b, c, e) or abs(_shoelace(Q)) > 0.0):
            out.append(Q)
    return out


def _neighbours(owner: np.ndarray):
    """For each entry of ``owner`` (loop numbers, each loop's entries together) the indices
    of the entries before and after it in its own loop (closed: the last's next is the
    first): ``(before, after)``."""
    starts, stops = _runs(owner)
    size = np.repeat(stops - starts, stops - starts)
    first = np.repeat(starts, stops - starts)
    idx = np.arange(len(owner)) - first
    return first + (idx - 1) % size, first + (idx + 1) % size


def _outside_dropped(P: np.ndarray, owner: np.ndarray, a: float, b: float, c: float,
                     e: float):
    """``(P, owner)`` without the vertices that lie outside the box in the same one of the
    eight regions around it as both their neighbours in their loop (``owner``)."""
    if not len(P):
        return P, owner
    region = (np.where(P[:, 0] < a, 0, np.where(P[:, 0] > c, 2, 1)) * 3
              + np.where(P[:, 1] < b, 0, np.where(P[:, 1] > e, 2, 1)))
    before, after = _neighbours(owner)
    keep = (region == 4) | (region != region[after]) | (region != region[before])
    return P[keep], owner[keep]


def _runs(owner: np.ndarray):
    """The (starts, stops) of the runs of equal values in ``owner`` (sorted)."""
    cut = np.flatnonzero(np.diff(owner)) + 1
    return np.concatenate([[0], cut]), np.concatenate([cut, [len(owner)]])


def _shorten(Q: np.ndarray, a: float, b: float, c: float, e: float) -> np.ndarray:
    """The closed loop ``Q`` (clamped to the box) without repeated vertices and without the
    middle vertex of three consecutive ones on one edge line of the box (until none is
    left); the winding number of every point inside the box is kept."""
    while len(Q) >= 3:
        n = len(Q)
        # only vertices on the box's edges can repeat or lie between two on one edge line
        # (the loop's own vertices inside are Clipper's: distinct)
        k = np.flatnonzero((Q[:, 0] == a) | (Q[:, 0] == c) | (Q[:, 1] == b) | (Q[:, 1] == e))
        if not len(k):
            break
        keep = np.ones(n, dtype=bool)
        keep[k[np.all(Q[k] == Q[k - 1], axis=1)]] = False       # repeated: the first stays
        if not keep.all():
            Q = Q[keep]
            continue
        P, prv, nx = Q[k], Q[k - 1], Q[(k + 1) % n]
        mid = np.zeros(len(k), dtype=bool)
        for axis, at in ((0, a), (0, c), (1, b), (1, e)):
            mid |= (P[:, axis] == at) & (prv[:, axis] == at) & (nx[:, axis] == at)
        if not mid.any():
            break
        if mid.all() and len(k) == n:          # all on one edge line: no area
            return Q[:0]
        keep[k[mid]] = False
        Q = Q[keep]
    return Q


def _within(Q: np.ndarray, a: float, b: float, c: float, e: float) -> bool:
    """Whether a vertex of ``Q`` lies strictly inside the box: a clipped loop of a simple
    loop that passes inside the box encloses some of it (the winding numbers on its two
    sides there differ), so it has an area without summing one."""
    return bool(((Q[:, 0] > a) & (Q[:, 0] < c) & (Q[:, 1] > b) & (Q[:, 1] < e)).any())


def _shoelace(Q: np.ndarray) -> float:
    """Twice the signed area of the closed loop ``Q``."""
    x, y = Q[:, 0], Q[:, 1]
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def _join(pieces: list, least: float, tick) -> list:
    """The connected pieces made of ``pieces`` ((tile number, CrossSection) pairs; pieces of
    one tile are disjoint, pieces of different tiles meet at most along the tiles' edges):
    pieces of different tiles whose boxes touch are grouped (connected components of the
    touching pairs), and a group of at least ``least`` mm^2 is united :data:`UNION_GROUP`
    parts at a time, the deadline's ``tick(ahead)`` before each union, then split again
    (touching boxes do not make the shapes touch)."""
    if not pieces:
        return []
    tiles = np.array([k for k, _ in pieces])
    shapes = [p for _, p in pieces]
    boxes = np.array([p.bounds() for p in shapes], dtype=float).reshape(-1, 4)
    span = float(np.max(np.abs(boxes))) if len(boxes) else 1.0
    pairs = box_pairs(boxes, pad=1e-9 * max(span, 1.0))
    pairs = pairs[tiles[pairs[:, 0]] != tiles[pairs[:, 1]]]
    label = _components(len(shapes), [pairs[:, 0]], [pairs[:, 1]])   # no SciPy import
    groups: dict = {}
    for i, g in enumerate(label):
        groups.setdefault(g, []).append(shapes[i])
    result = []
    for group in groups.values():
        if len(group) == 1 or sum(_area(p) for p in group) < least:
            result.extend(group)
            continue
        while len(group) > 1:
            nxt = []
            for i in range(0, len(group), UNION_GROUP):
                part = group[i:i + UNION_GROUP]
                tick(sum(p.num_vert() for p in part) * UNION_SECONDS_PER_VERTEX)
                nxt.append(_union(part))
            group = nxt
        result.extend(group[0].decompose())
    return result


