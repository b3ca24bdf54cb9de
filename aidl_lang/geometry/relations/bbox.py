"""Deferred bounding-box expressions (paper, appendix "Solver Details", *Deferred expressions*).

``s.bb.left`` evaluates to a :class:`BBTerm`; it is expanded into ``min``/``max`` over the
extreme points of the target's geometry only when the constraint is compiled, right before
solving, once the whole tree is known.  A structure's box covers its own geometry and all its
descendants' (construction geometry and a cut's ``overrun`` excluded), except descendants
whose own box appears in the same constraint: ``self.bb.top == self.lid.bb.top`` aligns the
lid with the rest of the body.
"""
from __future__ import annotations

import math

from ..core.expr import Expr, Lin, Nl, evaluate, func, rebuild, var
from ..core.model import Geometry, Structure

SIDES = ("left", "right", "bottom", "top")


class BBTerm(Expr):
    """One side (left/right/bottom/top) of a target's box, in the frame of ``frame``."""

    __slots__ = ("target", "side", "frame")

    def __init__(self, target, side: str, frame: Structure):
        self.target = target
        self.side = side
        self.frame = frame

    def __repr__(self):
        return f"bb({getattr(self.target, 'name', '?')}.{self.side})"

    def value(self, x) -> float:
        """This side's value at parameter values ``x`` (mm): what :func:`.expr.evaluate`
        gives for it (a pattern's copy origin about a box's centre, issue 111)."""
        return evaluate(side_expr(self.target, self.side, self.frame, x, set()), x)


def contains_bbox(e) -> bool:
    """True if a :class:`BBTerm` occurs in ``e`` (walked without recursion)."""
    t = type(e)
    if t is Lin:                  # the common case: an affine expression has no box terms
        return False
    if t is BBTerm:
        return True
    if t is not Nl:
        return False
    todo = [e]                    # nodes whose arguments are still to look at
    pop, append = todo.pop, todo.append
    while todo:
        for a in pop().args:
            t = type(a)
            if t is BBTerm:
                return True
            if t is Nl:
                append(a)
    return False


def defer_boxes(c) -> None:
    """Constraint ``c``'s equations deferred as a box constraint's are (expanded when the
    whole tree is known) when one reads a bounding box (``Circle(center=hull.center)``,
    ``r.bb.center``; a pattern's copies about `box.bottom.bb.center`), not compiled with a
    box side in them (each was an internal error, "cannot compile BBTerm into a residual")."""
    if c.deferred is None and any(type(e.expr) is not Lin and contains_bbox(e.expr)
                                  for e in c.equations):
        c.deferred, c.equations = c.equations, []


def reach(vals, least: int = 2) -> list | None:
    """The parameters each of ``vals`` (a call's arguments, or an equation's two sides)
    reads, in the order given, as frozensets of indices into the model's parameter vector:
    a point's coordinates, a shape's points and sizes (its parts' too), a shape's box's
    (``body.bb.center``), structures' frames as their expressions hold them; a structure
    named or boxed reads nothing here (``Constraint.args`` says which structures).  None
    when fewer than ``least`` arguments read anything (one shape, sizes only).  Who moves
    between the shapes of one structure is read off it (``Constraint.reach``)."""
    out = []
    for v in vals:
        got: set = set()
        _reach_into(v, got)
        out.append(frozenset(got))
    return out if sum(1 for r in out if r) >= least else None


def _reach_into(v, out: set) -> None:
    from ..core.values import PV, BBoxRef, GeomRef, Q
    todo = [v]
    while todo:
        v = todo.pop()
        t = type(v)
        if t is GeomRef:
            _geom_params(v.geom, out)
        elif t is PV:
            todo += (v.x, v.y)
        elif isinstance(v, Q):
            todo.append(v.expr)
        elif t is Lin:
            out.update(v.terms)
        elif t is Nl:
            todo += v.args
        elif t is BBTerm or t is BBoxRef:
            if isinstance(v.target, Geometry):
                _geom_params(v.target, out)
        elif isinstance(v, (list, tuple)):
            todo += v


