"""Geometry checks on the final shape: warnings about parts that solve but come out wrong.

The booleans (:mod:`.booleans`) record each structure's shape and what each hole cut; these
checks read them (docs/outputs.md, "Checks"; every code is in :mod:`aidl_lang.codes`):

* ``W0501`` a hole partly or wholly refilled by a sibling or ancestor solid (a hole cuts only
  the solid it is declared in; a solid united later fills it again);
* ``W0502`` a hole that cuts nothing (it lies outside its solid);
* ``W0503`` a hole that removes all of its solid;
* ``W0504`` a solid part whose final shape falls apart into separate pieces (assembly parts are
  separate by design and are not checked against each other);
* ``W0505`` engraving (a drawing) outside the material or across a hole;
* ``W0506`` a child solid that adds nothing: it lies wholly inside the rest of its parent (for
  example pattern copies that land inside a filled solid);
* ``W0507`` a wall thinner than ``min_wall`` (default :data:`MIN_WALL`, 0.5 mm): what a
  morphological opening of the part by a disc of that diameter removes (the erosion by
  ``min_wall / 2`` then the dilation back, Manifold offsets with round joins), in pieces of at
  least ``2 min_wall^2`` (so that sharp corners, which every opening rounds, do not count); the
  warning names the holes and the outer edge the wall lies between;
  between two holes, or a hole and the outline, the width is measured as the least distance
  between their boundaries, whatever the area;
* ``W0508`` two separately declared holes that overlap or touch: one opening;
* ``W0509`` a face of zero area, or a solid part that comes out empty unexplained;
* ``W0510`` (:func:`check_topology`, run by the pipeline and the live preview when param
  values are overridden) a part whose topology differs from the defaults';
* ``W0402`` an open outline (lines and arcs that do not close), drawn as engraving.

Pairs of holes are found with a spatial index (:mod:`.nearby`), so the checks grow as
n log n in the number of holes.

Areas are compared with a tolerance that ignores the chord slivers of tessellated curves:
:data:`MIN_FRACTION` of the feature and at least :data:`MIN_AREA` mm^2.
"""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ..diagnostics import DiagnosticSink, Label
from ..geometry.tessellate import CHORD_TOL
from dataclasses import dataclass, field
from ..geometry.model import Structure
from .booleans import Drawing
from .nearby import box_pairs, boundary, close_pairs

MIN_FRACTION = 0.02      # of a hole's or child's area
MIN_AREA = 0.05          # mm^2
ENGRAVE_TOL = 0.05       # mm: engraving this close to an edge still counts as on the material
MAX_CHILDREN = 64        # W0506 compares each child with the union of the others
MIN_WALL = 0.5           # mm: W0507's default minimum wall


def _area(cs) -> float:
    return 0.0 if cs is None or cs.is_empty() else float(cs.area())


def _union(shapes) -> mf.CrossSection:
    shapes = [s for s in shapes if s is not None and not s.is_empty()]
    return mf.CrossSection.batch_boolean(shapes, mf.OpType.Add) if shapes else mf.CrossSection()


def _significant(a: float, whole: float) -> bool:
    return a > MIN_AREA and a > MIN_FRACTION * whole


def _pct(a: float, whole: float) -> str:
    return f"{100.0 * a / whole:.0f}%" if whole > 0 else "0%"


def _part_roots(d: Drawing) -> dict[Structure, mf.CrossSection]:
    shapes = {}
    for p in d.parts:
        s = d.part_of.get(p.name)
        if s is not None:
            shapes[s] = p.shape
    return shapes


def _part_of(s: Structure, roots) -> Structure | None:
    node = s
    while node is not None:
        if node in roots:
            return node
        node = node.parent
    return None


def _contributors(d: Drawing, a: Structure, skip: Structure | None = None,
                  objects: bool = False):
    """What a solid ``a`` unites: (name, span, shape) of its own faces and solid children
    (``objects``: (name, span, shape, the Geometry or Structure))."""
    out = []
    for g, f in d.own.get(a, []):
        out.append((f"`{g.label}`", g.span, f, g) if objects else (f"`{g.label}`", g.span, f))
    for c in a.children.values():
        if c is skip or c.kind not in ("solid", "hole") or c.kind == "hole":
            continue
        if c in d.shapes:
            item = (f"solid `{c.path}`", c.span, d.shapes[c])
            out.append(item + (c,) if objects else item)
    return out


def _intended(hole: Structure, owner: Structure, obj) -> bool:
    """``AllowOverlap(hole, x)`` was written for this hole (or a structure between it and
    the solid it cuts) with ``x`` the refilling ``obj`` (a shape or a solid), a structure
    around it, or a shape inside it."""
    allowed: set = set()
    s = hole
    while s is not None:
        allowed |= getattr(s, "overlap_ok", set())
        if s is owner:
            break
        s = s.parent
    if not allowed:
        return False
    t = obj if isinstance(obj, Structure) else obj.owner
    if obj in allowed:
        return True
    if isinstance(obj, Structure) and any(not isinstance(a, Structure) and a.owner.is_within(obj)
                                          for a in allowed):
        return True                  # a shape named in AllowOverlap, inside this solid
    while t is not None:
        if t in allowed:
            return True
        t = t.parent
    return False


def check_drawing(d: Drawing, sink: DiagnosticSink, min_wall: float = MIN_WALL,
                  deadline=None) -> None:
    """Append the geometry warnings for the booleans' result ``d`` to ``sink``; ``min_wall``
    (mm) is W0507's minimum wall (0 turns that check off; W0508, holes that merge, stays on).
    ``deadline``: the compile's :class:`~aidl_lang.limits.Deadline`, checked between
    structures and holes (raises :class:`~aidl_lang.limits.OutOfBudget`)."""
    def tick(s, ahead: float = 0.0):
        if deadline is not None:
            deadline.check("the shape checks", s, ahead)
    roots = _part_roots(d)
    loops = {s: [np.asarray(p, dtype=float) for p in shape.to_polygons()]
             for s, shape in roots.items() if s.kind == "solid"}
    near = _Near(roots, loops, d.cuts)
    explained: set = set()          # parts whose emptiness a warning already explains
    owner_areas: dict = {}          # a solid's final area, taken once for all its holes
    for cut in d.cuts:
        tick(cut.hole)
        if _check_hole(d, cut, roots, sink, near.local, owner_areas) == "W0503":
            explained.add(_part_of(cut.owner, roots))
    for s, shape in roots.items():
        if s.kind == "solid":
            tick(s)
            _check_pieces(d, s, shape, sink, loops[s])
    for s in list(d.shapes):
        if s.kind == "solid":
            tick(s)
            _check_invisible(d, s, sink)
    tick(None)
    _check_engraving(d, roots, sink, loops)
    by_part: dict = {}
    for c in d.cuts:
        by_part.setdefault(_part_of(c.owner, roots), []).append(c)
    for s, shape in roots.items():
        if s.kind == "solid":
            tick(s)
            a = _analyse(d, s, shape, by_part.get(s, []), min_wall, loops[s])
            covered = _report_openings(a, s, min_wall, sink)
            _check_flush(d, s, shape, a, by_part.get(s, []), min_wall, sink)
            _check_voids(d, s, loops[s], by_part.get(s, []), min_wall, sink)
            tick(s)
            if min_wall > 0:
                _check_walls(d, s, shape, min_wall, by_part.get(s, []), sink, covered=covered,
                             loops=loops[s], tick=lambda ahead=0.0: tick(s, ahead))
    tick(None)
    _check_interpenetration(d, roots, sink, deadline)
    _check_text_overlap(d, sink)
    if getattr(d, "placement", None):
        tick(None)
        _check_fit(d, sink, deadline)
    for s in list(d.shapes):
        if s.kind == "hole":
            _check_repeated_faces(d, s, sink)
    for g, *_ in getattr(d, "shape_errors", None) or ():
        explained.add(_part_of(getattr(g, "owner", g), roots))     # an E0406 says why the part is empty
    for s, g, area in empty_faces(d):
        part = _part_of(s, roots)
        explained.add(part)
        what = "cuts" if s.kind == "hole" else "adds"
        sink.warning("W0509", f"`{g.label}` closes a loop of zero area ({abs(area):.2g} mm^2) "
                     f"in {s.kind} `{s.path}`: it encloses nothing, so it {what} nothing",
                     g.span,
                     hint="a face needs an inside: give it a non-zero width, height or radius, "
                          "or points that are not all on one line (a line and its own mirror "
                          "image close a loop with nothing inside); delete it if it is not "
                          "needed")
    for g in d.open_curves:
        explained.add(_part_of(g.owner, roots))
        sink.warning("W0402", f"`{g.label}` is not part of a closed outline, so it is drawn as a "
                     "line (engraved), not filled", g.span,
                     hint="share endpoints between lines and arcs so they form a loop, or put "
                          "the curve in a `drawing` structure")
    for s, shape in roots.items():
        if s.kind == "solid" and shape.is_empty() and s not in explained and any(
                not g.construction for n in s.subtree() for g in n.geometry):
            sink.warning("W0509", f"solid `{s.path}` comes out empty: none of its geometry "
                         "encloses any area", s.span,
                         hint="give the part a closed shape with an inside (a Rectangle, a "
                              "Circle, lines and arcs that close a loop around some area)")


TEXT_OVERLAP = 0.10     # of the smaller text's box: two labels overlapping more are on each other
TEXT_MARGIN = 0.10      # of a text's size: a mark this far inside the text's box does not count
TEXT_GAP = 0.5          # of the smaller text's size (about a word space): closer labels read as one


def _text_box(g, items) -> tuple:
    """The box of a text's pen strokes in the text's own frame (turned by its rotation):
    ``(polygon 4 x 2 in the model frame, rotation, (u0, v0, u1, v1))``."""
    P = np.concatenate([np.array([it[1], it[2]], dtype=float) for it in items])
    rot = float(g.data.get("rotation", 0.0) or 0.0)
    c, s_ = math.cos(rot), math.sin(rot)
    u, v = P[:, 0] * c + P[:, 1] * s_, -P[:, 0] * s_ + P[:, 1] * c
    u0, v0, u1, v1 = u.min(), v.min(), u.max(), v.max()
    corners = np.array([(u0, v0), (u1, v0), (u1, v1), (u0, v1)])
    poly = np.column_stack([corners[:, 0] * c - corners[:, 1] * s_,
                            corners[:, 0] * s_ + corners[:, 1] * c])
    return poly, rot, (u0, v0, u1, v1)


