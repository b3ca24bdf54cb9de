"""Expressions: numbers with units, strings, names, members, indexing, lists and
comprehensions, operators with unit arithmetic, and point arithmetic.

A mixin of :class:`aidl_lang.interp.Interpreter`; it uses the other parts through ``self``."""
from __future__ import annotations

import math

from .. import ast as A
from ..base.diagnostics import EvalError, did_you_mean
from ..geometry.relations.bbox import BBTerm
from ..geometry.core.expr import Lin, _lin, _new, as_const, func, lift
from ..geometry.relations.members import member as geom_member, member_names
from ..geometry.core.values import (_EMPTY, ANG, LEN, NUM, PV, BBoxRef, Builtin, GeomRef, Namespace, Q, Radians,
                               StructRef, dim_name, mul_dim, rad_power, radians_of, type_name)
from ..registry import (CONSTANTS, FUNCTIONS, UNITS_ANGLE, UNITS_LENGTH, lookup)
from .common import (DEG, POISON, Scope, _Silent, _a, _fmt_num, show)
from .call_hints import _drawn_member, branch_making


_HANDLERS: dict = {}      # (interpreter class, AST node class) -> the _e_<Node> function


class Expressions:
    def eval(self, e, name: str | None = None):
        t = type(e)
        if t is A.Call:                  # what _e_Call does, without the extra frame
            self.step(e.span)
            return self._call(e, name)
        if t is A.Name:                  # a name defined in scope: _e_Name's first case, inline
            nid = e.id
            if nid != "self":
                for vars_ in self.scope.chain:
                    if nid in vars_:
                        v = vars_[nid]
                        if v is POISON:
                            raise _Silent()
                        return v
            return self._e_Name(e)
        if t is A.Num:
            v = e.value
            u = e.unit
            if -1e15 <= v <= 1e15 and (u is None or u in UNITS_LENGTH):
                # _e_Num of a finite number, plain or a length (`10 mm` in a loop's body)
                c = _new(Lin)
                c.terms = {}
                q = _new(Q)                  # Q(c, NUM) without the class call
                if u is None:
                    c.const = float(v)
                    q.expr, q.dim, q.owners = c, NUM, _EMPTY
                else:
                    c.const = float(v * UNITS_LENGTH[u])
                    q.expr, q.dim, q.owners = c, LEN, _EMPTY
                return q
            return self._e_Num(e)
        key = (type(self), t)
        m = _HANDLERS.get(key)
        if m is None:
            m = _HANDLERS[key] = getattr(type(self), "_e_" + t.__name__)
        return m(self, e)

    def _e_Num(self, e: A.Num):
        if not math.isfinite(e.value) or abs(e.value) > 1e15:
            raise EvalError("E0112", "this number is too large", e.span,
                            hint="AIDL numbers must stay below 1e15")
        u = e.unit                       # Q.num, inline
        c = _new(Lin)
        c.terms = {}
        if u is None:
            c.const = float(e.value)
            return Q(c, NUM)
        if u in UNITS_LENGTH:
            c.const = float(e.value * UNITS_LENGTH[u])
            return Q(c, LEN)
        c.const = float(e.value * UNITS_ANGLE[u])
        return Q(c, ANG)

    def _e_Str(self, e):
        return e.value

    def _e_FStr(self, e: A.FStr):
        out = []
        for p in e.parts:
            if isinstance(p, str):
                out.append(p)
                continue
            node, fmt = p
            v = self.eval(node)
            if isinstance(v, Q):
                c = v.const()
                if c is None:
                    raise EvalError("E0118", "an f-string cannot show a solved value", e.span)
                if v.dim == LEN:
                    c /= self.unit_scale
                elif v.dim == ANG:
                    c /= DEG
                if fmt and _format_width(fmt) > self.budget.size:
                    raise EvalError("E0304", f"the format `{fmt}` asks for more than "
                                    f"{self.budget.size:,} characters", e.span,
                                    hint="use a width below the string size budget")
                try:
                    out.append(format(c, fmt) if fmt else _fmt_num(c))
                except ValueError:
                    raise EvalError("E0108", f"bad format `{fmt}`", e.span)
            else:
                out.append(show(v, self.unit_scale))
        text = "".join(out)
        self.check_size(len(text), e.span, "a string")
        return text

    def _e_Name(self, e: A.Name):
        if e.id == "self":
            if self.struct is None:
                raise EvalError("E0101", "`self` is only defined inside a structure", e.span)
            return StructRef(self.struct)
        v, sc = self.scope.lookup(e.id)
        if v is POISON:
            raise _Silent()
        if sc is not None:
            return v
        if e.id in ("true", "True"):
            return True
        if e.id in ("false", "False"):
            return False
        if e.id in ("pi", "PI"):           # a number of radians: 180 deg next to an angle
            return radians_of(Q.num(math.pi))
        if e.id == "tau":
            return radians_of(Q.num(2 * math.pi))
        # a structure's own name or an enclosing structure's name
        s = self.struct
        while s is not None:
            if s.name == e.id:
                return StructRef(s)
            s = s.parent
        if lookup(e.id) is not None or e.id in FUNCTIONS:
            return Builtin(e.id)
        if e.id in UNITS_LENGTH or e.id in UNITS_ANGLE:
            # a unit's name is one of that unit: `length / mm` is a number, `n * deg` an angle
            c = _new(Lin)
            c.terms = {}
            if e.id in UNITS_LENGTH:
                c.const = float(UNITS_LENGTH[e.id])
                return Q(c, LEN)
            c.const = float(UNITS_ANGLE[e.id])
            return Q(c, ANG)
        later = self.later_definition(e.id)
        if later is not None and later > e.span.line:
            raise EvalError("E0101", f"`{e.id}` is used before its definition: it is defined later, "
                            f"on line {later}", e.span,
                            hint=f"a definition may only use names defined above it; move line "
                                 f"{later} above line {e.span.line} (constraint statements may "
                                 f"name later geometry)")
        cands = list(self.scope.names()) + [s.name for s in self._enclosing()] + list(CONSTANTS)
        sugg = did_you_mean(e.id, cands)
        raise EvalError("E0101", f"unknown name `{e.id}`", e.span,
                        hint=f"did you mean `{sugg[0]}`?" if sugg else "define it before use",
                        suggestions=sugg)

    def _enclosing(self):
        s = self.struct
        while s is not None:
            yield s
            s = s.parent

    def _e_Call(self, e: A.Call, name=None):
        self.step(e.span)
        return self._call(e, name)

    def _e_Keyword(self, e):
        raise EvalError("E0001", "keyword argument outside a call", e.span)

    def _e_Member(self, e: A.Member):
        obj = self.eval(e.obj)
        if isinstance(obj, list) and e.name not in ("x", "y"):
            _list_member(e, obj)
        v = self.member(obj, e.name, e.name_span, e.obj.span)
        if v is POISON:             # `label.t` whose definition failed: reported once there,
            raise _Silent()         # never again as "no member" (issue 61)
        return v

    def member(self, obj, name: str, span, obj_span=None):
        S = self.struct
        if obj is POISON:
            raise _Silent()
        if isinstance(obj, Namespace):
            if name in obj.scope.vars:
                return obj.scope.vars[name]
            raise EvalError("E0102", f"`{obj.name}` has no `{name}`", span,
                            suggestions=did_you_mean(name, obj.scope.vars))
        if isinstance(obj, StructRef):
            s = obj.struct
            if name == "bb":
                return BBoxRef(s)
            if name in s.scope:
                if s.template is not None:      # a member the program reads (`values`)
                    self.model.members_read.add((s.template, name))
                v = s.scope[name]
                if isinstance(v, StructRef):
                    # read by name (an assert, a relation): deleting it breaks them (W0506's
                    # hint: run ef's armillary sphere, "else delete it" of an asserted bar)
                    v.struct.read_by_name = True
                return v
            if name in s.children:
                s.children[name].read_by_name = True
                return StructRef(s.children[name])
            if name in ("width", "height", "left", "right", "top", "bottom", "center"):
                return self.member(BBoxRef(s), name, span)
            d = getattr(s, "template_def", None)
            # a template instance's members: its shapes, children and arguments, not the
            # numbers its body works with (run bt, bu: `tabs.slot` offered `lo`)
            cands = list(dict.fromkeys(
                [k for k, v in s.scope.items() if d is None or _drawn_member(v)]
                + list(s.children) + ["bb"]
                + ([k for k in s.scope if any(p.name == k for p in d.params)] if d else [])))
            # a member of a child by that very name (run bj: `deck.word` for `deck.art.word`)
            deeper = [f"{c}.{name}" for c, k in s.children.items() if name in k.scope
                      or name in k.children]
            other = branch_making(d, name, self.sink) if d is not None else None
            sugg = [] if other else deeper[:1] or did_you_mean(name, cands)
            raise EvalError("E0102", f"structure `{s.path}` has no member `{name}`", span,
                            hint=other + f"; its members: {', '.join(cands[:12])}"
                            if other else f"did you mean `{sugg[0]}`?" if sugg else
                            f"its members: {', '.join(sorted(cands)[:12])}", suggestions=sugg)
        if isinstance(obj, GeomRef):
            g = obj.geom
            if name == "bb":
                return BBoxRef(g)
            if name == "center" and g.kind == "Hull":      # its box's center, as `.bb.center`
                return self.member(BBoxRef(g), name, span)
            if name == "center" and g.kind in ("Offset", "Shell") \
                    and geom_member(g, name, S) is None:     # its shape has none: its box's
                return self.member(BBoxRef(g), name, span)
            v = geom_member(g, name, S)
            if v is not None:
                return v
            cands = member_names(g)
            sugg = [c for c in did_you_mean(name, cands) if c != name]
            # run dd: "a Arc has no member `through`... did you mean `through`?" for an Arc
            # drawn from its center and angles (the member of the three-point form)
            form = (f"`{name}` is a member of the forms that take it; this {g.kind} has "
                    + (", ".join(f"`{c}`" for c in cands if c != name) or "none")
                    + (" (`midpoint`: the point halfway along)" if g.kind == "Arc" else "")
                    ) if name in (lookup(g.kind).members if lookup(g.kind) else ()) else None
            raise EvalError("E0102", f"a {g.kind} has no member `{name}`", span,
                            hint=form or (f"did you mean `{sugg[0]}`?" if sugg else
                                          f"its members: {', '.join(cands)}"),
                            suggestions=sugg)
        if isinstance(obj, BBoxRef):
            t = obj.target
            own = obj.owners
            side = {s: BBTerm(t, s, S) for s in ("left", "right", "bottom", "top")}
            L = lambda e: Q(e, LEN, own)
            table = {
                "left": lambda: L(side["left"]), "right": lambda: L(side["right"]),
                "bottom": lambda: L(side["bottom"]), "top": lambda: L(side["top"]),
                "width": lambda: L(side["right"] - side["left"]),
                "height": lambda: L(side["top"] - side["bottom"]),
                "center_x": lambda: L((side["left"] + side["right"]) * 0.5),
                "center_y": lambda: L((side["bottom"] + side["top"]) * 0.5),
                "center": lambda: PV((side["left"] + side["right"]) * 0.5,
                                     (side["bottom"] + side["top"]) * 0.5, None, own),
                "top_left": lambda: PV(side["left"], side["top"], None, own),
                "top_right": lambda: PV(side["right"], side["top"], None, own),
                "bottom_left": lambda: PV(side["left"], side["bottom"], None, own),
                "bottom_right": lambda: PV(side["right"], side["bottom"], None, own),
            }
            if name in table:
                return table[name]()
            sugg = did_you_mean(name, table)
            raise EvalError("E0102", f"a bounding box has no member `{name}`", span,
                            hint=f"did you mean `{sugg[0]}`?" if sugg else "members: " + ", ".join(table),
                            suggestions=sugg)
        if isinstance(obj, PV):
            if name in ("x", "y"):
                return Q(obj.x if name == "x" else obj.y, LEN, obj.owners)
            raise EvalError("E0102", f"a point has no member `{name}`", span,
                            hint="a point has `x` and `y`", suggestions=did_you_mean(name, ["x", "y"]))
        if isinstance(obj, (tuple, list)) and len(obj) == 2 and name in ("x", "y") and all(isinstance(c, Q) for c in obj):
            p = self._to_point(obj, span)
            return Q(p.x if name == "x" else p.y, LEN, p.owners)
        raise EvalError("E0102", f"{_a(type_name(obj))} has no member `{name}`", span)

    def _e_Index(self, e: A.Index):
        obj = self.eval(e.obj)
        idx = self.eval(e.index)
        if type(obj) is list and type(idx) is Q:        # `c1x[k]`: a list and a whole number
            x = idx.expr
            if type(x) is Lin and not x.terms:
                i = x.const
                if -len(obj) <= i < len(obj) and i == int(i):
                    v = obj[int(i)]
                    if v is POISON:
                        raise _Silent()
                    return v
        if obj is POISON or idx is POISON:
            raise _Silent()
        if type(obj) is PV and type(idx) is Q and idx.const() in (0, 1, -1, -2):
            # `p[0]`, `p[1]`: a point's x and y (run da: E0111 "a point cannot be indexed")
            return self.member(obj, "x" if idx.const() in (0, -2) else "y", e.span)
        if not isinstance(obj, (list, tuple, str)):
            hint = "only lists (loops, comprehensions, `poly.points`) are indexed"
            if isinstance(e.obj, A.Index) and isinstance(obj, (StructRef, GeomRef)):
                # `cells[r][c]` of a GridPattern (issue 111, run s: rows of lists guessed)
                name = e.obj.obj.id if isinstance(e.obj.obj, A.Name) else "cells"
                hint = ("a pattern's list is flat, one copy an item: a GridPattern's is row by "
                        f"row, copy (r, c) is `{name}[r * cols + c]`")
            elif isinstance(e.obj, A.Name) and (var := self._this_pass(e.obj.id)) is not None:
                # run ga: `RightOf(p[i], p[i - 1])` in the loop that makes `p = peg()`
                n = e.obj.id
                hint = (f"inside the loop that makes it, `{n}` is this pass's one (a list only "
                        f"after the loop): write `{n}` for it; to relate each to the one "
                        f"before, write a second loop after this one: `for {var} in "
                        f"range(1, len({n})) {{ RightOf({n}[{var}], {n}[{var} - 1]) }}`")
            raise EvalError("E0111", f"{_a(type_name(obj))} cannot be indexed", e.obj.span,
                            hint=hint)
        i = self._q(idx, e.index.span).const()
        if i is None or abs(i - round(i)) > 1e-9:
            raise EvalError("E0108", "a list index must be a whole number", e.index.span)
        i = int(round(i))
        n = len(obj)
        if not -n <= i < n:
            raise EvalError("E0110", f"index {i} is out of range: the list has {n} item{'s' if n != 1 else ''}"
                            + _nested_note(obj, i, e), e.index.span,
                            hint=f"valid indices are 0 to {n - 1}" if n else "the list is empty")
        if obj[i] is POISON:
            raise _Silent()
        return obj[i]

    def _this_pass(self, name: str) -> str | None:
        """The variable of the innermost loop whose pass so far assigned ``name`` (the name
        is then this pass's value, and a list only after the loop), or None."""
        sc = self.scope
        while sc is not None and getattr(sc, "loop_index", None) is not None:
            if name in sc.vars:
                return sc.loop_var
            sc = sc.parent
        return None

    def _e_TupleLit(self, e):
        ev = self.eval
        return tuple([ev(x) for x in e.items])

    def _e_ListLit(self, e):
        return [self.eval(x) for x in e.items]

    def _e_ListComp(self, e: A.ListComp):
        items = self._iterable(self.eval(e.iter), e.iter)
        out = []
        outer = self.scope
        self.frames.append(("the comprehension `[... for " + e.var + " in ...]`", e.span))
        try:
            for item in items:
                self.step(e.span)
                sc = Scope(outer, self.struct, self.file)
                sc.vars[e.var] = item
                self.scope = sc
                if e.cond is not None and not self._filter(e):
                    continue
                if e.flat:              # `[... for a in xs for b in ys]`: one flat list
                    out.extend(self.eval(e.elt))
                else:
                    out.append(self.eval(e.elt))
        finally:
            self.frames.pop()
            self.scope = outer
        return out

    def _filter(self, e: A.ListComp) -> bool:
        """The truth of comprehension ``e``'s filter for the item in scope; E0118 when it
        reads solved geometry says that a filter runs before the solve, in an ``assert``
        too (issue 111: a model counted a zig-zag's low points with a filter in an assert
        and was told that `a == b` is a constraint)."""
        try:
            return self._truth(self.eval(e.cond), e.cond)
        except EvalError as err:
            if err.code == "E0118":
                err.message = "a comprehension's filter cannot read geometry the solver moves"
                err.hint = (f"the filter picks items before solving, in an `assert` too: "
                            f"filter on a param or an index, or assert each item in a loop "
                            f"(`for {e.var} in ... {{ assert ... }}`)")
            raise

    def _e_Ternary(self, e):
        return self.eval(e.then) if self._truth(self.eval(e.cond), e.cond) else self.eval(e.orelse)

    def _e_BoolOp(self, e):
        l = self._truth(self.eval(e.left), e.left)
        if e.op == "and":
            return l and self._truth(self.eval(e.right), e.right)
        return l or self._truth(self.eval(e.right), e.right)

    def _e_Not(self, e):
        return not self._truth(self.eval(e.operand), e.operand)

    def _e_Neg(self, e):
        v = self.eval(e.operand)
        if isinstance(v, Q):
            q = Q(-lift(v.expr), v.dim, v.owners)
            return q if type(v) is Q else radians_of(q, rad_power(v))      # -pi: radians
        if isinstance(v, PV):
            return PV(-lift(v.x), -lift(v.y), None, v.owners)
        raise EvalError("E0108", f"cannot negate a {type_name(v)}", e.span)

    def _e_Compare(self, e: A.Compare):
        vals = [self.eval(x) for x in e.operands]
        for op, l, r in zip(e.ops, vals, vals[1:]):
            if isinstance(l, str) or isinstance(r, str) or isinstance(l, bool) or isinstance(r, bool):
                res = {"==": l == r, "!=": l != r}.get(op)
                if res is None:
                    raise EvalError("E0108", f"cannot order {type_name(l)} and {type_name(r)}", e.span)
            else:
                a, b, _ = self._unify(self._q(l, e.span), self._q(r, e.span), e.span, e)
                ca, cb = as_const(a), as_const(b)
                if ca is None or cb is None:
                    raise EvalError("E0118", "a condition cannot depend on geometry the solver moves",
                                    e.span, hint="as a statement of its own, `a == b` is a constraint")
                res = {"==": abs(ca - cb) <= 1e-9 * max(1.0, abs(ca), abs(cb)), "!=": abs(ca - cb) > 1e-9,
                       "<": ca < cb, "<=": ca <= cb, ">": ca > cb, ">=": ca >= cb}[op]
            if not res:
                return False
        return True

    def finite(self, v, span):
        """``v`` unchanged if it is not a number known before solving or a finite one; an
        infinite or NaN result is E0112 at ``span``."""
        if isinstance(v, Q):
            c = v.const()
            if c is not None and not math.isfinite(c):
                raise EvalError("E0112", "this computation gives " +
                                ("not a number (NaN)" if c != c else "infinity"), span,
                                hint="a value overflowed or was divided by a tiny number; "
                                     "AIDL numbers must stay finite")
        return v

    def _e_BinOp(self, e: A.BinOp):
        self.ops += 1
        if not self.ops & 4095:
            self.check_time(e.span)
        v = self._binop(e)
        if type(v) is Q:                  # a finite constant, as `finite` finds it, inline
            x = v.expr
            if type(x) is Lin and not x.terms and math.isfinite(x.const):
                return v
        return self.finite(v, e.span)

    def _binop(self, e: A.BinOp):
        l, r = self.eval(e.left), self.eval(e.right)
        op = e.op
        if type(l) is Q and type(r) is Q:         # the common case: two numbers
            q = self._q_op(op, l, r, e)
            return _arc(op, l, r, q) if l.dim[1] + r.dim[1] and q.dim[1] == 0 else q
        if op == "+" and isinstance(l, str) and isinstance(r, str):
            self.check_size(len(l) + len(r), e.span, "a string")
            return l + r
        if op == "+" and isinstance(l, list) and isinstance(r, list):
            self.check_size(len(l) + len(r), e.span, "a list")
            return l + r
        if isinstance(l, (tuple, list)) and len(l) == 2 and all(isinstance(c, Q) for c in l):
            l = self._to_point(l, e.left.span)
        if isinstance(r, (tuple, list)) and len(r) == 2 and all(isinstance(c, Q) for c in r):
            r = self._to_point(r, e.right.span)
        if isinstance(l, GeomRef) and l.geom.kind == "Point":
            l = geom_member(l.geom, "p", self.struct)
        if isinstance(r, GeomRef) and r.geom.kind == "Point":
            r = geom_member(r.geom, "p", self.struct)
        if isinstance(l, PV) or isinstance(r, PV):
            return self._point_op(op, l, r, e)
        if isinstance(l, bool):
            l = Q.num(float(l))
        if isinstance(r, bool):
            r = Q.num(float(r))
        if not isinstance(l, Q) or not isinstance(r, Q):
            raise EvalError("E0108", f"cannot apply `{op}` to {type_name(l)} and {type_name(r)}",
                            e.span, hint=_shape_operand_hint(e, l, r))
        if type(l) is Radians or type(r) is Radians:
            return self._radians_op(op, l, r, e)
        q = self._q_op(op, l, r, e)
        return _arc(op, l, r, q) if q.dim[1] == 0 else q

    def _radians_op(self, op: str, l: Q, r: Q, e: A.BinOp) -> Q:
        """``l op r`` where ``pi``, ``tau`` or a value made from them (:class:`Radians`)
        takes part: the value of :meth:`_q_op` (next to an angle a number of radians is read
        as radians, :func:`~aidl_lang.geometry.core.values.unify_add`), carrying the radian to the
        power units combine to: ``2 * pi / n`` and ``pi * module / pitch_r`` 1, ``pi * pi``
        2, ``pi / pi`` 0; ``+``/``-`` keep the power of their side that has one (``tau -
        0.1``: a plain number next to radians is radians, as in ``sin``), and a sum of two
        different powers has none."""
        q = self._q_op(op, l, r, e)
        if q.dim != NUM and ANG in (l.dim, r.dim) and op in ("+", "-"):
            return q                    # radians met an angle: an angle, read in radians
        a, b = rad_power(l), rad_power(r)
        if op == "*":
            k = a + b
        elif op == "/":
            k = a - b
        elif op in ("+", "-"):
            k = a if not b or a == b else b if not a else 0
        elif op == "**" and not b:
            c = r.const()
            k = int(a * c) if c is not None and c == int(c) else 0
        else:
            k = 0
        return radians_of(q, k) if k else q

    def floor_as_length(self, e: A.BinOp, exact: float, q: Q, use) -> None:
        """W0106: the floor division ``e`` (exactly ``exact``, floored to ``q``) gives a length
        (``80 mm // 3``) or is used as one at ``use`` (``width=80 // 3``): ``//`` is floor
        division (docs/language.md, *Comments*), and a truncated length is rarely what was
        meant.  Once per ``//``.  The fix replaces the operator with ``/``; the hint also says
        how to write a comment when the right operand is a single word ending the line (the
        ``// comment`` reading the rule did not take)."""
        from ..base.diagnostics import Fix, Label, Span
        key = ("W0106", e.span)
        if key in self.reported:
            return
        self.reported.add(key)
        src = self.sink.sources.get(e.span.file, "")
        mid = src[e.left.span.end:e.right.span.start]
        k = mid.find("//")
        fix = None
        if k >= 0:
            at = e.left.span.end + k
            line = src.count("\n", 0, at) + 1
            col = at - src.rfind("\n", 0, at)
            fix = Fix(Span(e.span.file, line, col, line, col + 2, at, at + 2), "/")
        whole = src[e.span.start:e.span.end]
        value = f"{q.const():g}" + (" mm" if q.dim == LEN else "")
        hint = "write `/` for division; `//` is floor division"
        if isinstance(e.right, A.Name):
            end = src.find("\n", e.right.span.end)
            rest = src[e.right.span.end:len(src) if end < 0 else end]
            if not rest.strip() or rest.strip().startswith("#"):
                hint += (f"; if `// {e.right.id}` was meant as a comment, write "
                         f"`# {e.right.id}` (`//` after an operand and before a single word "
                         "is read as floor division)")
        labels = [] if use is e.span else [Label(use, "used as a length here", primary=False)]
        if q.dim in (NUM, LEN):
            msg = (f"`{whole}` is floor division: it gives {value} (the whole part of "
                   f"{exact:.6g}), used as a length")
        else:
            msg = (f"`{whole}` is floor division of a number by a length: it gives "
                   f"{q.const():g} per mm, neither a number nor a length")
            fix = None                      # `/` would not make it a length either
        self.sink.warning("W0106", msg, e.span, hint, labels=labels, fix=fix)

    def _q_op(self, op: str, l: Q, r: Q, e: A.BinOp):
        """``l op r`` for two numbers (:class:`Q`): units checked, constants folded."""
        lo, ro = l.owners, r.owners
        own = ro if not lo else (lo if not ro or ro is lo else lo | ro)
        le, re_ = l.expr, r.expr
        if type(le) is Lin and type(re_) is Lin and not le.terms and not re_.terms:
            # two constants (most of a template's arithmetic): the same floating-point
            # operations as the general path below (``mul``, ``div``), without its dispatch
            if op == "*":
                return Q(_lin({}, re_.const * le.const), mul_dim(l.dim, r.dim), own)
            if op == "/" and re_.const != 0.0:
                return Q(_lin({}, (1.0 / re_.const) * le.const), mul_dim(l.dim, r.dim, -1), own)
        if op in ("+", "-"):
            a, b, d = self._unify(l, r, e.span, e)
            return Q(a + b if op == "+" else a - b, d, own)
        if op == "*":
            return Q(lift(l.expr) * r.expr, mul_dim(l.dim, r.dim), own)
        if op == "/":
            if r.const() == 0:
                raise EvalError("E0112", "division by zero", e.right.span)
            return Q(lift(l.expr) / r.expr, mul_dim(l.dim, r.dim, -1), own)
        if op in ("//", "%"):
            ca, cb = l.const(), r.const()
            if ca is None or cb is None:
                raise EvalError("E0118", f"`{op}` needs values known before solving", e.span)
            if l.dim != r.dim and NUM not in (l.dim, r.dim):
                raise EvalError("E0109", f"cannot apply `{op}` to a {dim_name(l.dim)} and a {dim_name(r.dim)}", e.span)
            a, b, d = self._unify(l, r, e.span) if op == "%" else (l.expr, r.expr, None)
            ca, cb = as_const(a), as_const(b)
            if cb == 0:
                raise EvalError("E0112", "division by zero", e.right.span)
            if op == "//":
                q = Q.num(math.floor(ca / cb), mul_dim(l.dim, r.dim, -1))
                if q.dim == LEN:            # `80 mm // 3`: a length cut to whole mm
                    self.floor_as_length(e, ca / cb, q, e.span)
                elif q.dim == NUM:          # a count, unless it is used as a length
                    self.floor_results[id(q)] = (q, e, ca / cb)
                elif l.dim == NUM:          # `80 // width`: a number by a length
                    self.floor_as_length(e, ca / cb, q, e.span)
                return q
            return Q.num(math.fmod(ca, cb) if ca * cb >= 0 else ca - cb * math.floor(ca / cb), d)
        if op == "**":
            cb = r.const()
            if cb is None or r.dim != NUM:
                why = (f"; this one is {_a(dim_name(r.dim))}" if r.dim != NUM else
                       "; this one is solved" if cb is None else "")
                raise EvalError("E0108", "an exponent must be a plain number known before "
                                f"solving{why}", e.right.span,
                                hint="divide its lengths by lengths so the units cancel "
                                     "(`(x / sigma) ** 2`, `exp(-(x / sigma) ** 2 / 2)`)"
                                if r.dim != NUM else None)
            if l.dim != NUM and abs(cb - round(cb)) > 1e-12:
                raise EvalError("E0109", "a length can only be raised to a whole power", e.span)
            k = int(round(cb)) if l.dim != NUM else 1
            ca = l.const()
            if ca is not None:
                try:
                    v = ca ** cb
                except (OverflowError, ZeroDivisionError) as ex:
                    raise EvalError("E0112", f"math error: {ex}", e.span)
                if isinstance(v, complex):
                    raise EvalError("E0112", f"a negative number ({_fmt_num(ca)}) to a fractional "
                                    f"power ({cb:g}) is not a real number", e.span,
                                    hint="raise the absolute value, or use a whole exponent")
                return Q.num(v, (l.dim[0] * k, l.dim[1] * k))
            return Q(func("pow", l.expr, cb), (l.dim[0] * k, l.dim[1] * k), own)
        raise EvalError("E0108", f"unknown operator `{op}`", e.span)

    def _point_op(self, op, l, r, e):
        if op in ("+", "-") and isinstance(l, PV) and isinstance(r, PV):
            sg = 1.0 if op == "+" else -1.0
            return PV(l.x + r.x * sg, l.y + r.y * sg, None, l.owners | r.owners)
        if op in ("*", "/") and (isinstance(l, Q) or isinstance(r, Q)):
            p, q = (l, r) if isinstance(l, PV) else (r, l)
            if op == "/" and isinstance(r, PV):
                raise EvalError("E0108", "cannot divide by a point", e.span)
            if q.dim != NUM:
                got = "a 1/length" if q.dim == (-1, 0) else _a(dim_name(q.dim))
                raise EvalError("E0109", f"a point can only be scaled by a plain number, not {got}",
                                e.span, hint=_scale_hint(q.dim))
            k = q.expr if op == "*" else lift(1.0) / q.expr
            return PV(lift(p.x) * k, lift(p.y) * k, None, p.owners | q.owners)
        raise EvalError("E0108", f"cannot apply `{op}` to {type_name(l)} and {type_name(r)}", e.span,
                        hint="points add and subtract as vectors; scale them by numbers")


