"""The faces of one geometry, the part of the booleans (:class:`~.booleans.Renderer`) that
reads a single shape: its exact curves (points at their frames' offset, outlines, splines,
elliptic arcs, a ``Drawing2D``'s loops, strokes and clipped lines) and its Manifold face,
tessellated within ``CHORD_TOL`` with each polygon edge's exact curve recorded
(:class:`~..edges.exact.Provenance`); the shapes made of other shapes' pieces (``Offset``,
``Shell``, ``Stroke``, ``Intersect``: :data:`DERIVED`) are built here once each.  The tree walk,
the unions and the cuts are :mod:`.booleans`'.
"""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ....geometry.shapes.curves import Circle, EllipticArc, Line, Loop, Spline, reverse
from ....geometry.shapes.ellipse import ellipse
from ....geometry.core.model import Geometry, Structure
from ....geometry.derived.hull import hull_loop
from ....geometry.derived.offset import offset_pieces
from ....geometry.shapes.biarc import as_arcs
from ....geometry.shapes.composites import region_of
from .outlines import (_arc_through, _band, _polygon, arc_slot_outline, rounded_outline,
                       rounded_outline_radii, sector_outline, slot_outline, spline_band)

DERIVED = ("Offset", "Shell", "Stroke", "Intersect")   # outlines that are booleans of pieces


