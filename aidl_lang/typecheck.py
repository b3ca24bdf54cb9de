"""Static checks before anything runs: names, calls, structure kinds.

* every name resolves (lexical scopes: structure bodies, template bodies with their parameters,
  loop and comprehension variables, the file's params/constants/templates/imports, built-ins);
  an unknown name is ``E0101`` with the nearest known names;
* every call names a primitive, constraint, function or template (``E0103``), with arguments
  that fit one of its forms: count (``E0104``), keywords (``E0105``), required ones (``E0106``);
* structure kinds are solid, hole, cut, drawing or assembly (``E0108``).

Checks that need values — types and units of arguments, list indices, members of geometry and
structures, and the paper's two validity rules on the exact objects referenced — are made by
the interpreter (:mod:`aidl_lang.interp`) as it runs, with the same diagnostic model.
"""
from __future__ import annotations

import itertools


from . import ast as A
from .base.diagnostics import Diagnostic, DiagnosticSink, Fix, Label, did_you_mean
from .library.arg_notes import ARG_NOTES, FORM_NOTES
from .registry import (CONSTANTS, ENTRIES, FUNCTIONS, SYNONYMS, accepted_args,
                       choose_variant, UNITS_ANGLE, UNITS_LENGTH, lookup, near_args,
                       template_param)
from .library.sources import ImportRefused


def _real(path: str) -> str:
    import os
    return os.path.realpath(path)

KINDS = ("solid", "hole", "cut", "drawing", "assembly")

# names models invent, and what to write instead (short, specific; never "delete it")
_BOOL = "booleans come from structure kinds: a `solid` unions its children, `hole NAME { ... }` children cut"
_TWO_D = "AIDL is 2D: draw the outline (Circle, Rectangle, Polygon, ...); the SVG is the part's profile"
_STRUCT = "group parts in a structure block: `solid NAME { ... }` (also hole, drawing, assembly)"
_PATTERN = "repeat with `LinearPattern(target, count, spacing)`, `CircularPattern(target, count, center)` or a `for i in range(n) { ... }` loop"
_TO_ANGLE = ("an angle from a plain number of radians: `x * 1 rad` (a literal: `0.5 rad`); from "
             "degrees: `radians(x)` or `x * 1 deg`; an angle as a number: `degrees(a)`; from a "
             "ratio: `atan(y / x)`, `atan2(y, x)`")
HALLUCINATIONS = {
    **{n: _TO_ANGLE for n in ("rad", "deg", "to_radians", "to_degrees", "deg2rad", "rad2deg",
                              "toRadians", "toDegrees", "rads", "degs")},
    "Rotate": "there is no Rotate: give shapes a `rotation=` argument, or relate lines with `Angle(a, b, 30 deg)`",
    "Rotation": "rotation is an argument: `Rectangle(center=(0, 0), width=10, height=5, rotation=30 deg)`",
    "Rotated": "rotation is an argument: `Rectangle(center=(0, 0), width=10, height=5, rotation=30 deg)`",
    "Position": "positions are arguments (`center=(x, y)`); relate parts with constraints (Above, LeftOf, Coincident, ...)",
    "Union": _BOOL,
    "Combine": _BOOL,
    "Merge": _BOOL,
    "Difference": "booleans come from structure kinds: put the cut-out in a `hole NAME { ... }` child",
    "Subtract": "booleans come from structure kinds: put the cut-out in a `hole NAME { ... }` child",
    "Cut": "booleans come from structure kinds: put the cut-out in a `hole NAME { ... }` child "
           "(into a part of a template instance: declare the hole beside it and write "
           "`CutInto(NAME, box.lid)`)",
    "Hole": "a hole is a structure: `hole NAME { c = Circle(center=(0, 0), radius=3) }` inside a solid",
    "Square": "write `Rectangle(center=..., width=s, height=s)`",
    "Box": "write `Rectangle(center=..., width=..., height=...)`",
    "Oval": "write `Ellipse(center=..., rx=..., ry=...)` (or a `Slot` for a stadium)",
    "Hexagon": "write `RegularPolygon(center=..., radius=..., sides=6)`",
    "Pentagon": "write `RegularPolygon(center=..., radius=..., sides=5)`",
    "Octagon": "write `RegularPolygon(center=..., radius=..., sides=8)`",
    "NURBS": "write `Spline(points=[...])` (a smooth curve through its points) or "
             "`Bezier(points=[p0, c1, c2, p1, ...])` (cubic control points; no weights)",
    "Ring": "a ring is `Shell(Circle(...), thickness)`, or a Circle in a solid with a smaller Circle in a `hole` child (add `Concentric`)",
    "Extrude": _TWO_D,
    "Cylinder": _TWO_D,
    "Cube": _TWO_D,
    "Sphere": _TWO_D,
    "Round": "round corners with `Fillet(radius)` in the solid, or use RoundedRectangle; `round(x)` rounds numbers",
    "RoundCorners": "round corners with `Fillet(radius)` in the solid, or use RoundedRectangle",
    "Bevel": "bevel corners with `Chamfer(distance)` in the solid",
    "Pattern": _PATTERN,
    "Array": _PATTERN,
    "Repeat": _PATTERN,
    "Copy": "copy with `Mirrored(target, about=line)`, `LinearPattern(...)`, `CircularPattern(...)` or a template",
    "Reflect": "copy about a line with `Mirrored(target, about=line)`, or mirror in place with `Flip(target, about=line)`; `Symmetric(a, b, about=line)` relates two shapes",
    "Group": _STRUCT,
    "Sketch": _STRUCT,
    "Body": _STRUCT,
    "Part": _STRUCT,
    "Component": _STRUCT,
    "Align": "say which: AlignLeft, AlignRight, AlignTop, AlignBottom, AlignCenterX or AlignCenterY",
    "Center": "write `CenterInside(a, b)` to center a in b (or AlignCenterX / AlignCenterY)",
    "Dimension": "state the dimension as a constraint: `Length(line, 20)`, `Distance(p, q, 5)` or `a.width == 20`",
    "Width": "sizes are members: write `a.width == 20` or `a.bb.width <= 60`",
    "Height": "sizes are members: write `a.height == 20` or `a.bb.height <= 60`",
    "AddConstraint": "constraints are statements: write `Coincident(a, b)` directly",
    "Constraint": "constraints are statements: write `Coincident(a, b)` directly",
    "Constrain": "constraints are statements: write `Coincident(a, b)` directly",
}