def _geom_params(g: Geometry, out: set) -> None:
    """Add the parameters of ``g`` (its points, sizes and parts') to ``out``."""
    todo = [g]
    while todo:
        g = todo.pop()
        for p in g.points.values():
            out.add(p.ix)
            out.add(p.iy)
        for sc in g.scalars.values():
            out.add(sc.index)
        for q in g.parts.values():
            if isinstance(q, Geometry):
                todo.append(q)
            elif hasattr(q, "ix"):                   # a point among the parts
                out.add(q.ix)
                out.add(q.iy)


def collect(e, out: list) -> list:
    if isinstance(e, BBTerm):
        out.append(e)
    elif isinstance(e, Nl):
        for a in e.args:
            collect(a, out)
    return out


def expand(e, x, exclude: set, cache: dict | None = None, boxes: dict | None = None):
    """Replace every BBTerm in ``e`` by its min/max expression (at parameter values ``x``).

    ``cache`` is passed on to :func:`side_expr`; ``boxes``, if given, records each box used as
    ``(id(target), id(frame)) -> [target, frame, axes]`` (for the solver's non-inversion rows).
    """
    if isinstance(e, BBTerm):
        if boxes is not None:
            ent = boxes.setdefault((id(e.target), id(e.frame)), [e.target, e.frame, set()])
            ent[2].add("x" if e.side in ("left", "right") else "y")
        return side_expr(e.target, e.side, e.frame, x, exclude, cache)
    if isinstance(e, Nl):
        return rebuild(e.op, tuple(expand(a, x, exclude, cache, boxes) for a in e.args))
    return e


def exclusions(terms: list[BBTerm]) -> set:
    """Descendant structures to leave out of ancestors' boxes in one constraint."""
    structs = {t.target for t in terms if isinstance(t.target, Structure)}
    out = set()
    for s in structs:
        for other in structs:
            if other is not s and other.is_within(s):
                out.add(other)
    return out


def side_expr(target, side: str, frame: Structure, x, exclude: set,
              cache: dict | None = None) -> Expr:
    """``min``/``max`` over the target's extreme coordinates, in ``frame``.  ``cache`` (a dict
    kept for one build of the rows) shares candidate lists and results between constraints."""
    if cache is not None:
        key = (id(target), side, id(frame), frozenset(map(id, exclude)))
        hit = cache.get(key)
        if hit is None:
            hit = cache[key] = _side_expr(target, side, frame, x, exclude, cache)
        return hit
    return _side_expr(target, side, frame, x, exclude, None)


def _side_expr(target, side, frame, x, exclude, cache) -> Expr:
    xs, ys = candidates(target, frame, x, exclude, cache)
    if side in ("left", "right"):
        cands = xs
    else:
        cands = ys
    if not cands:
        ox, oy = (target if isinstance(target, Structure) else target.owner).frame_offset(frame)
        return ox if side in ("left", "right") else oy
    if len(cands) == 1:
        return cands[0]
    op = "min" if side in ("left", "bottom") else "max"
    if all(type(c) is Lin and c.terms for c in cands):
        return Nl(op, tuple(cands))      # what func gives (nothing to fold), without lifting
    return func(op, *cands)


def candidates(target, frame: Structure, x, exclude: set,
               cache: dict | None = None) -> tuple[list, list]:
    if cache is not None:
        key = ("cand", id(target), id(frame), frozenset(map(id, exclude)))
        hit = cache.get(key)
        if hit is None:
            hit = cache[key] = _candidates(target, frame, x, exclude,
                                           cache.setdefault(("offsets",), {}))
        return hit
    return _candidates(target, frame, x, exclude, {})


def _candidates(target, frame, x, exclude: set, offs: dict) -> tuple[list, list]:
    xs: list = []
    ys: list = []
    if isinstance(target, Structure):
        # the original of a structure changed in place (`plaque_original`, its shapes made
        # construction by Scale, Translate, Flip) keeps its own box: its drawn shapes count
        # in it, and in nothing around it
        # (a shape drawn with `overrun=true`, a cut's run past the part's edge, counts in no
        # structure's box: aligning a slot to an edge gives the depth asked, issue 111)
        kept = target.__dict__.get("replaced", False)
        for s in _subtree(target, exclude, top=target):
            for g in s.geometry:
                if (not g.construction or kept and g.__dict__.get("replaced", False)) \
                        and not g.data.get("overrun"):
                    _geom_candidates(g, frame, x, xs, ys, offs)
    else:
        _geom_candidates(target, frame, x, xs, ys, offs)
    return xs, ys


