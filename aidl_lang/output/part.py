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
from dataclasses import dataclass, field

import numpy as np

from ..geometry.tessellate import CHORD_TOL
from .booleans import Drawing

Point = tuple[float, float]


class MissingDependency(RuntimeError):
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
        from ..geometry.tessellate import segments_for
        out = []
        for s in self.segments:
            if isinstance(s, Line):
                out.append(s.start)
            elif isinstance(s, Arc):
                n = max(1, segments_for(s.radius, abs(s.sweep)))
                out += [s.at(s.start_angle + s.sweep * i / n) for i in range(n)]
            else:
                n = segments_for(s.radius)
                sg = 1 if s.ccw else -1
                out += [(s.center[0] + s.radius * math.cos(sg * 2 * math.pi * i / n),
                         s.center[1] + s.radius * math.sin(sg * 2 * math.pi * i / n))
                        for i in range(n)]
        return np.asarray(out, dtype=float)


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
        xs, ys = [], []
        for p in self.parts:
            for lp in p.loops:
                pts = lp.points()
                if len(pts):
                    xs += [pts[:, 0].min(), pts[:, 0].max()]
                    ys += [pts[:, 1].min(), pts[:, 1].max()]
        for st in self.engrave:
            pts = Loop(st.segments).points() if st.segments else np.zeros((0, 2))
            ends = np.array([s.end for s in st.segments if not isinstance(s, Circle)] or
                            np.zeros((0, 2)))
            for q in (pts, ends):
                if len(q):
                    xs += [q[:, 0].min(), q[:, 0].max()]
                    ys += [q[:, 1].min(), q[:, 1].max()]
        if not xs:
            return (0.0, 0.0, 1.0, 1.0)
        return (min(xs), min(ys), max(xs), max(ys))


# ------------------------------------------------------------------ arc recovery
class _Circles:
    """The model's circles, with a bounding-box filter for one polygon."""

    def __init__(self, circles):
        uniq = {}
        for cx, cy, r in circles:
            if r > 0 and math.isfinite(r):
                uniq.setdefault((round(cx, 9), round(cy, 9), round(r, 9)), (cx, cy, r))
        self.c = np.array(list(uniq.values()), dtype=float).reshape(-1, 3)

    def near(self, pts: np.ndarray) -> np.ndarray:
        if not len(self.c) or not len(pts):
            return self.c[:0]
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        c = self.c
        m = ((c[:, 0] + c[:, 2] >= lo[0] - 1e-3) & (c[:, 0] - c[:, 2] <= hi[0] + 1e-3) &
             (c[:, 1] + c[:, 2] >= lo[1] - 1e-3) & (c[:, 1] - c[:, 2] <= hi[1] + 1e-3))
        return c[m]


def _max_step(r: np.ndarray) -> np.ndarray:
    """Largest angle (rad) one tessellation chord of radius ``r`` spans
    (:func:`~aidl_lang.geometry.tessellate.segments_for`: at least 3 chords a circle)."""
    with np.errstate(invalid="ignore"):
        step = 2 * np.arccos(np.clip(1 - CHORD_TOL / r, -1.0, 1.0))
    return np.minimum(np.maximum(step, math.pi / 4), 2 * math.pi / 3)


