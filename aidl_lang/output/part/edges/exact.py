"""Provenance: the booleans run on polygons, their result is put back on the exact curves.

Every face a renderer hands to Manifold is an exact :class:`~aidl_lang.geometry.shapes.curves.Loop`
(lines, arcs, circles).  :meth:`Provenance.section` tessellates it — every segment end is a
polygon vertex, every arc is cut into chords within
:data:`~aidl_lang.geometry.shapes.tessellate.CHORD_TOL` — and records, for each chord, the *carrier*
it came from (the segment's infinite line or full circle) and, for each segment end, the exact
point.  A boolean's result polygon (Manifold keeps edges on their input edges: every result
edge is a piece of one input chord, every result vertex an input vertex or the crossing of two
chords, to its 1e-8 mm grid) is then rebuilt by :meth:`Provenance.recover`:

1. each result edge is matched to the input chord that contains it (a uniform grid over the
   chords, so a part costs O(n) for n edges: :mod:`.matching`), which names its carrier;
2. consecutive edges on one carrier form a *run*: one :class:`Line` or one :class:`Arc`
   (a loop that is one circle's run is a :class:`Circle`);
3. each vertex between two runs becomes exact: the input segment end it stands for, when it
   lies on both carriers, else the carriers' exact intersection nearest to it
   (:func:`~aidl_lang.geometry.shapes.curves.intersect`: line-line, line-circle, circle-circle;
   touching carriers give their touching point, so a tangent join stays tangent);
4. a run whose exact ends come out in the wrong order or closer than
   :data:`~aidl_lang.geometry.shapes.curves.EPS` (an overlap thinner than the chords can show) is
   dropped and its neighbours joined at their own intersection; a loop left with fewer than
   two runs closes on nothing in exact geometry (a sliver where two curves touch, cut by
   their chords) and is left out.

So every vertex of an output loop lies on the curves that meet there to floating-point
accuracy, independent of the tessellation.  An edge no chord explains (none is known today)
stays a straight :class:`Line` between its polygon vertices; :attr:`Provenance.unmatched`
counts them.
"""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ....geometry.shapes.curves import (Arc, Circle, EllipticArc, Line, Loop, Spline, carrier,
                               distance_to, ellipse_chords, ellipse_xy, foot, intersect,
                               same_carrier, simplify, spline_chords, spline_xy, tolerance)
from ....geometry.shapes.tessellate import CHORD_TOL, segments_for
from ....base.limits import OutOfBudget

from .matching import _Grid

MATCH_TOL = 1e-6       # mm: a result vertex lies this close to its input chord (grid 1e-8)
SNAP_TOL = 1e-6        # mm: a result vertex this close to an input segment end is that end
POLYGONS_PER_CHECK = 256      # polygons recovered between two looks at the deadline (~25 ms)
WHOLE_PER_BLOCK = 4096        # whole-circle polygons of one size measured at once
CARRIER_DIGITS = 6            # decimals (mm) a result circle is looked up by (_tessellated)


