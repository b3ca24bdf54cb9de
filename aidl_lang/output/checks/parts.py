"""The solid parts as a whole:

* ``W0504`` a solid part whose final shape falls apart into separate pieces (assembly parts
  are separate by design and are not checked against each other);
* ``W0506`` a child solid that adds nothing: it lies wholly inside the rest of its parent
  (for example pattern copies that land inside a filled solid), or a hole of the same
  structure cuts it away;
* ``W0509`` a face of zero area (:func:`empty_faces`; the warnings themselves, and the one for
  a part that comes out empty unexplained, are written by ``check_drawing``);
* ``W0511`` two separate parts of an assembly whose final shapes interpenetrate in the
  flat view (not parts laid one on the other, nor those ``AllowOverlap`` names);
* ``W0520`` a ledge in the outline where one shape pokes past another's edge by less than
  the minimum wall (:func:`_check_steps`)."""
from __future__ import annotations

import math
import re

import manifold3d as mf
import numpy as np

from ...base.diagnostics import Diagnostic, DiagnosticSink, Fix, Label, Span, in_stdlib
from ...geometry.core.model import Structure
from ..part.build.booleans import Drawing
from ..part.measure.nearby import box_pairs
from ..part.build.scanwork import decompose
from .letters import fallen_counters, letters_in
from .common import (written, MIN_AREA, _area, _contributors, _depth, _edges, _inside, _say_few, _signed,
                     _solids_within, _union)
from .holes.openings import LARGER_STAYS
from .marks.engravings import _copy_label
from .marks.sampling import ENGRAVE_TOL, _samples

MAX_CHILDREN = 64        # W0506 compares each child with the union of the others
MAX_CUTTERS = 16         # W0504: holes measured for cutting a shape apart


# work units of one pair of parts' boolean in the interpenetration check, a vertex (1,000
# squares stacked: 499,500 pairs of 8 vertices, about 14 us a pair)
PAIR_UNITS = 0.12

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
    pairs come from the parts' boxes (:func:`..nearby.box_pairs`); ``deadline`` is checked
    before each pair's boolean."""
    parts = [(s, shp) for s, shp in roots.items() if s.kind == "solid" and not shp.is_empty()]
    if len(parts) < 2:
        return
    boxes = np.array([shp.bounds() for _, shp in parts], dtype=float)
    stacked: dict = {}          # id(home) -> placed parts laid on each other: said once each
    for i, j in sorted(map(tuple, box_pairs(boxes))):
        (a, sa), (b, sb) = parts[i], parts[j]
        if a.is_within(b) or b.is_within(a):
            continue              # a part drawn inside another's drawing: shown on it
        if deadline is not None:        # the pair's boolean paid before: by its vertices
            deadline.check("the shape checks", None,
                           PAIR_UNITS * (sa.num_vert() + sb.num_vert()))
        common = sa ^ sb
        area = _area(common)
        if area <= MIN_AREA or _allowed(a, b):
            continue
        home = a.parent
        while home is not None and not b.is_within(home):
            home = home.parent
        ra, rb = (x.path[len(home.path) + 1:] if home is not None else x.name for x in (a, b))
        if _placed_apart(a, b, home):   # overlapping on the sheet, each placed in 3D: one
            stacked.setdefault(id(home), []).append((a, b, ra, rb, area))   # warning for all
            continue              # (run cz: three, two of them offering AllowOverlap)
        if area > STACKED * min(_area(sa), _area(sb)):
            continue              # laid one on the other (a gear on its plate, clock hands)
        depth = _depth(common, boxes[i], boxes[j])
        labels = [Label(a.span, f"`{a.path}` is here", primary=False)] if a.span else []
        # the gears' rule only where a gear is named (issue 84: two O pieces of a tic-tac-toe
        # set were told about module * (teeth1 + teeth2) / 2)
        gears = ("(meshing gears sit at the centre distance module * (teeth1 + teeth2) / 2: "
                 "`gear_pair` in std/gears.aidl places them), "
                 if any(_is_gear(x) for x in (a, b)) else "")
        sink.warning("W0511", f"parts `{a.path}` and `{b.path}` interpenetrate: they overlap "
                     f"by {area:.2f} mm^2, {depth:.2f} mm deep (separate parts cannot occupy "
                     "the same place)", b.span or a.span, labels=labels,
                     hint=f"move `{b.path}` at least {depth:.2f} mm further from `{a.path}` "
                          f"{gears}or shrink one; if the overlap is meant (a picture of parts stacked), write "
                          f"`AllowOverlap({ra}, {rb})` in "
                          + (f"`{home.path}`" if home is not None else "their assembly"))
    for pairs in stacked.values():
        _stacked_placed(sink, pairs)


def _placed_apart(a, b, home) -> bool:
    """Whether parts ``a`` and ``b`` each have a 3D placement of their own (a ``Place`` of the
    part or of an assembly holding it, below ``home``, the structure holding both): then the
    flat drawing is not the assembled product but the parts to cut, and parts laid on each
    other there are cut through each other (issue 111, runs ci and ch: a cat cot's leg drawn on
    its top, unsaid because W0511 took it for a picture of the parts stacked)."""
    def own(x) -> bool:
        while x is not None and x is not home:
            if getattr(x, "placement", None) is not None:
                return True
            x = x.parent
        return False
    return own(a) and own(b)


