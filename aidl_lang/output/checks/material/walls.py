"""``W0507``: a wall thinner than ``min_wall`` (default :data:`.common.MIN_WALL`, 0.5 mm):
what a morphological opening of the part by a disc of that diameter removes (the erosion by
``min_wall / 2`` then the dilation back, Manifold offsets with round joins), in pieces of at
least ``2 min_wall^2`` (so that sharp corners, which every opening rounds, do not count); the
warning names the holes and the outer edge the wall lies between, and, for a wall of the
outline alone, the shape that makes it (:func:`_maker`; "blunt the tip" when it tapers to a
point there).  Walls between two
features already measured by :mod:`.openings` are not reported twice.  The opening of a
large part is taken tile by tile (:func:`_thin`), and the steps the deadline cannot
interrupt are refused when their vertex counts say they would end past it.

``W0519``, the dual for empty space: a slit narrower than ``min_wall`` between two shapes of
one outline, by a gap search between its edges (:func:`_check_slits`)."""
from __future__ import annotations

import manifold3d as mf
import numpy as np

from ....base.diagnostics import Diagnostic, DiagnosticSink, Fix, Label, Span
from ....geometry.core.model import Structure
from ...part.build.booleans import Drawing
from ...part.measure.nearby import _median, box_pairs
from ...part.measure.nearby import components as _components
from ...part.build.scanwork import turned, turned_back
from ..common import _area, _cut_openings, _loop_boxes, _solids_within, _union
from .nicks import slit_fix

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
        if names and any(set(names) <= c for c in covered):
            continue
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
            stated = np.floor((width - 1e-3) * 100) / 100
            if stated > 0 and (g.span is not None or s.span is not None):
                # the wall is one shape as the program states it: accepting it is one statement
                at = s.span
                edit = Fix(Span(at.file, at.line, at.col, at.line, at.col, at.start, at.start),
                           f"min_wall {stated:g} mm\n{' ' * (at.col - 1)}")
                meant = (f"; if the request asks for a wall this thin, state it: `min_wall "
                         f"{stated:g} mm` before `{s.name}` (the fix)")
        sink.add(Diagnostic(
            "W0507", f"a wall of `{s.path}`{made}{between} is {width:.2f} mm wide, thinner "
            f"than {t:g} mm (over {length:.1f} mm, near ({px:.1f}, {py:.1f}))", span, "warning",
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
    cache: dict = {}
    for k in np.flatnonzero(alone):
        tick()
        part = _thin_of_loop(loops[k], t, cache)
        if part is not None:
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


# --------------------------------------------------------------------------- slits (W0519)
FACING = 0.866     # cos 30 deg: two stretches of the outline face each other across a slit
                   # when their directions are opposite within 30 degrees (a V-notch sharper
                   # than 30 degrees; a square inner corner's sides are at 90 and do not count)


def _lone_circles(loops: list, t: float) -> np.ndarray:
    """Which of ``loops`` (each k x 2, mm) hold no pair of W0519's search at width ``t`` (mm),
    so that the search may leave them out: a round hole's or disc's chords (a convex loop
    whose vertices lie on one circle about their mean, within 1e-6 of its radius) farther
    than ``t`` from every other loop and too wide to face itself within ``t``.

    A vertex of such a loop faces one of its own edges only across the loop: the edge's
    normal is turned at least 180 - 30 - ``h`` degrees from the vertex's radius (30: the
    facing angle, :data:`FACING`; ``h``: half the widest edge's angle at the centre), so the
    vertex lies at least ``r_in + r_min * cos(30 deg + h)`` from it (``r_in``: the least
    distance from the centre to an edge's line; ``r_min``: the least radius).  Another loop
    is within ``t`` of it only when the centre is within ``r + t`` of one of that loop's
    edges (the circles' boxes grown by ``t / 2``, :func:`.nearby.box_pairs`, and
    :func:`.nearby.close_pairs` against the other loops' edges, each O(n log n)).  A
    perforated sheet's 50,000 holes: none searched, 2.2 million vertices fewer.  Inputs
    the search takes quickly anyway (up to :data:`.nearby.SMALL_VERTS` vertices) and
    crowds of circles (more than 8 close pairs a circle) are left as they are."""
    from ...part.measure.nearby import SMALL_VERTS, TooManyPairs, close_pairs
    n = len(loops)
    drop = np.zeros(n, dtype=bool)
    sizes = np.array([len(P) for P in loops], dtype=np.int64)
    if not n or int(sizes.sum()) <= SMALL_VERTS:
        return drop
    V, nxt, _ = _ring(loops)
    starts = np.cumsum(sizes) - sizes
    of = np.repeat(np.arange(n), sizes)
    M = np.add.reduceat(V, starts) / sizes[:, None]
    D = V - M.take(of, axis=0)
    R = np.hypot(D[:, 0], D[:, 1])
    rmax, rmin = np.maximum.reduceat(R, starts), np.minimum.reduceat(R, starts)
    E = V.take(nxt, axis=0) - V                 # each vertex's edge, and the next edge
    En = E.take(nxt, axis=0)
    L = np.hypot(E[:, 0], E[:, 1])
    rin = np.minimum.reduceat(np.abs(E[:, 0] * D[:, 1] - E[:, 1] * D[:, 0])
                              / np.maximum(L, 1e-300), starts)
    turn = E[:, 0] * En[:, 1] - E[:, 1] * En[:, 0]
    convex = (np.minimum.reduceat(turn, starts) > 0) | (np.maximum.reduceat(turn, starts) < 0)
    h = np.arcsin(np.minimum(1.0, np.maximum.reduceat(L, starts) / np.maximum(2 * rmax, 1e-300)))
    own = rin + rmin * np.cos(np.arccos(FACING) + h)
    cand = (sizes >= 8) & convex & (rmax - rmin <= 1e-6 * np.maximum(rmax, 1.0)) & (own > t)
    idx = np.flatnonzero(cand)
    if not len(idx):
        return drop
    idx = idx[rmax[idx] <= 4 * _median(rmax[idx])]     # a few large ones: searched as before
    C, r = M[idx], rmax[idx]
    pairs = box_pairs(np.column_stack([C - r[:, None], C + r[:, None]]), t / 2)
    if len(pairs) > 8 * len(idx):
        return drop
    near = np.zeros(len(idx), dtype=bool)
    gap = np.hypot(*(C[pairs[:, 0]] - C[pairs[:, 1]]).T) - r[pairs[:, 0]] - r[pairs[:, 1]]
    near[pairs[gap <= t].ravel()] = True
    other = np.ones(n, dtype=bool)
    other[idx] = False
    seg = np.flatnonzero(other[of])
    if len(seg):
        try:
            v, _, dist, _ = close_pairs(C, n + np.arange(len(idx)), V.take(seg, axis=0),
                                        V.take(nxt[seg], axis=0), of[seg], float(r.max()) + t)
        except TooManyPairs:
            return drop
        near[v[dist <= r[v] + t]] = True
    drop[idx[~near]] = True
    return drop


def _check_slits(d: Drawing, s: Structure, loops, cuts, t: float, sink: DiagnosticSink,
                 tick=lambda ahead=0.0: None, cut_open=None) -> None:
    """W0519 for part ``s`` (its final shape's ``loops``, counter-clockwise outside,
    clockwise around openings) at minimum width ``t`` mm: a slit of EMPTY space narrower than
    ``t`` that reaches into the part, the dual of W0507's thin wall (two lobes of one outline
    that almost meet: a dog-bone tag whose end circles nearly touch beyond the bar).

    Found as a gap search between the non-adjacent edges of one loop
    (:func:`.nearby.close_pairs_facing`, every vertex against the segments within ``t``
    that run against one of its tangents, O(n log n)):
    a pair counts when the two stretches face each other (the vertex's tangent and the
    segment's direction are opposite within 30 degrees, :data:`FACING`) and the middle of the
    gap lies outside the material.  The loops of holes' openings are left out (a hole drawn
    narrow is declared so).  Close pairs are grouped by place; a group whose span along the
    slit is at least ``t`` and whose sides are edges of two different shapes (a cusp drawn in
    one Bezier, a V-notch of one polygon, is meant) is reported: its least width, its
    length, its place and the two shapes (:func:`_faces_at`, at the slit's mouth).
    ``cut_open``: :func:`.common._cut_openings` of ``loops``, when the caller has it."""
    from ...part.measure.nearby import close_pairs_facing
    from ..common import SHOWN, _edges, _inside, _say_few
    if t <= 0 or not loops:
        return
    if cut_open is None:
        cut_open = _cut_openings(loops, cuts)
    keep = [np.asarray(P, dtype=float) for P, opening in zip(loops, cut_open)
            if len(P) >= 3 and not opening]      # not an opening a hole cuts
    lone = _lone_circles(keep, t)
    keep = [P for P, out in zip(keep, lone) if not out]
    if not keep:
        return
    tick()
    V, nxt, prv = _ring(keep)
    v, sg, dist, foot = close_pairs_facing(V, nxt, prv, t, FACING)
    if not len(v):
        return
    ok = (v != nxt[sg]) & (dist > 1e-6) & _facing(V, nxt, prv, v, sg, FACING)
    v, sg, dist, foot = v[ok], sg[ok], dist[ok], foot[ok]
    if not len(v):
        return
    mid = (V[v] + foot) / 2
    # the middle of the gap, and 1 um to either side across it (a slit's floor can be an
    # edge of the outline that the gap runs along: its middle lies on the outline itself)
    across = (foot - V[v])[:, ::-1] * np.array([1.0, -1.0])
    across *= 1e-3 / np.maximum(np.hypot(*across.T), 1e-300)[:, None]
    edges = _edges(loops)
    empty = ~_inside(mid, edges, tick)    # and where the middle is inside, either side
    full = np.flatnonzero(~empty)
    empty[full] = ~(_inside(mid[full] + across[full], edges, tick)
                    & _inside(mid[full] - across[full], edges, tick))
    v, sg, dist, foot, mid = v[empty], sg[empty], dist[empty], foot[empty], mid[empty]
    if not len(v):
        return
    tick()
    label = _clusters(mid, t)
    # the groups in the order of their least point, each group's points in order (one sort)
    order = np.argsort(label, kind="stable")
    cut = np.flatnonzero(np.r_[True, label[order][1:] != label[order][:-1]])
    lo, hi = np.minimum.reduceat(mid[order], cut), np.maximum.reduceat(mid[order], cut)
    long = np.flatnonzero(np.max(hi - lo, axis=1) >= t)
    groups = [(order[cut[i]:cut[i + 1] if i + 1 < len(cut) else len(order)],
               float(np.max(hi[i] - lo[i]))) for i in long]
    # the sides are named at each slit's mouth (its widest pair), clear of a floor that
    # another shape may make
    mouth = np.array([k[int(np.argmax(dist[k]))] for k, _ in groups], dtype=np.intp)
    faces = _faces_at(d, s, np.concatenate([V[v[mouth]], foot[mouth]]), tick) \
        if len(groups) else []
    corners: dict = {}                  # the part's nick corners, found once (slit_fix)
    said: list = []                     # the slits found, said by _say_few
    for i, (k, length) in enumerate(groups):
        tick()
        b = k[int(np.argmin(dist[k]))]
        w = float(dist[b])
        p, q = V[v[b]], foot[b]
        fp, fq = faces[i], faces[len(groups) + i]
        if fp is None or fq is None or fp is fq:
            continue            # a notch drawn in one shape (a heart's cusp) is meant
        names = [f"`{f.label}`" for f in (fp, fq) if f is not None]
        names = list(dict.fromkeys(names))
        later = max((f for f in (fp, fq) if f is not None and f.span is not None),
                    key=lambda f: (f.span.line, f.span.col), default=None)
        other = next((f for f in (fp, fq) if f is not None and f is not later
                      and f.span is not None), None)
        labels = [Label(other.span, "the other side of the slit", primary=False)] \
            if other is not None else []
        between = " and ".join(names)
        cx, cy = (p + q) / 2
        fix = slit_fix(d, s, (p + q) / 2, w, t, names, corners) if len(said) < SHOWN else ""
        said.append((f"a slit of empty space between {between} in `{s.path}` is "
                     f"{w:.2f} mm wide, narrower than {t:g} mm (over {length:.1f} mm, near "
                     f"({cx:.1f}, {cy:.1f})): narrower than a laser or router cuts, so it comes "
                     "out as a ragged notch or not at all",
                     later.span if later is not None else s.span,
                     {"labels": labels, "hint": f"{fix}; the minimum is set with --min-wall"}))
    _say_few(sink, "W0519", s.path, said)


def _faces_at(d: Drawing, s: Structure, points, tick=lambda: None) -> list:
    """For each of ``points`` (n x 2, mm), the geometry of part ``s``'s solids
    (:attr:`Drawing.own`) whose outline passes nearest to it (a point on the part's outline
    lies on some face's edge), or None; by one search of the
    faces' edges near the points (:func:`.nearby.close_pairs`, O((n + edges) log)): within a
    radius that doubles from 1 nm until every point has an edge, or has none within the
    part's box; the least distance wins, the first face in :attr:`Drawing.own`'s order on a tie
    (tests/test_checks_bounded.py holds the per-face loop it replaced, as its reference)."""
    from ...part.measure.nearby import close_pairs
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    A, Bq, poly, names = [], [], [], []     # the edges, their face (its number in order)
    for st, fs in _solids_within(d, s):
        for g, f in fs:
            if f is None or f.is_empty():
                continue
            for P in f.to_polygons():
                P = np.asarray(P, dtype=float).reshape(-1, 2)
                if len(P):
                    A.append(P)
                    Bq.append(np.roll(P, -1, axis=0))
                    poly.append(np.full(len(P), len(names), dtype=np.intp))
            names.append(g)
    out: list = [None] * len(points)
    if not A or not len(points):
        return out
    A, Bq, face = np.concatenate(A), np.concatenate(Bq), np.concatenate(poly)
    span = float(np.max(np.concatenate([A, points]).max(axis=0)
                        - np.concatenate([A, points]).min(axis=0)))
    todo = np.arange(len(points))
    radius = 1e-6
    while len(todo):
        tick()
        q, e, _dist, _foot = close_pairs(points[todo], np.full(len(todo), -1), A, Bq,
                                         np.zeros(len(A), dtype=np.intp), radius)
        if len(q):
            p = points[todo[q]]
            a, dd = A[e], Bq[e] - A[e]
            L2 = np.einsum("ij,ij->i", dd, dd)
            with np.errstate(divide="ignore", invalid="ignore"):
                u = np.clip(np.where(L2 > 0, np.einsum("ij,ij->i", p - a, dd) / L2, 0.0),
                            0.0, 1.0)
            e2 = a + u[:, None] * dd - p
            dm = np.einsum("ij,ij->i", e2, e2)
            best = np.lexsort((face[e], dm, q))
            first = best[np.r_[True, q[best][1:] != q[best][:-1]]]
            for k in first:
                out[todo[q[k]]] = names[face[e[k]]]
            found = np.zeros(len(todo), dtype=bool)
            found[q] = True
            todo = todo[~found]
        if radius > 2 * span + 1:
            break
        radius *= 8
    return out


def _clusters(points: np.ndarray, r: float) -> np.ndarray:
    """A label per point (n x 2, mm): points at most ``r`` apart in x and in y (their boxes
    grown by ``r / 2`` overlap) share one, transitively; the label is the least index of the
    points that share it.

    O(n log n) whatever the points, never listing the pairs (a map of the USA drawn 30 mm
    wide: 12,000 points all within 0.5 mm of hundreds of others, 5 GB of pairs): the points
    go into square cells of side ``r / 2`` (all points of a cell, and of two cells that touch,
    are closer than ``r``: one group); two cells two apart are joined when their points' x
    (or y) ranges come within ``r`` (rows one apart are within ``r`` in y), and two cells
    two apart diagonally when some pair is within ``r`` in both (a dominance test: the
    greatest y among the points past each x, by binary search).  The cells' groups come
    from :func:`_components` (no SciPy, whose import a cold ``aidl check`` avoids)."""
    P = np.asarray(points, dtype=float).reshape(-1, 2)
    n = len(P)
    if n < 2:
        return np.arange(n)
    s = r / 2
    ij = np.floor((P - P.min(axis=0)) / s).astype(np.int64)
    order = np.lexsort((ij[:, 1], ij[:, 0]))
    cij = ij[order]
    first = np.r_[True, np.any(cij[1:] != cij[:-1], axis=1)]
    start = np.flatnonzero(first)
    cell_of = np.empty(n, dtype=np.intp)
    cell_of[order] = np.cumsum(first) - 1
    C = cij[start]                            # the occupied cells (i, j), sorted
    m = len(C)
    Ps = P[order]
    lo = np.minimum.reduceat(Ps, start)
    hi = np.maximum.reduceat(Ps, start)
    # a cell's key: the rank of its column among the occupied ones, then its row
    cols = C[np.r_[True, C[1:, 0] != C[:-1, 0]], 0]    # sorted: np.unique imports numpy.ma
    rows = int(C[:, 1].max()) + 5
    key = np.searchsorted(cols, C[:, 0]) * rows + (C[:, 1] + 2)

    def find(di, dj):
        """(a, b): the cells a whose cell (i + di, j + dj) is occupied, b that cell."""
        c = C[:, 0] + di
        k = np.minimum(np.searchsorted(cols, c), len(cols) - 1)
        want = k * rows + C[:, 1] + dj + 2
        at = np.minimum(np.searchsorted(key, want), m - 1)
        ok = (cols[k] == c) & (key[at] == want)
        return np.flatnonzero(ok), at[ok]

    def near(b, a, axis):
        # the boxes' test (grown by r / 2 each: the same rounding at the boundary)
        return lo[b, axis] - s <= hi[a, axis] + s

    ea, eb, diag = [], [], []
    for di, dj in ((0, 1), (0, 2), (1, -2), (1, -1), (1, 0), (1, 1), (1, 2),
                   (2, -2), (2, -1), (2, 0), (2, 1), (2, 2)):
        a, b = find(di, dj)
        if not len(a):
            continue
        if di == 2 and abs(dj) == 2:
            diag.append((a, b, dj))
            continue
        if di == 2:
            ok = near(b, a, 0)
        elif dj == 2:
            ok = near(b, a, 1)
        elif dj == -2:
            ok = near(a, b, 1)
        else:
            ok = slice(None)
        ea.append(a[ok])
        eb.append(b[ok])
    root = _components(m, ea, eb)
    more_a, more_b = [], []
    for a, b, dj in diag:       # only the pairs not joined yet whose ranges come within r
        sy = 1.0 if dj > 0 else -1.0
        ok = (root[a] != root[b]) & near(b, a, 0) & (near(b, a, 1) if dj > 0 else
                                                     near(a, b, 1))
        for x, y in zip(a[ok], b[ok]):
            pa = Ps[start[x]:start[x + 1] if x + 1 < m else n]
            pb = Ps[start[y]:start[y + 1] if y + 1 < m else n]
            k = np.argsort(pa[:, 0] + s, kind="stable")
            xa = pa[k, 0] + s
            best = np.maximum.accumulate((sy * pa[k, 1] + s)[::-1])[::-1]   # greatest y past x
            at = np.searchsorted(xa, pb[:, 0] - s, side="left")
            got = at < len(xa)
            if np.any(best[at[got]] >= sy * pb[got, 1] - s):
                more_a.append(np.array([x]))
                more_b.append(np.array([y]))
    if more_a:
        root = _components(m, ea + more_a, eb + more_b)
    comp = root[cell_of]
    least = np.full(m, n, dtype=np.intp)
    np.minimum.at(least, comp, np.arange(n))
    return least[comp]


NECK_VERTS = 200_000   # W0507's neck search: not past this many vertices of members that overlap


def _outer_loops(cs) -> list:
    """The counter-clockwise loops (each k x 2, mm) of ``cs``: one per piece."""
    from ..common import _signed
    return [P for P in (np.asarray(p, dtype=float) for p in cs.to_polygons())
            if len(P) >= 3 and _signed(P) > 0]


def _eroded(shape, r: float):
    return shape.offset(-r, mf.JoinType.Round, 2.0, 16)


def _pieces_of(cs) -> tuple[list, np.ndarray]:
    """The loops of ``cs`` (each k x 2, mm) and for each the number of its piece: an outer
    (counter-clockwise) loop is its own piece, a hole belongs to the smallest outer loop
    whose box holds it."""
    from ..common import _signed
    loops = [np.asarray(p, dtype=float) for p in cs.to_polygons() if len(p) >= 2]
    outer = [k for k, P in enumerate(loops) if _signed(P) > 0]
    boxes = np.array([(*P.min(axis=0), *P.max(axis=0)) for P in loops]).reshape(-1, 4)
    area = np.prod(boxes[:, 2:] - boxes[:, :2], axis=1)
    piece = np.arange(len(loops))
    ob = boxes[outer]
    for k in range(len(loops)):
        if k in outer:
            continue
        ok = np.flatnonzero((ob[:, :2] <= boxes[k, :2]).all(axis=1)
                            & (ob[:, 2:] >= boxes[k, 2:]).all(axis=1))
        if len(ok):
            piece[k] = outer[int(ok[np.argmin(area[outer][ok])])]
    return loops, piece


def _closest_pieces(er, parent) -> tuple | None:
    """The two nearest pieces of the eroded shape ``er`` that ``parent`` (a point, mm ->
    the piece of the part before the erosion that holds it) puts in one piece of the part:
    ``(p, q, gap)``, ``p`` and ``q`` their nearest points (mm), by
    :func:`..part.nearby.close_pairs` within a radius that grows from 1 um; None when no two
    pieces of one piece of the part come within its size."""
    from ...part.measure.nearby import TooManyPairs, close_pairs
    loops, piece = _pieces_of(er)
    if len(loops) < 2:
        return None
    of = {int(k): parent(loops[k][0]) for k in set(piece.tolist())}
    V = np.concatenate(loops)
    B = np.concatenate([np.roll(P, -1, axis=0) for P in loops])
    feat = np.concatenate([np.full(len(P), piece[k]) for k, P in enumerate(loops)])
    span = float(np.max(V.max(axis=0) - V.min(axis=0)))
    radius = 1e-3
    while radius < 2 * span + 1:
        try:
            v, sg, dist, foot = close_pairs(V, feat, V, B, feat, radius)
        except TooManyPairs:
            return None
        same = np.array([of[int(feat[a])] is not None and of[int(feat[a])] == of[int(feat[b])]
                         for a, b in zip(v, sg)], dtype=bool)
        if same.any():
            k = np.flatnonzero(same)[int(np.argmin(dist[same]))]
            return V[v[k]], foot[k], float(dist[k])
        radius *= 4
    return None


def _face_at(d: Drawing, s: Structure, point, other):
    """The face ``(geometry, CrossSection)`` of part ``s``'s solids that covers ``point``
    (a 2 um square about it) most, one that does not cover ``other`` first (the member on
    ``point``'s side of a neck, where both overlap), or None."""
    q = mf.CrossSection.square((2e-3, 2e-3)).translate((point[0] - 1e-3, point[1] - 1e-3))
    o = mf.CrossSection.square((2e-3, 2e-3)).translate((other[0] - 1e-3, other[1] - 1e-3))
    best, most = None, (False, 0.0)
    for _, faces in _solids_within(d, s):
        for g, f in faces:
            if f is None:
                continue
            a, b, c, e = f.bounds()
            if a > point[0] + 1e-3 or c < point[0] - 1e-3 or b > point[1] + 1e-3 \
                    or e < point[1] - 1e-3:
                continue
            got = (_area(o ^ f) <= 0.0, _area(q ^ f))
            if got[1] > 0.0 and got > most:
                best, most = (g, f), got
    return best


def _check_necks(d: Drawing, s: Structure, shape, t: float, cuts, sink: DiagnosticSink,
                 tick=lambda ahead=0.0: None) -> None:
    """W0507 for two members of part ``s`` (solid shapes of its union, :attr:`Drawing.own`)
    that join over a neck narrower than ``t`` mm, or only at a point (a hook's loop that
    meets a leaf at its stem's tip: the cut part hangs by that point).  The opening of
    :func:`_check_walls` misses such a neck, which removes less than its ``2 t^2``.  A part
    of one member is not searched; in a part with holes, the members' union without them is
    (a web between holes is measured by the other W0507 checks).

    Found by the erosion of the part by ``t / 2`` (Manifold's offset, round joins): a neck
    narrower than ``t`` splits a piece in two, so the eroded part has more pieces (outer
    loops) than the part.  The neck's width is the least erosion that splits the part
    (bisection to 0.005 mm on the radius), its place the middle of the two pieces' nearest
    points just past that width, and the two members are the faces covering those points;
    a neck within one member (a plate cut nearly through by its holes) belongs to the other
    W0507 checks and is not reported here.  The hint gives how far to move the smaller side's
    member towards the other for a neck of ``t`` (bisection on the move, the two members
    and the shapes around the neck united again).  One erosion of the whole part (O(n log n)
    in its vertices, group by group: the members whose boxes overlap, united) when there is no
    neck; groups of more than :data:`NECK_VERTS` vertices in all are not searched."""
    from ..common import _edges, _inside, _union
    if t <= 0 or shape.is_empty():
        return
    faces = [f for _, fs in _solids_within(d, s) for _, f in fs if f is not None]
    if len(faces) < 2:
        return                  # one member: no neck between members
    # the members are united without the holes: a web a hole leaves is the other W0507s'
    # (a plate of 2,500 holes 0.3 mm apart would erode into 2,500 islands)
    # only members whose boxes overlap can join over a neck: the groups of them (connected by
    # overlapping boxes) are united and eroded each on its own - the same as the whole eroded,
    # since an erosion never joins what lies apart (Clipper's offset of 5,000 disjoint circles
    # at once took 20 s; a decompose of 4,000 of slightly different radii 40 s)
    # (the groups without listing the pairs: 1,000 concentric circles are 500,000 of them)
    from ...part.measure.nearby import box_groups
    group = box_groups(np.array([f.bounds() for f in faces], dtype=float))
    count = np.bincount(group, minlength=len(faces))
    if not (count > 1).any():
        return
    many = [_union([faces[k] for k in np.flatnonzero(group == g)])
            for g in np.flatnonzero(count > 1).tolist()]
    n = sum(p.num_vert() for p in many)
    if n > NECK_VERTS:
        return
    shape = mf.CrossSection.compose(many)       # the groups apart: composed, not united
    base = _outer_loops(shape)
    tick(n * THIN_SECONDS_PER_VERTEX)
    er = mf.CrossSection.compose([_eroded(p, t / 2) for p in many])
    if len(_outer_loops(er)) <= len(base):
        return
    edges = [_edges([P]) for P in base]

    def parent(pt):
        for k, E in enumerate(edges):
            if bool(_inside(np.asarray(pt, dtype=float)[None], E)[0]):
                return k
        return None
    far = _closest_pieces(er, parent)
    if far is None:
        return
    # the width, by bisection on the part within a window about the split (each step an
    # erosion of that window only): the least erosion that parts the two points
    c = (np.asarray(far[0]) + np.asarray(far[1])) / 2
    h = far[2] + 3 * t
    win = shape ^ mf.CrossSection.square((2 * h, 2 * h)).translate((c[0] - h, c[1] - h))
    wn = win.num_vert()

    def parted(r):
        tick(wn * THIN_SECONDS_PER_VERTEX)
        loops, piece = _pieces_of(_eroded(win, r))
        home = []
        for pt in (far[0], far[1]):
            k = next((int(piece[k]) for k, P in enumerate(loops) if piece[k] == k
                      and bool(_inside(np.asarray(pt)[None], _edges([P]))[0])), None)
            home.append(k)
        return home[0] is None or home[1] is None or home[0] != home[1]
    # the points lie 1 um inside the pieces eroded by t / 2 (on their edge otherwise)
    inward = (np.asarray(far[0]) - np.asarray(far[1]))
    inward = inward / max(float(np.hypot(*inward)), 1e-12) * 1e-3
    far = (np.asarray(far[0]) + inward, np.asarray(far[1]) - inward, far[2])
    lo, hi = 0.0, t / 2
    if not parted(hi):
        return
    while hi - lo > 2.5e-3:
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if parted(mid) else (mid, hi)
    width = 2 * lo
    if width >= t - 0.01:
        return                  # no narrower than the minimum, to the bisection's step
    near = _closest_pieces(_eroded(win, hi), parent)      # where the neck parts
    mid_pt = c if near is None else (np.asarray(near[0]) + np.asarray(near[1])) / 2
    # a neck beside a hole is a wall between the hole and the edge (the other W0507s)
    for cut in cuts:
        hs = d.shapes.get(cut.hole)
        if hs is None or hs.is_empty():
            continue
        x0, y0, x1, y1 = hs.bounds()
        if x0 - t <= mid_pt[0] <= x1 + t and y0 - t <= mid_pt[1] <= y1 + t and _area(
                hs ^ mf.CrossSection.circle(t, 32).translate((float(mid_pt[0]),
                                                              float(mid_pt[1])))) > 0:
            return
    # the members on either side: the faces at the nearest points of the pieces eroded by
    # t / 2 (clear of the neck itself, which both may cover)
    fp, fq = _face_at(d, s, far[0], far[1]), _face_at(d, s, far[1], far[0])
    if fp is None or fq is None or fp[0] is fq[0]:
        return
    # the member to move: the one on the smaller side of the split
    from ..common import _signed
    sides = _outer_loops(er)

    def side_area(pt):
        return next((abs(_signed(P)) for P in sides
                     if bool(_inside(np.asarray(pt, dtype=float)[None], _edges([P]))[0])),
                    np.inf)
    if side_area(far[1]) > side_area(far[0]):
        fp, fq = fq, fp
        far = (far[1], far[0], far[2])
    gp, (gq, sq) = fp[0], fq
    u = np.asarray(far[0], dtype=float) - np.asarray(far[1], dtype=float)
    nu = float(np.hypot(*u))
    move = None
    if nu > 1e-9:
        u /= nu
        x0, y0, x1, y1 = sq.bounds()
        reach = max(x1 - x0, y1 - y0) + 2 * t
        others = []
        for _, faces in _solids_within(d, s):
            for g, f in faces:
                if f is None or g is gq:
                    continue
                a, b, c, e = f.bounds()
                if a <= x1 + reach and c >= x0 - reach and b <= y1 + reach and e >= y0 - reach:
                    others.append(f)
        rest = _union(others)
        rest_n = len(_outer_loops(_eroded(rest, t / 2))) if not rest.is_empty() else 0
        own_n = len(_outer_loops(_eroded(sq, t / 2)))

        def joined(m):
            tick()
            whole = _union([rest, sq.translate((float(u[0] * m), float(u[1] * m)))])
            return len(_outer_loops(_eroded(whole, t / 2))) < rest_n + own_n
        top = reach
        if own_n and joined(top):
            a_, b_ = 0.0, top
            while b_ - a_ > 5e-3:
                m = (a_ + b_) / 2
                a_, b_ = (a_, m) if joined(m) else (m, b_)
            move = float(np.ceil(b_ * 100 - 1e-9) / 100)
            if not joined(move):
                move = b_
    from ..marks.engravings import _copy_label
    what_q, what_p = f"{gq.kind} `{_copy_label(gq)}`", f"{gp.kind} `{_copy_label(gp)}`"
    how = ("only at a point (a neck of zero width)" if width < 5e-3 else
           f"over a neck {width:.2f} mm wide")
    fix = (f"move {what_q} {move:.2f} mm towards {what_p} (by ({u[0] * move:.2f}, "
           f"{u[1] * move:.2f}) mm) so that they overlap over at least {t:g} mm"
           if move is not None else f"make {what_q} and {what_p} overlap over at least {t:g} mm")
    sink.warning(
        "W0507", f"{what_q} and {what_p} of `{s.path}` join {how}, narrower than {t:g} mm, "
        f"near ({mid_pt[0]:.1f}, {mid_pt[1]:.1f}): the cut part hangs by it and breaks there "
        "(or falls apart when the laser burns the neck away)",
        gq.span or s.span,
        labels=[Label(gp.span, "the other member", primary=False)] if gp.span else [],
        hint=f"{fix}; if the request asks for a joint this thin (a breakaway tab), say so: "
             f"`min_wall 0` in `{s.name}`; the minimum is set by `min_wall` or --min-wall")
