"""What the shape checks share (no warnings of their own): the area tolerances
(:data:`MIN_FRACTION` of a feature and at least :data:`MIN_AREA` mm^2, which ignore the chord
slivers of tessellated curves), W0507's default :data:`MIN_WALL`, areas and unions of
Manifold cross-sections, a structure's part and what a solid unites, the overlap depth of two
regions, and the point-in-polygon kernels (:func:`_inside`, :func:`_edges`, the signed area
:func:`_signed`) that the opening, engraving and topology checks test points with."""
from __future__ import annotations

import threading

import manifold3d as mf
import numpy as np

from ...base.diagnostics import Diagnostic
from ...geometry.core.model import Structure, within_index
from ..part.build.booleans import Drawing

MIN_FRACTION = 0.02      # of a hole's or child's area
MIN_AREA = 0.05          # mm^2
MIN_WALL = 0.5           # mm: W0507's default minimum wall
SHOWN = 5                # finds a per-part check says one by one before "and N more like it"


def _area(cs) -> float:
    return 0.0 if cs is None or cs.is_empty() else float(cs.area())


def _union(shapes) -> mf.CrossSection:
    """The union of ``shapes`` (None and empty ones left out), the boolean stage's way
    (:meth:`..part.booleans.Renderer.union`): up to :data:`..part.booleans.UNION_GROUP`
    shapes, or shapes whose boxes are all apart, in one ``batch_boolean``; more in groups of
    that many, then the groups' results, and so on (a balanced tree).  One batch costs about
    vertices x edges across a scan line: W0507's neck search united 1,000 concentric circles
    in 8.9 s CPU, in groups 0.05 s (the inner ones vanish in the first level).  Shapes apart
    but for the first (a part and the regions its holes cut: the part with its holes filled)
    unite in one pass too: nowhere more than two deep, where in groups the first, the
    largest, was passed again at every level (19,000 holes: 1.3 s, one pass 0.3 s)."""
    from ..part.build.booleans import UNION_GROUP
    from ..part.measure.nearby import faces_apart
    shapes = [s for s in shapes if s is not None and not s.is_empty()]
    if not shapes:
        return mf.CrossSection()
    if len(shapes) > UNION_GROUP and not faces_apart(shapes[1:]):
        while len(shapes) > UNION_GROUP:
            shapes = [mf.CrossSection.batch_boolean(shapes[i:i + UNION_GROUP], mf.OpType.Add)
                      for i in range(0, len(shapes), UNION_GROUP)]
    return mf.CrossSection.batch_boolean(shapes, mf.OpType.Add)


def _significant(a: float, whole: float) -> bool:
    return a > MIN_AREA and a > MIN_FRACTION * whole


def _pct(a: float, whole: float) -> str:
    return f"{100.0 * a / whole:.0f}%" if whole > 0 else "0%"


def _part_roots(d: Drawing) -> dict[Structure, mf.CrossSection]:
    shapes = {}
    for p in d.parts:
        s = d.part_of.get(p.name)
        if s is not None:
            shapes.setdefault(s, p.shape)     # a split part: its own piece, not those cut off
    return shapes


def _part_of(s: Structure, roots) -> Structure | None:
    """The nearest of ``s`` and the structures holding it that is in ``roots`` (a drawing
    that ``CutInto`` gives to a solid is held by it), or None."""
    return next((node for node in s.held_by() if node in roots), None)


def _contributors(d: Drawing, a: Structure, skip: Structure | None = None,
                  objects: bool = False):
    """What a solid ``a`` unites: (name, span, shape) of its own faces and solid children
    (``objects``: (name, span, shape, the Geometry or Structure))."""
    out = []
    own = d.own.get(a, [])
    # a loop's copies by index (run cb: "{`puppet.jaw.fang`}" five times, for fang[1]..[4])
    total: dict = {}
    for g, _ in own:
        if g.name and g.span is not None:
            total[(g.name, g.span)] = total.get((g.name, g.span), 0) + 1
    seen: dict = {}
    for g, f in own:
        key = (g.name, g.span)
        label = g.label
        if total.get(key, 0) > 1:
            seen[key] = seen.get(key, -1) + 1
            label = f"{g.label}[{seen[key]}]"
        out.append((f"`{label}`", g.span, f, g) if objects else (f"`{label}`", g.span, f))
    for c in a.children.values():
        if c is skip or c.kind not in ("solid", "hole") or c.kind == "hole":
            continue
        if c in d.shapes:
            item = (f"solid `{c.path}`", c.span, d.shapes[c])
            out.append(item + (c,) if objects else item)
    return out