class Provenance:
    """The exact curves behind every polygon handed to Manifold, and the way back.

    ``carriers[k]`` is a carrier tuple (``("L", px, py, ux, uy)`` or ``("C", cx, cy, r)``,
    mm); each chord of a tessellated face is stored with its carrier's index; ``ends`` are the
    exact segment ends (mm), each with the carriers of the two segments that meet there."""

    def __init__(self, max_vertices: int | None = None):
        self.carriers: list[tuple] = []
        self.max_vertices = max_vertices      # the budget's ``vertices`` (None: no limit)
        self.vertices = 0                     # tessellated so far
        self._key: dict = {}
        # chord starts (x, y), ends and carrier index, a piece per polygon: an end of None is
        # the polygon's next vertex (its starts turned by one), a carrier index of an int is
        # every chord's (one circle): made in one array for all polygons when the chords are
        # indexed (_chords), not two arrays per hole kept meanwhile (50,000 holes: 100,000)
        self._a: list = []
        self._b: list = []
        self._c: list = []
        self._ends: list = []         # (x, y, carrier before, carrier after)
        self._eg = None               # their grid (_ends_grid), with how many it holds
        self._index = None
        self._partial = None          # (circles left out, their grid): _grid_without
        self._circles = None          # (carriers, the circles' index): _circle_index
        self.unmatched = 0

    # ------------------------------------------------------------ forward: faces
    def carrier_id(self, c: tuple) -> int:
        """The index of carrier ``c``, registered on first use (equal carriers share one)."""
        if c[0] == "C":
            key = ("C", round(c[1], 9), round(c[2], 9), round(c[3], 9))
        elif c[0] == "S":
            key = c
        elif c[0] == "E":
            e = c[1]
            key = ("E", round(e.center[0], 9), round(e.center[1], 9), round(e.rx, 9),
                   round(e.ry, 9), round(e.rotation, 12))
        else:
            _, px, py, ux, uy = c
            if ux < 0 or (ux == 0 and uy < 0):
                ux, uy = -ux, -uy
            key = ("L", round(ux, 12), round(uy, 12), round(ux * py - uy * px, 9))
        k = self._key.get(key)
        if k is None:
            k = self._key[key] = len(self.carriers)
            self.carriers.append(c)
        return k

    def polygon(self, loop: Loop) -> np.ndarray:
        """The tessellated polygon (N x 2, closed implicitly) of an exact ``loop``, its
        chords and segment ends recorded."""
        segs = loop.segments
        if len(segs) == 1 and isinstance(segs[0], Circle):
            return self._circle(segs[0])
        xs: list = []
        ys: list = []
        ids: list = []
        # the vertices of each segment (an arc's chords), all counted before anything is made
        chords = [1 if isinstance(s, Line) else
                  spline_chords(s) if isinstance(s, Spline) else
                  ellipse_chords(s) if isinstance(s, EllipticArc) else
                  segments_for(s.radius) if isinstance(s, Circle) else
                  max(1, segments_for(s.radius, abs(s.sweep))) for s in segs]
        if self.max_vertices is not None:
            self.vertices += sum(chords)
            if self.vertices > self.max_vertices:
                raise OutOfBudget(f"outlines of more than {self.max_vertices:,} vertices "
                                  "(circles and arcs in chords of 0.005 mm)", "the booleans")
        seg_ids = [self.carrier_id(carrier(s)) for s in segs]
        ends = len(segs) > 1              # each segment's exact start, where two meet
        before = seg_ids[-1] if segs else -1
        for s, k, n in zip(segs, seg_ids, chords):
            if ends:
                x, y = s.start
                self._ends.append((float(x), float(y), before, k))
                before = k
            if isinstance(s, Line):
                xs.append(float(s.start[0]))
                ys.append(float(s.start[1]))
                ids.append(k)
                continue
            if isinstance(s, Spline):
                at = len(xs)
                spline_xy(s, xs, ys)
                ids += [k] * (len(xs) - at)
                continue
            if isinstance(s, EllipticArc):
                pts = ellipse_xy(s)
                xs += [p[0] for p in pts]
                ys += [p[1] for p in pts]
                ids += [k] * len(pts)
                continue
            cx, cy = s.center
            r = s.radius
            if isinstance(s, Circle):
                sg = 1.0 if s.ccw else -1.0
                t = [sg * 2 * math.pi * i / n for i in range(n)]
            else:
                a0, sw = s.start_angle, s.sweep
                t = [a0 + sw * i / n for i in range(n)]
            xs += [cx + r * math.cos(a) for a in t]
            ys += [cy + r * math.sin(a) for a in t]
            ids += [k] * n
        if not xs:
            return np.zeros((0, 2))
        P = np.column_stack([np.asarray(xs, float), np.asarray(ys, float)])
        self._a.append(P)
        self._b.append(None)                # np.roll(P, -1, axis=0), made in _chords
        self._c.append(np.asarray(ids, dtype=np.int64))
        self._index = self._partial = None
        return P

    def _circle(self, c: Circle) -> np.ndarray:
        """:meth:`polygon` of a loop that is one circle: its vertices from the unit circle of
        its chord count and turn (:func:`_unit_circle`, the same floats as one ``math.cos``
        per vertex: ``cx + r * cos(t)``, each operation IEEE), its chords recorded."""
        n = segments_for(c.radius)
        if self.max_vertices is not None:
            self.vertices += n
            if self.vertices > self.max_vertices:
                raise OutOfBudget(f"outlines of more than {self.max_vertices:,} vertices "
                                  "(circles and arcs in chords of 0.005 mm)", "the booleans")
        k = self.carrier_id(carrier(c))
        cos, sin = _unit_circle(n, bool(c.ccw))
        cx, cy = c.center
        r = c.radius
        P = np.empty((n, 2))
        np.multiply(cos, r, out=P[:, 0])
        P[:, 0] += cx
        np.multiply(sin, r, out=P[:, 1])
        P[:, 1] += cy
        self._a.append(P)
        self._b.append(None)
        self._c.append(k)
        self._index = self._partial = None
        return P

    def face(self, loop: Loop, area: float | None = None) -> mf.CrossSection:
        """A Manifold ``CrossSection`` of one exact closed ``loop`` (either orientation;
        ``area``: its signed area when known)."""
        if (loop.area if area is None else area) < 0:
            loop = loop.reversed()
        P = self.polygon(loop)
        if len(P) < 3:
            return mf.CrossSection()
        return mf.CrossSection([P], mf.FillRule.NonZero)         # the array as it is

    def section(self, loops: list[Loop]) -> mf.CrossSection:
        """A Manifold ``CrossSection`` of exact ``loops`` as :meth:`loops` gives them (outer
        loops counter-clockwise, holes clockwise)."""
        polys = [P for P in (self.polygon(lp) for lp in loops) if len(P) >= 3]
        return mf.CrossSection(polys, mf.FillRule.NonZero) if polys else mf.CrossSection()

    # ------------------------------------------------------------ back: result polygons
    def loops(self, shape: mf.CrossSection) -> list[Loop]:
        """The exact loops of a boolean result (outer loops counter-clockwise, holes
        clockwise, as Manifold gives them); loops that close on nothing are left out."""
        return self.loops_of([shape])[0]

    def loops_of(self, shapes: list, deadline=None) -> list[list[Loop]]:
        """:meth:`loops` of each of ``shapes``, every edge matched in one pass.  ``deadline``
        (a :class:`~aidl_lang.base.limits.Deadline`, or None): checked every
        :data:`POLYGONS_PER_CHECK` polygons (raises :class:`~aidl_lang.base.limits.OutOfBudget`)."""
        polys = [[np.asarray(p, dtype=float).reshape(-1, 2) for p in s.to_polygons()
                  if len(p) >= 3] for s in shapes]
        flat = [P for ps in polys for P in ps]
        if not flat:
            return [[] for _ in shapes]
        A = np.concatenate(flat)
        sizes = np.array([len(P) for P in flat], dtype=np.int64)
        starts = np.cumsum(sizes) - sizes
        nxt = np.arange(1, len(A) + 1)              # each polygon's vertices turned by one
        nxt[starts + sizes - 1] = starts            # (np.roll(P, -1) of each)
        B = A.take(nxt, axis=0)
        scale = max(1.0, float(np.abs(A).max()))
        tol = MATCH_TOL + 1e-11 * scale
        whole, intact = self._tessellated(A, starts, sizes, tol)
        rest = np.ones(len(flat), dtype=bool)
        rest[list(whole)] = False
        if rest.any():
            edges = np.repeat(rest, sizes)
            cid = self._match_rest(A, B, edges, tol, intact)
            self.unmatched += int((cid[edges] < 0).sum())
            kept = np.flatnonzero(rest)
            found = self._whole_circles(A, cid, starts[kept], sizes[kept])
            whole.update({int(kept[i]): lp for i, lp in found.items()})
        out, done = [], 0
        for ps in polys:
            loops = []
            for P in ps:
                if deadline is not None and done % POLYGONS_PER_CHECK == 0:
                    deadline.check("the exact outlines")
                lp = whole.get(done)
                if lp is None:
                    at = int(starts[done])
                    lp = self.recover(P, cid[at:at + len(P)])
                done += 1
                if lp.segments:
                    loops.append(lp)
            out.append(loops)
        return out

    def _tessellated(self, A, starts, sizes, tol: float) -> tuple[dict, set]:
        """``({polygon: Loop}, carriers)``: the result polygons (``A[starts[i]:starts[i] +
        sizes[i]]``) that are a circle's tessellation as :meth:`_circle` makes it, each the
        whole :class:`Circle` its way round, and those circles' carrier indices.  A polygon
        counts when it has the circle's chord count of vertices, each within ``tol`` (mm) of
        one of the circle's own vertices and the next vertex of the polygon at the next of
        the circle's, one way round: then every edge is one of the circle's chords, the
        answer the chord grid gives (:meth:`_whole_circles`).  These are the holes no boolean
        touched, most of a perforated sheet's polygons; they are found without the grid: each
        polygon's centroid and mean radius looked up among the circle carriers by their
        values to :data:`CARRIER_DIGITS` decimals (a dict), then every vertex compared in
        array operations, the polygons of one size at a time.  Two circles with the same
        rounded values are left to the grid, which settles between them; a polygon whose
        rounding falls on the other side of a digit from its circle's, too (the grid's answer
        either way)."""
        ids, C, where = self._circle_index()
        if not ids:
            return {}, set()
        poly = np.repeat(np.arange(len(sizes)), sizes)
        M = np.add.reduceat(A, starts) / sizes[:, None]
        D = A - M.take(poly, axis=0)
        R = np.add.reduceat(np.hypot(D[:, 0], D[:, 1]), starts) / sizes
        keys = np.round(np.column_stack([M, R]), CARRIER_DIGITS).tolist()
        at = np.array([where.get(tuple(k), -1) for k in keys], dtype=np.int64)
        hit = at >= 0
        at = np.maximum(at, 0)
        counts = {r: segments_for(r) for r in set(C[at[hit], 2].tolist())}
        hit[hit] = sizes[hit] == np.array([counts[r] for r in C[at[hit], 2].tolist()],
                                          dtype=np.int64)
        out: dict = {}
        intact: set = set()
        for m in sorted(set(sizes[hit].tolist())):
            cos, sin = _unit_circle(m, True)
            rows = np.flatnonzero(hit & (sizes == m))
            for b in range(0, len(rows), WHOLE_PER_BLOCK):
                r = rows[b:b + WHOLE_PER_BLOCK]
                c = C[at[r]]
                idx = starts[r, None] + np.arange(m)
                X = A[idx, 0] - c[:, :1]
                Y = A[idx, 1] - c[:, 1:2]
                j = np.rint(np.arctan2(Y, X) * (m / (2 * math.pi))).astype(np.int64) % m
                near = ((np.abs(X - c[:, 2:] * cos[j]) <= tol)
                        & (np.abs(Y - c[:, 2:] * sin[j]) <= tol))
                step = (np.roll(j, -1, axis=1) - j) % m
                ccw = (step == 1).all(axis=1)
                ok = near.all(axis=1) & (ccw | (step == m - 1).all(axis=1))
                for i, k, turn in zip(r[ok].tolist(), at[r[ok]].tolist(), ccw[ok].tolist()):
                    cr = self.carriers[ids[k]]
                    out[i] = Loop([Circle((cr[1], cr[2]), cr[3], turn)])
                    intact.add(ids[k])
        return out, intact

    def _circle_index(self) -> tuple[list, np.ndarray, dict]:
        """``(ids, C, where)`` of the circle carriers: their carrier indices, their ``(cx,
        cy, r)`` (k x 3, mm) and ``{values to CARRIER_DIGITS decimals: row of C}`` (-1 for
        two alike); made again only when a carrier has been added since (a compile asks
        for the exact loops of every finish and offset: once per carrier, not per call)."""
        got = self._circles
        if got is not None and got[0] == len(self.carriers):
            return got[1]
        ids = [k for k, c in enumerate(self.carriers) if c[0] == "C"]
        C = np.array([self.carriers[k][1:4] for k in ids], dtype=float).reshape(-1, 3)
        where: dict = {}
        for i, key in enumerate(map(tuple, np.round(C, CARRIER_DIGITS).tolist())):
            where[key] = -1 if key in where else i          # two alike: the grid's
        self._circles = (len(self.carriers), (ids, C, where))
        return ids, C, where

    def _match_rest(self, A, B, edges, tol: float, intact: set) -> np.ndarray:
        """The carrier of each edge ``A[i] -> B[i]`` where ``edges[i]`` (-1 elsewhere, and
        where no chord holds it), as the chord grid of every piece gives it.  The pieces that
        are one of the ``intact`` circles whole are left out of the grid when it is not built
        yet (:meth:`_tessellated` found them in the result, their chords all there: a
        perforated sheet's outline is then matched against a grid of its own few chords, not
        the 2,250,000 of 50,000 holes); an edge that grid leaves unmatched (the same circle
        drawn twice, once cut) is matched again against the whole grid."""
        out = np.full(len(A), -1, dtype=np.int64)
        at = np.flatnonzero(edges)
        P, Q = A.take(at, axis=0), B.take(at, axis=0)
        grid = self._index
        if grid is None and intact:
            grid = self._grid_without(intact)
        if grid is None:
            grid = self._chords()
        cid = grid.match(P, Q, tol)
        if grid is not self._index:
            miss = np.flatnonzero(cid < 0)
            if len(miss):
                cid[miss] = self._chords().match(P.take(miss, axis=0), Q.take(miss, axis=0), tol)
        out[at] = cid
        return out

    def _grid_without(self, intact: set):
        """The chord grid of the pieces other than whole circles of ``intact`` (kept until a
        piece is added, for a later call whose intact circles include these); None when
        every piece is in it (the whole grid, :meth:`_chords`, is then the one)."""
        got = self._partial
        if got is not None and got[0] <= intact:
            return got[1]
        keep = [i for i, c in enumerate(self._c) if not (isinstance(c, int) and c in intact)]
        if len(keep) == len(self._c):
            return None
        A, B, C = _distinct_chords(*_pieces([self._a[i] for i in keep],
                                            [self._b[i] for i in keep],
                                            [self._c[i] for i in keep]))
        grid = _Grid(A, B, C)
        self._partial = (frozenset(intact), grid)
        return grid

    def _whole_circles(self, A, cid, starts, sizes) -> dict:
        """``{polygon: Loop}`` of the polygons (``A[starts[i]:starts[i] + sizes[i]]``, edges'
        carriers ``cid``) whose every edge is on one circle: :meth:`recover`'s loop of each
        (the whole :class:`Circle` the polygon's way round, or an empty loop when the edges
        turn less than a full turn about its center: part of one circle, no area), the
        polygons of one size at a time in array operations (the holes of a perforated
        sheet: one row each)."""
        carriers = self.carriers
        if not carriers:
            return {}
        lo = np.minimum.reduceat(cid, starts)
        one = (lo == np.maximum.reduceat(cid, starts)) & (lo >= 0) & (sizes >= 3)
        is_circle = np.array([c[0] == "C" for c in carriers])
        one &= is_circle[np.maximum(lo, 0)]
        out: dict = {}
        for m in sorted(set(sizes[one].tolist())):     # np.unique imports numpy.ma
            rows = np.flatnonzero(one & (sizes == m))
            for b in range(0, len(rows), WHOLE_PER_BLOCK):
                r = rows[b:b + WHOLE_PER_BLOCK]
                C = np.array([carriers[k][1:3] for k in lo[r].tolist()])
                # the same operations as _sweep_sum's, a row per polygon (a row's sum is the
                # same pairwise sum as a polygon's own array's, bit for bit)
                idx = starts[r, None] + np.arange(m + 1) % m
                X = A[idx, 0] - C[:, :1]
                Y = A[idx, 1] - C[:, 1:]
                a = np.arctan2(X[:, :-1] * Y[:, 1:] - Y[:, :-1] * X[:, 1:],
                               X[:, :-1] * X[:, 1:] + Y[:, :-1] * Y[:, 1:])
                for i, k, total in zip(r.tolist(), lo[r].tolist(), a.sum(axis=1).tolist()):
                    c = carriers[k]
                    out[i] = (Loop([Circle((c[1], c[2]), c[3], total > 0)])
                              if abs(abs(total) - 2 * math.pi) < 1e-6 else Loop([]))
        return out

    def recover(self, poly: np.ndarray, cid: np.ndarray | None = None) -> Loop:
        """The exact :class:`Loop` of one result polygon (N x 2, vertices in order, no
        repeat); ``cid``: its edges' carriers when already matched.  See the module
        docstring for the steps."""
        P = np.asarray(poly, dtype=float).reshape(-1, 2)
        n = len(P)
        if n < 3:
            return Loop([])
        scale = max(1.0, float(np.abs(P).max()))
        cid = self._match(P, scale) if cid is None else cid.copy()
        runs = _runs(cid, self.carriers, scale)
        if runs is None:                    # the whole loop on one carrier
            return self._whole(P, int(cid[0]))
        # runs: [(carrier index or -1 for an unexplained edge, first edge, last edge)]
        at = P[[r[1] % n for r in runs]].tolist()      # each run's first vertex
        joins = [self._join(runs[j - 1][0], runs[j][0], at[j], scale) for j in range(len(runs))]
        sweeps: dict = _circle_sweeps(P, runs, self.carriers)

        def approx(c, first, last):       # the polygon's sweep of a run, computed once
            key = (first, last)
            if key not in sweeps:
                sweeps[key] = _sweep_sum(_unit(P, c[1]), ("C", 0.0, 0.0, 1.0), first, last) \
                    if c[0] == "E" else _sweep_sum(P, c, first, last)
            return sweeps[key]
        explained = all(k >= 0 for k, _, _ in runs)
        made: dict = {}                   # the arcs _drop_inverted made (_bad)
        kept, kjoins = _drop_inverted(runs, joins, P, self.carriers, self, scale, approx, made)
        if len(kept) < 2:
            # the exact curves close on nothing: a sliver the chords made (two curves that
            # touch, cut by their chords), left out; or one closed curve that another one,
            # inside it and a hair away (or touching it), crossed only in chords: that curve
            # whole; what no chord explains stays a polyline
            if not explained:
                return _polyline(P)
            if kept or runs:
                big = max(runs, key=lambda r: r[2] - r[1])[0]
                whole = self._whole(P, big)
                if whole.segments and abs(whole.area - _shoelace(P)) <= \
                        0.01 * abs(_shoelace(P)) + 1e-9:
                    return whole
            return Loop([])
        runs, joins = kept, kjoins
        segs = []
        m = len(runs)
        for j, (k, first, last) in enumerate(runs):
            a, b = joins[j], joins[(j + 1) % m]
            if k < 0:                        # an unexplained polygon edge
                pts = [a] + [tuple(P[i % n]) for i in range(first + 1, last + 1)] + [b]
                segs += [Line(_t(p), _t(q)) for p, q in zip(pts, pts[1:])]
                continue
            c = self.carriers[k]
            if c[0] == "L":
                segs.append(Line(a, b))
            elif c[0] == "S":
                segs.append(_spline_run(c[1], a, b, P, first, last))
            elif c[0] == "E":
                segs.append(_ellipse_run(c[1], a, b, approx(c, first, last)))
            else:
                got = made.get((k, first, last))      # the same run between the same ends
                segs.append(got[2] if got is not None and got[0] == a and got[1] == b else
                            _arc(c, a, b, approx(c, first, last)))
        return Loop(simplify(segs, scale))

    def _whole(self, P, k: int) -> Loop:
        """The loop of polygon ``P`` whose every edge is on carrier ``k``: the whole circle,
        ellipse or closed spline (the polygon's way round); nothing for a line or part of a
        circle (no area in exact geometry), a polyline for no carrier (-1)."""
        n = len(P)
        c = self.carriers[k] if k >= 0 else None
        if c is not None and c[0] == "C":
            total = _sweep_sum(P, c, 0, n - 1)
            if abs(abs(total) - 2 * math.pi) < 1e-6:
                return Loop([Circle((c[1], c[2]), c[3], total > 0)])
        if c is not None and c[0] == "E":
            total = _sweep_sum(_unit(P, c[1]), ("C", 0.0, 0.0, 1.0), 0, n - 1)
            if abs(abs(total) - 2 * math.pi) < 1e-6:
                return Loop([EllipticArc(c[1], 0.0, math.copysign(2 * math.pi, total))])
        if c is not None and c[0] == "S":       # closed, or open with meeting ends
            whole = Spline(c[1], 0.0, float(c[1].n))
            if _shoelace(P) * whole.area_term < 0:
                whole = Spline(c[1], float(c[1].n), 0.0)
            return Loop([whole])
        # every edge on one line, or on part of one circle: no area in exact geometry
        return _polyline(P) if c is None else Loop([])

    def _join(self, ka: int, kb: int, v, scale: float):
        """The exact vertex where carrier ``ka``'s run ends and ``kb``'s begins, near the
        polygon vertex ``v``."""
        v = (float(v[0]), float(v[1]))
        if ka < 0 or kb < 0:
            c = self.carriers[kb] if kb >= 0 else (self.carriers[ka] if ka >= 0 else None)
            return foot(c, v) if c is not None else v
        ca, cb = self.carriers[ka], self.carriers[kb]
        tol = tolerance(scale)
        for x, y, _, _ in self._near_ends(v):
            p = (x, y)
            if distance_to(ca, p) <= tol and distance_to(cb, p) <= tol:
                return p
        return intersect(ca, cb, v)

    def _near_ends(self, v):
        ends = self._ends_grid()
        if ends is None:
            return ()
        cell, grid, rows = ends
        key = (math.floor(v[0] / cell), math.floor(v[1] / cell))
        out = []
        for i in grid.get(key, ()):
            x, y = rows[i][0], rows[i][1]
            if math.hypot(x - v[0], y - v[1]) <= SNAP_TOL:
                out.append(rows[i])
        return out

    def _ends_grid(self):
        if not self._ends:
            return None
        if self._eg is not None and self._eg[0] == len(self._ends):
            return self._eg[1]
        cell = 1e-3
        grid: dict = {}
        for i, (x, y, _, _) in enumerate(self._ends):
            # the cells within SNAP_TOL of the end: one, or two or four near a cell's edge
            x0, x1 = math.floor((x - SNAP_TOL) / cell), math.floor((x + SNAP_TOL) / cell)
            y0, y1 = math.floor((y - SNAP_TOL) / cell), math.floor((y + SNAP_TOL) / cell)
            for gx in (x0,) if x0 == x1 else (x0, x1):
                for gy in (y0,) if y0 == y1 else (y0, y1):
                    grid.setdefault((gx, gy), []).append(i)
        self._eg = (len(self._ends), (cell, grid, self._ends))
        return self._eg[1]

    # ------------------------------------------------------------ edge -> chord
    def _chords(self):
        if self._index is None:
            A, B, C = _pieces(self._a, self._b, self._c)
            A, B, C = _distinct_chords(A, B, C)
            self._a, self._b, self._c = [A], [B], [C]
            self._index = _Grid(A, B, C)
        return self._index

    def _match(self, P: np.ndarray, scale: float) -> np.ndarray:
        """The carrier index of each polygon edge ``P[i] -> P[i+1]`` (-1: none)."""
        g = self._chords()
        Q = np.roll(P, -1, axis=0)
        tol = MATCH_TOL + 1e-11 * scale
        cid = g.match(P, Q, tol)
        bad = cid < 0
        if bad.any():
            self.unmatched += int(bad.sum())
        return cid


