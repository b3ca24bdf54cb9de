"""The LALR(1) loop and the AST it builds: the table's states and reductions (:class:`_Tables`),
the loop of Lark's ``ParserState.feed_token`` over the post-lexed tokens (:func:`_run_lalr`)
and the AST node of each grammar rule, built inside its reduction (:class:`_Builder`, the
reduction callbacks of :func:`_make_callback`): no parse tree is built and walked.
Imports :mod:`.tokens`, :mod:`.tables` and :mod:`.lexing`."""
from __future__ import annotations

import re
import threading

from .. import ast as A
from ..base.diagnostics import DiagnosticSink, Span, as_lf
from . import tables
from .lexing import _lex_lists, _postlex, _token
from .tokens import UnexpectedCharacters, UnexpectedToken, _BuildError, _new_span, parse_number

class _Tables:
    """What :func:`_run_lalr` runs, made from Lark's LALR(1) table for ``grammar/aidl.lark``
    (:func:`aidl_lang.parsing.tables.data`'s ``"parser"``): ``states``: per LALR state,
    terminal or rule name -> an ``int``: the next state (shift or goto) when >= 0, else ``~i``
    for reduction ``i``; ``reductions``: per rule ``(size, rule name, callback)``, ``(None,
    rule name, None)`` for a unit rule whose child stays as it is; ``start`` / ``end``: the
    first and accepting state of each start symbol (``start``, ``expr``).  The rows are the
    JSON's own dicts, used as they are loaded.  ``specialise=False``: every rule through the
    general callback (the reference the short callbacks are tested against)."""

    def __init__(self, data: dict, specialise: bool = True):
        ps = data["parser"]
        self.reductions = [_reduction(*spec, specialise=specialise) for spec in ps["rules"]]
        self.states = ps["states"]
        self.start, self.end = ps["start"], ps["end"]
        self.units: dict = {}           # see _unit_chain


_TABLES: _Tables | None = None
_TABLES_LOCK = threading.Lock()


def _tables() -> _Tables:
    """The parse table, made once from the cached table data (:func:`tables.data`; a cold
    ``aidl check`` so never imports Lark)."""
    global _TABLES
    if _TABLES is None:
        with _TABLES_LOCK:
            if _TABLES is None:
                _TABLES = _Tables(tables.data())
    return _TABLES


# rules whose AST builder returns its one child as it is (`arg: expr`, `bare_block: block`):
# with one child they are run as unit reductions (the child stays, only the state changes)
_PASS_THROUGH = frozenset(("arg", "bare_block"))


def _reduction(origin: str, size: int, name: str, include: list, tail: int, expand1: bool,
               unit: bool, specialise: bool = True):
    """A reduction of :attr:`_Tables.states` from a rule's spec (see :func:`_tables_data`).
    ``specialise=False``: every rule through the general callback, pass-through rules
    included (the reference the short callbacks are tested against)."""
    include = [tuple(i) for i in include]      # lists when read from the JSON cache
    if unit or (specialise and name in _PASS_THROUGH and size == 1
                and include == [(0, False, 0)] and not tail):
        return (None, origin, None)
    if name.startswith("_"):
        build = None                            # spliced into the parent
    else:
        build = getattr(_Builder, name, None)
        if build is None:
            if not expand1:
                raise RuntimeError(f"grammar rule `{name}` has no AST builder")
            build = _no_builder                # a `?rule` passes its one child through
    return (size, origin, _make_callback(tuple(map(tuple, include)), tail, expand1, build, size,
                                         specialise))


