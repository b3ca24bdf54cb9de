"""``aidl import``: a drawing turned into an editable AIDL program (docs/import.md).

:func:`to_program` writes one structure per DXF layer (or one for an SVG): outer outlines are
chains of the language's own ``Line``, ``Arc``, ``Spline`` and ``Bezier`` statements sharing their end
points (so they close into faces), outlines inside them become ``hole`` children (a circle is a
``Circle``), outlines inside holes become solids of their own, full ellipses are ``Ellipse``
and open paths are drawn in a ``drawing`` child (engraving).  A layer whose name starts with
``ENGRAVE`` (as ``aidl render`` writes them) becomes a ``drawing``.  Coordinates are written
with Python's shortest round-trip ``repr``, so the program renders back to the same curves
(1e-9 mm).  A spline piece that is the interpolating cubic spline through its span ends is
written as a ``Spline`` through them; any other (an SVG's or DXF's free cubics, a Spline
with ``corners=``) as a ``Bezier`` chain of its own control points.  Every piece, hole
curve, text, path and part is held where the file puts it (:func:`_holds`: ``aidl check``
says ``fully constrained``, with no ``W0401``); separate parts on one layer are a solid each;
loops on a layer named for holes that lie in another layer's part are its holes
(:func:`~.infer_layers._hole_layers`); a drawing read in inches is written in ``units in``
with the file's numbers (:mod:`.units`).
"""
from __future__ import annotations

import math

from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Loop, Spline
from ...geometry.shapes.drawing2d import _inside, _inside_many
from ..chains.containment import (_apart, _containers, _loops_of, _overlapping_parts, _probe,
                                  _whole_ellipse, engraved_on)
from ..chains.layers import engraved_layer
from ..chains.hole_cuts import cut_at_crossings, inner_rests, loop_key, runs_of
from ..chains.notches import EDGE_ACROSS
from ..model import Drawing, Note, Outline, Path
from .units import UNIT, in_unit
from .writer import (_num, _string, _pt, _ident, _length, _Writer, _holds, _emit_holds, COPIES_PER_LOOP)


def _structure(w: _Writer, depth: int, kind: str, name: str, d: Drawing) -> None:
    # every closed curve a loop, whatever its kind: which loops lie inside which makes a
    # part's outline, its hole, an island in the hole (a solid of its own), ...
    loops = [("o", o.segments) for o in d.outlines] + [("c", [c]) for c in d.circles] + \
        [("e", [_whole_ellipse(el)]) for el in d.ellipses]
    inside = _containers([segs for _, segs in loops], w.deadline)
    depths = [len(c) for c in inside]
    w.emit(depth, f"{kind} {name} {{")
    used: set = set()
    k = 0
    islands = []
    # a hole inside an island (a loop inside three others, five, ...) is the island's hole,
    # written in the island's solid (in the outer solid it cut nothing: W0508, its cut lost)
    island_holes: dict = {}
    if kind != "drawing":
        for i, dep in enumerate(depths):
            if dep >= 3 and dep % 2 == 1:
                owner = [j for j in inside[i] if depths[j] == dep - 1]
                if owner:
                    island_holes.setdefault(owner[0], []).append(i)
    deep = {i for v in island_holes.values() for i in v}
    named: list = []            # (its loop_key, name) of each hole written alone
    copies = _copies(loops, depths, kind) if w.compact else {}
    for (tag, segs), dep in zip(loops, depths):
        k += 1
        places = copies.get(k - 1)
        if places == []:                 # a copy of a loop written before: in its loop
            continue
        if places:
            w.emit(depth + 1, f"for p in [{', '.join(_pt(q) for q in places)}] {{")
            w.rel, depth = places[0], depth + 1
        if kind == "drawing" or dep == 0:
            _loop(w, depth + 1, segs, f"{tag}{k}_", None)
        elif k - 1 in deep:             # written in its island's solid (below)
            pass
        elif dep % 2 == 1:
            hole = _ident(f"hole{k}", used)
            _loop(w, depth + 1, segs, "", hole)
            if not places:
                named.append((loop_key(segs), hole))
        else:
            islands.append((segs, k))
        if places:
            w.rel, depth = None, depth - 1
            w.emit(depth + 1, "}")
    # holes drawn overlapping on a cut role (their inner pieces a sheet-level cut): one opening
    if w.overlaps and named:
        order = {ident: (n, hole) for n, (ident, hole) in enumerate(named)}
        for a, b in sorted(sorted((order[i] for i in pair)) for pair in w.overlaps
                           if all(i in order for i in pair)):
            w.emit(depth + 1, f"AllowOverlap({a[1]}, {b[1]})")
    if d.texts:
        inner = depth + 1 if kind == "drawing" else depth + 2
        if kind != "drawing":
            w.emit(depth + 1, "drawing labels {")
        _texts(w, inner, d.texts, "t")
        if kind != "drawing":
            w.emit(depth + 1, "}")
            w.emit(depth + 1, "Fixed(labels)")
    # a cut role's open paths: through-cuts, never engraved; a loop that crosses itself (a
    # closed curve in a `cut` is a hole's edge, which must not) stays an engraving, counted
    cut_paths = [p for p in d.paths if p.crossing is None] \
        if kind != "drawing" and d.paths_cut else []
    cut_ids = {id(p) for p in cut_paths}
    drawn = [p for p in d.paths if id(p) not in cut_ids]
    if cut_paths:
        w.emit(depth + 1, "cut cuts {")
        w.cut_paths += len(cut_paths)
        w.cut_length += sum(_length(p.segments) for p in cut_paths)
        _paths(w, depth + 2, cut_paths, name)
        w.emit(depth + 1, "}")
        w.emit(depth + 1, "Fixed(cuts)")
    if d.paths_cut and kind != "drawing":
        w.crossed += len(drawn)
    if drawn:
        if kind != "drawing":
            w.emit(depth + 1, "drawing paths {")
        _paths(w, depth + 1 if kind == "drawing" else depth + 2, drawn, name)
        if kind != "drawing":
            w.emit(depth + 1, "}")
            w.emit(depth + 1, "Fixed(paths)")
    e = getattr(d, "engrave", None)
    if e is not None and (not e.empty or e.texts):     # the shapes whose role is `engrave`
        if kind == "drawing":
            _structure_body(w, depth + 1, e, "g")
        else:
            w.emit(depth + 1, "drawing engrave {")
            _structure_body(w, depth + 2, e, "g")
            w.emit(depth + 1, "}")
            w.emit(depth + 1, "Fixed(engrave)")
    w.emit(depth, "}")
    if depth > 0:           # a part of the assembly: where the file puts it
        w.emit(depth, f"Fixed({name})")
    for run in _island_runs(islands, island_holes, loops, w.compact):
        segs, k = run[0]
        inner = depth
        if len(run) > 1:                 # islands of one shape moved: written once
            w.emit(depth, f"for p in [{', '.join(_pt(_place(q)) for q, _ in run)}] {{")
            w.rel, inner = _place(segs), depth + 1
        w.emit(inner, f"solid {name}_island{k} {{")
        _loop(w, inner + 1, segs, f"o{k}_", None)
        for i in island_holes.get(k - 1, ()):
            _loop(w, inner + 1, loops[i][1], "", _ident(f"hole{i + 1}", used))
        w.emit(inner, "}")
        if inner > 0:
            w.emit(inner, f"Fixed({name}_island{k})")
        if len(run) > 1:
            w.rel = None
            w.emit(depth, "}")


