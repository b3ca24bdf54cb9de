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
makes the drawn plaque 30 % smaller about ``center`` (the origin unless given), every size
and position of it, holes, fillets and text included.
"""
from __future__ import annotations

from .operations import OperationError, _as_construction, _copy, _mirror, _target, _translate
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
        return _finish(ctx, _mirror(ctx, S, target, args["about"], name, i, indexed),
                       target, in_place, name)
    if op == "Scaled":
        k = args["factor"].const()
        if k is None or not k > 0:
            raise OperationError(f"{kind} needs a factor more than 0 known before solving "
                                 f"(0.7: 30 % smaller; a mirror image is `Flip` or `Mirrored`)")
        c = args.get("center")
        xf, what, scale = _scale(c if c is not None else PV(0.0, 0.0), k), "scaled", k
    else:
        by = args["by"]
        xf, what, scale = _translate(by.x, by.y)[0], "moved", 1.0
    out = _copy(ctx, target, xf, 0.0, False, name, i, what, indexed=indexed, scale=scale)
    return _finish(ctx, out, target, in_place, name)


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
    _as_construction(target)
    if isinstance(out, GeomRef) and old:
        out.geom.name = old
    return out
