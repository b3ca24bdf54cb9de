"""``W0530`` for a pattern's copy that runs out through its part's outer edge while the
pattern's original is a closed hole: the copy cuts a notch where a hole was drawn (issue 111,
run v's towel-hook plate: `AlignCenterX(peg, body)` centred the pattern's *original*, so the
second of two 12 mm peg holes 80 mm apart broke out of the plate's right edge by 6 mm, and no
message said so).  A pattern whose original runs out too (a row of edge notches, a comb) is
drawn open on purpose and is not warned; nor is a copy the standard library's closed-opening
templates already report (:func:`_check_closed_openings`, below: a `keyhole`, and a hole's
font letters, that run out through the edge).

Copies are hole structures made by ``LinearPattern``/``CircularPattern``/``GridPattern`` of a
hole (the original's ``pattern_copies``), or shapes of one hole made by a pattern of a shape.  Each one's
vertices are tested against its solid's outline before its holes (``Cut.before``) grown by
:data:`EDGE_TOL` with one point-in-polygon pass (:func:`..common._inside`, O((N + E) log N)),
so the check grows as n log n in the copies, not as one boolean per copy."""
from __future__ import annotations

import math

import manifold3d as mf
import numpy as np

from ..common import MIN_AREA, _area, _edge_distance, _edges, _inside, _union, written

EDGE_TOL = 0.01        # mm: a copy's vertex this far past the outline still counts as inside


def check_pattern_edges(d, s, cuts, min_wall: float, sink, skip: set) -> None:
    """W0530 for each copy of a pattern among the holes ``cuts`` of part ``s`` that runs out
    through the outer edge of its solid while the pattern's original lies inside it (the
    first such copy of each original warned, with how many copies run out).  ``skip``: the
    templates whose own W0530 names them (:data:`.openings.CLOSED_OPENINGS`)."""
    things: dict = {}                      # id(hole or shape) -> (it, its shape, its cut)
    for c in cuts:
        h = c.hole
        if getattr(h, "template", None) in skip or c.before is None:
            continue
        shape = d.shapes.get(h)
        if shape is not None and not shape.is_empty():
            things[id(h)] = (h, shape, c)
        for g, f in d.own.get(h, ()):      # a pattern of shapes inside one hole
            if f is not None and not f.is_empty() and not g.construction:
                things[id(g)] = (g, f, c)
    groups: dict = {}                      # id(original) -> (original, [(copy, shape, cut)])
    items: list = []                       # (thing, shape, cut): every original and copy
    for key, (t, f, c) in things.items():
        copies = [things[id(k)] for k in t.__dict__.get("pattern_copies", ())
                  if id(k) in things]
        if copies:
            groups[key] = (t, copies)
            items.append((t, f, c))
            items.extend(copies)
    if not groups:
        return
    outside = _outside_depths(items)
    for key, (orig, copies) in groups.items():
        if id(orig) in outside:
            continue                       # the original runs out too: an edge pattern
        out = [(h, outside[id(h)]) for h, _, _ in copies if id(h) in outside]
        if not out:
            continue
        out.sort(key=lambda o: -o[1][0])   # the deepest first
        h, (depth, (x, y)) = out[0][0], out[0][1]
        x, y = written(s, x, y)          # where the program writes it (run ek: sheet coordinates)
        name = _name(h)
        more = f" ({len(out)} of its {len(copies)} copies do)" if len(out) > 1 else ""
        need = np.ceil((depth + 2 * min_wall) * 10) / 10
        sink.warning("W0530", f"{name}, a pattern's copy of `{_label(orig)}`, runs out through "
                     f"the outer edge of `{s.path}` by {depth:.2f} mm (its farthest point, "
                     f"about ({x:.2f}, {y:.2f})){more}, where the original is a closed hole: "
                     f"the copy cuts a notch where a hole was drawn", _span(h, orig),
                     hint=(f"place the whole pattern inside: move `{_label(orig)}` by at least "
                           f"{need:g} mm away from that edge (what runs out and a wall of twice "
                           f"the minimum); to centre a pattern, place its original half the "
                           f"pattern's span off the centre, not on it" if len(out) == 1 else
                           f"place or size the pattern so that every copy lies inside, {need:g} "
                           f"mm further in at the deepest (what runs out and a wall of twice "
                           f"the minimum): a smaller radius, step or count"))