# constructors whose arguments models give to a sibling: an argument of the sibling (that
# fits one of its forms with the rest of the call) on the first is redirected to it, with why
SIBLINGS = {
    "Rectangle": {"RoundedRectangle": "a Rectangle has sharp corners; RoundedRectangle "
                                      "rounds them"},
    "Circle": {"Ellipse": "a Circle has one radius; an Ellipse has two semi-axes"},
    "Ellipse": {"Circle": "an Ellipse takes semi-axes rx, ry; a Circle takes a radius"},
    "Arc": {"ArcSlot": "an Arc is a curve without width; an ArcSlot is the slot along it"},
}


# placement keywords models give to their own templates (as to the standard library's):
# keyword -> the member of the instance's box it places
PLACEMENT = {"cx": "center_x", "cy": "center_y", "center_x": "center_x",
             "center_y": "center_y", "center": "center", "position": "center", "at": "center",
             "pos": "center", "origin": "center"}


# the file's statements without `=` (docs/language.md 2): a program that reads one as a name is
# told so (what it sets, an example, the constant to name it by), not offered a near name
_STATEMENT_WORDS = {"thickness": ("material's thickness", "thickness 3 mm", "t"),
                    "kerf": ("laser's cut width", "kerf 0.15 mm", "kerf_w"),
                    "min_wall": ("thinnest wall the checks allow", "min_wall 0.3 mm", "wall")}


class _Scope:
    def __init__(self, parent: "_Scope | None", names=()):
        self.parent = parent
        self.names = set(names)

    def has(self, n: str) -> bool:
        s = self
        while s is not None:
            if n in s.names:
                return True
            s = s.parent
        return False

    def all(self) -> set:
        out, s = set(), self
        while s is not None:
            out |= s.names
            s = s.parent
        return out