def _length_inside(seg: tuple, rot: float, box) -> float:
    """The length (mm) of the segments ``seg`` (starts, ends: k x 2 each) inside ``box``
    (u0, v0, u1, v1) of the frame turned by ``rot``: each clipped exactly (Liang-Barsky), all
    in one array operation."""
    a, b = seg
    c, s_ = math.cos(rot), math.sin(rot)
    x, y = a[:, 0] * c + a[:, 1] * s_, -a[:, 0] * s_ + a[:, 1] * c
    dx, dy = b[:, 0] * c + b[:, 1] * s_ - x, -b[:, 0] * s_ + b[:, 1] * c - y
    u0, v0, u1, v1 = box
    t0, t1 = np.zeros(len(x)), np.ones(len(x))
    for p_, q_ in ((-dx, x - u0), (dx, u1 - x), (-dy, y - v0), (dy, v1 - y)):
        with np.errstate(divide="ignore", invalid="ignore"):
            r = q_ / p_
        par = p_ == 0
        t1 = np.where(par & (q_ < 0), 0.0, t1)           # parallel and outside
        t0 = np.where(~par & (p_ < 0), np.maximum(t0, r), t0)
        t1 = np.where(~par & (p_ > 0), np.minimum(t1, r), t1)
    return float((np.clip(t1 - t0, 0.0, None) * np.hypot(dx, dy)).sum())


def _mark_segments(items) -> tuple:
    """The segments of an engraved mark's ``items`` as (starts, ends), k x 2 each: lines
    exact, curves as the polylines of their W0505 samples."""
    a, b = [], []
    for it in items:
        P = _polyline(it)
        a.append(P[:-1])
        b.append(P[1:])
    return np.concatenate(a), np.concatenate(b)


def _check_text_overlap(d: Drawing, sink: DiagnosticSink) -> None:
    """W0513 for engraved text drawn over other text (their boxes, in each text's own frame,
    overlap by more than :data:`TEXT_OVERLAP` of the smaller) or over an engraved mark (a
    line, arc or circle that runs through the text's box, shrunk by :data:`TEXT_MARGIN` of the
    text's size, over more than a quarter of that size): two protractor labels on each other,
    a label on its tick mark.  Labels of two characters or more whose boxes come closer than
    :data:`TEXT_GAP` of their size run into each other (single letters are a word's letters
    laid out one by one, as ``text_on_arc`` does)."""
    texts: dict = {}
    marks: dict = {}
    for style, item, g in d.strokes:
        if g is None:
            continue
        if g.kind == "Text":
            texts.setdefault(g, []).append(item)
        else:
            marks.setdefault(g, []).append(item)
    if not texts:
        return
    tg = list(texts)
    boxes = [_text_box(g, texts[g]) for g in tg]
    shapes = [mf.CrossSection([b[0].tolist()]) for b in boxes]
    bb = np.array([[b[0][:, 0].min(), b[0][:, 1].min(), b[0][:, 0].max(), b[0][:, 1].max()]
                   for b in boxes], dtype=float)
    said = set()
    close: dict = {}            # (span, span) -> [(gap, near, a, b)]: labels that run together
    sizes = [float(g.data.get("size", 0.0) or 0.0) or (b[2][3] - b[2][1])
             for g, b in zip(tg, boxes)]
    pad = TEXT_GAP * max(sizes) / 2
    for i, j in sorted(map(tuple, box_pairs(bb, pad))):
        common = _area(shapes[i] ^ shapes[j])
        small = min(_area(shapes[i]), _area(shapes[j]))
        a, b = tg[i], tg[j]
        if common <= max(MIN_AREA, TEXT_OVERLAP * small):
            gap = _quad_gap(boxes[i][0], boxes[j][0])
            near = TEXT_GAP * min(sizes[i], sizes[j])
            word = min(len(str(g.data.get("text", "")).strip()) for g in (a, b)) > 1
            if gap < near and word and a.span is not None and b not in said:
                said.add(b)
                close.setdefault((a.span, b.span), []).append((gap, near, a, b))
            continue
        said.add(b)
        depth = _depth(shapes[i] ^ shapes[j], bb[i], bb[j])
        labels = [Label(a.span, f"`{a.label}` is here", primary=False)] if a.span else []
        sink.warning("W0513", f"text `{b.label}` (\"{b.data.get('text', '')}\") is drawn over "
                     f"text `{a.label}` (\"{a.data.get('text', '')}\"): their boxes overlap by "
                     f"{common:.2f} mm^2 ({_pct(common, small)} of the smaller)", b.span,
                     labels=labels,
                     hint=f"move `{b.label}` at least {depth:.2f} mm away from `{a.label}` (or "
                          "make them smaller) so that both can be read")
    for found in close.values():
        gap, near, a, b = min(found, key=lambda f: f[0])
        more = f"; {len(found) - 1} more pairs of these labels as close" if len(found) > 1 else ""
        sink.warning("W0513", f"text `{b.label}` (\"{b.data.get('text', '')}\") runs into "
                     f"text `{a.label}` (\"{a.data.get('text', '')}\"): their boxes are "
                     f"{gap:.2f} mm apart, less than {near:.2f} mm (half the text size), so "
                     f"they read as one string{more}", b.span,
                     labels=[Label(a.span, f"`{a.label}` is here", primary=False)],
                     hint=f"leave at least {near:.2f} mm between them: space the labels "
                          "further apart (a larger radius or step), or make them smaller")
    if not marks:
        return
    mg = list(marks)
    mpts = [_samples(marks[g]) for g in mg]
    mb = np.array([[p[:, 0].min(), p[:, 1].min(), p[:, 0].max(), p[:, 1].max()] for p in mpts],
                  dtype=float)
    n = len(tg)
    segs: dict = {}
    pairs = box_pairs(np.vstack([bb, mb]))
    for i, j in sorted(map(tuple, pairs)):
        if not (i < n <= j) or tg[i] in said:
            continue
        g, m = tg[i], mg[j - n]
        size = float(g.data.get("size", 0.0) or 0.0) or (boxes[i][2][3] - boxes[i][2][1])
        u0, v0, u1, v1 = boxes[i][2]
        e = TEXT_MARGIN * size
        inner = (u0 + e, v0 + e, u1 - e, v1 - e)
        if inner[0] >= inner[2] or inner[1] >= inner[3]:
            continue
        if m not in segs:
            segs[m] = _mark_segments(marks[m])
        length = _length_inside(segs[m], boxes[i][1], inner)
        if length <= max(0.2, 0.25 * size):
            continue
        said.add(g)
        labels = [Label(m.span, f"`{m.label}` is here", primary=False)] if m.span else []
        sink.warning("W0513", f"text `{g.label}` (\"{g.data.get('text', '')}\") is drawn over "
                     f"the engraved `{m.label}`: it runs {length:.2f} mm through the text",
                     g.span, labels=labels,
                     hint=f"move `{g.label}` clear of `{m.label}` (beside a tick mark, not on "
                          "it: e.g. further out along the same direction), or shorten the mark")


def _quad_gap(p, q) -> float:
    """The distance (mm) between two convex quadrilaterals ``p``, ``q`` (4 x 2, in order):
    0 when they overlap, else the least distance of a corner of one to an edge of the other."""
    def inside(pt, poly):
        e = np.roll(poly, -1, axis=0) - poly
        w = pt - poly
        cross = e[:, 0] * w[:, 1] - e[:, 1] * w[:, 0]
        return bool((cross >= 0).all() or (cross <= 0).all())
    if any(inside(pt, q) for pt in p) or any(inside(pt, p) for pt in q):
        return 0.0
    best = math.inf
    for a, b in ((p, q), (q, p)):
        s0, s1 = b, np.roll(b, -1, axis=0)
        d = s1 - s0
        for pt in a:
            t = np.clip(((pt - s0) * d).sum(1) / (d * d).sum(1), 0.0, 1.0)
            best = min(best, float(np.hypot(*(s0 + t[:, None] * d - pt).T).min()))
    return best


def _polyline(item) -> np.ndarray:
    """An engraving item as a polyline (lines exact, curves sampled as in W0505)."""
    if item[0] == "line":
        return np.array([item[1], item[2]], dtype=float)
    if item[0] == "poly":
        P = np.asarray(item[1], dtype=float)
        return np.vstack([P, P[:1]])
    if item[0] == "circle":
        P = _sample(item)
        return np.vstack([P, P[:1]])
    return _sample(item)


def _check_repeated_faces(d: Drawing, h: Structure, sink: DiagnosticSink) -> None:
    """W0512 for hole ``h``: the faces one statement draws several times (in a loop) that
    overlap or touch, so they cut fewer openings than the statement draws (a drill gauge of
    ten holes with nine openings).  Faces of different statements (a keyhole's circle and
    slot) are one opening by design and are not compared."""
    by_stmt: dict = {}
    for g, f in d.own.get(h, []):
        if g.span is not None and f is not None and not f.is_empty():
            by_stmt.setdefault(g.span, []).append((g, f))
    for span, faces in by_stmt.items():
        if len(faces) < 2:
            continue
        shapes = [f for _, f in faces]
        boxes = np.array([f.bounds() for f in shapes], dtype=float)
        merges = []
        for i, j in sorted(map(tuple, box_pairs(boxes, pad=TOUCH / 2))):
            common = shapes[i] ^ shapes[j]
            a = _area(common)
            if a > 1e-9:
                merges.append((i, j, _depth(common, boxes[i], boxes[j]), a))
            elif (shapes[i] + shapes[j]).num_contour() < 2:
                merges.append((i, j, 0.0, 0.0))        # they touch: one contour
        if not merges:
            continue
        openings = _union(shapes).num_contour()
        i, j, depth, a = merges[0]
        g = faces[0][0]
        how = (f"copies {i + 1} and {j + 1} overlap by {depth:.2f} mm ({a:.2f} mm^2 in common)"
               if a > 0 else f"copies {i + 1} and {j + 1} touch")
        more = f" ({len(merges)} such pairs)" if len(merges) > 1 else ""
        sink.warning("W0512", f"`{g.label}` of hole `{h.path}` is drawn {len(faces)} times but "
                     f"cuts {openings} opening{'s' if openings != 1 else ''}: {how}{more}",
                     span,
                     hint=f"space the copies at least {depth + MIN_WALL:.2f} mm further apart "
                          "(or make them smaller) so that material is left between them; if one "
                          "opening is meant, draw it as one shape (a Slot, a Polygon)")


def _perimeter(cs) -> float:
    return float(sum(np.hypot(*(np.roll(P, -1, axis=0) - P).T).sum()
                     for P in (np.asarray(p, dtype=float) for p in cs.to_polygons())))