def _outside_depths(items: list) -> dict:
    """For each ``(thing, shape, cut)`` of ``items``: ``id(thing) -> (depth,
    (x, y))``, how far (mm) the shape's farthest vertex outside its solid's outline before
    holes (``cut.before``) lies beyond it, and where; things wholly inside, and those wholly
    outside (``W0502``: a hole that cuts nothing), are left out.
    The outline is grown by :data:`EDGE_TOL` and its vertices tested in one
    :func:`..common._inside` per solid; the depth of a vertex outside is its distance to the
    outline's edges (the few vertices outside only)."""
    by_before: dict = {}
    for it in items:
        by_before.setdefault(id(it[2].before), []).append(it)
    found: dict = {}
    for group in by_before.values():
        before = group[0][2].before
        grown = before.offset(EDGE_TOL, mf.JoinType.Miter)
        edges = _edges([np.asarray(p, dtype=float) for p in grown.to_polygons()])
        pts, owner = [], []
        for k, (_, shape, _) in enumerate(group):
            P = [np.asarray(p, dtype=float) for p in shape.to_polygons() if len(p)]
            if P:
                V = np.concatenate(P)
                pts.append(V)
                owner.append(np.full(len(V), k))
        if not pts:
            continue
        V, who = np.concatenate(pts), np.concatenate(owner)
        off = ~_inside(V, edges)
        if not off.any():
            continue
        O, ow = V[off], who[off]
        depth = _edge_distance(O, _edges([np.asarray(p, dtype=float)
                                          for p in before.to_polygons()]))
        for k in np.unique(ow):
            if not (~off[who == k]).any():
                continue                   # wholly outside: W0502 says it cuts nothing
            sel = np.flatnonzero(ow == k)
            j = sel[int(np.argmax(depth[sel]))]
            found[id(group[int(k)][0])] = (float(depth[j]), (float(O[j, 0]), float(O[j, 1])))
    return found


def _label(t) -> str:
    return t.path if hasattr(t, "path") else t.label


def _name(t) -> str:
    return f"hole `{t.path}`" if hasattr(t, "path") else f"shape `{t.label}`"


def _span(t, orig):
    return getattr(t, "span", None) or getattr(orig, "span", None)


# The standard library's hole templates whose opening is meant to be closed (a screw's head
# and shank, a nut, a fastener's clearance): one that runs out through the part's outer edge
# is an open notch, not the feature asked for (issue 105's pick holder: a keyhole whose slot,
# 10 mm long by default, broke through the top edge).  An edge notch meant as one (a finger
# notch, a cable exit) is drawn with a shape or a template of its own and is not warned.
CLOSED_OPENINGS = {"keyhole": "its slot's `length=`, 10 mm unless given", "clearance_hole": "its `size=`",
                   "nut_trap": "its `size=`", "hex_pocket": "its `across_flats=`"}
MAX_DEPTH_POINTS = 4000     # vertices of the part outside measured for the depth (at most)