def _island_runs(islands: list, island_holes: dict, loops: list, compact: bool) -> list:
    """The islands of a structure (``(outline segments, loop number)``) in runs to write
    together: with ``compact``, islands that are one shape moved, their holes too (each
    hole's shape and its place from the outline's first point within 1e-9 mm,
    :func:`_shape_key`), in runs of at most :data:`COPIES_PER_LOOP`, written once in a ``for``
    over their places (Boxes.py's GridfinityBaseSplit: 126 base pieces, each a solid of
    its own with its four magnet holes); else each alone."""
    if not compact:
        return [[isl] for isl in islands]
    groups: dict = {}
    alone = []
    for segs, k in islands:
        key = _shape_key(segs)
        x0, y0 = _place(segs)
        holes = []
        for i in island_holes.get(k - 1, ()):
            h = loops[i][1]
            q = _place(h)
            holes.append((round((q[0] - x0) * 1e9), round((q[1] - y0) * 1e9), _shape_key(h)))
        if key is None or any(h[2] is None for h in holes):
            alone.append([(segs, k)])
            continue
        groups.setdefault((key, tuple(sorted(holes))), []).append((segs, k))
    runs = [idx[j:j + COPIES_PER_LOOP] for idx in groups.values()
            for j in range(0, len(idx), COPIES_PER_LOOP)]
    return sorted(runs + alone, key=lambda r: r[0][1])


def _shape_key(segs) -> tuple | None:
    """A key equal for two loops that are one shape moved (each point within 1e-9 mm of the
    other's, relative to the loop's first point, pieces of the same kinds in the same order):
    lines, arcs and spline pieces; a lone circle by its radius (a 20,000-hole panel's holes
    written once each passed the program's size limit); None for others."""
    if len(segs) == 1 and isinstance(segs[0], Circle):
        return ("C", round(segs[0].radius * 1e9))
    if len(segs) < 2:
        return None
    x0, y0 = segs[0].start

    def r(q):
        return (round((q[0] - x0) * 1e9), round((q[1] - y0) * 1e9))
    key = []
    for sg in segs:
        if isinstance(sg, Line):
            key.append(("L", r(sg.end)))
        elif isinstance(sg, Arc):
            key.append(("A", r(sg.center), r(sg.end), sg.sweep > 0))
        elif isinstance(sg, Spline):
            key.append(("S", tuple(r(q) for b in sg.spans for q in b),
                        tuple(round(h, 12) for h in sg.curve.h)))
        else:
            return None
    return tuple(key)


def _copies(loops: list, depths: list, kind: str) -> dict:
    """The loops of a structure that repeat one shape moved (:func:`_shape_key`), as
    ``{index of the first: [each copy's first point], index of another copy: []}``: the
    first is written once in a ``for p in [...]`` loop over the places, relative to ``p``
    (:meth:`_Writer.pt`), the others not at all.  Copies are grouped by role too (an outer
    loop, a hole, an island)."""
    groups: dict = {}
    for i, ((_tag, segs), dep) in enumerate(zip(loops, depths)):
        key = _shape_key(segs)
        if key is not None:
            # islands and their holes (depth 3, 5, ...: written in the island) are role 0
            role = "outer" if kind == "drawing" or dep == 0 else dep % 2 if dep == 1 else 0
            groups.setdefault((role, key), []).append(i)
    out: dict = {}
    for (role, _key), idx in groups.items():
        if len(idx) < 2 or role == 0:          # islands are written as solids of their own
            continue
        for k in range(0, len(idx), COPIES_PER_LOOP):
            run = idx[k:k + COPIES_PER_LOOP]
            out[run[0]] = [_place(loops[i][1]) for i in run]
            for i in run[1:]:
                out[i] = []
    return out


def _place(segs):
    """Where a copy of a loop is (:func:`_copies`): its first point, a lone circle's centre."""
    return segs[0].center if isinstance(segs[0], Circle) else segs[0].start


