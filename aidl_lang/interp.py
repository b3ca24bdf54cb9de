"""Interpret a checked AIDL program into a :class:`~aidl_lang.model.Model`.

Runs the statements of each structure (post-order children are created as their declarations
are met), evaluating expressions to values with units (:mod:`aidl_lang.values`), creating
geometry (:mod:`aidl_lang.primitives`) and compiling constraints to residual equations
(:mod:`aidl_lang.constraints`).  Errors found while running (types, units, indices, limits,
the paper's two validity rules on the exact objects referenced) become diagnostics; the
statement is skipped and interpretation goes on, so one run reports several problems.

Limits (docs/language.md, "Limits"): loops and comprehensions at most ``MAX_ITER`` iterations,
at most ``MAX_GEOMETRY`` geometry objects, template nesting at most ``MAX_TEMPLATE_DEPTH``.
"""
from __future__ import annotations

import math
from pathlib import Path

from . import ast as A
from .bbox import BBTerm, contains_bbox
from .constraints import BUILDERS, ConstraintError
from .diagnostics import Diagnostic, DiagnosticSink, Span, did_you_mean
from .expr import as_const, evaluate, func, lift, var
from .model import Constraint, Equation, Model, Point, Scalar, Structure
from .primitives import PrimitiveError, build, member as geom_member, member_names
from .registry import (CONSTANTS, ENTRIES, FUNCTIONS, UNITS_ANGLE, UNITS_LENGTH, canonical,
                       canonical_args, choose_variant, lookup)
from .values import (ANG, LEN, NUM, PV, BBoxRef, Builtin, GeomRef, Namespace, Q, StructRef,
                     Template, UnitError, dim_name, mul_dim, owners_of, type_name, unify_add)

MAX_ITER = 10_000
MAX_GEOMETRY = 50_000
MAX_TEMPLATE_DEPTH = 16
DEG = math.pi / 180.0
STDLIB = Path(__file__).resolve().parent.parent / "stdlib"
if not STDLIB.exists():
    STDLIB = Path(__file__).resolve().parent / "stdlib"


class EvalError(Exception):
    def __init__(self, code: str, message: str, span: Span | None, hint: str | None = None,
                 suggestions=None, labels=None):
        super().__init__(message)
        self.code, self.message, self.span, self.hint = code, message, span, hint
        self.suggestions = suggestions or []
        self.labels = labels or []


class _Silent(Exception):
    """Raised when a statement uses a name whose definition already failed (reported once)."""


POISON = object()


class Scope:
    def __init__(self, parent: "Scope | None", struct: Structure | None, file: "FileCtx"):
        self.vars: dict = {}
        self.parent = parent
        self.struct = struct
        self.file = file

    def lookup(self, name: str):
        s = self
        while s is not None:
            if name in s.vars:
                return s.vars[name], s
            s = s.parent
        return None, None

    def names(self):
        out = set()
        s = self
        while s is not None:
            out |= set(s.vars)
            s = s.parent
        return out


class FileCtx:
    def __init__(self, path: str, unit_scale: float = 1.0):
        self.path = path
        self.unit_scale = unit_scale
        self.scope = Scope(None, None, self)