def _pieces(a: list, b: list, c: list) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The chords ``(A, B, C)`` (starts and ends, n x 2 mm; carrier indices, n) of the pieces
    of :class:`Provenance`: ``a[i]`` a piece's starts, ``b[i]`` its ends or None (its starts
    turned by one: a closed polygon's next vertex), ``c[i]`` its carrier indices or one
    index for all of them."""
    if not a:
        return np.zeros((0, 2)), np.zeros((0, 2)), np.zeros(0, dtype=np.int64)
    A = np.concatenate(a)
    sizes = np.array([len(P) for P in a], dtype=np.int64)
    starts = np.cumsum(sizes) - sizes
    nxt = np.arange(1, len(A) + 1)
    full = sizes > 0
    nxt[(starts + sizes - 1)[full]] = starts[full]      # each piece's np.roll(P, -1)
    B = A.take(nxt, axis=0)
    C = np.empty(len(A), dtype=np.int64)
    for at, n, ends, ids in zip(starts.tolist(), sizes.tolist(), b, c):
        if ends is not None:
            B[at:at + n] = ends
        C[at:at + n] = ids
    return A, B, C


_UNIT: dict = {}


def _unit_circle(n: int, ccw: bool) -> tuple[np.ndarray, np.ndarray]:
    """``(cos t, sin t)`` for ``t = sg * 2 pi i / n``, i < n (``sg`` = 1 counter-clockwise,
    else -1), by ``math.cos``/``math.sin`` once per chord count: a plate of 19,000 equal
    holes computes one table (NumPy's own cos may differ from libm's in the last bit)."""
    key = (n, ccw)
    got = _UNIT.get(key)
    if got is None:
        sg = 1.0 if ccw else -1.0
        t = [sg * 2 * math.pi * i / n for i in range(n)]
        got = (np.array([math.cos(a) for a in t]), np.array([math.sin(a) for a in t]))
        if len(_UNIT) > 256:
            _UNIT.clear()
        _UNIT[key] = got
    return got


def _distinct_chords(A, B, C):
    """The chords ``A[i] -> B[i]`` (carrier ``C[i]``) without repeats: the same carrier
    tessellated twice (a circle drawn in 16 000 instances of one template, at one place)
    gives the same chords bit for bit (either way round), and one of each is enough to
    match against; without this, every result vertex there met every copy (31 billion
    candidate pairs, 232 GiB, for fuzz seed 12900)."""
    if len(A) < 2:
        return A, B, C
    swap = (A[:, 0] > B[:, 0]) | ((A[:, 0] == B[:, 0]) & (A[:, 1] > B[:, 1]))
    lo = np.where(swap[:, None], B, A)
    hi = np.where(swap[:, None], A, B)
    # first one sort of a hash of each chord (its floats' bits, -0.0 as 0.0): equal chords
    # hash alike, so chords whose hashes all differ have no repeats (a perforated sheet's
    # 900,000 chords: one sort of one key, not five)
    h = C.astype(np.uint64)
    with np.errstate(over="ignore"):
        for col in (lo[:, 0], lo[:, 1], hi[:, 0], hi[:, 1]):
            h = (h ^ (col + 0.0).view(np.uint64)) * np.uint64(0x100000001B3)
    h.sort()
    if not (h[1:] == h[:-1]).any():
        return A, B, C
    order = np.lexsort((C, hi[:, 1], hi[:, 0], lo[:, 1], lo[:, 0]))
    lo, hi, c = lo[order], hi[order], C[order]
    new = np.r_[True, (lo[1:] != lo[:-1]).any(axis=1) | (hi[1:] != hi[:-1]).any(axis=1)
                | (c[1:] != c[:-1])]
    if new.all():
        return A, B, C
    keep = np.sort(order[new])              # the first of each, in the original order
    return A[keep], B[keep], C[keep]


def _runs(cid: np.ndarray, carriers: list, scale: float):
    """Runs of consecutive edges on one carrier: [(carrier, first edge, last edge)], indices
    modulo n; ``None`` when every edge is on the same carrier."""
    n = len(cid)
    same = np.empty(n, dtype=bool)                 # edge i continues edge i-1's run
    prev = np.roll(cid, 1)
    same[:] = (cid == prev) & (cid >= 0)
    tol = tolerance(scale)
    ask = np.flatnonzero(~same & (cid >= 0) & (prev >= 0))
    for i, a, b in zip(ask.tolist(), cid[ask].tolist(), prev[ask].tolist()):
        if same_carrier(carriers[a], carriers[b], tol):
            same[i] = True
            cid[i] = b
    if same.all():
        return None
    starts = np.flatnonzero(~same).tolist()
    runs = []
    for st, end, k in zip(starts, starts[1:] + [starts[0] + n], cid[starts].tolist()):
        if k < 0:                              # unexplained edges: one run each
            runs += [(-1, i, i) for i in range(st, end)]
        else:
            runs.append((k, st, end - 1))
    return runs


def _sweep_sum(P, c, first: int, last: int) -> float:
    """The angle the polygon edges first..last turn about circle ``c``'s center."""
    n = len(P)
    idx = np.arange(first, last + 2) % n
    X = P[idx, 0] - c[1]
    Y = P[idx, 1] - c[2]
    a = np.arctan2(X[:-1] * Y[1:] - Y[:-1] * X[1:], X[:-1] * X[1:] + Y[:-1] * Y[1:])
    return float(a.sum())


