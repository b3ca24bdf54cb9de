"""Operations: copies of geometry or structures (mirror, linear and circular patterns) and
corner finishing of a solid's outline (fillets, chamfers).

Copies are real model geometry: every point of a copy is a new unknown tied to the transformed
original point by two equations, every dimension (radius, width, ...) by one, so a copy follows
its original through the solve, belongs to bounding boxes and can be constrained further.
A copy of a structure is a new sibling of the original (a child of the original's parent, which
is the structure where the operation is written or one inside it), with the same kind, children
and member names; its frame is held on its parent's.  A copy of geometry belongs to the
original's structure.  ``CircularPattern`` turns counter-clockwise: ``angle`` is the span from
the first instance to the last (a full turn spaces ``count`` instances 360/count apart), ``step``
the angle between neighbours.  The original must
lie in that structure's subtree (the validity rule for constraints).  The transform's line,
center and step may be solved values; rotations (pattern angles) are known before solving.

``Fillet(radius)`` and ``Chamfer(distance)`` act on the finished exact outline of the structure
they are written in, after its booleans (:func:`finish`, called by the renderer), on every
loop of it (outer outlines and holes).  A corner is a join where the outline's direction turns
by more than :data:`CORNER_TURN` (0.06 degrees; tangent joins are not corners).  A fillet
replaces every corner, convex or concave, by an arc of ``radius`` tangent to both segments
(lines or arcs: its center is where the two segments' offsets by ``radius`` cross); a chamfer
cuts every convex corner with two legs of ``distance`` along its segments.  Where a segment is
too short for both of its corners, each takes at most half of it (the fillet radius shrinks to
fit).  A size of 0 rounds (cuts) nothing: the outline stays as it is, so a param can switch
the rounding off.  Corners chosen with ``at`` (:func:`_chosen`): two edges name the corner where they meet
(at their ends, where they cross, or where one ends on the other), found after the solve; a
chamfer there cuts an inside corner too.  The rounding itself, and what is said when a chosen
corner is none (E0408) or is rounded smaller than asked (W0406), is :mod:`.corners`.
"""
from __future__ import annotations

import math

from ...base.diagnostics import EvalError
from ...base.limits import DEFAULT_BUDGET
from ..core.expr import Lin, _lin, combine, var
from .corners import Chosen, FinishCall
from .errors import OperationError
from ..core.model import Constraint, Equation, Geometry, Point, Structure, equation
from .scaling import ScaleRefused, scaled_data
from ..core.values import PV, GeomRef, Q, StructRef, type_name


class Copies(list):
    """The list an operation returns: the original first, then its copies."""


# ------------------------------------------------------------------ transforms
def _translate(dx, dy):
    return lambda x, y: (x + dx, y + dy), 0.0, False


def _rotate(c: PV, th: float, ctx=None):
    """The turn by ``th`` about ``c``: ``(map, th, False)``.  With ``ctx`` (the interpreter),
    one :class:`_Turn` per center and angle for its whole run (it is never changed once made):
    a planetary preview's patterns turn 2,900 copies by 121 distinct turns (issue 113).  The
    center is kept with it, so the ids of its coordinates' expressions stay its own."""
    cache = getattr(ctx, "__dict__", None)
    if cache is None or type(c.x) is not Lin or type(c.y) is not Lin:
        return _Turn(c, th), th, False
    turns = cache.setdefault("_turns", {})
    key = (id(c.x), id(c.y), th)
    got = turns.get(key)
    if got is None or got[0].x is not c.x or got[0].y is not c.y:
        got = turns[key] = (c, _Turn(c, th))
    return got[1], th, False


class _Turn:
    """The turn by ``th`` (radians, counter-clockwise) about ``c`` (a :class:`PV`): called on a
    point's coordinates ``(x, y)`` (expressions), the image ``c + R (p - c)``, written as
    ``R p + (I - R) c``, one affine combination per coordinate (:func:`.expr.combine`).

    :meth:`copy_point` makes a copied point's two rows directly, without the image's
    expressions, when the point has no frame offset and no unknown of the center is one of
    the point's (a patterned gear copies some 3,300 points a move)."""

    __slots__ = ("cs", "sn", "cx", "cy", "kx", "ky", "rx", "ry")

    def __init__(self, c: PV, th: float):
        cs, sn = math.cos(th), math.sin(th)
        self.cs, self.sn, self.cx, self.cy = cs, sn, c.x, c.y
        self.kx = self.ky = self.rx = self.ry = None
        cx, cy = c.x, c.y
        if type(cx) is Lin and type(cy) is Lin and not cx.terms.keys() & cy.terms.keys():
            # (I - R) c is the same for every point: made once, with the same floating-point
            # operations per term (no unknown is in both of c's coordinates)
            kx = self.kx = combine(((1.0 - cs, cx), (sn, cy)))
            ky = self.ky = combine(((-sn, cx), (1.0 - cs, cy)))
            self.rx = _turn_row(cs, -sn, kx)
            self.ry = _turn_row(sn, cs, ky)

    def __call__(self, x, y):
        cs, sn, kx, ky = self.cs, self.sn, self.kx, self.ky
        if kx is not None:
            return (combine(((cs, x), (-sn, y), (1.0, kx))),
                    combine(((sn, x), (cs, y), (1.0, ky))))
        cx, cy = self.cx, self.cy
        return (combine(((cs, x), (-sn, y), (1.0 - cs, cx), (sn, cy))),
                combine(((sn, x), (cs, y), (-sn, cx), (1.0 - cs, cy))))

    def copy_point(self, model, p: Point, dest: Structure, eqs: list) -> Point | None:
        """The copy of ``p`` (a point of the frame, copied into it): a new point of ``dest``
        started at the image's value, and its two rows ``q.x - X``, ``q.y - Y`` appended to
        ``eqs``: the very Lins :meth:`__call__` and :func:`.expr.sub` make (terms in the same
        order, floats by bits; ``tests/test_interp_fast.py``).  None when the center's terms
        meet the point's unknowns (or share one): the general path then."""
        rx = self.rx
        if rx is None:
            return None
        ix, iy = p.ix, p.iy
        ax, bx, kxr, vx, cx0, rcx = rx
        ay, by, kyr, vy, cy0, rcy = self.ry
        if kxr or kyr:
            if any(i == ix or i == iy for i, _v, _w in kxr + kyr):
                return None
        xs = model.x
        px, py = xs[ix], xs[iy]
        # the image's value, summed as value_of sums the image's terms: its constant first
        X = cx0 + vx[0] * px + vx[1] * py
        Y = cy0 + vy[0] * px + vy[1] * py
        for i, w, _v in kxr:
            X += w * xs[i]
        for i, w, _v in kyr:
            Y += w * xs[i]
        qx, qy = model.new_pair(X, Y, True, dest, p.label)
        tx = {qx: 1.0, ix: ax, iy: bx}
        for i, _w, v in kxr:
            tx[i] = v
        ty = {qy: 1.0, ix: ay, iy: by}
        for i, _w, v in kyr:
            ty[i] = v
        eqs.append(equation(_lin(tx, rcx)))
        eqs.append(equation(_lin(ty, rcy)))
        return Point(qx, qy, dest, None, p.label)


