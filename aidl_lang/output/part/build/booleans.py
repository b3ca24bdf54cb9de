"""From solved model to 2D shapes (Manifold booleans), keeping the exact curves.

Every closed shape has an exact outline (:mod:`aidl_lang.geometry.shapes.curves`, made by
:mod:`.outlines`: a slot is two lines and two half circles meeting at their tangent points, a
rounded rectangle four lines and four quarter arcs, a full round one two lines and two half
circles; lines and arcs whose endpoints meet in a cycle become one loop).  A solid is the union of its faces and solid children minus
its hole children; a hole is the union of its faces; assembly children stay separate parts;
drawing geometry is drawn as lines.  Booleans use ``manifold3d.CrossSection`` on the outlines
tessellated within ``CHORD_TOL`` (0.005 mm); :class:`~.exact.Provenance` records which exact
curve each polygon edge came from, so the result goes back onto the exact curves
(:mod:`.part`), and Fillet/Chamfer are cut on those exact loops.

Besides the shapes, the renderer records what the exact outputs and the geometry checks need
(:class:`Drawing` fields ``exact``, ``shapes``, ``cuts``, ``own``, ``empty_faces``): the
provenance of every polygon, the shape of every structure, what each hole cut, and the faces
that close on no area.
"""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ....geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Loop, Spline, carrier, reverse
from ....geometry.core.model import Geometry, Model, Structure
from ....geometry.derived.corners import SplineCorner
from ....geometry.derived.finishing import finish
from ....geometry.shapes.tessellate import CHORD_TOL
from ....geometry.shapes.text import text_strokes
from ....base.limits import DEFAULT_BUDGET, Deadline, OutOfBudget, seconds_as_work
from ..edges.exact import Provenance
from ..measure.nearby import faces_apart, meeting
from .outlines import _shoelace, _weld
from .placement import bends_of, origin_on_sheet, placement_matrix
from .result import Cut, Drawing, Part, SinkAt, SinkCall, Through
from .sunk import DEFAULT_THICKNESS, sunk_away, sunk_message
from .scanwork import TURN, TURN_BACK, plan, turned, turned_back, union_seconds
from .faces import DERIVED, Faces, _dist
from ....geometry.relations import bbox as _bbox

CLOSE_TOL = 1e-6
UNION_GROUP = 16          # faces united by one batch_boolean (Renderer.union)
# the least time per input vertex of one batch_boolean union (fuzz seed 791: 4 faces of
# 480,000 vertices in 3.5 s, 7.3 us; half of it, so that only a union sure to end past the
# deadline is refused before it starts, as the shape checks' estimates in checks/walls.py)
UNION_SECONDS_PER_VERTEX = 3.5e-6
END_CELL = 0.25           # mm: grid cell of the curve ends chained into loops (>= _tol at 1e6 mm)
# mm: half the width of the band a through-cut (a `cut` structure's open curve) takes out of
# its part where the part is analysed (what it separates, the webs it leaves): far below every
# tolerance of the output (MATCH_TOL, 1e-6 mm, puts the band's sides back on the curve), far
# above Manifold's grid (1e-8 mm)
SLIT_HALF = 2.5e-7
# mm: how far a piece a through-cut frees is grown back over the band (Booleans.slit): past
# its half of the band, short of the other piece's side (a band between two pieces cut off
# is covered twice over, the piece that stays keeps its side within MATCH_TOL of the cut)
SLIT_GROW = 1.5 * SLIT_HALF
SLIT_OFF = 1e-3    # of a band's own area: a through-cut with less of it on the material cuts nothing
HALF_TURN = ((-1.0, 0.0, 0.0), (0.0, -1.0, 0.0))    # exact: a turned union turned clockwise