def _cross(r1, r2) -> bool:
    """Whether two cut regions (CrossSections, or None) cross: each runs past the other on
    both sides, so each less the other falls into two pieces or more, at any rotation (run
    at's tambourine: a pin channel across each of four windows turned 206 to 334 degrees was
    judged by axis-aligned boxes and told to move 9.51 mm)."""
    if r1 is None or r2 is None:
        return False
    return all(sum(1 for p in (x - y).decompose() if _area(p) > MIN_AREA) >= 2
               for x, y in ((r1, r2), (r2, r1)))


def _body(s) -> str:
    """Where a statement for structure ``s`` is written: `` `path` ``, or the body of the
    template that makes it (run at's tambourine: "in `tambourine.middle`", a call)."""
    t = getattr(s, "template", None)
    return f"the body of `{t}` (the template that makes `{s.path}`)" if t else f"`{s.path}`"


def _depth(common, bi, bj) -> float:
    """How far two overlapping regions reach into each other: the extent of their common
    part along the line between their boxes' centres (for two circles exactly
    ``r1 + r2 - distance``), or its narrower side when the centres coincide."""
    P = np.concatenate([np.asarray(p, dtype=float) for p in common.to_polygons()])
    u = (np.asarray(bj[:2]) + bj[2:]) / 2 - (np.asarray(bi[:2]) + bi[2:]) / 2
    n = float(np.hypot(*u))
    if n < 1e-9:
        return float(min(np.ptp(P[:, 0]), np.ptp(P[:, 1])))
    proj = P @ (u / n)
    return float(proj.max() - proj.min())


def _inside_loops(pts: np.ndarray, loops) -> np.ndarray:
    """The reference even-odd test: every point against every edge of each loop in turn
    (O(points x edges) memory and time).  Kept for the property test of :func:`_inside`."""
    res = np.zeros(len(pts), dtype=bool)
    x, y = pts[:, 0], pts[:, 1]
    for lp in loops:
        P = np.asarray(lp, dtype=float)
        Q = np.roll(P, -1, axis=0)
        x1, y1, x2, y2 = P[:, 0][None], P[:, 1][None], Q[:, 0][None], Q[:, 1][None]
        yy = y[:, None]
        cond = (y1 > yy) != (y2 > yy)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            xi = x1 + (yy - y1) * (x2 - x1) / (y2 - y1)
        res ^= (np.sum(cond & (x[:, None] < xi), axis=1) % 2).astype(bool)
    return res


INSIDE_CHUNK = 1_000_000     # (edge, point) candidates :func:`_inside` holds at once (~50 MB)
INSIDE_LEAF = 65_536         # candidates a cell of the split tests directly, and
INSIDE_PER_ITEM = 16         # as many per point and edge: below that splitting saves nothing