def _run_lalr(text: str, start: str, lexed: tuple | None = None):
    """Lex ``text`` (:func:`_lex_lists`, :func:`_postlex`) and run the LALR(1) table over the
    tokens with the AST callbacks: the loop of Lark's ``ParserState.feed_token`` without its
    per-step assertions and rule-object look-ups.  Returns the start symbol's value.  Raises
    :class:`UnexpectedToken` / :class:`UnexpectedCharacters` (a lexer error only once the
    parser has taken every token before it, as a streaming lexer would).

    Three stacks: states, values (a token's value is its :class:`Span`; the builders read its
    text from ``builder.text``) and extents (the span each value covers, ``None`` for a
    reduction that covers no token), so no wrapper object is made per reduction.

    ``lexed``: the lexer's lists of ``text`` when known (:func:`.lexing.relex_blanked`)."""
    tb = _tables()
    states, reductions, start_states, end_states = tb.states, tb.reductions, tb.start, tb.end
    builder = _STATE.builder
    outer = builder.text
    builder.text = text
    try:
        types, spans, lex_error = _lex_lists(text, False, builder.path) if lexed is None \
            else lexed
        types, spans = _postlex(types, spans, text, lex_error is None)
        if lex_error is None:
            types.append("$END")
            spans.append(spans[-1] if spans else Span(builder.path, 1, 1, 1, 1, 0, 0))
        state = start_states[start]
        state_stack = [state]
        value_stack: list = []
        pos_stack: list = []
        push_state, push_value, push_pos = state_stack.append, value_stack.append, pos_stack.append
        units = tb.units
        end_state = end_states[start]
        span = _new_span
        k = -1
        for ttype in types:
            k += 1                               # spans[k] is the token's span
            while True:
                try:
                    act = states[state][ttype]
                except KeyError:
                    # the accepting state has no actions: with the input used up, it is done
                    if ttype == "$END" and state == end_state:
                        return value_stack[-1]
                    raise UnexpectedToken(_token(ttype, spans[k], text),
                                          _expected(states[state]))
                if act >= 0:
                    push_state(act)
                    sp = spans[k]
                    push_value(sp)
                    push_pos(sp)
                    state = act
                    break
                size, origin, cb = reductions[~act]
                if size is None:                 # unit rules: same value, new state
                    key = (state_stack[-2], state, ttype)
                    top = units.get(key)
                    if top is None:
                        top = units[key] = _unit_chain(tb, state_stack[-2], origin, ttype)
                    state_stack[-1] = state = top
                    continue
                if size == 1:                    # the extent stays the child's
                    value_stack[-1] = cb(value_stack[-1], pos_stack[-1], builder)
                    state_stack[-1] = state = states[state_stack[-2]][origin]
                    continue
                if size:
                    children = value_stack[-size:]
                    first, last = pos_stack[-size], pos_stack[-1]
                    if first is None or last is None:
                        pos = _extent(pos_stack[-size:])
                    else:
                        pos = span((first[0], first[1], first[2], last[3], last[4], first[5],
                                    last[6]))
                    del state_stack[-size:]
                    del value_stack[-size:]
                    del pos_stack[-size:]
                else:
                    children = []
                    pos = None
                push_value(cb(children, pos, builder))
                push_pos(pos)
                state = states[state_stack[-1]][origin]
                push_state(state)
        if lex_error is not None:
            raise lex_error
        # $END shifted: no LALR table of Lark's does
        raise UnexpectedToken(_token(types[-1], spans[-1], text), set())
    finally:
        builder.text = outer


def _extent(poses: list):
    """The span from the first to the last extent that is not ``None`` (``None`` if all are)."""
    for first in poses:
        if first is not None:
            for last in reversed(poses):
                if last is not None:
                    break
            return first if first is last else _new_span(
                (first[0], first[1], first[2], last[3], last[4], first[5], last[6]))
    return None


def _unit_chain(tb: _Tables, below: int, origin: str, ttype: str) -> int:
    """The state a run of unit reductions (``?sum: product``...) ends in, looking at a
    ``ttype`` token with ``below`` under the top of the stack: each one swaps the top for
    ``below``'s goto on the rule's name, until the action on ``ttype`` is not a unit
    reduction.  Remembered per ``(below, top, ttype)`` in :attr:`_Tables.units`, since the
    expression grammar's precedence levels make most reductions unit ones."""
    while True:
        top = tb.states[below][origin]
        act = tb.states[top].get(ttype)
        if act is None or act >= 0 or tb.reductions[~act][0] is not None:
            return top
        origin = tb.reductions[~act][1]


