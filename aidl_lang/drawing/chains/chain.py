"""Loose pieces joined into a drawing: the segments a reader made (open pieces, closed loops,
circles, ellipses; mm) in, a :class:`~.model.Drawing` of outlines and open paths out
(:func:`_finish`).  On the way: pieces that are one point dropped (:func:`_drop_degenerate`),
duplicates removed (:func:`_dedupe`), pieces chained end to end on a grid of their ends
(:func:`_chain`), a path whose end runs past its start closed at the crossing
(:func:`_overshoot`), gaps within the closing tolerance closed (:func:`_meet`), a loop's small
loops where it crosses itself cut off (:func:`_trim_small_loops`), a loop that still crosses
itself (:func:`_crossing`) split at its crossings on a cut role (:func:`_lobes`), else at
the points it passes through twice, a crumb pinched off there cut off (:func:`_pinched_lobes`),
else kept as a path.  Crossings are exact on the pieces' own carriers
(:func:`~aidl_lang.geometry.shapes.curves.crossings`)."""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Loop, Spline
from ..model import (_OPTS, JOIN_TOL, Drawing, Note, Outline, Path, _plural, _segs_box,
                     bezier_spline)

MAX_CROSSING_CHORDS = 6000   # loops with more chords are not checked for crossing themselves
# work units of _chord_hits: a row of chords (numpy's calls: about 25 us) and a pair of chords
CROSSING_ROW_UNITS = 3.3
CROSSING_PAIR_UNITS = 0.004


def _meet(a, b) -> tuple[list, list]:
    """``a`` and ``b`` (segments, ``a.end`` near ``b.start``) made to meet exactly: the end
    of ``a`` (else the start of ``b``) is moved onto the other when it is a Line over ten
    times longer than the gap (its direction turns by less than 0.1 rad), else a tiny Line
    bridges the gap; an arc's
    or a curve's own numbers are never changed (their exactness is kept)."""
    g = math.dist(a.end, b.start)
    if g == 0.0:
        return [a], [b]
    if isinstance(a, Line) and math.dist(a.start, a.end) > 10 * g:
        return [Line(a.start, b.start)], [b]
    if isinstance(b, Line) and math.dist(b.start, b.end) > 10 * g:
        return [a], [Line(a.end, b.end)]
    return [a, Line(a.end, b.start)], [b]


def _seg_key(s, q: float = 1e-6):
    """A key equal for two segments that are the same curve, run either way (ends rounded
    to ``q`` mm): lines, arcs and spline pieces; None for others."""
    def r(p):
        return (round(p[0] / q), round(p[1] / q))
    if isinstance(s, Line):
        return ("L", frozenset((r(s.start), r(s.end))))
    if isinstance(s, Arc):
        return ("A", r(s.center), round(s.radius / q), frozenset((r(s.start), r(s.end))),
                r(s.at(s.start_angle + s.sweep / 2)))
    if isinstance(s, Spline):
        pts = tuple(r(p) for b in s.spans for p in b)
        return ("S", min(pts, pts[::-1]))
    return None


def _dedupe(pieces: list, loops: list) -> tuple[list, list, int]:
    """``pieces`` and ``loops`` without the duplicates a drawing program leaves (the same
    line drawn twice, a path drawn over another): a piece or loop every segment of which is
    already drawn is left out.  Returns them and the count of segments removed."""
    seen: set = set()
    removed = 0

    def dup(segs) -> bool:
        keys = [_seg_key(x) for x in segs]
        if keys and all(k is not None and k in seen for k in keys):
            return True
        seen.update(k for k in keys if k is not None)
        return False
    out_loops = []
    for segs, src in loops:
        if dup(segs):
            removed += len(segs)
        else:
            out_loops.append((segs, src))
    out_pieces = []
    for p in pieces:
        if dup(p):
            removed += len(p)
        else:
            out_pieces.append(p)
    return out_pieces, out_loops, removed


def _chain(pieces: list, tol: float = JOIN_TOL, gaps: list | None = None,
           deadline=None) -> tuple[list, list]:
    """Join open pieces (lists of segments) end to end: ``(closed chains, open chains)``.
    The pieces' ends are kept in a grid of cells ``tol`` wide, so each step finds its
    neighbours in the 3 x 3 cells around an end: linear in the pieces (20 000 loose lines join
    in well under a second), where scanning them all at every step was quadratic.

    ``tol`` above :data:`JOIN_TOL` (the closing tolerance): ends that far apart are made to
    meet exactly (:func:`_meet`) and each gap so closed is appended to ``gaps`` as ``(gap mm,
    where)``.  ``deadline``: a :class:`~aidl_lang.base.limits.Deadline`, checked as it goes."""
    from ...geometry.shapes.curves import reverse
    pieces = [list(p) for p in pieces]
    used = [False] * len(pieces)
    grid: dict = {}

    def cell(p):
        return (math.floor(p[0] / tol), math.floor(p[1] / tol))

    def join(left: list, right: list) -> list:
        """``left + right``, their meeting ends made exact (the gap noted) when apart."""
        g = math.dist(left[-1].end, right[0].start)
        if g == 0.0 or tol <= JOIN_TOL or g <= JOIN_TOL:
            return left + right
        if gaps is not None:
            gaps.append((g, left[-1].end))
        a, b = _meet(left[-1], right[0])
        return left[:-1] + a + b + right[1:]

    for i, p in enumerate(pieces):
        for q in (p[0].start, p[-1].end):
            grid.setdefault(cell(q), []).append(i)

    def near(q):
        cx, cy = cell(q)
        out = []
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                out += [i for i in grid.get((cx + dx, cy + dy), ()) if not used[i]]
        return sorted(set(out))

    closed, paths = [], []
    for i0 in range(len(pieces)):
        if used[i0]:
            continue
        if deadline is not None and i0 % 256 == 0:
            deadline.check("joining the drawing's pieces")
        used[i0] = True
        cur = list(pieces[i0])
        for forward in (True, False):
            while math.dist(cur[0].start, cur[-1].end) > tol:
                end = cur[-1].end if forward else cur[0].start
                for i in near(end):
                    p = pieces[i]
                    if forward and math.dist(p[0].start, end) <= tol:
                        cur = join(cur, p)
                    elif forward and math.dist(p[-1].end, end) <= tol:
                        cur = join(cur, [reverse(s) for s in reversed(p)])
                    elif not forward and math.dist(p[-1].end, end) <= tol:
                        cur = join(p, cur)
                    elif not forward and math.dist(p[0].start, end) <= tol:
                        cur = join([reverse(s) for s in reversed(p)], cur)
                    else:
                        continue
                    used[i] = True
                    break
                else:
                    break
        g = math.dist(cur[0].start, cur[-1].end)
        if g <= tol:
            if g > JOIN_TOL:            # closed across the gap: its ends made one point
                if gaps is not None:
                    gaps.append((g, cur[-1].end))
                if len(cur) == 1:
                    cur = cur + [Line(cur[-1].end, cur[0].start)]
                else:
                    a, b = _meet(cur[-1], cur[0])
                    cur = b + cur[1:-1] + a
            closed.append(cur)
        else:
            paths.append(cur)
    return closed, paths