def _check_closed_openings(d: Drawing, s: Structure, shape, cuts, min_wall: float,
                           sink) -> None:
    """W0530 for each hole of part ``s`` made by a template of :data:`CLOSED_OPENINGS` (a
    ``keyhole``) that runs out through the part's outer edge: its shape reaches past the
    part with its holes filled by more than :data:`MIN_AREA`.  The warning names the hole,
    how far it runs out (the deepest vertex of the shape outside, from the filled part's
    edge, mm) and where, and the fix: shorten or shrink it, or move it inward, by that much
    and ``min_wall`` (a wall of twice the minimum left)."""
    mine = [c for c in cuts if (getattr(c.hole, "template", None) in CLOSED_OPENINGS
                                or _letters(c.hole) is not None)
            and c.region is not None and _area(c.region) > MIN_AREA   # (none: W0502's)
            and d.shapes.get(c.hole) is not None]
    if not mine:
        return
    filled = _union([shape] + [c.region for c in cuts if c.region is not None])
    edges = None
    for c in mine:
        out = d.shapes[c.hole] - filled
        a = _area(out)
        if a <= MIN_AREA:
            continue
        if edges is None:
            loops = [np.asarray(p, dtype=float) for p in filled.to_polygons()]
            edges = _edges(loops)
        P = np.vstack([np.asarray(p, dtype=float) for p in out.to_polygons()])[:MAX_DEPTH_POINTS]
        dist = _edge_distance(P, edges)
        k = int(np.argmax(dist))
        depth = float(dist[k])
        x, y = written(s, *P[k])
        need = math.ceil((depth + 2 * min_wall) * 10) / 10
        t = _letters(c.hole)
        if t is not None and c.hole.template not in CLOSED_OPENINGS:   # (run ay's "NOAH")
            sink.warning("W0530", f"the letters of `{t.label}` (\"{t.data['text']}\") in hole "
                         f"`{c.hole.path}` run out through the outer edge of `{s.path}` by "
                         f"{depth:.2f} mm (about ({x:.2f}, {y:.2f})): a letter is cut open "
                         "there", t.span, hint=f"fit the word: `max_width=` the room it has, a "
                         f"smaller size, or move it inward by at least {need:g} mm (what runs "
                         f"out and a wall of twice the minimum)")
            continue
        what = c.hole.template
        knob = CLOSED_OPENINGS[what]
        sink.warning("W0530", f"hole `{c.hole.path}` (a `{what}`) runs out through the outer edge "
                     f"of `{s.path}` by {depth:.2f} mm (its farthest point, about ({x:.2f}, "
                     f"{y:.2f})): the opening is open at the edge, not closed as a {what} is "
                     f"meant to be", c.hole.span,
                     hint=f"shorten or shrink `{c.hole.name}` ({knob}) or move it inward, by at "
                          f"least {need:g} mm (what runs out and a wall of twice the minimum, "
                          f"{2 * min_wall:g} mm)")


FLUSH = 0.01    # mm: a mortise grown by this much that reaches past the part lies on its edge


def check_open_mortises(d: Drawing, s: Structure, shape, cuts, min_wall: float, sink) -> None:
    """W0530 for each `tab_and_slot(part="slot")` hole of part ``s`` whose slots reach the
    part's outer edge or past it (flush: grown by :data:`FLUSH` they reach out): a mortise is
    a closed opening, and one on the edge is an open notch the tab falls out of (runs ba, bb,
    bx, cc: mortises drawn flush with the ledge's front edge; nothing said so, as a slot
    merged with the outline leaves no wall to call thin)."""
    mine = [c for c in cuts if getattr(c.hole, "template", None) == "tab_and_slot"
            and c.hole.scope.get("part") == "slot" and d.shapes.get(c.hole) is not None]
    if not mine:
        return
    filled = _union([shape] + [c.region for c in cuts if c.region is not None])
    for c in mine:
        grown = d.shapes[c.hole].offset(FLUSH, mf.JoinType.Miter)
        if _area(grown - filled) <= FLUSH * 1.0:
            continue                    # (less than 1 mm of a slot's side on the edge)
        out = d.shapes[c.hole] - filled
        x0, y0, x1, y1 = (grown - filled).bounds()
        depth = 0.0 if _area(out) <= MIN_AREA else max(x1 - x0, y1 - y0)
        where = "lies on" if depth == 0.0 else "runs out through"
        x, y = written(s, (x0 + x1) / 2, (y0 + y1) / 2)
        sink.warning("W0530", f"hole `{c.hole.path}` (a `tab_and_slot`'s slots, a mortise) "
                     f"{where} the outer edge of `{s.path}` (about ({x:.2f}, {y:.2f})): the "
                     "mortise is cut open into a notch, and the tab it holds can slide out",
                     c.hole.span,
                     # (runs eg, ek: the mortise's place was fixed by the part whose tabs it
                     # takes, and the fix was a wider panel, not a mortise moved)
                     hint=f"leave at least {2 * min_wall:g} mm of material between the slots "
                          f"and the edge: widen `{s.name}` past them (where the mortise's "
                          f"place is set by the part its tabs come from), or move "
                          f"`{c.hole.name}` inward (a tab meant to stand at the edge is the "
                          "`part=\"tab\"` half's)")


def _letters(h):
    """The first font Text of hole ``h`` (its letters cut as openings), else None."""
    return next((g for g in h.geometry if g.kind == "Text" and g.data.get("font")), None)