def _subtree(s: Structure, exclude: set, top: Structure):
    if s in exclude and s is not top:
        return
    yield s
    for c in s.children.values():
        yield from _subtree(c, exclude, top)


def _in_frame(p, frame, offs: dict) -> tuple[Lin, Lin]:
    """``p.in_frame(frame)`` (the same terms in the same order), with the owner's frame
    offset looked up in ``offs`` instead of walked up the tree for every point."""
    key = (id(p.owner), id(frame))
    o = offs.get(key)
    if o is None:
        ox, oy = p.owner.frame_offset(frame)
        o = offs[key] = (ox.terms, oy.terms)
    tx, ty = dict(o[0]), dict(o[1])
    tx[p.ix] = tx.get(p.ix, 0.0) + 1.0
    ty[p.iy] = ty.get(p.iy, 0.0) + 1.0
    return Lin(tx), Lin(ty)


def _geom_candidates(g: Geometry, frame, x, xs: list, ys: list, offs: dict) -> None:
    k = g.kind
    P = {n: _in_frame(p, frame, offs) for n, p in g.points.items()}
    if k == "Circle":
        cx, cy = P["center"]
        r = var(g.scalars["radius"].index)
        xs += [cx - r, cx + r]
        ys += [cy - r, cy + r]
        return
    if k == "Slot":
        r = var(g.scalars["radius"].index)
        for n in ("start", "end"):
            px, py = P[n]
            xs += [px - r, px + r]
            ys += [py - r, py + r]
        return
    if k in _ARCS:
        _arc_candidates(g, P, x, xs, ys)
        return
    if k in DERIVED_KINDS:
        _derived_candidates(g, frame, x, xs, ys, offs)
        return
    if k == "Ellipse":
        cx, cy = P["center"]
        rx, ry = var(g.scalars["rx"].index), var(g.scalars["ry"].index)
        rot = held_rotation(g, x)
        cs, sn = math.cos(rot), math.sin(rot)
        ex = func("sqrt", rx * rx * (cs * cs) + ry * ry * (sn * sn))
        ey = func("sqrt", rx * rx * (sn * sn) + ry * ry * (cs * cs))
        xs += [cx - ex, cx + ex]
        ys += [cy - ey, cy + ey]
        return
    if k in ("Spline", "Bezier"):
        _spline_candidates(g, P, x, xs, ys)
        return
    if k == "Drawing2D":
        from ..shapes.drawing2d import local_box
        ox, oy = P["origin"]
        bx = g.data.get("box")
        turn = held_turn(g, x) if g.data.get("mirror_lines") else 0.0
        if abs(turn) > 1e-15:           # a mirrored copy about a line the solve turned
            from ..shapes.drawing2d import copied
            bx = local_box(*copied(g.data["loops"], g.data["paths"], turn, None))
        elif bx is None:
            bx = g.data["box"] = local_box(g.data["loops"], g.data["paths"])
        xs += [ox + bx[0], ox + bx[2]]
        ys += [oy + bx[1], oy + bx[3]]
        return
    if k == "Star" and g.data.get("tip"):
        # rounded tips: each tip's fillet arc (its extremes that its sweep passes, its
        # ends), the notches as points; the arc's center on the line from the star's center
        # to the sharp tip, at the values x for its direction (a rigid star)
        dc, half = g.data["tip"]
        ro, rt = g.data["dims"]["outer_radius"], g.data["dims"]["tip_radius"]
        cx, cy = P["center"]
        c = g.points["center"]
        for i, name in enumerate(g.data["order"]):
            px, py = P[name]
            if i % 2:
                xs.append(px)
                ys.append(py)
                continue
            p = g.points[name]
            ang = math.atan2(x[p.iy] - x[c.iy], x[p.ix] - x[c.ix])
            fx, fy = cx + (px - cx) * (dc / ro), cy + (py - cy) * (dc / ro)
            for e in (ang - half, ang + half):
                xs.append(fx + rt * math.cos(e))
                ys.append(fy + rt * math.sin(e))
            _quadrants(fx, fy, rt, ang - half, 2 * half, xs, ys)
        return
    if k == "RoundedRectangle" and _turned_rounded(g, x):
        _rounded_candidates(g, P, xs, ys)
        return
    if k == "Text" and g.data.get("stencil") and g.data.get("along") is None:
        # the letters' openings: strokes swept by the weight, less the bridges (the top of
        # an O is bridged): the drawn outline's box, moving with the position point
        box = drawn_box(g, x)
        if box is not None:
            p = g.points["position"]
            ox, oy = g.owner.frame_offset(None)
            px0 = float(x[p.ix]) + float(evaluate(ox, x))
            py0 = float(x[p.iy]) + float(evaluate(oy, x))
            px, py = P["position"]
            xs += [px + (box[0] - px0), px + (box[1] - px0)]
            ys += [py + (box[2] - py0), py + (box[3] - py0)]
            return
    if k == "Text":
        px, py = P["position"]
        x0, x1, y0, y1 = g.data.get("extent", (0.0, 0.0, 0.0, 0.0))
        xs += [px + x0, px + x1]
        ys += [py + y0, py + y1]
        return
    for n, (px, py) in P.items():
        if n == "center":           # a shape's center point is never an extreme point
            continue
        xs.append(px)
        ys.append(py)


