"""The one output model: exact lines, arcs and circles per part, recovered from the solved model.

After the booleans (:mod:`.booleans`) every part is a Manifold ``CrossSection``: polygons whose
vertices are either vertices of the tessellated model curves or intersections of them.  This
module turns each polygon back into exact segments (docs/outputs.md, "Arcs"):

* every circle of the solved model is known exactly (:attr:`Drawing.circles`: absolute center
  and radius of each Circle, Arc, Slot end, RoundedRectangle corner);
* a polygon edge lies on a model circle when both its end vertices are within the chord
  tolerance (:data:`~aidl_lang.geometry.tessellate.CHORD_TOL`, plus float noise) of the circle
  and it spans at most one tessellation step of that circle;
* consecutive edges on the same circle, turning the same way, become one :class:`Arc`; a loop
  made entirely of one circle's edges becomes a :class:`Circle`;
* the ends of a recovered arc are moved onto the exact curve: intersected with the neighbouring
  line (or circle) rather than projected, so the loop stays closed and its lines straight;
* everything else stays :class:`Line`.  Ellipses and Fillet/Chamfer corners have no model
  circle and stay polylines of short lines (their chord error is below ``CHORD_TOL``).

The result, :class:`Output`, holds :class:`PartOutline` s (name, kind, loops, thickness) and
engraving strokes; every writer (SVG, DXF, PNG, STL/3MF, STEP) reads it.  All lengths are in
millimetres, angles in radians, y up.
"""
from __future__ import annotations

import math
from ..records import dataclass, field

import numpy as np

from ..geometry.tessellate import CHORD_TOL
from .booleans import Drawing

Point = tuple[float, float]


class OutputError(RuntimeError):
    """A writer cannot produce this file from this part (for example a PNG larger than the
    rasteriser allows); the message says why and what to change."""


class MissingDependency(OutputError):
    """An optional output library is not installed; the message says how to install it."""

# how far a boolean vertex may be from the exact intersection it stands for: two chords that
# cross at a shallow angle meet up to CHORD_TOL / sin(angle) away from the curves' crossing
SNAP_TOL = 20 * CHORD_TOL


@dataclass(frozen=True)
class Line:
    start: Point
    end: Point

    @property
    def length(self) -> float:
        return math.dist(self.start, self.end)


@dataclass(frozen=True)
class Arc:
    """Circular arc from ``start_angle`` sweeping ``sweep`` radians (> 0 counter-clockwise)."""
    center: Point
    radius: float
    start_angle: float
    sweep: float

    @property
    def end_angle(self) -> float:
        return self.start_angle + self.sweep

    @property
    def ccw(self) -> bool:
        return self.sweep > 0

    def at(self, a: float) -> Point:
        return (self.center[0] + self.radius * math.cos(a), self.center[1] + self.radius * math.sin(a))

    @property
    def start(self) -> Point:
        return self.at(self.start_angle)

    @property
    def end(self) -> Point:
        return self.at(self.end_angle)

    @property
    def length(self) -> float:
        return self.radius * abs(self.sweep)


@dataclass(frozen=True)
class Circle:
    center: Point
    radius: float
    ccw: bool = True

    @property
    def length(self) -> float:
        return 2 * math.pi * self.radius


Segment = Line | Arc | Circle


@dataclass
class Loop:
    """A closed outline: consecutive segments, each ending where the next starts.  A loop
    that runs clockwise (negative :attr:`area`) is a hole of its part."""
    segments: list[Segment]

    @property
    def area(self) -> float:
        """Signed area (mm^2): shoelace over the segment ends plus each arc's circular segment."""
        if len(self.segments) == 1 and isinstance(self.segments[0], Circle):
            c = self.segments[0]
            return (1 if c.ccw else -1) * math.pi * c.radius ** 2
        a = 0.0
        for s in self.segments:
            (x0, y0), (x1, y1) = s.start, s.end
            a += 0.5 * (x0 * y1 - x1 * y0)
            if isinstance(s, Arc):
                t = s.sweep
                a += 0.5 * s.radius ** 2 * (t - math.sin(t))
        return a

    @property
    def perimeter(self) -> float:
        return sum(s.length for s in self.segments)

    @property
    def is_hole(self) -> bool:
        return self.area < 0

    def points(self, tol: float = CHORD_TOL) -> np.ndarray:
        """A polyline of the loop (closed implicitly), arcs sampled within ``tol``."""
        xs, ys = [], []
        _sample_xy(self.segments, xs, ys)
        return np.column_stack([np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)]) \
            if xs else np.zeros((0,), dtype=float)