def _crossing(segs) -> tuple[float, float] | None:
    """A point where the closed loop ``segs`` crosses itself, or None (on its chords within
    0.005 mm of the curves)."""
    return next(_chord_hits(segs), None)


def _chord_hits(segs):
    """The points where the chords of the closed loop ``segs`` cross (within 0.005 mm of
    the curves), one by one, in the loop's order (a generator: a caller that passes over a
    hit goes on from it, the chords before it not measured again)."""
    import numpy as np
    pts = Loop(list(segs)).points()
    P = np.asarray(pts, dtype=float)
    n = len(P)
    if n < 4 or n > MAX_CROSSING_CHORDS:
        return
    deadline = getattr(_OPTS.get(None), "deadline", None)
    if deadline is not None:        # paid before: n rows of chords, each against the rest
        deadline.check("finding where the loops cross themselves",
                       ahead=n * (CROSSING_ROW_UNITS + CROSSING_PAIR_UNITS * n))
    A, B = P, np.roll(P, -1, axis=0)
    for i in range(n - 2):
        j0, j1 = i + 2, n if i > 0 else n - 1
        if j0 >= j1:
            continue
        a, b = A[i], B[i]
        c, d = A[j0:j1], B[j0:j1]
        def orient(p, q, r):
            return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])
        o1 = orient(a, b, c)
        o2 = orient(a, b, d)
        o3 = orient(c, d, a)
        o4 = orient(c, d, b)
        hit = (o1 * o2 < 0) & (o3 * o4 < 0)
        for k in np.flatnonzero(hit).tolist():
            t = o1[k] / (o1[k] - o2[k])
            x, y = c[k] + t * (d[k] - c[k])
            yield float(x), float(y)


OVERSHOOT = 0.5          # mm: a path whose end runs this far past its start is closed there


def _piece_length(s) -> float:
    return s.length if not isinstance(s, Circle) else 2 * math.pi * s.radius


def _split_at(s, x) -> tuple | None:
    """Segment ``s`` cut at its point ``x``: ``(s from its start to x, s from x to its
    end)``, each on ``s``'s own carrier (:func:`~aidl_lang.geometry.shapes.curves.with_ends`:
    exact, a line stays a line, an arc an arc, a curve the same curve); None when ``x`` is
    not on ``s`` between its ends (their lengths do not add up to its own)."""
    from ...geometry.shapes.curves import with_ends
    try:
        a, b = with_ends(s, s.start, x), with_ends(s, x, s.end)
        la, lb, l0 = _piece_length(a), _piece_length(b), _piece_length(s)
    except Exception:
        return None
    if abs(la + lb - l0) > 1e-9 * max(1.0, l0):
        return None
    return a, b


def _distinct(pts, tol: float = 1e-9) -> list:
    """The points ``pts`` (mm) in their order without the repeats of one within ``tol`` of
    an earlier one: two curves that touch (a corner curve run back along the edge it left)
    give their touching point many times, each one cut and measured again."""
    out: list = []
    for p in pts:
        if all(abs(p[0] - q[0]) > tol or abs(p[1] - q[1]) > tol for q in out):
            out.append(p)
    return out


def _splits(a, b):
    """Each exact crossing ``x`` of pieces ``a`` and ``b`` (of their carriers,
    :func:`~aidl_lang.geometry.shapes.curves.crossings`, distinct) with both split there:
    ``(x, (a before, a after), (b before, b after))``; a crossing where either cannot be
    split is skipped, and a pair whose carriers the solver cannot cross gives none."""
    from ...geometry.shapes.curves import carrier, crossings
    try:
        pts = _distinct(crossings(carrier(a), carrier(b)))
    except Exception:
        return
    for x in pts:
        sa, sb = _split_at(a, x), _split_at(b, x)
        if sa is not None and sb is not None:
            yield x, sa, sb


