"""Placement in 3D: ``Place`` (a part's rigid placement in the assembled product, by a
position and either rotations about x, y, z or the directions its top face and its drawing's
up look) and ``Bend`` (a part bent along a line), both known before solving and kept on the
part's structure for the assembled outputs (:mod:`aidl_lang.output.part.build.placement`).

A mixin of :class:`aidl_lang.interp.Interpreter`; it uses the other parts through ``self``."""
from __future__ import annotations

import math

from ..base.diagnostics import EvalError, shown_path
from ..base.limits import MAX_EXTENT
from ..geometry.core.values import ANG, LEN, NUM, PV, Q, StructRef, angle_scale, type_name
from .common import DEG, _a

# the directions ``face=`` and ``up=`` take by name (the assembled view's front is -y, where
# the front-left view looks from; up is +z)
DIRECTIONS = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0),
              "+z": (0, 0, 1), "-z": (0, 0, -1), "x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1),
              "right": (1, 0, 0), "left": (-1, 0, 0), "back": (0, 1, 0), "front": (0, -1, 0),
              "up": (0, 0, 1), "top": (0, 0, 1), "down": (0, 0, -1), "bottom": (0, 0, -1)}
_FACE_EG = 'Place(back, position=(0, 40, 0), face="front", up="+z")'


def facing_matrix(face, up) -> tuple:
    """The rotation (3x3, rows of floats) that turns a part's top face (its local +z: the face
    its engravings, countersinks and text are on) to unit vector ``face`` and its drawing's up
    (local +y) as near ``up`` as lies square to it (``up`` less its part along ``face``, as a
    camera's look-at does); local +x is then up x face.  ``face`` and ``up``: 3 floats, any
    length, not parallel (the caller checks).  Axis directions give exact 0 and 1 entries."""
    n = math.sqrt(sum(c * c for c in face))
    f = [c / n for c in face]
    d = sum(a * b for a, b in zip(up, f))
    u = [a - d * b for a, b in zip(up, f)]
    m = math.sqrt(sum(c * c for c in u))
    u = [c / m for c in u]
    x = [u[1] * f[2] - u[2] * f[1], u[2] * f[0] - u[0] * f[2], u[0] * f[1] - u[1] * f[0]]
    return tuple(tuple(float(v) + 0.0 for v in row) for row in zip(x, u, f))


