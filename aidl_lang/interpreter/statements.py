"""Statements: files and imports, structure bodies, assignments, loops, template instances,
constraints and equations (docs/language.md \u00a73-\u00a76; the paper's reference and subtree validity
rules are checked in :meth:`Statements._check_subtree`).

A mixin of :class:`aidl_lang.interp.Interpreter`; it uses the other parts through ``self``."""
from __future__ import annotations

from pathlib import Path

from .. import ast as A
from ..base.diagnostics import EvalError, Span, did_you_mean
from ..geometry.relations.bbox import contains_bbox, reach as bbox_reach
from ..geometry.core.model import Constraint, Equation, Model, Structure
from ..geometry.relations.members import member as geom_member
from ..geometry.core.expr import Lin, _new
from ..geometry.core.values import (ANG, LEN, NUM, dim_name, PV, Function, GeomRef, Namespace, Q, StructRef, Template, UnitError, angle_scale, owners_of, type_name, unify_add)
from ..base.limits import MAX_TEMPLATE_DEPTH
from ..registry import CONSTANTS, UNITS_LENGTH, template_param
from ..library.sources import ImportRefused, read_import, resolve_import
from .materials import material_statement, note_material
from .arguments import check_kinds, kind_error, precheck_asserts
from .asserts import Asserts
from .constants import early_constants, late_constant
from .order import changes_read_below
from .common import (loop_bound_names, ANGLE_TWICE, DEG, POISON, fraction_hint, FileCtx, Scope, _STMT_ERRORS, _Silent, _a, _common_ancestor,
                     _definition_lines, _fmt_num, _src, _is_geometry_stmt, _is_plain_const,
                     file_functions)