def _overshoot(segs: list, bound: float):
    """The closed loop of the open chain ``segs`` whose end crosses its own start (a path
    drawn past its start so that the beam closes it, as Boxes.py's D-bores end 0.1 mm past
    theirs): ``(loop, overshoot mm, crossing)``, the loop running from the crossing to the
    crossing with the bits before and after it trimmed, or None.  The trimmed bits each run
    at most ``bound`` mm along the chain; the crossing is exact on both pieces' carriers
    (:func:`~aidl_lang.geometry.shapes.curves.crossings`)."""
    if bound <= 0 or len(segs) < 2 or math.dist(segs[0].start, segs[-1].end) > 2 * bound:
        return None
    heads, run = [], 0.0            # the pieces whose start lies within bound of the start
    for i, sg in enumerate(segs):
        if run > bound:
            break
        heads.append((i, run))
        run += _piece_length(sg)
    tails, run = [], 0.0
    for j in range(len(segs) - 1, -1, -1):
        if run > bound:
            break
        tails.append((j, run))
        run += _piece_length(segs[j])
    best = None
    for i, before in heads:
        for j, after in tails:
            if j <= i:
                continue
            for x, sa, sb in _splits(segs[i], segs[j]):
                cut_head = before + _piece_length(sa[0])
                cut_tail = after + _piece_length(sb[1])
                if cut_head > bound or cut_tail > bound or _piece_length(sa[1]) <= JOIN_TOL \
                        or _piece_length(sb[0]) <= JOIN_TOL:
                    continue
                if best is None or cut_head + cut_tail < best[0]:
                    loop = [sa[1]] + segs[i + 1:j] + [sb[0]]
                    if j == i + 1 and len(loop) == 2 and _piece_length(loop[0]) + \
                            _piece_length(loop[1]) <= 4 * JOIN_TOL:
                        continue
                    best = (cut_head + cut_tail, loop, cut_tail, x)
    if best is None:
        return None
    return best[1], best[2], best[3]


def _box_of(s) -> tuple:
    """A box ``(x0, y0, x1, y1)`` that holds segment ``s``: exact for a line, an arc or an
    ellipse's arc; a curve piece's control points' (its hull holds it): the box only tells
    which pieces may meet, and the control points are read where the exact box solves
    each span's derivative for its roots (RoyalGame: 21,398 boxes, 7.7 of 28 s)."""
    if isinstance(s, Line):
        return (min(s.start[0], s.end[0]), min(s.start[1], s.end[1]),
                max(s.start[0], s.end[0]), max(s.start[1], s.end[1]))
    if isinstance(s, Spline) and s.spans:
        xs = [p[0] for b in s.spans for p in b]
        ys = [p[1] for b in s.spans for p in b]
        return (min(xs), min(ys), max(xs), max(ys))
    return _segs_box([s])


def _is_corner_loop(s) -> bool:
    """Whether segment ``s`` is a loop of its own (a curve that ends where it starts:
    Boxes.py's kerf-corrected inner corner, :func:`_corner_loops`)."""
    return not isinstance(s, Circle) and math.dist(s.start, s.end) <= 1e-9 and \
        _piece_length(s) > 0


def _trim_small_loops(segs: list, bound: float, closed: bool) -> tuple[list, int]:
    """``segs`` (a chain; ``closed``: a loop) without the small loops it makes where it
    crosses itself and comes back within ``bound`` mm along itself: the pieces between the
    crossing and its return are cut out, the two crossing pieces cut at the crossing on
    their own carriers (exact).  A laser cuts such a loop off as a crumb, so the part's edge
    is the chain without it: Boxes.py draws one at each inner corner with its default
    ``inner_corners="loop"`` and a burn (kerf) correction, and its D-bores' flat crosses
    their arc so.  Returns the chain and the number of loops cut out."""
    n_cut = 0
    out = list(segs)
    i = 0
    while i < len(out) - 2:
        a = out[i]
        ba = _box_of(a)
        run = 0.0
        hit = None
        for j in range(i + 2, len(out) - (1 if closed and i == 0 else 0)):
            run += _piece_length(out[j - 1])
            if run > bound:
                break
            b = out[j]
            bb = _box_of(b)
            if bb[0] > ba[2] + 1e-9 or ba[0] > bb[2] + 1e-9 or bb[1] > ba[3] + 1e-9 or \
                    ba[1] > bb[3] + 1e-9:
                continue
            for x, sa, sb in _splits(a, b):
                if _piece_length(sa[0]) <= JOIN_TOL or _piece_length(sb[1]) <= JOIN_TOL:
                    continue
                if _piece_length(sa[1]) <= JOIN_TOL and _piece_length(sb[0]) <= JOIN_TOL \
                        and all(_is_corner_loop(q) for q in out[i + 1:j]):
                    continue        # corner loops at the joint: cut by _corner_loops
                if run + _piece_length(sa[1]) + _piece_length(sb[0]) <= bound:
                    hit = (j, sa[0], sb[1])
                    break
            if hit is not None:
                break
        if hit is None:
            i += 1
            continue
        j, head, tail = hit
        out = out[:i] + [head, tail] + out[j + 1:]
        n_cut += 1
    return out, n_cut


MAX_LOBES = 64           # a loop that crosses itself is split into at most this many loops
CROSSING_NEAR = 0.1      # mm: an exact crossing this near the chords' is the one they found
LOBE_MIN = 1e-3          # mm: a loop split off shorter than this is no loop (a touch)