def _check_flush(d: Drawing, s: Structure, shape, a: _Openings, cuts, min_wall: float,
                 sink) -> None:
    """W0514 for each hole of part ``s`` that lies wholly inside its solid (no part of it
    outside: not drawn as a notch) and yet only touches the outer edge (:func:`_analyse`'s
    notches): at a point, or along less than ``min_wall`` mm (at least :data:`MIN_WALL`), a
    wall of zero width that pinches the hole open onto the edge (a round hole tangent to the
    edge, a window's corner on the roof line).  A hole flush with the edge along more than
    that is a notch, as asked for a connector cut-out or a cross-halving slot, and is left
    alone.  The figure is the length of the contact, ``(P(filled) + P(hole) - P(filled -
    hole)) / 2`` over perimeters."""
    if not a.notches:
        return
    feats = [c for c in cuts if c.region is not None and not c.region.is_empty()
             and _area(c.region) > 1e-9]
    for j in sorted(a.notches):
        c = feats[j - 1]
        whole = _area(d.shapes.get(c.hole))
        if whole - _area(c.region) > max(MIN_AREA, 1e-6 * whole):
            continue                       # it overhangs the edge: a notch by design
        filled = shape + c.region
        contact = max(0.0, (_perimeter(filled) + _perimeter(c.region)
                            - _perimeter(filled - c.region)) / 2)
        if contact >= max(min_wall, MIN_WALL):
            continue                       # flush along a side: a notch
        x0, y0, x1, y1 = c.region.bounds()
        where = "at a point" if contact < 2 * TOUCH else f"along only {contact:.2f} mm"
        sink.warning("W0514", f"hole `{c.hole.path}` lies inside `{s.path}` but touches its "
                     f"outer edge {where} (a wall of zero width), so it opens onto the edge "
                     f"(near ({(x0 + x1) / 2:.1f}, {(y0 + y1) / 2:.1f}))", c.hole.span,
                     hint=f"move `{c.hole.name}` inward (by at least the minimum wall) to "
                          "leave material around it; if a notch is meant, let the hole run "
                          "past the edge (e.g. by 1 mm) so that the intent is explicit")


def _check_voids(d: Drawing, s: Structure, loops, cuts, t: float, sink) -> None:
    """W0515 for each tiny opening of part ``s`` that no hole cut: an inner loop (clockwise)
    of less than ``max(2 t^2, 1)`` mm^2 whose box meets no hole's: a void left between merged
    shapes (two solids that nearly meet around a gap)."""
    inner = [P for P in loops if _signed(P) < 0]
    if not inner:
        return
    hb = np.array([c.region.bounds() for c in cuts if c.region is not None
                   and not c.region.is_empty()], dtype=float).reshape(-1, 4)
    limit = max(2 * t * t, 1.0)
    for P in inner:
        area = -_signed(P)
        if area >= limit:
            continue
        x0, y0 = P.min(axis=0)
        x1, y1 = P.max(axis=0)
        if len(hb) and ((hb[:, 0] <= x1) & (hb[:, 2] >= x0) & (hb[:, 1] <= y1)
                        & (hb[:, 3] >= y0)).any():
            continue
        width = area / max(1e-12, max(x1 - x0, y1 - y0))
        sink.warning("W0515", f"a void of {area:.3f} mm^2 (about {width:.2f} mm wide, "
                     f"{max(x1 - x0, y1 - y0):.2f} mm long) is left inside `{s.path}` near "
                     f"({(x0 + x1) / 2:.1f}, {(y0 + y1) / 2:.1f}): no hole cuts it, the "
                     "shapes around it do not quite meet", s.span,
                     hint="make the shapes around it overlap (e.g. `gap=-1 mm`, or a larger "
                          "size) so that no gap is left; if an opening is meant, cut it with "
                          "a hole")


def _allowed(a: Structure, b: Structure) -> bool:
    """``AllowOverlap(a, b)`` (or one naming a structure around either) was written."""
    for x, y in ((a, b), (b, a)):
        node = x
        while node is not None:
            ok = getattr(node, "overlap_ok", set())
            if any(isinstance(o, Structure) and (y is o or y.is_within(o)) for o in ok):
                return True
            node = node.parent
    return False


STACKED = 0.25          # of the smaller part's area: a larger overlap is parts laid on each other


def _check_interpenetration(d: Drawing, roots, sink: DiagnosticSink, deadline=None) -> None:
    """W0511 for two solid parts (separate parts of an assembly) whose final shapes overlap
    by more than :data:`MIN_AREA` mm^2: parts cut apart from one sheet cannot occupy the same
    place (two gears placed closer than their centre distance: their teeth interpenetrate).
    Parts whose overlap covers more than :data:`STACKED` of the smaller one are taken as laid
    one on the other in the assembly view (a gear on its mounting plate, a clock's hands on
    each other) and not warned: parts meant to mesh or touch collide at their rims.  Candidate
    pairs come from the parts' boxes (:func:`.nearby.box_pairs`); ``deadline`` is checked
    before each pair's boolean."""
    parts = [(s, shp) for s, shp in roots.items() if s.kind == "solid" and not shp.is_empty()]
    if len(parts) < 2:
        return
    boxes = np.array([shp.bounds() for _, shp in parts], dtype=float)
    for i, j in sorted(map(tuple, box_pairs(boxes))):
        (a, sa), (b, sb) = parts[i], parts[j]
        if a.is_within(b) or b.is_within(a):
            continue              # a part drawn inside another's drawing: shown on it
        if deadline is not None:
            deadline.check("the shape checks", None)
        common = sa ^ sb
        area = _area(common)
        if area <= MIN_AREA or _allowed(a, b):
            continue
        if area > STACKED * min(_area(sa), _area(sb)):
            continue              # laid one on the other (a gear on its plate, clock hands)
        depth = _depth(common, boxes[i], boxes[j])
        labels = [Label(a.span, f"`{a.path}` is here", primary=False)] if a.span else []
        sink.warning("W0511", f"parts `{a.path}` and `{b.path}` interpenetrate: they overlap "
                     f"by {area:.2f} mm^2, {depth:.2f} mm deep (separate parts cannot occupy "
                     "the same place)", b.span or a.span, labels=labels,
                     hint=f"move `{b.path}` at least {depth:.2f} mm further from `{a.path}` "
                          "(meshing gears sit at the centre distance module * (teeth1 + "
                          "teeth2) / 2: `gear_pair` in std/gears.aidl places them), or shrink "
                          "one; if the overlap is meant (a picture of parts stacked), write "
                          f"`AllowOverlap({a.name}, {b.name})` in their assembly")


def _check_fit(d: Drawing, sink: DiagnosticSink, deadline=None) -> None:
    """The fit check of the assembled product (:func:`.assembly.fit`, for a program that
    places its parts with ``Place``): W0517 for two parts whose solids collide (a slot
    narrower than its partner's thickness: the depth is by how much), W0518 for a part that
    touches no other (a tab short of its slot: the gap)."""
    from .assembly import extrude, fit, normals_of
    parts = [(p.name, p.kind, p.shape, d.thickness.get(p.name)) for p in d.parts]
    hits, gaps = fit(extrude(parts, d.placement, deadline=deadline), deadline,
                     normals_of(d.placement))

    def at(name):
        s = d.part_of.get(name)
        pl = getattr(s, "placement", None)
        return (pl[2] if pl is not None and pl[2] is not None else getattr(s, "span", None))
    for c in hits:
        x0, y0, z0, x1, y1, z1 = c.box
        sa = at(c.a)
        labels = [Label(sa, f"`{c.a}` is placed here", primary=False)] if sa else []
        sink.warning("W0517", f"assembled, parts `{c.a}` and `{c.b}` collide: they share "
                     f"{c.volume:.3g} mm^3, {c.depth:.3g} mm deep, in x {x0:.6g}..{x1:.6g}, "
                     f"y {y0:.6g}..{y1:.6g}, z {z0:.6g}..{z1:.6g} mm", at(c.b) or sa,
                     labels=labels,
                     hint=f"a slot or a gap is {c.depth:.3g} mm narrower than the part that "
                          "goes in it: widen it to the partner's thickness (or make the "
                          "material thinner), or move the part with its `Place`")
    for g in gaps:
        sink.warning("W0518", f"assembled, part `{g.part}` touches no other part: the nearest, "
                     f"`{g.nearest}`, is {g.gap:.3g} mm away", at(g.part),
                     hint=f"a tab does not reach its slot: move `{g.part}` {g.gap:.3g} mm "
                          "with its `Place`, or lengthen the tab")


_CLOSED = {"Circle", "Slot", "ArcSlot", "Star", "Ellipse", "Rectangle", "RoundedRectangle",
           "Triangle", "Polygon",
           "RegularPolygon", "Trapezoid", "Offset", "Shell", "Hull", "Stroke", "Sector"}


def empty_faces(d: Drawing) -> list:
    """The faces that close but enclose no area, as ``(structure, geometry, area)``: the
    booleans' ``Drawing.empty_faces`` when it has that field, and in any case what the model
    shows (a solid or hole whose own closed geometry gave no shape, or a chain of lines and
    arcs that closed into an empty loop), each geometry once, in model order."""
    out: dict = {}
    errored = {id(g) for g, *_ in getattr(d, "shape_errors", None) or ()}   # E0406 said
    for s, g, a in getattr(d, "empty_faces", None) or []:
        out.setdefault(id(g), (s, g, float(a)))
    for s in d.shapes:
        if s.kind not in ("solid", "hole"):
            continue
        own = d.own.get(s, [])
        shaped = {id(g) for g, f in own if f is not None and not f.is_empty()}
        for g, f in own:
            if f is None or f.is_empty():
                out.setdefault(id(g), (s, g, 0.0))
        for g in s.geometry:
            if not g.construction and (g.kind in _CLOSED or g.kind == "Polyline" and g.closed) \
                    and id(g) not in shaped \
                    and id(g) not in errored:
                out.setdefault(id(g), (s, g, 0.0))
    return list(out.values())


class _Near:
    """The final shape of a part near a region, for W0501: a part's loops whose bounding
    boxes meet the region's (found for every cut at once with :func:`.nearby.box_pairs`)
    filled even-odd give the part's shape exactly inside the region's box, so each hole is
    intersected with its neighbourhood, not with the whole part (which made W0501 quadratic
    in the number of holes)."""

    def __init__(self, roots, loops, cuts):
        self.roots, self.loops = roots, loops
        self.near: dict = {}                  # id(region) -> indices of the part's loops
        by_part: dict = {}
        for c in cuts:
            part = _part_of(c.owner, roots)
            if part in loops and c.region is not None and not c.region.is_empty():
                by_part.setdefault(part, []).append(c.region)
        for part, regions in by_part.items():
            lp = loops[part]
            if len(lp) <= 8:
                continue                      # small part: intersect with the whole
            boxes = [(p[:, 0].min(), p[:, 1].min(), p[:, 0].max(), p[:, 1].max()) for p in lp]
            boxes += [r.bounds() for r in regions]
            pairs = box_pairs(boxes)
            n = len(lp)
            hit = pairs[(pairs[:, 0] < n) & (pairs[:, 1] >= n)]
            found: dict = {i: [] for i in range(len(regions))}
            for i, j in hit:
                found[int(j) - n].append(int(i))
            for k, r in enumerate(regions):
                self.near[id(r)] = found[k]

    def local(self, part, region) -> mf.CrossSection:
        idx = self.near.get(id(region))
        if idx is None:
            return self.roots[part]
        lp = self.loops[part]
        return mf.CrossSection([lp[i].tolist() for i in idx], mf.FillRule.EvenOdd) if idx \
            else mf.CrossSection()