def _turn_row(a: float, b: float, k: Lin) -> tuple:
    """What a turned point's coordinate ``combine(((a, x), (b, y), (1.0, k)))`` (``x``, ``y``
    a point's own unknowns ``{i: 1.0}``, ``k`` the center's part) and its row ``q - X``
    (:func:`.expr.sub`) are made of, for :meth:`_Turn.copy_point`: ``(row's coefficient of
    x, of y, [(unknown of k, image's coefficient, row's coefficient)], (image's
    coefficients of x and y), image's constant, row's constant)``: each float the very
    operation those functions do."""
    ix_coef = 0.0 + a * 1.0                 # combine: get(i, 0.0) + k * v
    iy_coef = 0.0 + b * 1.0
    const = 0.0 + a * 0.0                   # combine: s = c; s += k * e.const
    const += b * 0.0
    const += 1.0 * k.const
    ks = [(i, 0.0 + 1.0 * v) for i, v in k.terms.items()]
    return (0.0 + ix_coef * -1.0, 0.0 + iy_coef * -1.0,     # sub: get(k, 0.0) + v * -1.0
            [(i, w, 0.0 + w * -1.0) for i, w in ks], (ix_coef, iy_coef), const,
            0.0 + const * -1.0)


def _reflect(a: PV, b: PV):
    dx, dy = b.x - a.x, b.y - a.y
    dd = dx * dx + dy * dy

    def f(x, y):
        t = ((x - a.x) * dx + (y - a.y) * dy) / dd
        return (a.x + dx * t) * 2.0 - x, (a.y + dy * t) * 2.0 - y
    return f, None, True