class Placing:
    def _part_to_place(self, conv, node, spans, what: str = "Place", verb: str = "places"):
        """The structure ``Place`` (or ``Bend``) names: a part (or an assembly) inside the
        structure the statement is written in, a child of an assembly; else a located E0108."""
        s = self._need_struct(node.span)
        ref = conv["part"]
        if not isinstance(ref, StructRef):
            raise EvalError("E0108", f"`{what}` {verb} a structure, not {_a(type_name(ref))}",
                            spans.get("part", node.span),
                            hint="name a part: `Place(lid, position=(0, 0, 47))`" if what == "Place"
                            else "name a part: `Bend(wall, at=40, angle=90 deg, radius=5)`")
        target = ref.struct
        if target is s or not target.is_within(s):
            raise EvalError("E0108", f"`{target.path}` is not a part inside `{s.path}`: a part "
                            "is placed by the structure that holds it",
                            spans.get("part", node.span), hint=self._outside_hint(
                                target, s, f"write the `{what}(...)` in `{target.parent.path}`")
                            if target.parent is not None else "place the parts of this structure")
        if target.parent.kind != "assembly":
            raise EvalError("E0108", f"`{target.path}` is not a part: it is merged into "
                            f"{target.parent.kind} `{target.parent.path}`",
                            spans.get("part", node.span),
                            hint="place a part (a child of an assembly) or an assembly; to "
                                 "turn a shape within its part, draw it turned")
        return target

    def _place(self, conv, node, spans):
        """``Place(part, position=(x, y, z), rotation=(rx, ry, rz))``: the part's rigid 3D
        placement (mm and radians, known before solving), kept on its structure as
        ``placement = (position, rotation, span)`` for the assembled outputs; ``rotation``
        is the three angles, or with ``face=``/``up=`` the 3x3 matrix (:meth:`_facing`)."""
        target = self._part_to_place(conv, node, spans)
        prev = getattr(target, "placement", None)
        if prev is not None:
            sp = prev[2]
            line = (f", on line {sp.line}" if sp is None or sp.file == node.span.file else
                    f", in {shown_path(sp.file)} line {sp.line}") if sp is not None else ""
            hint = "a part has one placement: keep one `Place`"
            tmpl = next((a.template for a in target.ancestors()
                         if a.template and sp is not None and sp.file != node.span.file), None)
            if tmpl:
                lift = ("; `lift=` raises what stands on the base" if tmpl in
                        ("gear_train", "rack_and_pinion", "planetary") else "")
                hint = (f"`{tmpl}` places its parts itself: its arguments say where (`aidl docs "
                        f"{tmpl}`{lift})")
            raise EvalError("E0108", f"`{target.path}` is already placed{line}", node.span,
                            hint=hint)
        on = self._placed_on(conv.get("on"), target, spans.get("on", node.span)) \
            if conv.get("on") is not None else None
        pv = conv.get("position")
        on_top = on is not None and (isinstance(pv, PV) or isinstance(pv, (list, tuple))
                                     and len(pv) == 2)
        if on_top and not isinstance(pv, PV):
            pv = [*pv, Q.num(0.0, LEN)]
        pos = self._triple(pv, "position", LEN, spans.get("position"), node)
        if on_top:                  # (x, y): on its top face, once every thickness is known
            self.on_top.append(target)
        if conv.get("face") is not None or conv.get("up") is not None:
            if conv.get("rotation") is not None:
                raise EvalError("E0108", "`Place` is given `rotation=` and `face=`/`up=`: the "
                                "part is turned one way", spans.get("rotation", node.span),
                                hint="keep `face=` and `up=` (which way its top face and its "
                                     "drawing's up look), or `rotation=` alone")
            rot = self._facing(conv, spans, node)
        else:
            rot = self._triple(conv.get("rotation"), "rotation", ANG, spans.get("rotation"),
                               node)
        target.placement = (pos, rot, node.span, on)
        return None

    def _placed_on(self, ref, target, span):
        """``on=`` of ``Place``: the structure whose frame the position and turn are given
        in (a part, an assembly, or a structure of a part such as its mortise); a located
        E0108 for no structure, the part itself or one of its own, or a ring of parts each
        placed on the next."""
        hint = ("name a placed part: `Place(vane, on=top, position=(40, -30), face=\"up\")` "
                "stands the vane on the top's face at its (40, -30)")
        if not isinstance(ref, StructRef):
            raise EvalError("E0108", f"`on=` of `Place` names a structure, not "
                            f"{_a(type_name(ref))}", span, hint=hint)
        on = ref.struct
        if on.is_within(target):
            raise EvalError("E0108", f"`{target.path}` is placed on "
                            + ("itself" if on is target else f"its own `{on.path}`"), span,
                            hint="place it on another part, or leave `on=` out: the "
                                 "position is then in the assembly's frame")
        seen, todo = set(), [on]
        while todo:                 # the frames `on`'s frame is built from: not `target`'s
            s = todo.pop()
            for a in [s, *s.ancestors()]:
                if id(a) in seen:
                    break
                seen.add(id(a))
                pl = getattr(a, "placement", None)
                if pl is not None and pl[3] is not None:
                    if pl[3].is_within(target):
                        raise EvalError("E0108", f"`{target.path}` is placed on `{on.path}`, "
                                        f"which is placed on `{target.path}`"
                                        + ("" if pl[3] is target else f" (`{pl[3].path}`)"),
                                        span, hint="place one of them in the assembly's frame "
                                                   "(no `on=`)")
                    todo.append(pl[3])
                    break
        return on

    def settle_on_top(self) -> None:
        """Each ``Place(part, on=other, position=(x, y))`` set on ``other``'s top face: z its
        thickness (mm; its own, its structures', the file's, else the default; 0 for an
        assembly), once the file's ``thickness`` (run after the structures) is known."""
        from ..output.part.build.sunk import DEFAULT_THICKNESS
        for target in self.on_top:
            pos, rot, span, on = target.placement
            t = 0.0 if on.kind == "assembly" else next(
                (getattr(a, "thickness") for a in [on, *on.ancestors()]
                 if getattr(a, "thickness", None) is not None),
                getattr(self.model, "thickness", None))
            z = float(t if t is not None else DEFAULT_THICKNESS)
            target.placement = ((pos[0], pos[1], z), rot, span, on)
        self.on_top = []

    def _bend(self, conv, node, spans):
        """``Bend(part, at=x, angle=a, radius=r)``: a bend of a solid part in the assembled
        product (mm and radians, known before solving), kept on its structure as ``bends =
        [(at, angle, radius, span)]``; the flat sheet is not changed
        (:func:`~aidl_lang.output.part.build.placement.bend_points`)."""
        target = self._part_to_place(conv, node, spans, "Bend", "bends")
        if target.kind != "solid":
            raise EvalError("E0108", f"`Bend` bends a solid part, not {target.kind} "
                            f"`{target.path}`", spans.get("part", node.span),
                            hint="bend each solid part of it: `Bend(wall, at=40, angle=90 deg, "
                                 "radius=5)`")
        vals = {}
        for k, dim in (("at", LEN), ("angle", ANG), ("radius", LEN)):
            q, sp = conv.get(k), spans.get(k, node.span)
            c = q.const() if isinstance(q, Q) and q.dim in (dim, NUM) else None
            if c is None:
                raise EvalError("E0109", f"`{k}` of `Bend` must be {'an angle' if dim is ANG else 'a length'} "
                                "known before solving", sp,
                                hint="use numbers and params: a bend is not solved, e.g. "
                                     "`Bend(wall, at=40, angle=90 deg, radius=5)`")
            scale = 1.0 if q.dim == dim else ((self.file.unit_scale if self.file else 1.0)
                                              if dim is LEN else angle_scale(q, DEG))
            vals[k] = float(c) * scale
        if not 0 < abs(vals["angle"]) <= 2 * math.pi:
            raise EvalError("E0108", f"the `angle` of `Bend` is {math.degrees(vals['angle']):g} "
                            "deg: a bend turns by more than 0 and at most 360 deg",
                            spans.get("angle", node.span), hint="write e.g. `angle=90 deg` "
                            "(negative: the other way)")
        if vals["radius"] < 0 or not abs(vals["at"]) <= MAX_EXTENT or vals["radius"] > MAX_EXTENT:
            raise EvalError("E0108", f"the `radius` of `Bend` is {vals['radius']:g} mm: an "
                            "inside radius is 0 or more (and `at` within the model extent)",
                            spans.get("radius", node.span), hint="write e.g. `radius=5`")
        bends = getattr(target, "bends", None) or []
        bends.append((vals["at"], vals["angle"], vals["radius"], node.span))
        target.bends = bends
        return None

    def _triple(self, v, what, dim, span, node) -> tuple[float, float, float]:
        """An (x, y, z) of lengths (mm) or angles (radians) known before solving; None: 0."""
        span = span or node.span
        eg = "position=(0, 0, 3 mm)" if dim is LEN else "rotation=(90 deg, 0, 0)"
        if v is None:
            return (0.0, 0.0, 0.0)
        if isinstance(v, PV):
            v = [Q(v.x, LEN), Q(v.y, LEN)] + ([Q.num(0.0, LEN)] if dim is LEN else [])
        if not isinstance(v, (list, tuple)) or len(v) != 3:
            raise EvalError("E0108", f"`{what}` of `Place` must be three "
                            f"{'lengths' if dim is LEN else 'angles'} (x, y, z), got "
                            f"{_a(type_name(v)) if not isinstance(v, (list, tuple)) else f'{len(v)} items'}",
                            span, hint=f"write `{eg}`")
        out = []
        for q in v:
            if not isinstance(q, Q) or q.dim not in (dim, NUM):
                raise EvalError("E0109", f"`{what}` of `Place` must be three "
                                f"{'lengths' if dim is LEN else 'angles'}, got {_a(type_name(q))}",
                                span, hint=f"write `{eg}`")
            c = q.const()
            if c is None:
                raise EvalError("E0109", f"`{what}` of `Place` must be known before solving",
                                span, hint="use numbers and params: a placement is not solved")
            scale = 1.0 if q.dim == dim else ((self.file.unit_scale if self.file else 1.0) if dim is LEN
                                              else angle_scale(q, DEG))
            v = float(c) * scale
            if dim is LEN and not abs(v) <= MAX_EXTENT:
                raise EvalError("E0305", f"`position` of `Place` is {v:g} mm, beyond the model "
                                f"extent of {MAX_EXTENT:g} mm", span,
                                hint="place parts within 1 km of the origin")
            out.append(v)
        return tuple(out)

    def _facing(self, conv, spans, node) -> tuple:
        """``face=`` and ``up=`` of ``Place``: the rotation (3x3, :func:`facing_matrix`) that
        turns the part's top face to ``face`` and its drawing's up towards ``up``; each a name
        of :data:`DIRECTIONS` (``"-y"``, ``"front"``) or three numbers.  ``up`` left out: +z, or
        +y for a face that looks up or down.  E0106 for an ``up`` without a ``face``; E0108 for
        a direction that is none, or an up along the face."""
        face = self._direction(conv.get("face"), "face", spans.get("face", node.span))
        if face is None:
            raise EvalError("E0106", "`Place` with `up=` needs `face=`: which way the part's "
                            "top face (its engraving, its countersinks) looks",
                            spans.get("up", node.span), hint=f"write `{_FACE_EG}`")
        up = self._direction(conv.get("up"), "up", spans.get("up", node.span))
        n2 = sum(c * c for c in face)
        if up is None:
            up = (0.0, 1.0, 0.0) if face[2] * face[2] > 0.998 * n2 else (0.0, 0.0, 1.0)
        along2 = sum(a * b for a, b in zip(up, face)) ** 2 / n2
        u2 = sum(c * c for c in up)
        if u2 - along2 <= 1e-12 * u2:
            raise EvalError("E0108", "`up=` of `Place` lies along `face=`: the drawing's up "
                            "turns to a direction square to the face",
                            spans.get("up", node.span),
                            hint='a part facing "front" (-y) stands with `up="+z"`; one lying '
                                 'face up (`face="+z"`) takes `up="+y"` or `up="-x"`')
        return facing_matrix(face, up)

    def _direction(self, v, what: str, span):
        """A direction of ``Place``: None, a name (:data:`DIRECTIONS`) or three numbers (not
        all zero, known before solving) -> three floats; else E0108."""
        if v is None:
            return None
        hint = ('write "+x", "-x", "+y", "-y", "+z" or "-z", a word ("front" is -y, "back", '
                f'"left", "right", "up", "down") or three numbers such as (0, -1, 1): `{_FACE_EG}`')
        if isinstance(v, str):
            got = DIRECTIONS.get(v.strip().lower().replace(" ", ""))
            if got is None:
                raise EvalError("E0108", f'`{what}="{v}"` of `Place` is no direction', span,
                                hint=hint)
            return tuple(float(c) for c in got)
        if isinstance(v, (list, tuple)) and len(v) == 3:
            out = []
            for q in v:
                c = q.const() if isinstance(q, Q) else None
                if c is None:
                    break
                out.append(float(c))
            else:
                if any(not math.isfinite(c) for c in out) or not any(out):
                    raise EvalError("E0108", f"`{what}=` of `Place` is no direction: its three "
                                    "numbers are 0", span, hint=hint)
                return tuple(out)
        got = _a(type_name(v)) if not isinstance(v, (list, tuple)) else f"{len(v)} items"
        raise EvalError("E0108", f"`{what}=` of `Place` must be a direction known before "
                        f"solving, got {got}", span, hint=hint)