# ------------------------------------------------------------ webs and merged holes
# mm: boundaries closer than this touch.  Curves are tessellated into inscribed polygons that
# deviate from them by up to CHORD_TOL each, so two circles that touch can come out up to
# 2 CHORD_TOL apart: below that, the gap is the tessellation's, not the design's.
TOUCH = 2 * CHORD_TOL


@dataclass
class _Openings:
    """What :func:`_analyse` finds between the holes of one part and its outline."""
    names: list                     # feature names: 0 the outline, 1.. the holes
    spans: list
    merges: list = field(default_factory=list)   # (i, j, depth mm, common area mm^2 | None)
    webs: list = field(default_factory=list)     # (i, j, width, length, (x, y))
    notches: set = field(default_factory=set)    # holes that reach the outline
    areas: list = field(default_factory=list)    # of the features' regions, mm^2


def _analyse(d: Drawing, s: Structure, shape, cuts, t: float, loops=None) -> _Openings:
    """The holes of part ``s`` (its ``cuts``) that overlap or touch each other (W0508) and the
    walls narrower than ``t`` between two holes or a hole and the outline (W0507), measured
    as the least distance between their boundaries (:func:`.nearby.close_pairs`; the hole's
    region is what it cut).  Candidate hole pairs come from :func:`.nearby.box_pairs`, so the
    work grows as n log n in the number of holes."""
    feats = [c for c in cuts if c.region is not None and not c.region.is_empty()
             and _area(c.region) > 1e-9]
    res = _Openings([f"the outer edge of `{s.path}`"] + [f"hole `{c.hole.path}`" for c in feats],
                    [s.span] + [c.hole.span for c in feats])
    if not feats or shape.is_empty():
        return res
    regions = [c.region for c in feats]
    res.areas = [0.0] + [_area(r) for r in regions] + [0.0]
    polys = [[np.asarray(p, dtype=float) for p in r.to_polygons()] for r in regions]
    boxes = np.array([r.bounds() for r in regions], dtype=float)
    reach = max(t, TOUCH)
    # 1. holes whose regions overlap: one opening
    merged = set()
    for i, j in box_pairs(boxes, pad=reach / 2):
        common = regions[i] ^ regions[j]
        a = _area(common)
        if a > 1e-9:
            merged.add((i, j))
            res.merges.append((i + 1, j + 1, _depth(common, boxes[i], boxes[j]), a))
    # 2. the least distance between every two boundaries closer than `reach`
    # the outline: the part with its holes filled; its outer loops are feature 0, the loops
    # of openings no hole cut (between solids, or left by a fillet) the last feature
    filled = [np.asarray(p, dtype=float) for p in _union([shape] + regions).to_polygons()]
    inner = len(feats) + 1
    res.names.append(f"an inner edge of `{s.path}`")
    res.spans.append(s.span)
    parts = [boundary([p for p in filled if _signed(p) > 0], 0)]
    parts += [boundary(polys[k], k + 1) for k in range(len(feats))]
    parts.append(boundary([p for p in filled if _signed(p) <= 0], inner))
    V, vf, A, B, sf = (np.concatenate([p[k] for p in parts]) for k in range(5))
    # (sf runs 0, 1, ..., inner in order: each feature's segments are one slice of A, B)
    v, sg, dist, foot = close_pairs(V, vf, A, B, sf, reach)
    if not len(v):
        return res
    fa, fb = vf[v], sf[sg]
    lo, hi = np.minimum(fa, fb), np.maximum(fa, fb)
    mid = (V[v] + foot) / 2
    key = lo * (inner + 1) + hi
    order = np.lexsort((dist, key))
    key, dist, mid, lo, hi = key[order], dist[order], mid[order], lo[order], hi[order]
    starts = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    ends = np.r_[starts[1:], len(key)]
    edges = _edges(loops if loops is not None else
                   [np.asarray(p, dtype=float) for p in shape.to_polygons()])
    in_material = _inside(mid[starts], edges)
    for k, (a0, a1) in enumerate(zip(starts, ends)):
        i, j, w = int(lo[a0]), int(hi[a0]), float(dist[a0])
        if i > 0 and j < inner and (i - 1, j - 1) in merged:
            continue
        if w <= TOUCH:
            if i == 0 and j < inner:
                res.notches.add(j)
            elif i > 0 and j < inner:
                merged.add((i - 1, j - 1))
                res.merges.append((i, j, 0.0, None))
            continue
        if w >= t or not in_material[k]:
            continue
        m = mid[a0:a1]
        x0, y0 = m.min(axis=0)
        x1, y1 = m.max(axis=0)
        # located at the middle of a narrowest span (within 0.01 mm of the least width), the
        # one nearest to the close points' box centre: that centre alone can fall between two
        # stretches of one pair of features (two windows of one hole under the roof line: the
        # pillar between them, where nothing is thin)
        c = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        si, sj = slice(*np.searchsorted(sf, (i, i + 1))), slice(*np.searchsorted(sf, (j, j + 1)))
        if _seg_distance(c, A[si], B[si]) + _seg_distance(c, A[sj], B[sj]) > w + 2 * TOUCH:              # the centre is not in the wall: its nearest narrowest
            narrow = m[dist[a0:a1] <= w + TOUCH]                          # span's middle is
            c = narrow[int(np.argmin(np.hypot(*(narrow - c).T)))]
        res.webs.append((i, j, w, max(x1 - x0, y1 - y0), (float(c[0]), float(c[1]))))
    res.merges.sort(key=lambda m: (m[1], m[0]))      # in the order of the located hole
    res.webs.sort(key=lambda w: (w[1], w[0]))
    return res


def _seg_distance(p, A, B) -> float:
    """The least distance (mm) from point ``p`` to the segments ``A[k]``-``B[k]``."""
    if not len(A):
        return math.inf
    d = B - A
    L2 = np.einsum("ij,ij->i", d, d)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, np.einsum("ij,ij->i", p - A, d) / L2, 0.0), 0.0, 1.0)
    e = A + t[:, None] * d - p
    return float(np.sqrt(np.einsum("ij,ij->i", e, e).min()))


def _depth(common, bi, bj) -> float:
    """How far two overlapping regions reach into each other: the extent of their common
    part along the line between their boxes' centres (for two circles exactly
    ``r1 + r2 - distance``), or its narrower side when the centres coincide."""
    P = np.concatenate([np.asarray(p, dtype=float) for p in common.to_polygons()])
    u = (np.asarray(bj[:2]) + bj[2:]) / 2 - (np.asarray(bi[:2]) + bi[2:]) / 2
    n = float(np.hypot(*u))
    if n < 1e-9:
        return float(min(np.ptp(P[:, 0]), np.ptp(P[:, 1])))
    proj = P @ (u / n)
    return float(proj.max() - proj.min())


def _inner(a: _Openings, i: int, j: int, common) -> int | None:
    """Which of holes ``i`` and ``j`` lies wholly inside the other (their common area is
    all of its area), if one does."""
    if common is None:
        return None
    for k in (j, i):
        if common >= (1 - 1e-6) * a.areas[k] - 1e-9:
            return k
    return None


def _report_openings(a: _Openings, s: Structure, t: float, sink: DiagnosticSink) -> set:
    """W0508 for each two holes that cut one opening and W0507 for each web of ``a``; returns
    the name pairs reported (the opening test of :func:`_check_walls` skips them)."""
    covered = set()
    for i, j, depth, common in a.merges:
        first, second = a.names[i], a.names[j]
        covered.add(frozenset((first, second)))
        inner = _inner(a, i, j, common)
        if inner is not None:
            outer = a.names[i + j - inner]
            labels = [Label(a.spans[i + j - inner], f"{outer} is here", primary=False)] \
                if a.spans[i + j - inner] else []
            sink.warning("W0508", f"{a.names[inner]} lies wholly inside {outer} of `{s.path}`: "
                         f"the two cut one opening, and {a.names[inner]} cuts nothing of its "
                         f"own ({common:.2f} mm^2)", a.spans[inner], labels=labels,
                         hint=f"move {a.names[inner]} clear of {outer} (its size or position may "
                              "be in another unit or frame than meant), or delete it")
            continue
        if common is None:
            how, far = "touch", f"{t:g} mm" if t > 0 else "a little"
        else:
            how = f"overlap by {depth:.2f} mm ({common:.2f} mm^2 in common)"
            far = f"{depth + t:.2f} mm" if t > 0 else f"{depth:.2f} mm"
        labels = [Label(a.spans[i], f"{first} is here", primary=False)] if a.spans[i] else []
        sink.warning("W0508", f"{first} and {second} of `{s.path}` {how}, so they cut one "
                     "opening, not two", a.spans[j], labels=labels,
                     hint=f"move {second} {far} further from {first} (or shrink one of them) so that "
                          "material is left between them; if one opening is meant, draw both "
                          "shapes in one hole structure (the faces of one hole may overlap)")
    inner = len(a.names) - 1
    for i, j, w, length, (x, y) in a.webs:
        covered.add(frozenset((a.names[i], a.names[j])))
        if i == 0 or j == inner:          # a hole and an edge of the outline
            hole, edge = (j, i) if i == 0 else (i, j)
            pair, away, labels = f"{a.names[hole]} and {a.names[edge]}", \
                a.names[edge].split(" of ")[0], []
        else:                             # two holes, located at the later one
            hole, pair, away = j, f"{a.names[i]} and {a.names[j]}", a.names[i]
            labels = [Label(a.spans[i], "the other side of the wall", primary=False)] \
                if a.spans[i] else []
        sink.warning("W0507", f"a wall of `{s.path}` between {pair} is "
                     f"{w:.2f} mm wide, thinner than {t:g} mm (over {length:.1f} mm, near "
                     f"({x:.1f}, {y:.1f}))", a.spans[hole], labels=labels,
                     hint=f"move {a.names[hole]} {t - w:.2f} mm further from {away} (or shrink "
                          f"it) so that at least {t:g} mm of material is left (a laser or "
                          "router cannot hold a thinner wall); the minimum is set with "
                          "--min-wall")
    return covered