def _circle_sweeps(P, runs, carriers) -> dict:
    """:func:`_sweep_sum` of every run of ``runs`` on a circle, ``{(first, last): sweep}``,
    the edges' angles of all of them in one array operation (a gear's outline has a thousand
    such runs): each run's angles are the same floating-point operations on the same values,
    summed by the same ``sum`` of a slice of as many angles, so each sweep equals
    :func:`_sweep_sum`'s."""
    sel = [(k, f, l) for k, f, l in runs if k >= 0 and carriers[k][0] == "C"]
    if len(sel) < 2:
        return {}
    n = len(P)
    first = np.array([f for _, f, _ in sel], dtype=np.int64)
    counts = np.array([l for _, _, l in sel], dtype=np.int64) - first + 2   # vertices
    at = np.cumsum(counts) - counts                    # where each run's vertices begin
    idx = (np.arange(int(counts.sum())) + np.repeat(first - at, counts)) % n
    X = P[idx, 0] - np.repeat([carriers[k][1] for k, _, _ in sel], counts)
    Y = P[idx, 1] - np.repeat([carriers[k][2] for k, _, _ in sel], counts)
    # the angle of each edge about its run's center (those across two runs are not read)
    a = np.arctan2(X[:-1] * Y[1:] - Y[:-1] * X[1:], X[:-1] * X[1:] + Y[:-1] * Y[1:])
    # each run's m - 1 angles summed: the runs of one length as the rows of one array (a
    # row's sum is the same pairwise sum as the slice's, bit for bit)
    sums = np.empty(len(sel))
    for m in sorted(set(counts.tolist())):
        rows = np.flatnonzero(counts == m)
        sums[rows] = a[at[rows, None] + np.arange(m - 1)].sum(axis=1)
    return {(f, l): v for (_, f, l), v in zip(sel, sums.tolist())}


