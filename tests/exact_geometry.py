"""Independent readers and exactness checks for the acceptance tests of "Exact by construction"
(tests/test_exact_output.py).

Nothing here imports the output code: files written by the writers are re-read with
independent libraries (ezdxf for DXF, svgelements for SVG) and turned into plain segments:

* :class:`L` -- a straight segment from ``start`` to ``end``;
* :class:`A` -- a circular arc from ``start`` to ``end`` about ``center`` with ``radius``,
  sweeping ``sweep`` radians (> 0 counter-clockwise);
* :class:`C` -- a full circle (a loop on its own);
* :class:`B` -- a cubic Bézier span (a spline's piece: SVG ``C``, a DXF ``SPLINE`` cut into its
  Bézier pieces by ezdxf).

:func:`loop_defects` then lists, in words, everything that keeps a loop from being exact:
gaps, zero-length segments, kinks at joins that should be tangent, radii that nobody asked for.
"""
from __future__ import annotations

import io
import math
from dataclasses import dataclass

# DXF: ezdxf writes full doubles (repr), so positions survive to ~1e-15 relative
DXF_TOL = 1e-9
# SVG: aidl_lang/output/svg.py prints coordinates with 9 decimals (`_f`: DIGITS), so a
# position re-read from SVG is good to 0.5e-9 mm, an arc's centre (from its rounded ends and
# radius, pieces of at most a quarter turn) to ~1.2e-9 mm; SVG checks use a few times that
SVG_TOL = 3e-9
# a join turning by less than this is meant to be tangent (curves do not meet at 0.06 deg
# corners by design); between this and the tangent tolerance it is a recovery error
CORNER_MIN = 1e-3


# ------------------------------------------------------------------ segments
@dataclass(frozen=True)
class L:
    start: tuple
    end: tuple

    @property
    def length(self) -> float:
        return math.dist(self.start, self.end)

    def tangent_at_start(self):
        return _unit(self.end[0] - self.start[0], self.end[1] - self.start[1])

    def tangent_at_end(self):
        return self.tangent_at_start()

    def __str__(self):
        return f"LINE {_p(self.start)} -> {_p(self.end)} (length {self.length:.12g})"


@dataclass(frozen=True)
class A:
    start: tuple
    end: tuple
    center: tuple
    radius: float
    sweep: float            # radians, > 0 counter-clockwise

    @property
    def length(self) -> float:
        return self.radius * abs(self.sweep)

    def _tangent(self, p):
        # perpendicular to the radius, in the direction of travel
        dx, dy = p[0] - self.center[0], p[1] - self.center[1]
        return _unit(-dy, dx) if self.sweep > 0 else _unit(dy, -dx)

    def tangent_at_start(self):
        return self._tangent(self.start)

    def tangent_at_end(self):
        return self._tangent(self.end)

    def __str__(self):
        return (f"ARC {_p(self.start)} -> {_p(self.end)} center {_p(self.center)} "
                f"r {self.radius:.12g} sweep {math.degrees(self.sweep):.9g} deg")


@dataclass(frozen=True)
class C:
    center: tuple
    radius: float

    @property
    def length(self) -> float:
        return 2 * math.pi * self.radius

    def __str__(self):
        return f"CIRCLE center {_p(self.center)} r {self.radius:.12g}"


@dataclass(frozen=True)
class B:
    p0: tuple
    p1: tuple
    p2: tuple
    p3: tuple

    @property
    def start(self):
        return self.p0

    @property
    def end(self):
        return self.p3

    def at(self, t: float):
        s = 1 - t
        c = (s ** 3, 3 * s * s * t, 3 * s * t * t, t ** 3)
        P = (self.p0, self.p1, self.p2, self.p3)
        return (sum(k * p[0] for k, p in zip(c, P)), sum(k * p[1] for k, p in zip(c, P)))

    @property
    def length(self) -> float:
        pts = [self.at(i / 64) for i in range(65)]
        return sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))

    def tangent_at_start(self):
        for q in (self.p1, self.p2, self.p3):
            if math.dist(q, self.p0) > 0:
                return _unit(q[0] - self.p0[0], q[1] - self.p0[1])
        return (0.0, 0.0)

    def tangent_at_end(self):
        for q in (self.p2, self.p1, self.p0):
            if math.dist(q, self.p3) > 0:
                return _unit(self.p3[0] - q[0], self.p3[1] - q[1])
        return (0.0, 0.0)

    def __str__(self):
        return f"BEZIER {_p(self.p0)} {_p(self.p1)} {_p(self.p2)} {_p(self.p3)}"