def _split_crossing(segs: list, hit, boxes=None) -> tuple[list, list] | None:
    """The closed loop ``segs`` split at its crossing near ``hit`` (a point :func:`_crossing`
    found on the chords) into the two loops that meet there, ``(from the crossing round to
    it on the first piece's side, the rest)``: the two crossing pieces cut at the exact
    crossing of their carriers (:func:`~aidl_lang.geometry.shapes.curves.crossings`), so every piece
    drawn is kept, end to end, in one loop or the other.  None when no exact crossing of two
    pieces lies within :data:`CROSSING_NEAR` of ``hit`` (with a loop longer than
    :data:`LOBE_MIN` on each side)."""
    r = CROSSING_NEAR
    boxes = boxes or [_box_of(sg) for sg in segs]
    near = [i for i, b in enumerate(boxes)
            if b[0] - r <= hit[0] <= b[2] + r and b[1] - r <= hit[1] <= b[3] + r]
    best = None
    for ii, i in enumerate(near):
        for j in near[ii + 1:]:
            for x, sa, sb in _splits(segs[i], segs[j]):
                d = math.dist(x, hit)
                if d > r or (best is not None and d >= best[0]):
                    continue
                first = [sa[1]] + segs[i + 1:j] + [sb[0]]
                rest = [sb[1]] + segs[j + 1:] + segs[:i] + [sa[0]]
                first = [q for q in first if _piece_length(q) > JOIN_TOL]
                rest = [q for q in rest if _piece_length(q) > JOIN_TOL]
                if sum(map(_piece_length, first)) > LOBE_MIN and \
                        sum(map(_piece_length, rest)) > LOBE_MIN:
                    best = (d, first, rest)
    return None if best is None else (best[1], best[2])


def _lobes(segs: list) -> list | None:
    """The loops a closed loop that crosses itself is made of, each crossing none: split at
    its crossings one by one (:func:`_split_crossing`), every piece kept.  A laser cuts
    along every line, so each loop is a piece of the sheet (a part, a hole in one, or a crumb
    where the line crosses itself).  None when a crossing cannot be placed exactly or the loop
    makes more than :data:`MAX_LOBES` loops."""
    out, todo = [], [list(segs)]
    while todo:
        cur = todo.pop()
        hit = _crossing(cur)
        if hit is None:
            out.append(cur)
            continue
        if len(out) + len(todo) + 2 > MAX_LOBES:
            return None
        boxes = [_box_of(sg) for sg in cur]
        two = _split_crossing(cur, hit, boxes)
        if two is not None:
            todo += [two[0], two[1]]
            continue
        flat = _unloop(cur, hit)         # (its own exact boxes: it takes the first curve)
        if flat is None:
            # no exact crossing there: only the chords cross, the curves a hair apart - the
            # loop stays whole (engraved); passing over such crossings made Lamp's exact
            # outline take minutes to recover (build 3.4 s -> over 190 s)
            return None
        todo.append(flat)
    return out


def _pinches(segs: list) -> list:
    """The closed loop ``segs`` split at each point it passes through twice (a vertex where
    one piece starts and, further round, another starts again within :data:`JOIN_TOL`): the
    loops that touch there, every piece kept in one of them, in the order drawn.  Boxes.py's
    burn-corrected acute corner comes into the corner, runs out 0.1 mm along the rounding and
    back to the corner, then leaves it: the outline and a crumb pinched off at the corner."""
    out, todo = [], [list(segs)]
    while todo:
        cur = todo.pop()
        seen: dict = {}
        found = None
        for k, sg in enumerate(cur):
            key = (round(sg.start[0] / JOIN_TOL), round(sg.start[1] / JOIN_TOL))
            i = seen.get(key)
            if i is not None and k - i > 1 and not (i == 0 and k == len(cur) - 1):
                found = (i, k)
                break
            seen.setdefault(key, k)
        if found is None:
            out.append(cur)
            continue
        i, k = found
        todo += [cur[k:] + cur[:i], cur[i:k]]
    return out


CRUMB_MAX = OVERSHOOT    # mm: a loop pinched off no longer than this is a crumb


def _pinched_lobes(segs: list) -> tuple[list, list] | None:
    """The loops of the closed loop ``segs`` that crosses itself where it is split at the
    points it passes through twice (:func:`_pinches`), each split at its own crossings
    (:func:`_lobes`): ``(loops that cross nothing, crumbs)``, a crumb a loop pinched off no
    longer than :data:`CRUMB_MAX` mm whose crossings cannot be placed (a curve out and back
    a hair beside itself: the laser cuts it off, it adds nothing to the part).  None when the
    loop has no such point or a longer loop's crossing cannot be placed."""
    pieces = _pinches(segs)
    if len(pieces) < 2:
        return None
    loops: list = []
    crumbs: list = []
    for q in pieces:
        if _crossing(q) is None:
            loops.append(q)
            continue
        lobes = _lobes(_trim_small_loops(q, OVERSHOOT, True)[0])
        if lobes is not None:
            loops += lobes
        elif sum(map(_piece_length, q)) <= CRUMB_MAX:
            crumbs.append(q)
        else:
            return None
    return loops, crumbs


def _unloop(segs: list, hit, boxes=None) -> list | None:
    """``segs`` with the curve piece near ``hit`` that loops round on itself and ends within
    :data:`OVERSHOOT` of its start (a cubic that crosses itself: Boxes.py's corner loops,
    rounded so their ends miss by 0.001 mm) replaced by the line from its start to its end
    (the crumb the laser cuts off there), or None when there is none."""
    r = CROSSING_NEAR
    boxes = boxes or [_segs_box([sg]) for sg in segs]
    for k, (sg, b) in enumerate(zip(segs, boxes)):
        if not isinstance(sg, Spline) or not (b[0] - r <= hit[0] <= b[2] + r and
                                              b[1] - r <= hit[1] <= b[3] + r):
            continue
        gap = math.dist(sg.start, sg.end)
        if gap <= OVERSHOOT and _piece_length(sg) > 3 * gap:
            rest = segs[:k] + ([Line(sg.start, sg.end)] if gap > JOIN_TOL else []) + \
                segs[k + 1:]
            return rest if len(rest) >= 2 else None
    return None