def _sheet_cut(w: _Writer, depth: int, name: str, d: Drawing) -> None:
    """A sheet-level cut, ``cut NAME { ... }`` directly in the assembly (language.md 2.5):
    the cut role's paths of ``d`` that lie in no part, cut where they are drawn."""
    w.emit(depth, f"cut {name} {{")
    _paths(w, depth + 1, d.paths, name)
    w.emit(depth, "}")
    w.emit(depth, f"Fixed({name})")


def _paths(w: _Writer, depth: int, paths: list, name: str) -> None:
    """The statements of open paths (and loops that cross themselves), ``p1_0 = ...``."""
    for i, p in enumerate(paths):
        closed = math.dist(p.start, p.end) <= 1e-6 and p.crossing is not None
        if not w.chain(depth, p.segments, closed, f"p{i + 1}_"):
            w.notes.append(Note("W0130", f"a path of `{name}` holds a piece no statement "
                                         f"writes (a whole circle or ellipse inside a "
                                         f"chain): left out"))
        else:
            _emit_holds(w, depth, _holds(p.segments, f"p{i + 1}_", closed))


def _texts(w: _Writer, depth: int, texts: list, prefix: str) -> None:
    """``Text(...)`` statements of a drawing's texts (:class:`~.read.Drawing`'s ``texts``)."""
    for i, (text, (x, y), h, rot, anchor, valign) in enumerate(texts):
        deg = round(math.degrees(rot), 9)      # the file's degrees (text is not exact)
        rot_txt = f", rotation={_num(deg)} deg" if deg else ""
        w.emit(depth, f"{prefix}{i + 1} = Text({_string(text)}, position={_pt((x, y))}, "
                      f"size={_num(h)}, anchor=\"{anchor}\", valign=\"{valign}\"{rot_txt})")
    _emit_holds(w, depth, [f"{prefix}{i + 1}" for i in range(len(texts))], "t")


def _structure_body(w: _Writer, depth: int, d: Drawing, prefix: str) -> None:
    """The statements of an engraving (every loop and path a stroke) at ``depth``."""
    k = 0
    for segs in [o.segments for o in d.outlines] + [[c] for c in d.circles]:
        k += 1
        _loop(w, depth, segs, f"{prefix}{k}_", None)
    for cx, cy, rx, ry, rot in d.ellipses:
        k += 1
        w.emit(depth, f"{prefix}{k} = Ellipse(center={_pt((cx, cy))}, rx={_num(rx)}, "
                      f"ry={_num(ry)}, rotation={_num(math.degrees(rot))} deg)")
        w.emit(depth, f"Fixed({prefix}{k})")
    for p in d.paths:
        k += 1
        closed = math.dist(p.start, p.end) <= 1e-6 and p.crossing is not None
        if not w.chain(depth, p.segments, closed, f"{prefix}{k}_"):
            w.notes.append(Note("W0130", "an engraved path holds a piece no statement writes "
                                         "(a whole circle or ellipse inside a chain): left out"))
        else:
            _emit_holds(w, depth, _holds(p.segments, f"{prefix}{k}_", closed))
    _texts(w, depth, d.texts, f"{prefix}t")


def _split_parts(d: Drawing, deadline=None,
                 joined: list | None = None) -> tuple[list[Drawing], Drawing | None]:
    """The separate parts of a sheet: one :class:`Drawing` per outer loop (a loop inside an
    even number of others, islands included; a whole circle or ellipse is a loop too,
    :func:`_loops_of`) with its holes (the loops just inside it) and the paths, texts and
    engravings that lie in it; and what lies in no part (a
    Drawing, or None).  An open path on a cut role (``d.paths_cut``) that starts outside
    every part goes to the part it reaches (:func:`_reached`), appended to ``joined``."""
    loops = [o for o in d.outlines] + list(d.circles) + list(d.ellipses)
    segs = _loops_of(d)
    inside = _containers(segs, deadline)
    depth = [len(c) for c in inside]
    roots = [i for i in range(len(loops)) if depth[i] % 2 == 0]
    parts = {i: Drawing(unit=d.unit, paths_cut=d.paths_cut) for i in roots}

    def put(part: Drawing, loop) -> None:
        (part.outlines if isinstance(loop, Outline) else part.circles
         if isinstance(loop, Circle) else part.ellipses).append(loop)
    for i in roots:
        put(parts[i], loops[i])
    for i in range(len(loops)):
        if depth[i] % 2 == 1:
            owner = [j for j in inside[i] if depth[j] == depth[i] - 1]
            if owner:
                put(parts[owner[0]], loops[i])
    import numpy as np
    polys = {i: np.asarray(Loop(list(segs[i])).points(), dtype=float) for i in roots}
    loose = Drawing(unit=d.unit)

    def owner_of(pt):
        best = None
        for i in roots:
            if len(polys[i]) >= 3 and _inside(pt, polys[i]) and \
                    (best is None or depth[i] > depth[best]):
                best = i
        return parts[best] if best is not None else loose
    for p in d.paths:
        owner = owner_of(_probe(p.segments))
        if owner is loose and d.paths_cut and p.crossing is None:
            j = _reached(p, [polys[i] for i in roots])
            if j is not None:
                owner = parts[roots[j]]
                if joined is not None:
                    joined.append(p)
        owner.paths.append(p)
    for t in d.texts:
        owner_of(t[1]).texts.append(t)
    e = getattr(d, "engrave", None)
    if e is not None:
        for o in e.outlines:
            _engrave_of(owner_of(_probe(o.segments))).outlines.append(o)
        for c in e.circles:
            _engrave_of(owner_of(c.center)).circles.append(c)
        for p in e.paths:
            _engrave_of(owner_of(_probe(p.segments))).paths.append(p)
        for el in e.ellipses:
            _engrave_of(owner_of((el[0], el[1]))).ellipses.append(el)
        for t in e.texts:
            _engrave_of(owner_of(t[1])).texts.append(t)
    out = [parts[i] for i in roots]
    left = None if loose.empty and not loose.texts and loose.engrave is None else loose
    return out, left