def _stacked_placed(sink: DiagnosticSink, pairs: list) -> None:
    """One W0511 for the parts of one assembly laid on each other on the flat drawing that
    are each placed in 3D (:func:`_placed_apart`; ``pairs``: ``(a, b, a's name there, b's,
    shared mm^2)``, in the check's order): the hint lays the first pair's second part beside
    its first, which moves it on the sheet only (``Place`` starts from the part's frame)."""
    a, b, ra, rb, area = pairs[0]
    names: list = []
    for x, y, *_ in pairs:
        for s in (x, y):
            if s not in names:
                names.append(s)
    shown = [f"`{s.path}`" for s in names]
    who = (f"parts {shown[0]} and {shown[1]} overlap" if len(pairs) == 1 else
           f"{len(names)} parts, {', '.join(shown[:-1])} and {shown[-1]}, overlap "
           f"({len(pairs)} pairs)")
    most = max(p[4] for p in pairs)
    labels = [Label(s.span, f"`{s.path}` is here", primary=False)
              for s in names if s is not b and s.span]
    sink.warning("W0511", f"{who} on the flat drawing (sharing up to {most:.2f} mm^2): each is "
                 "placed in 3D by its own `Place`, so the flat drawing is the parts to cut, and "
                 "these would be cut through each other", b.span or a.span, labels=labels,
                 hint=f"lay them side by side on the sheet, e.g. `RightOf({rb}, {ra}, gap=5 mm)` "
                      "in their assembly (a relation moves a placed part on the sheet only, "
                      "not in 3D), or cut with `aidl render --layout sheet`; parts meant to "
                      f"share material: `AllowOverlap({ra}, {rb})`")


def _is_gear(s) -> bool:
    """Whether structure ``s`` is a gear: an instance of a template, or a part, whose name
    says gear (`spur_gear`, `gear1`, `pinion`, a template of the file named so)."""
    while s is not None:
        for name in (s.template or "", s.name or ""):
            if "gear" in name.lower() or "pinion" in name.lower():
                return True
        s = s.parent if s.parent is not None and s.parent.kind == "solid" else None
    return False


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
            if not g.construction and (g.kind in _CLOSED or g.kind in ("Polyline", "Intersect")
                                     and g.closed) \
                    and id(g) not in shaped \
                    and id(g) not in errored:
                out.setdefault(id(g), (s, g, 0.0))
    return list(out.values())


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
    pieces = [p for p in decompose(shape, loops) if _area(p) > max(1e-9, 1e-6 * total)]
    if len(pieces) < 2:
        return
    items = _contributors(d, s)
    objs = [o for *_, o in _contributors(d, s, objects=True)]
    # the message names the first 6 pieces and up to 4 contributors of each (and "..." for
    # a fifth): only those are measured, and only contributors whose box meets the piece's
    # (every piece against every contributor was 25 M intersections for 5 000 circles)
    boxes = np.array([shp.bounds() for _, _, shp in items], dtype=float).reshape(-1, 4)
    groups, seen, split, named = [], {}, [], []
    for p in pieces[:6]:
        b = p.bounds()
        near = np.flatnonzero((boxes[:, 0] <= b[2]) & (boxes[:, 2] >= b[0])
                              & (boxes[:, 1] <= b[3]) & (boxes[:, 3] >= b[1]))
        names = []
        for k in near:
            n, _, shp = items[k]
            if _area(p ^ shp) > max(1e-9, 1e-6 * _area(shp)):
                names.append(n + letters_in(objs[k], shp, p))   # a word's letters (issue 112)
                seen[k] = seen.get(k, 0) + 1
                if seen[k] == 2:
                    split.append(k)     # one shape in two pieces: a hole cut it apart
                if len(names) > 4:
                    break
        groups.append("{" + ", ".join(names[:4]) + (", ..." if len(names) > 4 else "") + "}")
        named.append(names)
    scaled = [(n, o) for n, _, _, o in _contributors(d, s, objects=True)
              if getattr(o, "scaled_in_place", None) is not None and
              any(n in names for names in named)]
    if scaled:                 # Scale keeps its placement: adding a second one would fight it
        n, o = scaled[0]
        hint = (f"{n} is scaled in place (`Scale`, factor {o.scaled_in_place:g}) about its own "
                "centre and stays where its constraints (without any, its coordinates) place "
                "it: make the pieces overlap by changing that placement (an offset) or the "
                "factor, not by adding a second placement; or share an edge (touching at a "
                "point is not enough), or, if they are separate parts, make the structure an "
                "`assembly`")
    else:
        hint = ("make the pieces overlap (" + _joining(s, pieces, named) + ") or share an edge "
                "(touching at a point is not enough), or, if they are separate parts, make the "
                "structure an `assembly`")
        gap = _apart(pieces) if len(pieces) == 2 else None
        if gap is not None:            # how far the two are from touching, and where
            hint = (f"the two pieces are {gap[0]:.2f} mm apart at their nearest, near "
                    f"({gap[1]:.2f}, {gap[2]:.2f}): " + hint)
    words = [o for o in objs if getattr(o, "kind", None) == "Text" and o.data.get("font")]
    if words and not scaled:             # a word whose letters touch nothing (issue 112)
        w = words[0].name or "word"
        hint = (f"join the letters: a rail under the word (`rail = Rectangle(center=({w}.center.x, "
                f"{w}.position.y - 1 mm), width={w}.bb.width, height=3 mm)`, its baseline's: "
                "it draws a bar under every letter, an F then reads as an E), a heavier style "
                "(`font=\"sans:Black\"`) or a tighter layout; or, if they are separate parts "
                "(glued on one by one), write each letter as a Text in a `solid` of its own "
                "in an `assembly` (a font's letters stand in a solid, E0120)")
        along = words[0].data.get("along")       # (run af's house numbers: "42" to glue on)
        if along is not None and getattr(along, "name", None):   # laid along a curve
            c = along.name
            hint = (f"join the letters along their curve: a ring under them (`ring = Shell("
                    f"Circle(center={c}.center, radius={c}.radius + 1 mm), -3 mm)`), a "
                    "heavier style (`font=\"sans:Black\"`) or a tighter layout; or, if they "
                    "are separate parts, make the structure an `assembly`")
    cutters = _cutters(d, s, shape, [items[k] for k in split]) if split else []
    apart = ""
    letters: list = []
    if cutters:
        shapes = ", ".join(items[k][0] for k in split[:3])
        holes = ", ".join(f"`{h.path}`" for h in cutters[:4]) + (", ..." if len(cutters) > 4 else "")
        many = len(cutters) > 1
        apart = f" ({'holes' if many else 'hole'} {holes} cut{'' if many else 's'} {shapes} apart)"
        hint = (f"move, shorten or shrink {'those holes' if len(cutters) > 1 else 'that hole'} "
                "so that material joins the pieces where it crosses (or widen the shape "
                "there); only if the pieces are meant to be separate parts, make the "
                "structure an `assembly`")
        letters, texts = fallen_counters(d, cutters)
        if letters:                  # a word cut from a plate: its counters fall out
            apart += (": the counters of " + ", ".join(f"\"{c}\"" for c in letters)
                      + f" (`{texts[0].label}`) fall out")
            hint = (f"write `stencil=true` on `{texts[0].label}` (a bridge holds each counter "
                    "to the plate), or engrave the text in a `drawing` instead of cutting it")
    # pieces of one shape cut apart by holes: the holes say it, not "{`a`}; {`a`}; ..."
    listed = "" if apart and len(set(groups)) == 1 else (
        ": " + "; ".join(groups) + ("; ..." if len(pieces) > 6 else ""))
    if apart and not letters:       # where the piece cut off is (issue 111, run p: a heart's
        areas = [_area(p) for p in pieces]      # tip cut off by its joint, unsaid; pieces of
        k = min(range(len(pieces)), key=areas.__getitem__)  # one size: none is "the" one)
        if areas[k] < 0.5 * max(areas):
            b = pieces[k].bounds()
            apart += (f"; the smallest piece, {areas[k]:.3g} mm^2, lies from ({b[0]:.2f}, "
                      f"{b[1]:.2f}) to ({b[2]:.2f}, {b[3]:.2f})")
    sink.warning(
        "W0504",
        f"solid `{s.path}` falls apart into {len(pieces)} separate pieces" + listed + apart,
        s.span, hint=hint)