DEGENERATE_ABS = JOIN_TOL    # mm: a piece all of whose points lie this close to its start
DEGENERATE_REL = 1e-8       # ... or this share of the drawing's largest coordinate is dropped


def degenerate_tol(pieces, loops, circles, ellipses) -> float:
    """The size (mm) at or below which a piece of the drawing is one point and is dropped
    (:func:`_drop_degenerate`): ``max(DEGENERATE_ABS, DEGENERATE_REL * c)``, ``c`` the largest
    absolute coordinate of the pieces' ends, circles' and ellipses' centres.  The compiler
    calls two points one when they are within ``1e-9 * max(1 mm, the largest coordinate of
    the statement)`` (``Bezier`` and ``Spline``: E0108 "is one point",
    :func:`aidl_lang.geometry.shapes.spline.check_points`), so a piece kept here stays ten times
    past what it refuses, after the writer's shortest-decimal rounding (1e-12 mm); and
    :data:`JOIN_TOL` is where two ends are one point for the chaining."""
    c = 0.0
    for segs in list(pieces) + [segs for segs, _src in loops]:
        for s in segs:
            for p in (s.start, s.end):
                c = max(c, abs(p[0]), abs(p[1]))
    for x in circles:
        c = max(c, abs(x.center[0]), abs(x.center[1]))
    for e in ellipses:
        c = max(c, abs(e[0]), abs(e[1]))
    return max(DEGENERATE_ABS, DEGENERATE_REL * c)


def _reach(s) -> float:
    """An upper bound (mm) of how far segment ``s`` gets from its start."""
    if isinstance(s, Line):
        return math.dist(s.start, s.end)
    if isinstance(s, Arc):
        return s.radius * min(2.0, abs(s.sweep))
    if isinstance(s, Circle):
        return 2 * s.radius
    b = s.box()                                  # Spline, EllipticArc: the exact box
    return math.hypot(b[2] - b[0], b[3] - b[1])


def _span_reach(b) -> float:
    return max(math.dist(b[0], q) for q in b[1:])


def _drop_in(segs: list, tol: float, dropped: dict) -> list:
    """``segs`` without the pieces that are one point (within ``tol``), each counted in
    ``dropped`` by kind; a spline piece loses only its spans that are one point (the next span
    starts where the previous ends: the Bezier chain the writer writes shares them)."""
    out = []
    for s in segs:
        if isinstance(s, Spline):
            spans = s.spans
            keep = [i for i, b in enumerate(spans) if _span_reach(b) > tol]
            if len(keep) < len(spans):
                dropped["Bézier piece"] = dropped.get("Bézier piece", 0) + len(spans) - len(keep)
                if not keep:
                    continue
                from ...geometry.shapes.curves import _span_steps
                h = _span_steps(s)
                kept = [list(spans[i]) for i in keep]
                for j in range(1, len(kept)):        # each span starts where the last ended
                    kept[j][0] = kept[j - 1][3]
                s = bezier_spline(kept, [h[i] for i in keep] if len(h) == len(spans) else None)
            out.append(s)
        elif _reach(s) <= tol:
            kind = {Line: "line", Arc: "arc", EllipticArc: "elliptical arc",
                    Circle: "circle"}.get(type(s), "piece")
            dropped[kind] = dropped.get(kind, 0) + 1
        else:
            out.append(s)
    return out


def _corner_loops(segs: list) -> tuple[list, int]:
    """``segs`` (a counter-clockwise loop) with each segment that is a loop of its own (a
    curve that ends where it starts: Boxes.py's kerf-corrected inner corner, a cubic of
    0.14 mm round from the corner into the material and back) run so that what it encloses is
    cut out as a laser cuts it: clockwise inside the loop (else its inside counts twice and
    fills, and its cut is lost), counter-clockwise outside it.  Returns them and how many
    were turned round."""
    import numpy as np

    from ...geometry.shapes.curves import reverse, sample_xy
    from ...geometry.shapes.drawing2d import _inside
    at = [i for i, s in enumerate(segs) if _is_corner_loop(s)]
    if not at or len(at) == len(segs):
        return segs, 0
    xs: list = []
    ys: list = []
    sample_xy([s for i, s in enumerate(segs) if i not in set(at)], xs, ys)
    P = np.column_stack([xs, ys])
    out, turned = list(segs), 0
    for i in at:
        lx: list = []
        ly: list = []
        sample_xy([segs[i]], lx, ly)
        a = Loop([segs[i]]).area
        if len(lx) < 3 or a == 0.0:
            continue
        cx = sum(lx) / len(lx)                   # a point of what the loop encloses
        cy = sum(ly) / len(ly)
        if (a > 0) == _inside((cx, cy), P):
            out[i] = reverse(segs[i])
            turned += 1
    return out, turned


SPIKE_TOL = 0.005        # mm: a curve out to a cusp and back this near itself is cut once


def _beside(s, other, tol: float) -> bool:
    """Whether every point of segment ``s`` (its chord ends) lies within ``tol`` of
    ``other``'s carrier."""
    from ...geometry.shapes.curves import carrier, distance_to, sample_xy
    xs: list = []
    ys: list = []
    sample_xy([s], xs, ys)
    c = carrier(other)
    return all(distance_to(c, p) <= tol for p in list(zip(xs, ys)) + [s.end])