def _reached(p: Path, polys: list) -> int | None:
    """The index of the polygon (a part's outline, sampled) that the open path ``p`` enters
    (one of its pieces' ends inside it) or comes back to (an end within :data:`GAP_NOTE` of
    its edge), the nearest first; None when it reaches none."""
    import numpy as np
    from ..model import GAP_NOTE
    ends = [s.start for s in p.segments] + [p.end]
    for i, P in enumerate(polys):
        if len(P) >= 3 and any(_inside(q, P) for q in ends):
            return i
    best = None
    for i, P in enumerate(polys):
        if len(P) < 2:
            continue
        A, B = P, np.roll(P, -1, axis=0)
        AB = B - A
        L2 = np.maximum((AB ** 2).sum(axis=1), 1e-300)
        for q in (p.start, p.end):
            t = np.clip(((q[0] - A[:, 0]) * AB[:, 0] + (q[1] - A[:, 1]) * AB[:, 1]) / L2, 0, 1)
            dist = float(np.min(np.hypot(A[:, 0] + t * AB[:, 0] - q[0],
                                         A[:, 1] + t * AB[:, 1] - q[1])))
            if dist <= GAP_NOTE and (best is None or dist < best[0]):
                best = (dist, i)
    return None if best is None else best[1]


def _close_loose_cuts(d: Drawing, source: str, notes: list) -> Drawing:
    """``d`` (its open paths on a cut role) with each open path that lies in no outline and
    ends within :data:`~.model.GAP_NOTE` of its start closed across that gap into an outline
    of its own: a part's outline drawn open (Boxes.py leaves its burn-corrected corners so,
    0.14 mm apart), which a laser cuts out as a part; the gap is bridged by a line (the
    pieces drawn are kept exactly), small loops where the loop crosses itself cut off
    (:func:`~.chain._trim_small_loops`); one that still
    crosses itself stays a path.  A ``W0130`` appended to ``notes`` counts them and names
    the largest gap."""
    import dataclasses

    import numpy as np

    from ...geometry.shapes.curves import reverse
    from ..chains.chain import OVERSHOOT, _crossing, _trim_small_loops
    from ..model import CLOSE_TOL, GAP_NOTE
    if not d.paths_cut or not d.paths:
        return d
    polys = [np.asarray(Loop(list(o.segments)).points(), dtype=float) for o in d.outlines]
    polys += [np.asarray(Loop([c]).points(), dtype=float) for c in d.circles]
    new, keep, gaps = [], [], []
    for p in d.paths:
        g = math.dist(p.start, p.end)
        segs = list(p.segments)
        if p.crossing is not None or not 0 < g <= GAP_NOTE or len(segs) < 2 or \
                _length(segs) <= 10 * g or any(len(P) >= 3 and _inside(_probe(segs), P)
                                               for P in polys):
            keep.append(p)
            continue
        loop = segs + [Line(segs[-1].end, segs[0].start)]
        if _crossing(loop) is not None:
            loop, _k = _trim_small_loops(loop, max(CLOSE_TOL, OVERSHOOT), True)
        o = Outline(loop, p.source)
        if _crossing(loop) is not None or abs(o.area) <= g * _length(segs):
            keep.append(p)
            continue
        if o.area < 0:
            o.segments = [reverse(s) for s in reversed(loop)]
        new.append(o)
        gaps.append((g, p.end))
    if not new:
        return d
    n = len(new)
    g, at = max(gaps)
    notes.append(Note("W0130", f"{n} open path{'s' if n != 1 else ''} of `{source}` on a cut "
                               f"role {'lies' if n == 1 else 'lie'} in no part and "
                               f"{'ends' if n == 1 else 'end'} within {GAP_NOTE:g} mm of "
                               f"{'its' if n == 1 else 'their'} start: closed across the gap "
                               f"into the outline of a part (the largest gap {g:.3g} mm, at "
                               f"({at[0]:.6g}, {at[1]:.6g}) mm)",
                      "close the outline in the drawing program, or give engrave= (by layer "
                      "or colour) for paths that are to be engraved"))
    outlines = sorted(list(d.outlines) + new, key=lambda o: -abs(o.area))
    return dataclasses.replace(d, outlines=outlines, paths=keep)


def _engrave_of(d: Drawing) -> Drawing:
    if d.engrave is None:
        d.engrave = Drawing(unit=d.unit)
    return d.engrave


