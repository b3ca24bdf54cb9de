"""Engraving minus engraving (issue 95): a ``hole`` inside a ``drawing`` hides that drawing's
lines where it covers them, as a hole in a solid cuts that solid's material.

A compass rose's intercardinal points drawn behind the cardinal ones::

    drawing back {
        p = Polygon(points=[...])            # an intercardinal point, outlined
        hole behind { q = Polygon(...) }     # the cardinal point in front: hides what it covers
    }

The hole's shapes are united by Manifold (:meth:`Renderer.shape`, exact loops put back on
their lines and arcs); every stroke the drawing drew (its own geometry and its children's:
outlines, open curves, Text) is cut exactly where it crosses the hole's outline (the exact
crossings of the carriers, as :func:`~aidl_lang.geometry.derived.clip.clip`) and a piece is
kept when it lies outside the hole: not inside it (even-odd) and not along its outline (that
line is the front shape's own edge, drawn once by it).  Every kept piece lies on its own
carrier and ends exactly on the hole's outline.  An area engraved filled (``Text(..., font=,
fill=true)``) is its letters' area less the holes', its loops recovered exact.  Lengths in mm.
"""
from __future__ import annotations

from collections import Counter

import math

import numpy as np

from ....geometry.derived.clip import inside
from ....geometry.shapes.curves import (Arc, Circle, EllipticArc, Line, Loop, Spline, carrier,
                                       crossings, distance_to, with_ends)

EPS = 1e-9          # relative: points this near are one point


def merge_fills(R, out, mark: tuple[int, int]) -> None:
    """The filled shapes (``fill=true``, not a Text's letters, which are their union
    already) one drawing drew since ``mark`` that overlap, each group as one area: their
    union's exact loops, given to the group's first shape, so the laser fills their common
    part once (run ba's donkey: ten filled shapes, their overlaps burnt twice).  Groups by
    their boxes (:func:`~..measure.nearby.box_pairs`, n log n), then by their faces."""
    from ..measure.nearby import box_pairs
    filled = list({id(g): g for style, _, g in out.strokes[mark[0]:]
                   if style == "fill" and g.kind != "Text"}.values())
    if len(filled) < 2:
        return
    faces = [R.face(g) for g in filled]
    ok = [k for k, f in enumerate(faces) if f is not None and not f.is_empty()]
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    boxes = np.array([faces[k].bounds() for k in ok], dtype=float).reshape(-1, 4)
    meet = [(int(i), int(j)) for i, j in box_pairs(boxes)
            if (faces[ok[int(i)]] ^ faces[ok[int(j)]]).area() > 1e-9]
    if not meet:
        return
    ij = np.array(meet).T
    _, label = connected_components(coo_matrix((np.ones(len(meet)), (ij[0], ij[1])),
                                               shape=(len(ok), len(ok))), directed=False)
    groups: dict = {}
    for n, k in enumerate(ok):
        groups.setdefault(int(label[n]), []).append(k)
    merged = [ks for ks in groups.values() if len(ks) > 1]
    if not merged:
        return
    gone = {id(filled[k]) for ks in merged for k in ks}
    drawn = [st for st in out.strokes[mark[0]:] if not (st[0] == "fill" and id(st[2]) in gone)]
    del out.strokes[mark[0]:], out.lines[mark[1]:]   # (lines made again from the strokes)
    for ks in merged:
        area = faces[ks[0]]
        for k in ks[1:]:
            area = area + faces[k]
        R.fill_groups[id(filled[min(ks)])] = [filled[k] for k in ks]
        for lp in R.exact.loops(area):
            drawn.append(("fill", ("poly", lp.points(), lp), filled[min(ks)]))
    for st in drawn:
        out.strokes.append(st)
        out.lines.append((st[0], _polyline_of(st[1])))