def _cusp_spikes(segs: list) -> tuple[list, int]:
    """The closed loop ``segs`` without its spikes: a piece that runs out to a cusp (the
    loop turns round there) and the next one that comes back beside it within
    :data:`SPIKE_TOL` (Boxes.py's acute corner with a burn correction: a curve out along
    the corner's rounding and back 0.0005 mm beside it, which its chords see as a crossing).
    A laser cuts the spike once and it adds nothing to the part: the shorter piece is left
    out, the longer one cut at the foot of the shorter one's far end (on its own carrier)
    and a line bridges the hair between them.  Returns the loop and how many spikes."""
    from ...geometry.shapes.curves import carrier, foot, tangent_at
    out, n_cut, i = list(segs), 0, 0
    while i < len(out) and len(out) > 3:
        a, b = out[i], out[(i + 1) % len(out)]
        ta, tb = tangent_at(a, True), tangent_at(b, False)
        if isinstance(a, Circle) or isinstance(b, Circle) or \
                ta[0] * tb[0] + ta[1] * tb[1] > -0.999:
            i += 1
            continue
        short_first = _piece_length(a) <= _piece_length(b)
        sh, lg = (a, b) if short_first else (b, a)
        tip = sh.start if short_first else sh.end          # the short piece's far end
        at = foot(carrier(lg), tip)
        cut = _split_at(lg, at)
        if cut is None or math.dist(tip, at) > SPIKE_TOL or not _beside(sh, lg, SPIKE_TOL):
            i += 1
            continue
        keep = cut[1] if short_first else cut[0]
        if _piece_length(keep) <= JOIN_TOL:                # out and back, end to end
            i += 1
            continue
        bridge = [Line(tip, at)] if math.dist(tip, at) > JOIN_TOL else []
        if bridge and not short_first:
            bridge = [Line(at, tip)]
        new = bridge + [keep] if short_first else [keep] + bridge
        if i + 1 < len(out):
            out[i:i + 2] = new
        else:                                              # the pair wraps round
            out = new[1:] + out[1:i] + new[:1] if not short_first else \
                new + out[1:i]
        n_cut += 1
        i = max(0, i - 1)
    return out, n_cut


CUSP_TURN = -0.99        # cos of the turn at a piece's end past which the next comes back


def _cusp_spline_crossings(a: Spline, b: Spline) -> list:
    """The points where curve pieces ``a`` and ``b`` cross beside the cusp where ``a`` ends
    and ``b`` starts: each sampled from the cusp at 1e-12 to the whole of its parameter
    range, doubling, the two polylines' crossings (but at the cusp) polished by 2-D Newton
    on the curves.  The general crossing search halves the two pieces' boxes down to 1e-3
    mm all along where they run within 1e-3 mm of each other from the cusp (hundreds of box
    pairs, each polished: 0.1 s a cusp); this is about 40 points a piece."""
    import numpy as np
    from ...geometry.shapes.spline import newton2
    F = [0.0] + [2.0 ** -k for k in range(40, -1, -1)]
    ua = [a.u1 + (a.u0 - a.u1) * f for f in F]           # from the cusp back along a
    vb = [b.u0 + (b.u1 - b.u0) * f for f in F]           # from the cusp on along b
    PA = np.array([a.curve.at(u) for u in ua])
    PB = np.array([b.curve.at(v) for v in vb])
    p, r = PA[:-1, None, :], PA[1:, None, :] - PA[:-1, None, :]
    q, w = PB[None, :-1, :], PB[None, 1:, :] - PB[None, :-1, :]
    den = r[..., 0] * w[..., 1] - r[..., 1] * w[..., 0]
    d = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (d[..., 0] * w[..., 1] - d[..., 1] * w[..., 0]) / den
        s = (d[..., 0] * r[..., 1] - d[..., 1] * r[..., 0]) / den
    hit = (den != 0) & (t >= 0) & (t <= 1) & (s >= 0) & (s <= 1)
    hit[0, 0] = False                                     # the cusp itself
    lo_a, hi_a = min(a.u0, a.u1), max(a.u0, a.u1)
    lo_b, hi_b = min(b.u0, b.u1), max(b.u0, b.u1)
    out: list = []
    for i, j in zip(*np.nonzero(hit)):
        i, j = int(i), int(j)
        u = ua[i] + (ua[i + 1] - ua[i]) * float(t[i, j])
        v = vb[j] + (vb[j + 1] - vb[j]) * float(s[i, j])
        u, v = newton2(a.curve, b.curve, u, v)
        x, y = a.curve.at(u), b.curve.at(v)
        if lo_a <= u <= hi_a and lo_b <= v <= hi_b and math.dist(x, y) <= 1e-9:
            out.append(x)
    return out


def _cusp_crossings(segs: list, bound: float) -> tuple[list, int]:
    """The closed loop ``segs`` without the tiny loops at its cusps: where a curve piece ends
    and the next curve piece turns back (their directions there at least as opposed as
    :data:`CUSP_TURN`) and the two cross again beside the cusp (Boxes.py's burn-corrected
    fan blade: an end cap's last cubic and the blade's edge leave the cusp 0.004 rad apart
    and cross 0.002 mm from it), both are cut at that crossing, exact on their own curves
    (:func:`_cusp_spline_crossings`, :func:`_split_at`), and the loop
    between it and the cusp (at most ``bound`` mm of line) is left out: a laser cuts it
    off as a crumb, and a closed Bézier outline (a loop of curve pieces alone: the one
    statement the compiler checks so) that loops over itself is no outline (E0108).  Of
    several such crossings the farthest from the cusp within ``bound`` is taken.  Returns
    the loop and the number of loops cut out."""
    from ...geometry.shapes.curves import tangent_at
    out, n_cut, i = list(segs), 0, 0
    while i < len(out) and len(out) > 2:
        j = (i + 1) % len(out)
        a, b = out[i], out[j]
        if not isinstance(a, Spline) or not isinstance(b, Spline):
            i += 1
            continue
        ta, tb = tangent_at(a, True), tangent_at(b, False)
        if ta[0] * tb[0] + ta[1] * tb[1] > CUSP_TURN:
            i += 1
            continue
        try:
            pts = _cusp_spline_crossings(a, b)
        except Exception:
            pts = []
        best = None
        for x in pts:
            if math.dist(x, a.end) <= JOIN_TOL:
                continue                             # the cusp itself
            sa, sb = _split_at(a, x), _split_at(b, x)
            if sa is None or sb is None or min(map(_piece_length, (sa[0], sb[1]))) <= \
                    JOIN_TOL:
                continue
            loop = _piece_length(sa[1]) + _piece_length(sb[0])
            if loop <= bound and (best is None or loop > best[0]):
                best = (loop, sa[0], sb[1])
        if best is None:
            i += 1
            continue
        out[i], out[j] = best[1], best[2]
        n_cut += 1
    return out, n_cut