def _loop(w: _Writer, depth: int, segs: list, prefix: str, hole: str | None,
          hold: bool = True) -> None:
    """The statements of the closed loop ``segs`` (a ``hole`` of that name when given), and
    with ``hold`` what holds it where the file puts it (:func:`_holds`: ``aidl check`` has no
    degree of freedom to report)."""
    if hole is not None:
        w.emit(depth, f"hole {hole} {{")
        depth += 1
        prefix = "c" if len(segs) == 1 and isinstance(segs[0], Circle) else "e"
    held: list = []
    one = prefix.rstrip('_')
    if len(segs) == 1 and isinstance(segs[0], Circle):
        c = segs[0]
        w.emit(depth, f"{one or 'c'} = Circle(center={w.pt(c.center)}, "
                      f"radius={_num(c.radius)})")
        held = [one or "c"]
    elif len(segs) == 1 and isinstance(segs[0], EllipticArc) and segs[0].whole:
        e = segs[0].curve
        w.emit(depth, f"{one or 'e'} = Ellipse(center={w.pt(e.center)}, "
                      f"rx={_num(e.rx)}, ry={_num(e.ry)}, "
                      f"rotation={_num(math.degrees(e.rotation))} deg)")
        held = [one or "e"]
    elif w.compact and len(segs) >= 3 and all(isinstance(s, Line) for s in segs):
        # a big drawing: a loop of lines as the points of one Polygon
        w.emit(depth, f"{one or 'e'} = Polygon([{', '.join(w.pt(s.start) for s in segs)}])")
        held = [one or "e"]
    elif not w.chain(depth, segs, True, prefix):
        w.notes.append(Note("W0130", "an outline holds a piece no statement writes (a "
                                     "whole circle or ellipse inside a chain): left out"))
    else:
        held = _holds(segs, prefix)
    if hole is not None:
        w.emit(depth - 1, "}")
        held = [h if h.startswith(f"{hole}.") else f"{hole}.{h}" for h in held]
        depth -= 1
    if hold:
        _emit_holds(w, depth, held)


def to_program(layers: list[tuple[str, Drawing]], source: str, parts: bool = False,
               deadline=None, compact: bool = False) -> tuple[str, list[Note]]:
    """The AIDL text of a drawing read layer by layer (``(layer name, Drawing)``, in order),
    and the notes of what was left out.  ``source``: the drawing's file name, for the
    header comment.  ``parts``: a sheet of parts, one ``solid`` per outer loop (its holes,
    paths, texts and engravings with it) in one ``assembly`` (:func:`_split_parts`).
    ``compact``: a drawing too big to write piece by piece: each loop of lines one
    ``Polygon``, loops that repeat one shape moved written once in a ``for`` loop over their
    places (:func:`_copies`), as exact (1e-9 mm)."""
    w = _Writer(deadline)
    w.compact = compact
    w.emit(0, f"# imported from {source} by `aidl import`: edit freely")
    if compact:
        w.emit(0, "# (a big drawing: loops of lines as Polygons, repeated loops written once in "
                  "a `for` over their places)")
    from ..chains.layers import _hole_layers
    layers, moved = _hole_layers(layers, deadline)
    for line in moved:
        w.emit(0, f"# {line}")
    w.emit(0, f"units {UNIT.get()}")
    items = in_unit(_layer_items(layers, parts, deadline, source, w.notes, w.overlaps))
    multi = len(items) > 1 or any(kind == "cut" for kind, _, _ in items)
    if multi:
        w.emit(0, "assembly " + ("sheet" if parts else "drawing_import") + " {")
    for kind, name, d in items:
        if kind == "cut":
            _sheet_cut(w, 1, name, d)
        else:
            _structure(w, 1 if multi else 0, kind, name, d)
    if multi:           # a drawing layer on a part (a board's silkscreen): engraved on it
        on = engraved_on([(n, d) for k, n, d in items if k == "drawing"],
                         [(n, d) for k, n, d in items if k == "solid"])
        for drawn, part in on.items():
            w.emit(1, f"CutInto({drawn}, {part})")
        w.emit(0, "}")
    _cut_notes(w, source)
    return "\n".join(w.lines) + "\n", w.notes


def _cut_notes(w: _Writer, source: str) -> None:
    """The notes of a cut role's open paths written as through-cuts and of its loops that
    cross themselves (engraved), from the counts ``w`` kept; appended to ``w.notes``."""
    if w.cut_paths:
        n = w.cut_paths
        w.notes.append(Note("W0130", f"{n} open path{'s' if n != 1 else ''} of `{source}` "
                                     f"({w.cut_length:.6g} {UNIT.get()}) on a cut role "
                                     f"written as "
                                     f"through-cuts (`cut cuts {{ ... }}` in {'its' if n == 1 else 'their'} "
                                     f"part): the laser cuts along {'it' if n == 1 else 'them'}, "
                                     f"one pass each", "give engrave= (by layer or colour) for "
                                     "paths that are to be engraved instead"))
    if w.crossed:
        n = w.crossed
        w.notes.append(Note("W0130", f"{n} loop{'s' if n != 1 else ''} of `{source}` on a cut "
                                     f"role cross{'es' if n == 1 else ''} {'itself' if n == 1 else 'themselves'}: "
                                     f"engraved (`drawing paths`), neither a hole nor a "
                                     f"through-cut", "redraw the loop without the crossing in "
                                     "the drawing program, then import again"))


def _say_cuts(notes: list, source: str, paths: list, what: str) -> None:
    """The ``W0130`` of the open cut ``paths`` of ``source`` that lie in no part: their
    count, length and ``what`` became of them."""
    n = len(paths)
    notes.append(Note("W0130", f"{n} open path{'s' if n != 1 else ''} of `{source}` on a cut "
                               f"role ({sum(_length(p.segments) for p in paths):.6g} mm) "
                               f"{what}", "move them into a part in the drawing program, or "
                                          "give engrave= (by layer or colour) for paths that "
                                          "are to be engraved"))