# ------------------------------------------------------------------ cloning
class _Cloner:
    def __init__(self, ctx, frame: Structure, xf, rot, flip: bool, line_angle: float = 0.0,
                 line=None):
        self.ctx, self.frame, self.xf, self.flip = ctx, frame, xf, flip
        self.line = line                # a mirror's line: its ends (PV), in `frame`
        self.rot = rot
        self.turn = xf if type(xf) is _Turn else None      # its rows made directly
        self.line_angle = line_angle
        self.points: dict = {}
        self.geoms: dict = {}
        self.structs: dict = {}
        self.eqs: list = []
        self.scale = 1.0                # Scaled, Scale: sizes times this (transforms.py)

    def point(self, p: Point, dest: Structure) -> Point:
        q = self.points.get(p)
        if q is not None:
            return q
        if self.turn is not None and p.owner is self.frame and dest is self.frame:
            q = self.turn.copy_point(self.ctx.model, p, dest, self.eqs)
            if q is not None:
                self.points[p] = q
                return q
        X, Y = self.xf(*p.in_frame(self.frame))
        value_of = self.ctx.value_of
        ix, iy = self.ctx.model.new_pair(value_of(X), value_of(Y), True, dest, p.label)
        q = Point(ix, iy, dest, None, p.label)
        qx, qy = q.in_frame(self.frame)
        self.eqs += [equation(qx - X), equation(qy - Y)]
        self.points[p] = q
        return q

    def geom(self, g: Geometry, dest: Structure) -> Geometry:
        if g in self.geoms:
            return self.geoms[g]
        if g.kind == "Text" and self.flip:
            # its copy was the word turned 180 degrees, upside down, not a mirror image (run
            # ca's cookie stamp: `Flip(label, about=axis)` of a drawing with "MERCI")
            raise OperationError(
                f"a mirror image cannot hold Text: `{g.label}` (\"{g.data.get('text', '')}\") "
                "would be turned upside down, not mirrored; mirror the other shapes and write "
                "the copy's Text where it belongs (mirrored lettering is not made)")
        self.ctx.n_geometry += 1
        if hasattr(self.ctx, "count_object"):       # the interpreter's budget
            self.ctx.count_object(self.ctx.cur_span)
        most = getattr(self.ctx, "budget", DEFAULT_BUDGET).geometry
        if self.ctx.n_geometry > most:
            raise EvalError("E0303", f"more than {most} geometry objects", self.ctx.cur_span,
                            hint="use fewer or larger repetitions, or raise `--budget`")
        new = Geometry(g.kind, dest, g.span, construction=g.construction, closed=g.closed)
        new.copied = True          # made by Mirrored or a pattern: it follows its original
        if dest is not g.owner:
            # a copy of a structure: its shapes keep their names (`holes[1].c`, read by
            # `aidl check --values`); a copy of a shape next to it is named by its assignment
            new.name = g.name
        self.geoms[g] = new
        new.points = {n: self.point(p, dest) for n, p in g.points.items()}
        if g.kind in ("Arc", "ArcSlot") and self.flip:
            # a mirror turns counter-clockwise into clockwise: the copy runs counter-clockwise
            # from the image of the original's end to the image of its start
            new.points["start"], new.points["end"] = new.points["end"], new.points["start"]
        m = self.ctx.model
        k = self.scale
        for n, s in g.scalars.items():
            f = k if s.dim == "length" else 1.0        # a length scales, an angle does not
            i = m.new_param(f * m.x[s.index], True, dest, s.label)
            self.eqs.append(Equation(var(i) - f * var(s.index)) if f != 1.0 else
                            Equation(var(i) - var(s.index)))
            new.scalars[n] = type(s)(i, dest, s.dim, s.label)
        new.data = dict(g.data)
        if k != 1.0:
            try:
                scaled_data(new, k)
            except ScaleRefused as ex:
                raise OperationError(str(ex)) from None
        if g.kind == "Drawing2D" and (self.flip or self.rot):
            # its curves are held in its own frame: the copy's are the mirrored or turned ones
            from ..shapes.drawing2d import copied
            new.data["loops"], new.data["paths"] = copied(
                g.data["loops"], g.data["paths"], self.rot or 0.0,
                self.line_angle if self.flip else None)
            new.data.pop("box", None)
            # mirrored about the line as drawn; if the solve turns the line, the curves turn
            # by twice as much (bbox.held_turn): each mirror's line, angle as drawn and sense
            # (a later mirror reverses the earlier ones' turns)
            held = [(a, b, phi, -sense if self.flip else sense)
                    for a, b, phi, sense in g.data.get("mirror_lines", ())]
            if self.flip and self.line is not None:
                held.append((self.line[0], self.line[1], self.line_angle, 1.0))
            if held:
                new.data["mirror_lines"] = held
        if "rotation" in g.data:
            r = g.data["rotation"]
            new.data["rotation"] = 2 * self.line_angle - r if self.flip else r + (self.rot or 0.0)
            if g.kind == "Text" and g.data.get("along") is None and "extent" in g.data \
                    and new.data["rotation"] != r:
                # the copy's strokes are drawn at its own rotation: its box and center too
                # (issue 109: a turned copy's box was the original's, 11 mm off)
                from ..shapes.text import text_extent
                d = new.data
                new.data["extent"] = text_extent(d["text"], d["size"], d["anchor"],
                                                 d.get("valign", "baseline"), d["rotation"])
            if g.kind == "Ellipse" and self.flip and self.line is not None:
                # the angle follows the mirror line as solved (bbox.held_rotation)
                new.data["mirror"] = (self.line[0], self.line[1], r)
            elif "mirror" in g.data:     # a turned copy of a mirrored Ellipse
                a, b, r0 = g.data["mirror"]
                new.data["mirror"] = (a, b, r0 - (self.rot or 0.0))
            if g.kind == "Text" and g.data.get("font") and (self.rot or self.flip):
                from ..shapes.text_outlines import turned_extent
                new.data["extent"] = turned_extent(new)     # the copy's own box
        if "angles" in g.data:               # ArcSlot: counter-clockwise from a1 by sweep
            a1, sweep = g.data["angles"]
            new.data["angles"] = ((2 * self.line_angle - a1 - sweep) if self.flip else
                                  a1 + (self.rot or 0.0), sweep)
        if "edges" in g.data:
            new.data["edges"] = [self.geom(e, dest) for e in g.data["edges"]]
        if "sources" in g.data:              # Offset, Shell, Hull: made from the copies
            new.data["sources"] = [self.geom(src, dest) for src in g.data["sources"]]
        if "part_of" in g.data:
            new.data["part_of"] = self.geoms.get(g.data["part_of"], g.data["part_of"])
        if g.data.get("along") is not None:  # Text along a curve: the copy follows the copy
            new.data["along"] = self.geom(g.data["along"], dest)
            if g.data.get("angle") is not None:
                a = g.data["angle"]
                new.data["angle"] = 2 * self.line_angle - a if self.flip else a + (self.rot or 0.0)
        new.parts = {n: self.geom(p, dest) for n, p in g.parts.items()}
        if g.listed:                         # edges of shapes are parts, not listed
            new.listed = True
            dest.geometry.append(new)
        return new

    def struct(self, s: Structure, parent: Structure, name: str) -> Structure:
        ctx = self.ctx
        c = ctx._new_structure(name, s.kind, parent, s.span, template=s.template)
        ctx.model.free[c.fx] = ctx.model.free[c.fy] = False      # held on the parent's frame
        # where the original's origin goes (its own, or, for a copy, the one it stands for)
        fx, fy = self.frame.frame_offset(None)
        ox, oy = s.copy_origin or s.frame_offset(None)
        X, Y = self.xf(ox - fx, oy - fy)
        c.copy_origin = (X + fx, Y + fy)
        c.copy_of = s                   # (the solver moves the original's features with it)
        self.structs[s] = c
        if s.cuts_into is not None and parent is s.parent:     # given by CutInto: so is c
            c.cuts_into = s.cuts_into
            s.cuts_into.cut_by.append(c)
        for g in s.geometry:
            self.geom(g, c)
        for n, ch in s.children.items():
            self.struct(ch, c, n)
        c.scope = {k: self.remap(v) for k, v in s.scope.items()}
        if getattr(s, "finish", None):
            # the copy's outline is filleted (chamfered) as the original's: corners chosen
            # with `at` (absolute coordinates) move with it
            def moved(px, py):
                X, Y = self.xf(px - fx, py - fy)
                return X + fx, Y + fy
            c.finish = [(kind, r * self.scale,
                         None if at is None else [ch.moved(moved) for ch in at], call)
                        for kind, r, at, call in s.finish]
        return c

    def remap(self, v):
        if isinstance(v, GeomRef) and v.geom in self.geoms:
            return GeomRef(self.geoms[v.geom])
        if isinstance(v, StructRef) and v.struct in self.structs:
            return StructRef(self.structs[v.struct])
        if isinstance(v, list):
            return [self.remap(x) for x in v]
        return v