def _unit(x, y):
    n = math.hypot(x, y)
    return (x / n, y / n) if n > 0 else (0.0, 0.0)


def _p(p) -> str:
    return f"({p[0]:.12g}, {p[1]:.12g})"


def describe(segments) -> str:
    """One segment a line, for assertion messages."""
    return "\n".join(f"  [{i}] {s}" for i, s in enumerate(segments))


def arc_from_bulge(p0, p1, bulge: float) -> A:
    """The arc of an LWPOLYLINE vertex ``p0`` with ``bulge`` running to ``p1``.

    bulge = tan(sweep / 4), so sweep = 4 atan(bulge) (> 0 counter-clockwise); with the chord
    c = |p1 - p0|, the radius is r = c (1 + b^2) / (4 |b|) and the center lies on the chord's
    perpendicular bisector, c (1 - b^2) / (4 b) to the left of the chord's direction."""
    sweep = 4 * math.atan(bulge)
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    chord = math.hypot(dx, dy)
    r = chord * (1 + bulge * bulge) / (4 * abs(bulge))
    off = (1 - bulge * bulge) / (4 * bulge)          # times the chord vector, turned left
    mx, my = (p0[0] + p1[0]) / 2, (p0[1] + p1[1]) / 2
    center = (mx - dy * off, my + dx * off)
    return A(tuple(p0), tuple(p1), center, r, sweep)


def merge_cocircular(segments, tol: float):
    """Consecutive arcs on the same circle, turning the same way, as one arc (writers split
    arcs: DXF bulges over 180 degrees, SVG circles as two half arcs).  A loop that is one arc
    all the way round becomes a :class:`C`.  Lines are left alone: a split line is a finding."""
    out = []
    for s in segments:
        if out and _same_circle(out[-1], s, tol):
            a = out[-1]
            out[-1] = A(a.start, s.end, a.center, a.radius, a.sweep + s.sweep)
        else:
            out.append(s)
    if len(out) > 1 and _same_circle(out[-1], out[0], tol):          # across the loop's seam
        a, b = out[-1], out[0]
        out = [A(a.start, b.end, a.center, a.radius, a.sweep + b.sweep)] + out[1:-1]
    if len(out) == 1 and isinstance(out[0], A) and abs(abs(out[0].sweep) - 2 * math.pi) <= tol:
        out = [C(out[0].center, out[0].radius)]
    return out


def _same_circle(a, b, tol) -> bool:
    return (isinstance(a, A) and isinstance(b, A) and (a.sweep > 0) == (b.sweep > 0)
            and math.dist(a.center, b.center) <= tol and abs(a.radius - b.radius) <= tol)


# ------------------------------------------------------------------ DXF (ezdxf)
@dataclass
class Entity:
    """One DXF entity as plain segments; ``closed`` for a closed LWPOLYLINE or a CIRCLE."""
    dxftype: str
    layer: str
    closed: bool
    segments: list
    vertices: int = 0       # LWPOLYLINE vertex count


def read_dxf(path) -> list[Entity]:
    """Every LINE, ARC, CIRCLE and LWPOLYLINE of the modelspace of the DXF file ``path``, read
    with ``ezdxf.readfile``.  Co-circular consecutive bulge arcs are merged."""
    import ezdxf
    doc = ezdxf.readfile(str(path))
    out = []
    for e in doc.modelspace():
        t, layer = e.dxftype(), e.dxf.layer
        if t == "LINE":
            out.append(Entity(t, layer, False, [L(tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2])]))
        elif t == "CIRCLE":
            out.append(Entity(t, layer, True, [C(tuple(e.dxf.center)[:2], e.dxf.radius)]))
        elif t == "ARC":
            c, r = tuple(e.dxf.center)[:2], e.dxf.radius
            a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
            sweep = (a1 - a0) % (2 * math.pi) or 2 * math.pi          # DXF arcs run ccw
            at = lambda a: (c[0] + r * math.cos(a), c[1] + r * math.sin(a))  # noqa: E731
            out.append(Entity(t, layer, False, [A(at(a0), at(a1), c, r, sweep)]))
        elif t == "LWPOLYLINE":
            pts = [(x, y, b) for x, y, b in e.get_points("xyb")]
            n = len(pts)
            segs = []
            for i in range(n if e.closed else n - 1):
                x0, y0, b = pts[i]
                x1, y1, _ = pts[(i + 1) % n]
                segs.append(arc_from_bulge((x0, y0), (x1, y1), b) if b else L((x0, y0), (x1, y1)))
            segs = merge_cocircular(segs, DXF_TOL) if e.closed else segs
            out.append(Entity(t, layer, bool(e.closed), segs, n))
        elif t == "SPLINE":
            from ezdxf.math import BSpline
            bs = BSpline([tuple(v)[:2] for v in e.control_points], order=e.dxf.degree + 1,
                         knots=list(e.knots))
            segs = [B(*(tuple(p)[:2] for p in piece)) for piece in bs.bezier_decomposition()]
            closed = bool(segs) and math.dist(segs[0].start, segs[-1].end) <= DXF_TOL
            out.append(Entity(t, layer, closed, segs))
        else:
            out.append(Entity(t, layer, False, []))
    return out