def layer_names(data: bytes, name: str) -> list[str]:
    """The DXF layers that hold entities, in the order they first appear (an entity in a
    block on layer ``0`` is on its INSERT's layer, as CAD programs draw it); ``[""]`` for
    SVG."""
    if not name.lower().endswith(".dxf"):
        return [""]
    from ..read.dxf import MAX_BLOCK_DEPTH, _EzdxfLog, _open_dxf, entity_layer
    from ..model import DrawingError
    try:
        with _EzdxfLog():            # its log lines: a note of the read, not the terminal
            doc = _open_dxf(data, name)
    except DrawingError:
        return [""]
    seen: list[str] = []
    done: set = set()

    def walk(entities, inherited, depth) -> None:
        for e in entities:
            ly = entity_layer(e)
            if ly == "0" and inherited is not None:
                ly = inherited
            if e.dxftype() == "INSERT":
                key = (e.dxf.name, ly)
                blk = doc.blocks.get(e.dxf.name)
                if blk is not None and key not in done and depth < MAX_BLOCK_DEPTH:
                    done.add(key)
                    walk(blk, ly, depth + 1)
                continue
            if ly not in seen:
                seen.append(ly)
    walk(doc.modelspace(), None, 0)
    return seen or [""]


def _count_segments(d: Drawing) -> int:
    n = sum(len(o.segments) for o in d.outlines) + len(d.circles) + len(d.ellipses) + \
        sum(len(p.segments) for p in d.paths) + len(d.texts)
    return n + (_count_segments(d.engrave) if d.engrave is not None else 0)


def import_drawing(data: bytes, name: str, unit: str | None = None, layer=None, color=None,
                   ident=None, parts: bool = False, close_tolerance: float | None = None,
                   cut=None, engrave=None, ignore=None, roles=None,
                   budget=None, writer=None, snap: float | None = None,
                   work=None) -> tuple[str, list[Note]]:
    """``aidl import``: the program of the drawing ``data`` (``name``: its file name) and the
    notes (skipped entities, left-out loops).  ``budget`` (a
    :class:`~aidl_lang.base.limits.Budget`, default the compile's): the wall time of the whole
    import, the shapes read (its ``geometry`` figure) and the program's size; a program
    the compiler would refuse (more than :data:`~aidl_lang.base.limits.MAX_SOURCE_BYTES` or
    ``budget.geometry`` statements) is ``E0304``, naming ``Drawing2D`` (nothing is
    written).  ``writer``: the function that writes the program from the layers read
    (default :func:`to_program`; ``aidl import --infer`` passes
    :func:`~.infer.to_program_inferred` through :func:`~.infer.import_drawing`).  ``snap``
    (mm, ``--snap``): Bézier circles and arcs within it taken as true ones
    (:func:`~.snap.snap_drawing`), said in the program's header.  ``work``: the
    :class:`~aidl_lang.base.limits.Work` meter the import spends from (default a new one of
    ``budget``'s units; pass one to read what it spent: ``aidl import --json``'s ``work``).
    Raises :class:`~.read.DrawingError`."""
    from ...base.limits import DEFAULT_BUDGET, Deadline, OutOfBudget, budget_factor_text
    from ...base.limits import MAX_SOURCE_BYTES as MAX_IMPORT_BYTES
    from ..read.reader import MAX_ENTITIES, DrawingError, read_drawing
    budget = budget or DEFAULT_BUDGET
    deadline = Deadline.starting(budget, work=work)
    limit = max(1, int(MAX_ENTITIES * budget.geometry / DEFAULT_BUDGET.geometry))
    base = name.replace("\\", "/").rsplit("/", 1)[-1]
    too_big = ("keep the drawing as one reference instead: `d = Drawing2D(\"" + base + "\")` "
               "in a solid (`aidl docs Drawing2D`), or import a part of it with --layer")
    from ..read.dxf import one_parse
    try:
        with one_parse():       # a DXF parsed once for its layers, each layer and role
            layers = [layer] if layer is not None else layer_names(data, name)
            read: list[tuple[str, Drawing]] = []
            notes: list[Note] = []
            snapped: list = []
            total = 0
            for ly in layers:
                try:
                    d = read_drawing(data, name, layer=ly or None, color=color, ident=ident,
                                     unit=unit, keep_text=True, close_tolerance=close_tolerance,
                                     cut=cut, engrave=engrave, ignore=ignore, roles=roles,
                                     deadline=deadline, max_shapes=limit)
                except DrawingError as ex:
                    if ex.code == "E0132" and layer is None:
                        # a layer of only skipped entities (none at all: below): what was left
                        # out of it is said (a layer of only points, say, is not)
                        if "left out: " in ex.message:
                            notes.append(Note("W0130", ex.message, ex.hint))
                        continue
                    raise
                # text is written as Text engravings here (Drawing2D skips it with this note)
                notes += [n for n in d.notes            # each once, not once per layer
                          if not (d.texts and "text is not imported" in n.message)
                          and all(n.message != m.message for m in notes)]
                if snap:
                    from ..chains.snap import snap_drawing
                    snapped.append(snap_drawing(d, snap))
                read.append((ly if isinstance(ly, str) else "_".join(ly), d))
                total += _count_segments(d)
                if total > budget.geometry:
                    raise DrawingError("E0304", f"`{base}` holds {total} or more lines, arcs and "
                                                f"curves: the program would have more than the "
                                                f"{budget.geometry} geometry objects a program may "
                                                f"build", too_big)
            from .units import say_inches, written_unit
            say_inches(notes, [d for _, d in read])
            # an inch drawing written in inches: its layers, once made parts (in mm, the
            # tolerances of chaining and cuts), scaled back to the file's numbers (in_unit)
            token = UNIT.set(written_unit([d for _, d in read])[0])
            if not read:    # every layer empty: the whole drawing's E0132, as Drawing2D gives it
                read_drawing(data, name, color=color, ident=ident, unit=unit, keep_text=True,
                             close_tolerance=close_tolerance, cut=cut, engrave=engrave,
                             ignore=ignore, roles=roles, deadline=deadline, max_shapes=limit)
            try:
                text, more = (writer or to_program)(read, base, parts=parts, deadline=deadline)
                if writer is None and len(text.encode("utf-8")) > MAX_IMPORT_BYTES:
                    text, more = to_program(read, base, parts=parts, deadline=deadline,
                                            compact=True)
            finally:
                UNIT.reset(token)
    except OutOfBudget as ex:
        what = ex.what[3:] if ex.what.startswith("it needs") else "took " + ex.what
        more = (f" with `{budget_factor_text(ex.work, budget)}`"
                if ex.what.startswith("it needs") and ex.work else "")
        raise DrawingError("E0304", f"importing `{base}` {what} (while {ex.stage})",
                           "import a part of it with --layer, keep it as one `Drawing2D`, "
                           f"or raise the budget{more}") from None
    if snap:
        from ..chains.snap import header_line
        head, _, rest = text.partition("\n")
        text = f"{head}\n# {header_line(snapped, snap)}\n{rest}"
    size = len(text.encode("utf-8"))
    if size > MAX_IMPORT_BYTES:
        raise DrawingError("E0304", f"the program of `{base}` would be {size} bytes, more than "
                                    f"the {MAX_IMPORT_BYTES} bytes a program may have: not "
                                    f"written", too_big)
    return text, notes + more


