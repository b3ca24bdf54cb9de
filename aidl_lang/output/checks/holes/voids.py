"""``W0515``: an opening that no hole cut: a tiny void left between shapes that nearly meet
(:func:`_check_voids`), or a window the overlapping faces of one solid enclose
(:func:`_check_enclosed`, said as meant when an ``AllowOverlap`` names the faces:
:mod:`..allowances` reads the sets used).
"""
from __future__ import annotations

import manifold3d as mf
import numpy as np

from ....base.diagnostics import Diagnostic, Label
from ....geometry.core.model import Structure
from ...part.build.booleans import Drawing
from ...part.measure.nearby import box_pairs, box_pairs_between
from ..common import (MIN_AREA, _area, _cut_openings, _insert_fix, _inside, _loop_boxes, _signed,
                      SHOWN, _say_few, _solids_within, written)
from .openings import TOUCH, _NAMEABLE, _ref

# an enclosed opening narrower than this (mm, its box's smaller side) is led by the fill, with
# no suggested AllowOverlap: run aa's cake topper (7.1 x 2.4 mm between a star's lower tips and
# its rail, a defect) beside the meant windows of a lyre or a frame (tens of mm)
NARROW_WINDOW = 3.0


def _check_voids(d: Drawing, s: Structure, loops, cuts, t: float, sink,
                 tick=lambda ahead=0.0: None, cut_open=None) -> None:
    """W0515 for each tiny opening of part ``s`` that no hole cut: an inner loop (clockwise)
    of less than ``max(2 t^2, 1)`` mm^2 whose box meets no hole's: a void left between merged
    shapes (two solids that nearly meet around a gap).  ``tick()``: the compile's deadline,
    looked at as the openings are searched.  ``cut_open``: :func:`.common._cut_openings` of
    ``loops``, when the caller has it."""
    signed = [_signed(P) for P in loops]         # once per loop (20,000 holes: 3 times)
    inner = [k for k, a in enumerate(signed) if a < 0]
    if not inner:
        return
    if cut_open is None:
        cut_open = _cut_openings(loops, cuts)
    limit = max(2 * t * t, 1.0)
    _check_enclosed(d, s, [loops[k] for k in inner if -signed[k] >= limit], cuts, sink,
                    tick)
    voids: list = []                     # said by _say_few: the first few, then a count
    for k in inner:
        P = loops[k]
        area = -signed[k]
        if area >= limit or cut_open[k]:
            continue
        x0, y0 = P.min(axis=0)
        x1, y1 = P.max(axis=0)
        width = area / max(1e-12, max(x1 - x0, y1 - y0))
        around, span, labels = (_around(d, s, P) if len(voids) < SHOWN else
                                ("the shapes", s.span, []))
        wx, wy = written(s, (x0 + x1) / 2, (y0 + y1) / 2)     # as the program writes it
        voids.append((f"a void of {area:.3f} mm^2 (about {width:.2f} mm wide, "
                      f"{max(x1 - x0, y1 - y0):.2f} mm long) is cut through `{s.path}` near "
                      f"({wx:.1f}, {wy:.1f}): no hole declares it, "
                      f"{around} around it do not quite meet, so a sliver comes out there",
                      span,
                      {"hint": "make the shapes around it overlap (e.g. `gap=-1 mm`, or a "
                               "larger size) so that no gap is left; if an opening is meant, "
                               "cut it with a hole", "labels": labels}))
    _say_few(sink, "W0515", s.path, voids)


def _around(d: Drawing, s: Structure, P) -> tuple:
    """``(words, span, labels)`` for the tiny void ``P`` of part ``s``: the shapes of its
    solids whose faces border it (run aq's spider web: three slivers among eight legs said
    only "the shapes around it"), the warning at the first, the next three labelled."""
    region = mf.CrossSection([P[::-1].tolist()], mf.FillRule.Positive)
    shapes = list(dict.fromkeys(g for _, g, _ in _faces_around(d, s, region)))
    if not shapes:
        return "the shapes", s.span, []
    names = [f"`{g.label}`" for g in shapes]
    words = ", ".join(names[:4]) + (f" and {len(names) - 4} more" if len(names) > 4 else "")
    g0 = shapes[0]
    labels = [Label(g.span, "borders it", primary=False) for g in shapes[1:4]
              if g.span is not None and g.span != g0.span]
    return words, g0.span or s.span, labels


def _faces_around(d: Drawing, s: Structure, region) -> list:
    """:func:`_solid_faces` of part ``s`` that border the opening ``region``: those meeting
    the ring :data:`.openings.TOUCH` x 2 wide around it."""
    return _solid_faces(d, s, region.offset(2 * TOUCH, mf.JoinType.Miter, 2.0, 16) - region)