class Renderer(Faces):
    """``deadline``: the compile's :class:`~aidl_lang.base.limits.Deadline`, checked between
    geometries, loops and unions (running out raises :class:`~aidl_lang.base.limits.OutOfBudget`
    naming the structure); its budget's ``vertices`` bounds the tessellated outlines."""

    STAGE = "the booleans"

    def __init__(self, model: Model | None, deadline: Deadline | None = None, x=None):
        self.m = model
        self.x = model.xs() if x is None else np.asarray(x, dtype=float)
        self._xl = self.x.tolist()          # the same floats, read faster one at a time
        self._origin: dict = {}             # id(structure) -> its frames' offset (_pt)
        self.deadline = deadline
        budget = deadline.budget if deadline is not None else DEFAULT_BUDGET
        self.exact = Provenance(max_vertices=budget.vertices)
        self.empty_faces: list = []
        self.current: Structure | None = None       # the structure being built (E0304)
        # shapes made from other shapes (Offset, Shell): their CrossSection, once each
        self.derived: dict = {}
        # (geometry, message, hint[, code]) of Offset/Shell/Hull results that cannot be made
        # (E0406) and operations that cannot stay exact on a spline (E0407)
        self.shape_errors: list = []
        self.finish_said: set = set()     # (Fillet/Chamfer call, code, corner) said (E0408, W0406)
        self.spline_source: dict = {}        # CubicSpline -> the Spline geometry drawn as it
        self.through_paths: list = []        # (geometry, exact segments) of through-cuts
        self.through: list = []
        self.sheet_cuts: list = []           # (geometry, its cut, [N x 2 polylines, mm])
        self.slit_shapes: dict = {}
        self.unfinished: dict = {}      # Structure -> its shape before its Fillet/Chamfer
        self.split: set = set()
        # id(geometry) -> the filled shapes merged into its area (masks.merge_fills): what a
        # hole of an enclosing drawing clips (masks.masked)
        self.fill_groups: dict = {}

    def tick(self, s: Structure | None = None, faces=(), watched: bool = True) -> None:
        """Look at the deadline before a step; ``faces``: the Manifold shapes one
        uninterruptible union is about to take (refused when their vertex count, or, when
        ``watched``, their scan-line work (:func:`.scanwork.union_seconds`), says it would
        end past the deadline)."""
        if self.deadline is not None:
            vertices = sum(f.num_vert() for f in faces)
            ahead = vertices * UNION_SECONDS_PER_VERTEX
            if watched and len(faces) > 1:
                ahead = max(ahead, union_seconds(faces, self.deadline.seconds_left(),
                                                 vertices))
            self.deadline.check(self.STAGE, s or self.current, seconds_as_work(ahead))

    def union(self, faces: list, s: Structure | None = None, frame: bool = False):
        """The union of ``faces``: groups of :data:`UNION_GROUP` united, then the groups'
        results, and so on.  One ``batch_boolean`` over all faces costs about vertices x
        edges crossing a scan line: 1 000 concentric circles took 10 s; in groups the inner
        ones vanish early (0.04 s).  Faces whose boxes are apart (:func:`.nearby.faces_apart`:
        a perforated sheet's holes) unite in one pass (20,000 holes: 0.27 s, not 0.95 s), the
        same polygons in the same order as in groups.  Faces in a row along x
        are united scanned along x (turned a quarter turn and back, exact:
        :func:`.scanwork.plan`): 4 000 circles of different radii on a row, 31 s scanned
        along y, 0.1 s along x.  The deadline is checked between groups (:meth:`tick`), each
        group weighed by its scan-line work when all the faces' could come near the
        deadline.  A CrossSection; ``frame=True``: (the union as scanned, turned), for
        booleans with it scanned the same way (:meth:`shape`)."""
        if not faces:
            return (mf.CrossSection(), False) if frame else mf.CrossSection()
        if len(faces) == 1:
            # one face: a CrossSection is clean as made (Clipper's union by its fill rule), and
            # a batch of one gives it back as it is; no boolean, so no vertices priced (a
            # loop's 19,000 round holes paid 400,000 work units for 19,000 batches of one)
            self.tick(s)
            return (faces[0], False) if frame else faces[0]
        left = (self.deadline.seconds_left() if self.deadline is not None
                else float("inf"))
        turn, watched = plan(faces, left)
        if turn:
            faces = turned(faces)
        # faces apart (no two boxes meet) unite in one pass: in groups every level would pass
        # them all again, for the same result (the same polygons in the same order)
        grouped = len(faces) > UNION_GROUP and not faces_apart(faces)
        while grouped and len(faces) > UNION_GROUP:
            nxt = []
            for i in range(0, len(faces), UNION_GROUP):
                self.tick(s, faces[i:i + UNION_GROUP], watched)
                nxt.append(mf.CrossSection.batch_boolean(faces[i:i + UNION_GROUP],
                                                         mf.OpType.Add))
            faces = nxt
        self.tick(s, faces, watched)
        out = mf.CrossSection.batch_boolean(faces, mf.OpType.Add)
        self.tick(s)                # a union that ended past the deadline: E0304 at ``s``
        if frame:
            return out, turn
        return turned_back(out) if turn else out

    # -------------------------------------------------------- structures
    def own_faces(self, s: Structure, out: Drawing) -> list:
        faces = []
        open_curves = []
        self.current = s
        for g in s.geometry:
            self.tick(s)
            if g.construction:
                self.construct(g, out)
                continue
            if s.kind == "drawing":
                self.draw_lines(g, out)
                continue
            if g.kind in ("Line", "Arc", "EllipticArc") or (g.kind in ("Spline", "Bezier", "Polyline")
                                             and not g.closed):
                open_curves.append(g)
            elif (g.kind == "Text" and not g.data.get("stencil") and not g.data.get("font")) or (
                    g.kind == "Intersect" and not g.closed):
                self.draw_lines(g, out)         # (a clip's pieces: lines, as a drawing's)
            elif g.kind == "Point":
                continue
            else:
                f = self.face(g, s)
                if f is not None and not f.is_empty():
                    faces.append(f)
                    out.own.setdefault(s, []).append((g, f))
                if g.kind == "Drawing2D" and g.data.get("through_paths"):
                    self._through_of_drawing(g)
                if g.kind == "Drawing2D" and len(g.data["paths"]) > g.data["engraved_from"]:
                    # its engrave role's shapes and its text: engraved on the part, as a Text
                    # in a solid is
                    for segs in self.drawing2d(g)[1][g.data["engraved_from"]:]:
                        for seg in segs:
                            self._stroke_segment(seg, "drawing", g, out)
        if open_curves:
            loops, rest = self.loops(open_curves)
            for lp, chain in loops:
                f = self._face(lp, chain[0], s)
                if f is not None and not f.is_empty():
                    faces.append(f)
                    out.own.setdefault(s, []).append((chain[0], f))
            for g in rest:
                out.open_curves.append(g)
                out.lines.append(("open", self.curve(g)))
                self.stroke(g, "open", out)
        return faces

    def loops(self, curves: list[Geometry]):
        """Chain open curves whose endpoints meet into closed exact loops: ``([(Loop, the
        curves in order)], the curves left open)``.  Where a line meets an arc, the line's end
        is the arc's exact end (the solve leaves them equal to its tolerance).  The next curve
        of a chain is the first unused one (in declaration order) with an end within
        :func:`_tol` of the chain's end, found through a grid of the curves' ends (cells of
        :data:`END_CELL` mm, at least any tolerance up to the model extent): O(n) for n
        curves, where scanning every curve at every step was O(n^2) (5 000 lines, 12 s)."""
        segs, ends, kept = [], [], []
        for g in curves:
            if g.kind in ("Spline", "Bezier", "Polyline"):
                sg = self.pieces(g)
                if not sg:
                    continue
                a, b = sg[0].start, sg[-1].end
            else:
                # a Line's or an Arc's ends: its solved points (an arc's own ends are cos/sin
                # of them), read once for the segment and the chaining
                a, b = self._pt(g.points["start"]), self._pt(g.points["end"])
                sg = [self.segment(g, a, b)]
            segs.append(sg)
            ends.append((a, b))
            kept.append(g)
        curves = kept
        grid: dict = {}
        for j, (a, b) in enumerate(ends):
            for p in (a, b):
                key = (math.floor(p[0] / END_CELL), math.floor(p[1] / END_CELL))
                lst = grid.setdefault(key, [])
                if not lst or lst[-1] != j:
                    lst.append(j)

        def near(p, tol):
            """The curves with an end in a cell within 2 tol of ``p``, in order (one cell,
            nearly always: its list is in order already)."""
            x0, x1 = math.floor((p[0] - 2 * tol) / END_CELL), math.floor((p[0] + 2 * tol) / END_CELL)
            y0, y1 = math.floor((p[1] - 2 * tol) / END_CELL), math.floor((p[1] + 2 * tol) / END_CELL)
            if x0 == x1 and y0 == y1:
                return grid.get((x0, y0), ())
            return sorted({j for cx in range(x0, x1 + 1) for cy in range(y0, y1 + 1)
                           for j in grid.get((cx, cy), ())})

        used = [False] * len(curves)
        loops, rest = [], []
        for i in range(len(curves)):
            if used[i]:
                continue
            self.tick()
            chain = [i]
            used[i] = True
            run = list(segs[i])
            start, end = ends[i]
            closes = _tol(start)          # how near the start the chain's end closes it
            grown = True
            while grown and _dist(end, start) > closes:
                grown = False
                tol = _tol(end)
                for j in near(end, tol):
                    if used[j]:
                        continue
                    if _dist(ends[j][0], end) <= tol:
                        run += segs[j]
                        end = ends[j][1]
                    elif _dist(ends[j][1], end) <= tol:
                        run += [reverse(sg) for sg in reversed(segs[j])]
                        end = ends[j][0]
                    else:
                        continue
                    used[j] = True
                    chain.append(j)
                    grown = True
                    break
            closed = _dist(end, start) <= closes
            if closed and (len(run) >= 2 or isinstance(run[0], (Arc, Spline))):
                loops.append((Loop(_weld(run)), [curves[j] for j in chain]))
            else:
                rest += [curves[j] for j in chain]
        return loops, rest

    def stroke(self, g: Geometry, style: str, out: Drawing) -> None:
        """The exact engraving stroke of a Line, Arc, Spline or open Polyline."""
        if g.kind == "Polyline":
            for ln in self.pieces(g):
                out.strokes.append((style, ("line", np.array(ln.start), np.array(ln.end)), g))
            return
        seg = self.segment(g)
        if seg is None:
            return
        self._stroke_segment(seg, style, g, out)

    def _stroke_segment(self, seg, style: str, g: Geometry, out: Drawing) -> None:
        if isinstance(seg, EllipticArc):
            self.exact.carrier_id(carrier(seg))
            out.strokes.append((style, ("ellipse_arc", seg), g))
            return
        if isinstance(seg, Spline):
            self.exact.carrier_id(carrier(seg))
            out.strokes.append((style, ("spline", seg), g))
            return
        if isinstance(seg, Line):
            out.strokes.append((style, ("line", np.array(seg.start), np.array(seg.end)), g))
            return
        out.strokes.append((style, ("arc", np.array(seg.center), seg.radius, seg.start_angle,
                                    seg.end_angle), g))

    def draw_lines(self, g: Geometry, out: Drawing, style: str = "drawing") -> None:
        """The lines of a drawing's geometry ``g`` as exact strokes of ``style`` (``drawing``:
        engraved; ``cut``: a sheet-level cut, :meth:`sheet_cut`) and as polylines; a closed
        shape with ``fill=true`` in a drawing: its area's exact loops, style ``fill``."""
        if style == "drawing" and g.data.get("fill") and g.kind != "Text":
            area = self.face(g)         # its area (a self-crossing outline: as Manifold fills)
            for lp in (self.exact.loops(area) if area is not None and not area.is_empty()
                       else []):
                pl = lp.points()
                out.lines.append(("fill", np.vstack([pl, pl[:1]])))
                out.strokes.append(("fill", ("poly", pl, lp), g))
            return
        if g.kind == "Drawing2D":
            loops, paths = self.drawing2d(g)
            for lp in loops:
                for seg in lp.segments:
                    self.exact.carrier_id(carrier(seg))
                pl = lp.points()
                out.lines.append((style, np.vstack([pl, pl[:1]])))
                out.strokes.append((style, ("poly", pl, lp), g))
            for segs in paths:
                for seg in segs:
                    self._stroke_segment(seg, style, g, out)
            return
        if g.kind == "Intersect" and not g.closed:
            for seg in self.clipped(g):
                self._stroke_segment(seg, style, g, out)
            return
        if g.kind in ("Line", "Arc", "Spline", "Bezier", "EllipticArc") or (g.kind == "Polyline" and not g.closed):
            out.lines.append((style, self.curve(g)))
            self.stroke(g, style, out)
        elif g.kind == "Text" and g.data.get("font"):    # engraved outlines (issue 112)
            if g.data.get("fill") and style == "drawing":
                style = "fill"       # its area: the union's loops, outer ccw, holes cw
            for lp in self.loops_of(g):
                for seg in lp.segments:
                    self.exact.carrier_id(carrier(seg))
                pl = lp.points()
                out.lines.append((style, np.vstack([pl, pl[:1]])))
                out.strokes.append((style, ("poly", pl, lp), g))
        elif g.kind == "Text":
            p = self.P(g.points["position"])
            along = g.data.get("along")
            if along is not None:
                segs = self.text_along(g, along)
                p = np.array(self.segment(along).center if along.kind == "Arc" else
                             self._pt(along.points["center"]))
            else:
                segs = text_strokes(g.data["text"], g.data["size"], g.data["anchor"],
                                    g.data.get("valign", "baseline"), g.data.get("rotation", 0.0))
            if segs:      # every stroke moved to the position in one array operation
                ab = p + np.asarray(segs, dtype=float)          # k x 2 (ends) x 2 (x, y)
                for pts in ab:
                    out.lines.append((style, pts))
                    out.strokes.append((style, ("line", pts[0], pts[1]), g))
        elif g.kind == "Point":
            return
        elif g.kind == "Circle":
            r = float(abs(self.x[g.scalars["radius"].index]))
            c = self.P(g.points["center"])
            circle = Circle((float(c[0]), float(c[1])), r)
            self.exact.carrier_id(carrier(circle))
            pts = Loop([circle]).points()
            out.lines.append((style, np.vstack([pts, pts[:1]])))
            out.strokes.append((style, ("circle", c, r), g))
        else:           # a Shell's band or an Offset of a shape with openings: every loop
            for lp in self.loops_of(g) if g.kind in DERIVED else [self.outline(g)]:
                if lp is None or not lp.segments:
                    continue
                for seg in lp.segments:
                    self.exact.carrier_id(carrier(seg))
                pl = lp.points()
                out.lines.append((style, np.vstack([pl, pl[:1]])))
                out.strokes.append((style, ("poly", pl, lp), g))

    def text_along(self, g: Geometry, along: Geometry) -> list:
        """The strokes of a Text along a Circle or Arc (relative to its solved center): at
        its ``angle``, else the arc's middle (a circle's top)."""
        from ....geometry.shapes.text import text_strokes_along, wraps
        flip = bool(g.data.get("flip"))
        if along.kind == "Arc":
            arc = self.segment(along)
            r, mid = arc.radius, arc.start_angle + arc.sweep / 2
        else:                                    # a circle's top (flip: its bottom)
            r, mid = float(abs(self.x[along.scalars["radius"].index])), \
                -math.pi / 2 if flip else math.pi / 2
        said = wraps(g.data["text"], g.data["size"], r)
        if said is not None and not any(e[0] is g for e in self.shape_errors):
            self.shape_errors.append((g, f"text `{g.label}` {said[0]}", said[1], "W0111"))
        ang = g.data.get("angle")
        return text_strokes_along(g.data["text"], g.data["size"], r,
                                  mid if ang is None else ang, g.data["anchor"],
                                  g.data.get("valign", "baseline"), flip)

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
            elif c.kind == "cut":           # closed curves: holes; open: through-cuts (part)
                cf = self.cut_faces(c, out)
                out.shapes[c] = self.union(cf, c)
                if cf and s.kind == "solid":
                    holes.append((c, out.shapes[c]))
            else:
                faces.append(self.shape(c, out))
        if s.kind == "solid":
            for c in s.cut_by:              # `CutInto(c, s)`: a hole of an assembly cuts s
                if c.kind == "drawing":     # (a drawing is engraved on it)
                    self.drawing(c, out)
                elif c.kind == "cut":       # (a cut's lines cut through it, its loops holes)
                    cf = self.cut_faces(c, out)
                    out.shapes[c] = self.union(cf, c)
                    if cf:
                        holes.append((c, out.shapes[c]))
                    self.current = s
                else:
                    holes.append((c, self.shape(c, out)))
        self.current = s
        acc = self.union(faces, s)
        if holes:
            # the holes cut scanned along a row as they were united (5,000 circles along x:
            # 1.05 s scanned across it, 0.03 s along it), turned clockwise (exact), where
            # Clipper gives the loops in the order it gives them scanned across
            cut, turn = self.union([h for _, h in holes], s, frame=True)
            here, back = ((acc.transform(TURN_BACK), lambda x: x.transform(TURN)) if turn
                          else (acc, lambda x: x))
            cut = cut.transform(HALF_TURN) if turn else cut
            out.hole_outlines.cut(here, cut, turned=turn)   # the part of each hole that cuts
            for c, h in holes:
                self.tick(s)
                out.cuts.append(Cut(c, s, acc, acc ^ h))
            acc = back(here - cut)
        if getattr(s, "finish", None) and not acc.is_empty():
            self.unfinished[s] = acc
            try:
                # the deadline covers the exact recovery and every loop's fillets
                said = []
                loops = finish(s, self.exact.loops_of([acc], self.deadline)[0], self.x,
                               lambda: self.tick(s), said)
                if any(r > 0 for _, r, _, _ in s.finish):     # (size 0 changes nothing)
                    acc = self.exact.section(loops)
                for call, code, i, message, hint in said:   # once per call and corner
                    if (call, code, i) not in self.finish_said:
                        self.finish_said.add((call, code, i))
                        self.shape_errors.append((call, message, hint, code))
            except SplineCorner as ex:
                g = self.spline_source.get(ex.curve)
                self.shape_errors.append((g if g is not None else s, str(ex), ex.hint, "E0407"))
        out.shapes[s] = acc
        return acc

    def construct(self, g: Geometry, out: Drawing) -> None:
        """Construction geometry, kept only for ``--show construction``."""
        mark = len(out.strokes), len(out.lines)
        self.draw_lines(g, out)
        out.construction += out.strokes[mark[0]:]
        del out.strokes[mark[0]:], out.lines[mark[1]:]

    def children(self, s: Structure, out: Drawing) -> None:
        """The children of a drawing or an assembly: each drawn, or a separate part (a hole
        that ``CutInto`` gives to a solid is drawn with it: :meth:`shape`)."""
        for c in s.children.values():
            if c.cuts_into is not None:
                continue
            if c.kind == "drawing":
                self.drawing(c, out)
            elif c.kind == "assembly":
                self.assembly(c, out)
            elif c.kind == "cut":           # a sheet-level cut
                self.sheet_cut(c, out)
            elif c.kind == "hole" and s.kind == "drawing":
                continue                    # hides the drawing's lines (:mod:`.masks`)
            else:
                self.part(c, out)

    def sheet_cut(self, c: Structure, out: Drawing) -> None:
        """A ``cut`` directly in an assembly, a sheet-level cut (language.md 2.5): each curve,
        open or closed, is cut along as drawn, in no part (``cut`` strokes whose part is "");
        each curve's polylines go to :attr:`sheet_cuts` for the check that it crosses no part
        (W0525, :func:`..checks.through.check_sheet_cuts`)."""
        for g in c.geometry:
            self.current = c
            self.tick(c)
            if g.construction:
                self.construct(g, out)
                continue
            mark = len(out.lines)
            self.draw_lines(g, out, "cut")
            if len(out.lines) > mark:
                self.sheet_cuts.append((g, c, [pts for _, pts in out.lines[mark:]]))
        for k in c.children.values():        # only cuts (E0125)
            self.sheet_cut(k, out)

    def drawing(self, s: Structure, out: Drawing) -> None:
        mark = len(out.strokes), len(out.lines)
        for g in s.geometry:
            if g.construction:
                self.construct(g, out)
            else:
                self.draw_lines(g, out)
        from .masks import merge_fills
        merge_fills(self, out, mark)
        self.children(s, out)
        masks = [c for c in s.children.values() if c.kind == "hole" and c.cuts_into is None]
        if masks:                       # engraving minus engraving (issue 95)
            from .masks import masked
            masked(self, s, masks, out, mark)

    def assembly(self, s: Structure, out: Drawing) -> None:
        faces = self.own_faces(s, out)
        if faces:
            out.parts.append(Part(s.path, "solid", self.union(faces, s)))
            out.part_of[s.path] = s
        self.children(s, out)

    def cut_faces(self, c: Structure, out: Drawing) -> list:
        """The faces of the closed curves of ``cut`` structure ``c`` and its cut children
        (each cuts a hole); its open curves (Line, Arc, an open Spline, Bezier or Polyline)
        go to :attr:`through_paths` as their exact segments, cut through the part by
        :meth:`part` (:meth:`slit`), and are drawn as ``cut`` strokes."""
        faces = []
        self.current = c
        for g in c.geometry:
            self.tick(c)
            if g.construction:
                self.construct(g, out)
                continue
            if g.kind == "Point":
                continue
            if g.kind in ("Line", "Arc", "EllipticArc") or (
                    g.kind in ("Spline", "Bezier", "Polyline") and not g.closed):
                segs = self.pieces(g)
                if segs:
                    self.through_paths.append((g, segs))
                continue
            if g.kind == "Drawing2D" and g.data.get("through_paths"):
                self._through_of_drawing(g)
            f = self.face(g, c)
            if f is not None and not f.is_empty():
                faces.append(f)
                out.own.setdefault(c, []).append((g, f))
        for k in c.children.values():        # only cuts (E0125)
            faces += self.cut_faces(k, out)
            self.current = c
        return faces

    def _through_of_drawing(self, g: Geometry) -> None:
        """The open paths of ``Drawing2D`` ``g`` that are through-cuts (its file's open chains
        on the cut role in a solid, every open chain in a ``cut``) to :attr:`through_paths`."""
        for segs in self.drawing2d(g)[1][:g.data["through_paths"]]:
            if segs:
                self.through_paths.append((g, segs))

    def slit(self, s: Structure, shp: mf.CrossSection, paths: list, out: Drawing):
        """Part ``s`` (its final shape ``shp``) cut along its through-cuts ``paths``
        (geometry, exact segments): each is drawn as ``cut`` strokes and recorded as a
        :class:`Through` whose band (:data:`SLIT_HALF` either side) stands for it.  Where the
        bands separate material (a cut from edge to edge, one that closes a loop with the
        outline, itself or another), ``shp`` less the bands falls into pieces, as under the
        laser: in each piece of the part as it was, the largest stays the part, a piece
        enclosed by another falls out (a hole) and any other is a part of its own.  Returns
        ``(the part's shape, [the shapes of the pieces cut off])``; the part's shape is
        ``shp`` itself when nothing is separated (the cuts take no area)."""
        bands, seg_bands, seg_units = [], [], []
        for g, segs in paths:
            self.tick(s)
            # the chords registered (there and back): the band's sides match the curve
            self.exact.polygon(Loop(list(segs) + [reverse(x) for x in reversed(segs)]))
            pts = _chain_points(segs)
            out.lines.append(("cut", pts))
            bands.append(self.union([_quad(pts[i], pts[i + 1], SLIT_HALF)
                                     for i in range(len(pts) - 1)], s))
            # each segment's own band (a curve of one segment: the curve's), so that every
            # segment of a Polyline, Spline or Bezier is judged as a Line would be
            units = _units(segs)
            seg_bands.append([bands[-1]] if len(units) == 1 else [
                self.union([_quad(P[i], P[i + 1], SLIT_HALF) for i in range(len(P) - 1)], s)
                for P in (_chain_points([u]) for _, u in units)])
            seg_units.append(units)
        self._collinear_runs(paths)
        # each band's area on the material: against the pieces of the part whose boxes meet
        # its own (the pieces are disjoint, so the sum is its area in the whole part; the
        # whole part for every band cost bands x the part's vertices: 5.9 s for the 2,180
        # slits of Boxes.py's Lamp sheet); and each segment's on the material more than a
        # band's width in from the outline (none: it lies along the outline, cut anyway)
        # (a curve's chords and the outline's differ: an arc on a round outline lies up to
        # CHORD_TOL inside the outline's chords, so curves are measured that much further in)
        before = shp.decompose() if not shp.is_empty() else []
        flat = [b for bs in seg_bands for b in bs]
        curved = [not isinstance(u, Line) for units in seg_units for _, u in units]
        deep, seg_deep = {}, {}
        for bent in {False, True} & set(curved):
            deep[bent] = shp.offset(-2 * SLIT_HALF - (CHORD_TOL if bent else 0.0),
                                    mf.JoinType.Miter).decompose() if before else []
            seg_deep[bent] = meeting(flat, deep[bent])
        near, seg_near = meeting(bands, before), meeting(flat, before)
        cutting = []
        at = 0
        for (g, segs), band, pieces, bs, units in zip(paths, bands, near, seg_bands,
                                                      seg_units):
            self.tick(s)
            inside = sum((band ^ before[i]).area() for i in pieces)
            th = Through(g, s, segs, band, inside)
            along = []
            for k, b in enumerate(bs, at):
                area = b.area()
                on = sum((b ^ before[i]).area() for i in seg_near[k])
                bent = curved[k]
                if on > SLIT_OFF * area and sum((b ^ deep[bent][i]).area()
                                                for i in seg_deep[bent][k]) <= SLIT_OFF * area:
                    along.append(k - at)
            at += len(bs)
            th.along = tuple(along)
            th.units = [u for _, u in units] if len(units) > len(segs) else segs
            th.on_outline = inside > 0 and len(along) == len(units)
            self.through.append(th)
            if th.on_outline:       # W0522: not drawn (the outline is cut once), cuts nothing
                continue
            cut_along = {units[k][0] for k in along}
            for k, (j, u) in enumerate(units):
                if j not in cut_along:
                    if k == 0 or units[k - 1][0] != j:
                        self._stroke_segment(segs[j], "cut", g, out)    # the segment whole
                elif k not in along:    # the rest of a segment a stretch of which is along
                    self._stroke_segment(u, "cut", g, out)              # the outline: W0522
            cutting.append(band if not along else
                           self.union([b for k, b in enumerate(bs) if k not in along], s))
        if shp.is_empty():
            return shp, []
        cut = shp - self.union(cutting, s)
        self.slit_shapes[s.path] = (shp, cut)
        after = cut.decompose()
        if len(after) <= len(before):
            return shp, []
        # Which piece of the part as it was each piece after comes from (the one it overlaps
        # most), and whether it lies inside another piece's outline: only pieces whose boxes
        # meet are intersected (one whose box misses another's shares no area with it), so a
        # sheet cut into thousands of pieces costs O(n log n) box tests, not n^2 booleans.
        groups: dict = {}
        owners = meeting(after, before)
        for a, comp in enumerate(after):
            k, most = 0, 0.0                  # the first of the largest overlaps
            for i in owners[a]:
                got = (comp ^ before[i]).area()
                if got > most:
                    k, most = i, got
            groups.setdefault(k, []).append(comp)
        removed, pieces = [], []
        for k, comps in groups.items():
            comps.sort(key=lambda c: -c.area())
            filled = [_filled(c) for c in comps]
            meets = meeting(comps, filled)
            for i, comp in enumerate(comps[1:], 1):
                self.tick(s)
                # grown back over its half of the bands (to 0.5 SLIT_HALF past the cut's
                # line): its sides on the cut, a band between two pieces cut off taken whole
                grown = comp.offset(SLIT_GROW, mf.JoinType.Miter)
                removed.append(grown)
                around = self.union([filled[j] for j in meets[i] if j != i], s)
                if (comp - around).area() <= 1e-9 * max(1.0, comp.area()):
                    continue                 # enclosed: falls out with the scrap (a hole)
                # the piece within its piece of the part's outline (exact there; not the
                # whole part: a sheet of n pieces would cost n^2), a band wholly inside it
                # (a cut that does not reach across) closed again: it cuts no area
                pieces.append(before[k] ^ grown)
        self.split.add(s.path)
        # the part less what was cut off: its sides on the cuts, the bands' other stretches
        # (cuts that end inside it) no area.  Each piece cut off taken out with its band
        # (not the piece alone): a grid of cuts left the bands between the pieces cut off
        # in the part, a net of slivers round holes where the pieces were (a 3 x 3 grid:
        # the part 20 x 20 mm with an 8-gon hole, not one 10 x 10 mm square)
        return shp - self.union(removed, s), pieces

    def _collinear_runs(self, paths: list) -> None:
        """Register, for the lines of through-cuts ``paths`` that overlap or meet end to end
        on one carrier (two slits on one line), the line of their whole run (there and
        back), so that an edge of a piece the run cuts off is held by one chord: each edge
        is matched to the chord that holds it whole (:class:`.exact.Provenance`), and an
        edge from the plate's edge across both slits to a crossing, held by neither, kept
        Manifold's vertices, 1e-7 mm off (the pieces' shared edge then on two carriers, cut
        twice)."""
        from ..edges.shared import _span
        runs: dict = {}             # carrier -> [(lo, hi, point at lo, point at hi)]
        for _, segs in paths:
            for seg in segs:
                if isinstance(seg, Line):
                    key, lo, hi, fwd, tol, _ = _span(seg)
                    if key is not None and hi - lo > tol:
                        a, b = (seg.start, seg.end) if fwd else (seg.end, seg.start)
                        runs.setdefault(key, []).append((lo, hi, a, b, tol))
        for rs in runs.values():
            if len(rs) < 2:
                continue
            rs.sort(key=lambda r: r[:2])
            merged = [list(rs[0])]
            count = [1]
            for lo, hi, a, b, tol in rs[1:]:
                if lo <= merged[-1][1] + tol:
                    count[-1] += 1
                    if hi > merged[-1][1]:
                        merged[-1][1], merged[-1][3] = hi, b
                else:
                    merged.append([lo, hi, a, b, tol])
                    count.append(1)
            for (_, _, a, b, _), n in zip(merged, count):
                if n > 1:
                    self.exact.polygon(Loop([Line(a, b), Line(b, a)]))

    def part(self, s: Structure, out: Drawing) -> None:
        at = len(out.parts)             # a part is drawn under the parts of its drawings
        mark = len(self.through_paths)
        shp = self.shape(s, out)
        paths = self.through_paths[mark:]
        del self.through_paths[mark:]
        pieces = []
        if paths:
            shp, pieces = self.slit(s, shp, paths, out)
        out.parts.insert(at, Part(s.path, s.kind, shp))
        out.part_of[s.path] = s
        for k, piece in enumerate(pieces, 1):      # what its through-cuts freed: parts
            name = f"{s.path}.piece{k}"
            out.parts.insert(at + k, Part(name, s.kind, piece))
            out.part_of[name] = s
            self.split.add(name)
        if s.kind == "hole":
            out.hole_outlines.cut(shp, None)

    def run(self) -> Drawing:
        out = Drawing()
        root = self.m.root
        try:
            if root.kind == "assembly":
                self.assembly(root, out)
            elif root.kind == "drawing":
                self.drawing(root, out)
            else:
                self.part(root, out)
        except OutOfBudget as ex:           # the vertex count knows no structure: this one
            if ex.where is None:
                ex.where = self.current
            raise
        out.exact = self.exact
        out.empty_faces = self.empty_faces
        out.through, out.slit_shapes = self.through, self.slit_shapes
        out.unfinished = self.unfinished
        out.sheet_cuts = self.sheet_cuts
        out.split = frozenset(self.split)
        out.shape_errors = self.shape_errors
        out.spline_source = self.spline_source
        out.kerf, out.min_wall = {}, {}
        for word, into in (("thickness", out.thickness), ("kerf", out.kerf),
                           ("min_wall", out.min_wall)):
            default = getattr(self.m, word, None)
            for name, s in out.part_of.items():
                t = next((getattr(a, word) for a in [s, *s.ancestors()]
                          if getattr(a, word, None) is not None), default)
                if t is not None:
                    into[name] = float(t)
        if any(getattr(s, "placement", None) is not None for s in self.m.structures):
            out.placement = {name: placement_matrix(s, self.x) for name, s in out.part_of.items()}
            # where each part's own (0, 0) lies on the sheet: what its `Place` moves
            out.origins = {name: origin_on_sheet(s, self.x) for name, s in out.part_of.items()}
        out.bends = {n: b for n, s in out.part_of.items() if (b := bends_of(s, self.x))}
        for s in out.part_of.values():
            s.moved = self.moved(s)     # where the checks say positions as written
        out.sinks = self.sinks(out)
        return out

    def moved(self, s: Structure) -> tuple[float, float]:
        """How far the solve moved part ``s`` from where it is written: the sum of its and
        its ancestors' frame offsets (mm; a layout relation, `RightOf(b, a)`).  Kept on the
        part (``s.moved``) for the checks' messages (:func:`..checks.common.written`)."""
        chain = [s, *s.ancestors()]
        return (float(sum(self.x[a.fx] for a in chain if a.fx >= 0)),
                float(sum(self.x[a.fy] for a in chain if a.fy >= 0)))

    def sinks(self, out: Drawing) -> list[SinkAt]:
        """Each round hole a ``Countersink`` / ``Counterbore`` names, at its solved place:
        :class:`~.result.SinkAt` (its part: the solid the hole cuts)."""
        if not getattr(self.m, "sinks", None):
            return []
        part = {}
        for name, s in out.part_of.items():
            part.setdefault(id(s), name)
        got = []
        for sk in self.m.sinks:
            for g in sk.circles:
                name = next((part[id(a)] for a in g.owner.held_by() if id(a) in part), None)
                if name is None:
                    continue
                r = abs(self.x[g.scalars["radius"].index])
                got.append(SinkAt(sk.kind, name, g.label, self._pt(g.points["center"]),
                                  2 * float(r), sk.diameter, sk.angle, sk.depth, sk.span))
        shapes = {p.name: p.shape for p in out.parts if p.kind == "solid"}
        for name in dict.fromkeys(a.part for a in got):     # E0503: heads that leave nothing
            t = out.thickness.get(name) or DEFAULT_THICKNESS
            found = sunk_away(shapes.get(name), [(a.center, a) for a in got if a.part == name],
                              t)
            if found is not None:
                message, hint = sunk_message(name, found, t)
                self.shape_errors.append((SinkCall(found[2].span, out.part_of[name]), message,
                                          hint, "E0503"))
        return got


