"""Scale, move and flip a whole structure or shape (issue 95): ``Scaled``, ``Translated`` make
a copy, as ``Mirrored`` does; ``Scale``, ``Translate`` (``Move``) and ``Flip`` change the
thing in place.

A copy is solved geometry tied to its original (each point to the transformed original point,
each length times the factor): the original's constraints hold on it, transformed, and it can
be constrained itself.  In place, the transformed copy *is* the thing from then on: it takes
the original's name (in the structure and, for a name written alone, in the program's scope,
so the statements after it reach it) and the original becomes construction under the name
``NAME_original`` -- solved and referable, never drawn, as the template of a
``CircularPattern(..., start_angle=)``.  So ``Scale(plaque, 0.7)`` after a plaque's block
makes the drawn plaque 30 % smaller, every size and position of it, holes, fillets and text
included, about ``center``: for ``Scale``, the thing's own centre unless given (its bounding
box's centre as written; issue 105), for ``Scaled`` the origin.  ``Scale`` also carries the
constraints that place the thing, written before it outside it, to the scaled copy
(:func:`_carry_relations`): ``Scale(star, 1.5)`` after ``At(star.s.center, tree.body.center,
dy=45)`` keeps the star's centre where the ``At`` puts it; the original keeps its own box
(``bbox._candidates``), so a size written before stays on it and the copy is that size
scaled.
"""
from __future__ import annotations

from .operations import OperationError, _as_construction, _copy, _mirror, _target, _translate
from ..core.expr import Lin, _lin, _new
from ..core.model import equation
from ..core.values import PV, GeomRef, StructRef

IN_PLACE = {"Scale": "Scaled", "Translate": "Translated", "Flip": "Mirrored"}

# `aidl docs` examples (reference.EXAMPLES): the line in a plate with a 4 mm hole at (-20, -10)


def _scale(c: PV, k: float):
    """The map p -> c + k (p - c), on coordinates that are expressions."""
    cx, cy = c.x, c.y
    return lambda x, y: (cx + (x - cx) * k, cy + (y - cy) * k)


def apply(ctx, kind: str, args: dict, name: str | None):
    """``Scaled``/``Scale``(target, factor, center), ``Translated``/``Translate``(target, by),
    ``Flip``(target, about): the copy (or list of copies, for a list); in place, the copy
    that replaces the original."""
    target = args["target"]
    op = IN_PLACE.get(kind, kind)        # (Flip refuses Text as Mirrored does)
    if isinstance(target, list):
        return [_one(ctx, kind, args, _target(ctx, t, op), name, i, True)
                for i, t in enumerate(target)]
    return _one(ctx, kind, args, _target(ctx, target, op), name, 0, False)


def _one(ctx, kind, args, target, name, i: int, indexed: bool):
    op = IN_PLACE.get(kind, kind)
    in_place = kind in IN_PLACE
    if in_place:
        # the copy takes the original's name; the original is renamed, kept as construction
        name = _rename_original(ctx, target, i if indexed else None)
        indexed = False
    if op == "Mirrored":
        S = ctx.struct
        out = _mirror(ctx, S, target, args["about"], name, i, indexed)
        if in_place:
            _mark_in_place(out, target)
        return _finish(ctx, out, target, in_place, name)
    if op == "Scaled":
        k = args["factor"].const()
        if k is None or not k > 0:
            raise OperationError(f"{kind} needs a factor more than 0 known before solving "
                                 f"(0.7: 30 % smaller; a mirror image is `Flip` or `Mirrored`)")
        c = args.get("center")
        if c is None:              # Scale: about its own centre; Scaled: about the origin
            c = _own_centre(ctx, target) if in_place else PV(_lin({}, 0.0), _lin({}, 0.0))
        xf, what, scale = _scale(c, k), "scaled", k
    else:
        by = args["by"]
        xf, what, scale = _translate(by.x, by.y)[0], "moved", 1.0
    cloners: list = []
    out = _copy(ctx, target, xf, 0.0, False, name, i, what, indexed=indexed, scale=scale,
                cloners=cloners)
    if in_place:
        _carry_derived(target, cloners[0])
    if in_place and op == "Scaled":
        _carry_relations(ctx, target, cloners[0])
        made = out.struct if isinstance(out, StructRef) else out.geom
        made.scaled_in_place = k              # said by W0504's hint
        _mark_in_place(out, target)
    return _finish(ctx, out, target, in_place, name)


def _mark_in_place(out, target) -> None:
    """A thing scaled or flipped in place moves with its original: a shape as one shape
    with it, a structure by its original's frame (the solver's who-moves)."""
    if isinstance(out, GeomRef):
        out.geom.in_place_of = target.geom
    else:
        out.struct.in_place_of = target.struct


