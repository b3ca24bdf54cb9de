"""From solved model to 2D shapes (Manifold booleans).

Closed curves become faces; lines and arcs whose endpoints meet in a cycle become one face.
A solid is the union of its faces and solid children minus its hole children; a hole is the
union of its faces; assembly children stay separate parts; drawing geometry is drawn as lines.
Booleans use ``manifold3d.CrossSection``.  Circles and arcs are tessellated so that the chord
deviation is below ``CHORD_TOL`` (0.005 mm: a 100 mm circle deviates less than 0.01 mm).

Besides the shapes, the renderer records what the exact outputs and the geometry checks need
(:class:`Drawing` fields ``circles``, ``shapes``, ``cuts``, ``own``): every circle of the
solved model (absolute center and radius, the source of arc recovery in
:mod:`aidl_lang.output.part`), the shape of every structure, and what each hole cut.
"""
from __future__ import annotations

import math
from ..records import dataclass, field

import manifold3d as mf
import numpy as np

from ..geometry.model import Geometry, Model, Structure
from ..geometry.operations import finish
from ..geometry.tessellate import segments_for
from ..geometry.text import text_strokes

CLOSE_TOL = 1e-6


@dataclass
class Part:
    name: str
    kind: str                     # solid | hole (a hole with no solid to cut)
    shape: mf.CrossSection


@dataclass
class Cut:
    """A hole child ``hole`` of the solid ``owner``: ``region`` is what it removed (mm)."""
    hole: Structure
    owner: Structure
    before: mf.CrossSection       # the owner's shape before its holes
    region: mf.CrossSection       # before ∩ hole


@dataclass
class Drawing:
    parts: list[Part] = field(default_factory=list)
    lines: list[tuple[str, np.ndarray]] = field(default_factory=list)    # (style, Nx2 polyline)
    hole_outlines: list[np.ndarray] = field(default_factory=list)
    open_curves: list[Geometry] = field(default_factory=list)
    # exact curves of the solved model, absolute: (cx, cy, r) in mm
    circles: list[tuple[float, float, float]] = field(default_factory=list)
    # engraving in exact form: ("line", p, q) | ("arc", c, r, a1, a2) | ("circle", c, r) |
    # ("poly", Nx2 closed polyline); with its style and source geometry
    strokes: list[tuple[str, tuple, Geometry | None]] = field(default_factory=list)
    shapes: dict = field(default_factory=dict)       # Structure -> its final CrossSection
    own: dict = field(default_factory=dict)          # Structure -> [(Geometry, CrossSection)]
    cuts: list[Cut] = field(default_factory=list)
    construction: list[tuple[str, tuple, Geometry | None]] = field(default_factory=list)
    part_of: dict = field(default_factory=dict)      # Part name -> its Structure
    # Part name -> thickness in mm (`thickness 3 mm`: the structure's own, an ancestor's, or
    # the file's); parts without one are missing
    thickness: dict = field(default_factory=dict)

    def bounds(self):
        xs, ys = [], []
        for p in self.parts:
            if not p.shape.is_empty():
                b = p.shape.bounds()
                xs += [b[0], b[2]]
                ys += [b[1], b[3]]
        for _, pl in self.lines:
            if len(pl):
                xs += [pl[:, 0].min(), pl[:, 0].max()]
                ys += [pl[:, 1].min(), pl[:, 1].max()]
        if not xs:
            return (0.0, 0.0, 1.0, 1.0)
        return (min(xs), min(ys), max(xs), max(ys))