def _cutters(d: Drawing, s: Structure, shape, split: list) -> list:
    """The holes of part ``s`` that cut one of the ``split`` shapes (its contributors found
    in two pieces: ``(name, span, shape)``) apart: those without which ``shape`` would have
    fewer pieces (at most :data:`MAX_CUTTERS` holes whose box meets a split shape's are
    measured, one union with the part each: W0504 is rare, its cause named once)."""
    out = []

    def outer(x) -> int:
        return sum(_signed(np.asarray(p, dtype=float)) > 0 for p in x.to_polygons())
    base = outer(shape)
    boxes = [shp.bounds() for _, _, shp in split]
    tried = 0
    for c in d.cuts:
        if c.region is None or c.region.is_empty() or not c.owner.is_within(s) \
                and c.owner is not s or c.hole in out:
            continue
        b = c.region.bounds()
        if not any(x0 <= b[2] and x1 >= b[0] and y0 <= b[3] and y1 >= b[1]
                   for x0, y0, x1, y1 in boxes):
            continue
        tried += 1
        if tried > MAX_CUTTERS:
            break
        back = [c.region ^ shp for _, _, shp in split]
        back = [x for x in back if _area(x) > MIN_AREA]
        if not back:
            continue
        if outer(_union([shape] + back)) < base:
            out.append(c.hole)
        if len(out) >= 8:
            break
    return out


# W0504 measures how far two pieces are apart only up to this many vertices in all: every
# vertex of one against every edge of the other (6 M point-edge pairs at most, ~50 ms)
APART_VERTICES = 5_000


def _apart(pieces: list) -> tuple | None:
    """``(distance mm, x, y)``: where two pieces (CrossSections) come nearest, the middle of
    the least span between their outlines (issue 111's third run: a star 0.3 mm clear of a
    tree's top tier, its box overlapping the tier's, so no side relation could say it); None
    past :data:`APART_VERTICES` or for pieces that touch."""
    from .holes.contact import _nearest, _segments
    loops = [[np.asarray(p, dtype=float) for p in x.to_polygons()] for x in pieces]
    if sum(len(P) for ls in loops for P in ls) > APART_VERTICES:
        return None
    best = None
    for a, b in ((0, 1), (1, 0)):
        P = np.concatenate(loops[a])
        A, B = _segments(loops[b])
        d, foot = _nearest(P, A, B)
        k = int(np.argmin(d))
        if best is None or d[k] < best[0]:
            best = (float(d[k]), *((P[k] + foot[k]) / 2))
    return best if best[0] > 1e-6 else None