class Checker:
    def __init__(self, sink: DiagnosticSink, path: str):
        self.sink = sink
        self.path = path
        self.import_failed = False     # names may come from an import that failed: no E0101/E0103
        self.program: A.Program | None = None   # (E0101's hint: a name bound inside a structure)
        self.templates: dict[str, A.Def] = {}
        self.imported: dict[str, A.Def] = {}    # templates imported without `as`, by name
        self.bound: set = set()        # (name, arguments, keyword names) of registry calls that bind
        self.assign: A.Assign | None = None     # the assignment being checked
        self.template_calls: list = []  # (call, its template's Def): W0108's template arguments

    # ------------------------------------------------------------------ scopes
    def block_names(self, stmts) -> set:
        """Names bound anywhere in a structure body (not inside child structures)."""
        out = set()
        for st in stmts:
            if isinstance(st, A.Assign):
                out.add(st.name)
            elif isinstance(st, A.StructDecl):
                out.add(st.name)
            elif isinstance(st, A.For):
                out |= self.block_names(st.body.stmts)
            elif isinstance(st, A.If):
                out |= self.block_names(st.body.stmts)
                if st.orelse is not None:
                    out |= self.block_names(st.orelse.stmts)
        return out

    def run(self, program: A.Program) -> None:
        self.program = program
        self.bodies: list = []          # the bodies of the structures around a statement
        file_names = set()
        memo: dict = {}                 # imported file (real path) -> its names, once each
        self.params_once(program)
        self.units_assigned(program)
        for st in program.stmts:
            if isinstance(st, A.ParamDecl):
                file_names.add(st.name)
            elif isinstance(st, A.Def):
                file_names.add(st.name)
                self.templates[st.name] = st
            elif isinstance(st, A.Func):
                file_names.add(st.name)
            elif isinstance(st, A.Import):
                if st.alias:
                    file_names.add(st.alias)
                    try:
                        _imported_names(program.path, st.path, frozenset({_real(program.path)}),
                                        memo)
                    except ImportRefused as ex:
                        self.sink.error(ex.code, ex.message, st.path_span, hint=ex.hint,
                                        suggestions=ex.suggestions)
                else:
                    try:
                        file_names |= _imported_names(program.path, st.path,
                                                      frozenset({_real(program.path)}), memo,
                                                      self.imported)
                    except ImportRefused as ex:
                        self.sink.error(ex.code, ex.message, st.path_span, hint=ex.hint,
                                        suggestions=ex.suggestions)
                        self.import_failed = True
        top = [s for s in program.stmts
               if not isinstance(s, (A.UnitsDecl, A.Import, A.ParamDecl, A.Def, A.Func))]
        file_names |= self.block_names(top)
        fscope = _Scope(None, file_names)
        struct_names = [s.name for s in top if isinstance(s, A.StructDecl)]
        for st in program.stmts:
            if isinstance(st, A.ParamDecl):
                self.expr(st.value, fscope)
                for o in st.options:
                    self.expr(o.value, fscope)
            elif isinstance(st, A.Def):
                if st.kind not in KINDS:
                    self._kind_error(st.kind, st.kind_span)
                names = {p.name for p in st.params}
                for p in st.params:
                    if p.default is not None:
                        self.expr(p.default, fscope)
                tscope = _Scope(fscope, names | self.block_names(st.body.stmts) | {st.name})
                self.bodies.append(st.body.stmts)      # an assert's names: the template's
                self.stmts(st.body.stmts, tscope)
                self.bodies.pop()
            elif isinstance(st, A.Func):
                for p in st.params:
                    if p.default is not None:
                        self.expr(p.default, fscope)
                self.expr(st.value, _Scope(fscope, {p.name for p in st.params} | {st.name}))
        self.stmts(top, _Scope(fscope, set(struct_names) | {"model"}))
        self.unread_settings(program)
        self.uncalled_defs(program)

    def uncalled_defs(self, program: A.Program) -> None:
        """W0117 for a template or function of this file that nothing calls, in a file that
        draws a design (a top-level structure; a file of only templates is a library)."""
        if not any(isinstance(st, A.StructDecl) for st in program.stmts):
            return
        called = {n.func.id for n in A.walk(program)
                  if type(n) is A.Call and type(n.func) is A.Name}
        for st in program.stmts:
            if not isinstance(st, (A.Def, A.Func)) or st.name in called or st.span is None \
                    or st.span.file != self.path:
                continue
            what = "template" if isinstance(st, A.Def) else "function"
            self.sink.add(Diagnostic(
                "W0117", f"{what} `{st.name}` is defined but nothing calls it"
                         + (": nothing of it is made" if what == "template" else ""),
                st.name_span or st.span, "warning",
                hint=(f"call it where it belongs (`NAME = {st.name}(...)` in a structure)"
                      if what == "template" else f"use it (`{st.name}(...)`)")
                + ", or delete it if it is left over"))

    def params_once(self, program: A.Program) -> None:
        """E0107 for a param declared twice, or a param whose name a top-level `name = ...`
        also assigns (issue 110: the later declaration silently won, even for code above it,
        `--set` checked the later range and the sweep listed the name twice).  The error is
        at the second of the two, naming the first's line."""
        first: dict[str, A.Node] = {}
        self.defs_once(program)
        for st in program.stmts:
            if not isinstance(st, (A.ParamDecl, A.Assign)) or isinstance(st, A.KindAssign):
                continue
            before = first.get(st.name)
            if before is None:
                first[st.name] = st
                continue
            if not (isinstance(st, A.ParamDecl) or isinstance(before, A.ParamDecl)):
                continue                # two constants: the later is the value, as in Python
            line = before.span.line if before.span is not None else "?"
            if isinstance(st, A.ParamDecl) and isinstance(before, A.ParamDecl):
                said = f"param `{st.name}` is declared twice (first on line {line})"
            elif isinstance(st, A.ParamDecl):
                said = f"`{st.name}` is assigned on line {line} and declared a param here"
            else:
                said = f"`{st.name}` is a param (line {line}) and assigned here"
            self.sink.error(
                "E0107", said, st.name_span or st.span,
                hint=f"keep one `param {st.name} = ...` with the default and range you mean "
                     f"(its slider and `--set {st.name}=...` set it), or give the other name "
                     "another name")

    def units_assigned(self, program: A.Program) -> None:
        """E0001 for a top-level `units = cm`: a constant named `units` (a name, since round
        twelve: run bs's countdown had a wheel of that name), not the file's unit, which was
        silently left mm."""
        from .registry import UNITS_LENGTH
        for st in program.stmts:
            if type(st) is A.Assign and st.name == "units" and type(st.value) is A.Name \
                    and st.value.id in UNITS_LENGTH:
                self.sink.error("E0001", f"`units = {st.value.id}` names a constant `units`; "
                                "it does not set the file's unit", st.span,
                                hint=f"`units` is a statement without `=`: `units "
                                     f"{st.value.id}`")

    def defs_once(self, program: A.Program) -> None:
        """E0107 for a template or function defined twice in one file: the later one was
        silently the one every call made, the calls above it included.  A ``def`` written in
        a structure is one above it (:func:`aidl_lang.parsing.program.hoist_defs`), so two
        structures that each define a ``side`` are told to name them apart."""
        first: dict[str, A.Node] = {}
        for st in program.stmts:
            if not isinstance(st, (A.Def, A.Func)):
                continue
            before = first.setdefault(st.name, st)
            if before is st:
                continue
            line = before.span.line if before.span is not None else "?"
            apart = (" (a `def` written in a structure is defined for the whole file)"
                     if st.within != before.within else "")
            self.sink.error(
                "E0107", f"`{st.name}` is defined twice (first on line {line}){apart}",
                st.name_span or st.span,
                hint=f"give one of them another name (`{st.name}_2`) and call it by that name")

    def unread_settings(self, program: A.Program) -> None:
        """W0115 for a param that nothing reads; W0108 for a top-level name that nothing reads
        and that means a setting: `thickness
        = 4 mm` or `kerf = 0.2 mm` (an ordinary constant: the parts stay 3 mm thick, the cuts
        uncompensated; the fix is the statement `thickness 4 mm`), or a name a template call
        of the program leaves at its default (`module = 2 mm` beside `spur_gear(teeth=20)`:
        the fix passes it, `module=module`).  Issue 61."""
        reads = {n.id for n in A.walk(program) if type(n) is A.Name}
        src = program.source or ""

        def text(node) -> str:
            return src[node.span.start:node.span.end]
        for st in program.stmts:
            if not isinstance(st, (A.Assign, A.ParamDecl)) or isinstance(st, A.KindAssign) \
                    or st.name in reads or st.span is None or st.span.file != self.path:
                continue
            n, is_param = st.name, isinstance(st, A.ParamDecl)
            if n in ("thickness", "kerf", "min_wall"):
                what = ("the material's thickness (3D outputs, the parts list, the fit check; "
                        "3 mm when not set)" if n == "thickness" else
                        "the laser's cut width (cuts offset by half of it; none when not set)"
                        if n == "kerf" else
                        "the thinnest wall the checks accept (W0507, W0519, W0520; 0.5 mm "
                        "when not set)")
                if is_param:
                    new = f"{text(st)}\n{n} {n}"
                    said = f"`param {n}` is an ordinary value that nothing reads"
                    how = f"add the statement `{n} {n}` below it (the slider then sets it)"
                else:
                    new = f"{n} {text(st.value)}"
                    said = f"`{n} = ...` makes an ordinary constant that nothing reads"
                    how = f"write the statement without `=`: `{new}`"
                self.sink.add(Diagnostic(
                    "W0108", f"{said}: {what} is set by the statement `{n} VALUE`",
                    st.span, "warning", hint=how, fix=Fix(st.span, new)))
                continue
            for call, d in self.template_calls:
                params = [p.name for p in d.params]
                given = set(params[:len(call.args)]) | {template_param(k.name, params) or k.name
                                                       for k in call.kwargs}
                if n not in params or n in given or call.span is None \
                        or call.span.file != self.path:
                    continue
                body = text(call).rstrip()
                if not body.endswith(")"):
                    continue
                inner = body[:-1].rstrip()
                sep = "" if inner.endswith("(") else ", "
                new = f"{inner}{sep}{n}={n})"
                self.sink.add(Diagnostic(
                    "W0108", f"`{n}` is set at the top but nothing reads it, and `{d.name}(...)` "
                             f"on line {call.span.line} leaves its argument `{n}` at the default",
                    st.span, "warning",
                    hint=f"pass it: `{d.name}(..., {n}={n})`; a top-level name reaches a "
                         "template only as an argument",
                    labels=[Label(call.span, f"`{n}` not given here", primary=False)],
                    fix=Fix(call.span, new)))
                break
            else:
                if is_param:            # issue 111: declared, never used, nothing said
                    self.sink.add(Diagnostic(
                        "W0115", f"param `{n}` is declared but nothing reads it: its slider "
                                 f"and `--set {n}=...` change nothing", st.name_span or st.span,
                        "warning", hint=f"use `{n}` where the value it names is written (in place of "
                                        "that number), or delete the line if it is not meant"))

    def stmts(self, stmts, scope: _Scope) -> None:
        for st in stmts:
            self.stmt(st, scope)

    def stmt(self, st, scope: _Scope) -> None:
        if isinstance(st, A.StructDecl):
            if st.kind not in KINDS:
                self._kind_error(st.kind, st.kind_span)
            inner = _Scope(scope, self.block_names(st.body.stmts) | {st.name})
            self.bodies.append(st.body.stmts)
            self.stmts(st.body.stmts, inner)
            self.bodies.pop()
        elif isinstance(st, A.Assign):
            self.assign = st                # a template call's placement hint names it
            self.expr(st.value, scope)
            self.assign = None
        elif isinstance(st, (A.ExprStmt, A.Assert)):
            if isinstance(st, A.Assert):
                st.expr = self._reach_into(st.expr, scope)
            self.expr(st.expr, scope)
        elif isinstance(st, A.ThicknessDecl):
            self.expr(st.value, scope)
        elif isinstance(st, A.For):
            self.expr(st.iter, scope)
            self.stmts(st.body.stmts, _Scope(scope, {st.var}))
        elif isinstance(st, A.If):
            self.expr(st.cond, scope)
            self.stmts(st.body.stmts, scope)
            if st.orelse is not None:
                self.stmts(st.orelse.stmts, scope)
        elif isinstance(st, A.Block):
            self.stmts(st.stmts, scope)

    def _kind_error(self, kind: str, span) -> None:
        sugg = did_you_mean(kind, KINDS)
        self.sink.error("E0108", f"unknown structure kind `{kind}`", span,
                        hint="a structure is `solid`, `hole`, `cut`, `drawing` or `assembly` NAME { ... }",
                        suggestions=sugg)

    # ------------------------------------------------------------------ expressions
    def expr(self, e, scope: _Scope) -> None:
        if e is None:
            return
        t = type(e)
        if t is A.Num or t is A.Str:       # leaves (the most common nodes with names)
            return
        if t is A.Name:
            n = e.id                        # name()'s common case, inline
            s = scope
            while s is not None:
                if n in s.names:
                    return
                s = s.parent
            self.name(e, scope)
        elif isinstance(e, A.Name):
            self.name(e, scope)
        elif isinstance(e, A.Call):
            self.call(e, scope)
        elif isinstance(e, A.ListComp):
            self.expr(e.iter, scope)
            inner = _Scope(scope, {e.var})
            self.expr(e.elt, inner)
            self.expr(e.cond, inner)
        elif isinstance(e, A.Member):
            self.expr(e.obj, scope)
        elif isinstance(e, A.FStr):
            for p in e.parts:
                if isinstance(p, tuple):
                    self.expr(p[0], scope)
        else:
            for name in getattr(type(e), "__slots__", ()):
                v = getattr(e, name, None)
                if isinstance(v, A.Node):
                    self.expr(v, scope)
                elif isinstance(v, list):
                    for x in v:
                        if isinstance(x, A.Node):
                            self.expr(x, scope)

    def name(self, e: A.Name, scope: _Scope) -> None:
        n = e.id
        if scope.has(n) or n in CONSTANTS or n == "self" or n in FUNCTIONS or lookup(n) \
                or n in UNITS_LENGTH or n in UNITS_ANGLE:       # `length / mm`: 1 mm
            return
        if self.import_failed:
            return
        if n in _STATEMENT_WORDS:
            # run ec's quilt hanger: `position=(0, thickness, 0)` was told "did you mean
            # `nut_thickness`?" (a nut's height from std/fasteners: had the model followed it,
            # the board stood at the wrong depth and nothing said so)
            word, eg, name = _STATEMENT_WORDS[n]
            name = next((m for m in (name, f"{n}_value", f"my_{n}") if not scope.has(m)
                         and self._bound_inside(m, scope) is None), name)
            value = eg.split(" ", 1)[1]
            kind = {"kerf": A.KerfDecl, "min_wall": A.MinWallDecl}.get(n, A.ThicknessDecl)
            said = next((s.value for s in (self.program.stmts if self.program else ())
                         if type(s) is kind and type(s.value) is A.Num), None)
            if said is not None:        # the file's own figure: `thickness 6 mm` -> `t = 6 mm`
                value = f"{said.value:g}" + (f" {said.unit}" if said.unit else "")
                eg = f"{n} {value}"
            self.sink.error("E0101", f"unknown name `{n}`: `{n}` is a statement, not a value",
                            e.span, hint=f"`{eg}` sets the {word}; to use it in expressions "
                            f"too, name it once at the top (`{name} = {value}`, then `{n} "
                            f"{name}`) and write `{name}` here")
            return
        cands = scope.all() | set(CONSTANTS) | {"self"}
        # the very name bound inside a child beats a spelling neighbour (run bg: `sl` of a
        # child drawing was offered `self`)
        inside = self._bound_inside(n, scope)
        sugg = [] if inside else did_you_mean(n, cands)
        self.sink.error("E0101", f"unknown name `{n}`", e.span,
                        hint=f"did you mean `{sugg[0]}`?" if sugg else
                        f"`{n}` is defined inside `{inside}`: reach it by its path, "
                        f"`{inside}.{n}`" if inside else
                        "define it first (`NAME = ...`, or `param NAME = ...` at the top)",
                        suggestions=sugg or ([f"{inside}.{n}"] if inside else []))

    def _reach_into(self, e, scope: _Scope):
        """An assert's condition ``e`` with each name it reads that is bound nowhere in scope
        but in exactly one structure inside the structure the assert stands in read by its
        path (`len(bays)` in an assembly whose `deck` binds `bays`: `deck.bays`): nine first
        checks of issue 111's model runs failed on E0101 there, every one an assert counting
        or measuring what a child made.  Geometry is never read so: only an assert's names."""
        body = self.bodies[-1] if self.bodies else (
            self.program.stmts if self.program is not None else [])

        def paths(n, stmts, path):
            for st in stmts:
                if isinstance(st, A.StructDecl):
                    here = path + [st.name]
                    if n in self.block_names(st.body.stmts):
                        yield here + [n]
                    yield from paths(n, st.body.stmts, here)
                elif isinstance(st, (A.For, A.If)):
                    yield from paths(n, st.body.stmts, path)
                    if isinstance(st, A.If) and st.orelse is not None:
                        yield from paths(n, st.orelse.stmts, path)

        def known(n: str) -> bool:
            return (scope.has(n) or n in CONSTANTS or n == "self" or n in FUNCTIONS
                    or lookup(n) is not None or n in UNITS_LENGTH or n in UNITS_ANGLE
                    or n in self.templates or self.import_failed)

        def walk(node):
            if type(node) is A.Name:
                if known(node.id):
                    return node
                found = list(itertools.islice(paths(node.id, body, []), 2))
                if len(found) != 1:
                    return node
                out = A.Name(node.span, found[0][0])
                for part in found[0][1:]:
                    out = A.Member(node.span, out, part, node.span)
                return out
            if isinstance(node, A.Member):
                node.obj = walk(node.obj)       # `bays[1].r`: the chain's root
                return node
            if isinstance(node, A.ListComp):
                return node                     # its own variable: left as written
            for slot in getattr(type(node), "__slots__", ()):
                v = getattr(node, slot, None)
                if isinstance(v, A.Node):
                    setattr(node, slot, walk(v))
                elif isinstance(v, list):
                    setattr(node, slot, [walk(x) if isinstance(x, A.Node) else x for x in v])
            return node
        return walk(e)

    def _bound_inside(self, n: str, scope: _Scope) -> str | None:
        """The path, from a structure in ``scope``, of a structure whose body binds ``n``
        (issue 111's golf-ball rack: `grid` read beside `solid top { grid = ... }`, where
        `top.grid` was meant), or None."""
        def walk(stmts, path):
            for st in stmts:
                if isinstance(st, A.StructDecl):
                    here = path + [st.name]
                    if n in self.block_names(st.body.stmts):
                        yield here
                    yield from walk(st.body.stmts, here)
                elif isinstance(st, (A.For, A.If)):
                    yield from walk(st.body.stmts, path)
                    if isinstance(st, A.If) and st.orelse is not None:
                        yield from walk(st.orelse.stmts, path)
        names = scope.all()
        for path in walk(self.program.stmts if self.program is not None else [], []):
            for k in reversed(range(len(path))):    # the shortest tail that starts in scope
                if path[k] in names:
                    return ".".join(path[k:])
        return None

    def call(self, e: A.Call, scope: _Scope) -> None:
        for a in e.args:
            self.expr(a, scope)
        for kw in e.kwargs:
            self.expr(kw.value, scope)
        f = e.func
        if not isinstance(f, A.Name):
            self.expr(f, scope)
            return
        n = f.id
        if n in self.templates:
            self.template_calls.append((e, self.templates[n]))
            self.template_call(e, self.templates[n])
            return
        if n in self.imported and scope.has(n):
            self.template_calls.append((e, self.imported[n]))
        if scope.has(n):
            return            # a user value (imported template, alias...): checked when run
        if n in FUNCTIONS:
            lo, hi, _ = FUNCTIONS[n]
            if not lo <= len(e.args) <= hi:
                self.sink.error("E0104", f"`{n}` takes {lo if lo == hi else f'{lo} to {hi}'} "
                                f"argument{'s' if hi > 1 else ''}, got {len(e.args)}", e.span)
            return
        entry = lookup(n)
        if entry is None and self.import_failed:
            return
        if entry is None:
            cands = (list(ENTRIES) + list(SYNONYMS) + list(FUNCTIONS) + list(self.templates)
                     + [c for c in scope.all() if c in self.imported])
            sugg = did_you_mean(n, cands)
            hint = HALLUCINATIONS.get(n) or (f"did you mean `{sugg[0]}`?" if sugg else
                                             "`aidl docs` lists every shape, constraint and "
                                             "standard-library template")
            d_sugg = (self.templates.get(sugg[0]) or self.imported.get(sugg[0])) if sugg else None
            if d_sugg is not None and n not in HALLUCINATIONS:
                from .library.reference import template_params_hint
                hint += " " + template_params_hint(d_sugg)
            elif sugg and n not in HALLUCINATIONS and lookup(sugg[0]) is not None:
                e_sugg = lookup(sugg[0])
                hint += " " + "; ".join(e_sugg.signature(v) for v in e_sugg.variants)
            elif not sugg and n not in HALLUCINATIONS:
                from .library.reference import find
                t = find(n)             # `aidl docs` knows it: a stdlib template not imported
                if t is not None and t.kind.endswith(".aidl"):
                    module = t.kind.rsplit("std/", 1)[1]
                    hint = (f"`{t.name}` is a template of the standard library: write "
                            f"`import \"std/{module}\"` at the top, then `{t.name}(...)`; "
                            f"`aidl docs {t.name}` gives its parameters")
            d = self.sink.error("E0103", f"unknown function `{n}`", f.span, hint=hint,
                                suggestions=sugg)
            if n in HALLUCINATIONS:
                d.fix = None          # not a typo: renaming it to the nearest name is no fix
            return
        kwnames = [k.name for k in e.kwargs]
        key = (n, len(e.args), tuple(kwnames))
        if key in self.bound:               # this registry call shape binds: checked once
            return
        variant, reason = choose_variant(entry, len(e.args), kwnames)
        if variant is not None:
            self.bound.add(key)
            return
        all_names = accepted_args(entry)
        bad = next((k for k in e.kwargs if k.name not in all_names), None)
        if bad is not None and self.sibling(e, entry, bad):
            return
        if bad is not None:
            from .library.reference import entry_units_hint
            note = ARG_NOTES.get((entry.name, bad.name))
            sugg = [] if note else near_args(bad.name, all_names)
            if isinstance(bad.value, A.TupleLit) and len(bad.value.items) == 2:
                # a point given: only a point argument can take it (run am's
                # `RoundedRectangle(corner=(40, 20), ...)` was offered `corner_r`, a radius)
                pts = list(dict.fromkeys(a.name for v in entry.variants for a in v
                                         if a.type == "point"))
                sugg = [c for c in sugg if c in pts]
                if not sugg and pts:
                    corner = (" (`bottom_left`: the corner the width and height run from)"
                              if "bottom_left" in pts else "")
                    note = note or ("a point goes to " + " or ".join(f"`{c}`" for c in pts[:3])
                                    + corner)
            self.sink.error("E0105", f"`{n}` has no argument `{bad.name}`", bad.span,
                            hint=(f"did you mean `{sugg[0]}`? " if sugg else "")
                            + (f"{note}; " if note else "") + "forms: "
                            + "; ".join(entry.signature(v) for v in entry.variants)
                            + f"; accepted names: {', '.join(all_names)}; units: "
                            + entry_units_hint(entry),
                            suggestions=sugg)
            return
        code = "E0106" if reason and reason.startswith("missing") else "E0104"
        hint = "forms: " + "; ".join(entry.signature(v) for v in entry.variants)
        note = next((FORM_NOTES[(entry.name, k)] for k in kwnames
                     if (entry.name, k) in FORM_NOTES), None) if code == "E0104" else None
        if note:
            hint = f"{note}; {hint}"
        if entry.name == "Symmetric" and len(e.args) + len(e.kwargs) == 2:
            hint = ("to copy a shape or structure about a line write `Mirrored(target, "
                    "about=line)`; " + hint)
        self.sink.error(code, f"`{n}` {reason}", e.span, hint=hint)

    def sibling(self, e: A.Call, entry, bad) -> bool:
        """E0105 for keyword ``bad`` of call ``e`` to ``entry`` when it is an argument of a
        sibling constructor (:data:`SIBLINGS`: `Rectangle(..., corner_radius=3)` means
        `RoundedRectangle`) and the same arguments fit one of the sibling's forms: the message
        names the sibling, the hint and the fix give the call rewritten (the constructor's name
        and the keyword's canonical name replaced, the rest as written).  False when no
        sibling fits (the ordinary E0105 follows)."""
        from .base.diagnostics import Fix
        from .registry import arg_synonyms
        kwnames = [k.name for k in e.kwargs]
        for sib in SIBLINGS.get(entry.name, ()):
            s_entry = lookup(sib)
            if bad.name not in accepted_args(s_entry):
                continue
            variant, _ = choose_variant(s_entry, len(e.args), kwnames)
            if variant is None:
                continue
            canon = {a.name for a in variant}
            new = next((c for c in (bad.name,) + arg_synonyms(sib).get(bad.name, ())
                        if c in canon), bad.name)
            text = self._rewrite(e, sib, bad, new)
            call = f"`{text}`" if text else f"`{sib}(..., {new}=...)`"
            d = self.sink.error(
                "E0105", f"`{entry.name}` has no argument `{bad.name}`: `{new}` is an argument "
                f"of `{sib}`", bad.span,
                hint=f"write {call} ({SIBLINGS[entry.name][sib]}; `aidl docs {sib}` gives "
                "its forms)")
            if text:
                d.fix = Fix(e.span, text)
            return True
        return False

    def _rewrite(self, e: A.Call, name: str, bad, new: str) -> str | None:
        """The source of call ``e`` with the function renamed ``name`` and keyword ``bad``
        renamed ``new``; None when the source text is not at hand."""
        src = self.sink.sources.get(e.span.file)
        f = e.func
        if isinstance(bad.value, A.Name) and bad.value.id in ("true", "false"):
            return None                 # `rounded=true`: the sibling wants a size
        if not src or not (0 <= f.span.start < f.span.end <= bad.span.start < e.span.end
                           <= len(src)) or src[f.span.start:f.span.end] != f.id \
                or not src.startswith(bad.name, bad.span.start):
            return None
        k = bad.span.start
        return (name + src[f.span.end:k] + new + src[k + len(bad.name):e.span.end])

    def placement(self, e: A.Call, d: A.Def, placing: list) -> None:
        """One E0105 for the placement keywords (``cx``, ``cy``, ``center``, ...) given to a
        template of this file that has no such parameter (models expect every template to
        take the standard library's ``cx, cy``).  The hint says how to place the instance:
        a constraint on its box after the assignment, written out (the fix replaces the
        statement with the call without those keywords and the constraint), or placement
        parameters added to the ``def``."""
        from .base.diagnostics import Fix
        names = ", ".join(f"`{k.name}`" for k in placing)
        span = placing[0].span.cover(placing[-1].span)
        src = self.sink.sources.get(e.span.file) or ""
        st = self.assign if self.assign is not None and self.assign.value is e else None

        def text(n):
            return src[n.span.start:n.span.end] if 0 <= n.span.start < n.span.end <= len(src) \
                else None
        vals = {PLACEMENT[k.name]: text(k.value) for k in placing}
        target = st.name if st is not None else "NAME"
        if "center" in vals:
            eq = f"{target}.bb.center == {vals['center']}"
        elif "center_x" in vals and "center_y" in vals:
            eq = f"{target}.bb.center == ({vals['center_x']}, {vals['center_y']})"
        else:
            k, v = next(iter(vals.items()))
            eq = f"{target}.bb.{k} == {v}"
        kept = [text(a) for a in e.args] + [text(k) for k in e.kwargs if k not in placing]
        call = f"{d.name}({', '.join(x for x in kept if x)})"
        fix = None
        if st is not None and None not in vals.values() and None not in kept \
                and src[st.span.start:st.span.end].startswith(st.name):
            indent = " " * (st.span.col - 1)
            fix = f"{st.name} = {call}\n{indent}{eq}"
            how = (f"replace the statement with `{st.name} = {call}` followed by the "
                   f"constraint `{eq}`")
        else:
            how = f"assign the instance (`NAME = {call}`) and constrain it: `{eq}`"
        d_ = self.sink.error(
            "E0105", f"`{d.name}` has no parameter{'s' if len(placing) > 1 else ''} "
            f"{names}: only the standard library's "
            "templates take `cx`, `cy`; a template you define takes only its own parameters",
            span, hint=f"place the instance with a constraint: {how}; or give `def {d.name}` "
            "parameters `cx=0, cy=0` and add them to the positions in its body")
        if fix is not None:
            d_.fix = Fix(st.span, fix)

    def template_call(self, e: A.Call, d: A.Def) -> None:
        params = [p.name for p in d.params]
        if len(e.args) > len(params):
            self.sink.error("E0104", f"`{d.name}` takes {len(params)} arguments, got {len(e.args)}",
                            e.span, hint=f"`{d.name}({', '.join(params)})`")
            return
        given = set(params[:len(e.args)])
        placing = [kw for kw in e.kwargs if kw.name in PLACEMENT
                   and template_param(kw.name, params) is None]
        if placing:
            self.placement(e, d, placing)
        for kw in e.kwargs:
            name = template_param(kw.name, params)
            if name is None and kw in placing:
                continue
            if name is None:
                from .library.reference import template_params_hint
                sugg = did_you_mean(kw.name, params)
                self.sink.error("E0105", f"`{d.name}` has no parameter `{kw.name}`", kw.span,
                                hint=(f"did you mean `{sugg[0]}`? " if sugg else "")
                                + "parameters: " + template_params_hint(d), suggestions=sugg)
            elif name in given:
                self.sink.error("E0105", f"`{d.name}`: `{name}` is given twice"
                                + (f" (`{kw.name}` is another name for it)" if name != kw.name
                                   else ""), kw.span, hint=f"give `{name}` once")
            given.add(name or kw.name)
        for p in d.params:
            if p.default is None and p.name not in given:
                self.sink.error("E0106", f"`{d.name}` needs the argument `{p.name}`", e.span,
                                hint=f"`{d.name}({p.name}=...)`")