# ------------------------------------------------------------------ SVG (svgelements)
def read_svg_loops(path, group: str = "cut") -> list[list]:
    """The subpaths of the ``<g id=group>`` of the SVG file ``path`` as lists of segments, in
    millimetres and the model's coordinates (the viewBox's units moved back to its corner,
    y up again).  A closing ``Z`` that adds nothing (the path
    already returned to its start) is dropped."""
    import xml.etree.ElementTree as ET

    import svgelements as se
    ET.register_namespace("", "http://www.w3.org/2000/svg")
    root = ET.parse(str(path)).getroot()
    for g in list(root):                  # keep only the group asked for
        if g.tag.endswith("}g") and g.get("id") != group:
            root.remove(g)
    # width / height in user units equal to the viewBox's: the view transform is the identity
    # (svgelements' own mm -> px factor is rounded: it scaled radii by 1.00000054)
    vb = root.get("viewBox").replace(",", " ").split()
    root.set("width", vb[2])
    root.set("height", vb[3])
    doc = se.SVG.parse(io.StringIO(ET.tostring(root, encoding="unicode")), reify=True)
    # svgelements puts the viewBox's corner at the origin: move it back, and undo the
    # writer's y flip (y_svg = -y), which also turns every arc the other way
    vx, vy = float(vb[0]), float(vb[1])

    def model(pt):
        return (pt.x + vx, -(pt.y + vy))
    loops = []
    for el in doc.elements():
        if not isinstance(el, se.Shape):
            continue
        for sub in se.Path(el).as_subpaths():
            segs = []
            for s in sub:
                if isinstance(s, se.Move):
                    continue
                p, q = model(s.start), model(s.end)
                if isinstance(s, se.Close):
                    if math.dist(p, q) <= SVG_TOL:
                        continue
                    segs.append(L(p, q))
                elif isinstance(s, se.Line):
                    segs.append(L(p, q))
                elif isinstance(s, se.Arc):
                    assert abs(s.rx - s.ry) <= SVG_TOL, f"elliptical arc rx {s.rx} ry {s.ry}"
                    segs.append(A(p, q, model(s.center), (s.rx + s.ry) / 2, -s.sweep))
                elif isinstance(s, se.CubicBezier):
                    segs.append(B(p, model(s.control1), model(s.control2), q))
                else:
                    raise AssertionError(f"unexpected SVG segment {type(s).__name__}: {s}")
            if segs:
                loops.append(merge_cocircular(segs, SVG_TOL))
    return loops


def loop_box(segments) -> tuple[float, float, float, float]:
    """(left, bottom, right, top) of ``segments`` (mm): their ends, and each arc's extreme
    points where its sweep passes them."""
    xs, ys = [], []
    for sg in segments:
        for p in (sg.start, sg.end):
            xs.append(p[0])
            ys.append(p[1])
        if isinstance(sg, A):
            a0 = math.atan2(sg.start[1] - sg.center[1], sg.start[0] - sg.center[0])
            for k in range(4):
                if ((k * math.pi / 2 - a0) * math.copysign(1, sg.sweep)) % (2 * math.pi) \
                        <= abs(sg.sweep):
                    xs.append(sg.center[0] + sg.radius * math.cos(k * math.pi / 2))
                    ys.append(sg.center[1] + sg.radius * math.sin(k * math.pi / 2))
    return min(xs), min(ys), max(xs), max(ys)


# ------------------------------------------------------------------ checks
def kink(a, b) -> float:
    """The angle (radians, 0..pi) by which the direction of travel turns where ``a`` ends and
    ``b`` starts: 0 for a tangent join."""
    (ux, uy), (vx, vy) = a.tangent_at_end(), b.tangent_at_start()
    return abs(math.atan2(ux * vy - uy * vx, ux * vx + uy * vy))


def joins(segments, closed: bool = True):
    """(index, gap, kink) for every join of consecutive segments (and the last to the first
    when ``closed``): ``gap`` is the distance from segment i's end to segment i+1's start."""
    n = len(segments)
    for i in range(n if closed else n - 1):
        a, b = segments[i], segments[(i + 1) % n]
        yield i, math.dist(a.end, b.start), kink(a, b)