def _loop_suffix(ctx) -> str:
    """``[i]`` per loop around the statement being run (``""`` outside loops, or for a
    context that does not run loops)."""
    f = getattr(ctx, "_loop_suffix", None)
    return f() if f is not None else ""


def _copy(ctx, target, xf, rot, flip, name: str | None, k: int, what: str, line_angle=0.0,
          indexed: bool = False, line=None, scale: float = 1.0, cloners: list | None = None):
    """The copy of ``target`` (``xf``: the map of points); ``cloners``, if given, gets the
    :class:`_Cloner` that made it (what each original point, shape and structure became)."""
    S = ctx.struct
    cl = _Cloner(ctx, S, xf, rot, flip, line_angle, line)
    cl.scale = scale
    if cloners is not None:
        cloners.append(cl)
    if isinstance(target, StructRef):
        # copies belong where the original is: siblings of it, whichever structure the
        # operation is written in (paper rule: the original lies in that structure's subtree)
        home = target.struct.parent or S
        # a named copy in a loop is named per iteration as a structure there is (`rings[0][1]`
        # of `rings = CircularPattern(...)` in `for`): each iteration's copies their own names
        base = name + _loop_suffix(ctx) if name else f"{target.struct.name}_{what}"
        nm = base if k == 0 and not indexed else f"{base}[{k}]"
        if nm in home.children:
            raise OperationError(f"`{home.path}` already has a child named `{nm}`; "
                                 + (f"give these copies a name of their own (`{name}_2 = ...`)"
                                    if name else "name the copy: `copy = ...`"))
        out = StructRef(cl.struct(target.struct, home, nm))
    else:
        home = target.geom.owner
        g = cl.geom(target.geom, home)
        if not g.listed:           # a copy of an edge stands on its own
            g.listed = True
            home.geometry.append(g)
        out = GeomRef(g)
    # what each original became, for what follows it into its copies (a hole's countersink)
    orig = target.struct if isinstance(target, StructRef) else target.geom
    copy = out.struct if isinstance(out, StructRef) else out.geom
    orig.__dict__.setdefault("pattern_copies", []).append(copy)
    if k == 1 and not indexed:
        # the pattern's list starts with the original: it is the copies' `NAME[0]`
        if isinstance(out, StructRef):
            out.struct.pattern_original = target.struct
        else:
            out.geom.pattern_original = target.geom
    # named as a reader finds it in the code (W0401's "it follows from"): the statement's
    # name, or what it copies (issue 105: "pattern copy" named nothing one could find)
    of = (f"`{name}`" if name else
          f"`{target.struct.name if isinstance(target, StructRef) else target.geom.name}`")
    c = Constraint("internal", S, ctx.cur_span, cl.eqs, text=(
        f"the {what} {of}'s copy rule" if name else f"the {what} copy of {of}"), implicit=True)
    from ..relations.bbox import defer_boxes
    defer_boxes(c)              # about a box's centre (run r: `box.bottom.bb.center`)
    if isinstance(out, StructRef):
        # who moves: the copy goes with its original (run z1's ring toss: labels placed `At`
        # the copies made them references, held where written, and the construction square
        # the pattern's original stands on moved instead, three pegs off the board)
        c.args = [{out.struct}, {target.struct}]
        c.copy_rule = True      # (the original is no reference for it: tree.placed_on)
    S.constraints.append(c)
    ctx.model.constraints.append(c)
    return out


def _target(ctx, t, op: str):
    if isinstance(t, StructRef):
        s = t.struct
        if s is ctx.struct or ctx.struct.is_within(s):
            raise OperationError(f"{op} cannot copy `{s.name}` into itself; write it in the "
                                 f"structure that contains `{s.name}`")
        return t
    if isinstance(t, GeomRef):
        if t.geom.kind == "Text" and op == "Mirrored":
            raise OperationError("Mirrored cannot mirror Text; place a second Text instead")
        return t
    raise OperationError(f"{op} copies geometry or a structure, got {type_name(t)}")


def _count(q: Q, op: str) -> int:
    c = q.const()
    if c is None or abs(c - round(c)) > 1e-9 or not 1 <= round(c) <= 10_000:
        raise OperationError(f"{op} count must be a whole number from 1 to 10000")
    return int(round(c))