class Statements(Asserts):
    # ------------------------------------------------------------------ entry
    def run(self, program: A.Program) -> Model:
        self.root_dir = Path(program.path).resolve().parent
        fctx = self._load_file_decls(program, is_main=True)
        self.file = fctx
        top = [s for s in program.stmts if not isinstance(s, (A.UnitsDecl, A.Import, A.ParamDecl, A.Def,
                                                               A.Func, A.ThicknessDecl))]
        structs = [s for s in top if isinstance(s, A.StructDecl)]
        asserts = [s for s in top if isinstance(s, A.Assert)]
        funcs = file_functions(program.stmts)
        loose = [s for s in top if not isinstance(s, (A.StructDecl, A.Assert))
                 and not _is_plain_const(s, funcs)]
        for name in self.overrides:
            if name not in getattr(fctx, "params", {}):
                self.sink.error("E0113", f"`--set {name}=...`: the model has no param `{name}`",
                                None, hint="params: " + ", ".join(sorted(fctx.params)) if fctx.params else
                                "declare it with `param NAME = VALUE` at the top of the file",
                                suggestions=did_you_mean(name, fctx.params))
        if len(structs) == 1 and not loose:
            consts = [s for s in top if s is not structs[0] and not isinstance(s, A.Assert)]
            self.scope = fctx.scope
            for s in consts:
                self._exec_stmt(s)
            st = structs[0]
            try:
                root = self._new_structure(st.name, st.kind, None, st.span)
            except EvalError as e:       # a `cut` at the top (E0125): said, run as a solid
                self.error(e)
                root = self._new_structure(st.name, "solid", None, st.span)
            self._run_body(root, st.body, Scope(fctx.scope, root, fctx))
            if asserts:                 # after the structure, which they may name
                outer = Scope(fctx.scope, root, fctx)
                outer.vars[st.name] = StructRef(root)
                saved = self.struct, self.scope
                self.struct, self.scope = root, outer
                for s in asserts:
                    self._exec_stmt(s)
                self.struct, self.scope = saved
        else:
            kind = "assembly" if not any(_is_geometry_stmt(s) for s in loose) else "solid"
            root = self._new_structure("model", kind, None, program.span)
            self.scope = fctx.scope
            for s in top:
                if _is_plain_const(s, funcs):
                    self._exec_stmt(s)
            scope = Scope(fctx.scope, root, fctx)
            rest = [s for s in top if not _is_plain_const(s, funcs)]
            self._run_body(root, A.Block(program.span, rest), scope)
        # `thickness 3 mm` at the top level: the default of every part (after the constants)
        saved = self.struct, self.scope
        self.struct, self.scope = None, fctx.scope
        for s in program.stmts:
            if isinstance(s, A.ThicknessDecl):
                self._exec_stmt(s)
        self.struct, self.scope = saved
        self.settle_on_top()                            # Place(on=, (x, y)): its top face
        self.model.root = root
        self.model.constants = fctx.scope.vars
        from .sinks import fillet_copies, sink_copies
        from .materials import thickness_mismatch
        thickness_mismatch(self.model, self.sink)       # W0118: after every `thickness`
        from ..geometry.derived.operations import hold_mirror_lines
        sink_copies(self.model)          # a pattern's copies of a sunk hole, sunk alike
        fillet_copies(self.model)        # and of a shape filleted to another, filleted alike
        hold_mirror_lines(self.model)    # a mirror line nothing places stays where written
        return self.model

    def _new_structure(self, name, kind, parent, span, template=None) -> Structure:
        self.count_object(span)
        if kind == "cut" or (parent is not None and parent.kind == "cut"):
            _check_cut_place(name, kind, parent, span, template)
        s = Structure(name, kind, parent, span, template=template)
        s.fx, s.fy = self.model.new_pair(0.0, 0.0, parent is not None, s, f"{name}.frame")
        if parent is not None:
            parent.children[name] = s
        self.model.structures.append(s)
        return s

    # ------------------------------------------------------------------ files
    def _load_file_decls(self, program: A.Program, is_main: bool) -> FileCtx:
        fctx = FileCtx(program.path)
        fctx.params = {}
        fctx.param_ranges = {}
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
                    if st.span is not None:
                        self.model.file_units[st.span.file] = u
        self.model.units = "mm"
        early = early_constants(program.stmts)
        for st in program.stmts:
            try:
                if st in early:
                    # a constant above a param that reads it (and no param): worked out here,
                    # before the param (issue 111: `hooks = 5` then `param w = hooks * pitch`)
                    fctx.scope.vars[st.name] = POISON
                    fctx.scope.vars[st.name] = self.eval(st.value)
                elif isinstance(st, A.Import):
                    self._import(st, fctx)
                elif isinstance(st, A.Def):
                    if st.kind not in A.STRUCTURE_KINDS:
                        raise EvalError("E0108", f"unknown structure kind `{st.kind}`", st.kind_span,
                                        hint="a template returns solid, hole, cut, drawing or assembly",
                                        suggestions=did_you_mean(st.kind, list(A.STRUCTURE_KINDS)))
                    fctx.scope.vars[st.name] = Template(st, fctx.scope, fctx.unit_scale)
                elif isinstance(st, A.Func):
                    fctx.scope.vars[st.name] = Function(st, fctx.scope)
                elif isinstance(st, A.ParamDecl):
                    fctx.params[st.name] = None
                    overridden = st.name in self.overrides and is_main
                    val = default = self.eval(st.value)
                    if overridden:
                        try:
                            val = self._eval_override(st.name, self.overrides[st.name], fctx,
                                                      val, st.value)
                        except EvalError as e:
                            # one error that names the `--set` argument; the file goes on
                            # with the default, so nothing in it is blamed for the value
                            self.error(e)
                            overridden = False
                    if st.options:
                        try:
                            self._param_range(st, val, overridden, fctx.param_ranges)
                        except _Silent:
                            pass    # its range reads a param already said to be wrong: the
                            # value stays, its range is not judged (no second message)
                        except EvalError as e:
                            self.error(e)
                            if overridden and e.code == "E0124":
                                # a `--set` past the range: that one error, the file goes
                                # on with the default (no math error where it is used);
                                # the value asked for stays the param's (a form moves it
                                # back into the range: aidl studio)
                                fctx.scope.vars[st.name] = default
                                fctx.params[st.name] = val
                                continue
                            if getattr(e, "outside", False):
                                # past a range that follows other params (`max=d / 2`
                                # after `--set d=...`): that one error, its uses quiet
                                fctx.scope.vars[st.name] = POISON
                                fctx.params[st.name] = val
                                continue
                    fctx.scope.vars[st.name] = val
                    fctx.params[st.name] = val
            except _Silent:
                # a param whose value reads one already said to be wrong: quiet, as its uses
                if isinstance(st, A.ParamDecl):
                    fctx.scope.vars[st.name] = POISON
            except EvalError as e:
                if isinstance(st, A.ParamDecl):
                    e = late_constant(e, program) or e
                    fctx.scope.vars[st.name] = POISON    # said once: its uses stay quiet
                self.error(e)
        if not is_main:
            for st in program.stmts:
                if isinstance(st, A.Assign) and _is_plain_const(st, file_functions(
                        program.stmts)):
                    try:
                        fctx.scope.vars[st.name] = self.eval(st.value)
                    except EvalError as e:
                        self.error(e)
        self.file = prev if not is_main else fctx
        return fctx

    def _param_range(self, st: A.ParamDecl, val, overridden: bool,
                     into: dict | None = None) -> dict:
        """Check ``param NAME = V, min=A, max=B, step=S`` (docs/language.md, *Params*): the
        options have the param's dimension, ``min <= max``, ``step > 0``, and the value (the
        default, or the ``--set`` override) lies in ``[min, max]`` (E0124).  Returns
        ``{"min": float|None, "max": ..., "step": ...}`` in internal units (mm, rad), also
        written to ``into[NAME]`` once the range itself is sound, before the value is checked
        against it (a form moves a value that left its range, one that depends on other
        params, back into it: aidl studio)."""
        from ..geometry.core.values import dim_name
        if not isinstance(val, Q) or val.const() is None:
            raise EvalError("E0124", f"param `{st.name}` has a range but is not a number, length "
                            "or angle", st.options[0].span,
                            hint="drop min/max/step, or give the param a numeric value")
        out: dict = {"min": None, "max": None, "step": None}
        for o in st.options:
            if o.name not in out:
                raise EvalError("E0105", f"param option `{o.name}` is not one of min, max, step",
                                o.name_span, hint="write e.g. `param w = 40 mm, min=10 mm, "
                                "max=80 mm, step=1 mm`", suggestions=did_you_mean(o.name, list(out)))
            q = self.eval(o.value)
            if isinstance(q, Q) and q.dim != val.dim and q.const() is not None \
                    and q.dim == (0, 0) and val.dim == (1, 0):
                q = Q.num(q.const() * self.file.unit_scale, val.dim)     # a bare number: file units
            if not isinstance(q, Q) or q.const() is None or q.dim != val.dim:
                want = dim_name(val.dim)
                raise EvalError("E0124", f"`{o.name}` of param `{st.name}` must be a {want} like "
                                "its value", o.value.span, hint=f"give `{o.name}` the param's unit")
            out[o.name] = q.const()
        lo, hi, step = out["min"], out["max"], out["step"]
        opt = {o.name: o for o in st.options}
        if lo is not None and hi is not None and lo > hi:
            from .empty_range import empty_range     # "swap them" only where it is safe
            raise empty_range(self, st, opt, lo, hi, val, _fmt_q)
        if step is not None and step <= 0:
            raise EvalError("E0124", f"param `{st.name}`: step must be positive", opt["step"].span)
        if into is not None:
            into[st.name] = out
        v = val.const()
        bad = "min" if lo is not None and v < lo - 1e-9 else \
              "max" if hi is not None and v > hi + 1e-9 else None
        if bad:
            shown = _fmt_q(v, val.dim)
            rng = f"{_fmt_q(lo, val.dim) if lo is not None else '...'} .. " \
                  f"{_fmt_q(hi, val.dim) if hi is not None else '...'}"
            if overridden:
                raise EvalError("E0124", f"`--set {st.name}={self.overrides[st.name]}`: {shown} is "
                                f"outside the range {rng} declared for `{st.name}`", opt[bad].span,
                                hint=f"choose a value from {rng}, or widen the range here")
            err = EvalError("E0124", f"param `{st.name}` = {shown} is outside its own range {rng}",
                            st.value.span, hint=f"change the value or `{bad}`")
            err.outside = True          # its uses say nothing more (the value is not meant)
            raise err
        return out

    def _eval_override(self, name: str, text: str, fctx: FileCtx, default=None, expr=None):
        """The value of ``--set NAME=TEXT`` (also ``aidl_lang.compile(overrides=...)`` and the
        live preview's sliders) for the param whose value in the file is ``default``.  Raises
        E0113, naming the ``--set`` argument, when ``TEXT`` does not read as a value or is of
        another kind than the default (a length for an angle, a word for a number): that one
        error, not the errors the wrong value would cause where the param is used (issue
        28).  A bare number for a length or an angle param is in the param's own unit, the
        one its value ``expr`` is written in (``--set w=40`` on ``param w = 60 mm`` is 40 mm,
        ``--set angle=20`` on ``param angle = 30 deg`` is 20 deg; else the file's units or
        degrees: :func:`~.param_units.own_unit`, issue 105); a unit given for a param whose
        default is a bare number is checked where it is used (:meth:`override_misuse`)."""
        from ..geometry.core.values import ANG, dim_name
        from ..parser import ParseError, parse_expression
        arg = f"`--set {name}={text}`"
        want = type_name(default) if default is not None else "value"
        if isinstance(default, Q):
            shown = _fmt_q(default.const(), default.dim) if default.const() is not None \
                else None
            like = _a(dim_name(default.dim)) + (f" like its default `{shown}`" if shown else "")
            example = {LEN: f"`--set {name}=40mm`", ANG: f"`--set {name}=30deg`"}.get(
                default.dim, f"`--set {name}=4`")
        elif isinstance(default, bool):
            like, example = "true or false", f"`--set {name}=true`"
        else:
            like, example = _a(want), f"`--set {name}=...`"
        try:
            node = parse_expression(text, "<--set>", self.sink)
        except ParseError:
            raise EvalError("E0113", f"{arg}: cannot read `{text}` as a value", None,
                            hint=f"`{name}` is {like}: write a number with an optional unit, "
                                 f"e.g. {example}")
        if isinstance(node, A.Name) and fctx.scope.lookup(node.id)[1] is None \
                and node.id not in CONSTANTS:
            if isinstance(default, (Q, bool)):
                raise EvalError("E0113", f"{arg}: `{text}` is not a number or a known name, and "
                                f"`{name}` is {like}", None, hint=f"write e.g. {example}")
            return text                         # a bare word: a string
        try:
            val = self.eval(node)
        except EvalError as e:
            raise EvalError("E0113", f"{arg}: {e.message}", None, hint=e.hint,
                            suggestions=e.suggestions)
        if isinstance(default, Q) and isinstance(val, Q):
            a, b = default.dim, val.dim
            if a != b and NUM not in (a, b):
                raise EvalError("E0113", f"{arg}: `{name}` is {like}, got {_a(dim_name(b))}",
                                None, hint=f"give it in {_a(dim_name(a))} unit, e.g. {example}")
            if a == NUM and b != NUM:
                self.override_units[name] = (text, b)
            if a in (LEN, ANG) and b == NUM and val.const() is not None:
                # a bare number in the param's own unit (was the file's units, and an angle
                # param's range refused it: issue 105)
                from .param_units import own_unit, unit_scale
                unit = own_unit(expr, a, next((u for u, k in UNITS_LENGTH.items()
                                               if k == fctx.unit_scale), "mm"))
                val = Q.num(val.const() * unit_scale(unit), a)
        elif isinstance(default, Q) or isinstance(default, bool):
            if not (isinstance(default, bool) and isinstance(val, bool)):
                raise EvalError("E0113", f"{arg}: `{name}` is {like}, got {_a(type_name(val))}", None,
                                hint=f"write e.g. {example}")
        return val

    def _import(self, st: A.Import, fctx: FileCtx) -> None:
        from ..parser import parse_import
        raw = st.path
        try:
            target = resolve_import(raw, fctx.path)
        except ImportRefused as ex:
            raise EvalError(ex.code, ex.message, st.path_span, hint=ex.hint,
                            suggestions=ex.suggestions)
        key = str(target)
        if key in self.loading:
            raise EvalError("E0115", f"import cycle: `{raw}` imports this file again", st.path_span,
                            hint="move the shared templates into a third file")
        if key not in self.loaded:
            try:
                text = read_import(target, raw)
            except ImportRefused as ex:
                raise EvalError(ex.code, ex.message, st.path_span, hint=ex.hint)
            # errors in the file (its syntax, its constants): at the import
            self.sink.calls.append((f"the file `{raw}`", st.span))
            self.sink.called(Span(key, 1, 1, 1, 1, 0, -1), self.sink.calls)
            try:
                prog = parse_import(text, key, self.sink)
                self.loading.append(key)
                saved = (self.scope, self.file)
                try:
                    self.loaded[key] = self._load_file_decls(prog, is_main=False)
                finally:
                    self.scope, self.file = saved
                    self.loading.pop()
            finally:
                self.sink.calls.pop()
        sub = self.loaded[key]
        if st.alias:
            fctx.scope.vars[st.alias] = Namespace(st.alias, sub.scope)
        else:
            for k, v in sub.scope.vars.items():
                fctx.scope.vars.setdefault(k, v)

    # ------------------------------------------------------------------ statements
    def _run_body(self, struct: Structure, block: A.Block, scope: Scope) -> None:
        """Run a structure body: definitions (assignments, structures, loops, ifs) in order,
        then its constraint statements (bare calls and equations at the body's top level), so
        a constraint may name geometry defined below it (docs/language.md, "Order"); a change
        in place that a definition below reads runs just before it (:mod:`.order`)."""
        saved = (self.struct, self.scope, self.body_stmts)
        self.struct, self.scope = struct, scope
        self.body_stmts = block.stmts        # for "defined later" (see later_definition)
        struct.scope = scope.vars            # members (`self.body`) are visible while it runs
        try:
            later = []
            first = changes_read_below(block.stmts)     # a change a definition below reads
            done = {id(c) for cs in first.values() for c in cs}
            for i, st in enumerate(block.stmts):        # _exec_stmt, inline for assignments
                t = type(st)
                if t is A.ExprStmt or t is A.Assert:
                    if id(st) not in done:
                        later.append(st)
                elif t is A.Assign:
                    for c in first.get(i, ()):
                        self._exec_stmt(c)
                    self.cur_span = st.span
                    try:
                        self._assign(st)
                    except _STMT_ERRORS as ex:
                        self._stmt_failed(st, ex)
                else:
                    self._exec_stmt(st)
            for st in later:            # _exec_stmt, inline
                self.cur_span = st.span
                try:
                    if type(st) is A.Assert:
                        self._assert(st)
                    else:
                        self._expr_stmt(st.expr)
                except _STMT_ERRORS as ex:
                    self._stmt_failed(st, ex)
        finally:
            self.struct, self.scope, self.body_stmts = saved

    def later_definition(self, name: str) -> int | None:
        """The line of ``name``'s first definition in the body being run (also inside its
        loops and ifs), or None."""
        return _definition_lines(self.body_stmts or []).get(name)

    def _exec_block(self, block: A.Block) -> None:
        for st in block.stmts:
            self._exec_stmt(st)

    def _exec_stmt(self, st) -> None:
        self.cur_span = st.span
        try:
            t = type(st)                 # the two common statements without _exec's frame
            if t is A.Assign:
                self._assign(st)
            elif t is A.ExprStmt:
                self._expr_stmt(st.expr)
            else:
                self._exec(st)
        except _STMT_ERRORS as ex:
            self._stmt_failed(st, ex)

    def _stmt_failed(self, st, ex: Exception) -> None:
        """What a statement that raised ``ex`` (one of ``_STMT_ERRORS``) reports: nothing
        for a name whose definition already failed, the error itself, a math error (E0112)
        or too deep an expression (E0302); the statement is skipped, and the name it would
        have defined poisoned (its uses say nothing more)."""
        # later uses of the names it defines stay quiet (issue 95: a name left unbound by a
        # failed or skipped definition was "unknown name" at each use, a cascade)
        if isinstance(st, A.Assign):
            self.scope.vars[st.name] = POISON
        elif isinstance(st, A.StructDecl):
            self.scope.vars.setdefault(st.name, POISON)
        elif isinstance(st, (A.For, A.If)):
            for name in _definition_lines([st]):
                self.scope.vars.setdefault(name, POISON)
        if isinstance(ex, _Silent):
            pass
        elif isinstance(ex, EvalError):
            self.error(ex)
        elif isinstance(ex, (ValueError, ZeroDivisionError, OverflowError)):
            self.error(EvalError("E0112", f"math error: {ex}", st.span,
                                 hint="check for division by zero or sqrt/asin of an out-of-range value"))
        else:
            self.error(EvalError("E0302", "expression nested too deeply", st.span,
                                 hint="split it into named constants"))

    def _exec(self, st) -> None:
        t = type(st)
        if t is A.Assign:
            self._assign(st)
        elif t is A.ExprStmt:
            self._expr_stmt(st.expr)
        elif t is A.StructDecl:
            self._struct_decl(st)
        elif t is A.KindAssign:
            self._assign(st)
        elif isinstance(st, A.ThicknessDecl):
            material_statement(self, st)
        elif t is A.Assert:
            self._assert(st)
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
        elif isinstance(st, (A.ParamDecl, A.Import, A.UnitsDecl)):
            # (a `def` in a structure was hoisted above it by the parser)
            what = {A.ParamDecl: "param", A.Import: "import", A.UnitsDecl: "units"}[type(st)]
            raise EvalError("E0116", f"`{what}` is only allowed at the top level of a file", st.span,
                            hint=f"move the `{what}` line to the top of the file")

    def _need_struct(self, span) -> Structure:
        if self.struct is None:
            raise EvalError("E0117", "geometry and constraints must be inside a structure", span,
                            hint="wrap them in `solid NAME { ... }`")
        return self.struct

    def _struct_decl(self, st: A.StructDecl, name: str | None = None):
        parent = self._need_struct(st.span)
        if st.kind not in A.STRUCTURE_KINDS:
            raise EvalError("E0108", f"unknown structure kind `{st.kind}`", st.kind_span,
                            hint="a structure is `solid`, `hole`, `cut`, `drawing` or `assembly` NAME { ... }",
                            suggestions=did_you_mean(st.kind, list(A.STRUCTURE_KINDS)))
        name = name or st.name + self._loop_suffix()
        self._check_new_name(st.name, st.name_span, parent)
        child = self._new_structure(name, st.kind, parent, st.span)
        prev = self.scope.vars.get(st.name)
        if prev is not None and not isinstance(prev, (GeomRef, StructRef)):
            # run gf: a template's parameter `aperture` and its `hole aperture { ...
            # diameter=aperture }`: the name is the hole from here on (call_hints.shadowed)
            child.hides = st.name
        self.scope.vars[st.name] = StructRef(child)
        self._run_body(child, st.body, Scope(self.scope, child, self.file))
        return child

    def _loop_suffix(self) -> str:
        """``[i]`` per enclosing loop of the current structure body (outermost first): the
        innermost loop iteration's ``loop_suffix``, which holds its enclosing loops' too
        (:meth:`_for_items`); ``""`` outside a loop."""
        sc = self.scope
        while sc is not None and sc.struct is self.struct and sc.parent is not None:
            suffix = sc.__dict__.get("loop_suffix")
            if suffix is not None:
                return suffix
            sc = sc.parent
        return ""

    def _check_new_name(self, name: str, span, struct: Structure) -> None:
        prev = self.scope.vars.get(name)
        if isinstance(prev, (GeomRef, StructRef)):
            raise EvalError("E0107", f"`{name}` is already defined in `{struct.path}`", span,
                            hint="give each geometry and structure its own name")

    def _assign(self, st: A.Assign) -> None:
        v = st.value
        name = st.name
        callee = None
        if type(v) is A.Call and (type(v.func) is A.Name or type(v.func) is A.Member):
            callee = self._callee(v.func)
            if type(callee) is Template:
                self._check_new_name(name, st.name_span, self._need_struct(st.span))
                ref = self._instantiate(callee, v, name + self._loop_suffix(),
                                        kind=self._kind_of(st))
                self.scope.vars[name] = ref
                return
        if type(st) is A.KindAssign:
            self._kind_of(st)
            raise EvalError("E0108", f"`{st.kind} {name} = ...` makes a template instance of "
                            f"kind {st.kind}, but the value is not a template call",
                            st.kind_span,
                            hint=f"write `{st.kind} {name} {{ ... }}` around geometry, or call "
                                 f"a template: `{st.kind} {name} = outline(...)`")
        if name in CONSTANTS or name == "self":
            raise EvalError("E0107", f"`{name}` is a built-in name and cannot be assigned",
                            st.name_span, hint="choose another name")
        if type(v) is A.Call and self.struct is not None:
            prev = self.scope.vars.get(name)         # self._check_new_name(...), inline
            if prev is not None and (type(prev) is GeomRef or type(prev) is StructRef):
                self._check_new_name(name, st.name_span, self.struct)
        if callee is not None:
            val = self._call_statement(v, callee, name)
        else:
            val = self.eval(v, name=name)
        tv = type(val)
        if tv is GeomRef:
            g = val.geom
            if not g.name and g.owner is self.struct:
                g.name = name
        elif isinstance(val, list):
            for i, item in enumerate(val):
                if isinstance(item, GeomRef) and not item.geom.name:
                    item.geom.name = f"{name}[{i}]"
        self.scope.vars[name] = val

    def _kind_of(self, st) -> str | None:
        """The structure kind written before a template instance's name (``hole h = t()``),
        or None for a plain assignment."""
        if type(st) is not A.KindAssign:
            return None
        if st.kind not in A.STRUCTURE_KINDS:
            raise EvalError("E0108", f"unknown structure kind `{st.kind}`", st.kind_span,
                            hint="an instance's kind is `solid`, `hole`, `cut`, `drawing` or "
                                 "`assembly`: `hole h = outline(...)`",
                            suggestions=did_you_mean(st.kind, list(A.STRUCTURE_KINDS)))
        return st.kind

    def _call_statement(self, node: A.Call, callee, name: str | None):
        """What ``eval`` does for a call that is a statement's whole value, with its callee
        (``None``: not yet known) at hand: one step, then :meth:`_call`."""
        n = self.steps + 1               # self.step(node.span), inline
        if n > self.budget.steps or not n & 127:
            self.step(node.span)
        else:
            self.steps = n
        return self._call(node, name, callee)

    def _expr_stmt(self, e) -> None:
        t = type(e)
        if t is A.Call:
            f = e.func
            val = self._call_statement(e, self._callee(f) if type(f) is A.Name else None, None)
        elif t is A.Compare or t is A.BoolOp:
            self._equation(e)
            return
        else:
            val = self.eval(e)
        if val is None or isinstance(val, (GeomRef, StructRef)) or type(val).__name__ == "Copies":
            return
        self.sink.warning("W0101", "this statement has no effect", e.span,
                          hint="name the value (`x = ...`) or write a constraint (`a == b`)")

    def _for(self, st: A.For) -> None:
        items = self._iterable(self.eval(st.iter), st.iter)
        collected: dict[str, list] = {}
        outer = self.scope
        self.frames.append((f"the loop `for {st.var} in ...`", st.span))
        try:
            self._for_items(st, items, collected, outer)
        finally:
            self.frames.pop()
        for name, vals in collected.items():
            outer.vars[name] = vals
        if getattr(outer, "loop_index", None) is None:     # (an inner loop's: the outer's)
            for name in loop_bound_names(st.body):      # bound by no pass: an empty list
                if name not in collected and outer.lookup(name)[1] is None:
                    outer.vars[name] = []

    def _for_items(self, st: A.For, items, collected, outer) -> None:
        base = self._loop_suffix()          # the enclosing loops' indices (self.scope: outer)
        for k, item in enumerate(items):
            self.step(st.span)
            sc = Scope(outer, self.struct, self.file)
            sc.vars[st.var] = item
            sc.loop_index = k
            sc.loop_var = st.var
            sc.loop_suffix = f"{base}[{k}]"
            self.scope = sc
            try:
                for s in st.body.stmts:
                    self._exec_stmt(s)
            finally:
                self.scope = outer
            for name, v in sc.vars.items():
                if name != st.var:
                    collected.setdefault(name, []).append(v)

    def _iterable(self, v, node) -> list:
        if isinstance(v, (list, tuple)):
            if len(v) > self.budget.items:
                raise EvalError("E0301", f"a loop over {len(v)} items exceeds the limit of "
                                f"{self.budget.items}", node.span,
                                hint="use fewer items, or raise `--budget`")
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
    def _instantiate(self, t: Template, call: A.Call, name: str,
                     kind: str | None = None) -> StructRef:
        """Instance ``name`` of template ``t`` called by ``call``, a child of the structure
        being run; ``kind`` (from ``hole h = t(...)``) replaces the template's own kind."""
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
        spans: dict = {}                 # param -> the argument's value's text
        for p, a in zip(params, call.args):
            vals[p] = (self.eval(a), a)
            spans[p] = a.span
        for kw in call.kwargs:
            param = template_param(kw.name, params)
            if param is None:
                from ..library.reference import template_params_hint
                sugg = did_you_mean(kw.name, params)
                raise EvalError("E0105", f"`{d.name}` has no parameter `{kw.name}`", kw.span,
                                hint=(f"did you mean `{sugg[0]}`? " if sugg else "")
                                + "parameters: " + template_params_hint(d),
                                suggestions=sugg)
            if param in vals:
                raise EvalError("E0105", f"`{d.name}`: `{param}` is given twice", kw.span,
                                hint=f"give `{param}` once")
            vals[param] = (self.eval(kw.value), kw.value)
            spans[param] = kw.value.span
        for v, node in vals.values():
            if owners_of(v):
                # a size read of a shape (run gw: a rail's tab as long as the word above it,
                text = _src(self.sink, node.span)               # `length=word.bb.width`)
                size = text.rsplit(".", 1)[-1] in ("width", "height", "length", "radius")
                raise EvalError("E0204", "template arguments must be values, not geometry or structures",
                                node.span, hint=(
                                    f"`{text}` is read from a shape, known only after solving; a "
                                    f"template is made from numbers known before: give it numbers "
                                    f"(the ones that drew the shape), or draw the feature with "
                                    f"shapes here, which take solved values" + (
                                        f" (`Rectangle(..., width={text})`)" if size else "")
                                    if isinstance(v, (Q, PV)) else "pass numbers; relate the "
                                    "parts with constraints in the parent structure"))
        check_kinds(self, t, d, vals, spans)
        self._adapt_args(d, vals, spans)
        self.step(call.span)
        child = self._new_structure(name, kind or d.kind, parent, call.span, template=d.name)
        # the parameters the call gives and its template's file: what `values` lists of it
        child.given = (tuple(vals), d.span.file if d.span is not None else None)   # (issue 111)
        child.template_def = d          # (E0102: a member its other branch makes)
        self.frames.append((f"the template instance `{name} = {d.name}(...)`", call.span))
        self.sink.calls.append((f"`{d.name}`", call.span))      # errors inside: at the call
        self.sink.called(d.span, self.sink.calls, child.path)
        saved_file = self.file
        tscope = Scope(t.scope, child, t.scope.file)
        self.file = t.scope.file
        self.template_depth += 1
        saved_scope = self.scope
        try:
            self.scope = tscope
            for p in d.params:
                if p.name in vals:
                    tscope.vars[p.name] = vals[p.name][0]
                elif p.default is not None:
                    tscope.vars[p.name] = self.eval(p.default)
                else:
                    raise EvalError("E0106", f"`{d.name}` needs the argument `{p.name}`", call.span,
                                    hint=f"`{name} = {d.name}({p.name}=...)`")
            # the asserts over the arguments, before the body (issue 95): one error at the call
            precheck_asserts(self, d, tscope, vals, spans)
            note_material(child, tscope.vars, spans, call.span)     # W0118 (run dc)
            self.scope = saved_scope
            self._run_body(child, d.body, tscope)
        finally:
            self.scope = saved_scope       # also when a default or the asserts raised
            self.frames.pop()
            self.sink.calls.pop()
            self.template_depth -= 1
            self.file = saved_file
        return StructRef(child)

    def _adapt_args(self, d, vals: dict, spans: dict) -> None:
        """Give each argument of template ``d`` the unit kind of its parameter's default, at the call.

        A parameter whose default is written with a unit (``thickness=3 mm``, ``angle=30 deg``)
        is a length (angle): a bare number given to it is in the *caller's* file unit (degrees),
        as everywhere a length is expected, so that it does not stay bare inside a template of
        another file (where ``floor(run / finger)`` would be a length^-1). A value of another
        kind is ``E0109`` at the argument (``thickness=3 deg``), not at a use in the template.
        ``vals`` maps a parameter to ``(value, argument node)`` and is changed in place."""
        for p in d.params:
            got = vals.get(p.name)
            dflt = p.default
            if got is None or type(dflt) is not A.Num or dflt.unit is None:
                continue
            v, node = got
            if not isinstance(v, Q) or v.const() is None:
                continue
            want = LEN if dflt.unit in UNITS_LENGTH else ANG
            if v.dim == want:
                continue
            kind = "length" if want is LEN else "angle"
            if v.dim == NUM:
                f = self.file
                k = (f.unit_scale if f else 1.0) if want is LEN else angle_scale(v, DEG)
                vals[p.name] = (Q.num(v.const() * k, want), node)
                continue
            raise kind_error(self, d, p, v, spans.get(p.name, node.span), kind)

    # ------------------------------------------------------------------ constraints
    def _add_constraint(self, kind: str, eqs: list[Equation], span, text: str | None,
                        owners, args=None, reach=None) -> None:
        """Add a written constraint to the structure being run (``text`` None: the source
        text at ``span``, cut when first read; see ``Constraint.text``).  ``args``: the
        structures each argument reaches, in the order written (``Constraint.args``);
        ``reach``: the parameters each reads, for a constraint within one structure
        (``Constraint.reach``)."""
        s = self.struct
        if s is None:
            s = self._need_struct(span)
        for o in owners:
            if o is not s and not o.is_within(s):
                self._check_subtree(owners, span, s)
        if self.objects >= self.budget.objects:      # self.count_object(span), inline
            self.count_object(span)
        self.objects += 1
        c = _new(Constraint)                 # Constraint(kind, s, span, ...) without the class call
        c.kind, c.owner, c.span = kind, s, span
        for e in eqs:
            x = e.expr
            if type(x) is not Lin and contains_bbox(x):
                c.equations, c.deferred = [], eqs
                break
        else:
            c.equations, c.deferred = eqs, None
        if text is None:                     # its source text, cut when a message asks
            if span is None:
                c._text = ""
            else:
                c._text = None
                c._src = self.sink.sources.get(span.file, "")
        else:
            c._text = text
        c.implicit = c.hold = c.released = False
        c.args = args
        c.reach = reach
        s.constraints.append(c)
        self.model.constraints.append(c)

    def _helper_reach(self, vals, owners) -> None:
        """``Constraint.arg_reach`` of the constraint just added, relating structures
        ``owners`` (more than one), when one of them is the structure it is written in and
        that holds construction geometry: the parameters each of ``vals`` reads, so the solve
        holds a helper another structure is placed on (issue 111:
        :func:`aidl_lang.solver.core.tree._held_helpers`)."""
        c = self.model.constraints[-1]
        s = c.owner
        if s in owners and any(g.construction for g in s.geometry):
            c.arg_reach = bbox_reach(vals)

    def _check_subtree(self, owners, span, s: Structure) -> None:
        bad = [o for o in owners if not o.is_within(s)]
        if bad:
            o = bad[0]
            lca = _common_ancestor(o, s)
            where = f"`{lca.path}`" if lca else "a common parent"
            hint = self._outside_hint(o, s, f"move the constraint into {where}, which "
                                      f"contains both", "a constraint may only use its own "
                                      f"structure's subtree; move it into {where}, which "
                                      f"contains both")
            raise EvalError("E0202", f"this constraint in `{s.path}` refers to `{o.path}`, "
                            f"which is outside `{s.name}`'s subtree", span, hint=hint)

    def _outside_hint(self, o: Structure, s: Structure, other: str,
                      plain: str | None = None) -> str:
        """The hint for structure ``o`` used in ``s`` from outside it: when a name of ``s``'s
        body is bound to it (run aq's and be's `back = backplate` in an assembly), what that
        line does not do and the two forms that make the part, then ``other``; else
        ``plain`` (None: ``other``)."""
        alias = self._alias_of(o)
        if alias is None:
            return other if plain is None else plain
        return (f"`{alias} = {o.name}` names the structure `{o.path}` declared outside "
                f"`{s.name}`; it does not make a part of `{s.name}`: declare the solid inside "
                f"`{s.name}` (`solid {alias} {{ ... }}`), or make it a template (`def "
                f"{o.name}() -> {o.kind} {{ ... }}`, then `{alias} = {o.name}()`); or {other}")

    def _alias_of(self, o: Structure) -> str | None:
        """The name a body's own scope binds to structure ``o`` (or one of its ancestors)
        declared outside it (`back = backplate`), else None."""
        sc = self.scope
        while sc is not None and sc.struct is not None:
            for name, v in sc.vars.items():
                if type(v) is StructRef and o.is_within(v.struct) and name != v.struct.name:
                    return name
            sc = sc.parent
        return None

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
            # who moves (issue 84): an equation relating two structures is a relating
            # constraint like an Align*: the first-named side moves to the second
            owners = owners_of(l, r)
            self._add_constraint("equation", eqs, e.span, None, owners,
                                 [owners_of(l), owners_of(r)] if len(owners) > 1 else None,
                                 bbox_reach((l, r)) if len(owners) == 1 else None)
            if len(owners) > 1:
                self._helper_reach((l, r), owners)

    def _sides_of(self, op, l, r, span, eq):
        if isinstance(l, Q) and isinstance(r, Q):
            le, re_, dim = self._unify(l, r, span)
            return op, le, re_, dim
        return "==", eq.expr, 0.0, LEN      # points: each coordinate's difference is 0

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

    def _unify(self, a: Q, b: Q, span, node=None):
        """``unify_add`` of two operands, or a located E0109 that names each side and its
        unit kind (``node``: the ``BinOp``, whose sides' texts it quotes)."""
        try:
            return unify_add(a, b, self.unit_scale, DEG)
        except UnitError as ex:
            msg, hint = str(ex), "both sides must have the same unit kind (length, angle or number)"
            left, right = (getattr(node, "left", None), getattr(node, "right", None))
            # `3/8 in` is 3 / (8 in): said where a side is an inverse length or angle
            frac = fraction_hint(_src(self.sink, span)) if min(*a.dim, *b.dim) < 0 else None
            hint = frac or hint
            if left is not None and right is not None:
                lt, rt = _src(self.sink, left.span), _src(self.sink, right.span)
                if lt and rt and len(lt) + len(rt) < 160:
                    msg = (f"cannot combine {_a(dim_name(a.dim))} with {_a(dim_name(b.dim))}: "
                           f"`{lt}` is {_a(dim_name(a.dim))}, `{rt}` is {_a(dim_name(b.dim))}")
                if (0, 2) in (a.dim, b.dim):    # `acos(x) * 1 rad` (issue 111's run m)
                    hint = ANGLE_TWICE
                elif frac is None and "/" in lt + rt:      # a ratio that was meant to be a plain number
                    hint += ("; in `*` and `/` a bare number (`r = 15`, a list `[15, 25]`) "
                             "stays a plain number, so `length / r` is a length, not a ratio: "
                             "write `15 mm` where a length is meant")
            raise EvalError("E0109", msg, span, hint=hint)

    # ------------------------------------------------------------------ calls