def _arc(op: str, l: Q, r: Q, q: Q) -> Q:
    """``q = l op r`` of two quantities: an angle times (or over) a length is an arc length,
    a length (:func:`~aidl_lang.geometry.core.values.mul_dim`), that keeps the radian its angle
    had (a :class:`Radians` of that power), so that over a length again it is an angle, read
    in radians next to one (run fk's squirrel baffle: `360 deg * RB / L` was a bare 5.058,
    then `270 deg + ...` read it as 5.058 deg: the cone's flat pattern came out a sliver)."""
    if op not in ("*", "/") or not (l.dim[0] or r.dim[0]):
        return q
    k = l.dim[1] + (r.dim[1] if op == "*" else -r.dim[1])
    return radians_of(q, k) if k else q


def _nested_note(obj, i: int, e) -> str:
    """E0110's words for a list of lists indexed as if flat (run fd: two nested loops made
    `screw` a list of 2 lists of 2, and `screw[3]` meant the fourth hole): which item of
    which list index ``i`` counts to, ``screw[1][1]``; "" for any other list."""
    if i < 0 or not obj or not all(isinstance(v, list) for v in obj):
        return ""
    sizes = [len(v) for v in obj]
    if i >= sum(sizes):
        return ""
    a = 0
    while i >= sizes[a]:
        i -= sizes[a]
        a += 1
    name = e.obj.id if isinstance(e.obj, A.Name) else (
        e.obj.name if isinstance(e.obj, A.Member) else "list")
    each = (f"each a list of {sizes[0]}" if len(set(sizes)) == 1 else "each a list")
    return (f", {each} (nested loops make a list per pass of the outer one): counted "
            f"through them, it is `{name}[{a}][{i}]`")


