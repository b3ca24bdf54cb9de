"""What ``aidl check --sweep`` sweeps in a program that declares no numeric ``param`` (issue 92):
the numbers written in it that size its parts, each *lifted* into a ``param`` of a copy of
the program (the file is not touched), then swept as a param without a declared range.

A maker who never wrote a ``param`` still changes a program by its numbers: the plate's
``width=180``, the holes' ``diameter=4``, the ``range(4)`` of a row, a pattern's count.
Those are what a form would offer if the program had one (the studio's gallery lifts a
generator call's literal arguments the same way: :func:`aidl_lang.studio.gallery.lift_params`),
so they are what is swept:

* a top-level constant whose value is a number (``wall = 3 mm``): the constant itself;
* a literal argument of a call whose argument is a length, an angle or a number in the
  vocabulary (:mod:`aidl_lang.registry`: ``width``, ``diameter``, ``corner_radius``,
  ``count``, ``sides``, a constraint's ``distance``...), a keyword literal of a template call,
  and the literal of ``range(N)``; not what only places a shape (``center``, ``x``, ``dx``,
  ``rotation``, a template's ``cx``/``cy``) and not 0;
* the same number given to the same argument in one structure (two hanging holes'
  ``diameter=4``) is one dimension: one param, written at each place;
* when that finds fewer than :data:`FEW` numbers (a part drawn by its points only: a
  triangle's legs, an L profile), the :data:`MOST_POINTS` largest coordinates of its point
  lists as well, each value one param wherever it stands in that list (an L profile's
  ``40`` is both legs, its ``5`` the thickness of both).

A bare number given where a length (an angle) is expected is lifted with the file's unit
(degrees), so the sweep speaks in mm; one given to a template keeps its bareness (the
template says its kind).  The lifted params are appended to the copy after its last line
(params are read before anything else), so every other line keeps its number and what the
compile says is located as in the file; the sweep's ``W0110`` is located at the literal
itself, and :func:`written` writes a finding's values into the file's own literals (what
a maker would edit; the benchmark checks every finding so).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from .. import ast as A

# fewer lifted numbers than this: the point lists' largest coordinates are lifted too
FEW = 3
MOST_POINTS = 4
# arguments that only place a shape, or tune a solver: never lifted
PLACING = {"at", "x", "y", "dx", "dy", "cx", "cy", "close_tolerance", "weight", "rotation",
           "center", "position", "by", "step_point", "point", "origin", "offset"}
# point arguments that place a shape (a Triangle's a, b, c and a Line's ends draw it)
PLACING_POINTS = {"center", "at", "position", "by", "step", "point", "origin"}
KINDS = {"length", "angle", "number"}
# arguments of any kind that are lengths when given a number (a pattern's spacing, inset)
ANY_LENGTHS = {"inset", "spacing"}


@dataclass
class Literal:
    """One lifted param: ``name``, the ``text`` its declaration gives it (``180 mm``), its
    ``value`` as written (a number), ``spans`` of every literal it stands for (the file's),
    ``negated`` for each (``-40`` in a point list: written ``-name``), and ``where``: how
    the report names it (``width=180`` on line 6)."""

    name: str
    text: str
    value: float
    spans: list = field(default_factory=list)
    negated: list = field(default_factory=list)
    where: str = ""

    @property
    def span(self):
        return self.spans[0]


@dataclass
class Lifted:
    """A program with its numbers lifted: ``source`` (the copy swept), ``literals``
    (``{name: Literal}``, declaration order)."""

    source: str
    literals: dict


def lift(source: str, path: str) -> Lifted | None:
    """``source`` (named ``path``) with the numbers a maker would change lifted into params
    (the module's docstring); None when it does not parse or has none to lift."""
    from ..base.diagnostics import DiagnosticSink
    from ..parser import parse
    sink = DiagnosticSink()
    try:
        prog = parse(source, path, sink)
    except Exception:          # noqa: BLE001 - a sweep of the file as written instead
        return None
    if sink.has_errors or prog is None:
        return None
    f = _Finder(source, prog)
    f.statements(prog.stmts, "", top=True)
    if len(f.groups) + len(f.consts) < FEW:
        f.points()
    if not f.groups and not f.consts:
        return None
    return f.lifted()


def written(source: str, literals: dict, texts: dict) -> str:
    """``source`` with the ``--set`` texts ``texts`` (``{name: "12.5 mm"}``) written in place
    of the lifted ``literals`` they name (``-(12.5 mm)`` where the literal was negative; a
    constant's value replaced): the edit a maker would make to the file."""
    edits = []
    for name, t in texts.items():
        lit = literals.get(name)
        if lit is None:
            continue
        for sp, neg in zip(lit.spans, lit.negated):
            edits.append((sp.start, sp.end, f"-({t})" if neg else f"({t})"))
    for a, b, t in sorted(edits, reverse=True):
        source = source[:a] + t + source[b:]
    return source


class _Finder:
    def __init__(self, source: str, prog):
        self.source, self.prog = source, prog
        self.unit = next((s.unit for s in prog.stmts if isinstance(s, A.UnitsDecl)), "mm")
        self.groups: dict = {}       # (struct, arg, value, kind) -> [(node, member, neg)]
        self.consts: list = []       # top-level Assign with a number
        self.lists: list = []        # (struct, member, [Num nodes]) of point lists
        self.seen: set = set()
        self.taken = {n.id for n in A.walk(prog) if isinstance(n, A.Name)} | {
            getattr(n, "name", None) for n in A.walk(prog)}

    # ------------------------------------------------------------------ the numbers
    def statements(self, stmts, struct: str, top: bool = False) -> None:
        for st in stmts:
            if isinstance(st, (A.StructDecl, A.Def)):
                self.statements(st.body.stmts, st.name)
            elif isinstance(st, A.Assign):
                if top and _number(st.value) is not None and type(st) is A.Assign:
                    self.consts.append(st)
                else:
                    self.expr(st.value, struct, st.name)
            elif isinstance(st, A.For):
                self.expr(st.iter, struct, None)
                self.statements(st.body.stmts, struct)
            elif isinstance(st, A.If):
                self.statements(st.body.stmts, struct)
                orelse = st.orelse
                if orelse is not None:
                    self.statements(orelse.stmts if isinstance(orelse, A.Block) else [orelse],
                                    struct)
            elif isinstance(st, A.ExprStmt):
                self.expr(st.expr, struct, None)

    def expr(self, e, struct: str, member: str | None) -> None:
        for call in (n for n in A.walk(e) if isinstance(n, A.Call)):
            if isinstance(call.func, A.Name):
                self.call(call, struct, member)

    def call(self, call, struct: str, member: str | None) -> None:
        from ..registry import FUNCTIONS, bind_variant, lookup
        fname = call.func.id
        target = call.args[0].id if call.args and isinstance(call.args[0], A.Name) else None
        scope = member or target or struct or fname.lower()
        if fname == "range":
            for a in call.args[min(1, len(call.args) - 1):][:1]:     # its stop
                self.add(a, struct, scope, "range", "number", "`range({})`")
            return
        entry = lookup(fname)
        if entry is None:           # a template: its keywords by name (a function: none)
            if fname not in FUNCTIONS:
                for k in call.kwargs:
                    if k.name not in PLACING:
                        self.add(k.value, struct, scope, k.name, None, f"`{k.name}={{}}`")
            return
        variant, ren, _ = bind_variant(entry, len(call.args), [k.name for k in call.kwargs])
        if variant is None:
            return
        args = {a.name: a for a in variant}
        given = [(variant[i].name, a, f"the {variant[i].name} `{{}}` of `{fname}`")
                 for i, a in enumerate(call.args) if i < len(variant)]
        given += [(ren.get(k.name, k.name), k.value, f"`{k.name}={{}}`") for k in call.kwargs]
        for name, node, label in given:
            arg = args.get(name)
            if arg is None:
                continue
            if arg.type in KINDS and name not in PLACING:
                self.add(node, struct, scope, name, arg.type, label)
            elif arg.type == "any" and name in ANY_LENGTHS:
                self.add(node, struct, scope, name, "length", label)
            elif arg.type == "points" and isinstance(node, A.ListLit):
                self.point_list(node.items, struct, scope)
            elif arg.type == "point" and name not in PLACING_POINTS and \
                    isinstance(node, A.TupleLit):
                self.point_list([node], struct, scope, key=(struct, scope, id(call)))

    def add(self, node, struct, scope, arg, kind, label) -> None:
        """The literal ``node`` (if it is one, not 0) given to argument ``arg`` of kind
        ``kind`` (None: as written) in ``struct`` (``scope``: the member or target it sizes;
        ``label``: how the report says it, ``{}`` the literal)."""
        got = _number(node)
        if got is None or got[0] == 0 or id(node) in self.seen:
            return
        self.seen.add(id(node))
        value, unit, neg = got
        key = (struct, arg, abs(value), unit, kind)
        self.groups.setdefault(key, []).append((node, scope, neg, label))

    def point_list(self, items, struct, scope, key=None) -> None:
        nums = []
        for it in items:
            if isinstance(it, A.TupleLit):
                nums += [n for n in it.items if _number(n) is not None]
        if nums:
            k = key or (struct, scope, id(items))
            for i, (kk, s, m, old) in enumerate(self.lists):
                if kk == k:
                    self.lists[i] = (kk, s, m, old + nums)
                    return
            self.lists.append((k, struct, scope, nums))

    def points(self) -> None:
        """The largest coordinates of the point lists (``MOST_POINTS`` values in all)."""
        cands = []
        for _k, struct, scope, nums in self.lists:
            by: dict = {}
            for n in nums:
                v, unit, neg = _number(n)
                if v != 0:
                    by.setdefault((abs(v), unit), []).append(
                        (n, scope, neg, f"`{{}}` in the points of `{scope}`"))
            for (v, unit), occ in by.items():
                cands.append((v, struct, scope, unit, occ))
        cands.sort(key=lambda c: -c[0])
        for v, struct, scope, unit, occ in cands[:MOST_POINTS]:
            self.groups[(struct, _fmt(v), v, unit, "length")] = occ

    # ------------------------------------------------------------------ the copy
    def lifted(self) -> Lifted:
        src = self.source
        edits, decls, out = [], [], {}
        by_name: dict = {}
        for st in self.consts:
            by_name.setdefault(st.name, []).append(st)
        for name, sts in by_name.items():
            # a constant assigned more than once is one param (issue 105: it was swept
            # twice, and the copy declared the param twice): the last value, the one in
            # effect, lifted there; the others commented out of the copy; the file's
            # literals of that value are those a finding writes
            last = sts[-1]
            v, unit, _neg = _number(last.value)
            text = src[last.value.span.start:last.value.span.end]
            same = [st for st in sts if _number(st.value)[:2] == (v, unit)]
            lines = sorted({st.span.line for st in same})
            where = (f"`{name} = {text}` on line {lines[0]}" if len(lines) == 1 else
                     f"`{name} = {text}` on lines {', '.join(map(str, lines))}")
            if len(sts) > len(same):
                where += f" (the last of {len(sts)} assignments, the one in effect)"
            out[name] = Literal(name, text, v, [st.value.span for st in same],
                                [False] * len(same), where)
            edits.append((last.span.start, last.span.start, "param "))
            edits += [(st.span.start, st.span.start, "# ") for st in sts[:-1]]
        for (struct, arg, v, unit, kind), occ in _merged(self.groups):
            scopes = {s for _, s, _, _ in occ}
            name = self._name(f"{scopes.pop() if len(scopes) == 1 else struct or 'the'}_"
                              + ("count" if arg == "range" else arg))
            nodes = [n for n, _, _, _ in occ]
            text = _fmt(v) + (f" {unit}" if unit else f" {self.unit}" if kind == "length"
                              else " deg" if kind == "angle" else "")
            where = _where(src, occ)
            lit = Literal(name, text, v, [n.span for n in nodes],
                          [neg for _, _, neg, _ in occ], where)
            out[name] = lit
            for n, _, neg, _ in occ:
                edits.append((n.span.start, n.span.end, f"(-{name})" if neg else name))
            decls.append(f"param {name} = {text}")
        for a, b, t in sorted(edits, key=lambda e: (e[0], e[1]), reverse=True):
            src = src[:a] + t + src[b:]
        if decls:
            src = src.rstrip("\n") + ("\n\n# the numbers `aidl check --sweep` lifts into params "
                                      "(a copy)\n" + "\n".join(decls) + "\n")
        return Lifted(src, out)

    def _name(self, base: str) -> str:
        base = _ident(base)
        name, k = base, 2
        while name in self.taken:
            name, k = f"{base}_{k}", k + 1
        self.taken.add(name)
        return name


def _where(src: str, occ: list) -> str:
    """How the report names the literals ``occ`` of one lifted param: ``width=180`` on line
    7, ``2 x `diameter=4` on lines 9, 10``, one phrase for each way it is written."""
    by: dict = {}
    for n, _s, _neg, label in occ:
        shown = src[n.span.start:n.span.end].lstrip("-")
        by.setdefault(label.format(shown), []).append(n.span.line)
    out = []
    for text, lines in by.items():
        ls = sorted(set(lines))
        out.append((f"{len(lines)} x " if len(lines) > 1 else "") + text + (
            f" on line {ls[0]}" if len(ls) == 1 else f" on lines {', '.join(map(str, ls))}"))
    return " and ".join(out)


def _merged(groups: dict) -> list:
    """The groups of one structure each, those that size one member of the same name in
    several structures (the left and the right wheel cut-out's ``r``) merged: one param."""
    out: dict = {}
    for (struct, arg, v, unit, kind), occ in groups.items():
        scopes = {s for _, s, _, _ in occ}
        key = ((":", scopes.pop()) if len(scopes) == 1 else struct, arg, v, unit, kind)
        out.setdefault(key, []).extend(occ)
    return [((k[0] if isinstance(k[0], str) else "", *k[1:]), occ) for k, occ in out.items()]


def _number(node) -> tuple[float, str | None, bool] | None:
    """``(value, unit as written, negated)`` of a literal number (``40 mm``, ``-2.5``,
    ``-(3)``), else None."""
    neg = False
    if isinstance(node, A.Neg):
        node, neg = node.operand, True
    if not isinstance(node, A.Num) or isinstance(node.value, bool):
        return None
    v = float(node.value)
    return (-v if neg else v), node.unit, (neg or v < 0)


def _fmt(v: float) -> str:
    return f"{abs(v):.12g}"


def _ident(text: str) -> str:
    s = re.sub(r"\W+", "_", text).strip("_") or "n"
    return s if not s[0].isdigit() else "n" + s