def _sample_xy(segments, xs: list, ys: list) -> None:
    """Append the vertices of :meth:`Loop.points` of ``segments`` to ``xs`` and ``ys``: each
    line's start, each arc's start and its interior chord ends, each circle's chord ends
    (:func:`~aidl_lang.geometry.tessellate.segments_for` chords, mm)."""
    from ..geometry.tessellate import segments_for
    cos, sin, pi = math.cos, math.sin, math.pi
    for s in segments:
        if isinstance(s, Line):
            xs.append(s.start[0])
            ys.append(s.start[1])
        elif isinstance(s, Arc):
            cx, cy = s.center
            r, a0, sw = s.radius, s.start_angle, s.sweep
            n = max(1, segments_for(r, abs(sw)))
            angles = [a0 + sw * i / n for i in range(n)]
            xs += [cx + r * cos(a) for a in angles]
            ys += [cy + r * sin(a) for a in angles]
        else:
            cx, cy = s.center
            r = s.radius
            n = segments_for(r)
            sg = 1 if s.ccw else -1
            angles = [sg * 2 * pi * i / n for i in range(n)]
            xs += [cx + r * cos(a) for a in angles]
            ys += [cy + r * sin(a) for a in angles]


@dataclass
class PartOutline:
    """One part: its name (structure path), kind (``solid``, or ``hole`` for a hole with no
    solid to cut), outline loops (outer ones counter-clockwise, holes clockwise) and thickness
    (mm, for 3D outputs)."""
    name: str
    kind: str
    loops: list[Loop]
    thickness: float | None = None
    shape: object = None            # the manifold3d CrossSection the loops come from

    @property
    def area(self) -> float:
        return sum(lp.area for lp in self.loops)

    @property
    def perimeter(self) -> float:
        return sum(lp.perimeter for lp in self.loops)


@dataclass
class Stroke:
    """Engraving: an open or closed chain of segments (``style`` drawing | open)."""
    segments: list[Segment]
    style: str = "drawing"
    closed: bool = False
    source: str = ""


@dataclass
class Output:
    parts: list[PartOutline] = field(default_factory=list)
    engrave: list[Stroke] = field(default_factory=list)
    title: str = ""
    drawing: Drawing | None = None     # the booleans' result (debug layers, checks)

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
                _sample_xy(lp.segments, xs, ys)
        for st in self.engrave:
            _sample_xy(st.segments, xs, ys)
            for s in st.segments:
                if not isinstance(s, Circle):
                    e = s.end
                    xs.append(e[0])
                    ys.append(e[1])
        if not xs:
            return (0.0, 0.0, 1.0, 1.0)
        return (min(xs), min(ys), max(xs), max(ys))


# ------------------------------------------------------------------ arc recovery
class _Circles:
    """The model's circles (cx, cy, r, largest chord angle), with a bounding-box filter."""

    def __init__(self, circles):
        uniq = {}
        for cx, cy, r in circles:
            if r > 0 and math.isfinite(r):
                uniq.setdefault((round(cx, 9), round(cy, 9), round(r, 9)), (cx, cy, r))
        c = np.array(list(uniq.values()), dtype=float).reshape(-1, 3)
        self.c = np.column_stack([c, _max_step(c[:, 2]) * 1.001 + 1e-9]) if len(c) else \
            np.zeros((0, 4))
        self.lo = self.c[:, :2] - self.c[:, 2:3] - 1e-3
        self.hi = self.c[:, :2] + self.c[:, 2:3] + 1e-3
        # a uniform grid over the circles' boxes, so that a loop looks at its neighbours only
        self.cell = _median(self.hi - self.lo) if len(self.c) else 1.0
        self.grid: dict[tuple[int, int], list[int]] = {}
        self.big: list[int] = []
        for i in range(len(self.c)):
            (x0, y0), (x1, y1) = self._cells(self.lo[i], self.hi[i])
            if (x1 - x0 + 1) * (y1 - y0 + 1) > 64:
                self.big.append(i)
                continue
            for gx in range(x0, x1 + 1):
                for gy in range(y0, y1 + 1):
                    self.grid.setdefault((gx, gy), []).append(i)

    def _cells(self, lo, hi):
        s = self.cell
        return ((math.floor(lo[0] / s), math.floor(lo[1] / s)),
                (math.floor(hi[0] / s), math.floor(hi[1] / s)))

    def near(self, pts: np.ndarray) -> np.ndarray:
        if not len(self.c) or not len(pts):
            return self.c[:0]
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        (x0, y0), (x1, y1) = self._cells(lo, hi)
        if (x1 - x0 + 1) * (y1 - y0 + 1) > 256:
            idx = np.arange(len(self.c))
        else:
            cand = set(self.big)
            for gx in range(x0, x1 + 1):
                for gy in range(y0, y1 + 1):
                    cand.update(self.grid.get((gx, gy), ()))
            if not cand:
                return self.c[:0]
            idx = np.fromiter(cand, dtype=np.int64)
        m = np.all((self.hi[idx] >= lo) & (self.lo[idx] <= hi), axis=1)
        return self.c[idx[m]]