def _check_hole(d: Drawing, cut, roots, sink: DiagnosticSink, local=None,
                owner_areas: dict | None = None) -> str | None:
    """W0501-W0503 for one cut; ``local(part, region)``: the part's final shape near
    ``region`` (:class:`_Near`), else the whole final shape is intersected;
    ``owner_areas``: the owners' final areas by structure, filled as they are taken (a plate's
    area is O(its vertices): once per hole, it made 5,000 holes quadratic, issue 38)."""
    h, s = cut.hole, cut.owner
    hole_shape = d.shapes.get(h)
    whole = _area(hole_shape)
    cut_area = _area(cut.region)
    before = _area(cut.before)
    if whole <= 0:
        return
    if cut_area <= max(1e-9, 1e-6 * whole):
        sink.warning("W0502", f"hole `{h.path}` cuts nothing: it lies outside solid `{s.path}`",
                     h.span, hint=f"move the hole inside `{s.path}` (for example "
                                  f"`CenterInside({h.name}, self)`), or declare it in the solid "
                                  "it should cut")
        return
    if owner_areas is None:
        owner_areas = {}
    if before > 0 and s not in owner_areas:
        owner_areas[s] = _area(d.shapes.get(s))
    if before > 0 and owner_areas[s] <= max(1e-9, 1e-6 * before):
        sink.warning("W0503", f"hole `{h.path}` removes all of solid `{s.path}`", h.span,
                     hint=f"make the hole smaller than `{s.path}` or move it so that material "
                          "is left around it")
        return "W0503"
    part = _part_of(s, roots)
    if part is None:
        return
    final = local(part, cut.region) if local is not None else roots[part]
    refilled = _area(cut.region ^ final)
    if not _significant(refilled, cut_area):
        return
    # who refills it: the other contributors of each ancestor between the owner and the part
    culprits, node, intended = [], s, 0
    while node is not part and node.parent is not None:
        a = node.parent
        for name, span, shp, obj in _contributors(d, a, skip=node, objects=True):
            if _significant(_area(cut.region ^ shp), cut_area):
                if _intended(h, s, obj):        # AllowOverlap(hole, this): not reported
                    intended += 1
                    continue
                culprits.append((name, span, a, obj))
        if node.parent is part:
            break
        node = a
    if intended and not culprits:
        return
    survives = max(0.0, cut_area - refilled)
    who = ", ".join(c[0] for c in culprits[:3]) or "a solid united later"
    common = culprits[0][2] if culprits else part
    labels = [Label(span, "refills the hole", primary=False)
              for _, span, _, _ in culprits[:3] if span is not None]
    sink.warning(
        "W0501",
        f"hole `{h.path}` is refilled by {who}: only {_pct(survives, cut_area)} of it still "
        f"cuts through",
        h.span, labels=labels,
        hint=(f"a hole cuts only the solid it is declared in (`{s.path}`); declare the hole in "
              f"`{common.path}`, the common parent, so that it cuts everything united there, "
              "or move it clear of the solid that covers it; if the overlap is intended, "
              f"write `AllowOverlap({_rel(h, common)}, "
              f"{_rel(culprits[0][3], common) if culprits else 'solid'})` in `{common.path}`"))


def _rel(obj, base: Structure) -> str:
    """How structure ``base``'s body names ``obj`` (a structure or a named shape below it)."""
    if isinstance(obj, Structure):
        path, own = obj.path, None
    else:
        path, own = obj.owner.path, obj.name or obj.kind
    rel = path[len(base.path) + 1:] if path.startswith(base.path + ".") else \
        ("" if path == base.path else path)
    return ".".join(p for p in (rel, own) if p)


def _check_pieces(d: Drawing, s: Structure, shape, sink: DiagnosticSink,
                  loops: list | None = None) -> None:
    """W0504 for part ``s``.  A shape has one piece per outline loop that runs
    counter-clockwise (an outer boundary; holes run clockwise), so a shape with at most one
    such loop (``loops``: its polygons, when already at hand) is not split into pieces."""
    if shape.is_empty():
        return
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    if sum(_signed(p) > 0 for p in loops) < 2:
        return
    total = _area(shape)
    pieces = [p for p in shape.decompose() if _area(p) > max(1e-9, 1e-6 * total)]
    if len(pieces) < 2:
        return
    items = _contributors(d, s)
    # the message names the first 6 pieces and up to 4 contributors of each (and "..." for
    # a fifth): only those are measured, and only contributors whose box meets the piece's
    # (every piece against every contributor was 25 M intersections for 5 000 circles)
    boxes = np.array([shp.bounds() for _, _, shp in items], dtype=float).reshape(-1, 4)
    groups = []
    for p in pieces[:6]:
        b = p.bounds()
        near = np.flatnonzero((boxes[:, 0] <= b[2]) & (boxes[:, 2] >= b[0])
                              & (boxes[:, 1] <= b[3]) & (boxes[:, 3] >= b[1]))
        names = []
        for k in near:
            n, _, shp = items[k]
            if _area(p ^ shp) > max(1e-9, 1e-6 * _area(shp)):
                names.append(n)
                if len(names) > 4:
                    break
        groups.append("{" + ", ".join(names[:4]) + (", ..." if len(names) > 4 else "") + "}")
    sink.warning(
        "W0504",
        f"solid `{s.path}` falls apart into {len(pieces)} separate pieces: "
        + "; ".join(groups) + ("; ..." if len(pieces) > 6 else ""),
        s.span,
        hint="make the pieces overlap (for example `Above(a, b, gap=-1 mm)`) or share an edge "
             "(touching at a point is not enough), or, if they are separate parts, make the "
             "structure an `assembly`")


def _check_invisible(d: Drawing, s: Structure, sink: DiagnosticSink, quick: bool = True) -> None:
    """W0506 for the solid children of ``s`` that add nothing to it.  ``quick=False``
    measures every child (the reference for the area bound's test)."""
    items = _contributors(d, s)
    if len(items) < 2 or len(items) > MAX_CHILDREN:
        return
    areas = [_area(shp) for _, _, shp in items]
    total = sum(areas)
    for i, (name, span, shp) in enumerate(items):
        if not name.startswith("solid "):
            continue
        a = areas[i]
        if a <= MIN_AREA:
            continue
        # The others cover at most the sum of their areas, so at least `a - rest` of this
        # child shows; when that is far above the threshold (1e-6 of the areas: orders of
        # magnitude above Manifold's rounding) it is not measured.
        rest = total - a
        if quick and a - rest > max(1e-9, 1e-4 * a) + 1e-6 * (a + rest) + 1e-6:
            continue
        others = _union([o for j, (_, _, o) in enumerate(items) if j != i])
        if _area(shp - others) <= max(1e-9, 1e-4 * a):
            cut = [h for h in s.children.values() if h.kind == "hole" and h in d.shapes
                   and _area(shp ^ d.shapes[h]) > max(1e-9, 1e-4 * a)]
            if cut:                 # cut away by a hole of the same structure: say so
                share = _area(shp ^ _union([d.shapes[h] for h in cut])) / a
                how = ("all of it" if share >= 0.9995 else
                       f"{share:.0%} of it, and the rest lies inside the rest of `{s.path}`")
                sink.warning("W0506", f"{name} adds nothing to `{s.path}`: hole "
                             f"`{cut[0].path}` of the same structure cuts away {how}", span,
                             hint=f"a hole cuts every solid of the structure it is declared in, "
                                  f"children included; to keep this solid over the hole, "
                                  f"declare it beside `{s.name}` (a sibling structure's "
                                  f"material survives the hole), else delete it")
                continue
            sink.warning("W0506", f"{name} adds nothing to `{s.path}`: it lies wholly inside "
                         "the rest of it", span,
                         hint="move it where it shows (it is probably mispositioned), make it a "
                              "`hole` if it should cut, or delete it")


def _check_walls(d: Drawing, s: Structure, shape, t: float, cuts, sink: DiagnosticSink,
                 quick: bool = True, covered: set = frozenset(), loops=None,
                 tick=lambda ahead=0.0: None) -> None:
    """W0507 for part ``s`` (its final ``shape``, its ``cuts``) at minimum wall ``t`` mm: one
    warning per piece of at least ``2 t^2`` that the opening removes.  ``quick=False`` skips
    the whole-area bound below (the reference for its test); ``covered``: name pairs already
    reported with their measured width (:func:`_report_openings`), whose pieces are skipped;
    ``tick(ahead)`` is called before each step (the compile's deadline; ``ahead``: the
    seconds a step that cannot be interrupted is expected to take, from its vertex count)."""
    if shape.is_empty():
        return
    segs = 16
    tick(shape.num_vert() * THIN_SECONDS_PER_VERTEX)
    pieces = _thin(shape, t, loops, tick=tick, least=2 * t * t)
    # The pieces partition what the opening removes, so none reaches 2 t^2 when the whole does
    # not (the same polygon areas summed in another order: the margin is far above the
    # rounding).  On a part without thin walls the opening removes only corner slivers (the
    # telephone: 391 of them, 0.1 mm^2 in all against 0.5 mm^2), which are then not measured.
    areas = [_area(p) for p in pieces]
    if not pieces or quick and sum(areas) < 2 * t * t * (1 - 1e-9):
        return
    holes = [c for c in cuts if c.hole in d.shapes and not d.shapes[c.hole].is_empty()]
    hb = np.array([d.shapes[c.hole].bounds() for c in holes], dtype=float).reshape(-1, 4)
    filled = None
    for piece, a in zip(pieces, areas):
        tick()
        if a < 2 * t * t:
            continue
        if filled is None:
            filled = _union([shape] + [d.shapes[c.hole] for c in holes])
        near = piece.offset(t, mf.JoinType.Round, 2.0, segs)
        nx0, ny0, nx1, ny1 = near.bounds()
        close = np.flatnonzero((hb[:, 0] <= nx1) & (hb[:, 2] >= nx0) & (hb[:, 1] <= ny1)
                               & (hb[:, 3] >= ny0))
        names = [f"hole `{holes[k].hole.path}`" for k in close
                 if _area(near ^ d.shapes[holes[k].hole]) > 1e-9]
        if _area(near - filled) > 1e-9:
            names.append(f"the outer edge of `{s.path}`")
        names = list(dict.fromkeys(names))
        if names and any(set(names) <= c for c in covered):
            continue
        x0, y0, x1, y1 = piece.bounds()
        length = max(x1 - x0, y1 - y0, 1e-9)
        width = min(t, a / length)
        between = (" between " + " and ".join(names[:2])) if len(names) >= 2 else (
            f" beside {names[0]}" if names else "")
        span = next((c.hole.span for c in holes if f"hole `{c.hole.path}`" in names), s.span)
        px, py = _point_of(piece, ((x0 + x1) / 2, (y0 + y1) / 2))
        sink.warning("W0507", f"a wall of `{s.path}`{between} is thinner than {t:g} mm "
                     f"(about {width:.2f} mm over {length:.1f} mm, near "
                     f"({px:.1f}, {py:.1f}))", span,
                     hint=f"move or shrink the feature so that at least {t:g} mm of material is "
                          "left (a laser or router cannot hold a thinner wall); the minimum is "
                          "set with --min-wall")