def _expected(row: dict) -> set:
    """The terminal names a state accepts (its row's upper-case keys)."""
    return {s for s in row if s.isupper()}


def parse_expression(text: str, path: str, sink: DiagnosticSink) -> A.Node:
    """Parse one expression (``--set`` values); raises :class:`ParseError` when it does not parse
    (an error inside an f-string is also reported to ``sink``)."""
    builder = _Builder(path, sink)
    prev, _STATE.builder = getattr(_STATE, "builder", None), builder
    try:
        node = _run_lalr(as_lf(text), "expr")
    finally:
        _STATE.builder = prev
    if builder.failed:
        sink.error(*builder.failed[0])
        raise _BuildError(builder.failed[0][1])
    return node


_STATE = threading.local()       # .builder: the _Builder of the parse running in this thread


def _no_builder(builder, meta, items):
    raise RuntimeError("a `?rule` without an AST builder matched more than one item")


def _make_callback(include, tail, expand1, build, size: int, specialise: bool = True):
    """The reduction callback of one rule (see :func:`_tables_data` for ``include`` and
    ``tail``): ``cb(child, pos, builder)`` for a rule of one symbol, else
    ``cb(children, pos, builder)`` (``children``: the values, a fresh list the callback may
    keep; ``pos``: the rule's extent).  It returns the rule's value: the builder's node, the
    list of items of a ``_rule`` (spliced into its parent by the parent's ``include``), or the
    one item of a ``?rule``.  The common shapes get their own short callback (one child;
    every child kept in order; some tokens dropped; a left-recursive list growing in place);
    they compute exactly what the general one does (tests/test_parse_table.py)."""
    simple = not tail and all(not splice and not nn for _i, splice, nn in include)
    picks = tuple(i for i, _s, _n in include)
    whole = simple and picks == tuple(range(size))        # every child, in order

    if (specialise and size == 1 and build is None and not expand1 and not tail
            and include == ((0, True, 0),)):
        def reduce_pass(child, pos, builder):            # `__x: _sep`: the list as it is
            return child
        return reduce_pass

    if specialise and size == 1 and simple and not expand1:
        if not picks:                                     # `_sep: _NL`: nothing kept
            def reduce_none(child, pos, builder):
                return []
            return reduce_none
        if build is None:                                 # `_stmt: assign`: spliced
            def reduce_splice1(child, pos, builder):
                return [child]
            return reduce_splice1

        def reduce1(child, pos, builder):
            return build(builder, pos, [child])
        return reduce1

    if specialise and whole and not expand1 and build is not None and size > 1:
        def reduce_whole(children, pos, builder):
            return build(builder, pos, children)
        return reduce_whole

    if specialise and simple and not whole and not expand1 and build is not None and size > 1:
        def reduce_picks(children, pos, builder):   # `assign: NAME "=" expr`: tokens dropped
            return build(builder, pos, [children[i] for i in picks])
        return reduce_picks

    if (specialise and not tail and not expand1 and build is None and include
            and include[0] == (0, True, 0) and all(not nn for _i, _s, nn in include)
            and size > 1):
        rest = include[1:]

        def reduce_grow(children, pos, builder):    # `__block_star: __block_star _sep _stmt`
            items = children[0]                     # the list grows in place
            for i, splice, _nn in rest:
                if splice:
                    items += children[i]
                else:
                    items.append(children[i])
            return items
        return reduce_grow

    def reduce(children, pos, builder):
        if whole:
            items = list(children)
        elif simple:
            items = [children[i] for i in picks]
        else:
            items = []
            for i, splice, nn in include:
                if nn:
                    items += [None] * nn
                c = children[i]
                if splice:
                    if i == 0 and not items:
                        items = c           # a left-recursive list grows in place (no copy:
                    else:                   # the child's list is consumed here)
                        items += c
                else:
                    items.append(c)
            if tail:
                items += [None] * tail
        if expand1 and len(items) == 1:
            return items[0]                 # a `?rule` passes its one item through
        if build is None:
            return items                    # a `_rule`: its items are spliced
        return build(builder, pos, items)

    if size == 1:
        def reduce_one(child, pos, builder):
            return reduce([child], pos, builder)
        return reduce_one
    return reduce