def _units(segs: list) -> list:
    """``[(index of the segment, piece)]``: the pieces of the exact open segments ``segs``
    that the through-cut checks judge one by one: each segment, an open Spline's (a Bezier's)
    one per span, so that a Bezier's span on the outline is judged as a Polyline's side."""
    out = []
    for j, seg in enumerate(segs):
        if isinstance(seg, Spline) and not seg.curve.closed:
            lo, hi = sorted((seg.u0, seg.u1))
            at = [lo] + [float(i) for i in range(math.floor(lo) + 1, math.ceil(hi))] + [hi]
            if len(at) > 2:
                pairs = list(zip(at, at[1:]))
                out += [(j, Spline(seg.curve, a, b)) for a, b in pairs] if seg.u1 >= seg.u0 \
                    else [(j, Spline(seg.curve, b, a)) for a, b in reversed(pairs)]
                continue
        out.append((j, seg))
    return out


def _chain_points(segs: list) -> np.ndarray:
    """The polyline (N x 2, mm) of a chain of exact open segments, from the first start to
    the last end (arcs and curves in chords within CHORD_TOL)."""
    pts = []
    for seg in segs:
        if isinstance(seg, Line):
            pts.append(np.asarray([seg.start], dtype=float))
        else:
            pts.append(np.asarray(Loop([seg]).points(), dtype=float).reshape(-1, 2))
    pts.append(np.asarray([segs[-1].end], dtype=float))
    return np.vstack(pts)