def _joining(s: Structure, pieces: list, named: list) -> str:
    """W0504's example constraint for part ``s`` in two ``pieces`` (CrossSections), each made
    by one shape (``named``: each piece's contributors as the message names them): the
    relation that holds as drawn, smaller piece first (a constraint moves its first-named
    feature to the second), made to overlap by 1 mm (less for a piece thinner than 2 mm):
    `Below(foot, body, gap=-1 mm)` for a foot drawn under the body.  The hint of before gave
    `Above(a, b, gap=-1 mm)`: made with the pieces in the order named, the foot went on top
    of the body (issue 84).  Else the generic example."""
    plain = "for example `Above(a, b, gap=-1 mm)` with `a` the piece that moves"
    if len(pieces) != 2 or any(len(n) != 1 or n[0].count("`") != 2 for n in named):
        return plain
    small, big = sorted(range(2), key=lambda k: _area(pieces[k]))
    (a0, b0, a1, b1), (c0, d0, c1, d1) = pieces[small].bounds(), pieces[big].bounds()
    sides = [("Below", b1 <= d0, b1 - b0, a0 < c1 and c0 < a1),
             ("Above", b0 >= d1, b1 - b0, a0 < c1 and c0 < a1),
             ("LeftOf", a1 <= c0, a1 - a0, b0 < d1 and d0 < b1),
             ("RightOf", a0 >= c1, a1 - a0, b0 < d1 and d0 < b1)]
    found = [(rel, size) for rel, apart, size, facing in sides if apart and facing]
    if len(found) != 1:
        return plain
    rel, size = found[0]
    prefix = s.path + "."
    first, second = (named[k][0].split("`")[1] for k in (small, big))
    if not (first.startswith(prefix) and second.startswith(prefix)):
        return plain
    gap = min(1.0, math.floor(size / 2 * 100) / 100)
    return (f"`{rel}({first[len(prefix):]}, {second[len(prefix):]}, gap=-{gap:g} mm)` in "
            f"`{s.path}` moves `{first}` to overlap `{second}` by {gap:g} mm")


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
                cover = _covering_shape(items, i, a) if share < 0.5 else None
                also, ring = "", ""
                if cover is not None:       # mostly hidden by one filled shape (issue 61)
                    also = f" (the filled shape {cover[0]} covers it whole)"
                    ring = (f"; if {cover[0]} is meant as a rim or an outline, draw a ring "
                            f"(`Shell({cover[0].strip('`').rsplit('.', 1)[-1]}, 3)`) or make "
                            "it `construction=true`")
                sink.warning("W0506", f"{name} adds nothing to `{s.path}`: hole "
                             f"`{cut[0].path}` of the same structure cuts away {how}{also}",
                             span, hint=_kept_over(d, s, shp, others, cut, name) + ring)
                continue
            cover = _covering_shape(items, i, a)
            if cover is not None:           # one filled shape of s hides it (issue 61)
                cname, hidden = cover
                # (a loop's copies by their statement: `web.thread`, not thread[0], [1], ...)
                names = list(dict.fromkeys(re.sub(r"\[\d+\]`$", "`", n) for n in hidden))
                more = (f", and {len(hidden)} other shape{'s' if len(hidden) > 1 else ''} "
                        f"of `{s.path}` ({', '.join(names[:3])}{', ...' if len(names) > 3 else ''})"
                        if hidden else "")
                short = cname.strip("`").rsplit(".", 1)[-1]
                sink.warning("W0506", f"{name} adds nothing to `{s.path}`: the filled shape "
                             f"{cname} covers it whole{more}", span,
                             hint=f"{cname} is filled: if it is meant as a rim or an outline, "
                                  f"draw a ring (`Shell({short}, 3)`, or a `hole` "
                                  f"inside it) or make it `construction=true`; else move {name} "
                                  "where it shows")
                continue
            sink.warning("W0506", f"{name} adds nothing to `{s.path}`: it lies wholly inside "
                         "the rest of it", span,
                         hint="move it where it shows (it is probably mispositioned), make it a "
                              "`hole` if it should cut, or delete it")


def _kept_over(d: Drawing, s: Structure, shp, others, cut: list, name: str) -> str:
    """W0506's hint for solid ``name`` (its region ``shp``) of ``s`` that the holes ``cut``
    of ``s`` cut away (``others``: the rest of ``s``'s material, before the holes).  Kept over
    the hole, a solid must be a sibling of the structure the hole cuts: inside ``s`` when
    ``s`` is a part (declared beside the part, as the hint of before said, it became a part
    of its own, issue 84); it must overlap the material left around the hole (by more than
    :data:`.common.MIN_AREA`; touching is not joined), or it is an island (W0504), and leave
    some of the opening open, or the hole cuts nothing (W0501; and without the hole, the
    rest covers it, W0506 again): then deleting it (or making it reach that material) is
    offered."""
    opening = _union([d.shapes[h] for h in cut])
    left = others - opening
    holes = ", ".join(f"`{h.name}`" for h in cut)
    why = "a hole cuts every solid of the structure it is declared in, children included"
    if _area(opening - shp) <= MIN_AREA:     # kept, it would fill the hole (W0501)
        return (f"{why}; this solid covers the whole opening of {holes} (kept over it, the "
                "hole would cut nothing; with the hole gone, the rest covers it): delete it")
    if _area(shp ^ left) <= MIN_AREA and not _bridged(d, s, shp, left):
        # a disc that touches the opening's sides only, and no other solid of `s` joins it
        part = (f"; if it is a separate part (a pin through the hole), declare it beside "
                f"`{s.name}` in `{s.parent.path}` (a sibling structure's material survives the "
                "hole)") if s.parent is not None and s.parent.kind == "assembly" else ""
        return (f"{why}; this solid lies within the opening and touches no material around "
                f"it (kept, it would be an island): delete it, or make it reach the material "
                f"around the hole{part}")
    child = name.split("`")[1].rsplit(".", 1)[-1] if "`" in name else name
    # a solid other statements place or assert on is meant: no "delete it" (run s's
    # no-parking sign: deleting its bar left `At(bar.b.center, ...)` naming nothing, E0101)
    other = "" if _named_elsewhere(s, s.children.get(child)) else ", else delete it"
    if s.parent is None or s.parent.kind != "solid":       # `s` is a part
        return (f"{why}; to keep this solid over the hole, put the rest of `{s.name}` (its "
                f"shapes and hole {holes}) in a `solid` of their own inside `{s.name}`, beside "
                f"`{child}` (a sibling structure's material survives the hole){other}")
    return (f"{why}; to keep this solid over the hole, declare it beside `{s.name}` (a "
            f"sibling structure's material survives the hole){other}")