def _point_of(piece, near) -> tuple[float, float]:
    """The vertex of ``piece`` (what the opening removed: a thin wall) nearest to ``near``
    (its box's centre): a point on the wall itself, where the box's centre of a curved or
    L-shaped wall lies off it."""
    P = np.concatenate([np.asarray(p, dtype=float) for p in piece.to_polygons()])
    k = int(np.argmin(np.hypot(P[:, 0] - near[0], P[:, 1] - near[1])))
    return float(P[k, 0]), float(P[k, 1])


UNION_GROUP = 16       # tile pieces united in one uninterruptible call by _join
TILE_VERTS = 2000      # W0507's opening is taken tile by tile above this many vertices ...
WHOLE_LOOPS = 2        # ... and loops: an outline and one hole (a gear and its bore) are opened
WHOLE_VERTS = 10_000   # whole up to this many vertices, since clipping a loop into tiles costs
                       # more than opening it (not beyond: what the opening removes is split
                       # into its pieces at once, and Manifold's decompose crashes on 70,000)
# the least time per vertex of the steps the deadline cannot interrupt (measured on the 2-core
# machine: the opening ~60 us, decomposing what it removes ~24 us, uniting the tiles' parts
# ~18 us per vertex; half of that, so that only steps sure to overrun are refused before they
# start)
THIN_SECONDS_PER_VERTEX = 30e-6
DECOMPOSE_SECONDS_PER_VERTEX = 12e-6
UNION_SECONDS_PER_VERTEX = 9e-6     # seed 791: the tiles' last union, 515,225 vertices, 9.3 s


def _open(shape, t: float):
    segs = 16
    return shape.offset(-t / 2, mf.JoinType.Round, 2.0, segs).offset(t / 2, mf.JoinType.Round,
                                                                     2.0, segs)


def _thin(shape, t: float, loops=None, tile: int = TILE_VERTS, tick=lambda ahead=0.0: None,
          least: float = 0.0, whole_loops: int = WHOLE_LOOPS) -> list:
    """The connected pieces of what the opening of ``shape`` by a disc of diameter ``t``
    removes (a list of CrossSections; pieces of area below ``least`` mm^2 may come in bits).

    Clipper2's offset runs a sweep whose cost grows faster than the vertex count (on a grid of
    holes about as n^1.5: 12 ms at 100 holes, 256 ms at 900), so a shape of more than ``tile``
    vertices is cut into tiles: whether a point survives the opening depends only on the shape
    within ``t`` of it, so each tile is opened with a margin of ``2 t`` around it (the shape
    clipped to the grown tile) and what the opening removes inside the tile itself is kept.
    The tiles come from halving the box along its longer side while the clipped shape has more
    than ``tile`` vertices (each half clipped from its parent's piece): O(n log n) whatever the
    shape.  A grid of tiles over the bounding box cost tiles x vertices for one long loop (a
    diagonal chain of 10 000 circles: 81 tiles, each clipping the whole 150 000-vertex loop,
    20 s).  A shape of at most ``whole_loops`` loops and :data:`WHOLE_VERTS` vertices is
    opened whole: each tile clips the loops that cross it, and for one long loop that costs
    more than the opening itself (one wavy loop of 2,520 vertices: 11.6 ms in tiles, 7.0 ms
    whole; of 42,000: 883 and 193 ms; a diagonal chain of 1,000 circles, one loop of 16,000
    vertices: 591 and 149 ms), up to a size where what the opening removes could come in
    more pieces than Manifold's ``decompose`` survives (the chain of 10,000 circles, one loop
    of 160,000 vertices: 3.5 s in tiles; whole, the opening takes 1.0 s and decomposing its
    140,000 slivers crashes the process, as 70,000 do; 35,000 do not).

    When all of it weighs less than ``least``, the tiles' parts are returned as they are;
    else each is split into its pieces, and only the pieces that meet across a tile's edge
    (their boxes touch) and weigh at least ``least`` together are united (:func:`_join`).
    Uniting every tile's part into one shape first cost one uninterruptible Manifold call over
    all of them (fuzz seeds 791 and 1542: 5,000 circles, 515,225 vertices of corner slivers,
    9-25 s).  ``loops`` is accepted for the callers' convenience (unused); ``tick(ahead)`` is
    called before each tile and each union (the compile's deadline).

    The tiles are cut from the shape's loops (:func:`_clip_loops`: only the loops that cross a
    tile's edge are clipped), and a loop that lies alone (:func:`_isolated_loops`) is opened
    by itself, once per shape of loop (:func:`_thin_of_loop`): a plate of 5,000 equal round
    holes 2 mm apart opens one hole, its outline's edge and the holes beside it
    (``check_drawing`` 3.65 s -> 0.82 s)."""
    n = shape.num_vert()
    if n <= tile or n <= WHOLE_VERTS and shape.num_contour() <= whole_loops:
        thin = shape - _open(shape, t)
        if _area(thin) < least:
            return [thin]
        tick(thin.num_vert() * DECOMPOSE_SECONDS_PER_VERTEX)
        return thin.decompose()
    m = 2 * t
    out: list = []           # what the opening removes in each tile

    def box(a, b, c, e):
        return mf.CrossSection.square((c - a, e - b)).translate((a, b))

    def split(loops, boxes, a, b, c, e):
        tick()
        if not loops:
            return
        small = max(c - a, e - b) <= 8 * t          # halving no longer sheds the margin
        if sum(len(p) for p in loops) <= tile or small:
            piece = mf.CrossSection(loops, mf.FillRule.Positive)
            part = (piece - _open(piece, t)) ^ box(a, b, c, e)
            if not part.is_empty():
                out.append(part)
            return
        if c - a >= e - b:
            mid = (a + c) / 2
            halves = [(a, b, mid, e), (mid, b, c, e)]
        else:
            mid = (b + e) / 2
            halves = [(a, b, c, mid), (a, mid, c, e)]
        for h in halves:
            split(*_clip_loops(loops, boxes, h[0] - m, h[1] - m, h[2] + m, h[3] + m), *h)

    loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    boxes = _loop_boxes(loops)
    alone = _isolated_loops(loops, boxes, t)
    cache: dict = {}
    for k in np.flatnonzero(alone):
        tick()
        part = _thin_of_loop(loops[k], t, cache)
        if part is not None:
            out.append(part)
    rest = [loops[k] for k in np.flatnonzero(~alone)]
    x0, y0, x1, y1 = shape.bounds()
    split(rest, boxes[~alone], x0, y0, max(x1, x0 + 1e-9), max(y1, y0 + 1e-9))
    if sum(_area(p) for p in out) < least:        # corner slivers only: nothing to measure
        return out
    pieces = []
    for k, part in enumerate(out):
        tick(part.num_vert() * DECOMPOSE_SECONDS_PER_VERTEX)
        pieces.extend((k, p) for p in part.decompose())
    return _join(pieces, least, tick)


def _isolated_loops(loops: list, boxes: np.ndarray, t: float) -> np.ndarray:
    """Which ``loops`` (with their ``boxes``) lie farther than ``1.5 t`` from every other loop
    and enclose none (a boolean array; a sufficient test, by boxes: a loop said not isolated
    may still be).  What the opening by a disc of diameter ``t`` removes lies within ``t / 2``
    of the boundary, and whether a point there is removed depends on the shape within ``t``
    of it, so near an isolated loop it depends on that loop alone (:func:`_thin_of_loop`),
    and the other loops' part is the same without it.  Large loops (a plate's outline) are
    tested by their edges' boxes, so that the holes inside them are not all near them."""
    n = len(loops)
    if n < 2:
        return np.zeros(n, dtype=bool)
    diag = np.hypot(boxes[:, 2] - boxes[:, 0], boxes[:, 3] - boxes[:, 1])
    big = diag > max(4 * float(np.median(diag)), 8 * t)
    owner = [np.flatnonzero(~big)]
    items = [boxes[~big]]
    for k in np.flatnonzero(big):            # a large loop: one box per edge
        P = loops[k]
        Q = np.roll(P, -1, axis=0)
        items.append(np.hstack([np.minimum(P, Q), np.maximum(P, Q)]))
        owner.append(np.full(len(P), k))
    owner = np.concatenate(owner)
    pairs = box_pairs(np.concatenate(items), pad=0.75 * t * (1 + 1e-6) + 1e-9)
    near = owner[pairs]
    near = near[near[:, 0] != near[:, 1]]
    alone = ~big
    alone[near.ravel()] = False
    return alone


def _thin_of_loop(loop: np.ndarray, t: float, cache: dict):
    """What the opening by a disc of diameter ``t`` removes near ``loop`` (an (n, 2) array,
    counter-clockwise for an outline, clockwise for a hole) when no other loop lies within
    ``1.5 t`` of it (:func:`_isolated_loops`), a CrossSection, or None when it is empty: from
    the loop alone (a hole in a square of material ``2 t`` wider than its box).  Computed once
    per shape: ``cache`` holds what is removed near each loop seen, by its vertices relative
    to its box's corner (to 1e-9 mm), so a grid of 5,000 equal holes is opened once; the
    others take its result moved (Clipper rounds to its grid where the loop lies: the slivers
    of a moved circle differ by ~1e-8 mm^2)."""
    lo = loop.min(axis=0)
    key = (len(loop), np.round(loop - lo, 9).tobytes())
    seen = cache.get(key)
    if seen is None:              # opened where it lies (Clipper rounds to its own grid)
        (x0, y0), (x1, y1) = lo, loop.max(axis=0)
        own = mf.CrossSection([loop], mf.FillRule.Positive)
        if own.is_empty():                    # clockwise: a hole in the material around it
            own = (mf.CrossSection.square((x1 - x0 + 4 * t, y1 - y0 + 4 * t))
                   .translate((x0 - 2 * t, y0 - 2 * t))
                   - mf.CrossSection([loop[::-1]], mf.FillRule.Positive))
        near = (mf.CrossSection.square((x1 - x0 + 2 * t, y1 - y0 + 2 * t))
                .translate((x0 - t, y0 - t)))
        seen = cache[key] = ((own - _open(own, t)) ^ near, lo)
    thin, at = seen
    if thin.is_empty():
        return None
    return thin if at is lo else thin.translate((float(lo[0] - at[0]), float(lo[1] - at[1])))


def _loop_boxes(loops: list) -> np.ndarray:
    """The boxes (x0, y0, x1, y1) of ``loops`` ((n, 2) arrays), an (len(loops), 4) array."""
    if not loops:
        return np.zeros((0, 4))
    P = np.concatenate(loops)
    start = np.cumsum([0] + [len(p) for p in loops[:-1]])
    return np.hstack([np.minimum.reduceat(P, start), np.maximum.reduceat(P, start)])