# ------------------------------------------------------------------ entry point
def apply(ctx, kind: str, args: dict, name: str | None):
    """Run operation ``kind`` with checked, unit-converted ``args`` in ``ctx.struct``.

    Returns the copy (Mirrored), a :class:`Copies` list (patterns) or None (Fillet, Chamfer).
    Raises :class:`OperationError`.
    """
    S = ctx.struct
    if kind in ("Fillet", "Chamfer"):
        r = args["radius" if kind == "Fillet" else "distance"].const()
        if r is None or r < 0:
            # 0 rounds nothing (the corners stay sharp: a `fillet` param set to 0); the
            # corners chosen with `at` are still checked (E0408)
            raise OperationError(f"{kind} needs a size of 0 or more known before solving")
        if S.kind not in ("solid", "hole"):
            raise OperationError(f"{kind} works on the outline of a solid or hole, not on "
                                 f"{S.kind} `{S.name}`")
        at = None
        if "a" in args and "b" in args:           # Fillet(edge1, edge2, radius): their corner
            args = dict(args, at=[args["a"], args["b"]])
        if "at" in args:
            ox, oy = S.frame_offset(None)
            from ..relations.bbox import contains_bbox
            from .fillet_at import chosen
            at = chosen(ctx, args["at"], S, kind)
            if any(contains_bbox(p.x) or contains_bbox(p.y) for c in at for p in c.points):
                raise OperationError(f"{kind} at: name corners by geometry (`body.top_right`, "
                                     f"`[body.top, body.right]`), not by bounding-box values")
            at = [Chosen(c.what, tuple((p.x + ox, p.y + oy) for p in c.points), c.name,
                         tuple((n, (a.x + ox, a.y + oy), (b.x + ox, b.y + oy))
                               for n, a, b in c.alts), c.curve)
                  for c in at]
        call = FinishCall(args.get("_span") or ctx.cur_span, S, kind)
        S.finish = list(getattr(S, "finish", [])) + [(kind, r, at, call)]
        return None
    if kind == "AllowOverlap":
        return _allow_overlap([args["a"]] + ([args["b"]] if args.get("b") is not None else []),
                              S, args.get("_span"))
    if kind == "Rigid":
        return _rigid(ctx, _flat([args[k] for k in "ab" if args.get(k) is not None]))
    if kind == "Mirrored" and isinstance(args["target"], list):
        # a list of structures or shapes: a list of their mirror images, in order (`NAME[i]`
        # the image of item i), each beside its original as a single Mirrored puts it
        items = [_target(ctx, t, kind) for t in args["target"]]
        return [_mirror(ctx, S, t, args["about"], name, i, True) for i, t in enumerate(items)]
    target = _target(ctx, args["target"], kind)
    if kind == "Mirrored":
        return _mirror(ctx, S, target, args["about"], name, 0, False)
    if kind == "GridPattern":
        return _grid(ctx, target, args, name)
    if kind == "CornerPattern":
        return _corners(ctx, target, args, name)
    n = _count(args["count"], kind)
    start = step = 0.0
    if kind == "CircularPattern":
        start = args.get("start_angle", Q.num(0.0)).const()
        if start is None:
            raise OperationError("CircularPattern start_angle must be known before solving")
        step = _turn_step(args, n)
    else:
        _zero_step(n, [(args["step"].x, args["step"].y)], "LinearPattern step",
                   "the step from each instance to the next (`(12 mm, 0)`)")
    # a start angle turns every instance: the original is then only the pattern's template
    hide = start % (2 * math.pi) != 0.0
    out = Copies() if hide else Copies([target])
    for k in range(0 if hide else 1, n):
        if kind == "LinearPattern":
            st = args["step"]
            xf, rot, flip = _translate(st.x * float(k), st.y * float(k))
        else:
            xf, rot, flip = _rotate(args["center"], start + step * k, ctx)
        out.append(_copy(ctx, target, xf, rot, flip, name, k, "pattern", indexed=hide))
    if hide:
        _as_construction(target)
    return out


def _turn_step(args: dict, n: int) -> float:
    """CircularPattern's angle between neighbours (radians): ``step``, or ``angle`` spread
    over the ``n`` instances (a full turn: n gaps; else n - 1).  An OperationError when a copy
    would land on the original (a whole number of turns after k < n steps): the pattern would
    make fewer shapes than asked, one on another."""
    if "step" in args:
        step = args["step"].const()
        if step is None:
            raise OperationError("CircularPattern step must be known before solving")
        said = f"step={math.degrees(step):.6g} deg"
    else:
        total = args["angle"].const()
        if total is None:
            raise OperationError("CircularPattern angle must be known before solving")
        full = abs(abs(total) - 2 * math.pi) < 1e-9
        step = total / (n if full or n == 1 else n - 1)
        said = f"angle={math.degrees(total):.6g} deg over {n} copies"
    for k in range(1, n):
        turns = k * step / (2 * math.pi)
        if abs(turns - round(turns)) < 1e-9:
            lands = (f"every copy lands on the original (each turns {math.degrees(step):.6g} "
                     f"deg)" if k == 1 else
                     f"copy {k} lands on the original ({k} x {math.degrees(step):.6g} deg = "
                     f"{round(turns)} whole turn{'s' if abs(round(turns)) != 1 else ''}), so "
                     f"only {k} of the {n} places differ")
            raise OperationError(
                f"CircularPattern with {said}: {lands}; the pattern would make {n} shapes on "
                f"{k} spot{'s' if k > 1 else ''}. For {n} copies spread around a full turn "
                f"write angle=360 deg (or step=360 deg / {n}), for an arc the angle from the "
                f"first copy to the last")
    return step


def _zero_step(n: int, steps: list, what: str, fix: str, zero: str = "(0, 0)",
               lands: str = "all {n} instances land on one spot") -> None:
    """An OperationError when a pattern of ``n`` instances (``n`` > 1) moves each copy by a
    step known to be (0, 0) (``steps``: (x, y) expressions, each a step that is used): every
    copy would land on the original."""
    from ..core.expr import as_const
    for sx, sy in steps:
        x, y = as_const(sx), as_const(sy)
        if n > 1 and x is not None and y is not None and x == 0 and y == 0:
            raise OperationError(f"{what} is {zero}: {lands.format(n=n)}, so the pattern makes "
                                 f"one where {n} were asked; give {fix}")


def _mirror(ctx, S, target, about, name, k: int, indexed: bool):
    """The mirror image of ``target`` about the line ``about`` (its copy ``name``, or
    ``name[k]`` for the k-th item of a mirrored list)."""
    from ..relations.members import member
    line = about.geom
    a, b = member(line, "start", S), member(line, "end", S)
    dx, dy = ctx.value_of(b.x - a.x), ctx.value_of(b.y - a.y)
    if not math.hypot(dx, dy) > 1e-9:
        # a line of no length has no direction: the reflection divides by its length (the
        # same rule as the constraints' lines, geometry.constraints._direction)
        raise OperationError(f"`{getattr(line, 'label', None) or 'about'}` has zero length "
                             f"(its start and end are the same point), so there is no line "
                             f"to mirror about; give its start and end different places")
    ang = math.atan2(dy, dx)
    xf, rot, flip = _reflect(a, b)
    if line not in ctx.model.mirror_lines:
        ctx.model.mirror_lines.append(line)     # (hold_mirror_lines, after the program ran)
    return _copy(ctx, target, xf, rot, flip, name, k, "mirror", ang, indexed=indexed,
                 line=(a, b))