def _mark_replaced(target) -> None:
    """The original of a change in place keeps its box: its drawn geometry, made construction
    next, still counts in the box of the original itself (``plaque_original.bb``, and a
    constraint on its size written before the change, ``plaque.bb.width == 20``, which stays
    on it), not in the boxes of the structures around it (``bbox._candidates``)."""
    if isinstance(target, GeomRef):
        return
    todo = [target.struct]
    while todo:
        s = todo.pop()
        s.replaced = True
        for g in s.geometry:
            if not g.construction:
                g.replaced = True
        todo += s.children.values()


def _own_centre(ctx, target) -> PV:
    """The centre ``Scale`` scales ``target`` about when no ``center=`` is given: its
    bounding box's centre as written (the starting values), in the frame of the structure
    the call is written in (a structure's box: its drawn shapes and children, holes
    included; construction geometry only when it is all there is).  The origin when it
    holds no geometry.  The centre moves with the structure that holds the thing (its own
    frame, for a structure): where the solve moves that structure, the scaled copy moves
    with it, rigidly (``Scale(small.outline, 0.6)`` in an assembly that places ``small``
    by ``RightOf``: before, the centre stayed where ``small`` was written, the copy moved
    0.6 mm for each mm ``small`` moved, and its neighbour was pulled along)."""
    from ..core.expr import evaluate
    from ..relations.bbox import numeric_box
    what = target.struct if isinstance(target, StructRef) else target.geom
    box = numeric_box(what, ctx.struct, ctx.model.x)
    if box is None:
        return PV(_lin({}, 0.0), _lin({}, 0.0))
    x0, x1, y0, y1 = box
    holder = target.struct if isinstance(target, StructRef) else target.geom.owner
    if holder is ctx.struct or not holder.is_within(ctx.struct):
        return PV(_lin({}, (x0 + x1) / 2), _lin({}, (y0 + y1) / 2))
    fx, fy = holder.frame_offset(ctx.struct)
    x = ctx.model.x
    return PV(_lin(fx.terms, (x0 + x1) / 2 - evaluate(fx, x)),
              _lin(fy.terms, (y0 + y1) / 2 - evaluate(fy, x)))


def _carry_derived(target, cl) -> None:
    """``Scale`` or ``Translate`` in place: the shapes made from the thing before the change,
    outside it (``wall = Shell(outline, 2.5)`` before ``Scale(small.outline, 0.6)``; an
    ``Offset`` or ``Hull`` of it in a structure above), are made from the changed copy from
    then on, as every later statement is: the wall follows its outline.  (Before: the wall
    kept the original's size and place, and the Scale changed nothing drawn, silently; the
    fresh models' run data/model_runs/issue105b, request 10.)"""
    s = target.struct.parent if isinstance(target, StructRef) else target.geom.owner
    made = set(map(id, cl.geoms.values()))
    while s is not None:
        for g in s.geometry:
            src = g.data.get("sources")
            # (not the copies, nor the originals they copy: `wall_original` keeps its outline)
            if src and id(g) not in made and g not in cl.geoms:
                g.data["sources"] = [cl.geoms.get(q, q) for q in src]
        s = s.parent


