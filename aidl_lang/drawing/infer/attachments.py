"""``aidl import --infer``: outlines no one primitive makes, read as a primitive with
attachments (issue 60; docs/import.md, "Inferring the design"; used by :class:`~.infer._Part`).

In: one closed loop of :class:`~aidl_lang.geometry.shapes.curves.Line` and
:class:`~aidl_lang.geometry.shapes.curves.Arc` pieces (mm, radians).  Out, or None:

* :func:`_attachments`: a rectangle (rounded or not) with tabs standing out of its sides:
  the rectangle's :class:`~.infer_shapes.Shape` and each tab as a closed chain (its pieces off
  the rectangle, closed by lines reaching into it) or a ``Slot`` (:func:`_tab_slot`);
* :func:`_circle_attachments`: a circle with teeth standing out of it (a gear's root circle, a
  bore and its keyway): the ``Circle`` and each tooth's polygon.

Made by construction and checked, as :func:`~.infer_shapes.recognise` (the rectangle's own
pieces, from :func:`~.infer_shapes.rrect_pieces`, must lie on the loop's, to
:data:`~.infer_shapes.EQUAL_TOL`); nothing moves.
"""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Arc, Line
from .shapes import EQUAL_TOL, Shape, _close, rrect_pieces


def _attachments(segs: list):
    """A loop that is a rectangle (rounded or not) with tabs standing out of its sides:
    ``(rectangle Shape, [closed chains])``, each chain the tab's pieces off the rectangle
    closed by lines reaching into it; or None.  The rectangle is found from four equal
    corner arcs (or, with none, the loop's longest lines), checked as every one of its own
    pieces lying on the loop's pieces."""
    arcs = [s for s in segs if isinstance(s, Arc)]
    if not any(isinstance(s, Line) for s in segs) or len(segs) > 64 or \
            not all(isinstance(s, (Line, Arc)) for s in segs):
        return None
    by_r: dict = {}
    for a in arcs:
        by_r.setdefault(round(a.radius, 6), []).append(a)
    cands = []
    for r, group in by_r.items():
        if not 4 <= len(group) <= 8:     # four corners (and a tab's arcs of their radius)
            continue
        for i in range(len(group)):
            for j in range(i + 1, len(group)):
                # two opposite corners' centres give the rectangle (axis-aligned frame)
                p, q = group[i].center, group[j].center
                if abs(p[0] - q[0]) <= EQUAL_TOL or abs(p[1] - q[1]) <= EQUAL_TOL:
                    continue
                R = group[i].radius
                cx, cy = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
                w, h = abs(p[0] - q[0]) + 2 * R, abs(p[1] - q[1]) + 2 * R
                cands.append(((cx, cy), w, h, R))
    if not cands:
        # a sharp-cornered rectangle: its sides from the loop's horizontal and vertical lines
        hs = [g for g in segs if isinstance(g, Line) and abs(g.start[1] - g.end[1]) <= EQUAL_TOL]
        vs = [g for g in segs if isinstance(g, Line) and abs(g.start[0] - g.end[0]) <= EQUAL_TOL]
        if hs and vs:
            xs = [g.start[0] for g in vs]
            ys = [g.start[1] for g in hs]
            ys_v = [p[1] for g in vs for p in (g.start, g.end)]
            x0, x1 = min(xs), max(xs)
            y0, y1 = min(ys), max(ys)
            if y1 - y0 <= EQUAL_TOL:            # one side only: the other from the verticals
                y0, y1 = min(ys + ys_v), max(ys + ys_v)
            xs_h = [p[0] for g in hs for p in (g.start, g.end)]
            if x1 - x0 <= EQUAL_TOL:
                x0, x1 = min(xs + xs_h), max(xs + xs_h)
            if x1 - x0 > EQUAL_TOL and y1 - y0 > EQUAL_TOL:
                cands.append((((x0 + x1) / 2, (y0 + y1) / 2), x1 - x0, y1 - y0, 0.0))
    for center, w, h, R in sorted(cands, key=lambda c: -c[1] * c[2]):
        got = _split_rect(segs, center, w, h, R)
        if got is not None:
            return got
    return None