def _scale_hint(dim) -> str:
    """E0109's hint for a point scaled by a quantity with a unit: a 1/length factor is a plain
    number divided by a length, most often a bare number passed to a `def`, which keeps no
    unit (run ew: `toward(a, b, 10)` with `d / norm(a - b)` inside)."""
    if dim == (-1, 0):
        return ("the factor is a plain number divided by a length: give that number its "
                "unit (a bare number passed to a `def` stays a plain number: `10 mm`, not "
                "`10`), so a length over a length is a plain number")
    if dim == LEN:
        return ("a point times a length is no point: scale by a plain number (`p * 2`), or "
                "divide the length by another (`d / norm(a - b)`)")
    return "scale a point by a plain number: a length over a length, or a count"


_SIDES = ("top", "bottom", "left", "right")


def _shape_operand_hint(e, l, r) -> str | None:
    """E0108's hint for arithmetic on a shape (run dl: `outline.top - 5 mm`, where
    `outline.top` is the top edge, a Line): the number meant is a box side (`outline.bb.top`)
    or a member of the shape; None when neither operand is a shape."""
    for side, v in ((e.left, l), (e.right, r)):
        if not isinstance(v, GeomRef):
            continue
        text = _dotted(side)
        if isinstance(side, A.Member) and side.name in _SIDES and text:
            head = text.rsplit(".", 1)[0]
            what = "an edge, a Line" if v.geom.kind == "Line" else f"a {v.geom.kind}"
            return (f"`{text}` is {what}; its coordinate is `{head}.bb.{side.name}` (the "
                    "box's side, a length)")
        return (f"`{text or 'it'}` is a {v.geom.kind}: take a number of it (a member such as "
                f"`.length` or `.radius`, or a box side `.bb.top`), or a point (`.center`)")
    return None