def _carry_relations(ctx, target, cl) -> None:
    """``Scale`` in place (issue 105): the relations that place ``target`` -- the written
    constraints outside it (in the structures above it, or beside a shape) that read it and
    whose residual changes when it moves (``At(star.s.center, tree.body.center, dy=45)``,
    ``AlignCenterX(star, tree)``, ``Fixed(star)``) -- now hold on the scaled copy, which is
    the thing placed: the star's centre stays where its ``At`` puts it.  Constraints inside
    it (its shape) and those on it alone that do not place it (``star.bb.width == 20``,
    ``Radius(c, 5)``: its size, scaled with it) stay on the original, which the copy
    follows.  (Before: the ``At`` held the hidden original, and the star drawn 1.5 times as
    far from the origin floated off the tree.)  Each carried constraint's equations are
    rewritten on the copy's parameters (``cl``: what each original point, size, shape and
    structure became), its boxes on the copy's, and its who-moves arguments with them."""
    from ..core.expr import Nl, evaluate
    from ..relations.bbox import BBTerm, collect, exclusions, expand
    m = ctx.model
    if isinstance(target, StructRef):
        root = target.struct
        inside = set(root.subtree())
        ids = {i for t in inside for i in (t.fx, t.fy)}
        for t in inside:
            for g in t.geometry:
                _params(g, ids)
        shift = ([root.fx], [root.fy])
        home = root.parent
        objs = dict(cl.structs)
    else:
        root = None
        inside = set()
        ids = set()
        _params(target.geom, ids)
        pts: list = []
        _points(target.geom, pts)
        shift = ([p.ix for p in pts], [p.iy for p in pts])
        home = target.geom.owner
        objs = {}
    objs.update(cl.geoms)
    vmap: dict = {}
    for p, q in cl.points.items():
        vmap[p.ix], vmap[p.iy] = q.ix, q.iy
    for g, new in cl.geoms.items():
        for n, sc in g.scalars.items():
            if n in new.scalars:
                vmap[sc.index] = new.scalars[n].index
    for t, c in cl.structs.items():
        vmap[t.fx], vmap[t.fy] = c.fx, c.fy

    def reads(e) -> bool:
        todo = [e]
        while todo:
            a = todo.pop()
            ta = type(a)
            if ta is Lin:
                if not ids.isdisjoint(a.terms):
                    return True
            elif ta is Nl:
                todo += a.args
            elif ta is BBTerm and a.target in objs:
                return True
        return False

    x = list(m.x)

    def places(eqs) -> bool:
        for eq in eqs:
            e = eq.expr
            terms = collect(e, [])
            if terms:
                e = expand(e, x, exclusions(terms))
            v0 = evaluate(e, x)
            for axis in shift:
                moved = list(x)
                for i in axis:
                    moved[i] += 1.0
                if abs(evaluate(e, moved) - v0) > 1e-9:
                    return True
        return False

    def remap(e):
        te = type(e)
        if te is Lin:
            return _lin({vmap.get(k, k): v for k, v in e.terms.items()}, e.const)
        if te is Nl:
            out = _new(Nl)
            out.op, out.args = e.op, tuple(remap(a) for a in e.args)
            return out
        if te is BBTerm and e.target in objs:
            return BBTerm(objs[e.target], e.side, e.frame)
        return e

    s = home
    while s is not None:
        for c in s.constraints:
            if c.implicit or c.hold or (root is not None and c.owner in inside):
                continue
            eqs = c.deferred if c.deferred is not None else c.equations
            if not any(reads(eq.expr) for eq in eqs) or not places(eqs):
                continue
            new = [equation(remap(eq.expr), eq.ineq,
                            None if eq.branch is None else remap(eq.branch)) for eq in eqs]
            if c.deferred is not None:
                c.deferred = new
            else:
                c.equations = new
            if c.args is not None:
                c.args = [frozenset(objs.get(o, o) for o in a) for a in c.args]
            if c.reach is not None:
                c.reach = [frozenset(vmap.get(v, v) for v in r) for r in c.reach]
            if c.__dict__.get("arg_reach") is not None:
                c.arg_reach = [frozenset(vmap.get(v, v) for v in r) for r in c.arg_reach]
        s = s.parent


def _params(g, out: set) -> None:
    for p in g.points.values():
        out.add(p.ix)
        out.add(p.iy)
    for sc in g.scalars.values():
        out.add(sc.index)
    for q in g.parts.values():
        if hasattr(q, "points"):
            _params(q, out)
        elif hasattr(q, "ix"):
            out.add(q.ix)
            out.add(q.iy)


def _points(g, out: list) -> None:
    """The distinct points of shape ``g`` (its parts' too)."""
    seen = {id(p) for p in out}
    for p in g.points.values():
        if id(p) not in seen:
            seen.add(id(p))
            out.append(p)
    for q in g.parts.values():
        if hasattr(q, "points"):
            _points(q, out)


def _rename_original(ctx, target, i):
    """In place: free the original's name for its copy (the original becomes
    ``NAME_original``) and give back that name."""
    if isinstance(target, StructRef):
        s = target.struct
        home = s.parent
        old = s.name
        new = f"{old}_original"
        if home is not None:
            if new in home.children:
                raise OperationError(f"`{old}` was changed in place already; change it once "
                                     f"(or make copies with Scaled, Translated, Mirrored)")
            home.children = {(new if k == old else k): v for k, v in home.children.items()}
        s.name = new
        return old
    g = target.geom
    old = g.name
    g.name = f"{old}_original" if old else None
    return old


def _finish(ctx, out, target, in_place: bool, old: str | None = None):
    """In place: the original (every shape of it) becomes construction, drawn no more; a
    shape's copy takes its name."""
    if not in_place:
        return out
    _mark_replaced(target)
    _as_construction(target)
    if isinstance(out, GeomRef) and old:
        out.geom.name = old
    return out