def _drop_degenerate(pieces, loops, circles, ellipses, notes, name, hatch_circles=()):
    """The pieces, loops, circles and ellipses of a drawing without what is one point: a
    line, arc, Bézier span or elliptical arc all of whose points lie within
    :func:`degenerate_tol` of its start, a circle or ellipse of a radius or semi-axis within
    it (a Boxes.py ``C x,y x,y x,y``, a DXF spline's repeated knot, a LINE from a point to
    itself).  The compiler refuses some of them (``Bezier``: E0108 "is one point") and the
    others draw nothing; one ``W0130`` note counts them by kind."""
    tol = degenerate_tol(pieces, loops, list(circles) + list(hatch_circles), ellipses)
    dropped: dict = {}
    pieces = [q for q in (_drop_in(p, tol, dropped) for p in pieces) if q]
    loops = [(q, src) for q, src in ((_drop_in(p, tol, dropped), src) for p, src in loops) if q]
    keep_c = [c for c in circles if c.radius > tol]
    keep_h = [c for c in hatch_circles if c.radius > tol]
    if len(keep_c) + len(keep_h) < len(circles) + len(hatch_circles):
        dropped["circle"] = dropped.get("circle", 0) + len(circles) + len(hatch_circles) \
            - len(keep_c) - len(keep_h)
    keep_e = [e for e in ellipses if min(e[2], e[3]) > tol]
    if len(keep_e) < len(ellipses):
        dropped["ellipse"] = len(ellipses) - len(keep_e)
    if dropped:
        n = sum(dropped.values())
        what = ", ".join(_plural(v, w) for w, v in sorted(dropped.items()))
        notes.append(Note("W0130", f"{n} piece{'s' if n != 1 else ''} of `{name}` dropped: "
                                   f"zero length, all {'its' if n == 1 else 'their'} points "
                                   f"within {tol:.3g} mm of one point ({what})",
                          "nothing is lost: they draw nothing; delete them in the drawing "
                          "program to silence this"))
    return pieces, loops, keep_c, keep_e, keep_h