def _format_width(fmt: str) -> int:
    """The largest number written in a format spec (its width or precision), 0 if none."""
    import re
    return max((int(m) for m in re.findall(r"\d+", fmt)), default=0)


def _dotted(e) -> str | None:
    """``e`` as written when it is a name or a chain of members and whole-number indices
    (``j.cut``, ``lattice.dia[0]``), else None."""
    if isinstance(e, A.Name):
        return e.id
    if isinstance(e, A.Member):
        head = _dotted(e.obj)
        return f"{head}.{e.name}" if head else None
    if isinstance(e, A.Index) and isinstance(e.index, A.Num) and e.index.unit is None \
            and float(e.index.value).is_integer():
        head = _dotted(e.obj)
        return f"{head}[{int(e.index.value)}]" if head else None
    return None


def _list_member(e: A.Member, obj: list):
    """E0102 for a member of a list (a loop's or a template's shapes: `j.cut.bb`), with a
    hint that indexes it and, for a structure's list, gives the structure's own box (issue
    111: a model read a dovetail's `cut.bb`, a list of one gap per tail)."""
    text = _dotted(e.obj)
    n = len(obj)
    if text is None or not n:
        return
    hint = (f"`{text}` is a list of {n} (`{text}[0]`" + (f" to `{text}[{n - 1}]`" if n > 1
                                                          else "") +
            f"): write `{text}[0].{e.name}` for one of them")
    if text.endswith("]"):          # an item of a list of lists: a name set in nested loops
        hint += (f"; `{text.rsplit('[', 1)[0]}` holds one list per pass of the outer loop "
                 "that set it (a name set in nested loops), so index it twice")
    if "." in text and e.name in ("bb", "width", "height", "left", "right", "top", "bottom",
                                  "center"):
        owner = text.rsplit(".", 1)[0]
        hint += f", or `{owner}.{e.name}` for the box of all of `{owner}`"
    raise EvalError("E0102", f"a list has no member `{e.name}`", e.name_span, hint=hint)