MAX_IMPORT_DEPTH = 16


def _imported_names(path: str, target: str, seen: frozenset = frozenset(),
                    memo: dict | None = None, defs: dict | None = None) -> set:
    """Names ``import "target"`` (in the file ``path``) brings without ``as``: the file's
    templates, params and top-level constants, aliases, and what it imported in turn
    (docs/language.md §2.2).  Raises :class:`~aidl_lang.library.sources.ImportRefused` for the
    import itself; a refused or cyclic import *inside* the imported file adds no names (the
    interpreter reports it where it is written).  ``memo`` (real path -> names) makes each
    file read and parsed once per check: an import graph costs linear time (a diamond of
    16 levels, each file importing the two of the next, was read on every path: 2^16
    times, 82 s).  ``defs`` (name -> :class:`~aidl_lang.ast.Def`), when given, receives the
    templates read, for the hints that list a template's parameters."""
    from .library.sources import read_import, resolve_import
    from .parser import parse_import
    real = resolve_import(target, path)
    key = str(real)
    if key in seen or len(seen) > MAX_IMPORT_DEPTH:
        return set()
    if memo is not None and key in memo:
        return memo[key]
    text = read_import(real, target)
    prog = parse_import(text, key, DiagnosticSink())
    out = set()
    for st in prog.stmts:
        if isinstance(st, (A.Def, A.Func, A.ParamDecl, A.Assign)):
            out.add(st.name)
            if defs is not None and isinstance(st, A.Def):
                defs.setdefault(st.name, st)
        elif isinstance(st, A.Import):
            if st.alias:
                out.add(st.alias)
            else:
                try:
                    out |= _imported_names(key, st.path, seen | {key}, memo, defs)
                except ImportRefused:
                    pass
    if memo is not None:
        memo[key] = out
    return out


def check(program: A.Program, sink: DiagnosticSink) -> None:
    """Run the static checks on ``program``; diagnostics go to ``sink``."""
    Checker(sink, program.path).run(program)