def _layer_items(layers, parts: bool, deadline, source: str, notes: list,
                 overlaps: set | None = None) -> list:
    """``[(kind, name, drawing)]``: each layer's drawing as the structure it is written as
    (``drawing`` for an ENGRAVE layer or text alone, else ``solid``), with unique names; with
    ``parts``, a solid layer's outer loops each a solid of its own (:func:`_split_parts`) and
    what lies in none an engraving, counted in a ``W0130`` appended to ``notes``."""
    used: set = set()
    items = []
    for layer, d in layers:
        # a layer of text alone, or whose every shape has the role `engrave` (`--engrave
        # LABELS`: its texts in `d.engrave`), is an engraving, not an empty solid
        kind = "drawing" if engraved_layer(layer, d) or (d.empty and (
            d.texts or (d.engrave is not None and (not d.engrave.empty or d.engrave.texts)))) \
            else "solid"
        if kind == "solid" and d.paths_cut:        # a part's outline left open: closed
            d = _close_loose_cuts(d, source, notes)
        # which loops lie inside which, found once for both questions below
        inside = _containers(_loops_of(d), deadline) if kind == "solid" and d.paths_cut \
            else None
        notch = _outside_remainders(d, inside, deadline) if inside is not None else []
        inner = inner_rests(_loops_of(d), inside, deadline, overlaps) \
            if inside is not None else []
        crossed, touched = (0, 0) if parts or inside is None else \
            _overlapping_parts(d, inside, deadline)
        # separate parts on one layer (two brackets, a plate and its washers): a solid of
        # each, as `--parts` writes them (one solid of both falls apart: W0504)
        apart = kind == "solid" and not (parts or crossed or touched) and \
            _apart(d, inside, deadline)
        if crossed:
            notes.append(Note("W0130", f"{crossed} pair{'s' if crossed != 1 else ''} of parts "
                                       f"of `{source}` on a cut role overlap: each part is "
                                       f"written as a solid of its own (`assembly "
                                       f"drawing_import`), as `--parts` does (one solid would "
                                       f"fuse them and lose the cut lines where they overlap)",
                              "move the parts apart in the drawing program if they are not "
                              "to overlap on the sheet"))
        if touched:
            notes.append(Note("W0130", f"{touched} pair{'s' if touched != 1 else ''} of parts "
                                       f"of `{source}` on a cut role touch along an edge: "
                                       f"each part is written as a solid of its own "
                                       f"(`assembly drawing_import`), as `--parts` does (one "
                                       f"solid would fuse them and lose the cut along the "
                                       f"edge they share)"))
        if (parts or crossed or touched or apart) and kind == "solid":
            joined: list = []
            pieces, loose = _split_parts(d, deadline, joined)
            base = _ident(layer, set()) if layer else "part"
            for k, pd in enumerate(pieces):
                items.append(("solid", _ident(f"{base}{k + 1}", used), pd))
            if joined:
                _say_cuts(notes, source, joined, "found outside every part but reaching one: "
                                                 "written as cuts of the part each reaches")
            cuts = [p for p in loose.paths if p.crossing is None] \
                if loose is not None and d.paths_cut else []
            if cuts:            # a cut role's paths in no part: a sheet-level cut
                loose.paths = [p for p in loose.paths if p.crossing is not None]
                items.append(("cut", _ident(f"{layer or 'sheet'}_cuts", used),
                              Drawing(unit=d.unit, paths=cuts, paths_cut=True)))
                _say_cuts(notes, source, cuts, f"in no part, reaching none: written as the "
                                               f"sheet-level cut `{items[-1][1]}` (a `cut` "
                                               f"in the assembly: the laser cuts along them "
                                               f"where they are drawn)")
                if loose.empty and not loose.texts and loose.engrave is None:
                    loose = None
            if loose is not None:
                items.append(("drawing", _ident(f"{layer or 'sheet'}_loose", used), loose))
                n = len(loose.paths) + len(loose.ellipses) + len(loose.texts)
                notes.append(Note("W0130", f"{n} path{'s' if n != 1 else ''} or label"
                                             f"{'s' if n != 1 else ''} of `{source}` lie in no "
                                             f"part: written as the engraving "
                                             f"`{items[-1][1]}`",
                                    "move them into a part, or delete the drawing if they "
                                    "are notes"))
        else:
            items.append((kind, _ident(layer or "part", used), d))
        if notch:       # the rest of a hole drawn across its part's edge: cut on the sheet
            items.append(("cut", _ident(f"{layer or 'sheet'}_cuts", used),
                          Drawing(unit=d.unit, paths=notch, paths_cut=True)))
            edge = [p for p in notch if p.source == EDGE_ACROSS]
            n, e = len(notch) - len(edge), len(edge)
            ln = sum(_length(p.segments) for p in edge)
            also = (f", and {e} piece{'s' if e != 1 else ''} of the part's edge drawn across "
                    f"the notch ({ln:.6g} mm)") if e else ""
            notes.append(Note("W0130", f"{n} piece{'s' if n != 1 else ''} of hole"
                                       f"{'s' if n != 1 else ''} of `{source}` on a cut role "
                                       f"drawn across {'their' if n != 1 else 'its'} part's "
                                       f"edge {'lie' if n != 1 else 'lies'} outside the part "
                                       f"({sum(_length(p.segments) for p in notch) - ln:.6g} "
                                       f"mm){also}: the part keeps the "
                                       f"notch, and {'they are' if n + e != 1 else 'it is'} "
                                       f"written as the sheet-level cut `{items[-1][1]}` (the "
                                       f"laser cuts along {'them' if n + e != 1 else 'it'})"))
        if inner:       # the pieces of holes drawn overlapping inside another: on the sheet
            if notch:                   # with the outer rests, in their sheet-level cut
                items[-1][2].paths = notch + inner
            else:
                items.append(("cut", _ident(f"{layer or 'sheet'}_cuts", used),
                              Drawing(unit=d.unit, paths=inner, paths_cut=True)))
            _say_inner(notes, source, inner, items[-1][1])
    return items