def loop_defects(segments, *, closed: bool = True, tol: float = DXF_TOL,
                 tangent: str | set = "auto", kink_tol: float = DXF_TOL,
                 corner_min: float = CORNER_MIN, radii=None, radius_tol: float | None = None):
    """Everything that keeps a chain of segments from being exact, one sentence each (an empty
    list when it is exact).

    * every join closes: the gap between one segment's end and the next's start is <= ``tol``;
    * no segment is shorter than ``tol`` (a zero-length line, a sliver arc);
    * joins meant tangent turn by at most ``kink_tol`` radians.  ``tangent="all"``: every join is
      meant tangent; a set of indices: those joins (join i is segment i -> segment i+1);
      ``"auto"``: a join is either a clear corner (turning by more than ``corner_min``) or
      tangent -- a join turning by a hair (the chord of a tessellated circle left in the
      outline) is a defect; ``"none"``: no kink check;
    * with ``radii`` (the radii the program asked for), every arc's and circle's radius equals
      one of them within ``radius_tol`` (default ``tol``).
    """
    radius_tol = tol if radius_tol is None else radius_tol
    out = []
    if len(segments) == 1 and isinstance(segments[0], C):
        c = segments[0]
        if c.radius <= tol:
            out.append(f"zero-radius circle {c}")
    else:
        for i, s in enumerate(segments):
            if isinstance(s, C):
                out.append(f"[{i}] a circle inside a chain: {s}")
            elif s.length <= tol:
                out.append(f"[{i}] zero-length segment ({s.length:.3g} mm): {s}")
        for i, gap, k in joins(segments, closed):
            j = (i + 1) % len(segments)
            if gap > tol:
                out.append(f"join [{i}]->[{j}]: gap {gap:.3g} mm")
            if tangent == "none":
                continue
            meant = (tangent == "all" or (isinstance(tangent, (set, frozenset)) and i in tangent)
                     or (tangent == "auto" and k <= corner_min))
            if meant and k > kink_tol:
                out.append(f"join [{i}]->[{j}]: kink {k:.3g} rad ({math.degrees(k):.4g} deg) "
                           f"where the curves should be tangent")
    if radii is not None:
        asked = sorted(set(radii))
        for i, s in enumerate(segments):
            if isinstance(s, (A, C)):
                miss = min((abs(s.radius - r) for r in asked), default=math.inf)
                if miss > radius_tol:
                    out.append(f"[{i}] radius {s.radius:.12g} is {miss:.3g} mm from every asked "
                               f"radius {asked[:8]}{'...' if len(asked) > 8 else ''}")
    return out


def dist_to_line(p, a, b) -> float:
    """Distance from point ``p`` to the infinite line through ``a`` and ``b``."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    return abs((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / math.hypot(dx, dy)


def dist_to_circle(p, center, r) -> float:
    """Distance from point ``p`` to the circle (the curve) of ``center`` and radius ``r``."""
    return abs(math.dist(p, center) - r)


def count(segments):
    """(number of lines, number of arcs, number of circles)."""
    return (sum(isinstance(s, L) for s in segments), sum(isinstance(s, A) for s in segments),
            sum(isinstance(s, C) for s in segments))


def step_edge_points(path, samples: int, bsplines_only: bool = False) -> list:
    """Points (x, y) sampled on the edges of a STEP file's bottom face (z = 0), re-read by
    OCP (the ``step`` extra), ``samples`` + 1 per edge, ends included; ``bsplines_only``:
    only the edges OCP reads as B-spline curves.  Without OCP the calling test skips."""
    import pytest
    pytest.importorskip("OCP", reason="the step extra (OCP) is not installed")
    from OCP.BRepAdaptor import BRepAdaptor_Curve
    from OCP.GeomAbs import GeomAbs_BSplineCurve
    from OCP.STEPControl import STEPControl_Reader
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    reader = STEPControl_Reader()
    reader.ReadFile(str(path))
    reader.TransferRoots()
    out = []
    ex = TopExp_Explorer(reader.OneShape(), TopAbs_EDGE)
    while ex.More():
        ad = BRepAdaptor_Curve(TopoDS.Edge(ex.Current()))
        if not bsplines_only or ad.GetType() == GeomAbs_BSplineCurve:
            a, b = ad.FirstParameter(), ad.LastParameter()
            for i in range(samples + 1):
                q = ad.Value(a + (b - a) * i / samples)
                if abs(q.Z()) < 1e-12:                     # the bottom face's edge
                    out.append((q.X(), q.Y()))
        ex.Next()
    return out