def _on_piece(m, s) -> bool:
    """Piece ``m`` of the rectangle lies on piece ``s`` of the loop, or ``s`` on ``m``
    (a side of the rectangle interrupted by a tab is two shorter lines)."""
    from .shapes import _same
    if not isinstance(s, (Line, Arc)):
        return False            # a curve is never a piece of a side (its ends may be)
    if isinstance(m, Arc) or isinstance(s, Arc):
        return isinstance(m, Arc) and isinstance(s, Arc) and _same(m, s)
    ux, uy = m.end[0] - m.start[0], m.end[1] - m.start[1]
    L = math.hypot(ux, uy)
    ux, uy = ux / L, uy / L
    for p in (s.start, s.end):
        vx, vy = p[0] - m.start[0], p[1] - m.start[1]
        if abs(vx * uy - vy * ux) > EQUAL_TOL:
            return False
        t = vx * ux + vy * uy
        if t < -EQUAL_TOL or t > L + EQUAL_TOL:
            return False
    return True


def _cyclic_runs(segs, start: int, inside) -> list[list]:
    """The maximal runs of consecutive pieces of the closed loop ``segs`` whose index passes
    ``inside``, in order, read once round from ``start`` (the first piece of a run)."""
    n = len(segs)
    runs: list[list] = []
    i, seen = start, 0
    while seen < n:
        if inside(i):
            run = []
            while inside(i) and seen < n:
                run.append(segs[i])
                i = (i + 1) % n
                seen += 1
            runs.append(run)
        else:
            i = (i + 1) % n
            seen += 1
    return runs


def _split_rect(segs, center, w, h, R):
    made = rrect_pieces(center, w, h, 0.0, [R] * 4)
    # the rectangle's arcs must be the loop's; its lines covered (in part) by the loop's
    rest = []
    for s in segs:
        if not any(_on_piece(m, s) for m in made):
            rest.append(s)
    if not rest or len(rest) == len(segs):
        return None
    for m in made:
        if isinstance(m, Arc) and not any(isinstance(s, Arc) and _on_piece(m, s) for s in segs):
            return None
    # the pieces off the rectangle, in the loop's order, as runs between two side points
    n = len(segs)
    idx = {i for i, s in enumerate(segs) if s in rest}
    start = next((i for i in range(n) if i in idx and (i - 1) % n not in idx), None)
    if start is None:
        return None
    runs = _cyclic_runs(segs, start, lambda i: i in idx)
    hw, hh = w / 2, h / 2
    x0, x1, y0, y1 = center[0] - hw, center[0] + hw, center[1] - hh, center[1] + hh
    depth = min(w, h) / 4
    chains = []
    for run in runs:
        a, b = run[0].start, run[-1].end
        # both ends on one straight side: the outward normal
        side = None
        for nrm, on in (((0, 1), lambda p: abs(p[1] - y1) <= EQUAL_TOL),
                        ((0, -1), lambda p: abs(p[1] - y0) <= EQUAL_TOL),
                        ((1, 0), lambda p: abs(p[0] - x1) <= EQUAL_TOL),
                        ((-1, 0), lambda p: abs(p[0] - x0) <= EQUAL_TOL)):
            if on(a) and on(b):
                side = nrm
        if side is None:
            return None
        # the run must stand out of the rectangle (its pieces' middles outside)
        for s in run:
            mid = s.at(s.start_angle + s.sweep / 2) if isinstance(s, Arc) else \
                ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2)
            if x0 + EQUAL_TOL < mid[0] < x1 - EQUAL_TOL and \
                    y0 + EQUAL_TOL < mid[1] < y1 - EQUAL_TOL:
                return None
        # the ends within the side's straight part, clear of the corner arcs
        along = 0 if side[1] else 1
        lo = (x0 if along == 0 else y0) + R
        hi = (x1 if along == 0 else y1) - R
        if not all(lo - EQUAL_TOL <= p[along] <= hi + EQUAL_TOL for p in (a, b)):
            return None
        slot = _tab_slot(run, side, min(w, h))
        if slot is not None:
            chains.append(slot)
            continue
        a2 = (a[0] - side[0] * depth, a[1] - side[1] * depth)
        b2 = (b[0] - side[0] * depth, b[1] - side[1] * depth)
        chain = list(run)
        # close inside the rectangle: b -> b2 -> a2 -> a, merged with a collinear end line
        tail = [Line(b, b2), Line(b2, a2), Line(a2, a)]
        if isinstance(chain[-1], Line) and _collinear(chain[-1], tail[0]):
            tail[0] = Line(chain[-1].start, b2)
            chain.pop()
        if isinstance(chain[0], Line) and _collinear(chain[0], tail[-1]) and chain:
            tail[-1] = Line(a2, chain[0].end)
            chain.pop(0)
            chain = chain + tail[:-1]
            chain = [tail[-1]] + chain
        else:
            chain = chain + tail
        chains.append(chain)
    if abs(R) <= EQUAL_TOL:
        rect = Shape("Rectangle", center, {"width": w, "height": h}, ("Rectangle", w, h), 0)
    else:
        rect = Shape("RoundedRectangle", center, {"width": w, "height": h, "corner_radius": R},
                     ("RoundedRectangle", w, h, R), 0)
    rect.pieces = len(segs) - len(rest)
    return rect, chains