def _clip_loops(loops: list, boxes: np.ndarray, a: float, b: float, c: float, e: float):
    """The loops of a shape (outer loops counter-clockwise, holes clockwise, as
    ``CrossSection.to_polygons`` gives them, with their ``boxes``) clipped to the box
    ``a <= x <= c, b <= y <= e``: (loops, boxes) with the same winding number at every point
    of the box.  A loop whose box lies inside the box is kept whole and one whose box misses
    it is dropped, without a boolean; only the loops whose boxes cross its edge are clipped
    (one Clipper boolean over those alone).  Every loop that encloses a crossing loop crosses
    too (its box contains the other's), so the crossing loops' winding numbers are 0 or 1
    and the boolean keeps them; adding the whole loops' windings gives the shape's.  On a
    plate of 5,000 round holes this clips a few hundred vertices per tile where clipping the
    whole shape cost its 225,000 vertices at each of the halving's 7 levels."""
    inside = (boxes[:, 0] > a) & (boxes[:, 1] > b) & (boxes[:, 2] < c) & (boxes[:, 3] < e)
    meets = (boxes[:, 0] <= c) & (boxes[:, 2] >= a) & (boxes[:, 1] <= e) & (boxes[:, 3] >= b)
    keep = [loops[k] for k in np.flatnonzero(inside)]
    cross = np.flatnonzero(meets & ~inside)
    if len(cross) == 0:
        return keep, boxes[inside]
    rect = mf.CrossSection.square((c - a, e - b)).translate((a, b))
    cut = mf.CrossSection([loops[k] for k in cross], mf.FillRule.Positive) ^ rect
    cut_loops = [np.asarray(p, dtype=float) for p in cut.to_polygons()]
    return keep + cut_loops, np.concatenate([boxes[inside], _loop_boxes(cut_loops)])


def _join(pieces: list, least: float, tick) -> list:
    """The connected pieces made of ``pieces`` ((tile number, CrossSection) pairs; pieces of
    one tile are disjoint, pieces of different tiles meet at most along the tiles' edges):
    pieces of different tiles whose boxes touch are grouped (connected components of the
    touching pairs), and a group of at least ``least`` mm^2 is united :data:`UNION_GROUP`
    parts at a time, the deadline's ``tick(ahead)`` before each union, then split again
    (touching boxes do not make the shapes touch)."""
    if not pieces:
        return []
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    tiles = np.array([k for k, _ in pieces])
    shapes = [p for _, p in pieces]
    boxes = np.array([p.bounds() for p in shapes], dtype=float).reshape(-1, 4)
    span = float(np.max(np.abs(boxes))) if len(boxes) else 1.0
    pairs = box_pairs(boxes, pad=1e-9 * max(span, 1.0))
    pairs = pairs[tiles[pairs[:, 0]] != tiles[pairs[:, 1]]]
    n = len(shapes)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _count, label = connected_components(graph, directed=False)
    groups: dict = {}
    for i, g in enumerate(label):
        groups.setdefault(g, []).append(shapes[i])
    result = []
    for group in groups.values():
        if len(group) == 1 or sum(_area(p) for p in group) < least:
            result.extend(group)
            continue
        while len(group) > 1:
            nxt = []
            for i in range(0, len(group), UNION_GROUP):
                part = group[i:i + UNION_GROUP]
                tick(sum(p.num_vert() for p in part) * UNION_SECONDS_PER_VERTEX)
                nxt.append(_union(part))
            group = nxt
        result.extend(group[0].decompose())
    return result


def _inside_loops(pts: np.ndarray, loops) -> np.ndarray:
    """The reference even-odd test: every point against every edge of each loop in turn
    (O(points x edges) memory and time).  Kept for the property test of :func:`_inside`."""
    res = np.zeros(len(pts), dtype=bool)
    x, y = pts[:, 0], pts[:, 1]
    for lp in loops:
        P = np.asarray(lp, dtype=float)
        Q = np.roll(P, -1, axis=0)
        x1, y1, x2, y2 = P[:, 0][None], P[:, 1][None], Q[:, 0][None], Q[:, 1][None]
        yy = y[:, None]
        cond = (y1 > yy) != (y2 > yy)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            xi = x1 + (yy - y1) * (x2 - x1) / (y2 - y1)
        res ^= (np.sum(cond & (x[:, None] < xi), axis=1) % 2).astype(bool)
    return res


def _inside(pts: np.ndarray, loops) -> np.ndarray:
    """Even-odd point-in-polygon of ``pts`` (N x 2, mm) against the union of closed ``loops``
    (each M x 2, implicitly closed; or their :func:`_edges`): True where a ray to -x crosses the loops' edges an odd
    number of times (the crossing-number test, as in W. R. Franklin's ``pnpoly``).

    The edges of all loops are taken together (the parity of the total equals the XOR of the
    per-loop parities) and each edge is tested only against the points whose y lies in its
    half-open y range ``[min(y1, y2), max(y1, y2))``, found by binary search in the points
    sorted by y; so the work is O((N + E) log N + crossings-candidates), not O(N E).  The
    crossing abscissa is computed with the same floating-point expression as the reference
    :func:`_inside_loops`, so the result is identical to it."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 2)
    n = len(pts)
    x1, y1, x2, y2 = loops if isinstance(loops, tuple) else _edges(loops)
    if not n or not len(x1):
        return np.zeros(n, dtype=bool)
    x, y = pts[:, 0], pts[:, 1]
    order = np.argsort(y, kind="stable")
    ys = y[order]
    lo = np.searchsorted(ys, np.minimum(y1, y2), side="left")
    hi = np.searchsorted(ys, np.maximum(y1, y2), side="left")
    cnt = np.maximum(hi - lo, 0)
    total = int(cnt.sum())
    if not total:
        return np.zeros(n, dtype=bool)
    edge = np.repeat(np.arange(len(x1)), cnt)
    start = np.cumsum(cnt) - cnt
    pt = order[lo[edge] + (np.arange(total) - start[edge])]
    yy, ex1, ey1, ex2, ey2 = y[pt], x1[edge], y1[edge], x2[edge], y2[edge]
    cond = (ey1 > yy) != (ey2 > yy)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        xi = ex1 + (yy - ey1) * (ex2 - ex1) / (ey2 - ey1)
    hit = cond & (x[pt] < xi)
    return (np.bincount(pt[hit], minlength=n) % 2).astype(bool)


def _edges(loops) -> tuple:
    """The edges of closed ``loops`` as four arrays (x1, y1, x2, y2): each vertex to the next,
    the last back to the first; what :func:`_inside` takes (prepared once per part)."""
    polys = [np.asarray(lp, dtype=float).reshape(-1, 2) for lp in loops]
    polys = [P for P in polys if len(P)]
    if not polys:
        return (np.zeros(0),) * 4
    P = np.concatenate(polys)
    Q = np.concatenate([np.concatenate([p[1:], p[:1]]) for p in polys])   # np.roll(p, -1)
    return P[:, 0], P[:, 1], Q[:, 0], Q[:, 1]


_T9 = np.linspace(0, 1, 9)[:, None]


def _sample(item) -> np.ndarray:
    kind = item[0]
    if kind == "line":
        p, q = np.asarray(item[1], float), np.asarray(item[2], float)
        return p + _T9 * (q - p)
    if kind == "poly":
        P = np.asarray(item[1], float)
        return np.vstack([P, (P + np.roll(P, -1, axis=0)) / 2])
    if kind == "circle":
        c, r = np.asarray(item[1], float), float(item[2])
        t = np.linspace(0, 2 * math.pi, 32, endpoint=False)
        return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])
    if kind == "ellipse_arc":            # 17 points along it
        arc = item[1]
        return np.array([arc.at(arc.start_param + arc.sweep * i / 16) for i in range(17)])
    if kind == "spline":                 # 9 points along each span
        from ..geometry.spline import bez_at
        return np.array([bez_at(b, float(t)) for b in item[1].spans for t in _T9[:, 0]])
    _, c, r, a1, a2 = item
    sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
    t = a1 + np.linspace(0, sweep, 17)
    return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])


def _n_samples(item) -> int:
    """How many points :func:`_sample` gives for ``item``."""
    kind = item[0]
    if kind == "poly":
        return 2 * len(item[1])
    if kind == "spline":
        return 9 * len(item[1].spans)
    return {"line": 9, "circle": 32}.get(kind, 17)


_T32 = np.linspace(0, 2 * math.pi, 32, endpoint=False)
_COS32, _SIN32 = np.cos(_T32), np.sin(_T32)


def _samples(items) -> np.ndarray:
    """The sample points of engraving ``items``, in order: :func:`_sample` of each, with the
    runs of lines and of circles each taken as one array operation (the same floating-point
    operations per point)."""
    out, run, kind = [], [], None

    def flush():
        if kind == "line":
            L = np.asarray(run, dtype=float)             # k x 2 x 2
            p, q = L[:, 0][:, None, :], L[:, 1][:, None, :]
            out.append((p + _T9[None] * (q - p)).reshape(-1, 2))
        elif kind == "circle":
            C = np.asarray([c for c, _ in run], dtype=float)    # k x 2
            R = np.asarray([r for _, r in run], dtype=float)[:, None]
            xy = np.empty((len(run), 32, 2))
            xy[:, :, 0] = C[:, :1] + R * _COS32
            xy[:, :, 1] = C[:, 1:] + R * _SIN32
            out.append(xy.reshape(-1, 2))
        run.clear()
    for it in items:
        k = it[0]
        if k != kind and run:
            flush()
        if k == "line":
            run.append((it[1], it[2]))
        elif k == "circle":
            run.append((it[1], float(it[2])))
        else:
            out.append(_sample(it))
        kind = k if k in ("line", "circle") else None
    if run:
        flush()
    return np.vstack(out)


# Manifold's round offset puts its arc vertices on the circle (Clipper2's round joins, arc
# tolerance r (1 - cos(pi / segments)) with 16 segments), so the part grown by ENGRAVE_TOL
# holds every point within ENGRAVE_TOL cos(pi / 16) of the part, less the 1e-8 mm grid
_SURELY_GROWN = ENGRAVE_TOL * math.cos(math.pi / 16) - 1e-6


def _all_on_material(shape, pts: np.ndarray, loops: list | None = None) -> bool:
    """True when every point of ``pts`` is certainly inside ``shape`` grown by
    :data:`ENGRAVE_TOL` (what W0505 tests), without growing it: each point is inside the
    outline itself or within :data:`_SURELY_GROWN` of one of its edges.  False means "not
    shown": the grown outline then decides (engraving drawn on the edge is the usual case
    the outline alone cannot settle).  ``loops``: the shape's polygons, when at hand."""
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    edges = _edges(loops)
    out = ~_inside(pts, edges)
    if not out.any():
        return True
    return bool(_within(pts[out], edges, _SURELY_GROWN).all())