RECT_CORNERS = ("bottom_left", "bottom_right", "top_right", "top_left")   # points_of's order


def _radii(g: Geometry) -> list:
    """A rounded rectangle's corner radii in :data:`RECT_CORNERS`' order (mm)."""
    rr = g.data.get("corner_radii")
    return [float(r) for r in rr] if rr else [float(g.data.get("corner_radius", 0.0))] * 4


def _turned_rounded(g: Geometry, x) -> bool:
    """Whether rounded rectangle ``g`` has a rounded corner and sides not along the axes at
    the values ``x`` (a copy turned by a pattern or a mirror): its sharp corners are then
    outside its drawn outline, and its box is its corner arcs'."""
    if not any(r > 0 for r in _radii(g)):
        return False
    rot = g.data.get("rotation")
    if isinstance(rot, (int, float)):   # held (its own, a pattern's or a mirror's turn): the
        k = rot / (math.pi / 2)         # same expressions from any start (a warm re-solve
        return abs(k - round(k)) > 1e-9     # from moved guesses matches a fresh one)
    a, b = g.points["bottom_left"], g.points["bottom_right"]
    dx, dy = float(x[b.ix] - x[a.ix]), float(x[b.iy] - x[a.iy])
    return abs(dx) > 1e-12 * abs(dy) and abs(dy) > 1e-12 * abs(dx)


def _rounded_candidates(g: Geometry, P: dict, xs: list, ys: list) -> None:
    """The extremes of a turned rounded rectangle: each rounded corner's arc center (the
    corner moved ``r`` along both of its sides, an expression of the corners) grown by
    ``r`` (the outline is the convex hull of its corner discs); a sharp corner itself."""
    from ..core.expr import hypot
    C = [P[n] for n in RECT_CORNERS]
    for k, r in enumerate(_radii(g)):
        px, py = C[k]
        if r <= 0:
            xs.append(px)
            ys.append(py)
            continue
        cx, cy = px, py
        for qx, qy in (C[k - 1], C[(k + 1) % 4]):
            L = hypot(qx - px, qy - py)
            cx = cx + (qx - px) * r / L
            cy = cy + (qy - py) * r / L
        xs += [cx - r, cx + r]
        ys += [cy - r, cy + r]


_ARCS = ("ArcSlot", "Sector", "Arc", "EllipticArc")
DERIVED_KINDS = ("Offset", "Shell", "Hull", "Stroke", "Intersect")