def _quad(p, q, h: float) -> mf.CrossSection:
    """The rectangle ``2 h`` wide along the chord ``p`` -> ``q``, ``h`` longer at each end
    (consecutive chords' rectangles overlap at their joint; a cut ending on an edge crosses
    it)."""
    d = np.asarray(q, dtype=float) - np.asarray(p, dtype=float)
    L = float(np.hypot(*d))
    if L == 0:
        return mf.CrossSection()
    u = d / L * h
    n = np.array([-u[1], u[0]])
    a, b = np.asarray(p, dtype=float) - u, np.asarray(q, dtype=float) + u
    return mf.CrossSection([[tuple(a - n), tuple(b - n), tuple(b + n), tuple(a + n)]])


def _filled(c: mf.CrossSection) -> mf.CrossSection:
    """``c`` with its holes filled: the region inside its outer contours."""
    outer = [P for P in c.to_polygons() if _shoelace(np.asarray(P)) > 0]
    return mf.CrossSection(outer, mf.FillRule.NonZero) if outer else mf.CrossSection()


def _tol(p) -> float:
    return max(1e-6, 1e-7 * max(abs(p[0]), abs(p[1])))


def render_model(model: Model, deadline: Deadline | None = None) -> Drawing:
    """The booleans' :class:`Drawing` of a solved ``model``; ``deadline``: see
    :class:`Renderer` (raises :class:`~aidl_lang.base.limits.OutOfBudget`)."""
    return Renderer(model, deadline).run()