def _a(what: str) -> str:
    return ("an " if what[:1] in "aeiou" else "a ") + what


def _fmt_q(v: float, dim) -> str:
    """A value in internal units (mm, rad) as the user writes it: ``172.5 mm``, ``30 deg``."""
    import math
    if dim == (1, 0):
        return f"{v:.6g} mm"
    if dim == (0, 1):
        return f"{math.degrees(v):.6g} deg"
    return f"{v:.6g}"


def _check_cut_place(name: str, kind: str, parent, span, template) -> None:
    """E0125 for a ``cut`` where it cuts nothing: a cut's curves are through-cuts of the solid
    it sits in (directly or in another cut), or, directly in an assembly, sheet-level cuts
    (the laser cuts along them on the sheet, in no part: language.md 2.5), so a cut at the
    top, in a drawing or a hole, and anything but a cut inside a cut, is refused with the
    fix."""
    what = f"`{name} = {template}(...)`" if template else f"`{kind} {name}`"
    if kind == "cut":
        if parent is None:
            raise EvalError("E0125", f"{what}: a `cut` at the top level has no material to "
                            "cut through", span,
                            hint="put it inside the solid it cuts: `solid plate { body = "
                                 "Rectangle(...)  cut slits { ... } }` (or, to cut the sheet "
                                 "in no part, in an assembly beside the parts)")
        if parent.kind in ("solid", "cut", "assembly"):
            return
        fix = {"drawing": "a drawing's lines are engraved, not cut: move the cut into the "
                          "solid it cuts through",
               "hole": "a hole is removed whole already: draw the curve in the hole's "
                       "solid, in a `cut` beside the hole"}.get(parent.kind, "")
        raise EvalError("E0125", f"{what} is inside {parent.kind} `{parent.name}`: a `cut` "
                        "cuts through the solid it sits in", span, hint=fix)
    raise EvalError("E0125", f"{what}: a `cut` holds only curves (through-cuts) and other "
                    f"`cut`s, not a {kind}", span,
                    hint=f"move `{name}` out of cut `{parent.name}` into the solid around it")