# (shape, parameter values) -> (left, right, bottom, top) of the exact outline the booleans
# draw for the shape, in the root frame (None: it draws nothing there).  Set by
# aidl_lang.output.part.build.booleans (the booleans sit above geometry: the function is
# handed down, not imported); None until the output stage is imported.
DRAWN_BOX = None
_DRAWN: dict = {}           # (what a shape is drawn from, relative) -> its box: made already


def box_follows_sources(g: Geometry) -> bool:
    """Whether the box of derived shape ``g`` is its sources' boxes, grown by a distance,
    exactly: a ``Hull`` (its sources' boxes), an outward ``Offset`` or ``Shell`` with round
    joins (the Minkowski sum with a disc: the box grown by the distance), an inward
    ``Shell`` (its outer side is the source's outline), a ``Stroke`` with round caps (the
    path's box grown by half the width).  Every other one (an ``Inset``, a miter join, flat
    caps, an ``Intersect``) is boxed from its drawn outline (:func:`_derived_candidates`)."""
    k = g.kind
    if k == "Hull":
        return True
    if k == "Stroke":
        return g.data.get("cap", "round") == "round"
    if k == "Shell":
        return g.data["thickness"] < 0 or g.data.get("join", "round") == "round"
    if k == "Offset":
        return g.data["distance"] >= 0 and g.data.get("join", "round") == "round"
    return False


def _derived_candidates(g: Geometry, frame, x, xs: list, ys: list, offs: dict) -> None:
    """The extreme coordinates of a shape made from other shapes (:data:`DERIVED_KINDS`),
    each an expression of its sources' points, exactly its drawn outline's at the values
    ``x``.  Where the box follows the sources' (:func:`box_follows_sources`) it is their
    candidates grown by the distance (exact wherever the sources move).  Otherwise each side
    is the source candidate extreme on that side at ``x`` plus the constant that puts it on
    the drawn outline's side (:data:`DRAWN_BOX`): exact at ``x`` (an ``assert``, the values
    reported are read at the solution) and following the source's extreme point as the
    solve moves it, as a spline's extremes do (:func:`_spline_candidates`)."""
    srcs = g.data["sources"]
    if g.kind == "Intersect":           # inside every closed one: the first one's points
        srcs = [next(s for s in srcs if s.closed)] if g.closed else srcs
    sx: list = []
    sy: list = []
    for src in srcs:
        _geom_candidates(src, frame, x, sx, sy, offs)
    if box_follows_sources(g):
        d = g.data.get("distance", g.data.get("thickness", g.data.get("width", 0.0) / 2))
        if g.kind != "Hull" and d > 0:
            sx = [c - d for c in sx] + [c + d for c in sx]
            sy = [c - d for c in sy] + [c + d for c in sy]
        xs += sx
        ys += sy
        return
    box = drawn_box(g, x)
    if box is None or not sx or not sy:
        xs += sx                        # nothing drawn (E0406 says so): the sources' box
        ys += sy
        return
    rx: list = []
    ry: list = []
    for src in srcs:
        _geom_candidates(src, None, x, rx, ry, offs)
    for cands, root, (lo, hi) in ((sx, rx, box[:2]), (sy, ry, box[2:])):
        vals = [float(evaluate(c, x)) for c in root]
        i = min(range(len(vals)), key=vals.__getitem__)
        j = max(range(len(vals)), key=vals.__getitem__)
        out = xs if cands is sx else ys
        out += [cands[i] + (lo - vals[i]), cands[j] + (hi - vals[j])]


def boxed_by_drawing(g: Geometry) -> bool:
    """Whether shape ``g``'s box is read from its drawn outline (:func:`_derived_candidates`),
    itself or through a shape it is made from (a Hull of an Intersect)."""
    todo = [g]
    while todo:
        h = todo.pop()
        if h.kind in DERIVED_KINDS:
            if not box_follows_sources(h):
                return True
            todo += h.data["sources"]
    return False