def hold_mirror_lines(model) -> None:
    """Hold where it is written each mirror line (``Mirrored``/``Flip``'s ``about``) of
    ``model`` that is construction and that no constraint but the mirror copies' rules reads:
    nothing places it, so a relation on the original or its image moved the line instead of
    the part (run by's stencil: the right boot print's axis, a free construction line, went
    32.9 mm left when the left print was placed, and the image 65.75 mm with it; run au's
    nail board, the same with `Flip`).  A line a written constraint places, or a drawn one,
    is left to its constraints."""
    lines = [g for g in model.mirror_lines if g.construction]
    if not lines:
        return
    mine = {id(g): {i for p in g.points.values() for i in (p.ix, p.iy)} for g in lines}
    every = set().union(*mine.values())
    read: set = set()
    for c in model.constraints:
        if c.implicit and (c.kind == "internal" or getattr(c, "copy_rule", False)):
            continue                        # a mirror copy's rule, a shape's own
        for eq in c.equations:
            _indices(eq.expr, every, read)
    for g in lines:
        if mine[id(g)] & read:
            continue
        eqs = [Equation(var(i) - model.x[i]) for i in sorted(mine[id(g)]) if model.free[i]]
        if eqs:
            c = Constraint("internal", g.owner, None, eqs,
                           text=f"the mirror line `{g.label}` held where it is written",
                           implicit=True)
            g.owner.constraints.append(c)
            model.constraints.append(c)


def _indices(e, among: set, out: set) -> None:
    """The unknowns of ``among`` that expression ``e`` reads, added to ``out``."""
    if isinstance(e, Lin):
        out.update(among.intersection(e.terms))
        return
    for a in getattr(e, "args", ()) or ():
        _indices(a, among, out)


def _allow_overlap(items: list, S=None, span=None) -> None:
    """``AllowOverlap(a, b, ...)``: the shapes and structures named (lists, such as the
    copies a loop makes, are spread out) may overlap.  Each hole among them (a hole structure,
    or a shape in one) may be refilled by every other (W0501, W0508:
    :func:`aidl_lang.output.checks.holes.openings._intended`); every two solid structures among them
    (parts of an assembly) may interpenetrate (W0511:
    :func:`aidl_lang.output.checks.parts._allowed`).  Both are kept in the structures'
    ``overlap_ok`` sets; an engraving named with its part (or a shape of it) may run off
    the part's material (W0505: :func:`aidl_lang.output.checks.marks.allowed.meant_off`),
    kept in the drawing's ``engrave_ok``; the call itself (``span``, the things named) in the ``allowances`` of
    ``S``, the structure it is written in (W0523: one that allows nothing).  One argument is
    a list (``AllowOverlap(c)``: a loop's copies in a hole, W0512).  Raises :class:`OperationError` for an argument that is no shape or
    structure, or when nothing is named that the two rules concern (no hole, fewer than two
    solid structures)."""
    objs = []
    for v in _flat(items):
        if isinstance(v, StructRef):
            objs.append(v.struct)
        elif isinstance(v, GeomRef):
            objs.append(v.geom)
        else:
            raise OperationError(f"AllowOverlap takes shapes, structures and lists of them; "
                                 f"got {_what(v)}")

    def hole_of(o):
        owner = o if isinstance(o, Structure) else o.owner
        return owner if owner.kind == "hole" else None
    done = False
    for k, o in enumerate(objs):
        h = hole_of(o)
        others = [x for m, x in enumerate(objs) if m != k and x is not h]
        if h is not None and others:
            if not hasattr(h, "overlap_ok"):
                h.overlap_ok = set()
            h.overlap_ok.update(others)
            done = True
    # parts: solids inside no other solid (in an assembly, or at the top); two solids of one
    # solid merge by design, so allowing them to overlap would mean nothing
    solids = [o for o in objs if isinstance(o, Structure) and o.kind == "solid"
              and not any(a.kind == "solid" for a in o.ancestors())]
    if len({id(o) for o in solids}) > 1:
        for o in solids:
            if not hasattr(o, "overlap_ok"):
                o.overlap_ok = set()
            o.overlap_ok.update(x for x in solids if x is not o)
        done = True
    # shapes of one solid structure: their overlaps and the window they enclose are meant
    # (W0515; the fix W0515 writes, issue 91: it follows the shapes, not typed coordinates)
    by_solid: dict = {}
    for o in objs:
        if not isinstance(o, Structure) and o.owner.kind == "solid":
            by_solid.setdefault(o.owner, set()).add(o)
    for owner, shapes in by_solid.items():
        if len(shapes) > 1:
            owner.enclosure_ok = list(getattr(owner, "enclosure_ok", ())) + [shapes]
            done = True
    # an engraving (a drawing, or a shape in one) that runs off its part's material on
    # purpose, named with the part (`self`) or a shape of it: W0505 is said as meant
    # (aidl_lang.output.checks.marks.allowed.meant_off; grid lines over a joint band)
    def holder(o):
        return o if isinstance(o, Structure) else o.owner
    drawn = [o for o in objs if holder(o).in_drawing()]
    # the part's material, or a hole of it the engraving crosses (run fj: `AllowOverlap(marks,
    # notch)`, an A4 outline drawn across a finger notch, "allows nothing" beside the W0505)
    material = [o for o in objs if not holder(o).in_drawing() and holder(o).kind in
                ("solid", "hole") and any(a.kind == "solid" for a in
                                          [holder(o), *holder(o).ancestors()])]
    if drawn and not material and S is not None and S.in_drawing() and any(
            o is S for o in objs):
        # `AllowOverlap(guide, self)` written in the drawing itself (run co: W0523 "allows
        # nothing", the W0505s kept): `self` is the drawing there, and the call means what
        # W0505's hint writes in the part, its lines run off the part it is on
        material = [a for a in S.ancestors() if a.kind == "solid"][:1]
    if drawn and material:
        for o in drawn:
            node = o if isinstance(o, Structure) else o.owner
            node.engrave_ok = list(getattr(node, "engrave_ok", ())) + [(o, material)]
        done = True
    elif drawn and len(drawn) == len(objs):
        # texts and marks laid out close as meant (W0513: labels round a disc that "run into"
        # each other; run z3's kumihimo numbers): each may come near or over every other
        for o in drawn:
            node = o if isinstance(o, Structure) else o.owner
            node.text_ok = set(getattr(node, "text_ok", ())) | set(drawn)
        done = True
    if not done:
        raise OperationError("AllowOverlap names a hole and what may refill it, two solid "
                             "parts (of an assembly) that may overlap, two or more shapes "
                             "of one solid that enclose an opening as meant, an engraving "
                             "and its part (`self`) that it runs off on purpose, or texts "
                             "and marks (a drawing) laid out close as meant; got "
                             + " and ".join(_what(StructRef(o) if isinstance(o, Structure)
                                                  else GeomRef(o)) for o in objs))
    if S is not None:
        # kept where it is written, with its statement, for W0523 (one that allows nothing:
        # aidl_lang.output.checks.allowances)
        S.allowances = list(getattr(S, "allowances", ())) + [(span, objs)]
    return None