def _named_elsewhere(s: Structure, child) -> bool:
    """Whether a constraint of ``s`` relates ``child`` (or what is in it) to something, or
    the program reads it by name as a member (`meridian.axis.bar`, in an assert)."""
    if child is None:
        return False
    if child.__dict__.get("read_by_name"):
        return True
    inside = {id(t) for t in child.subtree()}
    return any(id(o) in inside for c in s.constraints if c.args for grp in c.args
               for o in grp)


def _bridged(d: Drawing, s: Structure, shp, left) -> bool:
    """Another solid child of ``s`` overlaps ``shp`` and the material ``left`` around the
    hole: kept over the hole with it, ``shp`` is joined, no island (issue 111, run s's no-parking
    sign: its "P", inside the ring's opening, crossed by the bar that reaches the ring, was
    told "delete it")."""
    own = _area(shp)
    for c in s.children.values():
        cs = d.shapes.get(c) if c.kind == "solid" else None
        if cs is None or cs.is_empty():
            continue
        common = _area(cs ^ shp)
        if MIN_AREA < common < own - MIN_AREA and _area(cs ^ left) > MIN_AREA:
            return True
    return False


def _covering_shape(items, i: int, a: float):
    """(name, names of the other shapes it hides too) of one own shape of the structure
    (not a solid child) that covers item ``i`` (area ``a``) whole by itself, or None."""
    shp = items[i][2]
    for j, (cname, _, cshp) in enumerate(items):
        if j == i or cname.startswith("solid "):
            continue
        if _area(shp - cshp) <= max(1e-9, 1e-4 * a):
            hidden = [n for k, (n, _, o) in enumerate(items)
                      if k not in (i, j) and not n.startswith("solid ") and n != cname
                      and _area(o - cshp) <= max(1e-9, 1e-4 * _area(o))]
            return cname, hidden
    return None


# --------------------------------------------------------------------------- steps (W0520)
CORNER = 30.0        # degrees: a turn of the outline sharper than this is a corner
# mm: a ledge under this is a note: it hardly shows once cut (run fc: a trapezoid tine's side
# 0.07 mm off a joint's notch, four warnings no maker would see; run dl: a 0.09 mm ledge
# "fixed" by the hint into a visible 2 mm step)
LEDGE_SEEN = 0.1
PARALLEL = 15.0      # degrees: the stretches before and after a step keep their direction