def masked(R, s, masks: list, out, mark: tuple[int, int]) -> None:
    """Hide what the hole children ``masks`` of drawing ``s`` cover of the strokes drawn since
    ``mark`` (lengths of ``out.strokes`` and ``out.lines`` before ``s`` drew): those strokes
    are replaced by their exact pieces outside the holes, and their polylines by the pieces'.
    A hole that hides nothing is said (``W0526``, once per hole)."""
    from .result import Drawing
    scratch = Drawing()
    sections = [(c, R.shape(c, scratch)) for c in masks]
    drawn = out.strokes[mark[0]:]
    g0 = drawn[0][2] if drawn else None
    del out.strokes[mark[0]:], out.lines[mark[1]:]
    before = {id(g): g for _, _, g in drawn if g is not None}     # what drew, to judge
    filled = list({id(g): g for style, _, g in drawn if style == "fill"}.values())
    drawn = [d for d in drawn if d[0] != "fill"]
    areas = [_fill_area(R, g) for g in filled]
    for c, sec in sections:
        loops = R.exact.loops(sec) if not sec.is_empty() else []
        kept, hid = [], False
        for k, area in enumerate(areas):       # an area engraved filled: less the hole
            if area is not None and not sec.is_empty() and not (area ^ sec).is_empty():
                areas[k], hid = area - sec, True
        for style, stroke, g in drawn:
            segs = stroke_segments(stroke)
            pieces = [p for seg in segs for p in outside(seg, loops)]
            if _changed(segs, pieces):
                hid = True
                kept += [(style, ("piece", p), g) for p in pieces]
            else:
                kept.append((style, stroke, g))
        drawn = kept
        if not hid and (_first_geometry(c) or g0) is not None:
            R.shape_errors.append((_first_geometry(c) or g0, (
                f"hole `{c.path}` covers none of drawing `{s.path}`'s lines, so it hides "
                f"nothing (a hole in a drawing hides the engraving under it)"),
                "move the hole over the lines it should hide, or delete it (a hole in a "
                "drawing cuts no material)", "W0526"))
    _hidden_whole(R, s, masks, before, drawn, filled, areas)
    for g, area in zip(filled, areas):
        for lp in (R.exact.loops(area) if area is not None and not area.is_empty() else []):
            pl = lp.points()
            out.strokes.append(("fill", ("poly", pl, lp), g))
            out.lines.append(("fill", np.vstack([pl, pl[:1]])))
    for style, stroke, g in drawn:
        if stroke[0] == "piece":
            seg = stroke[1]
            R._stroke_segment(seg, style, g, out)
            out.lines.append((style, _polyline(seg)))
        else:
            out.strokes.append((style, stroke, g))
            out.lines.append((style, _polyline_of(stroke)))


def _fill_area(R, g):
    """The area filled shape ``g`` engraves: its own face, or the union of the filled shapes
    merged into it (:func:`merge_fills`: run fh's snake heads, merged with their bodies, lost
    whole when a hole of the drawing around them clipped the bodies' faces alone)."""
    group = R.fill_groups.get(id(g))
    if not group:
        return R.face(g)
    faces = [f for f in (R.face(m) for m in group) if f is not None and not f.is_empty()]
    if not faces:
        return None
    area = faces[0]
    for f in faces[1:]:
        area = area + f
    return area


def _hidden_whole(R, s, masks, before: dict, drawn: list, filled: list, areas: list) -> None:
    """W0533 for a shape of drawing ``s`` whose every line its holes ``masks`` hide (run es's
    garden gnome: the hole under the beard's lines hid the whole nose, unsaid); a
    loop's copies are left alone (grid lines inside a masked label's box are meant)."""
    left = {id(g) for _, _, g in drawn if g is not None}
    left |= {id(g) for g, a in zip(filled, areas) if a is not None and not a.is_empty()}
    hidden = [g for k, g in before.items()
              if k not in left and not g.construction and g.owner is s]
    if not hidden:
        return
    copies = Counter(h.span for h in s.geometry if h.span is not None)   # once, not per shape
    for g in hidden:
        if g.span is not None and copies[g.span] > 1:
            continue                        # one of a loop's copies
        names = ", ".join(f"`{c.path}`" for c in masks[:2])
        R.shape_errors.append((g, (
            f"`{g.label}` of drawing `{s.path}` is hidden whole by its hole "
            f"{names}: a hole in a drawing hides the engraving under it, so none of "
            f"`{g.name or g.kind}` is engraved"),
            f"move or shrink the hole so that it leaves `{g.name or g.kind}` (or give the "
            "shape a drawing of its own, beside this one, which the hole does not hide)",
            "W0533"))