def _arc(c, a, b, approx: float) -> Arc:
    cx, cy, r = c[1], c[2], c[3]
    a1 = math.atan2(a[1] - cy, a[0] - cx)
    a2 = math.atan2(b[1] - cy, b[0] - cx)
    sw = a2 - a1
    sw += 2 * math.pi * round((approx - sw) / (2 * math.pi))
    return Arc((cx, cy), r, a1, sw)


def _unit(P, e) -> np.ndarray:
    """Polygon ``P`` in the frame where ellipse ``e`` is the unit circle (its parameter is
    the angle there)."""
    c, s = math.cos(e.rotation), math.sin(e.rotation)
    X, Y = P[:, 0] - e.center[0], P[:, 1] - e.center[1]
    return np.column_stack([(X * c + Y * s) / e.rx, (-X * s + Y * c) / e.ry])


def _ellipse_run(e, a, b, approx: float) -> EllipticArc:
    """The arc of ellipse ``e`` from exact point ``a`` to ``b`` whose parameter sweep is the
    one nearest to the polygon's, ``approx``."""
    t1, t2 = e.param(a), e.param(b)
    sw = t2 - t1
    sw += 2 * math.pi * round((approx - sw) / (2 * math.pi))
    return EllipticArc(e, t1, sw)


def _bad(k, a, b, P, first, last, carriers, tol, approx=None, made=None) -> bool:
    """True when run ``k`` from exact point ``a`` to ``b`` is shorter than ``tol`` or runs
    against its polygon edges (an overlap the chords could not show).  ``made``: a dict where
    the arc of a run on a circle is kept, ``{(k, first, last): (a, b, arc)}``, so that the loop
    built from the runs kept takes it rather than making it again."""
    n = len(P)
    if k < 0:
        return False
    c = carriers[k]
    if c[0] == "S":
        sp = _spline_run(c[1], a, b, P, first, last)
        return sp is None or sp.length <= tol
    if c[0] == "E":
        sw = approx(c, first, last) if approx is not None else \
            _sweep_sum(_unit(P, c[1]), ("C", 0.0, 0.0, 1.0), first, last)
        arc = _ellipse_run(c[1], a, b, sw)
        return abs(arc.sweep) * c[1].ry <= tol or arc.sweep * sw <= 0
    if c[0] == "L":
        dx, dy = b[0] - a[0], b[1] - a[1]
        ex = P[(last + 1) % n] - P[first % n]
        return math.hypot(dx, dy) <= tol or dx * ex[0] + dy * ex[1] <= 0
    sw = approx(c, first, last) if approx is not None else _sweep_sum(P, c, first, last)
    arc = _arc(c, a, b, sw)
    if made is not None:
        made[(k, first, last)] = (a, b, arc)
    return abs(arc.sweep) * c[3] <= tol or arc.sweep * sw <= 0


