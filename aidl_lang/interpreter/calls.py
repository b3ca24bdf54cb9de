"""Calls: resolving a callee, primitive and constraint constructors from the registry,
argument coercion to points, lengths and angles, templates, and the built-in functions.

A mixin of :class:`aidl_lang.interp.Interpreter`; it uses the other parts through ``self``."""
from __future__ import annotations

import math

from .. import ast as A
from ..base.diagnostics import EvalError, did_you_mean
from ..geometry.relations.bbox import reach as bbox_reach
from ..geometry.relations.constraints import BUILDERS, ConstraintError
from ..geometry.core.expr import Lin, _lin, _new, as_const, func, lift, mul, var
from ..geometry.relations.members import member as geom_member
from ..geometry.core.model import Constraint, Equation, Point, Scalar
from ..geometry.shapes.constructors import build
from ..geometry.shapes.primitives import PrimitiveError
from ..geometry.core.values import (ANG, LEN, NUM, PV, BBoxRef, Builtin, GeomRef, Namespace, Q, StructRef,
                               Function, Template, UnitError, angle_scale, dim_name, mul_dim, owners_in, owners_of,
                               rad_power, radians_of, type_name)
from ..base.limits import MAX_EXTENT
from ..registry import (ENTRIES, FUNCTIONS, POINT_ALIGNS, accepted_args, bind_variant, canonical,
                        canonical_args, lookup)
from .call_hints import _center_hint, foreign_read, list_arg_hint, shadowed
from .cut_into import cut_into
from .functions import call_function
from .measured import measured_distance, of_shapes
from .common import (_defer_boxes, said_shrunk, DEG, _a, _fmt_num, _src, fraction_hint, show,
                     ANGLE_TWICE)


_DIMS = {"length": LEN, "angle": ANG, "number": NUM}
# argument types a reference to geometry of these kinds passes unchanged (see _coerce)
_GEOM_KINDS = {"line": ("Line", "Slot"), "circular": ("Circle", "Arc"),
               "curve": ("Line", "Circle", "Arc")}
# shapes made from other shapes (their source must be in the same structure: E0201's hint)
DERIVED = ("Offset", "Inset", "Shell", "Hull", "Stroke", "Intersect")


_BUILTINS: dict = {}      # name -> its Builtin value (one per name; values are never changed)


TRANSFORMS = ("Scaled", "Scale", "Translated", "Translate", "Flip")