def drawn_box_misses(model, x=None) -> list:
    """``(constraint, how far it misses)`` for each relation of ``model`` on a box read from
    a drawn outline (:func:`boxed_by_drawing`) that the values ``x`` (default: the model's)
    do not meet within 1e-9 mm: the solve took that box as its source's extreme point plus a
    constant, and moved the sources so that the drawn outline changed (an ``Intersect`` of
    shapes the solve moved apart, an ``Inset`` of a shape it stretched).  The solver solves
    again from there (:func:`aidl_lang.solver.solve`); what is left is W0405."""
    if not any(boxed_by_drawing(g) for g in model.all_geometry()):
        return []
    x = model.xs() if x is None else x
    memo: dict = {}

    def reads(t) -> bool:
        k = id(t)
        if k not in memo:
            if isinstance(t, Structure):
                memo[k] = any(boxed_by_drawing(g) for s in _subtree(t, set(), t)
                              for g in s.geometry if not g.construction)
            else:
                memo[k] = boxed_by_drawing(t)
        return memo[k]

    out = []
    for c in model.constraints:
        if not c.deferred or getattr(c, "released", False):
            continue
        terms = [t for eq in c.deferred for t in collect(eq.expr, [])]
        if not any(reads(t.target) for t in terms):
            continue
        excl = exclusions(terms)
        worst = 0.0
        for eq in c.deferred:
            v = float(evaluate(expand(eq.expr, x, excl), x))
            worst = max(worst, -v if eq.ineq else abs(v))
        if not worst <= 1e-9:
            out.append((c, worst))
    return out


def drawn_box(g: Geometry, x) -> tuple[float, float, float, float] | None:
    """(left, right, bottom, top) in mm, root frame, of the outline drawn for ``g`` at the
    values ``x`` (:data:`DRAWN_BOX`).  Kept by what it is drawn from: the kinds and held data
    of ``g`` and the shapes it is made from, their sizes and their points (relative to the
    first one, and where that one is), so a shape read again at the same values is drawn
    once."""
    if DRAWN_BOX is None:
        return None
    sig: list = []
    rel: list = []
    x0 = y0 = None
    todo = [g]
    while todo:
        h = todo.pop()
        sig.append((h.kind, _held(h.data), tuple(h.points), tuple(h.scalars)))
        for p in h.points.values():
            px, py = float(x[p.ix]), float(x[p.iy])
            s = p.owner
            while s is not None:
                px += float(x[s.fx])
                py += float(x[s.fy])
                s = s.parent
            if x0 is None:
                x0, y0 = px, py
            rel += (px - x0, py - y0)
        rel += [float(x[sc.index]) for sc in h.scalars.values()]
        todo += h.data.get("sources", ())
    if x0 is None:
        return DRAWN_BOX(g, x)
    # where it is, too: a box drawn elsewhere and moved differs from the one drawn here in
    # its last bits, and a solve would then depend on what the process drew before (a warm
    # re-solve of the telephone 0.47 mm from a fresh one, tests/test_resolve.py)
    key = (tuple(sig), tuple(rel), x0, y0)
    box = _DRAWN.get(key, _DRAWN)
    if box is _DRAWN:
        box = DRAWN_BOX(g, x)
        if len(_DRAWN) > 512:
            _DRAWN.clear()
        _DRAWN[key] = box
    return box


def _held(v, depth: int = 0):
    """The held data ``v`` (numbers, strings, lists and dicts of them) as a hashable value;
    shapes and other objects by their kind only (the shapes are walked by :func:`drawn_box`)."""
    if v is None or isinstance(v, (bool, int, float, str)):
        return v
    if depth > 4:
        return type(v).__name__
    if isinstance(v, dict):
        return tuple(sorted((str(k), _held(w, depth + 1)) for k, w in v.items()))
    if isinstance(v, (list, tuple)):
        return tuple(_held(w, depth + 1) for w in v)
    return getattr(v, "kind", type(v).__name__)