def recover(poly: np.ndarray, circles: _Circles) -> Loop:
    """Exact segments of one closed polygon (N x 2, vertices in order, no repeat)."""
    P = np.asarray(poly, dtype=float)
    n = len(P)
    C = circles.near(P)
    if n < 3 or not len(C):
        return Loop([Line(tuple(P[i]), tuple(P[(i + 1) % n])) for i in range(n)])
    scale = max(1.0, float(np.abs(P).max()))
    vtol = CHORD_TOL * 1.02 + 1e-7 * scale
    # vertex-to-circle deviation, N x M
    d = np.hypot(P[:, None, 0] - C[None, :, 0], P[:, None, 1] - C[None, :, 1])
    on = np.abs(d - C[None, :, 2]) <= vtol
    Q = np.roll(P, -1, axis=0)
    onq = np.roll(on, -1, axis=0)
    both = on & onq
    # angle spanned by each edge about each circle's center, signed
    ax, ay = P[:, None, 0] - C[None, :, 0], P[:, None, 1] - C[None, :, 1]
    bx, by = Q[:, None, 0] - C[None, :, 0], Q[:, None, 1] - C[None, :, 1]
    ang = np.arctan2(ax * by - ay * bx, ax * bx + ay * by)
    ok = both & (np.abs(ang) <= _max_step(C[:, 2])[None, :] * 1.001 + 1e-9) & (np.abs(ang) > 0)
    dev = np.abs(d - C[None, :, 2]) + np.abs(np.roll(d, -1, axis=0) - C[None, :, 2])
    dev = np.where(ok, dev, np.inf)
    best = np.argmin(dev, axis=1)
    edge_c = np.where(np.isfinite(dev[np.arange(n), best]), best, -1)
    edge_s = np.sign(ang[np.arange(n), np.maximum(edge_c, 0)])
    key = [(int(edge_c[i]), float(edge_s[i])) if edge_c[i] >= 0 else None for i in range(n)]
    if key[0] is not None and all(k == key[0] for k in key):
        k = edge_c[0]
        total = float(np.sum(ang[np.arange(n), k]))
        if abs(abs(total) - 2 * math.pi) < 1e-6:
            return Loop([Circle((float(C[k, 0]), float(C[k, 1])), float(C[k, 2]), total > 0)])
    # runs of equal keys; rotate so that index 0 starts a run
    start = 0
    if all(k == key[0] for k in key):
        start = 0
    else:
        for i in range(n):
            if key[i] != key[i - 1]:
                start = i
                break
    order = [(start + i) % n for i in range(n)]
    runs: list[tuple[object, list[int]]] = []
    for i in order:
        if runs and key[i] is not None and runs[-1][0] == key[i]:
            runs[-1][1].append(i)
        else:
            runs.append((key[i], [i]))
    # vertices (exact, snapped) at the start of each run; lines keep their vertices
    verts: list[np.ndarray] = [P[idx[0]].copy() for _, idx in runs]
    m = len(runs)

    def circ(k):
        return C[k[0]] if k is not None else None

    for j in range(m):
        kprev, kcur = runs[j - 1][0], runs[j][0]
        cprev, ccur = circ(kprev), circ(kcur)
        v = verts[j]
        if cprev is None and ccur is None:
            continue
        if ccur is not None and cprev is not None:
            verts[j] = _snap_cc(v, cprev, ccur)
        else:
            c = ccur if ccur is not None else cprev
            # the neighbouring line: from this vertex to the other end of the line edge
            if ccur is None:          # line run starts here: its edge goes to P[i+1]
                other = P[(runs[j][1][0] + 1) % n]
            else:                     # line run ended here: its last edge came from P[i-1]
                other = P[runs[j - 1][1][-1]]
            verts[j] = _snap_lc(v, other, c)
    segs: list[Segment] = []
    for j, (k, idx) in enumerate(runs):
        a, b = verts[j], verts[(j + 1) % m]
        if k is None:
            pts = [a] + [P[i] for i in idx[1:]] + [b]
            segs += [Line(_t(pts[i]), _t(pts[i + 1])) for i in range(len(pts) - 1)]
            continue
        c = C[k[0]]
        a1 = math.atan2(a[1] - c[1], a[0] - c[0])
        a2 = math.atan2(b[1] - c[1], b[0] - c[0])
        approx = float(np.sum(ang[idx, k[0]]))
        sweep = a2 - a1
        sweep += 2 * math.pi * round((approx - sweep) / (2 * math.pi))
        if abs(sweep) < 1e-12:
            segs.append(Line(_t(a), _t(b)))
            continue
        if abs(abs(sweep) - 2 * math.pi) < 1e-9 and m == 1:
            return Loop([Circle((float(c[0]), float(c[1])), float(c[2]), sweep > 0)])
        segs.append(Arc((float(c[0]), float(c[1])), float(c[2]), a1, sweep))
    return Loop(segs)


def _t(p) -> Point:
    return (float(p[0]), float(p[1]))


def _snap_lc(v, other, c) -> np.ndarray:
    """The intersection of the line (other -> v) with circle ``c`` nearest to ``v``."""
    v, o = np.asarray(v, float), np.asarray(other, float)
    d = v - o
    L = float(np.hypot(*d))
    if L < 1e-12:
        return _project(v, c)
    u = d / L
    f = o - c[:2]
    b = float(np.dot(f, u))
    disc = b * b - (float(np.dot(f, f)) - c[2] ** 2)
    if disc < 0:
        return _project(v, c)
    roots = [-b - math.sqrt(disc), -b + math.sqrt(disc)]
    best = min((o + t * u for t in roots), key=lambda q: float(np.hypot(*(q - v))))
    return best if np.hypot(*(best - v)) <= SNAP_TOL else _project(v, c)


def _snap_cc(v, c1, c2) -> np.ndarray:
    """The intersection of two circles nearest to ``v`` (projection when they do not cross)."""
    if np.allclose(c1, c2):
        return _project(v, c1)
    p1, p2 = c1[:2], c2[:2]
    dvec = p2 - p1
    D = float(np.hypot(*dvec))
    r1, r2 = c1[2], c2[2]
    if D < 1e-12 or D > r1 + r2 or D < abs(r1 - r2):
        return _project(v, c1)
    a = (r1 * r1 - r2 * r2 + D * D) / (2 * D)
    h = math.sqrt(max(0.0, r1 * r1 - a * a))
    m = p1 + a * dvec / D
    perp = np.array([-dvec[1], dvec[0]]) / D
    best = min((m + h * perp, m - h * perp), key=lambda q: float(np.hypot(*(q - v))))
    return best if np.hypot(*(best - v)) <= SNAP_TOL else _project(v, c1)


def _project(v, c) -> np.ndarray:
    d = np.asarray(v, float) - c[:2]
    L = float(np.hypot(*d))
    return c[:2] + d / L * c[2] if L > 0 else np.asarray(v, float)


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
    name to its thickness in mm (or is one number for all parts)."""
    circles = _Circles(drawing.circles)
    out = Output(title=title, drawing=drawing)
    for p in drawing.parts:
        if p.shape.is_empty():
            continue
        loops = [recover(np.asarray(poly), circles) for poly in p.shape.to_polygons()]
        t = thickness.get(p.name) if isinstance(thickness, dict) else thickness
        out.parts.append(PartOutline(p.name, p.kind, loops, t, p.shape))
    for style, item, g in drawing.strokes:
        out.engrave += _stroke(item, circles, style, g.label if g is not None else "")
    return out