class _Origin:
    """A structure's frame origin as a point of a ``Rigid`` group: its position in frame
    ``S`` is the sum of the frames between them."""

    def __init__(self, struct):
        self.owner = struct

    def in_frame(self, S):
        return self.owner.frame_offset(S)


def _flat(items: list) -> list:
    """``Rigid``'s arguments with lists (``Rigid(holes)``, ``Rigid([a, b])``) spread out."""
    out: list = []
    for v in items:
        if isinstance(v, (list, tuple)) and not (len(v) == 2 and all(
                isinstance(x, (int, float)) or hasattr(x, "dim") for x in v)):
            out += _flat(list(v))
        else:
            out.append(v)
    return out


def _rigid(ctx, items: list) -> None:
    """``Rigid(a, b, ...)``: a structure is marked rigid (the solver of its ancestors moves it
    only by its frame, :func:`aidl_lang.solver.core.tree._rigid_below`); shapes keep their
    points' starting offsets from the first shape's first point (two linear equations per
    point, in the writing structure's frame): they move together, translation only."""
    S = ctx.struct
    pts: list = []
    seen: set = set()
    several = len(items) > 1
    for v in items:
        if isinstance(v, StructRef):
            v.struct.rigid = True
            if several and v.struct is not S and id(v.struct) not in seen:
                # named beside others: its origin keeps its offset from them too (the group
                # moves as one body)
                seen.add(id(v.struct))
                pts.append(_Origin(v.struct))
        elif isinstance(v, GeomRef):
            for p in _placing_points(ctx, v.geom):
                if id(p) not in seen:
                    seen.add(id(p))
                    pts.append(p)
        else:
            raise OperationError(f"Rigid takes structures and shapes, got {_what(v)}")
    if len(pts) < 2:
        return None
    x0, y0 = pts[0].in_frame(S)
    eqs = []
    for p in pts[1:]:
        x, y = p.in_frame(S)
        dx, dy = ctx.value_of(x - x0), ctx.value_of(y - y0)
        eqs += [Equation(x - x0 - dx), Equation(y - y0 - dy)]
    ctx._add_constraint("Rigid", eqs, ctx.cur_span, None, {p.owner for p in pts})
    return None


_HELD_SHAPES = ("Circle", "RegularPolygon", "Star", "ArcSlot", "Trapezoid", "Ellipse", "Text")


def _placing_points(ctx, g) -> list:
    """The points that place shape ``g`` given its own implicit constraints: one for a shape
    whose form is held (a Circle, a Rectangle by size, a rigid Polygon, ...), the two ends
    of a bar or of a Rectangle by corners, else every point (no redundant rows)."""
    if "sources" in g.data and not g.points:
        # Offset, Inset, Shell, Hull: placed by the shapes they are made from
        return [p for src in g.data["sources"] for p in _placing_points(ctx, src)]
    P = g.points
    free = ctx.model.free
    if g.kind in _HELD_SHAPES or g.data.get("rigid") or (
            g.kind in ("Rectangle", "RoundedRectangle", "Slot", "Triangle")
            and "center" in P and not any(free[s.index] for s in g.scalars.values())):
        return [P["center"] if "center" in P else next(iter(P.values()))]
    if g.kind in ("Rectangle", "RoundedRectangle"):
        if "start" in P:
            return [P["start"], P["end"]]
        if not any(free[s.index] for s in g.scalars.values()):
            return [P["bottom_left"]]
        return [P["bottom_left"], P["top_right"]]
    return list(P.values())


def _as_construction(target) -> None:
    """Make ``target`` (geometry, or every shape of a structure's subtree) construction: solved
    and referable, not drawn (the template of a pattern that moves every instance)."""
    if isinstance(target, GeomRef):
        target.geom.construction = True
        return
    todo = [target.struct]
    while todo:
        s = todo.pop()
        for g in s.geometry:
            g.construction = True
        todo += s.children.values()