class Interpreter:
    def __init__(self, sink: DiagnosticSink, overrides: dict[str, str] | None = None):
        self.sink = sink
        self.model = Model()
        self.overrides = dict(overrides or {})
        self.template_depth = 0
        self.n_geometry = 0
        self.loading: list[str] = []
        self.loaded: dict[str, FileCtx] = {}
        self.struct: Structure | None = None
        self.scope: Scope | None = None
        self.file: FileCtx | None = None
        self.root_dir: Path | None = None
        self.cur_span: Span | None = None

    # ------------------------------------------------------------------ helpers
    @property
    def unit_scale(self) -> float:
        return self.file.unit_scale if self.file else 1.0

    def value_of(self, e) -> float:
        return evaluate(lift(e), self.model.x)

    def error(self, e: EvalError) -> None:
        self.sink.add(Diagnostic(e.code, e.message, e.span, "error", e.hint,
                                 labels=e.labels, suggestions=e.suggestions))

    def warn_nonconst(self, what: str) -> None:
        self.sink.warning("W0103", f"{what} depends on solved geometry; its starting value is "
                          "used and held", self.cur_span,
                          hint="give it a number or a param; relate shapes with constraints instead")

    # ------------------------------------------------------------------ entry
    def run(self, program: A.Program) -> Model:
        self.root_dir = Path(program.path).resolve().parent
        fctx = self._load_file_decls(program, is_main=True)
        self.file = fctx
        top = [s for s in program.stmts if not isinstance(s, (A.UnitsDecl, A.Import, A.ParamDecl, A.Def))]
        structs = [s for s in top if isinstance(s, A.StructDecl)]
        loose = [s for s in top if not isinstance(s, A.StructDecl) and not _is_plain_const(s)]
        for name in self.overrides:
            if name not in getattr(fctx, "params", {}):
                self.sink.error("E0113", f"`--set {name}=...`: the model has no param `{name}`",
                                None, hint="params: " + ", ".join(sorted(fctx.params)) if fctx.params else
                                "declare it with `param NAME = VALUE` at the top of the file",
                                suggestions=did_you_mean(name, fctx.params))
        if len(structs) == 1 and not loose:
            consts = [s for s in top if s is not structs[0]]
            self.scope = fctx.scope
            for s in consts:
                self._exec_stmt(s)
            st = structs[0]
            root = self._new_structure(st.name, st.kind, None, st.span)
            self._run_body(root, st.body, Scope(fctx.scope, root, fctx))
        else:
            kind = "assembly" if not any(_is_geometry_stmt(s) for s in loose) else "solid"
            root = self._new_structure("model", kind, None, program.span)
            self.scope = fctx.scope
            for s in top:
                if _is_plain_const(s):
                    self._exec_stmt(s)
            scope = Scope(fctx.scope, root, fctx)
            rest = [s for s in top if not _is_plain_const(s)]
            self._run_body(root, A.Block(program.span, rest), scope)
        self.model.root = root
        return self.model

    def _new_structure(self, name, kind, parent, span, template=None) -> Structure:
        s = Structure(name, kind, parent, span, template=template)
        s.fx = self.model.new_param(0.0, parent is not None, s, f"{name}.frame.x")
        s.fy = self.model.new_param(0.0, parent is not None, s, f"{name}.frame.y")
        if parent is not None:
            parent.children[name] = s
        self.model.structures.append(s)
        return s

    # ------------------------------------------------------------------ files
    def _load_file_decls(self, program: A.Program, is_main: bool) -> FileCtx:
        fctx = FileCtx(program.path)
        fctx.params = {}
        prev = self.file
        self.file = fctx
        self.scope = fctx.scope
        for st in program.stmts:
            if isinstance(st, A.UnitsDecl):
                u = st.unit.lower()
                if u not in UNITS_LENGTH:
                    self.sink.error("E0109", f"unknown length unit `{st.unit}`", st.unit_span,
                                    hint="use one of " + ", ".join(UNITS_LENGTH),
                                    suggestions=did_you_mean(st.unit, UNITS_LENGTH))
                else:
                    fctx.unit_scale = UNITS_LENGTH[u]
        self.model.units = "mm"
        for st in program.stmts:
            try:
                if isinstance(st, A.Import):
                    self._import(st, fctx)
                elif isinstance(st, A.Def):
                    if st.kind not in ("solid", "hole", "drawing", "assembly"):
                        raise EvalError("E0108", f"unknown structure kind `{st.kind}`", st.kind_span,
                                        hint="a template returns solid, hole, drawing or assembly",
                                        suggestions=did_you_mean(st.kind, ["solid", "hole", "drawing", "assembly"]))
                    fctx.scope.vars[st.name] = Template(st, fctx.scope, fctx.unit_scale)
                elif isinstance(st, A.ParamDecl):
                    fctx.params[st.name] = None
                    if st.name in self.overrides and is_main:
                        val = self._eval_override(st.name, self.overrides[st.name], fctx)
                    else:
                        val = self.eval(st.value)
                    fctx.scope.vars[st.name] = val
                    fctx.params[st.name] = val
            except EvalError as e:
                self.error(e)
        if not is_main:
            for st in program.stmts:
                if isinstance(st, A.Assign) and _is_plain_const(st):
                    try:
                        fctx.scope.vars[st.name] = self.eval(st.value)
                    except EvalError as e:
                        self.error(e)
        self.file = prev if not is_main else fctx
        return fctx

    def _eval_override(self, name: str, text: str, fctx: FileCtx):
        from .parser import lark_parser, _Builder
        from lark.exceptions import LarkError
        try:
            tree = lark_parser().parse(text, start="expr")
            node = _Builder("<--set>", self.sink).transform(tree)
        except LarkError:
            raise EvalError("E0113", f"`--set {name}={text}`: cannot read `{text}` as a value",
                            None, hint="write a number with an optional unit, e.g. `--set width=40mm`")
        if isinstance(node, A.Name) and fctx.scope.lookup(node.id)[1] is None \
                and node.id not in CONSTANTS:
            return text                         # a bare word: a string
        return self.eval(node)

    def _import(self, st: A.Import, fctx: FileCtx) -> None:
        from .parser import parse
        raw = st.path
        if raw.startswith("std/") or raw.startswith("std:"):
            base = STDLIB
            rel = raw[4:]
        else:
            base = Path(fctx.path).resolve().parent
            rel = raw
        if not rel.endswith(".aidl"):
            rel += ".aidl"
        target = (base / rel).resolve()
        allowed = [STDLIB.resolve(), self.root_dir]
        if not any(target == a or a in target.parents for a in allowed) or Path(rel).is_absolute():
            raise EvalError("E0114", f"import `{raw}` leaves the project folder", st.path_span,
                            hint="import only .aidl files in this file's folder tree, or `std/NAME.aidl`")
        if not target.is_file():
            cands = [p.name for p in target.parent.glob("*.aidl")] if target.parent.is_dir() else []
            raise EvalError("E0114", f"cannot find `{raw}` to import", st.path_span,
                            hint=f"looked for {target}", suggestions=did_you_mean(target.name, cands))
        key = str(target)
        if key in self.loading:
            raise EvalError("E0115", f"import cycle: `{raw}` imports this file again", st.path_span,
                            hint="move the shared templates into a third file")
        if key not in self.loaded:
            text = target.read_text(encoding="utf-8", errors="replace")
            prog = parse(text, key, self.sink)
            self.loading.append(key)
            saved = (self.scope, self.file)
            try:
                self.loaded[key] = self._load_file_decls(prog, is_main=False)
            finally:
                self.scope, self.file = saved
                self.loading.pop()
        sub = self.loaded[key]
        if st.alias:
            fctx.scope.vars[st.alias] = Namespace(st.alias, sub.scope)
        else:
            for k, v in sub.scope.vars.items():
                fctx.scope.vars.setdefault(k, v)

    # ------------------------------------------------------------------ statements
    def _run_body(self, struct: Structure, block: A.Block, scope: Scope) -> None:
        saved = (self.struct, self.scope)
        self.struct, self.scope = struct, scope
        struct.scope = scope.vars            # members (`self.body`) are visible while it runs
        try:
            for st in block.stmts:
                self._exec_stmt(st)
        finally:
            self.struct, self.scope = saved

    def _exec_block(self, block: A.Block) -> None:
        for st in block.stmts:
            self._exec_stmt(st)

    def _exec_stmt(self, st) -> None:
        self.cur_span = st.span
        try:
            self._exec(st)
        except _Silent:
            pass
        except EvalError as e:
            self.error(e)
            if isinstance(st, A.Assign):       # later uses of the name stay quiet
                self.scope.vars[st.name] = POISON
            elif isinstance(st, A.StructDecl):
                self.scope.vars.setdefault(st.name, POISON)
        except (ValueError, ZeroDivisionError, OverflowError) as e:
            self.error(EvalError("E0112", f"math error: {e}", st.span,
                                 hint="check for division by zero or sqrt/asin of an out-of-range value"))
        except RecursionError:
            self.error(EvalError("E0302", "expression nested too deeply", st.span,
                                 hint="split it into named constants"))

    def _exec(self, st) -> None:
        if isinstance(st, A.StructDecl):
            self._struct_decl(st)
        elif isinstance(st, A.Assign):
            self._assign(st)
        elif isinstance(st, A.ExprStmt):
            self._expr_stmt(st.expr)
        elif isinstance(st, A.For):
            self._for(st)
        elif isinstance(st, A.If):
            c = self._truth(self.eval(st.cond), st.cond)
            if c:
                self._exec_block(st.body)
            elif st.orelse is not None:
                self._exec_block(st.orelse)
        elif isinstance(st, A.Block):
            raise EvalError("E0001", "a block `{ ... }` without a header", st.span,
                            hint="name it: `solid NAME { ... }`")
        elif isinstance(st, (A.ParamDecl, A.Def, A.Import, A.UnitsDecl)):
            what = {A.ParamDecl: "param", A.Def: "def", A.Import: "import", A.UnitsDecl: "units"}[type(st)]
            raise EvalError("E0116", f"`{what}` is only allowed at the top level of a file", st.span,
                            hint=f"move the `{what}` line to the top of the file")

    def _need_struct(self, span) -> Structure:
        if self.struct is None:
            raise EvalError("E0117", "geometry and constraints must be inside a structure", span,
                            hint="wrap them in `solid NAME { ... }`")
        return self.struct

    def _struct_decl(self, st: A.StructDecl, name: str | None = None):
        parent = self._need_struct(st.span)
        if st.kind not in ("solid", "hole", "drawing", "assembly"):
            raise EvalError("E0108", f"unknown structure kind `{st.kind}`", st.kind_span,
                            hint="a structure is `solid`, `hole`, `drawing` or `assembly` NAME { ... }",
                            suggestions=did_you_mean(st.kind, ["solid", "hole", "drawing", "assembly"]))
        name = name or st.name + self._loop_suffix()
        self._check_new_name(st.name, st.name_span, parent)
        child = self._new_structure(name, st.kind, parent, st.span)
        self.scope.vars[st.name] = StructRef(child)
        self._run_body(child, st.body, Scope(self.scope, child, self.file))
        return child

    def _loop_suffix(self) -> str:
        """``[i]`` per enclosing loop of the current structure body (outermost first)."""
        idx = []
        sc = self.scope
        while sc is not None and sc.struct is self.struct and sc.parent is not None:
            if hasattr(sc, "loop_index"):
                idx.append(sc.loop_index)
            sc = sc.parent
        return "".join(f"[{i}]" for i in reversed(idx))

    def _check_new_name(self, name: str, span, struct: Structure) -> None:
        prev = self.scope.vars.get(name)
        if isinstance(prev, (GeomRef, StructRef)):
            raise EvalError("E0107", f"`{name}` is already defined in `{struct.path}`", span,
                            hint="give each geometry and structure its own name")

    def _assign(self, st: A.Assign) -> None:
        v = st.value
        if isinstance(v, A.Call) and isinstance(v.func, (A.Name, A.Member)):
            callee = self._callee(v.func)
            if isinstance(callee, Template):
                self._check_new_name(st.name, st.name_span, self._need_struct(st.span))
                ref = self._instantiate(callee, v, st.name + self._loop_suffix())
                self.scope.vars[st.name] = ref
                return
        if st.name in CONSTANTS or st.name in ("self",):
            raise EvalError("E0107", f"`{st.name}` is a built-in name and cannot be assigned",
                            st.name_span, hint="choose another name")
        if isinstance(v, A.Call) and self.struct is not None:
            self._check_new_name(st.name, st.name_span, self.struct)
        val = self.eval(v, name=st.name)
        if isinstance(val, GeomRef) and not val.geom.name and val.geom.owner is self.struct:
            val.geom.name = st.name
        if isinstance(val, list):
            for i, item in enumerate(val):
                if isinstance(item, GeomRef) and not item.geom.name:
                    item.geom.name = f"{st.name}[{i}]"
        self.scope.vars[st.name] = val

    def _expr_stmt(self, e) -> None:
        if isinstance(e, (A.Compare, A.BoolOp)):
            self._equation(e)
            return
        val = self.eval(e)
        if val is None or isinstance(val, (GeomRef, StructRef)) or type(val).__name__ == "Copies":
            return
        self.sink.warning("W0101", "this statement has no effect", e.span,
                          hint="name the value (`x = ...`) or write a constraint (`a == b`)")

    def _for(self, st: A.For) -> None:
        items = self._iterable(self.eval(st.iter), st.iter)
        collected: dict[str, list] = {}
        outer = self.scope
        for k, item in enumerate(items):
            sc = Scope(outer, self.struct, self.file)
            sc.vars[st.var] = item
            sc.loop_index = k
            self.scope = sc
            try:
                for s in st.body.stmts:
                    self._exec_stmt(s)
            finally:
                self.scope = outer
            for name, v in sc.vars.items():
                if name != st.var:
                    collected.setdefault(name, []).append(v)
        for name, vals in collected.items():
            outer.vars[name] = vals

    def _iterable(self, v, node) -> list:
        if isinstance(v, (list, tuple)):
            if len(v) > MAX_ITER:
                raise EvalError("E0301", f"a loop over {len(v)} items exceeds the limit of {MAX_ITER}",
                                node.span, hint="use fewer items")
            return list(v)
        if isinstance(v, str):
            return list(v)
        raise EvalError("E0111", f"cannot loop over a {type_name(v)}", node.span,
                        hint="loop over `range(n)` or a list")

    def _truth(self, v, node) -> bool:
        if isinstance(v, bool):
            return v
        if isinstance(v, Q):
            c = v.const()
            if c is None:
                raise EvalError("E0118", "a condition cannot depend on geometry the solver moves",
                                node.span, hint="write it as a constraint, or test a param instead")
            return c != 0
        if isinstance(v, (list, str)):
            return len(v) > 0
        if v is None:
            return False
        return True

    # ------------------------------------------------------------------ templates
    def _instantiate(self, t: Template, call: A.Call, name: str) -> StructRef:
        parent = self._need_struct(call.span)
        d = t.node
        if self.template_depth >= MAX_TEMPLATE_DEPTH:
            raise EvalError("E0302", f"templates nested more than {MAX_TEMPLATE_DEPTH} deep",
                            call.span, hint="a template probably instantiates itself")
        params = [p.name for p in d.params]
        if len(call.args) > len(params):
            raise EvalError("E0104", f"`{d.name}` takes {len(params)} arguments, got {len(call.args)}",
                            call.span, hint=f"`{d.name}({', '.join(params)})`")
        vals: dict = {}
        for p, a in zip(params, call.args):
            vals[p] = (self.eval(a), a)
        for kw in call.kwargs:
            if kw.name not in params:
                raise EvalError("E0105", f"`{d.name}` has no parameter `{kw.name}`", kw.span,
                                hint=f"parameters: {', '.join(params) or 'none'}",
                                suggestions=did_you_mean(kw.name, params))
            vals[kw.name] = (self.eval(kw.value), kw.value)
        for v, node in vals.values():
            if owners_of(v):
                raise EvalError("E0204", "template arguments must be values, not geometry or structures",
                                node.span, hint="pass numbers; relate the parts with constraints "
                                "in the parent structure")
        child = self._new_structure(name, d.kind, parent, call.span, template=d.name)
        saved_file = self.file
        tscope = Scope(t.scope, child, t.scope.file)
        self.file = t.scope.file
        self.template_depth += 1
        try:
            saved_scope = self.scope
            self.scope = tscope
            for p in d.params:
                if p.name in vals:
                    tscope.vars[p.name] = vals[p.name][0]
                elif p.default is not None:
                    tscope.vars[p.name] = self.eval(p.default)
                else:
                    raise EvalError("E0106", f"`{d.name}` needs the argument `{p.name}`", call.span,
                                    hint=f"`{name} = {d.name}({p.name}=...)`")
            self.scope = saved_scope
            self._run_body(child, d.body, tscope)
        finally:
            self.template_depth -= 1
            self.file = saved_file
        return StructRef(child)

    # ------------------------------------------------------------------ constraints
    def _add_constraint(self, kind: str, eqs: list[Equation], span, text: str, owners) -> None:
        s = self._need_struct(span)
        self._check_subtree(owners, span, s)
        c = Constraint(kind, s, span, text=text)
        if any(contains_bbox(e.expr) for e in eqs):
            c.deferred = eqs
        else:
            c.equations = eqs
        s.constraints.append(c)
        self.model.constraints.append(c)

    def _check_subtree(self, owners, span, s: Structure) -> None:
        bad = [o for o in owners if not o.is_within(s)]
        if bad:
            o = bad[0]
            lca = _common_ancestor(o, s)
            where = f"`{lca.path}`" if lca else "a common parent"
            raise EvalError("E0202", f"this constraint in `{s.path}` refers to `{o.path}`, "
                            f"which is outside `{s.name}`'s subtree", span,
                            hint=f"a constraint may only use its own structure's subtree; "
                                 f"move it into {where}, which contains both")

    def _equation(self, e) -> None:
        if isinstance(e, A.BoolOp):
            if e.op != "and":
                raise EvalError("E0108", "`or` cannot join constraints", e.span,
                                hint="constraints all hold at once; join them with `and`")
            self._equation(e.left)
            self._equation(e.right)
            return
        if not isinstance(e, A.Compare):
            raise EvalError("E0108", "only comparisons can be joined with `and` into a constraint",
                            e.span, hint="write `a == b and c <= d`")
        vals = [self.eval(x) for x in e.operands]
        for op, (l, r), (ln, rn) in zip(e.ops, zip(vals, vals[1:]), zip(e.operands, e.operands[1:])):
            eqs = self._compare_eqs(op, l, r, e.span)
            self._add_constraint("equation", eqs, e.span, _src(self.sink, e.span),
                                 owners_of(l, r))

    def _compare_eqs(self, op, l, r, span) -> list[Equation]:
        if op == "!=":
            raise EvalError("E0108", "`!=` cannot be a constraint", span,
                            hint="state what should hold: `==`, `<=` or `>=`")
        if isinstance(l, (tuple, list)) and len(l) == 2:
            l = self._to_point(l, span)
        if isinstance(r, (tuple, list)) and len(r) == 2:
            r = self._to_point(r, span)
        if isinstance(l, GeomRef) and l.geom.kind == "Point":
            l = geom_member(l.geom, "p", self.struct)
        if isinstance(r, GeomRef) and r.geom.kind == "Point":
            r = geom_member(r.geom, "p", self.struct)
        if isinstance(l, PV) and isinstance(r, PV):
            if op != "==":
                raise EvalError("E0108", f"points can only be compared with `==`, not `{op}`", span)
            return [Equation(l.x - r.x), Equation(l.y - r.y)]
        if not isinstance(l, Q) or not isinstance(r, Q):
            raise EvalError("E0108", f"cannot constrain a {type_name(l)} {op} a {type_name(r)}", span,
                            hint="compare numbers, lengths or angles (e.g. `a.width == 2 * b.width`), "
                                 "or points with `==`")
        le, re_, _ = self._unify(l, r, span)
        if op == "==":
            return [Equation(le - re_)]
        if op in ("<=", "<"):
            return [Equation(re_ - le, True)]
        return [Equation(le - re_, True)]

    def _unify(self, a: Q, b: Q, span):
        try:
            return unify_add(a, b, self.unit_scale, DEG)
        except UnitError as ex:
            raise EvalError("E0109", str(ex), span,
                            hint="both sides must have the same unit kind (length, angle or number)")

    # ------------------------------------------------------------------ calls
    def _callee(self, f):
        if isinstance(f, A.Name):
            v, _ = self.scope.lookup(f.id)
            if v is not None:
                return v
            if lookup(f.id) is not None or f.id in FUNCTIONS:
                return Builtin(f.id)
            return None
        if isinstance(f, A.Member):
            obj = self._callee(f.obj) if isinstance(f.obj, (A.Name, A.Member)) else None
            if isinstance(obj, Namespace):
                return obj.scope.vars.get(f.name)
        return None

    def _call(self, node: A.Call, name: str | None = None):
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
        if isinstance(callee, Template):
            if name is None:
                raise EvalError("E0119", f"an instance of template `{callee.node.name}` needs a name",
                                node.span, hint=f"write `part = {callee.node.name}(...)`")
            return self._instantiate(callee, node, name)
        if not isinstance(callee, Builtin):
            raise EvalError("E0111", f"a {type_name(callee)} cannot be called", node.func.span)
        nm = callee.name
        if nm in FUNCTIONS:
            return self._function(nm, node)
        entry = lookup(nm)
        args = [self.eval(a) for a in node.args]
        kwargs = {kw.name: (self.eval(kw.value), kw) for kw in node.kwargs}
        variant, reason = choose_variant(entry, len(args), list(kwargs))
        if variant is None:
            span = node.span
            bad_kw = next((kw for kw in node.kwargs
                           if not any(kw.name in [a.name for a in v] for v in entry.variants)), None)
            if bad_kw is not None:
                names = sorted({a.name for v in entry.variants for a in v})
                raise EvalError("E0105", f"`{nm}` has no argument `{bad_kw.name}`", bad_kw.span,
                                hint=f"{entry.signature()}", suggestions=did_you_mean(bad_kw.name, names))
            code = "E0106" if reason and reason.startswith("missing") else "E0104"
            raise EvalError(code, f"`{nm}` {reason}", span, hint=entry.signature())
        bound = {}
        spans = {}
        for a, v, node_a in zip(variant, args, node.args):
            bound[a.name] = v
            spans[a.name] = node_a.span
        for k, (v, kw) in kwargs.items():
            bound[k] = v
            spans[k] = kw.value.span
        bound, spans = canonical_args(nm, bound), canonical_args(nm, spans)
        conv = {}
        for a in variant:
            if a.name in bound:
                conv[a.name] = self._coerce(bound[a.name], a.type, spans[a.name], nm, a.name)
            elif a.default is not None:      # registry defaults are in mm / radians
                dim = {"length": LEN, "angle": ANG, "number": NUM}.get(a.type)
                conv[a.name] = Q.num(a.default, dim) if dim else a.default
        if entry.category == "primitive":
            return self._primitive(canonical(nm), conv, node, spans)
        if entry.category == "operation":
            from .operations import OperationError, apply
            self._check_subtree(owners_of(*conv.values()), node.span, self._need_struct(node.span))
            try:
                return apply(self, canonical(nm), conv, name)
            except OperationError as ex:
                raise EvalError("E0108", str(ex), node.span, hint=entry.signature())
        owners = owners_of(*conv.values())
        try:
            eqs = BUILDERS[canonical(nm)](self, **conv)
        except ConstraintError as ex:
            raise EvalError("E0108", str(ex), node.span, hint=entry.signature())
        except UnitError as ex:
            raise EvalError("E0109", str(ex), node.span)
        self._add_constraint(canonical(nm), eqs, node.span, _src(self.sink, node.span), owners)
        return None

    def _primitive(self, kind, conv, node, spans):
        s = self._need_struct(node.span)
        for k, v in conv.items():
            bad = [o for o in owners_of(v) if o is not s]
            if bad:
                raise EvalError("E0201", f"geometry in `{s.path}` refers to `{k}` of `{bad[0].path}`, "
                                f"another structure", spans.get(k, node.span),
                                hint="geometry may only use geometry of its own structure; give it its "
                                     "own starting value and relate the two with a constraint, "
                                     "e.g. `Coincident(...)`, in a structure that contains both")
        if kind == "Text" and s.kind != "drawing":
            raise EvalError("E0120", f"Text must be in a `drawing` structure, not in {s.kind} `{s.name}`",
                            node.span, hint="put it in `drawing labels { ... }` inside this structure")
        self.n_geometry += 1
        if self.n_geometry > MAX_GEOMETRY:
            raise EvalError("E0303", f"more than {MAX_GEOMETRY} geometry objects", node.span,
                            hint="use fewer or larger repetitions")
        try:
            g = build(self, kind, conv, node.span)
        except PrimitiveError as ex:
            raise EvalError("E0108", str(ex), node.span, hint=lookup(kind).signature())
        if kind == "Text":
            from .text import text_extent
            g.data["extent"] = text_extent(g.data["text"], g.data["size"], g.data["anchor"])
        return GeomRef(g)

    # -- used by primitives.build
    def point(self, v: PV, label: str) -> Point:
        s = self.struct
        if v.obj is not None and v.obj.owner is s:
            return v.obj
        x0, y0 = self.value_of(v.x), self.value_of(v.y)
        ix = self.model.new_param(x0, True, s, f"{label}.x")
        iy = self.model.new_param(y0, True, s, f"{label}.y")
        p = Point(ix, iy, s, None, label)
        if as_const(v.x) is None or as_const(v.y) is None:
            c = Constraint("internal", s, None, [Equation(var(ix) - v.x), Equation(var(iy) - v.y)],
                           text=f"{label} placed at a derived point", implicit=True)
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
        self.struct.constraints.append(c2)
        self.model.constraints.append(c2)
        return sc

    def new_scalar(self, value: float, label: str, held: bool) -> Scalar:
        i = self.model.new_param(value, not held, self.struct, label)
        return Scalar(i, self.struct, "length", label)

    def internal(self, g, eqs, text: str) -> None:
        c = Constraint("internal", self.struct, g.span, eqs, text=text, implicit=True)
        self.struct.constraints.append(c)
        self.model.constraints.append(c)

    # ------------------------------------------------------------------ coercion
    def _to_point(self, v, span) -> PV:
        if isinstance(v, PV):
            return v
        if isinstance(v, GeomRef) and v.geom.kind == "Point":
            return geom_member(v.geom, "p", self.struct)
        if isinstance(v, (tuple, list)) and len(v) == 2 and all(isinstance(c, Q) for c in v):
            xs = [self._as_length(c, span) for c in v]
            return PV(xs[0], xs[1], None, owners_of(*v))
        raise EvalError("E0108", f"expected a point, got {type_name(v)}", span,
                        hint="write a point as `(x, y)` or refer to one, e.g. `rect.top_left`")

    def _as_length(self, q: Q, span):
        if q.dim == LEN:
            return q.expr
        if q.dim == NUM:
            return lift(q.expr) * self.unit_scale
        raise EvalError("E0109", f"expected a length, got a {dim_name(q.dim)}", span,
                        hint="give a length unit such as `mm` or `in`")

    def _coerce(self, v, typ: str, span, fname: str, aname: str):
        where = f"argument `{aname}` of `{fname}`"
        if typ == "any":
            return v
        if v is None and typ == "point":
            return None
        if typ in ("length", "angle", "number"):
            if not isinstance(v, Q):
                raise EvalError("E0108", f"{where} must be {_a(typ)}, got {type_name(v)}", span,
                                hint=lookup(fname).signature())
            want = {"length": LEN, "angle": ANG, "number": NUM}[typ]
            if v.dim == want:
                return v
            if v.dim == NUM:
                k = self.unit_scale if typ == "length" else DEG
                return Q(lift(v.expr) * k, want, v.owners)
            raise EvalError("E0109", f"{where} must be {_a(typ)}, got {_a(dim_name(v.dim))}", span,
                            hint=f"write it with a {typ} unit" + (" such as `mm`" if typ == "length" else
                                                                     " such as `deg`" if typ == "angle" else ""))
        if typ == "point":
            return self._to_point(v, span)
        if typ == "points":
            if not isinstance(v, (list, tuple)):
                raise EvalError("E0108", f"{where} must be a list of points, got {type_name(v)}", span)
            return [self._to_point(p, span) for p in v]
        if typ == "bool":
            if not isinstance(v, bool):
                raise EvalError("E0108", f"{where} must be true or false, got {type_name(v)}", span)
            return v
        if typ == "string":
            if isinstance(v, Q) and v.const() is not None:
                return _fmt_num(v.const())
            if not isinstance(v, str):
                raise EvalError("E0108", f"{where} must be a string, got {type_name(v)}", span)
            return v
        if typ == "line":
            if isinstance(v, GeomRef) and v.geom.kind in ("Line", "Slot"):
                return v
            raise EvalError("E0108", f"{where} must be a Line, got {type_name(v)}", span,
                            hint="rectangle edges are lines: `rect.top`, `rect.left`, ...")
        if typ == "circular":
            if isinstance(v, GeomRef) and v.geom.kind in ("Circle", "Arc"):
                return v
            raise EvalError("E0108", f"{where} must be a Circle or Arc, got {type_name(v)}", span)
        if typ == "curve":
            if isinstance(v, GeomRef) and v.geom.kind in ("Line", "Circle", "Arc"):
                return v
            raise EvalError("E0108", f"{where} must be a Line, Circle or Arc, got {type_name(v)}", span)
        if typ == "geometry":
            if isinstance(v, (GeomRef, PV)):
                return v
            if isinstance(v, (tuple, list)):
                return self._to_point(v, span)
            raise EvalError("E0108", f"{where} must be geometry, got {type_name(v)}", span)
        if typ == "boxed":
            if isinstance(v, (GeomRef, StructRef, BBoxRef)):
                return v
            raise EvalError("E0108", f"{where} must be a structure or geometry, got {type_name(v)}",
                            span)
        return v

    # ------------------------------------------------------------------ functions
    def _function(self, nm: str, node: A.Call):
        lo, hi, _doc = FUNCTIONS[nm]
        if node.kwargs:
            raise EvalError("E0105", f"`{nm}` takes no keyword arguments", node.kwargs[0].span)
        args = [self.eval(a) for a in node.args]
        if not lo <= len(args) <= hi:
            raise EvalError("E0104", f"`{nm}` takes {lo if lo == hi else f'{lo} to {hi}'} "
                            f"argument{'s' if hi > 1 else ''}, got {len(args)}", node.span)
        sp = node.span
        if nm == "range":
            ns = [self._int(a, sp) for a in args]
            r = range(*ns)
            if len(r) > MAX_ITER:
                raise EvalError("E0301", f"range of {len(r)} items exceeds the limit of {MAX_ITER}", sp)
            return [Q.num(i) for i in r]
        if nm == "len":
            if not isinstance(args[0], (list, tuple, str)):
                raise EvalError("E0108", f"`len` needs a list or string, got {type_name(args[0])}", sp)
            return Q.num(len(args[0]))
        if nm == "str":
            v = args[0]
            return _fmt_num(v.const()) if isinstance(v, Q) and v.const() is not None else str(v)
        if nm in ("min", "max"):
            if len(args) == 1 and isinstance(args[0], list):
                args = args[0]
            if not args:
                raise EvalError("E0108", f"`{nm}` of an empty list", sp)
            qs = [self._q(a, sp) for a in args]
            acc = qs[0]
            for q in qs[1:]:
                a, b, d = self._unify(acc, q, sp)
                acc = Q(func(nm, a, b), d, acc.owners | q.owners)
            return acc
        if nm == "norm":
            p = self._to_point(args[0], sp) if not isinstance(args[0], Q) else None
            if p is None:
                return Q(func("abs", args[0].expr), args[0].dim, args[0].owners)
            return Q(func("sqrt", p.x * p.x + p.y * p.y), LEN, p.owners)
        if nm == "distance":
            p, q = self._to_point(args[0], sp), self._to_point(args[1], sp)
            return Q(func("sqrt", (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y)), LEN,
                     p.owners | q.owners)
        q = [self._q(a, sp) for a in args]
        if nm in ("sin", "cos", "tan"):
            if q[0].dim not in (ANG, NUM):
                raise EvalError("E0109", f"`{nm}` needs an angle, got a {dim_name(q[0].dim)}", sp)
            return Q(func(nm, q[0].expr), NUM, q[0].owners)
        if nm in ("asin", "acos", "atan"):
            self._dimless(q[0], nm, sp)
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
            return Q(func("sqrt", q[0].expr), (d[0] // 2, d[1] // 2), q[0].owners)
        if nm == "abs":
            return Q(func("abs", q[0].expr), q[0].dim, q[0].owners)
        if nm == "square":
            return Q(q[0].expr * q[0].expr, mul_dim(q[0].dim, q[0].dim), q[0].owners)
        if nm in ("round", "floor", "ceil"):
            c = q[0].const()
            if c is None:
                raise EvalError("E0118", f"`{nm}` of a solved value", sp,
                                hint="round params and constants only")
            if nm == "round":
                nd = int(q[1].const() or 0) if len(q) > 1 else 0
                return Q.num(round(c, nd), q[0].dim)
            return Q.num(math.floor(c) if nm == "floor" else math.ceil(c), q[0].dim)
        if nm == "radians":
            return Q(lift(q[0].expr) * DEG, ANG, q[0].owners)
        if nm == "degrees":
            e = q[0].expr if q[0].dim == ANG else q[0].expr
            return Q(lift(e) * (1 / DEG), NUM, q[0].owners)
        raise EvalError("E0103", f"unknown function `{nm}`", sp)

    def _dimless(self, q: Q, nm, sp):
        if q.dim != NUM:
            raise EvalError("E0109", f"`{nm}` needs a plain number, got a {dim_name(q.dim)}", sp)

    def _q(self, v, sp) -> Q:
        if isinstance(v, bool):
            return Q.num(1.0 if v else 0.0)
        if isinstance(v, Q):
            return v
        raise EvalError("E0108", f"expected a number, got {type_name(v)}", sp)

    def _int(self, v, sp) -> int:
        q = self._q(v, sp)
        c = q.const()
        if c is None or q.dim != NUM:
            raise EvalError("E0108", "range() needs plain whole numbers", sp)
        if abs(c - round(c)) > 1e-9:
            raise EvalError("E0108", f"range() needs whole numbers, got {_fmt_num(c)}", sp)
        return int(round(c))

    # ------------------------------------------------------------------ expressions
    def eval(self, e, name: str | None = None):
        m = getattr(self, "_e_" + type(e).__name__)
        return m(e, name) if type(e) is A.Call else m(e)

    def _e_Num(self, e: A.Num):
        if not math.isfinite(e.value) or abs(e.value) > 1e15:
            raise EvalError("E0112", "this number is too large", e.span,
                            hint="AIDL numbers must stay below 1e15")
        if e.unit is None:
            return Q.num(e.value)
        if e.unit in UNITS_LENGTH:
            return Q.num(e.value * UNITS_LENGTH[e.unit], LEN)
        return Q.num(e.value * UNITS_ANGLE[e.unit], ANG)

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
                try:
                    out.append(format(c, fmt) if fmt else _fmt_num(c))
                except ValueError:
                    raise EvalError("E0108", f"bad format `{fmt}`", e.span)
            else:
                out.append(str(v).lower() if isinstance(v, bool) else str(v))
        return "".join(out)

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
        if e.id in ("pi", "PI"):
            return Q.num(math.pi)
        if e.id == "tau":
            return Q.num(2 * math.pi)
        # a structure's own name or an enclosing structure's name
        s = self.struct
        while s is not None:
            if s.name == e.id:
                return StructRef(s)
            s = s.parent
        if lookup(e.id) is not None or e.id in FUNCTIONS:
            return Builtin(e.id)
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
        return self._call(e, name)

    def _e_Keyword(self, e):
        raise EvalError("E0001", "keyword argument outside a call", e.span)

    def _e_Member(self, e: A.Member):
        obj = self.eval(e.obj)
        return self.member(obj, e.name, e.name_span, e.obj.span)

    def member(self, obj, name: str, span, obj_span=None):
        S = self.struct
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
                return s.scope[name]
            if name in s.children:
                return StructRef(s.children[name])
            if name in ("width", "height", "left", "right", "top", "bottom", "center"):
                return self.member(BBoxRef(s), name, span)
            cands = list(s.scope) + list(s.children) + ["bb"]
            sugg = did_you_mean(name, cands)
            raise EvalError("E0102", f"structure `{s.path}` has no member `{name}`", span,
                            hint=f"did you mean `{sugg[0]}`?" if sugg else
                            f"its members: {', '.join(sorted(cands)[:12])}", suggestions=sugg)
        if isinstance(obj, GeomRef):
            g = obj.geom
            if name == "bb":
                return BBoxRef(g)
            v = geom_member(g, name, S)
            if v is not None:
                return v
            cands = member_names(g)
            sugg = did_you_mean(name, cands)
            raise EvalError("E0102", f"a {g.kind} has no member `{name}`", span,
                            hint=f"did you mean `{sugg[0]}`?" if sugg else f"its members: {', '.join(cands)}",
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
        raise EvalError("E0102", f"a {type_name(obj)} has no member `{name}`", span)

    def _e_Index(self, e: A.Index):
        obj = self.eval(e.obj)
        idx = self.eval(e.index)
        if not isinstance(obj, (list, tuple, str)):
            raise EvalError("E0111", f"a {type_name(obj)} cannot be indexed", e.obj.span,
                            hint="only lists (loops, comprehensions, `poly.points`) are indexed")
        i = self._q(idx, e.index.span).const()
        if i is None or abs(i - round(i)) > 1e-9:
            raise EvalError("E0108", "a list index must be a whole number", e.index.span)
        i = int(round(i))
        n = len(obj)
        if not -n <= i < n:
            raise EvalError("E0110", f"index {i} is out of range: the list has {n} item{'s' if n != 1 else ''}",
                            e.index.span, hint=f"valid indices are 0 to {n - 1}" if n else "the list is empty")
        return obj[i]

    def _e_TupleLit(self, e):
        return tuple(self.eval(x) for x in e.items)

    def _e_ListLit(self, e):
        return [self.eval(x) for x in e.items]

    def _e_ListComp(self, e: A.ListComp):
        items = self._iterable(self.eval(e.iter), e.iter)
        out = []
        outer = self.scope
        try:
            for item in items:
                sc = Scope(outer, self.struct, self.file)
                sc.vars[e.var] = item
                self.scope = sc
                if e.cond is not None and not self._truth(self.eval(e.cond), e.cond):
                    continue
                out.append(self.eval(e.elt))
        finally:
            self.scope = outer
        return out

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
            return Q(-lift(v.expr), v.dim, v.owners)
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
                a, b, _ = self._unify(self._q(l, e.span), self._q(r, e.span), e.span)
                ca, cb = as_const(a), as_const(b)
                if ca is None or cb is None:
                    raise EvalError("E0118", "a condition cannot depend on geometry the solver moves",
                                    e.span, hint="as a statement of its own, `a == b` is a constraint")
                res = {"==": abs(ca - cb) <= 1e-9 * max(1.0, abs(ca), abs(cb)), "!=": abs(ca - cb) > 1e-9,
                       "<": ca < cb, "<=": ca <= cb, ">": ca > cb, ">=": ca >= cb}[op]
            if not res:
                return False
        return True

    def _e_BinOp(self, e: A.BinOp):
        l, r = self.eval(e.left), self.eval(e.right)
        op = e.op
        if op == "+" and isinstance(l, str) and isinstance(r, str):
            return l + r
        if op == "+" and isinstance(l, list) and isinstance(r, list):
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
            raise EvalError("E0108", f"cannot apply `{op}` to {type_name(l)} and {type_name(r)}", e.span)
        own = l.owners | r.owners
        if op in ("+", "-"):
            a, b, d = self._unify(l, r, e.span)
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
                return Q.num(math.floor(ca / cb), mul_dim(l.dim, r.dim, -1))
            return Q.num(math.fmod(ca, cb) if ca * cb >= 0 else ca - cb * math.floor(ca / cb), d)
        if op == "**":
            cb = r.const()
            if cb is None or r.dim != NUM:
                raise EvalError("E0108", "an exponent must be a plain number known before solving", e.right.span)
            if l.dim != NUM and abs(cb - round(cb)) > 1e-12:
                raise EvalError("E0109", "a length can only be raised to a whole power", e.span)
            k = int(round(cb)) if l.dim != NUM else 1
            ca = l.const()
            if ca is not None:
                try:
                    return Q.num(ca ** cb, (l.dim[0] * k, l.dim[1] * k))
                except (OverflowError, ZeroDivisionError) as ex:
                    raise EvalError("E0112", f"math error: {ex}", e.span)
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
                raise EvalError("E0109", "a point can only be scaled by a plain number", e.span)
            k = q.expr if op == "*" else lift(1.0) / q.expr
            return PV(lift(p.x) * k, lift(p.y) * k, None, p.owners | q.owners)
        raise EvalError("E0108", f"cannot apply `{op}` to {type_name(l)} and {type_name(r)}", e.span,
                        hint="points add and subtract as vectors; scale them by numbers")


def _is_plain_const(st) -> bool:
    """A top-level `NAME = expr` that creates no geometry (a file constant)."""
    if not isinstance(st, A.Assign):
        return False
    for n in A.walk(st.value):
        if isinstance(n, A.Call) and isinstance(n.func, A.Name):
            e = lookup(n.func.id)
            if e is not None and e.category in ("primitive", "operation"):
                return False
            if n.func.id not in FUNCTIONS and e is None:
                return False   # a template call
    return True


def _is_geometry_stmt(st) -> bool:
    """A top-level statement that creates geometry directly (not a constraint)."""
    v = st.value if isinstance(st, A.Assign) else st.expr if isinstance(st, A.ExprStmt) else None
    if isinstance(v, A.Call) and isinstance(v.func, A.Name):
        e = lookup(v.func.id)
        return e is not None and e.category == "primitive"
    return isinstance(st, (A.For, A.If))


def _common_ancestor(a: Structure, b: Structure):
    anc = set()
    s = a
    while s is not None:
        anc.add(s)
        s = s.parent
    s = b
    while s is not None:
        if s in anc:
            return s
        s = s.parent
    return None


def _src(sink: DiagnosticSink, span: Span | None) -> str:
    if span is None:
        return ""
    src = sink.sources.get(span.file, "")
    return " ".join(src[span.start:span.end].split())[:120]


def _a(word: str) -> str:
    return ("an " if word[:1] in "aeiou" else "a ") + word


def _fmt_num(c: float) -> str:
    if abs(c - round(c)) < 1e-9:
        return str(int(round(c)))
    return f"{c:.6g}"