def _first_geometry(s):
    """The first geometry of structure ``s`` or of its children (where a message about it
    points)."""
    if s.geometry:
        return s.geometry[0]
    return next((g for c in s.children.values() if (g := _first_geometry(c)) is not None), None)


def stroke_segments(stroke: tuple) -> list:
    """The exact segments of an engraving stroke (:attr:`Drawing.strokes`' forms)."""
    kind = stroke[0]
    if kind == "line":
        return [Line(tuple(map(float, stroke[1])), tuple(map(float, stroke[2])))]
    if kind == "arc":
        c, r, a1, a2 = stroke[1:]
        return [Arc((float(c[0]), float(c[1])), float(r), float(a1), float(a2 - a1))]
    if kind == "circle":
        c, r = stroke[1:]
        return [Arc((float(c[0]), float(c[1])), float(r), 0.0, 2 * math.pi)]
    if kind == "poly":
        return [Arc(sg.center, sg.radius, 0.0, 2 * math.pi if sg.ccw else -2 * math.pi)
                if isinstance(sg, Circle) else sg for sg in stroke[2].segments]
    return [stroke[1]]                  # ellipse_arc, spline, piece


def _param(seg, p) -> float:
    """How far along ``seg`` its point ``p`` lies, from 0 (its start) to its end's value."""
    if isinstance(seg, Line):
        (x0, y0), (x1, y1) = seg.start, seg.end
        L = seg.length
        return ((p[0] - x0) * (x1 - x0) + (p[1] - y0) * (y1 - y0)) / L if L else 0.0
    if isinstance(seg, Arc):
        a = math.atan2(p[1] - seg.center[1], p[0] - seg.center[0])
        d = (a - seg.start_angle) if seg.sweep > 0 else (seg.start_angle - a)
        return d % (2 * math.pi)
    if isinstance(seg, EllipticArc):
        d = (seg.curve.foot(p) - seg.start_param) * (1 if seg.sweep > 0 else -1)
        return d % (2 * math.pi)
    return seg.curve.foot(p) * (1 if seg.u1 >= seg.u0 else -1)


def _end(seg) -> float:
    if isinstance(seg, Line):
        return seg.length
    if isinstance(seg, (Arc, EllipticArc)):
        return abs(seg.sweep)
    return seg.u1 * (1 if seg.u1 >= seg.u0 else -1)


def _on(seg, p, tol) -> bool:
    """``p`` (a point near ``seg``'s carrier) lies on segment ``seg``."""
    if distance_to(carrier(seg), p) > tol:
        return False
    if isinstance(seg, Line):
        L = seg.length
        return L > 0 and -tol <= _param(seg, p) <= L + tol
    t, e = _param(seg, p), _end(seg)
    if isinstance(seg, Spline):
        t0 = seg.u0 * (1 if seg.u1 >= seg.u0 else -1)
        return t0 - 1e-9 <= t <= e + 1e-9
    arm = seg.radius if isinstance(seg, Arc) else max(seg.curve.rx, seg.curve.ry)
    return t <= e + tol / arm or t >= 2 * math.pi - tol / arm