def _within(pts: np.ndarray, edges: tuple, dist: float, max_pairs: int = 2_000_000) -> np.ndarray:
    """True where a point of ``pts`` (N x 2) lies within ``dist`` of one of the segments
    ``edges`` (x1, y1, x2, y2 arrays).  Each segment is measured only against the points
    whose y lies within ``dist`` of its y range (binary search in the points sorted by y).
    All False when more than ``max_pairs`` pairs would be measured."""
    pts = np.asarray(pts, dtype=float).reshape(-1, 2)
    n = len(pts)
    x1, y1, x2, y2 = edges
    res = np.zeros(n, dtype=bool)
    if not n or not len(x1):
        return res
    x, y = pts[:, 0], pts[:, 1]
    order = np.argsort(y, kind="stable")
    ys = y[order]
    ymin, ymax = np.minimum(y1, y2), np.maximum(y1, y2)
    # the window is wider than ``dist`` by a few units in the last place, so that a point
    # which the distance below rounds to exactly ``dist`` is never filtered out first
    pad = dist + 8 * np.finfo(float).eps * (np.abs(ymin) + np.abs(ymax) + dist)
    lo = np.searchsorted(ys, ymin - pad, side="left")
    hi = np.searchsorted(ys, ymax + pad, side="right")
    cnt = np.maximum(hi - lo, 0)
    total = int(cnt.sum())
    if not total or total > max_pairs:
        return res
    edge = np.repeat(np.arange(len(x1)), cnt)
    start = np.cumsum(cnt) - cnt
    pt = order[lo[edge] + (np.arange(total) - start[edge])]
    ax, ay = x1[edge], y1[edge]
    dx, dy = x2[edge] - ax, y2[edge] - ay
    px, py = x[pt] - ax, y[pt] - ay
    L2 = dx * dx + dy * dy
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(L2 > 0, (px * dx + py * dy) / L2, 0.0), 0.0, 1.0)
    ex, ey = px - t * dx, py - t * dy
    res[pt[ex * ex + ey * ey <= dist * dist]] = True
    return res


def _check_engraving(d: Drawing, roots, sink: DiagnosticSink, loops: dict | None = None) -> None:
    """W0505 for each engraved geometry with sample points off its part's material (the part
    grown by :data:`ENGRAVE_TOL`).  The points of all the geometries of one part are tested
    in one :func:`_inside` call (a point's verdict does not depend on the other points), and
    a part whose points are all certainly on it (:func:`_all_on_material`) is not grown."""
    by_geom: dict = {}
    for style, item, g in d.strokes:
        if style == "drawing" and g is not None:
            by_geom.setdefault(g, []).append(item)
    by_part: dict = {}
    for g, items in by_geom.items():
        part = _part_of(g.owner, roots)
        if part is None or part.kind != "solid" or roots[part].is_empty():
            continue
        by_part.setdefault(part, []).append((g, items))
    verdicts: dict = {}
    for part, geoms in by_part.items():
        shp = roots[part]
        pts = _samples([it for _, items in geoms for it in items])
        _check_on_cut(part, shp, geoms, pts, (loops or {}).get(part), sink)
        if _all_on_material(shp, pts, (loops or {}).get(part)):
            continue
        grown = shp.offset(ENGRAVE_TOL, mf.JoinType.Round, 2.0, 16)
        grown_loops = [np.asarray(p, dtype=float) for p in grown.to_polygons()]
        inside = _inside(pts, _edges(grown_loops))
        at = 0
        for g, items in geoms:
            n = sum(_n_samples(it) for it in items)
            verdicts[g] = (part, pts[at:at + n], inside[at:at + n], grown_loops)
            at += n
    outer_of: dict = {}
    for g in by_geom:
        if g not in verdicts:
            continue
        part, pts, inside, grown_loops = verdicts[g]
        if inside.all():
            continue
        if part not in outer_of:
            outer_of[part] = _edges([p for p in grown_loops if _signed(p) > 0])
        in_outline = _inside(pts[~inside], outer_of[part])
        where = "across a hole" if in_outline.all() else (
            "outside the outline" if not in_outline.any() else "outside the outline and across a hole")
        sink.warning("W0505", f"engraving `{g.label}` runs {where} of `{part.path}` "
                     f"({_pct(float((~inside).sum()), float(len(pts)))} of it is off the material)",
                     g.span,
                     hint="move or shrink the drawing so that it lies on the material (constrain "
                          "it, e.g. `Inside(label, body)`), or clear the hole it crosses")


ON_CUT = 1 / 3           # of an engraving's samples: more on the outline is engraved over the cut


def _check_on_cut(part, shape, geoms, pts: np.ndarray, loops, sink) -> None:
    """W0516 for each engraved geometry of ``part`` of which more than :data:`ON_CUT` of the
    sample points (at least 3) lie within :data:`ENGRAVE_TOL` of the part's outline: a mark
    drawn along the cut edge (a protractor's 0 and 180 deg ticks on its straight edge), which
    the laser engraves over the cut, so it is not seen.  ``pts``: the samples of ``geoms`` in
    order (:func:`_samples`)."""
    if loops is None:
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
    on = _within(pts, _edges(loops), ENGRAVE_TOL)
    if not on.any():
        return
    at = 0
    for g, items in geoms:
        n = sum(_n_samples(it) for it in items)
        k = int(on[at:at + n].sum())
        at += n
        if k < 3 or k <= ON_CUT * n:
            continue
        sink.warning("W0516", f"engraving `{g.label}` runs along the cut edge of `{part.path}` "
                     f"({_pct(float(k), float(n))} of it lies on the outline): the laser "
                     "engraves over the cut, so the mark is not seen", g.span,
                     hint="move the mark inside the outline (start it at least its line "
                          "width from the edge) or leave it out; the cut already draws the edge")


def _signed(poly) -> float:
    P = np.asarray(poly, dtype=float)
    x, y = P[:, 0], P[:, 1]
    return 0.5 * float(np.dot(x, np.concatenate([y[1:], y[:1]]))       # np.roll(y, -1)
                       - np.dot(y, np.concatenate([x[1:], x[:1]])))


# ------------------------------------------------------------ topology under `--set` (W0510)
@dataclass
class Topology:
    """What W0510 compares of one solid part between the program's defaults and a `--set`."""
    span: object
    pieces: int
    openings: int
    merges: set          # frozensets of two hole names that cut one opening
    notches: set         # hole names that reach the outline
    contacts: set        # frozensets of two face names (different solids) that overlap
    holes: set           # every hole name
    faces: set           # every solid face name


def topology(d: Drawing) -> dict:
    """The :class:`Topology` of every solid part of ``d``, by part path: its pieces and
    openings (counter-clockwise and clockwise loops of its final shape), the holes that merge
    (:func:`_analyse` at the touching distance) or reach the outline, and the faces of
    different solid structures that overlap (candidates from :func:`.nearby.box_pairs`)."""
    roots = _part_roots(d)
    by_part: dict = {}
    for c in d.cuts:
        by_part.setdefault(_part_of(c.owner, roots), []).append(c)
    faces_of: dict = {}
    for st, own in d.own.items():
        if st.kind != "solid":
            continue
        part = _part_of(st, roots)
        if part is not None and part.kind == "solid":
            faces_of.setdefault(part, []).extend(
                (f"`{g.label}`", st, f) for g, f in own if f is not None and not f.is_empty())
    out = {}
    for s, shape in roots.items():
        if s.kind != "solid":
            continue
        loops = [np.asarray(p, dtype=float) for p in shape.to_polygons()]
        pos = sum(_signed(p) > 0 for p in loops)
        a = _analyse(d, s, shape, by_part.get(s, []), 0.0, loops)
        faces = faces_of.get(s, [])
        contacts = set()
        if len(faces) > 1:
            boxes = [f.bounds() for _, _, f in faces]
            for i, j in box_pairs(boxes):
                (ni, si, fi), (nj, sj, fj) = faces[i], faces[j]
                if si is not sj and _area(fi ^ fj) > 1e-6:
                    contacts.add(frozenset((ni, nj)))
        out[s.path] = Topology(s.span, pos, len(loops) - pos,
                               {frozenset((a.names[i], a.names[j])) for i, j, _, _ in a.merges},
                               {a.names[j] for j in a.notches}, contacts, set(a.names[1:]),
                               {n for n, _, _ in faces})
    return out


def _count(n: int, what: str) -> str:
    return f"{n} {what}" + ("" if n == 1 else "s")


def topology_changes(base: Topology, new: Topology) -> list[str]:
    """What changed from ``base`` (the defaults) to ``new``, in words, most telling first."""
    out = []
    if new.pieces != base.pieces:
        out.append(f"{_count(new.pieces, 'piece')} instead of {base.pieces}")
    if new.openings != base.openings:
        out.append(f"{_count(new.openings, 'opening')} instead of {base.openings}")
    for m in sorted(new.merges - base.merges, key=sorted):
        a, b = sorted(m)
        out.append(f"{a} merges with {b}")
    for m in sorted(base.merges - new.merges, key=sorted):
        if m <= new.holes:
            a, b = sorted(m)
            out.append(f"{a} and {b} no longer merge")
    for h in sorted(new.notches - base.notches):
        out.append(f"{h} now breaks through the outline")
    for h in sorted(base.notches - new.notches):
        if h in new.holes:
            out.append(f"{h} no longer reaches the outline")
    for c in sorted(new.contacts - base.contacts, key=sorted):
        if c <= base.faces:
            a, b = sorted(c)
            out.append(f"{a} now overlaps {b}")
    for c in sorted(base.contacts - new.contacts, key=sorted):
        if c <= new.faces:
            a, b = sorted(c)
            out.append(f"{a} no longer overlaps {b}")
    return out


def check_topology(base: Drawing | dict, d: Drawing, values: dict, sink: DiagnosticSink) -> None:
    """W0510 for each solid part of ``d`` (compiled with the param ``values``) whose
    topology differs from ``base`` (the same program with its defaults: a Drawing, or its
    :func:`topology` already taken)."""
    if not values:
        return
    before = base if isinstance(base, dict) else topology(base)
    now = topology(d)
    with_ = ", ".join(f"{k}={v}" for k, v in values.items())
    for path, t in now.items():
        b = before.get(path)
        if b is None:
            continue
        what = topology_changes(b, t)
        if not what:
            continue
        sink.warning("W0510", f"with {with_}, part `{path}` changes: " + "; ".join(what[:4])
                     + ("; ..." if len(what) > 4 else "") + " (not so with the defaults)",
                     t.span,
                     hint="such a change is rarely what the param is for: choose another "
                          "value, derive the spacing from the param so that the design follows "
                          "it, or declare the param's `min=`/`max=` to keep values that fit")