def _solid_faces(d: Drawing, s: Structure, near) -> list:
    """The faces of part ``s``'s solids (its own and its solid descendants', :attr:`Drawing.own`)
    that meet the region ``near`` (a CrossSection): ``[(structure, geometry, face)]``, in the
    order of :attr:`Drawing.own`."""
    x0, y0, x1, y1 = near.bounds()
    out = []
    for t, faces in _solids_within(d, s):
        for g, f in faces:
            if f is None or f.is_empty():
                continue
            a, b, c, e = f.bounds()
            if a > x1 or c < x0 or b > y1 or e < y0:
                continue
            if _area(near ^ f) > 1e-9:
                out.append((t, g, f))
    return out


def _check_enclosed(d: Drawing, s: Structure, openings, cuts, sink,
                    tick=lambda ahead=0.0: None) -> None:
    """W0515 for each opening of part ``s`` (``openings``: clockwise loops of its final shape,
    each of at least :func:`_check_voids`' limit) that no hole cuts or covers (no hole shape
    of the part meets it; candidates by :func:`.nearby.box_pairs`, so a plate of 5,000 holes
    costs n log n) and that the faces of ONE solid structure enclose: shapes merged around a
    window the program never declares (a dinosaur's legs and belly).  Left alone: an
    opening framed by faces of several solid structures (a telephone's cradle between its
    base and handset, each placed by a constraint), or by faces that only abut, none
    overlapping another (a frame of bars laid edge to edge): built to enclose it; and an
    opening inside one face's own outer loop, which is that face's own hole (a ``Drawing2D``
    of 19,000 holes, a polygon drawn with a hole), found by boxes and one point test each."""
    if not openings:
        return
    own = _own_outlines(d, s)
    boxes = _loop_boxes(openings)            # (one array op, not two per opening)
    framed = _inside_one_face(openings, boxes, own)
    todo = np.flatnonzero(~framed)          # (framed: a face's own hole, a drawing's inner
    if not len(todo):                       # loop, or a plate's: 19,000 holes listed for
        return                              # nothing, 0.2 s)
    holes = [d.shapes[c.hole] for c in cuts
             if d.shapes.get(c.hole) is not None and not d.shapes[c.hole].is_empty()]
    near: dict = {}
    if holes:
        n = len(todo)
        pairs = box_pairs(np.vstack([boxes[todo], np.array([h.bounds() for h in holes],
                                                           dtype=float).reshape(-1, 4)]))
        for i, j in pairs[(pairs[:, 0] < n) & (pairs[:, 1] >= n)]:
            near.setdefault(int(todo[i]), []).append(holes[int(j) - n])
    for m, k in enumerate(todo.tolist()):
        if m % 64 == 0:
            tick()
        P = openings[k]
        region = mf.CrossSection([P[::-1].tolist()], mf.FillRule.Positive)
        if region.is_empty() or any(_area(h ^ region) > MIN_AREA for h in near.get(k, ())):
            continue                          # a hole cuts it, or is declared over it
        _report_enclosed(d, s, P, -_signed(P), region, sink)


def _own_outlines(d: Drawing, s: Structure) -> tuple:
    """The outer loops (counter-clockwise polylines) of every face of part ``s``'s solids and
    their boxes (k x 4): ``(loops, boxes)``."""
    outer = []
    for t, faces in _solids_within(d, s):
        for _, f in faces:
            if f is None or f.is_empty():
                continue
            outer += [P for P in (np.asarray(q, dtype=float) for q in f.to_polygons())
                      if len(P) >= 3 and _signed(P) > 0]
    boxes = np.array([(P[:, 0].min(), P[:, 1].min(), P[:, 0].max(), P[:, 1].max())
                      for P in outer], dtype=float).reshape(-1, 4)
    return outer, boxes


def _inside_one_face(openings, boxes, own) -> np.ndarray:
    """For each opening of ``openings`` (clockwise polylines; ``boxes``: theirs): whether it
    lies inside the outer loop of one face of ``own`` (:func:`_own_outlines`: both its
    :func:`_probes` within that loop, the loop's box around its own), the face's own hole, since the face
    would otherwise cover it.  Candidates by box (:func:`.nearby.box_pairs_between`), then one
    even-odd test (:func:`.common._inside`) per face loop for all the openings it may hold."""
    outer, oboxes = own
    res = np.zeros(len(openings), dtype=bool)
    if not len(oboxes) or not len(openings):
        return res
    ob = np.asarray(boxes, dtype=float).reshape(-1, 4)
    pairs = box_pairs_between(ob, oboxes)
    i, j = pairs[:, 0], pairs[:, 1]
    holds = ((oboxes[j, 0] <= ob[i, 0]) & (oboxes[j, 1] <= ob[i, 1]) & (oboxes[j, 2] >= ob[i, 2])
             & (oboxes[j, 3] >= ob[i, 3]))
    i, j = i[holds], j[holds]
    order = np.argsort(j, kind="stable")
    i, j = i[order], j[order]
    mean = {}
    for a, z in zip(*_runs(j)):
        idx = [k for k in i[a:z].tolist() if not res[k]]
        if not idx:
            continue
        for k in idx:
            if k not in mean:
                mean[k] = _probes(openings[k])
        pts = np.vstack([mean[k] for k in idx])
        res[idx] |= _inside(pts, [outer[int(j[a])]]).reshape(-1, 2).all(axis=1)
    return res