def _grid(ctx, target, args: dict, name: str | None) -> Copies:
    """GridPattern: ``rows`` x ``cols`` instances, copy (r, c) moved by (c * dx, r * dy),
    and with ``stagger`` every odd row by dx / 2 more (a honeycomb); the list in row-major
    order (index r * cols + c), the original first."""
    rows, cols = _count(args["rows"], "GridPattern rows"), _count(args["cols"], "GridPattern cols")
    if rows * cols > 10_000:
        raise OperationError(f"GridPattern makes {rows} x {cols} = {rows * cols} instances, more "
                             f"than 10000")
    if "spacing" in args:
        sp = args["spacing"]
        span = ctx.cur_span
        if isinstance(sp, Q):
            d = ctx._coerce(sp, "length", span, "GridPattern", "spacing").expr
            dx = dy = d
        elif isinstance(sp, (tuple, list, PV)):
            p = ctx._coerce(sp, "point", span, "GridPattern", "spacing")
            dx, dy = p.x, p.y
        else:
            raise OperationError(f"GridPattern spacing is a length (the same both ways) or "
                                 f"(dx, dy), got {type_name(sp)}")
    else:
        dx, dy = args["col_spacing"].expr, args["row_spacing"].expr
    _zero_step(cols, [(dx, 0.0)], "GridPattern's column spacing",
               "the distance between columns (`spacing=(12 mm, 10 mm)`), or cols=1", "0",
               "its {n} columns land on one another")
    _zero_step(rows, [(0.0, dy)], "GridPattern's row spacing",
               "the distance between rows (`spacing=(12 mm, 10 mm)`), or rows=1", "0",
               "its {n} rows land on one another")
    stagger = bool(args.get("stagger"))
    out = Copies([target])
    for r in range(rows):
        for c in range(cols):
            if r == 0 and c == 0:
                continue
            shift = 0.5 if stagger and r % 2 else 0.0
            xf, rot, flip = _translate(dx * (float(c) + shift), dy * float(r))
            out.append(_copy(ctx, target, xf, rot, flip, name, r * cols + c, "pattern"))
    return out


def _corners(ctx, target, args: dict, name: str | None) -> Copies:
    """CornerPattern: the target's center (a shape's ``center``, else its bounding box's)
    placed on the first point, a copy moved onto each other point; the points are a
    Rectangle's corners (bottom_left, bottom_right, top_right, top_left), each ``inset``
    toward the center along the rectangle's own sides, or the list ``at``."""
    from ..relations.members import _pv
    S = ctx.struct
    span = ctx.cur_span
    if "at" in args:
        pts = list(args["at"])
        if not pts:
            raise OperationError("CornerPattern at: needs at least one point")
        if len(pts) > 10_000:
            raise OperationError("CornerPattern at: more than 10000 points")
        _same_points(pts)
    else:
        rect = args["rect"]
        if not (isinstance(rect, GeomRef) and rect.geom.kind in ("Rectangle", "RoundedRectangle")):
            raise OperationError(f"CornerPattern needs a Rectangle (e.g. `body`), got "
                                 f"{_what(rect)}; for other points write `at=[p1, p2, ...]`")
        g = rect.geom
        inset_x, inset_y = _inset(ctx, args.get("inset", 0.0))
        if "start" in g.points:      # a bar: its direction follows its ends
            from ..core.expr import hypot
            bl, br, tl = (_pv(g.points[n], S) for n in ("bottom_left", "bottom_right", "top_left"))
            wu, wv = hypot(br.x - bl.x, br.y - bl.y), hypot(tl.x - bl.x, tl.y - bl.y)
            ux, uy = (br.x - bl.x) / wu, (br.y - bl.y) / wu
            vx, vy = (tl.x - bl.x) / wv, (tl.y - bl.y) / wv
        else:                        # the held rotation
            rot = g.data.get("rotation", 0.0)
            ux, uy = math.cos(rot), math.sin(rot)
            vx, vy = -uy, ux
        pts = []
        for nm, (su, sv) in (("bottom_left", (1, 1)), ("bottom_right", (-1, 1)),
                             ("top_right", (-1, -1)), ("top_left", (1, -1))):
            p = _pv(g.points[nm], S)
            pts.append(PV(p.x + inset_x * su * ux + inset_y * sv * vx,
                          p.y + inset_x * su * uy + inset_y * sv * vy, None, p.owners))
    ref = None
    if isinstance(target, GeomRef) and len(target.geom.data.get("sources", ())) > 1:
        # a Hull of several shapes is placed as one body: its shapes move together (else
        # placing its box's center would pull its extreme shapes apart)
        _rigid(ctx, [target])
    if isinstance(target, GeomRef):
        from ..relations.members import member
        ref = member(target.geom, "center", S)
    if not isinstance(ref, PV):
        ref = ctx.member(ctx.member(target, "bb", span), "center", span)
    p0 = pts[0]
    ctx._add_constraint("CornerPattern", [Equation(ref.x - p0.x), Equation(ref.y - p0.y)],
                        span, None, set(ref.owners) | set(p0.owners))
    out = Copies([target])
    for k, p in enumerate(pts[1:], 1):
        xf, rot, flip = _translate(p.x - p0.x, p.y - p0.y)
        out.append(_copy(ctx, target, xf, rot, flip, name, k, "pattern"))
    return out


def _same_points(pts: list) -> None:
    """An OperationError when two of CornerPattern's ``at`` points are the same numbers (two
    copies on one spot)."""
    from ..core.expr import as_const
    seen: dict = {}
    for i, p in enumerate(pts):
        xy = (as_const(getattr(p, "x", None)), as_const(getattr(p, "y", None)))
        if None in xy:
            continue
        if xy in seen:
            raise OperationError(f"CornerPattern at: points {seen[xy]} and {i} are both "
                                 f"({xy[0]:.6g}, {xy[1]:.6g}) mm, so two copies land on one "
                                 f"spot; give each copy its own point")
        seen[xy] = i


def _inset(ctx, v):
    """CornerPattern's ``inset``: one length (the same along both sides) or ``(dx, dy)``, dx
    along the rectangle's width and dy along its height (its own sides, turned with it);
    mm expressions."""
    span = ctx.cur_span
    if isinstance(v, (int, float)):
        return float(v), float(v)
    if isinstance(v, Q):
        d = ctx._coerce(v, "length", span, "CornerPattern", "inset").expr
        return d, d
    if isinstance(v, (tuple, list, PV)):
        p = ctx._coerce(v, "point", span, "CornerPattern", "inset")
        return p.x, p.y
    raise OperationError(f"CornerPattern inset is a length (the same along both sides) or "
                         f"(dx, dy) along the rectangle's width and height, got {type_name(v)}")


def _what(v) -> str:
    if isinstance(v, GeomRef):
        return f"a {v.geom.kind}"
    if isinstance(v, StructRef):
        return f"structure `{v.struct.name}`"
    return type_name(v)
