"""``Countersink`` and ``Counterbore`` (issue 102): the call checked and recorded on the
model (:class:`~..geometry.core.model.Sink`); the outputs cut them after the solve.  And what
follows a pattern's original into its copies after the program: a sink, a fillet at two
shapes (:func:`fillet_copies`)."""
from __future__ import annotations

import math

from ..base.diagnostics import EvalError
from ..base.limits import MAX_EXTENT
from ..geometry.core.values import ANG, LEN, NUM, GeomRef, Q, StructRef, angle_scale, type_name
from .common import DEG, _a


def sink_call(interp, cname: str, conv, node, spans):
    """``Countersink(hole, diameter, angle)`` / ``Counterbore(hole, diameter, depth)``
    (issue 102): the round holes named (a hole structure's Circles, a Circle of a hole,
    or a list of these: a pattern) get a head recorded on the model
    (:class:`~..geometry.core.model.Sink`), cut by the outputs after the solve.  The
    sizes are known before solving; else a located E0109, and E0108 for what is no
    round hole or a size out of range."""
    from ..geometry.core.model import Sink
    hspan = spans.get("hole", node.span)
    eg = ("Countersink(holes, diameter=9 mm)" if cname == "Countersink"
          else "Counterbore(holes, diameter=10 mm, depth=5 mm)")
    circles: list = []

    def take(v) -> None:
        if isinstance(v, (list, tuple)):
            for item in v:
                take(item)
            return
        if isinstance(v, GeomRef) and v.geom.kind == "Circle" and \
                v.geom.owner.kind == "hole":
            circles.append(v.geom)
            return
        if isinstance(v, StructRef) and v.struct.kind == "hole":
            found = [g for st in [v.struct, *_descendants(v.struct)] for g in st.geometry
                     if g.kind == "Circle" and not g.construction]
            if found:
                circles.extend(found)
                return
            raise EvalError("E0108", f"`{cname}` sinks round holes: hole "
                            f"`{v.struct.path}` has no Circle", hspan,
                            hint=f"draw the hole as a Circle, then `{eg}`")
        raise EvalError("E0108", f"`{cname}` sinks a round hole (a hole structure with a "
                        f"Circle, a Circle of one, or a list of them), got "
                        f"{_a(type_name(v))}", hspan,
                        hint=f"name the hole: `hole holes {{ c = Circle(center=(10, 10), "
                             f"diameter=4.5 mm) }}` then `{eg}`")
    take(conv["hole"])
    vals = {}
    for k, dim in (("diameter", LEN), ("angle", ANG), ("depth", LEN)):
        q = conv.get(k)
        if q is None:
            continue
        sp = spans.get(k, node.span)
        c = q.const() if isinstance(q, Q) and q.dim in (dim, NUM) else None
        if c is None:
            raise EvalError("E0109", f"`{k}` of `{cname}` must be "
                            f"{'an angle' if dim is ANG else 'a length'} known before "
                            "solving", sp, hint=f"use numbers and params: `{eg}`")
        scale = 1.0 if q.dim == dim else ((interp.file.unit_scale if interp.file else 1.0)
                                          if dim is LEN else angle_scale(q, DEG))
        vals[k] = float(c) * scale
    if not 0 < vals["diameter"] <= MAX_EXTENT:
        raise EvalError("E0108", f"the `diameter` of `{cname}` is {vals['diameter']:g} mm: "
                        "the head's diameter is above 0", spans.get("diameter", node.span),
                        hint=f"write e.g. `{eg}`")
    angle = vals.get("angle")
    if angle is not None and not math.radians(30) <= angle <= math.radians(150):
        raise EvalError("E0108", f"the `angle` of `Countersink` is "
                        f"{math.degrees(angle):g} deg: a countersink's included angle is "
                        "from 30 to 150 deg (90 deg for metric flat-head screws, 82 deg "
                        "for inch)", spans.get("angle", node.span),
                        hint="write `angle=90 deg`, or leave it out (90 deg)")
    depth = vals.get("depth")
    if depth is not None and not 0 < depth <= MAX_EXTENT:
        raise EvalError("E0108", f"the `depth` of `Counterbore` is {depth:g} mm: a "
                        "counterbore is more than 0 deep", spans.get("depth", node.span),
                        hint=f"write e.g. `{eg}`")
    kind = cname.lower()
    # each sunk Circle's call, kept beside the model's list (a pattern of 10,000 holes sunk
    # one call each is not searched again at every call)
    model, index = interp.__dict__.get("_sunk") or (None, None)
    if model is not interp.model:
        index = {}
        interp.__dict__["_sunk"] = (interp.model, index)
    circles = _once(index, circles, kind, vals["diameter"], angle, depth, cname, hspan,
                    node.span)
    if circles is not None:
        sk = Sink(kind, circles, vals["diameter"], angle, depth, node.span)
        interp.model.sinks.append(sk)
        index.update((id(g), sk) for g in circles)
    return None