def _arc_candidates(g: Geometry, P: dict, x, xs: list, ys: list) -> None:
    """:func:`_geom_candidates` of the kinds with a sweep (:data:`_ARCS`): their ends and the
    extremes of x and y the sweep passes."""
    k = g.kind
    if k == "ArcSlot":
        # the end caps (half circles of width/2 around start and end) and the outer arc's
        # extremes that its sweep passes (held shape: angles and radii are numbers)
        h = g.data["dims"]["width"] / 2
        Ro = g.data["dims"]["outer_radius"]
        a1, sweep = g.data["angles"]
        for n in ("start", "end"):
            px, py = P[n]
            xs += [px - h, px + h]
            ys += [py - h, py + h]
        cx, cy = P["center"]
        _quadrants(cx, cy, Ro, a1, sweep, xs, ys)
        return
    if k == "Sector":
        # the radial lines' ends (the center of a pie slice) and the outer arc's extremes
        # that its sweep passes (a held shape: angles and radii are numbers)
        R = g.data["dims"]["radius"]
        sweep = g.data["angles"][1]
        c, m = g.points["center"], g.points["midpoint"]       # a copy's, turned or mirrored
        a1 = math.atan2(x[m.iy] - x[c.iy], x[m.ix] - x[c.ix]) - sweep / 2
        for n in ("start", "end", "inner_start", "inner_end") if "inner_start" in P else \
                ("start", "end", "center"):
            px, py = P[n]
            xs.append(px)
            ys.append(py)
        cx, cy = P["center"]
        _quadrants(cx, cy, R, a1, sweep, xs, ys)
        return
    if k == "Arc":
        cx, cy = P["center"]
        sx, sy = P["start"]
        ex, ey = P["end"]
        xs += [sx, ex]
        ys += [sy, ey]
        c = g.points["center"]
        s = g.points["start"]
        e = g.points["end"]
        a1 = math.atan2(x[s.iy] - x[c.iy], x[s.ix] - x[c.ix])
        a2 = math.atan2(x[e.iy] - x[c.iy], x[e.ix] - x[c.ix])
        sweep = (a2 - a1) % (2 * math.pi) or 2 * math.pi
        r = func("sqrt", (var(s.ix) - var(c.ix)) * (var(s.ix) - var(c.ix))
                 + (var(s.iy) - var(c.iy)) * (var(s.iy) - var(c.iy)))
        _quadrants(cx, cy, r, a1, sweep, xs, ys)
        return
    if k == "EllipticArc":
        # rigid: its ends and the extremes of x and y its sweep passes, each the center
        # plus its offset at the values (the arc of a copy, turned or mirrored, from its
        # own points)
        from ..shapes.curves import elliptic_arc
        pt = {n: (float(x[g.points[n].ix]), float(x[g.points[n].iy]))
              for n in ("center", "vertex", "co_vertex", "start", "midpoint", "end")}
        c = pt["center"]
        arc = elliptic_arc(c, math.dist(c, pt["vertex"]), math.dist(c, pt["co_vertex"]),
                           math.atan2(pt["vertex"][1] - c[1], pt["vertex"][0] - c[0]),
                           pt["start"], pt["midpoint"], pt["end"])
        cx, cy = P["center"]
        for n in ("start", "end"):
            px, py = P[n]
            xs.append(px)
            ys.append(py)
        x0, y0, x1, y1 = arc.box()
        xs += [cx + (x0 - c[0]), cx + (x1 - c[0])]
        ys += [cy + (y0 - c[1]), cy + (y1 - c[1])]
        return


def _quadrants(cx, cy, r, a1: float, sweep: float, xs: list, ys: list) -> None:
    """The extremes of x and y (at 0, 90, 180, 270 degrees) of the circle about ``(cx, cy)``
    of radius ``r`` that the sweep ``sweep`` from angle ``a1`` passes, added to ``xs``, ``ys``."""
    for ang, (dx, dy) in ((0.0, (1, 0)), (math.pi / 2, (0, 1)), (math.pi, (-1, 0)),
                          (1.5 * math.pi, (0, -1))):
        if (ang - a1) % (2 * math.pi) <= sweep:
            if dx:
                xs.append(cx + r * dx)
            else:
                ys.append(cy + r * dy)