def _check_steps(d: Drawing, s: Structure, loops, cuts, t: float, sink: DiagnosticSink,
                 tick=lambda: None, cut_open=None) -> None:
    """W0520 for part ``s`` (its final shape's ``loops``) at minimum wall ``t`` mm: a step of
    the outline where one shape pokes past another by less than ``t`` (a music note's stem
    0.2 mm past its head's side): two corners of opposite turns (each sharper than
    :data:`CORNER` degrees) at most ``2 t`` apart along the outline, between two stretches
    that keep their direction (the turns cancel within :data:`PARALLEL` degrees) and are
    offset sideways by more than 0.01 mm (twice the tessellation's chord error) and less than
    ``t``: two faces that almost but not quite align.  ``2 t`` bounds the step's own length:
    a longer link between two edges less than ``t`` apart is a gentle taper, not a ledge.
    The step is reported when the shapes at its two corners differ (:func:`.material.slits._faces_at`;
    a step drawn in one polygon is meant).  Loops of holes' openings are left out.  O(n)
    in the outline's vertices, plus a face search per step found.  ``cut_open``:
    :func:`.common._cut_openings` of ``loops``, when the caller has it."""
    from .common import _cut_openings
    from .material.slits import _faces_at
    if t <= 0 or not loops:
        return
    if cut_open is None:
        cut_open = _cut_openings(loops, cuts)
    found = []
    mine = [P for P, opening in zip(loops, cut_open) if not opening]   # not a hole's opening
    for P, skip in zip(mine, _cornerless(mine)):
        if skip:
            continue                             # fewer than two corners
        P = np.asarray(P, dtype=float)
        e = np.roll(P, -1, axis=0) - P
        L = np.hypot(*e.T)
        keep = L > 1e-9
        P, e, L = P[keep], e[keep], L[keep]
        n = len(P)
        if n < 4:
            continue
        ep = np.roll(e, 1, axis=0)                           # the edge into each vertex
        turn = np.degrees(np.arctan2(ep[:, 0] * e[:, 1] - ep[:, 1] * e[:, 0],
                                     np.einsum("ij,ij->i", ep, e)))
        c = np.flatnonzero(np.abs(turn) > CORNER)
        if len(c) < 2:
            continue
        pos = np.concatenate([[0.0], np.cumsum(L)])          # arc length at each vertex
        total = pos[-1]
        cum = np.concatenate([[0.0], np.cumsum(turn)])       # turning before each vertex
        a, b = c, np.roll(c, -1)
        gap = (pos[b] - pos[a]) % total
        prev_gap = np.roll(gap, 1)
        next_gap = np.roll(gap, -1)
        net = np.where(b > a, cum[b + 1] - cum[a], cum[n] - cum[a] + cum[b + 1])
        cand = (gap <= 2 * t) & (np.sign(turn[a]) != np.sign(turn[b])) \
            & (np.abs(net) < PARALLEL) & (prev_gap >= gap) & (next_gap >= gap)
        for k in np.flatnonzero(cand):
            i, j = int(a[k]), int(b[k])
            u = ep[i] / np.hypot(*ep[i])
            off = P[j] - P[i]
            side = float(u[0] * off[1] - u[1] * off[0])
            if not 2 * 0.005 < abs(side) < t - 2 * 0.005:
                continue
            # the poking shape's move that aligns it (the poking one: at j when the first
            # corner turns in, else at i), across the longer of the two stretches (the
            # other may be a curve's chord)
            w = ep[i] / L[i - 1] if L[i - 1] >= L[j] else e[j] / L[j]
            across = float(w[0] * off[1] - w[1] * off[0])
            move = (-across if turn[i] < 0 else across) * np.array([-w[1], w[0]])
            # each corner's shape looked for a hair along its own stretch (back from i,
            # on from j): a block set back 0.2 mm from a base's side has its corner ON the
            # base's edge, where the base was found twice and the ledge was not said
            qi = P[i] - ep[i] * min(1e-3, L[i - 1] / 2) / L[i - 1]
            qj = P[j] + e[j] * min(1e-3, L[j] / 2) / L[j]
            found.append((qi, qj, abs(side), float(gap[k]), u, turn[i], move))
        _bumps(P, e, ep, turn, pos, t, found)
    # the faces at every step's two corners by one search of the faces' edges
    faces = _faces_at(d, s, np.array([f[0] for f in found] + [f[1] for f in found],
                                     dtype=float).reshape(-1, 2), tick) if found else []
    said: list = []                 # the ledges found, said by _say_few
    hairs: list = []                # those under LEDGE_SEEN: notes
    pairs: dict = {}                # (poke, other) -> (its row, ledge, move, where): a twin
    area = {id(g): f.area() for _, fs in _solids_within(d, s) for g, f in fs
            if f is not None and not f.is_empty()} if found else {}
    for k, (pi, pj, side, gap, u, ti, mv) in enumerate(found):
        tick()
        fi, fj = faces[k], faces[len(found) + k]
        if fi is None or fj is None or fi is fj:
            continue
        # the corner that turns outward (convex, left on a counter-clockwise outline) is the
        # poking shape's own corner; the other is where it meets the shape it passes
        poke, other = (fj, fi) if ti < 0 else (fi, fj)
        at = pj if ti < 0 else pi
        labels = [Label(other.span, "the edge it almost meets", primary=False)] \
            if other.span is not None else []
        # the smaller of the two moves (run dv: the hint moved a 300 mm sign's panel 0.21 mm
        # for the last of twenty grass blades)
        mover, sign = (other, -1.0) if area.get(id(poke), 0.0) > \
            LARGER_STAYS * area.get(id(other), math.inf) else (poke, 1.0)
        twin = pairs.get((id(poke), id(other)))
        if twin is not None and abs(twin[1] - side) < 1e-3 and \
                float(np.hypot(*(np.asarray(twin[2]) + np.asarray(mv)))) < 1e-3:
            # the same ledge on the other side (run fm: a star's petals 0.39 mm past both
            # sides of its stem, hints to move it 0.385 mm left and right): one is said, as
            # a resize; a move would align one side and double the other
            k2, _, _, at2 = twin
            row = (said if side >= LEDGE_SEEN else hairs)
            msg, span, kw = row[k2]
            w2 = written(s, *at)
            width = 2 * float(np.hypot(*mv))
            axis = np.asarray(mv, dtype=float) / max(float(np.hypot(*mv)), 1e-12)
            row[k2] = (msg.replace(" in the outline near (", " in the outline on both sides, "
                                   "near (", 1).replace("): the two edges",
                                                        f") and ({w2[0]:.1f}, {w2[1]:.1f}): the "
                                                        "two edges", 1), span,
                       {**kw, "hint": f"align both sides: make `{_copy_label(mover)}` "
                                      f"{width:.3f} mm {'narrower' if sign > 0 else 'wider'} "
                                      f"across (along ({abs(axis[0]) + 0:.3f}, "
                                      f"{abs(axis[1]) + 0:.3f})), its middle where it is (a "
                                      "move aligns one side and doubles the other), or make "
                                      f"the offset clear (at least {t:g} mm) if a ledge is "
                                      "meant"})
            continue
        row = said if side >= LEDGE_SEEN else hairs
        pairs[(id(poke), id(other))] = (len(row), side, mv, at)
        row.append((
                     f"`{_copy_label(poke)}` pokes {side:.2f} mm past `{_copy_label(other)}` "
                     f"in `{s.path}`, a ledge of {side:.2f} mm in the outline near "
                     f"({written(s, *at)[0]:.1f}, {written(s, *at)[1]:.1f}): the two edges "
                     "almost align but not quite" + ("" if side >= LEDGE_SEEN else
                                                     " (a step this small hardly shows once "
                                                     "cut: align them where it is a fit)"),
                     poke.span or s.span,
                     {"labels": labels,
                      "hint": f"align the edges: move `{_copy_label(mover)}` by "
                              f"({sign * mv[0] + 0:.3f}, {sign * mv[1] + 0:.3f}) mm (or resize "
                              "it so that this edge moves as much; or tie the two edges with "
                              f"a constraint), or make the offset clear (at least {t:g} mm) if "
                              "a ledge is meant"}))
    _say_few(sink, "W0520", s.path, said)
    _say_few(sink, "W0520", s.path, hairs, "note")