def _tab_slot(run: list, side, room: float):
    """A tab that is a line, a half circle and a line back (a rounded tab): the ``Slot`` from
    the half circle's centre into the rectangle, its inner end a radius deep, or None."""
    if len(run) != 3 or not isinstance(run[1], Arc) or not isinstance(run[0], Line) or \
            not isinstance(run[2], Line):
        return None
    arc = run[1]
    r = arc.radius
    if abs(abs(arc.sweep) - math.pi) > 1e-9 or 3 * r >= room:
        return None
    a = run[0].start
    # how far the arc's centre stands out of the side
    out = (arc.center[0] - a[0]) * side[0] + (arc.center[1] - a[1]) * side[1]
    if out <= EQUAL_TOL:
        return None
    end = (arc.center[0] - side[0] * (out + r), arc.center[1] - side[1] * (out + r))
    from .shapes import _as_slot
    made = _as_slot([run[1], Line(run[2].start, (run[2].end[0] - side[0] * r,
                                                 run[2].end[1] - side[1] * r)),
                     Arc(end, r, arc.start_angle + math.pi, arc.sweep),
                     Line((run[0].start[0] - side[0] * r, run[0].start[1] - side[1] * r),
                          run[0].end)])
    return made


def _circle_attachments(segs: list):
    """A loop that is a circle with teeth standing out of it (a gear's root circle and its
    teeth, a bore and its keyway): ``(Circle Shape, [tooth vertices])``, each tooth the
    polygon of a run of lines off the circle, its first and last lines carried on into the
    circle so that their crossing with it stays where it was; or None."""
    arcs = [s for s in segs if isinstance(s, Arc)]
    if not arcs or not any(isinstance(s, Line) for s in segs):
        return None
    groups: dict = {}
    for a in arcs:
        key = (round(a.center[0], 6), round(a.center[1], 6), round(a.radius, 6))
        groups.setdefault(key, []).append(a)
    base = max(groups.values(), key=lambda g: sum(abs(a.sweep) for a in g))
    C, R = base[0].center, base[0].radius

    def on_base(s) -> bool:
        return isinstance(s, Arc) and _close(s.center, C) and abs(s.radius - R) <= EQUAL_TOL
    n = len(segs)
    if not any(on_base(s) for s in segs) or all(on_base(s) for s in segs):
        return None
    start = next(i for i in range(n) if on_base(segs[i - 1]) and not on_base(segs[i]))
    runs = _cyclic_runs(segs, start, lambda i: not on_base(segs[i]))
    teeth = []
    for run in runs:
        if not all(isinstance(s, Line) for s in run):
            return None
        a, b = run[0].start, run[-1].end
        if abs(math.dist(a, C) - R) > EQUAL_TOL or abs(math.dist(b, C) - R) > EQUAL_TOL:
            return None
        pts = [s.end for s in run[:-1]]
        if any(math.dist(p, C) <= R + EQUAL_TOL for p in pts):
            return None             # a notch into the circle, not a tooth
        # carry the first and last lines on into the circle, a tenth of its radius deep
        p1 = run[0].end
        q1 = run[-1].start
        ua = ((a[0] - p1[0]) / run[0].length, (a[1] - p1[1]) / run[0].length)
        ub = ((b[0] - q1[0]) / run[-1].length, (b[1] - q1[1]) / run[-1].length)
        d = 0.1 * R
        a2 = (a[0] + ua[0] * d, a[1] + ua[1] * d)
        b2 = (b[0] + ub[0] * d, b[1] + ub[1] * d)
        if math.dist(a2, C) >= R - EQUAL_TOL or math.dist(b2, C) >= R - EQUAL_TOL:
            return None
        teeth.append([a2] + pts + [b2])
    circle = Shape("Circle", C, {"radius": R}, ("Circle", R), 0)
    circle.pieces = n
    return circle, teeth