def shape_box(g: Geometry, x) -> tuple[float, float, float, float] | None:
    """(left, right, bottom, top) in mm, in the root frame, of the exact outline that the
    booleans draw for shape ``g`` at the parameter values ``x`` (a clipping ``Intersect``:
    its clipped pieces); None when it draws nothing there.  Registered with
    :mod:`aidl_lang.geometry.relations.bbox` (``DRAWN_BOX``), which boxes an ``Inset``, a
    miter ``Offset``, a flat-capped ``Stroke`` and an ``Intersect`` by it (docs/language.md,
    "Members are the drawn geometry")."""
    r = Renderer(None, x=x)
    try:
        if g.kind == "Intersect" and not g.closed:
            segs = r.clipped(g)
        else:
            segs = [sg for lp in r.loops_of(g) for sg in lp.segments]
    except Exception:           # noqa: BLE001 (a shape that cannot be made: E0406 later)
        return None
    if not segs or r.shape_errors:
        return None
    boxes = [sg.box() for sg in segs]
    return (min(b[0] for b in boxes), max(b[2] for b in boxes),
            min(b[1] for b in boxes), max(b[3] for b in boxes))


_bbox.DRAWN_BOX = shape_box


def area(drawing: Drawing) -> float:
    """Total area (mm^2) of the solid parts."""
    return sum(p.shape.area() for p in drawing.parts if p.kind == "solid")