def _say_inner(notes: list, source: str, inner: list, name: str) -> None:
    """The ``W0130`` of the pieces ``inner`` of holes drawn overlapping that lie inside
    another hole of their part (:func:`~.hole_cuts.inner_rests`), written as the sheet-level
    cut ``name``."""
    n, s = len(inner), "s" if len(inner) != 1 else ""
    notes.append(Note("W0130", f"{n} piece{s} of holes of `{source}` on a cut role drawn "
                               f"overlapping {'lie' if n != 1 else 'lies'} inside another "
                               f"hole of {'their' if n != 1 else 'its'} part "
                               f"({sum(_length(p.segments) for p in inner):.6g} mm): the part "
                               f"keeps the one opening, and {'they are' if n != 1 else 'it is'}"
                               f" written as the sheet-level cut `{name}` (the laser cuts "
                               f"along {'them' if n != 1 else 'it'})"))


def _outside_remainders(d: Drawing, inside: list, deadline=None) -> list[Path]:
    """The pieces of ``d``'s holes that lie outside the loop they are holes of, and the
    pieces of that loop's edge inside them: a hole drawn across its part's edge (Boxes.py's
    WallChiselHolder slots) is the part's notch, and the rest of its loop, in no part, is
    still asked to be cut, as is the part's edge drawn across the notch.  Each hole outline
    (a loop inside an odd number of others) that has sampled points outside its owner is
    cut exactly (:func:`~.hole_cuts.cut_at_crossings`) at the points where it crosses the owner's
    edge, and the owner's edge where it crosses the hole; the runs of the hole's pieces
    whose middles lie outside the owner, then of the owner's pieces whose middles lie inside
    the hole, are returned as open paths (mm), in their loop's order, but for those no
    longer than :data:`~.model.GAP_NOTE` (a burn-correction overlap).  Whole circles are
    left as they are.  ``inside``: :func:`_containers` of :func:`_loops_of`."""
    import numpy as np

    from ..model import GAP_NOTE
    loops = _loops_of(d)
    if len(loops) < 2:
        return []
    depth = [len(c) for c in inside]
    polygon: dict = {}              # an owner's sampled polygon, made once for all its holes
    out: list[Path] = []
    for i, segs in enumerate(loops[:len(d.outlines)]):
        if depth[i] % 2 == 0:
            continue
        owner = [j for j in inside[i] if depth[j] == depth[i] - 1]
        if not owner:
            continue
        if deadline is not None:
            deadline.check("finding the holes that cross their part's edge")
        own = loops[owner[0]]
        if owner[0] not in polygon:
            polygon[owner[0]] = np.asarray(Loop(list(own)).points(), dtype=float)
        P = polygon[owner[0]]
        H = np.asarray(Loop(list(segs)).points(), dtype=float)
        X, Y = P[:, 0], P[:, 1]
        X2, Y2 = np.roll(X, -1), np.roll(Y, -1)
        lo, hi = H.min(axis=0), H.max(axis=0)
        if not np.any((np.maximum(X, X2) >= lo[0]) & (np.minimum(X, X2) <= hi[0]) &
                      (np.maximum(Y, Y2) >= lo[1]) & (np.minimum(Y, Y2) <= hi[1])):
            continue            # no edge of the owner near it: inside, as its probe is
        if _inside_many(H[:, 0], H[:, 1], P).all():
            continue                                   # every sample inside: a plain hole
        pieces, _ = cut_at_crossings(segs, own)
        runs = [(r, "the part of a hole outside its part")
                for r in runs_of(pieces, [not _inside(_probe([p]), P) for p in pieces])]
        if not runs:
            continue
        # the owner's edge across the notch (split where its segments meet the hole's box)
        edge, near = cut_at_crossings(own, segs, (lo[0], lo[1], hi[0], hi[1]))
        runs += [(r, EDGE_ACROSS)
                 for r in runs_of(edge, [n and _inside(_probe([p]), H)
                                       for p, n in zip(edge, near)])]
        # a run within the gap a laser closes anyway (Boxes.py's 0.1 mm burn-correction
        # overlaps, Lamp's and SmallPartsTray2's) is no cut of its own
        out += [Path(r, why) for r, why in runs if _length(r) > GAP_NOTE]
    return out