def outside(seg, loops: list[Loop]) -> list:
    """The exact pieces of segment ``seg`` outside the area bounded by ``loops``: cut where
    it crosses their outline (and where an outline's stretch along it ends), kept when a
    piece's middle is neither inside (even-odd) nor on the outline."""
    if not loops:
        return [seg]
    bounds = [b for lp in loops for b in lp.segments]
    polys = [lp.points(1e-4) for lp in loops]
    size = max(1.0, *(abs(v) for v in seg.start), *(abs(v) for v in seg.end))
    tol = EPS * size * 100
    cuts = [(0.0, seg.start)]
    c = carrier(seg)
    for b in bounds:
        cb = carrier(b)
        hits = list(crossings(c, cb))
        if not isinstance(b, Circle):
            hits += [b.start, b.end]
        for p in hits:
            if _on(seg, p, tol) and _on(b, p, tol) if not isinstance(b, Circle) else (
                    _on(seg, p, tol) and distance_to(cb, p) <= tol):
                cuts.append((_param(seg, p), p))
    cuts.sort(key=lambda tp: tp[0])
    cuts.append((_end(seg), seg.end))
    t_start = cuts[0][0]
    out: list = []
    for (t1, p), (t2, q) in zip(cuts, cuts[1:]):
        if t2 - t1 <= 1e-12 or math.dist(p, q) <= EPS * size and not (
                isinstance(seg, Arc) and t2 - t1 > math.pi):
            continue
        piece = seg if (t1 == t_start and q is seg.end and p is seg.start) else _between(seg, p, q)
        if piece is None:
            continue
        mid = _middle(piece)
        if any(distance_to(carrier(b), mid) <= tol and _on_bound(b, mid, tol) for b in bounds):
            continue                    # along the outline: the front shape draws it
        if not inside(polys, mid):
            out.append(piece)
    return _joined(seg, out)


def _on_bound(b, p, tol) -> bool:
    return True if isinstance(b, Circle) else _on(b, p, tol)


def _between(seg, p, q):
    if isinstance(seg, Arc):            # (with_ends would take a whole turn for no arc)
        a1 = math.atan2(p[1] - seg.center[1], p[0] - seg.center[0])
        sw = _param(seg, q) - _param(seg, p)
        if abs(sw) < 1e-12:
            sw = 2 * math.pi
        return Arc(seg.center, seg.radius, a1, sw if seg.sweep > 0 else -sw)
    piece = with_ends(seg, p, q)
    if isinstance(piece, EllipticArc) and piece.sweep == 0:
        return None
    return piece


def _middle(seg):
    if isinstance(seg, Line):
        return ((seg.start[0] + seg.end[0]) / 2, (seg.start[1] + seg.end[1]) / 2)
    if isinstance(seg, Arc):
        return seg.at(seg.start_angle + seg.sweep / 2)
    if isinstance(seg, EllipticArc):
        return seg.at(seg.start_param + seg.sweep / 2)
    return seg.curve.at((seg.u0 + seg.u1) / 2)


def _joined(seg, pieces: list) -> list:
    """A whole circle's first and last kept pieces are one arc when they meet at its start
    (the start was no crossing)."""
    if (len(pieces) >= 2 and isinstance(seg, Arc) and abs(abs(seg.sweep) - 2 * math.pi) < 1e-12
            and math.dist(pieces[0].start, seg.start) <= 1e-12
            and math.dist(pieces[-1].end, seg.start) <= 1e-12):
        last, first = pieces[-1], pieces[0]
        pieces = [Arc(seg.center, seg.radius, last.start_angle, last.sweep + first.sweep),
                  *pieces[1:-1]]
    return pieces


def _changed(segs: list, pieces: list) -> bool:
    return len(pieces) != len(segs) or any(a is not b for a, b in zip(segs, pieces))


def _polyline(seg) -> np.ndarray:
    from ....geometry.shapes.curves import sample_xy
    xs: list = []
    ys: list = []
    sample_xy([seg], xs, ys)
    xs.append(seg.end[0])
    ys.append(seg.end[1])
    return np.column_stack([np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)])


def _polyline_of(stroke: tuple) -> np.ndarray:
    segs = stroke_segments(stroke)
    if stroke[0] == "poly":
        pl = stroke[1]
        return np.vstack([pl, pl[:1]])
    return np.vstack([_polyline(sg) for sg in segs])