def _median(a: np.ndarray) -> float:
    """``float(np.median(a))`` over all entries, without ``np.median``'s import of
    ``numpy.ma`` (10-15 ms of a cold render): the middle value, or the mean of the two."""
    v = np.sort(np.asarray(a, dtype=float).ravel())
    n = len(v)
    if np.isnan(v[-1]):
        return math.nan
    return float(v[n // 2]) if n % 2 else float((v[n // 2 - 1] + v[n // 2]) / 2)


def _max_step(r: np.ndarray) -> np.ndarray:
    """Largest angle (rad) one tessellation chord of radius ``r`` spans
    (:func:`~aidl_lang.geometry.tessellate.segments_for`: at least 3 chords a circle)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        step = 2 * np.arccos(np.clip(1 - CHORD_TOL / r, -1.0, 1.0))
    return np.minimum(np.maximum(step, math.pi / 4), 2 * math.pi / 3)


def recover(poly: np.ndarray, circles: _Circles) -> Loop:
    """Exact segments of one closed polygon (N x 2, vertices in order, no repeat)."""
    P = np.asarray(poly, dtype=float)
    n = len(P)
    C = circles.near(P) if n >= 3 else circles.c[:0]
    if not len(C):
        return Loop([Line(_t(P[i]), _t(P[(i + 1) % n])) for i in range(n)])
    scale = max(1.0, float(np.abs(P).max()))
    vtol = CHORD_TOL * 1.02 + 1e-7 * scale
    nxt = np.arange(1, n + 1) % n
    # vertex-to-circle deviation, N x M
    ax, ay = P[:, None, 0] - C[None, :, 0], P[:, None, 1] - C[None, :, 1]
    dev = np.abs(np.hypot(ax, ay) - C[None, :, 2])
    on = dev <= vtol
    bx, by = ax[nxt], ay[nxt]
    # angle spanned by each edge about each circle's center, signed
    ang = np.arctan2(ax * by - ay * bx, ax * bx + ay * by)
    absang = np.abs(ang)
    ok = on & on[nxt] & (absang <= C[None, :, 3]) & (absang > 0)
    score = np.where(ok, dev + dev[nxt], np.inf)
    best = np.argmin(score, axis=1)
    rows = np.arange(n)
    has = np.isfinite(score[rows, best])
    if not has.any():
        return Loop([Line(_t(P[i]), _t(P[(i + 1) % n])) for i in range(n)])
    sgn = ang[rows, best] > 0
    keys = np.where(has, best * 2 + sgn, -1)
    if (keys == keys[0]).all():
        k = int(best[0])
        total = float(np.sum(ang[:, k]))
        if abs(abs(total) - 2 * math.pi) < 1e-6:
            return Loop([Circle((float(C[k, 0]), float(C[k, 1])), float(C[k, 2]), total > 0)])
        starts = np.array([0])
    else:
        starts = np.flatnonzero(keys != keys[np.arange(-1, n - 1)])
    # runs of equal keys: (key, first edge, last edge), indices modulo n
    runs = []
    for j, st in enumerate(starts):
        end = starts[j + 1] if j + 1 < len(starts) else starts[0] + n
        k = int(keys[st])
        runs.append((k, int(st), int(end - 1)))
    m = len(runs)
    Pl = P.tolist()
    verts = [list(Pl[st % n]) for _, st, _ in runs]

    def circ(k):
        return C[k // 2] if k >= 0 else None

    for j in range(m):
        kprev, kcur = runs[j - 1][0], runs[j][0]
        if kprev < 0 and kcur < 0:
            continue
        cprev, ccur = circ(kprev), circ(kcur)
        v = verts[j]
        if ccur is not None and cprev is not None:
            verts[j] = _snap_cc(v, cprev, ccur)
        elif ccur is None:            # a line run starts here: its first edge goes to P[st+1]
            verts[j] = _snap_lc(v, Pl[(runs[j][1] + 1) % n], cprev)
        else:                         # a line run ended here: its last edge came from P[last]
            verts[j] = _snap_lc(v, Pl[runs[j - 1][2] % n], ccur)
    segs: list[Segment] = []
    for j, (k, st, last) in enumerate(runs):
        a, b = verts[j], verts[(j + 1) % m]
        if k < 0:
            pts = [a] + [Pl[i % n] for i in range(st + 1, last + 1)] + [b]
            segs += [Line(_t(pts[i]), _t(pts[i + 1])) for i in range(len(pts) - 1)]
            continue
        c = C[k // 2]
        cx, cy, r = float(c[0]), float(c[1]), float(c[2])
        a1 = math.atan2(a[1] - cy, a[0] - cx)
        a2 = math.atan2(b[1] - cy, b[0] - cx)
        approx = float(np.sum(ang[np.arange(st, last + 1) % n, k // 2]))
        sweep = a2 - a1
        sweep += 2 * math.pi * round((approx - sweep) / (2 * math.pi))
        if abs(sweep) < 1e-12:
            segs.append(Line(_t(a), _t(b)))
            continue
        if abs(abs(sweep) - 2 * math.pi) < 1e-9 and m == 1:
            return Loop([Circle((cx, cy), r, sweep > 0)])
        segs.append(Arc((cx, cy), r, a1, sweep))
    return Loop(segs)


def _t(p) -> Point:
    return (float(p[0]), float(p[1]))


def _snap_lc(v, other, c) -> list:
    """The intersection of the line (other -> v) with circle ``c`` nearest to ``v``."""
    cx, cy, r = float(c[0]), float(c[1]), float(c[2])
    dx, dy = v[0] - other[0], v[1] - other[1]
    L = math.hypot(dx, dy)
    if L < 1e-12:
        return _project(v, c)
    ux, uy = dx / L, dy / L
    fx, fy = other[0] - cx, other[1] - cy
    b = fx * ux + fy * uy
    disc = b * b - (fx * fx + fy * fy - r * r)
    if disc < 0:
        return _project(v, c)
    best, dist = None, math.inf
    for t in (-b - math.sqrt(disc), -b + math.sqrt(disc)):
        q = [other[0] + t * ux, other[1] + t * uy]
        dq = math.hypot(q[0] - v[0], q[1] - v[1])
        if dq < dist:
            best, dist = q, dq
    return best if dist <= SNAP_TOL else _project(v, c)


def _snap_cc(v, c1, c2) -> list:
    """The intersection of two circles nearest to ``v`` (projection when they do not cross)."""
    x1, y1, r1 = float(c1[0]), float(c1[1]), float(c1[2])
    x2, y2, r2 = float(c2[0]), float(c2[1]), float(c2[2])
    dx, dy = x2 - x1, y2 - y1
    D = math.hypot(dx, dy)
    if D < 1e-12 or D > r1 + r2 or D < abs(r1 - r2):
        return _project(v, c1)
    a = (r1 * r1 - r2 * r2 + D * D) / (2 * D)
    h = math.sqrt(max(0.0, r1 * r1 - a * a))
    mx, my = x1 + a * dx / D, y1 + a * dy / D
    px, py = -dy / D, dx / D
    best, dist = None, math.inf
    for sg in (1, -1):
        q = [mx + sg * h * px, my + sg * h * py]
        dq = math.hypot(q[0] - v[0], q[1] - v[1])
        if dq < dist:
            best, dist = q, dq
    return best if dist <= SNAP_TOL else _project(v, c1)


def _project(v, c) -> list:
    cx, cy, r = float(c[0]), float(c[1]), float(c[2])
    dx, dy = v[0] - cx, v[1] - cy
    L = math.hypot(dx, dy)
    return [cx + dx / L * r, cy + dy / L * r] if L > 0 else list(v)


# ------------------------------------------------------------------ build
def _stroke(item, circles: _Circles, style: str, source: str) -> list[Stroke]:
    kind = item[0]
    if kind == "line":
        return [Stroke([Line(_t(item[1]), _t(item[2]))], style, False, source)]
    if kind == "arc":
        _, c, r, a1, a2 = item
        sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
        return [Stroke([Arc(_t(c), float(r), float(a1), float(sweep))], style, False, source)]
    if kind == "circle":
        return [Stroke([Circle(_t(item[1]), float(item[2]))], style, True, source)]
    lp = recover(item[1], circles)
    return [Stroke(lp.segments, style, True, source)]


def build(drawing: Drawing, title: str = "", thickness=None) -> Output:
    """The exact :class:`Output` of a booleans :class:`Drawing`.  ``thickness`` maps a part's
    name to its thickness in mm (or is one number for all parts); by default the program's
    (``thickness 3 mm``, :attr:`Drawing.thickness`)."""
    circles = _Circles(drawing.circles)
    out = Output(title=title, drawing=drawing)
    if thickness is None:
        thickness = drawing.thickness
    for p in drawing.parts:
        if p.shape.is_empty():
            continue
        loops = [recover(np.asarray(poly), circles) for poly in p.shape.to_polygons()]
        t = thickness.get(p.name) if isinstance(thickness, dict) else thickness
        out.parts.append(PartOutline(p.name, p.kind, loops, t, p.shape))
    for style, item, g in drawing.strokes:
        out.engrave += _stroke(item, circles, style, g.label if g is not None else "")
    return out