def _probes(P) -> np.ndarray:
    """Two points (2 x 2) that lie inside a face's outer loop when the opening ``P`` (a
    clockwise loop) is that face's own hole: its mean vertex, and a point 1e-3 mm inside
    the opening from the middle of its longest edge.  The mean alone was not enough: a
    window between a rim's arc and two bars (run ao's party glasses) has most of its
    vertices on the arc, so their mean fell inside the rim's circle, which does not hold
    the window."""
    Q = np.roll(P, -1, axis=0)
    e = Q - P
    i = int(np.argmax(np.hypot(e[:, 0], e[:, 1])))
    m = (P[i] + Q[i]) / 2
    n = np.array([-e[i, 1], e[i, 0]]) / max(float(np.hypot(*e[i])), 1e-300)
    return np.array([P.mean(axis=0), m - 1e-3 * n])  # (clockwise: the inside on the right)


def _runs(keys) -> tuple:
    """The runs of equal values of the sorted array ``keys``: (starts, stops)."""
    if not len(keys):
        return np.zeros(0, dtype=np.intp), np.zeros(0, dtype=np.intp)
    starts = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])
    return starts, np.r_[starts[1:], len(keys)]


def _report_enclosed(d: Drawing, s: Structure, P, area: float, region, sink) -> None:
    """The W0515 of :func:`_check_enclosed` for the opening ``P`` (its ``region``), when the
    faces around it are of one solid structure."""
    faces = _faces_around(d, s, region)
    owners = list(dict.fromkeys(t for t, _, _ in faces))
    if len(owners) != 1:
        return
    shapes = [f for _, _, f in faces]
    if not any(_area(shapes[i] ^ shapes[j]) > MIN_AREA
               for i, j in box_pairs(np.array([f.bounds() for f in shapes], dtype=float))):
        return                  # edge to edge (a frame of bars that abut): built to enclose it
    owner = owners[0]
    around = {g for _, g, _ in faces}
    if any(g.kind == "Text" and g.data.get("font") for g in around):
        return                  # a word's letters and what joins them (a rail under the A's
        #                         legs): the windows the font draws (issue 112)
    said = [ok for ok in getattr(owner, "enclosure_ok", ()) if around <= ok]
    if said:                    # AllowOverlap(the shapes around it): the window is meant
        owner.enclosure_used = getattr(owner, "enclosure_used", set()) | set(map(frozenset,
                                                                                 said))
        return
    x0, y0 = P.min(axis=0)
    x1, y1 = P.max(axis=0)
    w, h = x1 - x0, y1 - y0
    cx, cy = written(owner, (x0 + x1) / 2, (y0 + y1) / 2)    # as the program writes it
    names = list(dict.fromkeys(f"`{g.label}`" for _, g, _ in faces))
    who = ", ".join(names[:4]) + (f" and {len(names) - 4} more" if len(names) > 4 else "")
    g0 = faces[0][1]
    labels = [Label(g.span, "bounds it", primary=False) for _, g, _ in faces[1:4]
              if g.span is not None and g.span != g0.span]
    final = d.shapes.get(s)
    island = final is not None and _area(region ^ final) > MIN_AREA
    refs = list(dict.fromkeys(_ref(g, owner) for _, g, _ in faces))
    stmt = f"AllowOverlap({', '.join(refs)})" if "self" not in refs \
        and all(_NAMEABLE.match(r) for r in refs) else None
    narrow = min(w, h) < NARROW_WINDOW    # (run aa's cake topper: a star's tips on a rail)
    say = (f"say so with `{stmt}` in `{owner.path}` ({'' if narrow else 'the suggested fix: '}"
           "the part stays as it is, cut with this opening, and the statement names the "
           "shapes, so it holds whatever the params make of them)" if stmt else
           f"name the shapes around it and write `AllowOverlap(` them `)` in `{owner.path}` "
           "(the part stays as it is)")
    fill = ("fill it: make the shapes around it overlap across it (or move them apart so "
            "that it opens onto the edge), and the opening is gone")
    # a wider window is a note: 10 of the 13 the model runs met were meant (a bracket's
    # gusset window x3, a lyre's x4, a trigger guard, glasses' rims), 3 not (two of run ao's
    # glasses' corners, issue 91's dinosaur); a narrow one stays a warning (run aa's slivers)
    sink.add(Diagnostic(
        "W0515", f"an opening of {w:.2f} x {h:.2f} mm ({area:.2f} mm^2) near "
        f"({cx:.1f}, {cy:.1f}) is cut through `{owner.path}`"
        + (" around an island of material inside it" if island else "")
        + f": {who} enclose it and no hole declares it, so the part comes out with "
        "a window there", g0.span or owner.span, "warning" if narrow else "note",
        labels=labels,
        hint=(f"an opening under {NARROW_WINDOW:g} mm across is rarely meant: {fill}; "
              f"if it is meant, {say}") if narrow else
        f"if it is meant, {say}; if it is not meant, {fill}",
        fix=_insert_fix(owner, stmt, sink) if stmt and not narrow else None))