def _cornerless(loops) -> np.ndarray:
    """Which ``loops`` :func:`_check_steps` would pass over for having fewer than two
    corners (turns sharper than :data:`CORNER`), for all loops at once: the same turns (the
    same arithmetic on the same edges) without a dozen NumPy calls per loop (a plate of
    20,000 round holes read from a DXF: 0.57 -> 0.1 s).  A loop with an edge of at most
    1e-9 mm (dropped before the turns are taken), or of fewer than 4 vertices, is not
    said cornerless: it takes the per-loop path."""
    sizes = np.array([len(P) for P in loops], dtype=np.intp)
    out = np.zeros(len(loops), dtype=bool)
    if not len(loops) or sizes.min() < 1:
        return out
    V = np.concatenate([np.asarray(P, dtype=float).reshape(-1, 2) for P in loops])
    start = np.repeat(np.cumsum(sizes) - sizes, sizes)
    size = np.repeat(sizes, sizes)
    idx = np.arange(len(V))
    e = V[start + (idx - start + 1) % size] - V
    ep = e[start + (idx - start - 1) % size]
    L = np.hypot(*e.T)
    turn = np.degrees(np.arctan2(ep[:, 0] * e[:, 1] - ep[:, 1] * e[:, 0],
                                 np.einsum("ij,ij->i", ep, e)))
    first = np.cumsum(sizes) - sizes
    corners = np.add.reduceat((np.abs(turn) > CORNER).astype(np.intp), first)
    short = np.add.reduceat((L <= 1e-9).astype(np.intp), first)
    return (corners < 2) & (short == 0) & (sizes >= 4)


BUMP = 2.0           # degrees: a concave turn this sharp is where two faces' edges cross
BUMP_LENGTH = 40     # of the minimum wall: the farthest a bump is followed (20 mm at 0.5 mm)


def _bumps(P, e, ep, turn, pos, t: float, found: list) -> None:
    """The hair-thin overshoots of one counter-clockwise loop ``P`` (its edges ``e``, the
    edges into each vertex ``ep``, the turns in degrees, the arc length ``pos`` at each
    vertex): at a shallow concave turn (right turn of :data:`BUMP` to :data:`CORNER` degrees,
    where the edge of one shape crosses a straight side of another at a small angle), the
    outline beyond it strays outward from the line of that side (the straight edge before
    the turn, extended; and the same backward, for the turn's mirror image) by more than
    0.01 mm and less than ``t`` before it comes back across the line or turns away from it
    by 90 degrees (within ``BUMP_LENGTH t`` mm): a heart's lobe that pokes past the
    triangle's side by a hair.  Appended to ``found`` as ``(the turn, the farthest vertex,
    height, length followed, direction, -1, the move that brings the bulge back onto the
    line)``."""
    n = len(P)
    cand = np.flatnonzero((turn < -BUMP) & (turn > -CORNER))
    if not len(cand):
        return
    total = pos[-1]
    reach = min(BUMP_LENGTH * t, total)
    pos2 = np.concatenate([pos[:n], pos[:n] + total])      # twice round, to search windows
    for a in cand:
        a = int(a)
        for step, u in ((1, ep[a]), (-1, -e[a])):
            if float(np.hypot(*u)) < 2 * t:
                continue                 # not a straight side: a curve's chord
            u = u / np.hypot(*u)
            # the vertices after the turn (before it, walking backward), up to `reach` mm
            if step == 1:
                hi = int(np.searchsorted(pos2, pos[a] + reach, side="right"))
                idx = np.arange(a + 1, min(hi, a + n)) % n
                along = (pos[idx] - pos[a]) % total
            else:
                lo = int(np.searchsorted(pos2, pos[a] + total - reach, side="left"))
                idx = np.arange(a + n - 1, max(lo, a) - 1, -1) % n
                along = (pos[a] - pos[idx]) % total
            if not len(idx):
                continue
            rel = P[idx] - P[a]
            side = u[0] * rel[:, 1] - u[1] * rel[:, 0]
            if step == -1:
                side = -side            # walking backward the material is on the right
            out = -side                 # outward, away from the material
            d = P[idx] - P[np.r_[a, idx[:-1]]]
            ahead = d @ u                # moving on along the line's direction
            stop = np.flatnonzero((out <= 0) | (ahead < -1e-12))
            if not len(stop) or out[stop[0]] > 0 or stop[0] == 0:
                continue                 # it turns away from the line: a wider shape's edge
            k = int(stop[0])
            h = float(out[:k].max())
            if not 2 * 0.005 < h < t - 2 * 0.005:
                continue
            far = P[idx[int(np.argmax(out[:k]))]]
            found.append((P[a], far, h, float(along[:k].max() if len(along) else 0.0), u,
                          -1.0, step * h * np.array([-u[1], u[0]])))


def _above(sp_: Span, call: str) -> Fix | None:
    """The fix that writes ``call`` on its own line above the statement at ``sp_`` (W0109's
    and W0116's `CutInto(...)`), or None in a standard-library file or for a copy's name
    (`lid_hole[2]`) that cannot be written."""
    if in_stdlib(sp_.file) or "[" in call:
        return None
    at = Span(sp_.file, sp_.line, sp_.col, sp_.line, sp_.col, sp_.start, sp_.start)
    return Fix(at, f"{call}\n{' ' * (sp_.col - 1)}")