def _once(first: dict, circles: list, kind: str, diameter: float, angle, depth, cname: str,
          hspan, span) -> list | None:
    """``circles`` with each hole once (issue 109, law 5: one thing is counted once): a hole
    named twice in one call (``[a, a.c]``) or sunk again by an earlier call with the same
    head (the same sink repeated) is dropped, and ``None`` when nothing new is left; a hole
    an earlier call sank with another head (``first``: id of a Circle -> its
    :class:`~..geometry.core.model.Sink`) is a located E0108 naming that call's line."""
    out, ids = [], set()
    for g in circles:
        if id(g) in ids:
            continue
        ids.add(id(g))
        sk = first.get(id(g))
        if sk is None:
            out.append(g)
            continue
        if sk.kind == kind and abs(sk.diameter - diameter) <= 1e-9 and \
                _same(sk.angle, angle) and _same(sk.depth, depth):
            continue                    # the same head again: one countersink, said once
        at = sk.span
        line = "" if at is None else (f" (line {at.line})" if span is None or
                                      at.file == span.file else f" ({at.file}:{at.line})")
        raise EvalError("E0108", f"`{cname}` sinks hole `{g.label}` a second time: "
                        f"`{_head(sk)}` sinks it already{line}; a hole takes one countersink "
                        "or counterbore", hspan,
                        hint="drop this one (or the hole from its list), or give the first "
                             "the head meant")
    return out if out or not circles else None


def _same(a, b) -> bool:
    return (a is None) == (b is None) and (a is None or abs(a - b) <= 1e-9)


def _head(sk) -> str:
    """A recorded sink as a call, for a message: ``Countersink(diameter=9 mm)``."""
    if sk.kind == "countersink":
        return (f"Countersink(diameter={sk.diameter:g} mm, "
                f"angle={math.degrees(sk.angle):g} deg)")
    return f"Counterbore(diameter={sk.diameter:g} mm, depth={sk.depth:g} mm)"


def _descendants(s) -> list:
    """Every structure under ``s`` (its children, theirs, ...)."""
    out, todo = [], list(s.children.values())
    while todo:
        c = todo.pop()
        out.append(c)
        todo.extend(c.children.values())
    return out


def sink_copies(model) -> None:
    """A pattern copies a sunk hole with its head: each ``Countersink`` / ``Counterbore``
    of the model also sinks the copies that a ``LinearPattern``, ``CircularPattern``,
    ``CornerPattern``, ``Mirrored`` (or a copy of a structure holding the hole) made of a hole it
    names, as a CAD pattern copies a countersunk hole feature whole (issue 111's third run: a
    `CornerPattern(screw, plate, inset=6 mm)` then `Countersink(screw, diameter=6 mm)` sank one
    of four screw holes, said only as "1 countersink head").  A copy some call sinks itself
    keeps that call's head; copies of copies follow.  Run once, after the program: each sunk
    Circle costs the depth of its structure, each structure's geometry indexed once."""
    sinks = getattr(model, "sinks", None)
    if not sinks:
        return
    sunk = {id(g) for sk in sinks for g in sk.circles}
    index: dict = {}                # id(structure) -> {id(geometry): its place in it}
    for sk in sinks:
        todo = list(sk.circles)
        while todo:
            g = todo.pop()
            for c in _copies_of(g, index):
                if id(c) not in sunk:
                    sunk.add(id(c))
                    sk.circles.append(c)
                    todo.append(c)


def fillet_copies(model) -> None:
    """``Fillet([a, b], r)`` (and ``Chamfer``) at two shapes one of which a pattern copies
    (run ab's boomerang: `Fillet([hub, blade.b], 8)` beside `CircularPattern(blade, 3, ...)`
    rounded the first blade's roots, the other two sharp): each copy's meeting with the other
    shape is rounded alike, as a CAD pattern copies a fillet feature.  A copy whose outline
    does not meet the other shape is passed over in silence (its original's is what the call
    named).  Run once, after the program."""
    from ..geometry.derived.corners import Chosen
    from ..geometry.derived.fillet_at import outline_spec
    index: dict = {}
    for s in model.structures:
        fin = getattr(s, "finish", None)
        if not fin:
            continue
        ox, oy = s.frame_offset(None)
        for k, (kind, r, at, call) in enumerate(fin):
            more = []
            for c in at or ():
                if c.what != "shapes_meet":
                    continue
                ga, gb = c.curve[2], c.curve[3]
                for side, g in ((0, ga), (1, gb)):
                    for cp in _copies_of(g, index, g.kind):
                        if cp.owner is not s and s not in cp.owner.ancestors():
                            continue
                        pair = (cp, gb) if side == 0 else (ga, cp)
                        specs, pts = [], []
                        for e in pair:
                            spec, ps = outline_spec(e, s)
                            specs.append((spec, len(ps)))
                            pts += [(p.x + ox, p.y + oy) for p in ps]
                        ch = Chosen("shapes_meet", tuple(pts), c.name, curve=tuple(specs) + pair)
                        ch.quiet = True
                        more.append(ch)
            if more:
                fin[k] = (kind, r, list(at) + more, call)


def _copies_of(g, index: dict, kind: str = "Circle") -> list:
    """The shapes of ``kind`` that copies made of ``g``: of ``g`` itself, or of a structure
    that holds it (the shape at the same place in each copy: the same children, the same index
    in its structure's geometry; ``index``: each structure's places, filled as needed)."""
    out = [c for c in g.__dict__.get("pattern_copies", ()) if c.kind == kind]
    st, path = g.owner, []
    at_ = index.get(id(st))
    if at_ is None:
        at_ = index[id(st)] = {id(x): i for i, x in enumerate(st.geometry)}
    k = at_.get(id(g))
    while st is not None and k is not None:
        for copy in st.__dict__.get("pattern_copies", ()):
            at = copy
            for name in reversed(path):
                at = at.children.get(name)
                if at is None:
                    break
            if at is not None and k < len(at.geometry) and at.geometry[k].kind == kind:
                out.append(at.geometry[k])
        path.append(st.name)
        st = st.parent
    return out