def _inside(pts: np.ndarray, loops, tick=None) -> np.ndarray:
    """Even-odd point-in-polygon of ``pts`` (N x 2, mm) against the union of closed ``loops``
    (each M x 2, implicitly closed; or their :func:`_edges`): True where a ray to +x crosses
    the loops' edges an odd number of times (the crossing-number test, as in W. R. Franklin's
    ``pnpoly``); a point with a coordinate that is not finite is outside.

    The edges of all loops are taken together (the parity of the total equals the XOR of the
    per-loop parities) and each edge is tested only against the points whose y lies in its
    half-open y range ``[min(y1, y2), max(y1, y2))``, found by binary search in the points
    sorted by y.  When those (edge, point) candidates are many (thousands of edges across the
    same heights: 5,000 circles in a row), the distinct points are split in halves by their
    median along the longer side of their box, as a k-d tree (:func:`_inside_split`): in each
    cell an edge wholly to the right of the cell's points crosses the ray of every point in
    its y range (counted from the sorted range ends, no pairs), one wholly to the left
    crosses none, and only the edges across the cell go on; a cell is tested directly once
    its candidates are few.  Every split halves the points, so the work is O((N + E) log N)
    for edges short beside the points' spread, and the memory at most :data:`INSIDE_CHUNK`
    candidates.  The crossing abscissa is computed with the same floating-point expression
    as the reference :func:`_inside_loops` (a cell's left and right are decided with a margin
    far above its rounding), so the result is identical to it.  ``tick()``: called at each
    cell (the deadline, :class:`~aidl_lang.base.limits.Deadline`; it may raise)."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 2)
    n = len(pts)
    x1, y1, x2, y2 = loops if isinstance(loops, tuple) else _edges(loops)
    if not n or not len(x1):
        return np.zeros(n, dtype=bool)
    y = pts[:, 1]
    order = np.argsort(y, kind="stable")
    ys = y[order]
    lo = np.searchsorted(ys, np.minimum(y1, y2), side="left")
    hi = np.searchsorted(ys, np.maximum(y1, y2), side="left")
    total = int(np.maximum(hi - lo, 0).sum())
    if not total:
        return np.zeros(n, dtype=bool)
    if total <= min(INSIDE_CHUNK, INSIDE_LEAF + INSIDE_PER_ITEM * (n + len(x1))):
        return _inside_direct(pts, (x1, y1, x2, y2), order, lo, hi)
    res = np.zeros(n, dtype=bool)
    fin = np.flatnonzero(np.isfinite(pts).all(axis=1))
    if len(fin):
        U, inv = np.unique(pts[fin], axis=0, return_inverse=True)
        res[fin] = _inside_split(U, (x1, y1, x2, y2), tick)[inv.reshape(-1)]
    return res


def _inside_direct(pts, edges, order=None, lo=None, hi=None) -> np.ndarray:
    """:func:`_inside` by testing every (edge, point) candidate of the y search, in runs of
    edges of at most :data:`INSIDE_CHUNK` candidates (``order``, ``lo``, ``hi``: the points'
    y order and each edge's range in it, when at hand)."""
    n = len(pts)
    x1, y1, x2, y2 = edges
    x, y = pts[:, 0], pts[:, 1]
    if order is None:
        order = np.argsort(y, kind="stable")
        ys = y[order]
        lo = np.searchsorted(ys, np.minimum(y1, y2), side="left")
        hi = np.searchsorted(ys, np.maximum(y1, y2), side="left")
    cnt = np.maximum(hi - lo, 0)
    odd = np.zeros(n, dtype=bool)
    run = np.cumsum(cnt)
    a = 0
    while a < len(cnt):
        # the edges from a whose candidates fit in one chunk (at least one edge)
        b = max(a + 1, int(np.searchsorted(run, (run[a - 1] if a else 0) + INSIDE_CHUNK,
                                           side="right")))
        c = cnt[a:b]
        total = int(c.sum())
        if total:
            edge = a + np.repeat(np.arange(b - a), c)
            start = np.cumsum(c) - c
            pt = order[lo[edge] + (np.arange(total) - start[edge - a])]
            yy, ex1, ey1, ex2, ey2 = y[pt], x1[edge], y1[edge], x2[edge], y2[edge]
            cond = (ey1 > yy) != (ey2 > yy)
            with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                xi = ex1 + (yy - ey1) * (ex2 - ex1) / (ey2 - ey1)
            odd ^= (np.bincount(pt[cond & (x[pt] < xi)], minlength=n) % 2).astype(bool)
        a = b
    return odd


def _inside_split(U: np.ndarray, edges, tick=None) -> np.ndarray:
    """:func:`_inside` of the distinct finite points ``U`` by the k-d split its docstring
    describes (an explicit stack of cells: (point indices, edge indices))."""
    x1, y1, x2, y2 = edges
    ylo, yhi = np.minimum(y1, y2), np.maximum(y1, y2)
    xlo, xhi = np.minimum(x1, x2), np.maximum(x1, x2)
    span = max(float(np.max(np.abs(U))), float(np.nanmax(np.abs([xlo, xhi, ylo, yhi]))))
    m = 1e-9 * (1.0 + span)       # far above the crossing's rounding (a few ulps of span)
    odd = np.zeros(len(U), dtype=bool)
    live = np.flatnonzero(ylo < yhi)            # a level edge (or NaN) crosses no ray
    stack = [(np.arange(len(U)), live)]
    while stack:
        if tick is not None:
            tick()
        P, E = stack.pop()
        px, py = U[P, 0], U[P, 1]
        xa, xb, ya, yb = px.min(), px.max(), py.min(), py.max()
        E = E[(ylo[E] <= yb) & (yhi[E] > ya)]
        right = xlo[E] > xb + m
        if right.any():
            # wholly right of every point: crosses the ray of each point in its y range
            R = E[right]
            c = (np.searchsorted(np.sort(ylo[R]), py, side="right")
                 - np.searchsorted(np.sort(yhi[R]), py, side="right"))
            odd[P] ^= (c % 2).astype(bool)
            E = E[~right]
        E = E[xhi[E] >= xa - m]                   # wholly left: crosses none
        if not len(E):
            continue
        order = np.argsort(py, kind="stable")
        ys = py[order]
        lo = np.searchsorted(ys, ylo[E], side="left")
        hi = np.searchsorted(ys, yhi[E], side="left")
        total = int(np.maximum(hi - lo, 0).sum())
        few = INSIDE_LEAF + INSIDE_PER_ITEM * (len(P) + len(E))
        if len(P) == 1 or total <= min(INSIDE_CHUNK, few):
            odd[P] ^= _inside_direct(U[P], (x1[E], y1[E], x2[E], y2[E]), order, lo, hi)
            continue
        along = px if xb - xa >= yb - ya else py
        k = len(P) // 2
        half = np.argpartition(along, k)
        stack.append((P[half[:k]], E))
        stack.append((P[half[k:]], E))
    return odd


def _edge_distance(P: np.ndarray, edges) -> np.ndarray:
    """The distance (mm) from each point of ``P`` (N x 2) to the nearest of ``edges`` (the
    four arrays of :func:`_edges`), points against edges in blocks of at most a million
    pairs (the farthest point of a keyhole run out of its part, W0530; a pattern's copy)."""
    x1, y1, x2, y2 = (np.asarray(e, dtype=float) for e in edges)
    dx, dy = (x2 - x1)[None], (y2 - y1)[None]
    L2 = dx * dx + dy * dy
    step = max(1, 1_000_000 // max(1, len(x1)))
    dist = np.empty(len(P))
    for i in range(0, len(P), step):
        px, py = P[i:i + step, :1] - x1[None], P[i:i + step, 1:] - y1[None]
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.clip(np.where(L2 > 0, (px * dx + py * dy) / L2, 0.0), 0.0, 1.0)
        dist[i:i + step] = np.hypot(px - t * dx, py - t * dy).min(axis=1)
    return dist


def _edges(loops) -> tuple:
    """The edges of closed ``loops`` as four arrays (x1, y1, x2, y2): each vertex to the next,
    the last back to the first; what :func:`_inside` takes (prepared once per part)."""
    polys = [np.asarray(lp, dtype=float).reshape(-1, 2) for lp in loops]
    polys = [P for P in polys if len(P)]
    if not polys:
        return (np.zeros(0),) * 4
    P = np.concatenate(polys)
    Q = np.concatenate([np.concatenate([p[1:], p[:1]]) for p in polys])   # np.roll(p, -1)
    return P[:, 0], P[:, 1], Q[:, 0], Q[:, 1]


# the signed areas of the loops the checks of one drawing share (a part's loops are looked at
# by W0504, W0515, W0519 and W0520 alike): id -> (the array, its area), filled while
# check_drawing runs (the arrays are held, so an id is not reused) and emptied after it
_SIGNED: dict = {}
_SHARING = [0]              # check_drawing calls running (threads of a server)
_LOCK = threading.Lock()


def _signed(poly) -> float:
    """The signed area (mm^2) of the closed polygon ``poly`` (k x 2): positive when it runs
    counter-clockwise (the shoelace formula)."""
    hit = _SIGNED.get(id(poly))
    if hit is not None and hit[0] is poly:
        return hit[1]
    P = np.asarray(poly, dtype=float)
    x, y = P[:, 0], P[:, 1]
    a = 0.5 * float(np.dot(x, np.concatenate([y[1:], y[:1]]))       # np.roll(y, -1)
                    - np.dot(y, np.concatenate([x[1:], x[:1]])))
    if _SHARING[0] and isinstance(poly, np.ndarray):
        _SIGNED[id(poly)] = (poly, a)
    return a


# each drawing's solid structures by the structures they lie within (what _solids_within
# answers): id of the drawing's ``own`` -> (that dict, the index), filled while
# check_drawing runs and emptied after it, as _SIGNED
_WITHIN: dict = {}


def _solids_within(d, s) -> list:
    """``[(t, faces)]`` of :attr:`Drawing.own` for every solid structure ``t`` that is ``s``
    or lies within it, in ``own``'s order.  While :func:`check_drawing` runs, from an index
    of the drawing built once (:func:`~...geometry.model.within_index`: O(structures x
    depth)); asking every structure of ``own`` for every part cost parts x structures (a
    sheet of 4,000 parts: W0515 ran out of its share)."""
    own = d.own
    if not _SHARING[0]:
        return [(t, f) for t, f in own.items() if t.kind == "solid" and t.is_within(s)]
    hit = _WITHIN.get(id(own))
    if hit is None or hit[0] is not own:
        solids = [(t, f) for t, f in own.items() if t.kind == "solid"]
        hit = _WITHIN[id(own)] = (own, within_index(solids, lambda tf: tf[0]))
    return hit[1].get(s, [])


def _cut_boxes(cuts) -> np.ndarray:
    """The bounding boxes of the holes' cut regions: n x 4 (x0, y0, x1, y1), mm."""
    return np.array([c.region.bounds() for c in cuts if c.region is not None
                     and not c.region.is_empty()], dtype=float).reshape(-1, 4)


def _loop_boxes(loops: list) -> np.ndarray:
    """The boxes (x0, y0, x1, y1) of ``loops`` ((n, 2) arrays, n >= 1), an (len(loops), 4)
    array."""
    if not loops:
        return np.zeros((0, 4))
    P = np.concatenate(loops)
    start = np.cumsum([0] + [len(p) for p in loops[:-1]])
    return np.hstack([np.minimum.reduceat(P, start), np.maximum.reduceat(P, start)])


def _cut_openings(loops: list, cuts) -> np.ndarray:
    """Which of a part's final ``loops`` are openings a hole cuts (clockwise, the loop's box
    meeting the box of a hole's cut region, :func:`_cut_boxes`): a bool per loop,
    all loops in one box pass (:func:`..part.nearby.box_pairs_between`).  Taken once per part
    and shared by W0515, W0519 and W0520, which leave these loops out."""
    from ..part.measure.nearby import box_pairs_between
    out = np.zeros(len(loops), dtype=bool)
    hb = _cut_boxes(cuts)
    inner = [k for k, P in enumerate(loops) if len(P) and _signed(P) < 0]
    if not len(hb) or not inner:
        return out
    pairs = box_pairs_between(_loop_boxes([np.asarray(loops[k], dtype=float) for k in inner]),
                              hb)
    out[np.asarray(inner, dtype=np.intp)[pairs[:, 0]]] = True
    return out


def _insert_fix(struct: Structure, stmt: str, sink=None):
    """A :class:`~aidl_lang.base.diagnostics.Fix` that writes the statement ``stmt`` as the last
    of structure ``struct``'s body (before its closing ``}``), indented one step inside it,
    or None when the structure is not in a source of ``sink`` (the program's own files: a
    stdlib template's, a generated one is not edited); ``sink``'s ``sources`` also tell
    whether the ``}`` stands on a line of its own."""
    from ...base.diagnostics import Fix, Span, in_stdlib
    sp = getattr(struct, "span", None)
    if sp is None or not sp.file or sp.end <= sp.start or in_stdlib(sp.file):
        return None
    src = getattr(sink, "sources", {}).get(sp.file) if sink is not None else None
    if src is None or sp.end > len(src) or src[sp.end - 1] != "}":
        return None                 # not a file of the program's own (a stdlib template's)
    col = sp.end_col - 1                              # the closing brace's column (1-based)
    line = src[src.rfind("\n", 0, sp.end - 1) + 1:sp.end - 1]
    alone = not line.strip()
    at = Span(sp.file, sp.end_line, col, sp.end_line, col, sp.end - 1, sp.end - 1)
    pad = line[:len(line) - len(line.lstrip())]
    text = f"    {stmt}\n{pad}" if alone else f"\n{pad}    {stmt}\n{pad}"
    return Fix(at, text)


def below(w: float, t: float, places: int = 2) -> str:
    """A measured width ``w`` (mm) under the minimum ``t`` (mm) as a sentence says it: to
    ``places`` decimals, or more until the text reads less than ``t`` ("0.4996", never "0.50
    mm wide, thinner than 0.5 mm": the page drops trailing zeros, issue 113)."""
    for d in range(places, 7):
        text = f"{w:.{d}f}"
        if float(text) < t:
            return text
    return f"{w:.15g}"


def _say_few(sink, code: str, path: str, finds: list, severity: str = "warning") -> None:
    """Warn ``code`` for the first :data:`SHOWN` of ``finds`` (each ``(message, span, kw)``,
    ``kw`` the warning's other fields: hint, labels), in their order; when there are more,
    the last one said ends "(and N more like it in `path`)": a part of 4,000 circles that
    falls apart finds hundreds of slits (W0519) or voids (W0515), a flood that no reader
    (person or model) reads, while the first few and the count say what to fix."""
    rest = len(finds) - SHOWN
    for k, (message, span, kw) in enumerate(finds[:SHOWN]):
        if rest > 0 and k == SHOWN - 1:
            message += f" (and {rest} more like it in `{path}`)"
        sink.add(Diagnostic(code, message, span, severity, **kw))


def part_min_wall(d: Drawing, part, given: float | None = None) -> float:
    """The minimum wall (mm) the checks hold part ``part`` to: ``given`` (the command line's
    ``--min-wall``) when set, else the program's ``min_wall`` statement for it (its own, an
    ancestor's or the top level's: :attr:`Drawing.min_wall`), else :data:`MIN_WALL`."""
    if given is not None:
        return given
    own = getattr(d, "min_wall", None) or {}
    name = getattr(part, "path", None)
    return own.get(name, MIN_WALL) if name is not None else MIN_WALL


def freed_share(d, part, off: np.ndarray, tol: float) -> int:
    """How many of the pieces that the through-cuts of ``part`` free (the parts named
    ``PATH.pieceK``) the points ``off`` (N x 2, mm: an engraving's points off ``part``'s
    material) lie on, each within ``tol``; 0 unless every point lies on one of them (run ae's
    jigsaw: a heart and two names across the 12 pieces of a puzzle)."""
    pre = part.path + ".piece"
    pieces = [p.shape for p in d.parts if p.name.startswith(pre) and not p.shape.is_empty()]
    if not pieces or not len(off):
        return 0
    hit = np.zeros(len(off), dtype=bool)
    used = 0
    for shp in pieces:
        grown = shp.offset(tol, mf.JoinType.Round, 2.0, 16)
        on = _inside(off, _edges([np.asarray(q, dtype=float) for q in grown.to_polygons()]))
        used += bool(on.any())
        hit |= on
    return used if hit.all() else 0


def written(s, x: float, y: float) -> tuple[float, float]:
    """Point ``(x, y)`` (mm, on the sheet) of part ``s`` where its program writes it: less how
    far the solve moved the part (``s.moved``, set by the booleans: a layout relation,
    `RightOf(b, a)`), so that a message's position is the one in the program (runs cw, dk:
    positions given in the laid-out sheet's coordinates, 300 mm off the program's)."""
    dx, dy = s.__dict__.get("moved", (0.0, 0.0)) if s is not None else (0.0, 0.0)
    return x - dx + 0.0, y - dy + 0.0


def _template_own(a, i: int, j: int) -> str:
    """The start of W0508's hint when one of the two holes is a standard-library template's
    own opening and the other the program's (runs ec, ev: a finger slot added over
    `sliding_lid_box`'s lid pull, "move it 5.52 mm" where the lid already had a pull); else
    ``""``."""
    if not a.cuts:
        return ""
    hi, hj = a.cuts[i - 1].hole, a.cuts[j - 1].hole
    ti, tj = _stdlib_template(hi), _stdlib_template(hj)
    if bool(ti) == bool(tj):
        return ""
    own, other = (a.names[i], a.names[j]) if ti else (a.names[j], a.names[i])
    return (f"{own} is `{ti or tj}`'s own opening, which the template makes: if {other} is "
            "there for the same job, leave it out; else ")


def _stdlib_template(h) -> str | None:
    """The standard-library template whose body drew hole ``h`` (its statement in std/), or
    None for a hole the program draws."""
    from ...base.diagnostics import in_stdlib
    if h.span is None or not in_stdlib(h.span.file):
        return None
    for s in h.ancestors():
        if getattr(s, "template", None):
            return s.template
    return None


def _apart(shape) -> bool:
    """The part's final shape is in more than one piece: overlapping openings that cut it
    apart are not meant, and no fix says so with `AllowOverlap` (run et's Maxwell wheel: six
    windows run together cut the hub off the rim, W0504, and the fix would have hidden it)."""
    return shape is not None and not shape.is_empty() and len(shape.decompose()) > 1