def check_stray_holes(sink: DiagnosticSink, drawing: Drawing, deadline=None) -> None:
    """W0109 for a hole declared in an assembly (a part of its own, so it cuts nothing; issue
    61: `hole lid_hole` beside `box = finger_box(...)`), naming the solid part it lies over
    (the most overlap, one whose name the hole's names first) and carrying the fix that
    cuts it there: `CutInto(lid_hole, box.lid)` inserted above the hole, in the assembly.
    ``deadline`` (:class:`~aidl_lang.base.limits.Deadline`): looked at for each hole and every
    256 solids it is compared with (raises :class:`~aidl_lang.base.limits.OutOfBudget`)."""
    holes = [p for p in drawing.parts if p.kind == "hole"]
    if not holes:
        return
    solids = [p for p in drawing.parts if p.kind == "solid"]
    for hp in holes:
        h = drawing.part_of.get(hp.name)
        if h is None or h.parent is None or h.parent.kind != "assembly" or h.span is None:
            continue
        home = h.parent
        best, best_key = None, None
        hx0, hy0, hx1, hy1 = hp.shape.bounds()
        for k, sp in enumerate(solids):
            if deadline is not None and k % 256 == 0:
                deadline.check("the shape checks", h)
            t = drawing.part_of.get(sp.name)
            if t is None or not t.is_within(home):
                continue
            sx0, sy0, sx1, sy1 = sp.shape.bounds()
            if sx0 > hx1 or sx1 < hx0 or sy0 > hy1 or sy1 < hy0:
                continue                # boxes apart: no overlap (no boolean for it)
            try:
                area = (hp.shape ^ sp.shape).area()
            except Exception:           # a degenerate shape: no overlap to speak of
                continue
            if area <= 1e-9:
                continue
            key = (t.name.split("[")[0] in h.name, area)
            if best_key is None or key > best_key:
                best, best_key = t, key
        msg = (f"hole `{h.path}` is declared in assembly `{home.path}`, so it cuts nothing: a "
               "hole cuts only the solid it is declared in")
        fix = None
        if best is not None:
            rel = best.path[len(home.path) + 1:]
            call = f"CutInto({h.name}, {rel})"
            hint = (f"it lies over `{best.path}`: `{call}` in `{home.path}` cuts it there "
                    "(the fix); a part of a template instance is cut only this way")
            fix = _above(h.span, call)
            msg += f"; it lies over `{best.path}`"
        else:
            hint = (f"declare it inside the solid it should cut, or write `CutInto({h.name}, "
                    f"PART)` in `{home.path}` to cut a solid part of it (a part of a template "
                    "instance: `box.lid`)")
        sink.add(Diagnostic("W0109", msg, h.span, "warning", hint=hint, fix=fix))


def check_loose_drawings(sink: DiagnosticSink, drawing: Drawing, deadline=None) -> None:
    """W0116 for a drawing declared in an assembly (an illustration beside the parts, engraved
    on none) that lies on a solid part of it: all its sample points on that part's material
    (grown by :data:`~.marks.engravings.ENGRAVE_TOL`, as W0505 reads it: the fix then warns
    of nothing; a drawing partly off every part is an illustration).  The flat sheet engraves it where it lies, while a cutting
    layout (`--layout sheet`) and the parts list carry the part without it (issue 111's tea
    box: "TEA" beside `box = finger_box(...)`, left out of the sheet).  The fix writes
    `CutInto(label, box.front)` above the drawing, which engraves it on that part.
    ``deadline``: looked at for each drawing (raises
    :class:`~aidl_lang.base.limits.OutOfBudget`)."""
    loose: dict = {}
    for style, item, g in drawing.strokes:
        if g is None or style not in ("drawing", "fill"):
            continue
        d = g.owner
        while d.parent is not None and d.parent.kind == "drawing" and d.cuts_into is None:
            d = d.parent
        if d.kind == "drawing" and d.cuts_into is None and d.parent is not None \
                and d.parent.kind == "assembly" and d.span is not None:
            loose.setdefault(d, []).append(item)
    if not loose:
        return
    solids = [(p, drawing.part_of.get(p.name)) for p in drawing.parts if p.kind == "solid"]
    for d, items in loose.items():
        if deadline is not None:
            deadline.check("the shape checks", d)
        pts = _samples(items)
        x0, y0 = pts.min(axis=0)
        x1, y1 = pts.max(axis=0)
        best, most = None, 0
        for p, s in solids:
            if s is None or not s.is_within(d.parent):
                continue
            sx0, sy0, sx1, sy1 = p.shape.bounds()
            if sx0 > x1 or sx1 < x0 or sy0 > y1 or sy1 < y0:
                continue
            grown = p.shape.offset(ENGRAVE_TOL, mf.JoinType.Round, 2.0, 16)
            on = int(_inside(pts, _edges([np.asarray(q, dtype=float)
                                          for q in grown.to_polygons()])).sum())
            if on > most:
                best, most = s, on
        if best is None or most < len(pts):
            continue
        home = d.parent
        rel = best.path[len(home.path) + 1:]
        call = f"CutInto({d.name}, {rel})"
        fix = _above(d.span, call)
        sink.add(Diagnostic(
            "W0116", f"drawing `{d.path}` is declared in assembly `{home.path}`, so it is engraved "
            f"on no part, yet it lies on `{best.path}`: the flat sheet engraves it there, while "
            "a cutting layout (`--layout sheet`) and the parts list carry the part without it",
            d.span, "warning", fix=fix,
            hint=f"`{call}` in `{home.path}` engraves it on `{best.path}` (the fix); an "
                 "illustration meant beside the parts is drawn off them"))