def _collinear(p: Line, q: Line) -> bool:
    ux, uy = p.end[0] - p.start[0], p.end[1] - p.start[1]
    vx, vy = q.end[0] - q.start[0], q.end[1] - q.start[1]
    lu, lv = math.hypot(ux, uy), math.hypot(vx, vy)
    if lu <= EQUAL_TOL or lv <= EQUAL_TOL:
        return False
    return abs(ux * vy - uy * vx) / lu <= EQUAL_TOL and ux * vx + uy * vy > 0



def _notches(segs: list):
    """A loop of axis-aligned lines that is a rectangle with equal rectangular notches cut
    into one side (a cable comb's slots): ``(rectangle Shape, side, [notch centres along
    the side, sorted], notch width along the side, depth)``, ``side`` one of ``"top"``,
    ``"bottom"``, ``"left"``, ``"right"``; or None.  Checked: every piece off the rectangle
    is one of the notches' three sides, the notches equal (EQUAL_TOL), and the loop's area
    the rectangle's less the notches'."""
    if len(segs) < 12 or len(segs) > 4096 or not all(isinstance(s, Line) for s in segs):
        return None
    pts = [s.start for s in segs]
    x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
    y0, y1 = min(p[1] for p in pts), max(p[1] for p in pts)
    sides = {"left": (0, x0), "right": (0, x1), "bottom": (1, y0), "top": (1, y1)}

    def side_of(p):
        return {k for k, (ax, v) in sides.items() if abs(p[ax] - v) <= EQUAL_TOL}

    def on_boundary(s):
        return bool(side_of(s.start) & side_of(s.end))
    n = len(segs)
    start = next((i for i in range(n) if on_boundary(segs[i])), None)
    if start is None:
        return None
    runs, cur = [], []
    for k in range(1, n + 1):
        s = segs[(start + k) % n]
        if on_boundary(s):
            if cur:
                runs.append(cur)
                cur = []
        else:
            cur.append(s)
    notches = []
    for run in runs:
        if len(run) != 3:
            return None
        a, b, c = run[0].start, run[1].start, run[2].start
        d = run[2].end
        common = side_of(a) & side_of(d)
        if len(common) != 1:
            return None
        side = common.pop()
        ax, v = sides[side]
        along = 1 - ax
        depth = abs(b[ax] - v)
        if abs(abs(c[ax] - v) - depth) > EQUAL_TOL or abs(b[along] - a[along]) > EQUAL_TOL \
                or abs(d[along] - c[along]) > EQUAL_TOL or depth <= EQUAL_TOL:
            return None
        lo, hi = sorted((a[along], d[along]))
        notches.append((side, (lo + hi) / 2, hi - lo, depth))
    if len(notches) < 2 or len({t[0] for t in notches}) != 1:
        return None
    w, dep = notches[0][2], notches[0][3]
    if any(abs(t[2] - w) > EQUAL_TOL or abs(t[3] - dep) > EQUAL_TOL for t in notches):
        return None
    W, H = x1 - x0, y1 - y0
    area = 0.5 * abs(sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(pts, pts[1:] + pts[:1])))
    if abs(area - (W * H - len(notches) * w * dep)) > 1e-9 * max(W * H, 1.0):
        return None
    rect = Shape("Rectangle", ((x0 + x1) / 2, (y0 + y1) / 2),
                 {"width": W, "height": H, "rotation": 0.0}, ("Rectangle", W, H, 0.0), 4)
    return rect, notches[0][0], sorted(t[1] for t in notches), w, dep