class Calls:
    def _callee(self, f):
        if type(f) is A.Name:
            name = f.id
            for vars_ in self.scope.chain:   # Scope.lookup, inlined: the first scope that has it
                if name in vars_:
                    v = vars_[name]
                    if v is not None:
                        return v
                    break
            b = _BUILTINS.get(name)
            if b is None and (lookup(name) is not None or name in FUNCTIONS):
                b = _BUILTINS[name] = Builtin(name)
            return b
        if isinstance(f, A.Member):
            obj = self._callee(f.obj) if isinstance(f.obj, (A.Name, A.Member)) else None
            if isinstance(obj, Namespace):
                return obj.scope.vars.get(f.name)
        return None

    def _call(self, node: A.Call, name: str | None = None, callee=None):
        """Evaluate a call (``callee``: ``self._callee(node.func)`` when the caller has it)."""
        if callee is None:
            callee = self._callee(node.func)
        if callee is None:
            if isinstance(node.func, A.Name):
                cands = list(self.scope.names()) + list(ENTRIES) + list(FUNCTIONS)
                sugg = did_you_mean(node.func.id, cands)
                raise EvalError("E0103", f"unknown function `{node.func.id}`", node.func.span,
                                hint=(f"did you mean `{sugg[0]}`?" if sugg else
                                      "see `aidl explain E0103` for the vocabulary"),
                                suggestions=sugg)
            callee = self.eval(node.func)
        if isinstance(callee, Function):
            return call_function(self, callee, node)
        if isinstance(callee, Template):
            if name is None:
                t = callee.node.name
                # (run fo: `bars = [bar(), bar(), bar()]`)
                hint = (f"write `part = {t}(...)`; for several, a loop: `for i in range(3) "
                        f"{{ part = {t}(...) }}` (after it `part` is the list: `part[0]`)")
                comp = next((f[0] for f in reversed(self.frames)
                             if f[0].startswith("the comprehension")), None)
                if comp is not None:     # `[knob(...) for i in ...]` (issue 84's second run)
                    var = comp.split("for ", 1)[1].split(" ", 1)[0]
                    hint = (f"a list comprehension cannot name its instances: write a loop, "
                            f"`for {var} in ... {{ part = {t}(...) }}` (after the loop `part` "
                            "is the list of the copies: `part[0]`)")
                raise EvalError("E0119", f"an instance of template `{t}` needs a name",
                                node.span, hint=hint)
            return self._instantiate(callee, node, name)
        if not isinstance(callee, Builtin):
            raise EvalError("E0111", f"{_a(type_name(callee))} cannot be called", node.func.span)
        nm = callee.name
        if nm in FUNCTIONS:
            return self.finite(self._function(nm, node), node.span)
        entry = lookup(nm)
        args = [self.eval(a) for a in node.args]
        kwargs = {kw.name: (self.eval(kw.value), kw) for kw in node.kwargs}
        variant, ren, reason = bind_variant(entry, len(args), list(kwargs))
        if variant is None:
            span = node.span
            ok = accepted_args(entry)
            bad_kw = next((kw for kw in node.kwargs if kw.name not in ok), None)
            if bad_kw is not None:
                from ..library.reference import entry_units_hint
                from ..library.arg_notes import ARG_NOTES
                from ..registry import near_args
                note = ARG_NOTES.get((entry.name, bad_kw.name))
                raise EvalError("E0105", f"`{nm}` has no argument `{bad_kw.name}`", bad_kw.span,
                                hint=(f"{note}\n" if note else "") +
                                     f"{entry.signature()}\naccepted names: {', '.join(ok)}"
                                     f"\nunits: {entry_units_hint(entry)}",
                                suggestions=[] if note else near_args(bad_kw.name, ok))
            code = "E0106" if reason and reason.startswith("missing") else "E0104"
            raise EvalError(code, f"`{nm}` {reason}", span, hint=entry.signature())
        bound = {}
        spans = {}
        if args:                         # (most geometry calls have keyword arguments only)
            arg_spans = [a.span for a in node.args]
            npos = sum(not a.kw_only for a in variant)
            if len(args) > npos:         # entry.varargs: the extras join the last positional
                args = args[:npos - 1] + [args[npos - 1:]]
                arg_spans[npos - 1:] = [arg_spans[npos - 1].cover(arg_spans[-1])]
            for a, v, span_a in zip(variant, args, arg_spans):
                bound[a.name] = v
                spans[a.name] = span_a
        for k, (v, kw) in kwargs.items():
            bound[ren[k]] = v
            spans[ren[k]] = kw.value.span
        cname = canonical(nm)
        if cname == "Text" and "center" in kwargs and "valign" not in bound:
            bound["valign"] = "middle"        # Text(center=...) means centered on that point
            spans["valign"] = node.span
        bound, spans = canonical_args(nm, bound), canonical_args(nm, spans)
        conv = {}
        for a in variant:
            if a.name in bound:
                try:
                    conv[a.name] = self._coerce(bound[a.name], a.type, spans[a.name], nm,
                                                a.name)
                except EvalError as ex:
                    if a.type == "boxed" and isinstance(bound[a.name], list):
                        ex.hint = list_arg_hint(self, cname, a.name, node, spans, bound) or ex.hint
                    raise
            elif a.default is not None:      # registry defaults are in mm / radians
                dim = _DIMS.get(a.type)
                conv[a.name] = Q.num(a.default, dim) if dim else a.default
        for k, v in conv.items():
            self._check_magnitudes(v, spans.get(k, node.span), k)
        if entry.category == "primitive":
            if conv.get("mirror") is not None and "points" in conv:
                # Polygon(half, mirror="y"): the half, then its mirror images (issue 61)
                conv["points"] = self._mirror(conv["points"], conv["mirror"], node)
            conv.pop("mirror", None)
            return self._primitive(cname, conv, node, spans)
        if entry.category == "placement":
            if cname == "Bend":
                return self._bend(conv, node, spans)
            return self._place(conv, node, spans)
        if entry.category == "operation":
            from ..geometry.derived.operations import OperationError, apply
            self._check_subtree(owners_of(*conv.values()), node.span, self._need_struct(node.span))
            if cname == "CutInto":
                return cut_into(conv, node, spans)
            if cname in ("Countersink", "Counterbore"):
                from .sinks import sink_call
                return sink_call(self, cname, conv, node, spans)
            if cname in ("AllowOverlap", "Fillet", "Chamfer"):
                # W0523 locates one that allows nothing; E0408, W0406 a corner not rounded
                conv = dict(conv, _span=node.span)
            n0 = len(self.model.constraints)
            if cname in TRANSFORMS:          # issue 95: Scale, Translate, Flip of a whole structure
                from ..geometry.derived.transforms import apply
            try:
                out = apply(self, cname, conv, name)
            except OperationError as ex:
                raise EvalError("E0108", str(ex), node.span, hint=entry.signature())
            if cname in ("Scale", "Translate", "Flip") and type(node.args[0] if node.args
                                                              else None) is A.Name:
                self._rebind(node.args[0].id, out)     # in place: the name is the copy's
            owners = owners_of(*conv.values()) if len(self.model.constraints) > n0 else ()
            if len(owners) > 1:
                args = [owners_of(v) for v in conv.values()]   # who moves: the pattern's
                helped = any(g.construction for g in self.struct.geometry) \
                    if self.struct in owners else False
                for c in self.model.constraints[n0:]:
                    if c.args is None:
                        c.args = args
                        if helped and c.owner is self.struct:
                            # a construction rect stays, the target goes to its corner
                            # (run z1's ring toss: the square moved onto the peg, 3 pegs off)
                            c.arg_reach = bbox_reach(conv.values(), least=1)
            return out
        owners = owners_of(*conv.values())
        try:
            eqs = BUILDERS[cname](self, **conv)
        except ConstraintError as ex:
            raise EvalError("E0108", str(ex), node.span,
                            hint=_center_hint(conv.values(), entry.signature()))
        except UnitError as ex:
            raise EvalError("E0109", str(ex), node.span)
        args = [owners_of(v) for v in conv.values()] if len(owners) > 1 else None
        # who moves between shapes of one structure: what each argument reads
        reach = bbox_reach(conv.values()) if len(owners) == 1 else None
        self._add_constraint(cname, eqs, node.span, None, owners, args, reach)
        if args is not None:
            self._helper_reach(conv.values(), owners)
        return None

    def _rebind(self, name: str, value) -> None:
        """``name`` (where it is bound, innermost first) now means ``value``."""
        for vars_ in self.scope.chain:
            if name in vars_:
                vars_[name] = value
                return

    def _primitive(self, kind, conv, node, spans):
        s = self.struct
        if s is None:
            s = self._need_struct(node.span)
        mine = s._own                    # frozenset({s}) once made: the owners of s's points
        for k, v in conv.items():
            t = type(v)
            if t is Q or t is PV:
                own = v.owners
                if not own or own is mine:
                    continue
            elif t is GeomRef:
                if v.geom.owner is s:
                    continue             # geometry of this structure
                own = owners_of(v)
            elif t is bool or t is str or v is None:
                continue                 # no geometry
            else:
                own = owners_of(v)
            if not own or (s in own and len(own) == 1):
                continue
            bad = [o for o in owners_of(v) if o is not s]
            if bad:
                hint = ("geometry may only use geometry of its own structure; give it its "
                        "own starting value and relate the two with a constraint, "
                        "e.g. `Coincident(...)`, in a structure that contains both")
                if kind in DERIVED and t is GeomRef:
                    hint = (f"`{kind}` makes its shape from a shape of its own structure: write "
                            f"it in `{bad[0].path}`, where `{v.geom.name or k}` is"
                            + (f" (a frame or wall cut from it: `Shell({v.geom.name or k}, "
                               "-thickness)` there)" if kind in ("Offset", "Inset") else "")
                            + ", or draw the shape again here and place it with a constraint")
                if kind == "Text" and k == "along":
                    hint = ("a Text follows a curve of its own drawing: draw one there, "
                            "`ring = Circle(center=(0, 0), radius=30, construction=true)`, "
                            f"and put its center on the shape's with `Coincident(...)` in "
                            f"`{bad[0].path}`")
                read = foreign_read(self, node, spans.get(k), bad[0])
                if read is not None and kind not in DERIVED and not (kind == "Text"
                                                                     and k == "along"):
                    # run ck: `polar(disc.center, 46, a)` in a drawing inside the disc's part
                    hint = (f"use numbers where `{read}` is (the point as written, in the "
                            f"same frame: a child's coordinates are its parent's unless a "
                            f"relation moves it), or write this shape in `{bad[0].path}`, or "
                            f"give it its own starting value and relate the two with a "
                            f"constraint in a structure that contains both")
                raise EvalError("E0201", f"geometry in `{s.path}` refers to "
                                + (f"`{read}` (in its `{k}`)" if read else f"`{k}`")
                                + f" of `{bad[0].path}`, another structure",
                                spans.get(k, node.span), hint=hint)
        if conv.get("fill"):
            from .fonts import check_fill
            check_fill(conv, s, node, spans, kind)
        if kind == "Text" and conv.get("font") is not None:
            from .fonts import text_font
            text_font(self, conv, s, node, spans)
        elif kind == "Text" and s.kind != "drawing" and not (
                conv.get("stencil") and s.kind in ("hole", "solid")):
            raise EvalError("E0120", f"Text must be in a `drawing` structure, not in {s.kind} `{s.name}`",
                            node.span, hint="put it in `drawing labels { ... }` inside this structure"
                            " (or cut the letters out: `hole h { t = Text(..., stencil=true) }`)"
                            if s.kind != "cut" else "a cut holds curves to cut along: engrave "
                            "the text in `drawing labels { ... }` in the solid around the cut")
        self.n_geometry += 1
        if self.n_geometry > self.budget.geometry:
            raise EvalError("E0303", f"more than {self.budget.geometry} geometry objects", node.span,
                            hint="use fewer or larger repetitions, or raise `--budget`")
        if self.objects >= self.budget.objects:      # self.count_object(node.span), inline
            self.count_object(node.span)
        self.objects += 1
        if kind == "Drawing2D":
            conv = dict(conv, _drawing=self._load_drawing(conv, s, node, spans))
        try:
            g = build(self, kind, conv, node.span)
        except PrimitiveError as ex:
            raise EvalError("E0108", str(ex), node.span,
                            hint=getattr(ex, "hint", None) or lookup(kind).signature())
        if kind == "Text":
            from ..geometry.shapes.text import missing_glyphs, text_extent
            self.check_size(len(g.data["text"]), node.span, "a Text")
            g.data["extent"] = g.data.get("extent") or text_extent(g.data["text"], g.data["size"], g.data["anchor"],
                                           g.data["valign"], g.data["rotation"])
            if g.data.get("shrunk"):
                said_shrunk(self.sink, g, spans.get("max_width", node.span))
            lost = [] if g.data.get("font") else missing_glyphs(g.data["text"])
            if g.data.get("font"):
                from .fonts import font_missing
                font_missing(self, g, spans, node)
            if lost:
                from .fonts import stroke_font_missing
                stroke_font_missing(self, g, lost, spans.get("text", node.span))
        r = _new(GeomRef)              # GeomRef(g) without the class call
        r.geom = g
        return r

    def _load_drawing(self, conv, s, node, spans):
        """The :class:`~aidl_lang.drawing.Drawing` of a ``Drawing2D`` call, read once per
        compile per (real path, selection); its notes are warnings at the call, and an open
        or self-crossing chain where an outline is needed is E0131 (with the gap and where)."""
        from ..drawing import DrawingError, read_drawing
        from ..library.sources import ImportRefused, load_drawing
        at = spans.get("file", node.span)

        def sel(v, what):
            if v is None or isinstance(v, str):
                return v
            if isinstance(v, Q) and v.const() is not None and what == "color":
                return int(v.const())
            if isinstance(v, (list, tuple)):
                return [sel(x, what) for x in v]
            raise EvalError("E0108", f"`{what}=` of Drawing2D takes a name or a list of names"
                            + (" (DXF colours: ACI numbers; SVG: \"#rrggbb\")" if what == "color"
                               else ""), spans.get(what, node.span))
        layer, color, ident = sel(conv.get("layer"), "layer"), sel(conv.get("color"), "color"), \
            sel(conv.get("id"), "id")
        roles = {k: sel(conv.get(k), "color") for k in ("cut", "engrave", "ignore")}
        roles["roles"] = conv.get("roles")
        tol = conv.get("close_tolerance")
        if tol is not None:
            tol = tol.const() if isinstance(tol, Q) else tol
            if tol is None:
                raise EvalError("E0108", "close_tolerance= of Drawing2D takes a number (mm)",
                                spans.get("close_tolerance", node.span))
        raw = conv["file"]
        try:
            real, data = load_drawing(raw, self.file.path)
        except ImportRefused as ex:
            raise EvalError(ex.code, ex.message, at, hint=ex.hint,
                            suggestions=ex.suggestions) if ex.suggestions else \
                EvalError(ex.code, ex.message, at, hint=ex.hint)
        cache = self.__dict__.setdefault("_drawings", {})
        key = (str(real), repr(layer), repr(color), repr(ident), conv.get("units"), tol,
               repr(roles))
        d = cache.get(key)
        if d is None:
            try:
                d = read_drawing(data, raw, layer=layer, color=color, ident=ident,
                                 unit=conv.get("units"), close_tolerance=tol, **roles)
            except DrawingError as ex:
                raise EvalError(ex.code, ex.message, at, hint=ex.hint or None)
            cache[key] = d
            for n in d.notes:
                self.sink.warning(n.code, n.message, at, hint=n.hint or None)
        if s.kind != "drawing" and not conv.get("construction") and d.paths:
            # the open chains of a Drawing2D in a `cut` are through-cuts (issue 59); a loop
            # that crosses itself is not.  In a solid an open chain stays E0131: a gap in an
            # outline (a slip) must not become a cut silently
            through = s.kind == "cut"
            p = next((q for q in d.paths if q.crossing is not None), None) if through \
                else d.paths[0]
            if p is None:
                return d
            if p.crossing is not None:
                x, y = p.crossing
                raise EvalError("E0131", f"a loop of `{raw}` crosses itself at ({x:.6g}, "
                                f"{y:.6g}) mm (drawing coordinates): it cannot be an outline "
                                f"of {s.kind} `{s.name}`", at,
                                hint="fix the drawing, select other layers or ids, or put "
                                     "the Drawing2D in a `drawing` (engraving)")
            gap = math.dist(p.start, p.end)
            raise EvalError("E0131", f"{len(d.paths)} open chain{'s' if len(d.paths) > 1 else ''}"
                            f" in `{raw}` where {s.kind} `{s.name}` needs closed outlines: the "
                            f"first has a gap of {gap:.6g} mm from ({p.end[0]:.6g}, "
                            f"{p.end[1]:.6g}) to ({p.start[0]:.6g}, {p.start[1]:.6g}) mm "
                            f"(drawing coordinates)", at,
                            hint="close the outline in the drawing, raise close_tolerance= "
                                 f"above {gap:.3g} mm if the gap is a slip, select only closed "
                                 "outlines with layer=/id= (or engrave= them), put the "
                                 "Drawing2D in a `drawing` (engraving) or give it "
                                 "construction=true, or, for slits the laser cuts along, read "
                                 "them with a second Drawing2D inside a `cut` of the solid")
        return d

    # -- used by primitives.build
    def point(self, v: PV, label: str) -> Point:
        s = self.struct
        o = v.obj
        if o is not None and o.owner is s:
            return o
        if self.objects >= self.budget.objects:      # self.count_object(...), inline
            self.count_object(self.cur_span)
        self.objects += 1
        x, y = v.x, v.y                               # as_const(v.x), as_const(v.y)
        cx = (None if x.terms else x.const) if type(x) is Lin else as_const(x)
        cy = (None if y.terms else y.const) if type(y) is Lin else as_const(y)
        x0 = cx if cx is not None else self.value_of(v.x)
        y0 = cy if cy is not None else self.value_of(v.y)
        ix, iy = self.model.new_pair(x0, y0, True, s, label)
        p = _new(Point)                # Point(ix, iy, s, None, label) without the class call
        p.ix = ix
        p.iy = iy
        p.owner = s
        p.span = None
        p.label = label
        if cx is None or cy is None:
            c = Constraint("internal", s, None, [Equation(var(ix) - v.x), Equation(var(iy) - v.y)],
                           text=f"{label} placed at a derived point", implicit=True)
            _defer_boxes(c)
            s.constraints.append(c)
            self.model.constraints.append(c)
        return p

    def scalar(self, q: Q, label: str, held: bool) -> Scalar:
        c = q.const()
        if c is not None:
            return self.new_scalar(c, label, held)
        sc = self.new_scalar(self.value_of(q.expr), label, held=False)
        c2 = Constraint("internal", self.struct, None, [Equation(var(sc.index) - q.expr)],
                        text=f"{label} from an expression", implicit=True)
        _defer_boxes(c2)
        self.struct.constraints.append(c2)
        self.model.constraints.append(c2)
        return sc

    def new_scalar(self, value: float, label: str, held: bool) -> Scalar:
        i = self.model.new_param(value, not held, self.struct, label)
        return Scalar(i, self.struct, "length", label)

    def internal(self, g, eqs, text: str) -> None:
        c = Constraint("internal", self.struct, g.span, eqs, text=text, implicit=True)
        _defer_boxes(c)         # `Rectangle(center=(c.center.x, c.bb.bottom))`: was a TapeError
        self.struct.constraints.append(c)
        self.model.constraints.append(c)

    # ------------------------------------------------------------------ coercion
    def _to_point(self, v, span) -> PV:
        if isinstance(v, PV):
            return v
        if isinstance(v, GeomRef) and v.geom.kind == "Point":
            return geom_member(v.geom, "p", self.struct)
        if isinstance(v, (tuple, list)) and len(v) == 2 and isinstance(v[0], Q) \
                and isinstance(v[1], Q):
            x, y = self._as_length(v[0], span), self._as_length(v[1], span)
            return PV(x, y, None, owners_in(v))
        raise EvalError("E0108", f"expected a point, got {type_name(v)}", span,
                        hint=_center_hint([v], "write a point as `(x, y)` or refer to one, "
                                               "e.g. `rect.top_left`"))

    def _as_length(self, q: Q, span):
        if q.dim == LEN:
            return q.expr
        if q.dim == NUM:
            f = self.file               # lift(q.expr) * self.unit_scale
            return mul(lift(q.expr), f.unit_scale if f else 1.0)
        raise EvalError("E0109", f"expected a length, got a {dim_name(q.dim)}", span,
                        hint="give a length unit such as `mm` or `in`")

    def _floor_used(self, v: Q, span) -> None:
        """A bare number made by ``//`` is used as a length at ``span``: W0106."""
        q, node, exact = self.floor_results[id(v)]
        if q is v:
            self.floor_as_length(node, exact, q, span)

    def _coerce(self, v, typ: str, span, fname: str, aname: str):
        t = type(v)                    # the common cases first: nothing to convert
        if t is Q:
            if v.dim == _DIMS.get(typ):
                return v
        elif t is PV:
            if typ == "point" or typ == "geometry":
                return v
        elif t is GeomRef:
            if typ in _GEOM_KINDS:
                if v.geom.kind in _GEOM_KINDS[typ]:
                    return v
            elif typ == "boxed" or typ == "geometry" or typ == "any":
                return v
            elif typ == "point" and v.geom.kind == "Point":
                return geom_member(v.geom, "p", self.struct)
        elif t is StructRef or t is BBoxRef:
            if typ == "boxed" or typ == "any":
                return v
        if typ == "any":
            return v
        if v is None and typ == "point":
            return None
        if typ in ("length", "angle", "number"):
            if not isinstance(v, Q):
                raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be {_a(typ)}, got {type_name(v)}", span,
                                hint=shadowed(self, v, span) or (
                                    lookup(fname).signature() if lookup(fname) is not None
                                    else FUNCTIONS[fname][2].split(":")[0] if fname in FUNCTIONS
                                    else None))
            want = _DIMS[typ]
            if v.dim == want:
                return v
            if v.dim == NUM:
                if self.floor_results and typ == "length" and id(v) in self.floor_results:
                    self._floor_used(v, span)
                k = self.unit_scale if typ == "length" else angle_scale(v, DEG)   # pi: radians
                e = v.expr
                if type(e) is Lin and not e.terms:     # a number: what mul() gives, directly
                    return Q(_lin({}, k * e.const), want, v.owners)
                return Q(lift(e) * k, want, v.owners)
            raise EvalError("E0109", f"argument `{aname}` of `{fname}` must be {_a(typ)}, got {_a(dim_name(v.dim))}", span,
                            hint=ANGLE_TWICE if typ == "angle" and v.dim == (0, 2) else
                            (fraction_hint(_src(self.sink, span)) if min(v.dim) < 0 else None) or
                            f"write it with {_a(typ)} unit" + (" such as `mm`" if typ == "length" else
                                                               " such as `deg`" if typ == "angle" else ""))
        if typ == "point":
            if isinstance(v, Q) and v.dim == LEN and canonical(fname) in (
                    "HorizontalDistance", "VerticalDistance"):
                # `HorizontalDistance(tab.bb.left, ring.center, 7 mm)` (issue 111's zipper pull)
                ax = "x" if canonical(fname) == "HorizontalDistance" else "y"
                raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a point, got "
                                "a length (a coordinate)", span,
                                hint=f"`{fname}` measures between two points; for a distance "
                                     f"from a coordinate (`tab.bb.left`), write an equation on "
                                     f"the other point's `.{ax}`: `ring.center.{ax} == "
                                     f"tab.bb.left + 7 mm`")
            return self._to_point(v, span)
        if typ == "points":
            if not isinstance(v, (list, tuple)):
                raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a list of points, got {type_name(v)}", span)
            return [self._to_point(p, span) for p in v]
        if typ == "bool":
            if not isinstance(v, bool):
                raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be true or false, got {type_name(v)}", span)
            return v
        if typ == "string":
            if isinstance(v, Q) and v.const() is not None:
                return _fmt_num(v.const())
            if not isinstance(v, str):
                raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a string, got {type_name(v)}", span)
            return v
        if typ == "line":
            if isinstance(v, GeomRef) and v.geom.kind in ("Line", "Slot"):
                return v
            raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a Line, got {type_name(v)}", span,
                            hint="rectangle edges are lines: `rect.top`, `rect.left`, ...")
        if typ == "circular":
            if isinstance(v, GeomRef) and v.geom.kind in ("Circle", "Arc"):
                return v
            raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a Circle or Arc, got {type_name(v)}", span)
        if typ == "centered":
            return self._centered(v, span, fname, aname)
        if typ == "curve":
            if isinstance(v, GeomRef) and v.geom.kind in ("Line", "Circle", "Arc"):
                return v
            raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a Line, Circle or Arc, got {type_name(v)}", span)
        if typ == "geometry":
            if isinstance(v, (GeomRef, PV)):
                return v
            if isinstance(v, (tuple, list)):
                return self._to_point(v, span)
            raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be geometry, got {type_name(v)}", span)
        if typ == "boxed":
            if isinstance(v, (GeomRef, StructRef, BBoxRef)):
                return v
            if t is PV and canonical(fname) in POINT_ALIGNS:
                return v        # `AlignCenterX(cuff, sock.points[0])`: the point's x (run z7)
            if isinstance(v, (list, tuple)) and v and canonical(fname) == "Mirrored":
                # Mirrored(legs, axis): each item mirrored, a list back (issue 61)
                bad = next((x for x in v if not isinstance(x, (GeomRef, StructRef))), None)
                if bad is None:
                    return list(v)
                raise EvalError("E0108", f"`Mirrored` of a list mirrors structures and shapes, "
                                f"but the list holds {_a(type_name(bad))}", span,
                                hint="mirror a list of structures or shapes (`Mirrored(legs, "
                                     "axis)`), or each item by itself")
            raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a structure or "
                            f"geometry, got {type_name(v)}", span,
                            hint="name a structure (`self`, `lid`) or a shape (`lid.body`)")
        return v

    def _centered(self, v, span, fname: str, aname: str):
        """An argument of type ``centered`` (Concentric): a shape with a ``center`` member or
        a point; a structure or a shape without one is E0108 with a hint that names the
        member to use (a template instance: its first circle, `gear.hub`)."""
        if isinstance(v, PV):
            return v
        if isinstance(v, (tuple, list)):
            return self._to_point(v, span)
        if isinstance(v, GeomRef):
            if v.geom.kind == "Point":
                return geom_member(v.geom, "p", self.struct)
            entry = lookup(v.geom.kind)
            if entry is not None and "center" in entry.members:
                return v
        hint = "name a shape with a center (a Circle, an ArcSlot, ...) or a point"
        if isinstance(v, StructRef):
            own = [(n, x.geom) for n, x in v.struct.scope.items()
                   if isinstance(x, GeomRef) and x.geom.owner is v.struct
                   and "center" in getattr(lookup(x.geom.kind), "members", {})]
            own.sort(key=lambda ng: (ng[1].kind != "Circle", ng[1].construction))
            if own:
                n, g = own[0]
                hint = (f"a structure has no center of its own: name its shape, "
                        f"`{v.struct.name}.{n}` (a {g.kind}), or the point "
                        f"`{v.struct.name}.{n}.center`")
            else:
                hint = "a structure has no center of its own: name a shape in it"
        elif isinstance(v, GeomRef):
            hint = (f"a {v.geom.kind} has no center member; name a point "
                    f"(`{v.geom.name or 'shape'}.bb.center`, a point of it) or a shape with a center")
        raise EvalError("E0108", f"argument `{aname}` of `{fname}` must be a shape with a center "
                        f"or a point, got {type_name(v)}", span, hint=hint)

    # ------------------------------------------------------------------ functions
    def _function(self, nm: str, node: A.Call):
        lo, hi, _doc = FUNCTIONS[nm]
        kw = {}
        if nm == "mirror" and len(node.kwargs) == 1 and node.kwargs[0].name in (
                "about", "axis", "line", "across") and len(node.args) == 1:
            kw["about"] = self.eval(node.kwargs[0].value)
        elif node.kwargs:
            raise EvalError("E0105", f"`{nm}` takes no keyword arguments" + (
                " but `about=`" if nm == "mirror" else ""), node.kwargs[0].span)
        if nm == "range":       # `//` in range(): E0108 gives the count, not W0106 (run gx)
            self.reported.update(("W0106", d.span) for a in node.args
                                 for d in _divisions(a) if d.op == "//")
        args = [self.eval(a) for a in node.args]
        if nm == "mirror":
            return self._mirror(args[0], kw.get("about", args[1] if len(args) > 1 else "y"),
                                node)
        if not lo <= len(args) <= hi:
            raise EvalError("E0104", f"`{nm}` takes {lo if lo == hi else f'{lo} to {hi}'} "
                            f"argument{'s' if hi > 1 else ''}, got {len(args)}", node.span)
        sp = node.span
        if nm == "range":
            ns = [self._int(a, sp, e) for a, e in zip(args, node.args)]
            r = range(*ns)
            if len(r) > self.budget.items:
                raise EvalError("E0301", f"range of {len(r)} items exceeds the limit of "
                                f"{self.budget.items}", sp, hint="use fewer items, or raise `--budget`")
            return [Q.num(i) for i in r]
        if nm == "len":
            if not isinstance(args[0], (list, tuple, str)):
                raise EvalError("E0108", f"`len` needs a list or string, got {type_name(args[0])}", sp)
            return Q.num(len(args[0]))
        if nm == "str":
            v = args[0]
            text = _fmt_num(v.const()) if isinstance(v, Q) and v.const() is not None else show(v, self.unit_scale)
            self.check_size(len(text), sp, "a string")
            return text
        if nm == "sum":                 # `sum([len(row) for row in dia])`
            items = args[0] if isinstance(args[0], (list, tuple)) else [args[0]]
            if not items:
                return Q.num(0.0)
            acc = self._q(items[0], sp)
            for x in items[1:]:
                q = self._q(x, sp)
                a, b, d = self._unify(acc, q, sp)
                acc = Q(a + b, d, acc.owners | q.owners)
            return acc
        if nm in ("min", "max"):
            if len(args) == 1 and isinstance(args[0], list):
                args = args[0]
            if not args:
                raise EvalError("E0108", f"`{nm}` of an empty list", sp)
            qs = [self._q(a, sp) for a in args]
            acc = qs[0]
            for q in qs[1:]:
                a, b, d = self._unify(acc, q, sp)
                # the least of radians is radians (`max(pi / 8, tau / n)`)
                k = rad_power(acc) if rad_power(acc) == rad_power(q) else 0
                acc = radians_of(Q(func(nm, a, b), d, acc.owners | q.owners), k)
            return acc
        if nm == "norm":
            p = self._to_point(args[0], sp) if not isinstance(args[0], Q) else None
            if p is None:
                return Q(func("abs", args[0].expr), args[0].dim, args[0].owners)
            return Q(func("sqrt", p.x * p.x + p.y * p.y), LEN, p.owners)
        if nm == "distance":
            if of_shapes(args):
                return measured_distance(self, args, sp)     # of shapes: in an assert
            p, q = self._to_point(args[0], sp), self._to_point(args[1], sp)
            return Q(func("sqrt", (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y)), LEN,
                     p.owners | q.owners)
        if nm == "polar":
            c = self._to_point(args[0], sp)
            r = self._coerce(args[1], "length", sp, "polar", "radius")
            a = self._coerce(args[2], "angle", sp, "polar", "angle")
            ca, sa = func("cos", a.expr), func("sin", a.expr)
            return PV(c.x + r.expr * ca, c.y + r.expr * sa, None,
                      c.owners | r.owners | a.owners)
        q = [self._q(a, sp) for a in args]
        if nm in ("sin", "cos", "tan"):
            if q[0].dim not in (ANG, NUM):
                got = dim_name(q[0].dim)
                twice = q[0].dim == (0, 2)          # `sin(atan2(y, x) * 1 rad)`
                raise EvalError("E0109", f"`{nm}` needs an angle, got {_a(got)}", sp,
                                hint=ANGLE_TWICE if twice else
                                "give it an angle (`30 deg`, `pi / 6`)")
            if q[0].dim == NUM and rad_power(q[0]) != 1:          # `cos(3 * pi)` is meant
                self._plain_radians(nm, q[0].const(), sp)
            return Q(func(nm, q[0].expr), NUM, q[0].owners)
        if nm in ("asin", "acos", "atan"):
            self._dimless(q[0], nm, sp)
            c = q[0].const()
            if nm != "atan" and c is not None and abs(c) > 1 + 1e-12:
                raise EvalError("E0112", f"`{nm}` of {_fmt_num(c)}: outside -1 .. 1", sp,
                                hint="the value it is given comes from params set past what "
                                     "they allow: keep it within -1 .. 1 (a ratio of a length "
                                     "to a larger one)")
            return Q(func(nm, q[0].expr), ANG, q[0].owners)
        if nm == "atan2":
            a, b, _ = self._unify(q[0], q[1], sp)
            return Q(func("atan2", a, b), ANG, q[0].owners | q[1].owners)
        if nm == "sqrt":
            d = q[0].dim
            if d[0] % 2 or d[1] % 2:
                raise EvalError("E0109", f"`sqrt` of a {dim_name(d)} has no unit", sp)
            c = q[0].const()
            if c is not None and c < 0:
                raise EvalError("E0112", f"`sqrt` of a negative number ({_fmt_num(c)})", sp)
            k = rad_power(q[0])                 # sqrt(pi * pi): radians
            return radians_of(Q(func("sqrt", q[0].expr), (d[0] // 2, d[1] // 2), q[0].owners),
                              k // 2 if k % 2 == 0 else 0)
        if nm in ("exp", "log"):        # run ah's Galton board: a bell curve
            if q[0].dim != NUM:
                raise EvalError("E0109", f"`{nm}` takes a plain number, not {_a(dim_name(q[0].dim))}", sp,
                                hint="divide lengths by lengths: `exp(-(x / sigma) ** 2 / 2)`")
            if nm == "log" and q[0].const() is not None and q[0].const() <= 0:
                raise EvalError("E0112", f"`log` of {_fmt_num(q[0].const())}: not above 0", sp)
            return Q(func(nm, q[0].expr), NUM, q[0].owners)
        if nm == "abs":
            return radians_of(Q(func("abs", q[0].expr), q[0].dim, q[0].owners), rad_power(q[0]))
        if nm == "square":
            return Q(q[0].expr * q[0].expr, mul_dim(q[0].dim, q[0].dim), q[0].owners)
        if nm in ("round", "floor", "ceil"):
            c = q[0].const()
            if c is None:
                raise EvalError("E0118", f"`{nm}` of a solved value", sp,
                                hint="round params and constants only")
            k = rad_power(q[0])                 # round(pi / 4, 3): still radians
            if nm == "round":
                nd = int(q[1].const() or 0) if len(q) > 1 else 0
                return radians_of(Q.num(round(c, nd), q[0].dim), k)
            return radians_of(Q.num(math.floor(c) if nm == "floor" else math.ceil(c), q[0].dim), k)
        if nm == "radians":     # (of an angle: that angle, not its radians read as degrees: run ho)
            return q[0] if q[0].dim == ANG else Q(lift(q[0].expr) * DEG, ANG, q[0].owners)
        if nm == "degrees":
            e = q[0].expr if q[0].dim == ANG else q[0].expr
            return Q(lift(e) * (1 / DEG), NUM, q[0].owners)
        raise EvalError("E0103", f"unknown function `{nm}`", sp)

    def _mirror(self, pts, about, node) -> list:
        """``mirror(points, about)``: the points, then their reflections in reverse order, so
        that a Polygon or closed Spline through them is symmetric; a first or last point on
        the axis is not repeated.  ``about``: "y" (x -> -x: exact), "x" (y -> -y), or a Line
        (reflected across it as it starts, before solving)."""
        sp = node.span
        if not isinstance(pts, (list, tuple)) or isinstance(pts, tuple) and len(pts) == 2 \
                and all(isinstance(v, Q) for v in pts):
            raise EvalError("E0108", f"`mirror` takes a list of points, got {type_name(pts)}",
                            node.args[0].span if node.args else sp,
                            hint='write `mirror([(0, -20), (10, -10), (0, 20)], about="y")`')
        P = [self._to_point(v, sp) for v in pts]
        if isinstance(about, str) and about.lower() in ("y", "x"):
            sx, sy = (-1.0, 1.0) if about.lower() == "y" else (1.0, -1.0)

            def refl(p):
                return PV(p.x * sx, p.y * sy, None, p.owners)
        elif isinstance(about, GeomRef) and about.geom.kind in ("Line", "Slot"):
            s_, e_ = (geom_member(about.geom, n, self.struct) for n in ("start", "end"))
            ax, ay = self.value_of(s_.x), self.value_of(s_.y)
            dx, dy = self.value_of(e_.x) - ax, self.value_of(e_.y) - ay
            L = math.hypot(dx, dy)
            if not L > 0:
                raise EvalError("E0108", "`mirror` about a Line of zero length", sp)
            L2 = dx * dx + dy * dy
            c2, s2 = (dx * dx - dy * dy) / L2, 2 * dx * dy / L2   # cos, sin of twice the angle

            def refl(p):
                # p' = a + [[cos 2t, sin 2t], [sin 2t, -cos 2t]] (p - a): rational in the
                # line's direction, so a line at 0, 45 or 90 degrees reflects exactly
                qx, qy = p.x - ax, p.y - ay
                return PV(qx * c2 + qy * s2 + ax, qx * s2 - qy * c2 + ay, None, p.owners)
        else:
            raise EvalError("E0108", f"`mirror` reflects about \"y\" (the y axis), \"x\" or a "
                            f"Line, got {type_name(about) if not isinstance(about, str) else repr(about)}",
                            sp, hint='write `about="y"` for a shape symmetric left and right')
        if not P:
            return []
        M = [refl(p) for p in P]

        def on_axis(p, m) -> bool:
            try:
                px, py = self.value_of(p.x), self.value_of(p.y)
                mx, my = self.value_of(m.x), self.value_of(m.y)
            except (TypeError, AttributeError):
                return False
            return math.hypot(px - mx, py - my) <= 1e-9 * max(1.0, abs(px), abs(py))
        back = M[::-1]
        if on_axis(P[-1], M[-1]):
            back = back[1:]
        if back and len(P) > 1 and on_axis(P[0], M[0]):
            back = back[:-1]
        self.check_size(len(P) + len(back), sp, "a list")
        return P + back

    def _dimless(self, q: Q, nm, sp):
        if q.dim != NUM:
            raise EvalError("E0109", f"`{nm}` needs a plain number, got a {dim_name(q.dim)}", sp)

    def _plain_radians(self, nm: str, c, sp) -> None:
        """W0107 once per call site: ``sin``/``cos``/``tan`` of a plain number past a whole turn
        (2 pi), which reads radians where a degree was almost surely meant (``cos(i * 10)``
        for labels every 10 degrees: 10 rad is 573 deg)."""
        if c is None or abs(c) <= 2 * math.pi + 1e-9:
            return
        said = self.__dict__.setdefault("_radians_said", set())
        if sp in said:
            return
        said.add(sp)
        self.sink.warning("W0107", f"`{nm}` reads a plain number as radians, and this one "
                          f"reaches {_fmt_num(c)} ({_fmt_num(math.degrees(c))} deg)", sp,
                          hint=f"an angle in degrees takes `deg`: `{nm}(i * 10 deg)`, "
                               f"`{nm}(30 deg)`; a plain number is only degrees where an "
                               "argument is an angle (rotation=, angle=)")

    def _q(self, v, sp) -> Q:
        if isinstance(v, bool):
            return Q.num(1.0 if v else 0.0)
        if isinstance(v, Q):
            return v
        raise EvalError("E0108", f"expected a number, got {type_name(v)}", sp)

    def _int(self, v, sp, arg=None) -> int:
        """``v``, an argument of ``range()`` (written ``arg``), as a whole number, or E0108."""
        q = self._q(v, sp)
        c = q.const()
        if c is None or q.dim != NUM:
            # run ex's peg board: a count from `x / pitch` where x was a bare number in the
            # file's unit and pitch a length: a number per mm, "needs plain whole numbers"
            # with no word of what it got
            from ..geometry.core.values import dim_name
            per = {(-1, 0): " per mm", (1, 0): " mm", (0, 1): " rad"}.get(q.dim)
            got = ("a value known only after solving" if c is None else
                   f"{_fmt_num(c)}{per} (a {dim_name(q.dim)})" if per else
                   f"a {dim_name(q.dim)}")
            hint = ("a count is a plain number: divide a length by a length (`width / "
                    "pitch`, both with units, or both bare) and round it (`floor(...)`)"
                    if q.dim != NUM else "a count must be known before solving: compute it "
                    "from numbers and params, not from a shape's solved size")
            bare = [d for d in _divisions(arg) if isinstance(d.right, A.Num)
                    and d.right.unit is None] if q.dim == LEN and c is not None else []
            if bare:            # `range(slot_len // 10 + 1)`: the divisor a length too
                src, d = self.sink.sources.get(arg.span.file, ""), bare[0]
                a0, r1, end = arg.span.start, d.right.span.end, arg.span.end
                hint = (f"a count is a plain number: divide the length by a length, `range("
                        f"{src[a0:r1]} mm{src[r1:end]})`" + ("" if d.op == "//" else " rounded"))
            raise EvalError("E0108", f"range() needs plain whole numbers, got {got}", sp,
                            hint=hint)
        if abs(c - round(c)) > 1e-9:
            raise EvalError("E0108", f"range() needs whole numbers, got {_fmt_num(c)}", sp)
        return int(round(c))

    # ------------------------------------------------------------------ magnitudes
    def _check_magnitudes(self, v, span, arg: str) -> None:
        """Arguments of primitives, constraints and operations: every number known before
        solving must be finite (E0112), and lengths and coordinates within the model extent
        :data:`~aidl_lang.base.limits.MAX_EXTENT` (E0305)."""
        t = type(v)
        if t is Q:                     # the common case: one number
            e = v.expr
            if type(e) is Lin:
                if e.terms:
                    return
                c = e.const
            else:
                c = v.const()
                if c is None:
                    return
            if c - c == 0.0 and (v.dim != LEN or abs(c) <= MAX_EXTENT):
                return                 # finite, and within the extent
        elif t is GeomRef or t is StructRef or t is str or t is bool:
            return
        if isinstance(v, (list, tuple)):
            for item in v[:10_000]:
                self._check_magnitudes(item, span, arg)
            return
        if isinstance(v, PV):
            vals = [(as_const(v.x), True), (as_const(v.y), True)]
        elif isinstance(v, Q):
            vals = [(v.const(), v.dim == LEN)]
        else:
            return
        for c, is_len in vals:
            if c is None:
                continue
            if not math.isfinite(c):
                raise EvalError("E0112", f"`{arg}` is {_nonfinite(c)}", span,
                                hint="a computation overflowed or divided by a tiny number; "
                                     "check the expression")
            if is_len and abs(c) > MAX_EXTENT:
                raise EvalError("E0305", f"`{arg}` is {c:.4g} mm, beyond the model extent of "
                                f"{MAX_EXTENT:.0e} mm", span,
                                hint="models are limited to 1 km in every direction; check the "
                                     "units and the expression")


def _nonfinite(c: float) -> str:
    return "not a number (NaN)" if c != c else "infinite"


def _divisions(e) -> list:
    """The divisions (``/``, ``//``) in the arithmetic of expression ``e``, outermost first."""
    if isinstance(e, A.Neg):
        return _divisions(e.operand)
    return ([e] if e.op in ("/", "//") else []) + _divisions(e.left) + _divisions(e.right) \
        if isinstance(e, A.BinOp) else []