class Faces:
    """The geometry-by-geometry half of :class:`~.booleans.Renderer` (a base of it): reads
    ``self.x``, ``self.exact``, ``self.derived``, ``self.shape_errors``, ``self.spline_source``
    and the deadline that the renderer sets up."""

    def P(self, p) -> np.ndarray:
        """Point ``p``'s solved position in the root frame (mm), as an array."""
        return np.array(self._pt(p))

    def _pt(self, p) -> tuple[float, float]:
        """Point ``p``'s solved position in the root frame (mm): its coordinates plus the
        frame shifts of its structure and their parents, added innermost first."""
        x = self._xl
        o = self._origin.get(id(p.owner))
        if o is None:                       # the sums of its frames, once per structure
            ox, oy = 0.0, 0.0
            s = p.owner
            while s is not None:
                ox += x[s.fx]
                oy += x[s.fy]
                s = s.parent
            o = self._origin[id(p.owner)] = (ox, oy)
        return (x[p.ix] + o[0], x[p.iy] + o[1])

    # -------------------------------------------------------- exact outlines
    def spline(self, g: Geometry) -> Spline | None:
        """The exact :class:`Spline` segment of a ``Spline`` geometry at the solved points:
        the whole curve (closed or open); None when the solved points give no spline (two
        consecutive ones moved onto each other)."""
        from ....geometry.shapes.spline import SplineError, bezier_chain, interpolate
        from ....geometry.relations.members import points_of
        try:
            pts = [self._pt(p) for p in points_of(g)]
            if g.kind == "Bezier":          # the control points as given (closed: back to p0)
                c = bezier_chain(pts + pts[:1] if g.closed else pts, g.closed)
            else:
                c = interpolate(pts, bool(g.data.get("closed")), g.data.get("corners", ()))
        except SplineError as ex:
            if not any(e[0] is g for e in self.shape_errors):     # said once, at the call
                self.shape_errors.append((g, f"`{g.label}` after the solve: {ex}",
                                          "a constraint moved the points onto each other: "
                                          "keep consecutive points apart", "E0108"))
            return None
        if g.kind == "Spline" and c not in self.spline_source and not any(
                u.kind == "drawing" for u in (g.owner, *g.owner.ancestors())):
            self._swung(g, c)           # (an engraved wave may mean its swing)
        self.spline_source.setdefault(c, g)
        return Spline(c, 0.0, float(c.n))

    def _swung(self, g: Geometry, c) -> None:
        """W0412 for a Spline whose curve swings off a straight run of its points
        (:func:`~aidl_lang.geometry.shapes.spline.strays`), once per curve."""
        from ....geometry.shapes.spline import strays
        m = c.n + (0 if c.closed else 1)
        corners = sorted({k % m for k in g.data.get("corners", ()) or ()})
        found = strays(c, corners)
        if not found or any(e[0] is g for e in self.shape_errors):
            return
        i, far, sharp = found[0]
        more = len(found) - 1
        j = (i + 1) % m
        self.shape_errors.append((g, (
            f"`{g.label}` swings {far:.3g} mm off the straight run of its points between "
            f"points[{i}] and points[{j}]" + (f" (and in {more} more place{'s' * (more > 1)})"
                                              if more else "")
            + f": a smooth curve through the points overshoots there to round the turn at "
            f"points[{sharp}]"), (
            f"to keep the run straight, add a point where the turn begins, so the curve has "
            f"room to round it, make points[{sharp}] a corner (`corners="
            f"{sorted(set(corners) | {sharp})}`), or draw the outline as a Polygon rounded "
            f"by `Fillet` (its sides stay straight); a spline passes through its points, not "
            f"between them in straight lines"), "W0412"))

    def segment(self, g: Geometry, start=None, end=None):
        """The exact segment of an open curve (a Line, an open Spline, or an Arc
        counter-clockwise from its start to its end point on the circle through its start);
        ``start``, ``end``: a Line's or an Arc's solved end points, when already read."""
        if g.kind in ("Spline", "Bezier"):
            return self.spline(g)
        if g.kind == "EllipticArc":
            return self.elliptic_arc(g)
        pts = g.points
        if start is None:
            start, end = self._pt(pts["start"]), self._pt(pts["end"])
        if g.kind == "Line":
            return Line(start, end)
        return _arc_through(self._pt(pts["center"]), start, end)

    def elliptic_arc(self, g: Geometry) -> EllipticArc:
        """The exact arc of an ``Ellipse(..., start_angle=, end_angle=)`` at its solved
        points: the ellipse of its center, vertex and co-vertex, from its start through its
        midpoint to its end (a mirrored copy runs clockwise)."""
        from ....geometry.shapes.curves import elliptic_arc
        c, v, w, s0, m, e = (self._pt(g.points[n]) for n in
                             ("center", "vertex", "co_vertex", "start", "midpoint", "end"))
        arc = elliptic_arc(c, math.dist(c, v), math.dist(c, w),
                           math.atan2(v[1] - c[1], v[0] - c[0]), s0, m, e)
        self.spline_source.setdefault(arc.curve, g)    # located refusals name the Ellipse
        return arc

    def pieces(self, g: Geometry) -> list:
        """The exact segments of an open curve in order: a Polyline's lines, else the one
        :meth:`segment` (none when it has none)."""
        if g.kind == "Polyline":
            from ....geometry.relations.members import points_of
            P = [self._pt(p) for p in points_of(g)]
            return [Line(P[i], P[i + 1]) for i in range(len(P) - 1)]
        seg = self.segment(g)
        return [] if seg is None else [seg]

    def curve(self, g: Geometry) -> np.ndarray:
        """Polyline of an open curve (Line, Arc, Spline or Polyline), from start to end."""
        if g.kind == "Polyline":
            from ....geometry.relations.members import points_of
            return np.array([self.P(p) for p in points_of(g)])
        seg = self.segment(g)
        if seg is None:
            return np.zeros((0, 2))
        if isinstance(seg, Line):
            return np.array([seg.start, seg.end])
        pts = Loop([seg]).points()
        return np.vstack([pts, [seg.end]])

    def outline(self, g: Geometry) -> Loop | None:
        """The exact closed outline of a shape (any orientation), or None when it has none."""
        k = g.kind
        if k in ("Spline", "Bezier"):
            seg = self.spline(g) if g.closed else None
            if seg is None:
                return None
            from ....geometry.shapes.spline import self_crossings
            cross = self_crossings(seg.curve, self.tick)
            if cross:
                x, y = seg.curve.at(cross[0][0])
                if not any(e[0] is g for e in self.shape_errors):
                    self.shape_errors.append((g, (
                        f"`{g.label}` crosses itself at ({x:g}, {y:g}) mm: a closed {k} "
                        f"outline must not loop over itself (its inside would be ambiguous)"),
                        "move or reorder the points so that the curve goes round once "
                        "without crossing", "E0108"))
                return None
            return Loop([seg])
        if k == "Circle":
            r = abs(self.x[g.scalars["radius"].index])
            return Loop([Circle(self._pt(g.points["center"]), float(r))]) if r > 0 else None
        if k == "Slot":
            r = float(abs(self.x[g.scalars["radius"].index]))
            if r <= 0:
                return None
            return Loop(slot_outline(self._pt(g.points["start"]), self._pt(g.points["end"]), r))
        if k == "Ellipse":
            rx, ry = (abs(self.x[g.scalars[n].index]) for n in ("rx", "ry"))
            if rx <= 0 or ry <= 0:
                return None
            from ....geometry.relations.bbox import held_rotation
            c, rot = self._pt(g.points["center"]), held_rotation(g, self.x)
            if rx == ry:
                return Loop([Circle(c, float(rx))])
            curve, _ = ellipse(c, float(rx), float(ry), float(rot))
            self.spline_source.setdefault(curve, g)       # located refusals name the Ellipse
            return Loop([EllipticArc(curve, 0.0, 2 * math.pi)])
        if k == "Drawing2D":
            loops = self.drawing2d(g)[0]
            return loops[0] if len(loops) == 1 else None
        if k == "ArcSlot":
            # the solved start (a copy's is turned or mirrored with it), counter-clockwise
            c, s = self._pt(g.points["center"]), self._pt(g.points["start"])
            a1, sweep = math.atan2(s[1] - c[1], s[0] - c[0]), g.data["angles"][1]
            d = g.data["dims"]
            return Loop(arc_slot_outline(c, d["radius"], d["width"] / 2, a1, sweep))
        if k == "Sector":
            # from the solved midpoint: a copy turned or mirrored (a pattern, Mirrored) has
            # its midpoint turned or mirrored with it, and the sweep is the original's
            c, m = self._pt(g.points["center"]), self._pt(g.points["midpoint"])
            sweep = g.data["angles"][1]
            a1 = math.atan2(m[1] - c[1], m[0] - c[0]) - sweep / 2
            return Loop(sector_outline(c, g.data["dims"]["radius"],
                                       g.data["dims"]["inner_radius"], a1, sweep))
        if k == "Hull":             # (a Point: a loop of one line of no length, its site;
            return hull_loop([lp for src in g.data["sources"] for lp in (   # a Line or an
                [Loop([Line(self._pt(src.points["p"]), self._pt(src.points["p"]))])]
                if src.kind == "Point" else [self._closed(self.segment(src))]   # Arc closed
                if src.kind in ("Line", "Arc") else self.loops_of(src))])       # by its chord)
        if k in DERIVED:
            loops = self.loops_of(g)
            return loops[0] if len(loops) == 1 else None
        if k == "RoundedRectangle" and g.data.get("corner_radii"):
            from ....geometry.relations.members import points_of
            return Loop(rounded_outline_radii([self.P(p) for p in points_of(g)],
                                              g.data["corner_radii"]))
        if k in ("Rectangle", "RoundedRectangle", "Triangle", "Polygon", "RegularPolygon",
                 "Trapezoid", "Star") or (k == "Polyline" and g.closed):
            from ....geometry.relations.members import points_of
            pts = np.array([self.P(p) for p in (points_of(g) if k != "Triangle" else
                                                 [g.points[n] for n in ("a", "b", "c")])])
            if k == "RoundedRectangle":
                r = float(g.data.get("corner_radius", 0.0))
                if r > 0:
                    return Loop(rounded_outline(pts, r))
            if k == "Star" and g.data.get("tip"):
                # rounded tips (tip_radius=): each tip an exact arc tangent to its sides,
                # the notches (odd points) sharp
                from .outlines import star_outline
                return Loop(star_outline(pts, g.data["dims"]["tip_radius"]))
            return _polygon(pts)
        return None

    def drawing2d(self, g: Geometry) -> tuple[list[Loop], list[list]]:
        """The exact loops (holes clockwise) and open paths of a ``Drawing2D`` at its solved
        origin."""
        from ....geometry.relations.bbox import held_turn
        from ....geometry.shapes.drawing2d import copied, moved
        ox, oy = self._pt(g.points["origin"])
        held, held_paths = g.data["loops"], g.data["paths"]
        turn = held_turn(g, self.x) if g.data.get("mirror_lines") else 0.0
        if abs(turn) > 1e-15:           # mirrored about a line the solve turned
            held, held_paths = copied(held, held_paths, turn, None)
        loops = [Loop(moved(lp.segments, ox, oy)) for lp in held]
        paths = [moved(p, ox, oy) for p in held_paths]
        for lp in loops:
            for sg in lp.segments:
                if isinstance(sg, Spline):
                    self.spline_source.setdefault(sg.curve, g)
        return loops, paths

    @staticmethod
    def _closed(seg) -> Loop:
        """An open Line or Arc ``seg`` closed by the chord back to its start (the region whose
        hull is its hull)."""
        return Loop([seg, Line(seg.end, seg.start)])

    def loops_of(self, g: Geometry) -> list[Loop]:
        """The exact outline of a shape as loops: outer ones counter-clockwise, holes
        clockwise (a shape made by Offset or Shell may have several; others have one)."""
        if g.kind == "Drawing2D":
            return self.drawing2d(g)[0]
        if g.kind == "Text" and (g.data.get("stencil") or g.data.get("font")):
            sec = self.face(g)
            return self.exact.loops(sec) if sec is not None else []
        if g.kind in DERIVED:
            sec = self.derived_section(g)
            return self.exact.loops(sec) if sec is not None else []
        lp = self.outline(g)
        if lp is None or not lp.segments:
            return []
        return [lp.reversed() if lp.area < 0 else lp]

    def derived_section(self, g: Geometry) -> mf.CrossSection | None:
        """The shape of an ``Offset`` or ``Shell`` (cached): its source's shape with the
        sweeps of :func:`~aidl_lang.geometry.derived.offset.offset_pieces` added (outward) or cut
        (inset), all exact loops, so :mod:`.exact` puts the result back on the offset lines
        and arcs; None (and an E0406 in :attr:`shape_errors`) when nothing is left."""
        if id(g) in self.derived:
            return self.derived[id(g)]
        self.derived[id(g)] = None                 # (a cycle cannot be written; be safe)
        if g.kind == "Stroke":
            out = self._stroke(g)
            self.derived[id(g)] = out
            return out
        if g.kind == "Intersect":
            out = self._common(g)
            self.derived[id(g)] = out
            return out
        srcs = g.data["sources"]
        src = srcs[0]
        loops = self.loops_of(src)
        base = self.exact.section(loops) if loops else mf.CrossSection()
        if len(srcs) > 1:               # `Inset([a, b], d)`: the offset of their union
            base = self.union([base] + [self.exact.section(lp) for lp in
                                        (self.loops_of(o) for o in srcs[1:]) if lp])
            loops = self.exact.loops(base)
        join = g.data.get("join", "round")
        if g.kind == "Offset":
            d = g.data["distance"]
            out = self._offset(base, loops, d, join)
        else:
            t = g.data["thickness"]
            moved = self._offset(base, loops, t, join)
            out = moved - base if t > 0 else base - moved
            if t < 0 and moved.is_empty():
                out = mf.CrossSection()
        if out.is_empty() and not base.is_empty():
            what = "distance" if g.kind == "Offset" else "thickness"
            v = g.data[what]
            self.shape_errors.append((g, (
                f"`{g.label}`: an inset of {abs(v):g} mm leaves nothing of "
                f"{' and '.join(f'`{o.label}`' for o in srcs[:3])}: "
                f"the shape is nowhere more than {2 * abs(v):g} mm across"),
                f"use a smaller {what}: an inset removes a band {abs(v):g} mm wide along the "
                f"whole outline" + ("" if g.kind == "Offset" else
                                    "; a Shell that fills the shape is the shape itself")))
            out = None
        self.derived[id(g)] = out
        return out

    def _common(self, g: Geometry) -> mf.CrossSection | None:
        """The area an ``Intersect``'s closed shapes have in common (Manifold's intersection
        of their exact sections, put back on their exact curves by :mod:`.exact`); None and
        an E0406 at the call when they have none."""
        region = region_of(g)[0]
        out = None
        boxes = []
        for src in region:
            loops = self.loops_of(src)
            sec = self.exact.section(loops) if loops else mf.CrossSection()
            boxes.append(sec.bounds() if not sec.is_empty() else None)
            out = sec if out is None else out ^ sec
        if out is None or out.is_empty() or out.area() <= 1e-12:
            # which copy of a loop's, and where each shape lies (run cd: a 17th stripe past
            # its band's end, "`sign.stripes.st`" for all 17)
            twins = [h for h in g.owner.geometry if h.span == g.span and h.name == g.name]
            label = g.label + (f"[{twins.index(g)}]" if len(twins) > 1 and g in twins else "")
            names = ", ".join(f"`{s.label}`" + (f" (x {b[0]:.6g}..{b[2]:.6g}, y {b[1]:.6g}.."
                                                 f"{b[3]:.6g})" if b is not None else "")
                              for s, b in zip(region, boxes))
            self.shape_errors.append((g, (
                f"`{label}`: {names} have no area in common: the Intersect is empty"),
                "place the shapes so that they overlap (an Intersect keeps only the area "
                "inside all of them)"))
            return None
        return out

    def clipped(self, g: Geometry) -> list:
        """The exact pieces of a clipping ``Intersect``'s open curves that lie inside the
        common area of its closed shapes: each curve cut where it crosses the area's
        outline (exact crossings of the carriers), a piece kept when its middle is inside."""
        from ....geometry.derived.clip import clip
        region, curves = region_of(g)
        if len(region) == 1:
            loops = self.loops_of(region[0])
        else:
            sec = self._common(g)
            loops = self.exact.loops(sec) if sec is not None else []
        return clip([seg for src in curves for seg in self.pieces(src)], loops)

    def stroke_path(self, g: Geometry) -> list:
        """The exact segments of a Stroke's path in order, each piece turned to start where
        the previous one ends."""
        chain: list = []
        for src in g.data["sources"]:
            segs = self.pieces(src)
            if not segs:
                continue
            if chain:
                end = chain[-1].end
                if _dist(segs[-1].end, end) < _dist(segs[0].start, end):
                    segs = [reverse(sg) for sg in reversed(segs)]
            elif len(g.data["sources"]) > 1:
                nxt = self.pieces(g.data["sources"][1])
                if nxt:
                    far = min(_dist(segs[0].start, p) for p in (nxt[0].start, nxt[-1].end))
                    near = min(_dist(segs[-1].end, p) for p in (nxt[0].start, nxt[-1].end))
                    if far < near:
                        segs = [reverse(sg) for sg in reversed(segs)]
            chain += segs
        return chain

    def _stroke(self, g: Geometry) -> mf.CrossSection | None:
        """The band of a ``Stroke``: the union of every path segment's sweep by a disc of
        radius width/2 (:func:`~aidl_lang.geometry.derived.offset.sweep_loops`: stadiums, arc slots);
        with flat caps the first and last segments are swept square at the free end (a
        rectangle, an annulus segment) and a disc keeps the join round.  Exact lines and
        arcs; a Spline piece's band is :func:`.outlines.spline_band` (within
        :data:`.outlines.STROKE_TOL`; a bend tighter than width/2 is E0108 at the call)."""
        from ....geometry.derived.offset import sweep_loops
        from ....geometry.shapes.spline import SplineError
        h = g.data["width"] / 2
        path = self.stroke_path(g)
        if not path:
            return None
        flat = g.data.get("cap") == "flat"
        loops: list = []
        n = len(path)
        for i, sg in enumerate(path):
            free = (flat and i == 0, flat and i == n - 1)
            if isinstance(sg, Spline):
                try:
                    loops.append(spline_band(sg, h, free))
                except SplineError as ex:
                    self.shape_errors.append((g, f"`{g.label}`: {ex}",
                                              "use a smaller width, or smooth the path "
                                              "(points further apart)", "E0108"))
                    return None
                continue
            if not any(free):
                loops += sweep_loops(sg, h)
                continue
            band = _band(sg, h)
            if band is None:
                self.shape_errors.append((g, (
                    f"`{g.label}`: an arc of radius {sg.radius:g} mm in the path is tighter "
                    f"than half the width ({h:g} mm): a flat end cannot be cut square there"),
                    'use cap="round", a smaller width or a wider arc', "E0108"))
                return None
            loops.append(band)
            for k, p in ((0, sg.start), (1, sg.end)):
                if not free[k]:
                    loops.append(Loop([Circle(p, h)]))
        faces = [self.exact.face(lp) for lp in loops]
        return self.union(faces)

    def _offset(self, base, loops, d: float, join: str) -> mf.CrossSection:
        if d == 0 or base.is_empty():
            return base
        # an ellipse or a spline is offset as its biarcs (the offset of an ellipse is no
        # ellipse, of a cubic no cubic): within geometry.biarc.BIARC_TOL of the true offset
        loops = [as_arcs(lp)[0] for lp in loops]
        pieces = [self.exact.face(lp) for lp in offset_pieces(loops, d, join)]
        band = self.union(pieces)
        return base + band if d > 0 else base - band

    def font_text(self, g: Geometry) -> tuple[list[Loop], list[Loop]]:
        """The exact loops of a Text in a font at its solved position (outer loops
        counter-clockwise; glyphs may overlap) and, for a stencil, its bridges."""
        from ....geometry.shapes.drawing2d import moved
        from ....geometry.shapes.text_outlines import bridges, local_loops
        ox, oy = self._pt(g.points["position"])
        along = g.data.get("along")
        if along is not None:             # about the curve's solved center and radius
            from ....geometry.shapes import font as F
            flip = bool(g.data.get("flip"))
            if along.kind == "Arc":
                arc = self.segment(along)
                (ox, oy), r, mid = arc.center, arc.radius, arc.start_angle + arc.sweep / 2
            else:
                r = float(abs(self.x[along.scalars["radius"].index]))
                mid = -math.pi / 2 if flip else math.pi / 2
            ang = g.data.get("angle")
            from ....geometry.shapes.text_outlines import along_loops
            local = along_loops(g, r, mid if ang is None else ang)
            bands = along_loops(g, r, mid if ang is None else ang, bands=True) \
                if g.data.get("stencil") else []
            wide = F.width(F.shaped(g.data["font"], g.data["text"], g.data["size"]))
            if wide > 2 * math.pi * r and not any(e[0] is g for e in self.shape_errors):
                self.shape_errors.append((g, (
                    f"text `{g.label}` is {wide:.4g} mm long along a circle only "
                    f"{2 * math.pi * r:.4g} mm around (radius {r:.4g} mm): its last letters "
                    "run round onto its first ones"), "use a smaller size, a larger circle "
                    "or a shorter text", "W0111"))
        else:
            local = local_loops(g)
            bands = bridges(g) if g.data.get("stencil") else []
        loops = [Loop(moved(lp.segments, ox, oy)) for lp in local]
        for lp in loops:
            for sg in lp.segments:
                if isinstance(sg, Spline):
                    self.spline_source.setdefault(sg.curve, g)
        held = [Loop(moved(lp.segments, ox, oy)) for lp in bands]
        return loops, held

    def face(self, g: Geometry, s: Structure | None = None) -> mf.CrossSection | None:
        if g.kind == "Text" and g.data.get("font"):       # the letters' outlines (issue 112)
            if id(g) not in self.derived:
                loops, held = self.font_text(g)
                sec = self.exact.section(loops)
                if held:
                    sec = sec - self.exact.section(held)
                self.derived[id(g)] = None if sec.is_empty() else sec
            return self.derived[id(g)]
        if g.kind == "Text" and g.data.get("stencil"):    # the letters' openings (issue 95)
            from .stencil import stencil_section
            return stencil_section(self, g, self.P(g.points["position"]))
        if g.kind == "Drawing2D":
            loops = self.drawing2d(g)[0]
            return self.exact.section(loops) if loops else None
        if g.kind in DERIVED:
            return self.derived_section(g)
        lp = self.outline(g)
        if lp is None:
            return None
        return self._face(lp, g, s)

    def _face(self, lp: Loop, g: Geometry, s: Structure | None) -> mf.CrossSection | None:
        """The CrossSection of an exact loop; a loop of no area is recorded in
        :attr:`Drawing.empty_faces` and gives None."""
        area = lp.area
        if abs(area) <= 1e-6:           # small: compare with the size of the coordinates
            scale = max(1.0, max((abs(v) for seg in lp.segments for p in _ends(seg) for v in p),
                                 default=1.0))
            if abs(area) <= 1e-9 * scale:
                if s is not None:
                    self.empty_faces.append((s, g, abs(area)))
                return None
        return self.exact.face(lp, area)


def _dist(p, q) -> float:
    return math.hypot(p[0] - q[0], p[1] - q[1])


def _ends(seg):
    if isinstance(seg, Circle):
        c, r = seg.center, seg.radius
        return ((c[0] - r, c[1] - r), (c[0] + r, c[1] + r))
    if isinstance(seg, Spline):
        x0, y0, x1, y1 = seg.curve.box()
        return ((x0, y0), (x1, y1))
    return (seg.start, seg.end)