def _drop_inverted(runs, joins, P, carriers, prov, scale, approx=None, made=None):
    """Drop the runs :func:`_bad` finds, joining their neighbours (one run when they are on
    one carrier, else at the neighbours' own intersection); ``([], [])`` when fewer than
    two runs would be left.  ``made``: see :func:`_bad`."""
    tol = tolerance(scale)
    n = len(P)
    changed = True
    while changed:
        changed = False
        m = len(runs)
        for j in range(m):
            k, first, last = runs[j]
            if not _bad(k, joins[j], joins[(j + 1) % m], P, first, last, carriers, tol, approx,
                        made):
                continue
            if m <= 2:
                return [], []
            # turn the lists so that the bad run is the second: neighbours 0 and 2
            r = (j - 1) % m
            runs, joins = runs[r:] + runs[:r], joins[r:] + joins[:r]
            kp, kn = runs[0][0], runs[2][0]
            mid = P[(first + last + 1) // 2 % n]
            if kp >= 0 and kn >= 0 and (kp == kn or same_carrier(carriers[kp], carriers[kn], tol)):
                last2 = runs[2][2]
                while last2 < runs[0][1]:
                    last2 += n
                runs = [(kp, runs[0][1], last2)] + runs[3:]
                joins = [joins[0]] + joins[3:]
                if len(runs) < 2:
                    return [], []
            else:
                joins[2] = prov._join(kp, kn, mid, scale)
                del runs[1], joins[1]
            changed = True
            break
    return runs, joins


def _shoelace(P) -> float:
    X, Y = P[:, 0], P[:, 1]
    return 0.5 * float(np.dot(X, np.roll(Y, -1)) - np.dot(Y, np.roll(X, -1)))


def _cyc(c, u: float, v: float) -> float:
    """How far forward from position ``u`` to ``v`` along curve ``c`` (modulo ``n`` when
    closed)."""
    d = v - u
    return d % c.n if c.closed else d


def _spline_run(c, a, b, P, first: int, last: int):
    """The exact piece of spline ``c`` from exact point ``a`` to ``b`` that the polygon
    edges ``first..last`` follow; None when the exact ends come in the wrong order (an
    overlap thinner than the chords could show)."""
    n = len(P)
    if not c.closed and last > first and math.dist(c.ctrl[0], c.ctrl[-1]) <= 1e-7 and \
            math.dist(a, c.ctrl[0]) <= 1e-7 and math.dist(b, c.ctrl[0]) <= 1e-7:
        # an open curve that ends where it starts (a corner loop), run from that point round
        # to it: the whole curve, the way its vertices go (the point's foot is either end)
        fwd = c.foot(tuple(P[(first + 1) % n])) <= c.foot(tuple(P[last % n]))
        return Spline(c, 0.0, float(c.n)) if fwd else Spline(c, float(c.n), 0.0)
    ua, ub = c.foot(a), c.foot(b)
    # the run's own vertices say which way it goes along the curve, and how far
    v0 = P[first % n]
    v1 = P[(last + 1) % n]
    vm = P[((first + last + 1) // 2) % n] if last > first else (P[first % n] + P[(last + 1) % n]) / 2
    u0, um, u1 = c.foot(tuple(v0)), c.foot(tuple(vm)), c.foot(tuple(v1))
    fwd = _cyc(c, u0, um) + _cyc(c, um, u1)
    back = _cyc(c, um, u0) + _cyc(c, u1, um)
    if c.closed:
        forward = fwd <= back
        approx = fwd if forward else back
    else:
        forward = u1 >= u0 if abs(u1 - u0) > 1e-12 else um >= u0
        approx = abs(u1 - u0)
    d = _cyc(c, ua, ub) if forward else _cyc(c, ub, ua)
    if c.closed and abs(d - approx) > c.n / 2 or not c.closed and d < 0:
        return None                                 # the ends swapped past each other
    return Spline(c, ua, ua + d if forward else ua - d)


def _polyline(P) -> Loop:
    n = len(P)
    return Loop([Line(_t(P[i]), _t(P[(i + 1) % n])) for i in range(n)])


def _t(p):
    return (float(p[0]), float(p[1]))


__all__ = ["Provenance", "CHORD_TOL"]