class Renderer:
    def __init__(self, model: Model):
        self.m = model
        self.x = model.xs()
        self.circles: list[tuple[float, float, float]] = []

    def _circle(self, c, r) -> None:
        self.circles.append((float(c[0]), float(c[1]), float(abs(r))))

    def P(self, p) -> np.ndarray:
        ox, oy = 0.0, 0.0
        s = p.owner
        while s is not None:
            ox += self.x[s.fx]
            oy += self.x[s.fy]
            s = s.parent
        return np.array([self.x[p.ix] + ox, self.x[p.iy] + oy])

    # -------------------------------------------------------- outlines
    def arc_points(self, c, r, a1, a2) -> np.ndarray:
        sweep = (a2 - a1) % (2 * math.pi)
        if sweep < 1e-12:
            sweep = 2 * math.pi
        n = segments_for(r, sweep)
        t = a1 + np.linspace(0.0, sweep, n + 1)
        return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])

    def circle_points(self, c, r) -> np.ndarray:
        n = segments_for(r)
        t = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
        return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])

    def curve(self, g: Geometry) -> np.ndarray:
        """Polyline of an open curve (Line or Arc), from start to end."""
        if g.kind == "Line":
            return np.array([self.P(g.points["start"]), self.P(g.points["end"])])
        c, s, e = (self.P(g.points[n]) for n in ("center", "start", "end"))
        r = float(np.hypot(*(s - c)))
        self._circle(c, r)
        a1 = math.atan2(s[1] - c[1], s[0] - c[0])
        a2 = math.atan2(e[1] - c[1], e[0] - c[0])
        pts = self.arc_points(c, r, a1, a2)
        pts[0], pts[-1] = s, e
        return pts

    def face(self, g: Geometry) -> mf.CrossSection | None:
        k = g.kind
        if k == "Circle":
            r = abs(self.x[g.scalars["radius"].index])
            if r <= 0:
                return None
            c = self.P(g.points["center"])
            self._circle(c, r)
            return _cs(self.circle_points(c, r))
        if k == "Slot":
            r = abs(self.x[g.scalars["radius"].index])
            a, b = self.P(g.points["start"]), self.P(g.points["end"])
            self._circle(a, r)
            self._circle(b, r)
            pts = np.vstack([self.circle_points(a, r), self.circle_points(b, r)])
            return mf.CrossSection.hull_points(pts.tolist())
        if k == "Ellipse":
            rx, ry = (abs(self.x[g.scalars[n].index]) for n in ("rx", "ry"))
            if rx <= 0 or ry <= 0:
                return None
            c, rot = self.P(g.points["center"]), g.data.get("rotation", 0.0)
            n = segments_for(max(rx, ry))     # sagitta of a parameter step <= that of radius a
            t = np.linspace(0.0, 2 * math.pi, n, endpoint=False)
            u, v = rx * np.cos(t), ry * np.sin(t)
            cs, sn = math.cos(rot), math.sin(rot)
            return _cs(np.column_stack([c[0] + u * cs - v * sn, c[1] + u * sn + v * cs]))
        if k in ("Rectangle", "RoundedRectangle", "Triangle", "Polygon", "RegularPolygon",
                 "Trapezoid"):
            from ..geometry.primitives import points_of
            pts = np.array([self.P(p) for p in (points_of(g) if k != "Triangle" else
                                                 [g.points[n] for n in ("a", "b", "c")])])
            cs = _cs(pts)
            if k == "RoundedRectangle":
                r = float(g.data.get("corner_radius", 0.0))
                w = abs(self.x[g.scalars["width"].index])
                h = abs(self.x[g.scalars["height"].index])
                r = min(r, w / 2 - 1e-6, h / 2 - 1e-6)
                if r > 0:
                    segs = segments_for(r)
                    inner = cs.offset(-r, mf.JoinType.Miter, 2.0)
                    for poly in inner.to_polygons():       # the corner arcs' centers
                        for q in poly:
                            self._circle(q, r)
                    cs = inner.offset(r, mf.JoinType.Round, 2.0, segs)
            return cs
        return None

    # -------------------------------------------------------- structures
    def own_faces(self, s: Structure, out: Drawing) -> list:
        faces = []
        open_curves = []
        for g in s.geometry:
            if g.construction:
                self.construct(g, out)
                continue
            if s.kind == "drawing":
                self.draw_lines(g, out)
                continue
            if g.kind in ("Line", "Arc"):
                open_curves.append(g)
            elif g.kind == "Text":
                self.draw_lines(g, out)
            elif g.kind == "Point":
                continue
            else:
                f = self.face(g)
                if f is not None and not f.is_empty():
                    faces.append(f)
                    out.own.setdefault(s, []).append((g, f))
        if open_curves:
            loops, rest = self.loops(open_curves)
            for lp, chain in loops:
                f = _cs(lp)
                faces.append(f)
                out.own.setdefault(s, []).append((chain[0], f))
            for g in rest:
                out.open_curves.append(g)
                out.lines.append(("open", self.curve(g)))
                self.stroke(g, "open", out)
        return faces

    def loops(self, curves: list[Geometry]):
        """Chain open curves whose endpoints meet into closed loops."""
        polys = [self.curve(g) for g in curves]
        used = [False] * len(curves)
        loops, rest = [], []
        for i in range(len(curves)):
            if used[i]:
                continue
            chain = [i]
            used[i] = True
            pts = [polys[i]]
            start, end = polys[i][0], polys[i][-1]
            grown = True
            while grown and np.hypot(*(end - start)) > _tol(start):
                grown = False
                for j in range(len(curves)):
                    if used[j]:
                        continue
                    pj = polys[j]
                    if np.hypot(*(pj[0] - end)) <= _tol(end):
                        pts.append(pj)
                    elif np.hypot(*(pj[-1] - end)) <= _tol(end):
                        pts.append(pj[::-1])
                    else:
                        continue
                    used[j] = True
                    chain.append(j)
                    end = pts[-1][-1]
                    grown = True
                    break
            if np.hypot(*(end - start)) <= _tol(start) and len(chain) >= 2 or (
                    len(chain) == 1 and len(pts[0]) > 3 and np.hypot(*(end - start)) <= _tol(start)):
                loops.append((np.vstack([p[:-1] for p in pts]), [curves[j] for j in chain]))
            else:
                rest += [curves[j] for j in chain]
        return loops, rest

    def stroke(self, g: Geometry, style: str, out: Drawing) -> None:
        """The exact engraving stroke of a Line or Arc."""
        if g.kind == "Line":
            out.strokes.append((style, ("line", self.P(g.points["start"]), self.P(g.points["end"])), g))
            return
        c, s, e = (self.P(g.points[n]) for n in ("center", "start", "end"))
        r = float(np.hypot(*(s - c)))
        a1 = math.atan2(s[1] - c[1], s[0] - c[0])
        a2 = math.atan2(e[1] - c[1], e[0] - c[0])
        out.strokes.append((style, ("arc", c, r, a1, a2), g))

    def draw_lines(self, g: Geometry, out: Drawing) -> None:
        if g.kind in ("Line", "Arc"):
            out.lines.append(("drawing", self.curve(g)))
            self.stroke(g, "drawing", out)
        elif g.kind == "Text":
            p = self.P(g.points["position"])
            segs = text_strokes(g.data["text"], g.data["size"], g.data["anchor"],
                                g.data.get("valign", "baseline"), g.data.get("rotation", 0.0))
            if segs:      # every stroke moved to the position in one array operation
                ab = p + np.asarray(segs, dtype=float)          # k x 2 (ends) x 2 (x, y)
                for pts in ab:
                    out.lines.append(("drawing", pts))
                    out.strokes.append(("drawing", ("line", pts[0], pts[1]), g))
        elif g.kind == "Point":
            return
        elif g.kind == "Circle":
            r = abs(self.x[g.scalars["radius"].index])
            c = self.P(g.points["center"])
            self._circle(c, r)
            out.lines.append(("drawing", np.vstack([self.circle_points(c, r),
                                                    self.circle_points(c, r)[:1]])))
            out.strokes.append(("drawing", ("circle", c, r), g))
        else:
            f = self.face(g)
            if f is not None:
                for poly in f.to_polygons():
                    pl = np.asarray(poly)
                    out.lines.append(("drawing", np.vstack([pl, pl[:1]])))
                    out.strokes.append(("drawing", ("poly", pl), g))

    def shape(self, s: Structure, out: Drawing) -> mf.CrossSection:
        """Union of a solid or hole structure, holes subtracted for solids."""
        faces = self.own_faces(s, out)
        holes = []
        for c in s.children.values():
            if c.kind == "drawing":
                self.drawing(c, out)
            elif c.kind == "assembly":
                self.assembly(c, out)
            elif c.kind == "hole" and s.kind == "solid":
                holes.append((c, self.shape(c, out)))
            else:
                faces.append(self.shape(c, out))
        acc = mf.CrossSection.batch_boolean(faces, mf.OpType.Add) if faces else mf.CrossSection()
        if holes:
            cut = mf.CrossSection.batch_boolean([h for _, h in holes], mf.OpType.Add)
            for poly in (acc ^ cut).to_polygons():      # the part of each hole that cuts
                out.hole_outlines.append(np.asarray(poly))
            for c, h in holes:
                out.cuts.append(Cut(c, s, acc, acc ^ h))
            acc = acc - cut
        if getattr(s, "finish", None):
            acc = finish(s, acc, self.x)
        out.shapes[s] = acc
        return acc

    def construct(self, g: Geometry, out: Drawing) -> None:
        """Construction geometry, kept only for ``--show construction``."""
        mark = len(out.strokes), len(out.lines), len(self.circles)
        self.draw_lines(g, out)
        out.construction += out.strokes[mark[0]:]
        del out.strokes[mark[0]:], out.lines[mark[1]:], self.circles[mark[2]:]

    def children(self, s: Structure, out: Drawing) -> None:
        """The children of a drawing or an assembly: each drawn, or a separate part."""
        for c in s.children.values():
            if c.kind == "drawing":
                self.drawing(c, out)
            elif c.kind == "assembly":
                self.assembly(c, out)
            else:
                self.part(c, out)

    def drawing(self, s: Structure, out: Drawing) -> None:
        for g in s.geometry:
            if g.construction:
                self.construct(g, out)
            else:
                self.draw_lines(g, out)
        self.children(s, out)

    def assembly(self, s: Structure, out: Drawing) -> None:
        faces = self.own_faces(s, out)
        if faces:
            out.parts.append(Part(s.path, "solid", mf.CrossSection.batch_boolean(faces, mf.OpType.Add)))
            out.part_of[s.path] = s
        self.children(s, out)

    def part(self, s: Structure, out: Drawing) -> None:
        at = len(out.parts)             # a part is drawn under the parts of its drawings
        shp = self.shape(s, out)
        out.parts.insert(at, Part(s.path, s.kind, shp))
        out.part_of[s.path] = s
        if s.kind == "hole":
            for poly in shp.to_polygons():
                out.hole_outlines.append(np.asarray(poly))

    def run(self) -> Drawing:
        out = Drawing()
        root = self.m.root
        if root.kind == "assembly":
            self.assembly(root, out)
        elif root.kind == "drawing":
            self.drawing(root, out)
        else:
            self.part(root, out)
        out.circles = self.circles
        default = getattr(self.m, "thickness", None)
        for name, s in out.part_of.items():
            t = next((getattr(a, "thickness") for a in [s, *s.ancestors()]
                      if getattr(a, "thickness", None) is not None), default)
            if t is not None:
                out.thickness[name] = float(t)
        return out


def _tol(p) -> float:
    return max(1e-6, 1e-7 * float(np.max(np.abs(p))))


def _cs(pts) -> mf.CrossSection:
    pts = np.asarray(pts, dtype=float)
    if len(pts) < 3:
        return mf.CrossSection()
    return mf.CrossSection([pts.tolist()], mf.FillRule.NonZero) if _area(pts) > 0 else \
        mf.CrossSection([pts[::-1].tolist()], mf.FillRule.NonZero)


def _area(pts) -> float:
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def render_model(model: Model) -> Drawing:
    return Renderer(model).run()


def area(drawing: Drawing) -> float:
    """Total area (mm^2) of the solid parts."""
    return sum(p.shape.area() for p in drawing.parts if p.kind == "solid")