def _finish(pieces, loops, circles, ellipses, notes, unit, name,
            hatch_circles: list | None = None) -> Drawing:
    """The :class:`Drawing` of the pieces read: pieces that are one point dropped
    (:func:`_drop_degenerate`; ``hatch_circles``, a DXF's, are filtered in place), duplicates
    removed, chained, gaps within the closing tolerance closed, loops sorted into outlines and
    paths."""
    opts = _OPTS.get()
    pieces, loops, circles, ellipses, kept = _drop_degenerate(
        pieces, loops, circles, ellipses, notes, name, hatch_circles or ())
    if hatch_circles:
        hatch_circles[:] = kept
    pieces, loops, dups = _dedupe(pieces, loops)
    if dups:
        notes.append(Note("W0130", f"{dups} duplicate segment{'s' if dups > 1 else ''} of "
                                   f"`{name}` removed (drawn twice, over one another)",
                          "delete the duplicates in the drawing program to silence this"))
    closed, open_ = _chain(pieces, deadline=opts.deadline)
    if open_ and opts.close_tol > 0:
        # a path whose end runs past its start, crossing it: closed at the crossing (before
        # the gaps below, which would close it across the overshoot into a loop that
        # crosses itself)
        shot, keep_open = [], []
        for segs in open_:
            o = _overshoot(segs, max(opts.close_tol, OVERSHOOT))
            if o is None:
                keep_open.append(segs)
            else:
                closed.append(o[0])
                shot.append((o[1], o[2]))
        open_ = keep_open
        if shot:
            g, at = max(shot)
            notes.append(Note("W0130", f"{len(shot)} path{'s' if len(shot) > 1 else ''} of "
                                       f"`{name}` closed where {'its' if len(shot) == 1 else 'their'} "
                                       f"end crosses {'its' if len(shot) == 1 else 'their'} start "
                                       f"(the overshoot trimmed: the largest {g:.3g} mm, at "
                                       f"({at[0]:.6g}, {at[1]:.6g}) mm)",
                              "give close_tolerance=0 (`aidl import --close-tolerance 0`) to "
                              "keep them as drawn"))
    if open_ and opts.close_tol > JOIN_TOL:
        gaps: list = []
        more, open_ = _chain(open_, opts.close_tol, gaps, opts.deadline)
        closed += more
        if gaps:
            g, at = max(gaps)
            notes.append(Note("W0130", f"{len(gaps)} gap{'s' if len(gaps) > 1 else ''} of "
                                       f"`{name}` closed (the largest {g:.3g} mm, at "
                                       f"({at[0]:.6g}, {at[1]:.6g}) mm): ends within the "
                                       f"closing tolerance of {opts.close_tol:g} mm made one "
                                       f"point", "give close_tolerance=0 (`aidl import "
                                                 "--close-tolerance 0`) to keep them open"))
    d = Drawing(circles=circles, ellipses=ellipses, notes=notes, unit=unit)
    crumbs = 0
    split: list = []                # loops that crossed themselves: the loops each made
    for segs, src in [(c, "") for c in closed] + loops:
        if len(segs) == 1 and isinstance(segs[0], Circle):
            d.circles.append(segs[0])
            continue
        hit = _crossing(segs)
        if hit is not None and opts.split_crossings:
            segs, k = _cusp_spikes(segs)         # a curve out and back beside itself
            if k:
                hit = _crossing(segs)
        if hit is not None and opts.close_tol > 0:
            # small loops where it crosses itself (a kerf-corrected inner corner) cut off
            bound = max(opts.close_tol, OVERSHOOT)
            for turn in (segs, segs[len(segs) // 2:] + segs[:len(segs) // 2]):
                # a small loop across the loop's first point (Boxes.py's key cut-outs
                # end with one) is found from a start half way round
                trimmed, k = _trim_small_loops(turn, bound, True)
                if k and _crossing(trimmed) is None:
                    segs, hit = trimmed, None
                    crumbs += k
                    break
        parts = [segs]
        if hit is not None and opts.close_tol > 0 and opts.split_crossings:
            # still crossing, on a cut role: split at its crossings into loops that cross nothing, every
            # line kept (Boxes.py's PaperBox flaps, a slot whose edges cross)
            whole = _trim_small_loops(segs, max(opts.close_tol, OVERSHOOT), True)[0]
            lobes = _lobes(whole)
            pinched = _pinched_lobes(segs) if lobes is None else None
            if pinched is not None:
                # a crumb pinched off at a corner (Boxes.py's acute corner) is cut off, as
                # the small loops above; the loops it leaves cross nothing
                parts, hit = pinched[0], None
                crumbs += len(pinched[1])
                if len(parts) > 1:
                    split.append(len(parts))
            elif lobes is not None:
                parts, hit = lobes, None
                if len(lobes) > 1 or len(lobes[0]) != len(whole) or \
                        any(p is not q for p, q in zip(lobes[0], whole)):
                    split.append(len(lobes))     # (not when only its chords cross)
        if hit is not None:          # kept as a stroke; an error where an outline is needed
            d.paths.append(Path(list(segs), "crosses itself", crossing=hit))
            continue
        for segs in parts:
            if opts.close_tol > 0 and all(isinstance(s, Spline) for s in segs):
                # written as one closed Bezier, which must not cross itself (E0108): tiny
                # loops beside its cusps cut off (the chords do not see them)
                segs, k = _cusp_crossings(segs, max(opts.close_tol, OVERSHOOT))
                crumbs += k
            o = Outline(list(segs), src)
            if len(parts) > 1 and abs(o.area) <= LOBE_MIN ** 2:
                continue        # a curve drawn out and back over itself: no area, no loop
            if o.area < 0:
                from ...geometry.shapes.curves import reverse
                o.segments = [reverse(s) for s in reversed(o.segments)]
            if opts.split_crossings:             # a cut role: corner loops cut
                o.segments = _corner_loops(o.segments)[0]
            d.outlines.append(o)
    d.outlines.sort(key=lambda o: -abs(o.area))
    if crumbs:
        notes.append(Note("W0130", f"{crumbs} small loop{'s' if crumbs > 1 else ''} of `{name}` "
                                   f"cut off where an outline crosses itself and comes back "
                                   f"within {max(opts.close_tol, OVERSHOOT):g} mm (a kerf-"
                                   f"corrected inner corner drawn as a loop): the outline "
                                   f"runs through the crossing",
                          "give close_tolerance=0 (`aidl import --close-tolerance 0`) to "
                          "keep them as drawn"))
    if split:
        notes.append(Note("W0130", f"{len(split)} loop{'s' if len(split) > 1 else ''} of "
                                   f"`{name}` cross{'es' if len(split) == 1 else ''} "
                                   f"{'itself' if len(split) == 1 else 'themselves'}: split at "
                                   f"the crossings into {sum(split)} loops that do not, every "
                                   f"line kept (a laser cuts each out: a part, a hole or a "
                                   f"crumb; a corner curve that loops round on itself is cut "
                                   f"off at its ends)", "redraw the outline without the crossing in the "
                                              "drawing program if a crumb is not meant"))
    for segs in open_:
        d.paths.append(Path(list(segs)))
    d.circles = [Circle(c.center, c.radius) for c in d.circles]
    d.circles.sort(key=lambda c: (-c.radius, c.center[0], c.center[1]))
    return d


def open_gaps(d: Drawing) -> list[tuple[float, tuple[float, float]]]:
    """``(gap in mm, where)`` of each open path (its end to its start)."""
    return [(math.dist(p.start, p.end), p.end) for p in d.paths]


CIRCULAR_TOL = 1e-7    # mm: the radii of an elliptical arc this close: a circular Arc


def circular(segs: list) -> list:
    """``segs`` with each elliptical arc whose two radii are equal (an SVG ``A`` or ``rect``
    corner) as the circular :class:`Arc` it is: the same points (its parameter is its angle
    less the rotation), the radii equal within :data:`CIRCULAR_TOL`."""
    out = []
    for g in segs:
        if isinstance(g, EllipticArc) and not g.whole and \
                abs(g.curve.rx - g.curve.ry) <= CIRCULAR_TOL:
            e = g.curve
            g = Arc(tuple(e.center), e.rx, g.start_param + e.rotation, g.sweep)
        out.append(g)
    return out