def _spline_candidates(g: Geometry, P: dict, x, xs: list, ys: list) -> None:
    """A spline's extreme points: its points, and where a span's x (or y) turns, as the
    affine combination of the points that gives that point of the curve.  The weights are
    taken at the values ``x`` (the chord lengths and turning parameters there): exact for a
    rigid spline (literal points move together), a first-order model of a flexible one."""
    import numpy as np
    from ..shapes.spline import _steps, bez_extremes, interpolation_matrix
    names = g.data["order"]
    pts = [g.points[n] for n in names]
    V = np.array([(float(x[p.ix]), float(x[p.iy])) for p in pts])
    closed = g.data.get("closed", False)
    if g.kind == "Bezier":
        # the control points themselves: W picks them (closed: the last row is p0); the
        # curve passes through every third one only
        m = len(names)
        W = np.eye(m + 1 if closed else m, m)
        if closed:
            W[m, 0] = 1.0
        nspans = (W.shape[0] - 1) // 3
        for n in names[::3]:
            px, py = P[n]
            xs.append(px)
            ys.append(py)
    else:
        for n in names:
            px, py = P[n]
            xs.append(px)
            ys.append(py)
        h = _steps(V, closed)
        if len(V) < (3 if closed else 2) or not (h > 0).all():
            return
        W = interpolation_matrix(h, closed, g.data.get("corners", ()))
        nspans = len(h)
    C = W @ V
    for i in range(nspans):
        b = tuple(tuple(C[3 * i + k]) for k in range(4))
        for axis, ts in enumerate(bez_extremes(b)):
            for t in ts:
                s_ = 1.0 - t
                bern = np.array([s_ ** 3, 3 * s_ * s_ * t, 3 * s_ * t * t, t ** 3])
                w = bern @ W[3 * i:3 * i + 4]
                terms: dict = {}
                const = 0.0
                for wj, n in zip(w.tolist(), names):
                    e = P[n][axis]
                    for kk, vv in e.terms.items():
                        terms[kk] = terms.get(kk, 0.0) + wj * vv
                    const += wj * e.const
                (xs if axis == 0 else ys).append(Lin(terms, const))


def held_rotation(g: Geometry, x) -> float:
    """The held ``rotation`` (radians) of shape ``g`` at the values ``x``.  A mirrored copy of
    an Ellipse has only its center and this angle, so its rotation follows its mirror line
    as solved (``g.data["mirror"]``: the line's ends (points) and the angle mirrored),
    not the line's starting direction."""
    m = g.data.get("mirror")
    if m is None:
        return g.data.get("rotation", 0.0)
    a, b, r = m
    dx = float(evaluate(b.x, x)) - float(evaluate(a.x, x))
    dy = float(evaluate(b.y, x)) - float(evaluate(a.y, x))
    return 2 * math.atan2(dy, dx) - r


def held_turn(g: Geometry, x) -> float:
    """The angle (radians) by which a mirrored ``Drawing2D`` copy's curves, held mirrored
    about each mirror line as drawn, must still turn about its origin at the values ``x``:
    reflecting about a line at ``phi`` is reflecting about ``phi0`` then turning by
    ``2 (phi - phi0)``; a later mirror reverses an earlier turn (``g.data["mirror_lines"]``:
    ``(line start, line end, phi0, sense)``)."""
    tot = 0.0
    for a, b, phi0, sense in g.data.get("mirror_lines", ()):
        dx = float(evaluate(b.x, x)) - float(evaluate(a.x, x))
        dy = float(evaluate(b.y, x)) - float(evaluate(a.y, x))
        if dx == 0.0 and dy == 0.0:
            continue
        tot += sense * 2 * (math.atan2(dy, dx) - phi0)
    return math.remainder(tot, 2 * math.pi)


def numeric_box(target, frame, x, exclude=frozenset()) -> tuple[float, float, float, float] | None:
    """(left, right, bottom, top) at values ``x``; None if the target holds no geometry."""
    xs, ys = candidates(target, frame, x, set(exclude))
    if not xs:
        return None
    vx = [evaluate(e, x) for e in xs]
    vy = [evaluate(e, x) for e in ys]
    return min(vx), max(vx), min(vy), max(vy)


__all__ = ["BBTerm", "SIDES", "contains_bbox", "collect", "expand", "exclusions",
           "side_expr", "numeric_box", "held_rotation", "held_turn"]