class _Builder:
    """The AST node for each grammar rule; ``meta`` is the rule's extent, a :class:`Span` (every
    rule with a builder covers at least one token, so it is never ``None`` here).  A token
    among ``items`` is its :class:`Span`; its text is ``self.text[span.start:span.end]``
    (:meth:`tx`)."""

    def __init__(self, path: str, sink: DiagnosticSink):
        self.path = path
        self.sink = sink
        self.text = ""               # the text being parsed (set by _run_lalr)
        self.failed: list = []       # f-string errors (code, message, span) of this attempt

    def tx(self, token: Span) -> str:
        """A token's text."""
        return self.text[token.start:token.end]

    def unquote(self, token: Span, skip: int = 0) -> str:
        """A string token's value (:func:`_unquote`), with W0114 at each unknown escape (kept
        as written, backslash and all: `"50\\% off"` is engraved `50\\% off`); ``skip``
        leading characters (an f-string's ``f``) are not part of the literal."""
        text = self.tx(token)[skip:]
        for at, esc in _unknown_escapes(text):
            col = token.col + skip + 1 + at
            where = Span(token.file, token.line, col, token.line, col + len(esc),
                         token.start + skip + 1 + at, token.start + skip + 1 + at + len(esc))
            self.sink.warning(
                "W0114", f"`{esc}` is not an escape: the backslash is kept", where,
                hint=f"write `\\\\{esc[1:]}` for a backslash and `{esc[1:]}`, or `{esc[1:]}` "
                     "alone; the escapes are \\n (line break), \\t (tab), \\\\ (backslash), "
                     "\\\" and \\' (quotes)")
        return _unquote(text)

    # statements
    def start(self, meta, items):
        return [i for i in items if isinstance(i, A.Node)]

    def block(self, meta, items):
        return A.Block(meta, [i for i in items if isinstance(i, A.Node)])

    def units_decl(self, meta, items):
        return A.UnitsDecl(meta, self.tx(items[-1]), items[-1])     # (items[0]: UNITS)

    def units_in(self, meta, items):
        sp = meta
        return A.UnitsDecl(sp, "in", Span(sp.file, sp.end_line, sp.end_col - 2, sp.end_line,
                                          sp.end_col, sp.end - 2, sp.end))

    def import_dotted(self, meta, items):
        # `import stdlib.shapes` / `import std.shapes` is `import "std/shapes.aidl"`;
        # `import parts.gears` is `import "parts/gears.aidl"` (relative to this file)
        *parts, alias = items
        names = [self.tx(t) for t in parts]
        if names[0] in ("std", "stdlib") and len(names) > 1:
            path = "std/" + "/".join(names[1:]) + ".aidl"
        else:
            path = "/".join(names) + ".aidl"
        sp, last = parts[0], parts[-1]
        tsp = Span(sp.file, sp.line, sp.col, last.end_line, last.end_col, sp.start, last.end)
        return A.Import(meta, path, tsp, self.tx(alias) if alias else None)

    def thickness_decl(self, meta, items):
        return A.ThicknessDecl(meta, items[1])

    def kerf_decl(self, meta, items):
        return A.KerfDecl(meta, items[1])

    def min_wall_decl(self, meta, items):
        return A.MinWallDecl(meta, items[1])

    def import_decl(self, meta, items):
        tok, alias = items[0], items[1]
        return A.Import(meta, _unquote(self.tx(tok)), tok, self.tx(alias) if alias else None)

    def param_decl(self, meta, items):
        opts = list(items[2:])
        seen = set()
        for o in opts:
            if o.name in seen:
                self.sink.error("E0107", f"`{o.name}` given twice for param `{self.tx(items[0])}`",
                                o.name_span, hint="give each of min, max and step once")
            seen.add(o.name)
        return A.ParamDecl(meta, self.tx(items[0]), items[0], items[1], opts)

    def param_opt(self, meta, items):
        return A.ParamOption(meta, self.tx(items[0]), items[0], items[1])

    def params(self, meta, items):
        return list(items)

    def param(self, meta, items):
        return A.TemplateParam(meta, self.tx(items[0]), items[1] if len(items) > 1 else None)

    def def_decl(self, meta, items):
        name, params, kind, body = items
        return A.Def(meta, self.tx(name), name, self.tx(kind), kind, params or [], body)

    def def_expr(self, meta, items):
        name, params, value = items
        return A.Func(meta, self.tx(name), name, params or [], value)

    def def_short(self, meta, items):
        kind, name, params, body = items
        return A.Def(meta, self.tx(name), name, self.tx(kind), kind, params or [], body)

    def struct_decl(self, meta, items):
        kind, name, body = items
        tx = self.text
        return A.StructDecl(meta, tx[kind.start:kind.end], kind, tx[name.start:name.end], name,
                            body)

    def assign(self, meta, items):
        name = items[0]
        return A.Assign(meta, self.text[name.start:name.end], name, items[1])

    def kind_assign(self, meta, items):
        kind, name, value = items
        tx = self.text
        return A.KindAssign(meta, tx[name.start:name.end], name, value,
                            tx[kind.start:kind.end], kind)

    def for_stmt(self, meta, items):
        return A.For(meta, self.tx(items[0]), items[0], items[1], items[2])

    def if_stmt(self, meta, items):
        orelse = items[2] if len(items) > 2 else None
        return A.If(meta, items[0], items[1], orelse)

    elif_stmt = if_stmt

    def else_part(self, meta, items):
        x = items[0]
        return x if isinstance(x, A.Block) else A.Block(x.span, [x])

    def expr_stmt(self, meta, items):
        return A.ExprStmt(meta, items[0])

    def assert_stmt(self, meta, items):
        msg = self.unquote(items[1]) if len(items) > 1 and items[1] is not None else None
        return A.Assert(meta, items[0], msg)

    def bare_block(self, meta, items):
        return items[0]

    # expressions
    def number(self, meta, items):
        tok = items[0]
        v, unit = parse_number(self.text[tok.start:tok.end])
        return A.Num(meta, v, unit)

    def string(self, meta, items):
        return A.Str(meta, self.unquote(items[0]))

    def fstring(self, meta, items):
        tok = items[0]
        body = self.unquote(tok, skip=1)
        return A.FStr(meta, self._fparts(body, tok))

    def _fparts(self, body: str, tok: Span) -> list:
        parts: list = []
        i = 0
        buf = ""
        while i < len(body):
            ch = body[i]
            if ch == "{" and body.startswith("{{", i):
                buf += "{"; i += 2; continue
            if ch == "}" and body.startswith("}}", i):
                buf += "}"; i += 2; continue
            if ch == "{":
                j = body.find("}", i)
                if j < 0:
                    self.failed.append(("E0001", "unclosed `{` in f-string", tok))
                    return parts
                inner = body[i + 1:j]
                fmt = None
                if ":" in inner:
                    inner, fmt = inner.split(":", 1)
                if buf:
                    parts.append(buf); buf = ""
                try:
                    expr = _run_lalr(inner.strip(), "expr")
                except (UnexpectedToken, UnexpectedCharacters):
                    self.failed.append(("E0001", f"cannot parse `{inner}` in f-string",
                                        tok))
                    return parts
                _respan(expr, tok)
                parts.append((expr, fmt))
                i = j + 1
                continue
            buf += ch
            i += 1
        if buf:
            parts.append(buf)
        return parts

    def name(self, meta, items):
        tok = items[0]
        return A.Name(meta, self.text[tok.start:tok.end])

    def tuple(self, meta, items):
        return A.TupleLit(meta, [i for i in items if i is not None])

    def list(self, meta, items):
        return A.ListLit(meta, [i for i in items if i is not None])

    def listcomp(self, meta, items):
        elt, var, it, cond, *more = items
        clauses = [(var, it, cond)] + more
        out = elt                       # the innermost `for` makes the items; each outer
        for k, (v, i, c) in enumerate(reversed(clauses)):      # one joins its lists
            out = A.ListComp(meta, out, self.tx(v), v, i, c, flat=k > 0)
        return out

    def comp_for(self, meta, items):
        var, it, cond = items
        return (var, it, cond)

    def ternary(self, meta, items):
        then, cond, orelse = items
        return A.Ternary(meta, cond, then, orelse)

    def or_op(self, meta, items):
        return A.BoolOp(meta, "or", items[0], items[1])

    def and_op(self, meta, items):
        return A.BoolOp(meta, "and", items[0], items[1])

    def not_op(self, meta, items):
        return A.Not(meta, items[0])

    def compare(self, meta, items):
        operands = items[0::2]
        ops = [self.tx(t) for t in items[1::2]]
        return A.Compare(meta, ops, operands)

    def binop(self, meta, items):
        op = items[1]
        return A.BinOp(meta, self.text[op.start:op.end], items[0], items[2])

    def pow(self, meta, items):
        return A.BinOp(meta, "**", items[0], items[-1])

    def neg(self, meta, items):
        sign, x = items
        if self.tx(sign) == "+":
            return x
        if isinstance(x, A.Num):
            return A.Num(meta, -x.value, x.unit)
        return A.Neg(meta, x)

    def call(self, meta, items):
        func, args = items[0], items[1] or []
        pos = [a for a in args if not isinstance(a, A.Keyword)]
        kws = [a for a in args if isinstance(a, A.Keyword)]
        return A.Call(meta, func, pos, kws)

    def args(self, meta, items):
        return list(items)

    def arg(self, meta, items):
        return items[0]

    def kwarg(self, meta, items):
        tok = items[0]
        return A.Keyword(meta, self.text[tok.start:tok.end], items[1])

    def member(self, meta, items):
        tok = items[1]
        return A.Member(meta, items[0], self.text[tok.start:tok.end], tok)

    def index(self, meta, items):
        return A.Index(meta, items[0], items[1])


def _respan(node, span: Span) -> None:
    for n in A.walk(node):
        n.span = span


# A string's escapes (docs/language.md, "Strings"): `\n` a line break, `\t` a tab, `\\` a
# backslash, `\"` and `\'` a quote; any other backslash is kept as written (W0114)
ESCAPES = {"n": "\n", "t": "\t", "\\": "\\", '"': '"', "'": "'"}


def _unquote(s: str) -> str:
    """A string literal's value: ``s`` with its quotes taken off and its escapes
    (:data:`ESCAPES`) replaced; an unknown escape keeps its backslash."""
    return re.sub(r"\\(.)", lambda m: ESCAPES.get(m.group(1), m.group(0)), s[1:-1])


def _unknown_escapes(s: str) -> list[tuple[int, str]]:
    """(offset in ``s``, the escape) of each backslash in the literal ``s`` that
    :data:`ESCAPES` does not name."""
    return [(m.start(), m.group(0)) for m in re.finditer(r"\\(.)", s[1:-1])
            if m.group(1) not in ESCAPES]
