"""Parse AIDL source text into the typed AST of :mod:`aidl_lang.ast`.

Lark LALR(1) over ``grammar/aidl.lark``, a post-lexer that drops newlines inside brackets and
before ``else``, and statement-level error recovery: each syntax error becomes an ``E0001``
diagnostic listing the expected tokens, the offending logical line is blanked (its braces kept)
and the file is parsed again, so one run reports several errors.

Lark is the parser generator: :func:`_tables_data` builds Lark's LALR(1) table and basic
lexer and keeps them as plain data, cached as JSON (never a pickle) in the user's own cache
folder, owner-only (issue 15), see :func:`_tables`; a run reads that and never imports Lark.

Speed (issue 12, docs/dev/performance.md): the AST node of each rule is built inside the LALR
reduction (no parse tree is built and walked), its span taken from the first and last token it
covers (what Lark's ``propagate_positions`` would give); the lexer, the post-lexer and the
LALR loop each make one pass over a token list.  tests/test_parse_table.py checks the result
against Lark's own parser.
"""
from __future__ import annotations

import re
import threading
from functools import partial
from itertools import accumulate
from pathlib import Path

from . import ast as A
from .cache import cache_dir, read_checked, write_checked
from .controls import check_controls, code_point, invisible
from .diagnostics import DiagnosticSink, Label, Span, as_lf
from .memory import gc_paused

# a Span from a 7-tuple in one C call (no Python __init__): tokens and reduction extents
_new_span = partial(tuple.__new__, Span)

# the package's own grammar (a link to the repository's ``grammar/`` in a checkout), never a
# ``grammar`` folder beside the installed package
GRAMMAR = (Path(__file__).resolve().parent / "grammar" / "aidl.lark").resolve()

MAX_ERRORS = 20
MAX_NESTING = 64           # brackets nested deeper than this are refused (E0003)
MAX_BRACKET_DECISIONS = 64  # closers weighed by look-ahead when locating a bracket problem

UNIT_RE = re.compile(r"^(?P<num>(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)[ \t]*(?P<unit>[a-z°]+)?$")

TOKEN_NAMES = {
    "_NL": "newline", "LPAR": "`(`", "RPAR": "`)`", "LSQB": "`[`", "RSQB": "`]`",
    "LBRACE": "`{`", "RBRACE": "`}`", "COMMA": "`,`", "EQUAL": "`=`", "COLON": "`:`",
    "SEMICOLON": "`;`", "DOT": "`.`", "NAME": "a name", "NUMBER": "a number",
    "STRING": "a string", "FSTRING": "an f-string", "COMP_OP": "a comparison",
    "ADD_OP": "`+` or `-`", "MUL_OP": "`*` or `/`", "MINUS": "`-`", "PLUS": "`+`",
    "__ANON_0": "`->`", "RARROW": "`->`", "$END": "end of file",
}


_STATEMENT_START = frozenset(("_NL", "SEMICOLON", "LBRACE", "RBRACE"))
_THICKNESS_NEXT = frozenset(("NUMBER", "NAME", "ADD_OP"))
# the words that start a `WORD LENGTH` statement (retyped by the post-lexer) and their terminals
_DECL_WORDS = {"thickness": "THICKNESS", "kerf": "KERF", "min_wall": "MIN_WALL"}
_BLOCK_FOLLOW = frozenset(("_NL", "SEMICOLON", "RBRACE", "ELSE", "ELIF"))
_OPEN = frozenset(("LPAR", "LSQB"))
_CLOSE = frozenset(("RPAR", "RSQB"))
_ELSE = frozenset(("ELSE", "ELIF"))


def _postlex(types: list, spans: list, text: str, complete: bool = True) -> tuple[list, list]:
    """The post-lexer, on the lexer's terminal names and spans (:func:`_lex_lists`; ``text`` is
    what they index), returning the parser's names and spans (``complete=False``: the lexer
    stopped at an error after these tokens, so what the streaming post-lexer would still hold
    back -- a trailing newline or ``thickness`` -- is not passed on):

    - ``thickness`` at the start of a statement and followed by a number, a name or a sign is
      the ``thickness 3 mm`` statement (THICKNESS); anywhere else it is an ordinary NAME;
      ``kerf`` and ``min_wall`` likewise (KERF, MIN_WALL: ``kerf 0.15 mm``, ``min_wall 0.3 mm``);
    - ``_NL`` is dropped inside () and [] and before ``else``/``elif``, and repeats collapse;
    - a closing ``}`` ends a statement even without a newline (``} stmt`` on one line): an
      ``_NL`` at the ``}``'s span is put in (its text is ``"\n"``, see :func:`_token`).

    :class:`_PostLex` is the same as Lark's streaming post-lexer (the tests' reference)."""
    out_t: list = []
    out_s: list = []
    push_t, push_s = out_t.append, out_s.append
    depth = 0
    pending = None          # the span of a newline held back: dropped before else/elif
    prev_type = None        # the type of the last token seen (after retyping)
    prev_span = None
    n = len(types)
    for k in range(n):
        t = types[k]
        sp = spans[k]
        if t == "NAME" and text[sp[5]:sp[6]] in _DECL_WORDS and (
                k == 0 or types[k - 1] in _STATEMENT_START):
            if k + 1 == n and not complete:
                break                          # still held when the lexer failed
            if k + 1 < n and types[k + 1] in _THICKNESS_NEXT:
                t = _DECL_WORDS[text[sp[5]:sp[6]]]
        if prev_type == "RBRACE" and depth == 0 and pending is None and t not in _BLOCK_FOLLOW:
            push_t("_NL")
            push_s(prev_span)
        prev_type, prev_span = t, sp
        if t == "_NL":
            if depth == 0 and pending is None:
                pending = sp
            continue
        if pending is not None:
            if t not in _ELSE:
                push_t("_NL")
                push_s(pending)
            pending = None
        if t in _OPEN:
            depth += 1
        elif t in _CLOSE:
            if depth:
                depth -= 1
        push_t(t)
        push_s(sp)
    if pending is not None and complete:
        push_t("_NL")
        push_s(pending)
    return out_t, out_s


class _PostLex:
    """:func:`_postlex` as a streaming Lark post-lexer (``Lark(..., postlex=_PostLex())``): the
    reference the parser's list version is tested against (tests/test_parse_table.py), for
    tools that run Lark's own parser over the grammar."""

    always_accept = ("_NL",)

    def process(self, stream):
        return self._process(_retype_thickness(stream))

    def _process(self, stream):
        depth = 0
        pending = None
        prev = None
        for tok in stream:
            if (prev is not None and prev.type == "RBRACE" and depth == 0 and pending is None
                    and tok.type not in ("_NL", "SEMICOLON", "RBRACE", "ELSE", "ELIF")):
                # `} stmt` on one line: a block ends a statement
                yield type(prev).new_borrow_pos("_NL", "\n", prev)
            prev = tok
            if tok.type == "_NL":
                if depth == 0 and pending is None:
                    pending = tok
                continue
            if pending is not None:
                if tok.type not in ("ELSE", "ELIF"):
                    yield pending
                pending = None
            if tok.type in ("LPAR", "LSQB"):
                depth += 1
            elif tok.type in ("RPAR", "RSQB"):
                depth = max(0, depth - 1)
            yield tok
        if pending is not None:
            yield pending


def _retype_thickness(stream):
    """Streaming: ``thickness`` at the start of a statement and followed by a number, a name or
    a sign is the ``thickness 3 mm`` statement (THICKNESS); anywhere else an ordinary NAME."""
    prev = None
    held = None
    for tok in stream:
        if held is not None:
            if tok.type in ("NUMBER", "NAME", "ADD_OP"):
                held = type(held).new_borrow_pos(_DECL_WORDS[str(held)], str(held), held)
            yield held
            held = None
        if (tok.type == "NAME" and str(tok) in _DECL_WORDS
                and (prev is None or prev.type in ("_NL", "SEMICOLON", "LBRACE", "RBRACE"))):
            held = tok
            prev = tok
            continue
        prev = tok
        yield tok
    if held is not None:
        yield held


class Token(str):
    """A token from the lexer: its text (the ``str`` value), ``type`` (the terminal's name) and
    ``pos``, its :class:`Span` (lines and columns 1-based, offsets 0-based; the program's path
    as ``file``), also readable by the names of Lark's ``Token`` fields."""

    def __new__(cls, type, value, start_pos=None, line=None, column=None, end_line=None,
                end_column=None, end_pos=None, file=""):
        t = str.__new__(cls, value)
        t.type = type
        t.pos = _new_span((file, line, column, end_line, end_column, start_pos, end_pos))
        return t

    line = property(lambda self: self.pos[1])
    column = property(lambda self: self.pos[2])
    end_line = property(lambda self: self.pos[3])
    end_column = property(lambda self: self.pos[4])
    start_pos = property(lambda self: self.pos[5])
    end_pos = property(lambda self: self.pos[6])

    @property
    def value(self) -> str:
        return str(self)

    @classmethod
    def new_borrow_pos(cls, type_: str, value, borrow: "Token") -> "Token":
        """A token of another type and text at ``borrow``'s place."""
        t = str.__new__(cls, value)
        t.type = type_
        t.pos = borrow.pos
        return t


class ParseError(Exception):
    """A syntax error found by the lexer or the LALR table (reported as E0001 / E0002)."""


class UnexpectedToken(ParseError):
    """The LALR table has no action for ``token`` here; ``expected`` holds the terminal names
    that would have been accepted."""

    def __init__(self, token: Token, expected: set):
        super().__init__(f"unexpected {token.type} {str(token)!r}")
        self.token, self.expected = token, expected
        self.pos_in_stream = token.start_pos


class UnexpectedCharacters(ParseError):
    """No terminal of the grammar matches the text at offset ``pos_in_stream``."""

    def __init__(self, text: str, pos: int, line: int, column: int):
        super().__init__(f"no terminal matches at line {line}, column {column}")
        self.pos_in_stream, self.line, self.column = pos, line, column


_LARK_OPTIONS = dict(parser="lalr", lexer="basic", maybe_placeholders=True, start=["start", "expr"])
_TABLES_FORMAT = 5      # 5: a header line with the key, length and CRC-32 (cache.write_checked)


# ----------------------------------------------------------------- the parse table
class _Tables:
    """What :func:`_lex` and :func:`_run_lalr` run, made from Lark's LALR(1) table and basic
    lexer for ``grammar/aidl.lark`` (:func:`_tables_data`):

    - ``mres``: the lexer's compiled alternations of every terminal (named groups, Lark's
      order and priorities); ``ignore`` / ``newline``: terminal names skipped / counted for
      lines; ``keywords``: per terminal (``NAME``), what retypes a token as a keyword (Lark's
      ``UnlessCallback``): a dict text -> keyword when every keyword is a plain string (as in
      this grammar), else the whole-match patterns;
    - ``states``: per LALR state, terminal or rule name -> an ``int``: the next state (shift or
      goto) when >= 0, else ``~i`` for reduction ``i``; ``reductions``: per rule
      ``(size, rule name, callback)``, ``(None, rule name, None)`` for a unit rule whose child
      stays as it is; ``start`` / ``end``: the first and accepting state of each start symbol
      (``start``, ``expr``).  The rows are the JSON's own dicts, used as they are loaded."""

    def __init__(self, data: dict, specialise: bool = True):
        lx = data["lexer"]
        self.patterns = lx["patterns"]
        self._mres: list | None = None
        fc = lx.get("first")
        self.parts = fc["parts"] if fc else None
        self.first = {c: tuple(ix) for c, ix in fc["first"].items()} if fc else {}
        self.by_first: dict = {}        # see regex_for
        self._by_ids: dict = {}
        self.ignore = frozenset(lx["ignore"])
        self.newline = frozenset(lx["newline"])
        self.keywords = {t: (kw["literal"] if "literal" in kw
                             else [re.compile(p, f) for p, f in kw["patterns"]])
                         for t, kw in lx["keywords"].items()}
        # terminals the lexer passes on as they are: not skipped, not counted for lines, not
        # retyped as keywords (one set test per token on the common path)
        names = ([n for n, _p, _f in self.parts] if self.parts is not None
                 else [n for mre in self.mres for n in mre.groupindex])
        self.plain = frozenset(n for n in names
                               if n not in self.ignore and n not in self.newline
                               and n not in self.keywords)
        # single-line terminals retyped by a text -> keyword dict (NAME)
        self.literal_keywords = {t: kw for t, kw in self.keywords.items()
                                 if type(kw) is dict and t not in self.ignore
                                 and t not in self.newline}
        ps = data["parser"]
        self.reductions = [_reduction(*spec, specialise=specialise) for spec in ps["rules"]]
        self.states = ps["states"]
        self.start, self.end = ps["start"], ps["end"]
        self.units: dict = {}           # see _unit_chain

    @property
    def mres(self) -> list:
        """Lark's lexer alternations, compiled on first use (~2 ms): the lexer needs them only
        where the first-character dispatch has no entry."""
        if self._mres is None:
            self._mres = [re.compile(p, f) for p, f in self.patterns]
        return self._mres

    def regex_for(self, ch: str):
        """The alternation of the terminals that can start with ``ch``, in Lark's order (so the
        same terminal wins as in Lark's whole alternation: the others cannot match here), or
        ``None`` when there is no dispatch entry for ``ch`` (the lexer then runs the whole
        alternations).  Compiled once per set of terminals and remembered per character."""
        ids = self.first.get(ch)
        rx = None
        if ids is not None:
            rx = self._by_ids.get(ids)
            if rx is None:
                flags = {self.parts[i][2] for i in ids}
                if len(flags) == 1:
                    rx = re.compile("|".join(self.parts[i][1] for i in ids), flags.pop())
                    self._by_ids[ids] = rx
        self.by_first[ch] = rx
        return rx


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


def _split_alternation(pattern: str, names) -> list[str] | None:
    """The alternatives ``(?P<NAME>...)`` of one of Lark's lexer alternations, in order, or
    ``None`` when the text does not split back into exactly them."""
    starts = [pattern.find(f"(?P<{n}>") for n in names]
    if not starts or starts[0] != 0 or sorted(starts) != starts:
        return None
    parts = [pattern[a:b - 1] for a, b in zip(starts, starts[1:])] + [pattern[starts[-1]:]]
    if "|".join(parts) != pattern:
        return None
    return parts


def _first_chars(patterns: list) -> dict | None:
    """For the lexer's first-character dispatch (:func:`_lex`): each terminal's regex
    alternative and the ASCII characters a match of it can start with (the FIRST set of the
    regex, read from its parse by :mod:`re`'s own parser), as ``{"parts": [[name, regex,
    flags], ...], "first": {char: [terminal index, ...]}}`` in Lark's order.  A terminal whose
    FIRST set cannot be worked out (an unknown construct, a category other than ``\\d``, a
    possibly empty match) counts as starting with every character.  ``None`` when the
    alternations do not split into their terminals (then the lexer runs the alternations as
    Lark builds them).  Built with the table, so a cold run never parses a regex."""
    try:
        from re import _constants as C
        from re import _parser as sre
    except ImportError:                            # pragma: no cover - another Python's re
        return None
    every = frozenset(range(128))

    def seq(items):
        out: set = set()
        for op, av in items:
            f, nullable = one(op, av)
            out |= f
            if not nullable:
                return out, False
        return out, True

    def one(op, av):
        if op is C.LITERAL:
            return ({av} if av < 128 else set()), False
        if op is C.NOT_LITERAL:
            return set(every - {av}), False
        if op is C.IN:
            chars: set = set()
            negate = False
            for o, a in av:
                if o is C.NEGATE:
                    negate = True
                elif o is C.LITERAL:
                    chars |= {a} if a < 128 else set()
                elif o is C.RANGE:
                    chars |= set(range(a[0], min(a[1], 127) + 1))
                elif o is C.CATEGORY and a is C.CATEGORY_DIGIT:
                    chars |= set(range(48, 58))
                else:
                    return set(every), False
            return (set(every - chars) if negate else chars), False
        if op is C.SUBPATTERN:
            return seq(av[-1])
        if op is C.BRANCH:
            out, nullable = set(), False
            for alt in av[1]:
                f, n = seq(alt)
                out |= f
                nullable |= n
            return out, nullable
        if op in (C.MAX_REPEAT, C.MIN_REPEAT):
            f, n = seq(av[2])
            return f, n or av[0] == 0
        if op is C.AT:                             # an anchor matches no character
            return set(), True
        return set(every), True                    # anything else: it may start anywhere

    parts = []
    for pattern, flags in patterns:
        names = list(re.compile(pattern, flags).groupindex)
        split = _split_alternation(pattern, names)
        if split is None:
            return None
        parts += [[n, p, flags] for n, p in zip(names, split)]
    first: dict = {}
    for i, (_name, part, flags) in enumerate(parts):
        try:
            chars, nullable = seq(sre.parse(part, flags))
        except Exception:                          # pragma: no cover - an unparsable regex
            return None
        if nullable or flags & re.IGNORECASE:
            chars = set(every)
        for c in sorted(chars):
            first.setdefault(chr(c), []).append(i)
    return {"parts": parts, "first": first}


def _tables_data() -> dict:
    """Build Lark's LALR(1) parser for ``grammar/aidl.lark`` (imports Lark; ~0.4 s) and keep what
    the parse needs as plain data: the lexer's patterns, ignored and newline terminals and
    keyword patterns, and the LALR table with one spec per rule (origin, length, AST builder,
    the children it keeps, trailing ``None``s of ``[optional]`` parts, ``?rule`` and unit
    flags) -- the same steps as Lark's tree builder with ``propagate_positions=True`` and
    ``maybe_placeholders=True``."""
    from lark import Lark
    lp = Lark(GRAMMAR.read_text(), **_LARK_OPTIONS)
    basic = lp.parser.lexer
    scanner = basic.scanner
    from lark.lexer import PatternStr
    keywords = {}
    for t, cb in basic.callback.items():
        terms = cb.scanner.terminals
        if all(isinstance(k.pattern, PatternStr) and not k.pattern.flags for k in terms):
            literal: dict = {}
            for k in terms:                     # Lark's order: the first match wins
                literal.setdefault(k.pattern.value, k.name)
            keywords[t] = {"literal": literal}
        else:
            keywords[t] = {"patterns": [(m.pattern, m.flags) for m in cb.scanner._mres]}
    index = {}
    specs = []
    for rule in lp.rules:
        name = rule.alias or rule.options.template_source or rule.origin.name
        expansion = rule.expansion
        empty = rule.options.empty_indices
        if empty:
            bits = "".join(str(int(b)) for b in empty)
            nones = [len(ones) for ones in bits.split("0")]
        else:
            nones = [0] * (len(expansion) + 1)
        include = []
        pending = 0
        for i, sym in enumerate(expansion):
            pending += nones[i]
            if rule.options.keep_all_tokens or not (sym.is_term and sym.filter_out):
                include.append((i, not sym.is_term and sym.name.startswith("_"), pending))
                pending = 0
        tail = pending + nones[len(expansion)]
        expand1 = bool(rule.options.expand1 and not rule.alias)
        unit = expand1 and len(expansion) == 1 and include == [(0, False, 0)] and not tail
        index[rule] = len(specs)
        specs.append([rule.origin.name, len(expansion), name, include, tail, expand1, unit])
    table = lp.parser.parser._parse_table
    states = []
    for st in range(len(table.states)):
        row = {}
        for sym, (_action, arg) in table.states[st].items():
            row[sym] = arg if isinstance(arg, int) else -index[arg] - 1
        states.append(row)
    patterns = [(m.pattern, m.flags) for m in scanner._mres]
    return {"lexer": {"patterns": patterns,
                      "ignore": sorted(basic.ignore_types), "newline": sorted(basic.newline_types),
                      "keywords": keywords, "first": _first_chars(patterns)},
            "parser": {"rules": specs, "states": states, "start": table.start_states,
                       "end": table.end_states}}


_TABLES: _Tables | None = None
_TABLES_LOCK = threading.Lock()


def _tables() -> _Tables:
    """The parse table, read from the user's cache folder (plain JSON, owner-only, see
    :mod:`aidl_lang.cache`) or built with Lark and written there; keyed by the grammar text,
    the options, the table format and Lark's version (all kept in the file and compared).  A
    cold ``aidl check`` so never imports Lark (~35 ms) nor unpacks its serialized parser."""
    global _TABLES
    if _TABLES is not None:
        return _TABLES
    with _TABLES_LOCK:
        if _TABLES is None:
            import json
            import zlib
            # the whole key (grammar text included) is kept in the file and compared, so the
            # file name needs no cryptographic hash (hashlib costs ~5 ms to import)
            key = repr((_TABLES_FORMAT, _lark_version(), sorted(_LARK_OPTIONS.items()))) \
                + "\n" + GRAMMAR.read_text()
            d = cache_dir()
            name = f"parser-{zlib.crc32(key.encode()):08x}-{len(key)}.json"
            path = d / name if d is not None else None
            text = read_checked(path, key) if path is not None else None
            data = None
            if text is not None:
                try:
                    data = json.loads(text)
                    _check_tables(data)
                    tables = _Tables(data)
                except Exception:           # a stale or damaged cache: rebuild it below
                    data = None
            if data is None:
                data = _tables_data()
                tables = _Tables(data)
                if path is not None:
                    write_checked(path, key, json.dumps(data))
            _TABLES = tables
    return _TABLES


def _check_tables(data: dict) -> None:
    """Raise ``ValueError`` unless every state and reduction the cached table names exists
    (a table read back must never send the parser to a missing row: an IndexError, or an
    E0001 on a valid program)."""
    ps = data["parser"]
    states, n_rules = ps["states"], len(ps["rules"])
    n = len(states)
    for row in states:
        for v in row.values():
            if type(v) is not int or not (0 <= v < n or 0 <= ~v < n_rules):
                raise ValueError("a damaged parse table")
    for st in (*ps["start"].values(), *ps["end"].values()):
        if type(st) is not int or not 0 <= st < n:
            raise ValueError("a damaged parse table")


def _lark_version() -> str:
    """Lark's version, read from its ``__init__.py`` without importing it (so a Lark upgrade
    rebuilds the cached table)."""
    import importlib.util
    spec = importlib.util.find_spec("lark")
    if spec is None or spec.origin is None:
        return "?"
    try:
        m = re.search(r"__version__\s*(?::\s*str\s*)?=\s*['\"]([^'\"]+)", Path(spec.origin).read_text())
    except OSError:
        return "?"
    return m.group(1) if m else "?"


def _lex_lists(text: str, keep_ignored: bool = False,
               path: str = "") -> tuple[list, list, "UnexpectedCharacters | None"]:
    """Lark's basic lexer over ``text`` (same terminals, same order, same keyword retyping,
    same positions), as one loop: at each position the alternation of only the terminals that
    can start with the character there (:meth:`_Tables.regex_for`; the whole alternations
    where there is no entry), since trying two dozen alternatives in turn was half the
    lexer's time.  Returns the terminal names, their :class:`Span` s (``file`` = ``path``) and
    the :class:`UnexpectedCharacters` where no terminal matched (the tokens then stop there),
    else ``None``.  No token object is made: a token's text is ``text[span.start:span.end]``
    (a str subclass with a ``__dict__`` per token was a third of the lexer's time).
    ``keep_ignored``: also the whitespace and comment tokens the parser skips (Lark's
    ``lex(dont_ignore=True)``; used by ``aidl fmt``)."""
    tb = _tables()
    by_first, regex_for = tb.by_first, tb.regex_for
    ignore, newline, keywords = tb.ignore, tb.newline, tb.keywords
    plain = tb.plain                # terminals that are neither skipped, multi-line nor retyped
    literal = tb.literal_keywords
    skip = frozenset() if keep_ignored else ignore - newline
    pos, line, line_start, end = 0, 1, 0, len(text)
    types: list = []
    spans: list = []
    push_t, push_s = types.append, spans.append
    span = _new_span
    while pos < end:
        ch = text[pos]
        try:
            rx = by_first[ch]
        except KeyError:
            rx = regex_for(ch)
        m = rx.match(text, pos) if rx is not None else None
        if m is None:
            for mre in tb.mres:
                m = mre.match(text, pos)
                if m:
                    break
            else:
                return types, spans, UnexpectedCharacters(text, pos, line, pos - line_start + 1)
        type_ = m.lastgroup
        npos = m.end()
        if type_ in plain:
            push_t(type_)
            push_s(span((path, line, pos - line_start + 1, line, npos - line_start + 1, pos,
                         npos)))
            pos = npos
            continue
        if type_ in skip:           # single-line whitespace or comment: no text needed
            pos = npos
            continue
        if type_ in literal:        # a NAME, perhaps a keyword
            push_t(literal[type_].get(m.group(), type_))
            push_s(span((path, line, pos - line_start + 1, line, npos - line_start + 1, pos,
                         npos)))
            pos = npos
            continue
        value = m.group()
        if type_ in ignore and not keep_ignored:
            if type_ in newline:
                k = value.count("\n")
                if k:
                    line += k
                    line_start = pos + value.rindex("\n") + 1
            pos = npos
            continue
        start_line, column = line, pos - line_start + 1
        if type_ in newline:
            k = value.count("\n")
            if k:
                line += k
                line_start = pos + value.rindex("\n") + 1
        if type_ in keywords:
            kw = keywords[type_]
            if type(kw) is dict:
                type_ = kw.get(value, type_)
            else:
                for kre in kw:
                    km = kre.fullmatch(value)
                    if km:
                        type_ = km.lastgroup
                        break
        push_t(type_)
        push_s(span((path, start_line, column, line, npos - line_start + 1, pos, npos)))
        pos = npos
    return types, spans, None


def _token(type_: str, span: Span, text: str) -> Token:
    """The :class:`Token` of a lexed token (for errors, ``aidl fmt`` and the tests): its text
    is ``text[span.start:span.end]``, but ``"\n"`` for a newline the post-lexer put in at a
    ``}`` and ``""`` for ``$END``."""
    if type_ == "$END":
        value = ""
    else:
        value = text[span[5]:span[6]]
        if type_ == "_NL" and not value.startswith(("\n", "\r")):
            value = "\n"
    t = str.__new__(Token, value)
    t.type = type_
    t.pos = span
    return t


def _lex(text: str, keep_ignored: bool = False,
         path: str = "") -> tuple[list, "UnexpectedCharacters | None"]:
    """:func:`_lex_lists` as :class:`Token` s (``aidl fmt``; the tests compare them with
    Lark's)."""
    types, spans, error = _lex_lists(text, keep_ignored, path)
    return [_token(t, sp, text) for t, sp in zip(types, spans)], error


def _tokens(text: str, path: str = "") -> tuple[list, "UnexpectedCharacters | None"]:
    """The parser's tokens, lexed and post-lexed, as :class:`Token` s (what Lark's
    ``Lark.lex`` gives with the post-lexer; for the tests)."""
    types, spans, error = _lex_lists(text, False, path)
    types, spans = _postlex(types, spans, text, error is None)
    return [_token(t, sp, text) for t, sp in zip(types, spans)], error


def _run_lalr(text: str, start: str):
    """Lex ``text`` (:func:`_lex_lists`, :func:`_postlex`) and run the LALR(1) table over the
    tokens with the AST callbacks: the loop of Lark's ``ParserState.feed_token`` without its
    per-step assertions and rule-object look-ups.  Returns the start symbol's value.  Raises
    :class:`UnexpectedToken` / :class:`UnexpectedCharacters` (a lexer error only once the
    parser has taken every token before it, as a streaming lexer would).

    Three stacks: states, values (a token's value is its :class:`Span`; the builders read its
    text from ``builder.text``) and extents (the span each value covers, ``None`` for a
    reduction that covers no token), so no wrapper object is made per reduction."""
    tb = _tables()
    states, reductions, start_states, end_states = tb.states, tb.reductions, tb.start, tb.end
    builder = _STATE.builder
    outer = builder.text
    builder.text = text
    try:
        types, spans, lex_error = _lex_lists(text, False, builder.path)
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


# --------------------------------------------------------------- preprocessing
def mask_comments(src: str, record: list | None = None) -> str:
    """Turn ``//`` comments into ``# `` comments (same length, so spans stay valid).

    The rule (docs/language.md, "Comments"): ``//`` is floor division when the code before it
    ends an operand (a name, number, ``)``, ``]``) on the same line -- or on an earlier line
    inside open ``(``/``[`` -- and the rest of the line does not read as prose (two words side
    by side that are not keywords, or characters no expression uses).  Otherwise it starts a
    comment: ``// note`` on its own line, ``x = 5  // half the width``.  So code that parses
    as an expression is never swallowed.  ``record`` (if given) receives ``(offset, is_comment)``
    for every ``//`` seen, for the syntax-error hints.
    """
    if "//" not in src:                         # nothing to decide (and nothing to record)
        return src
    out = list(src)
    i, n = 0, len(src)
    quote = None
    line_start = True
    depth = 0
    prev = ""                # the last code character (outside strings and comments)
    while i < n:
        ch = src[i]
        if quote:
            if ch == "\\":
                i += 2
                continue
            if ch == quote or ch == "\n":
                quote = None
                prev = "a"   # a string ends an operand
            i += 1
            continue
        if ch not in _SPECIAL:                  # a run of ordinary characters at once
            m = _PLAIN.match(src, i)
            seg = m.group()
            if not seg.isspace():
                line_start = False
                prev = seg.rstrip()[-1]
                for b in _BRACKETS.findall(seg):
                    if b in "([":
                        depth += 1
                    elif depth:
                        depth -= 1
            i = m.end()
            continue
        if ch in "\"'":
            quote = ch
            line_start = False
        elif ch == "#":
            j = src.find("\n", i)
            i = n if j < 0 else j
            continue
        elif ch == "/" and src.startswith("/*", i):
            j = src.find("*/", i + 2)
            i = n if j < 0 else j + 2
            continue
        elif ch == "/" and src.startswith("//", i):
            j = src.find("\n", i)
            rest = src[i + 2: (n if j < 0 else j)]
            operand_before = prev.isalnum() or prev in "_)]°"
            division = operand_before and (not line_start or depth > 0) and not _is_prose(rest)
            if record is not None:
                record.append((i, not division))
            if not division:
                out[i], out[i + 1] = "#", " "
                i = n if j < 0 else j
                continue
            prev = "/"
            line_start = False
            i += 2
            continue
        elif ch == "\n":
            line_start = True
        elif not ch.isspace():
            line_start = False
            prev = ch
            if ch in "([":
                depth += 1
            elif ch in ")]" and depth:
                depth -= 1
        i += 1
    return "".join(out)


_SPECIAL = frozenset("\"'#/\n")
_PLAIN = re.compile(r"[^\"'#/\n]+")
_BRACKETS = re.compile(r"[()\[\]]")
_ANY_BRACKET = re.compile(r"[()\[\]{}]")
_BRACKET_STEP = {"(": 1, "[": 1, "{": 1, ")": -1, "]": -1, "}": -1}
_KW = {"if", "else", "and", "or", "not", "for", "in"}
_STRINGS = re.compile(r"[fF]?(\"(\\.|[^\"\\\n])*\"?|'(\\.|[^'\\\n])*'?)")


def _is_prose(rest: str) -> bool:
    """After ``//``: prose (two words side by side, not keywords, or characters no
    expression uses), so a comment.  Strings in the rest are not looked into."""
    code = _STRINGS.sub('""', rest).split("#", 1)[0].split("//", 1)[0]
    if not code.strip():
        return True
    for m in re.finditer(r"(?<![\w.])([A-Za-z_]\w*)[ \t]+(?=([A-Za-z_]\w*))", code):
        if m.group(1) not in _KW and m.group(2) not in _KW:
            return True
    return bool(re.search(r"[^\w\s.()\[\]{}+\-*/%,<>=!:;\"'°]", code))


def _slash_hint(sink: DiagnosticSink, slashes: list, text: str, pos: int) -> None:
    """Add to the syntax error just reported (at ``pos``) which way a nearby ``//`` was read."""
    if not slashes or not sink.items:
        return
    d = sink.items[-1]
    line = text.count("\n", 0, min(pos, len(text))) + 1
    for off, is_comment in reversed(slashes):
        ln = text.count("\n", 0, off) + 1
        if not is_comment and ln == line:
            d.hint = ("`//` on this line is read as floor division (after an operand, before "
                      "code); start a comment with `#`")
            return
        if is_comment and ln <= line and (ln == line or pos >= len(text.rstrip())):
            d.hint = (f"`//` on line {ln} starts a comment, so the rest of that line is not "
                      f"code; for floor division write the operands on both sides, e.g. `n // 2`")
            return


def _blank_logical_line(text: str, pos: int) -> str:
    """Blank the logical line (bracket-balanced) around offset ``pos``, keeping braces/newlines.

    It goes on over the next lines while a ``(`` or ``[`` is open, as long as they read as its
    continuation: indented deeper than its first line, or starting with a closing bracket.  A
    bracket left open by a typo so blanks its own line, not the rest of the file."""
    start = text.rfind("\n", 0, pos) + 1
    end = text.find("\n", pos)
    end = len(text) if end < 0 else end
    first = text[start:end]
    indent = len(first) - len(first.lstrip(" \t"))
    # extend forward while () / [] are open
    depth = sum(1 if c in "([" else -1 if c in ")]" else 0 for c in first)
    while depth > 0 and end < len(text):
        nxt = text.find("\n", end + 1)
        nxt = len(text) if nxt < 0 else nxt
        line = text[end + 1:nxt]
        body = line.lstrip(" \t")
        if body and len(line) - len(body) <= indent and body[0] not in ")]":
            break
        depth += sum(1 if c in "([" else -1 if c in ")]" else 0 for c in text[end:nxt])
        end = nxt
    seg = "\n".join(_blank_keeping_blocks(line) for line in text[start:end].split("\n"))
    return text[:start] + seg + text[end:]


def _blank_keeping_blocks(line: str) -> str:
    """``line`` blanked but for the braces that open or close a block: all of them when they
    balance on the line (``if a { x = 1 }``), else a ``{`` that ends it and a ``}`` that starts
    it (``solid a {``, ``} else {``); a brace typed inside an expression (``Circle(c{enter``)
    would nest or close the blocks around it."""
    if line.count("{") == line.count("}"):
        return "".join(c if c in "{}" else " " for c in line)
    body = line.strip(" \t\r")
    out = [" "] * len(line)
    if body.startswith("}"):
        out[line.index("}")] = "}"
    if body.endswith("{"):
        out[line.rindex("{")] = "{"
    return "".join(out)


def _expected_text(expected) -> str:
    names = []
    for e in sorted(expected or []):
        nm = TOKEN_NAMES.get(e)
        if nm is None:
            if e.isupper() and e.isalpha() and len(e) < 10:
                nm = f"`{e.lower()}`"
            else:
                continue
        if nm not in names:
            names.append(nm)
    if not names:
        return ""
    if len(names) > 8:
        names = names[:8] + ["..."]
    return "expected " + ", ".join(names)


# ----------------------------------------------------------------- brackets (issue 28)
_PAIR = {"RPAR": "LPAR", "RSQB": "LSQB", "RBRACE": "LBRACE"}
_CHAR = {"LPAR": "(", "RPAR": ")", "LSQB": "[", "RSQB": "]", "LBRACE": "{", "RBRACE": "}"}
_CLOSER_OF = {"LPAR": ")", "LSQB": "]", "LBRACE": "}"}


class _Lines:
    """Lines of a text: their indentation (``None`` for a blank or comment-only line)."""

    def __init__(self, text: str):
        self.lines = text.split("\n")
        self.indent = []
        for ln in self.lines:
            body = ln.lstrip(" \t")
            blank = not body.strip() or body.startswith(("#", "//"))
            self.indent.append(None if blank else len(ln) - len(body))

    def of(self, line: int) -> int | None:
        return self.indent[line - 1] if 0 < line <= len(self.indent) else None

    def continued(self, toks: list) -> None:
        """Mark the lines that start inside an open ``(`` or ``[`` (an expression carried on):
        :meth:`stmt` gives them the indentation of the line the statement starts on.  A ``{``
        or ``}`` ends any expression left open (blocks are statements: no expression holds
        one), so one unclosed ``(`` does not make the rest of the file its continuation."""
        self.cont = [False] * (len(self.indent) + 1)
        depth, line = 0, 1
        for t, sp in toks:
            if t in ("LBRACE", "RBRACE"):
                depth = 0
            if sp.line > line:
                for k in range(line + 1, sp.line + 1):
                    self.cont[k - 1] = depth > 0
                line = sp.line
            if t in ("LPAR", "LSQB"):
                depth += 1
            elif t in ("RPAR", "RSQB") and depth:
                depth -= 1
        self.start = list(range(len(self.cont) + 1))     # line -> the line its statement starts on
        for k in range(2, len(self.cont) + 1):
            if self.cont[k - 1]:
                self.start[k] = self.start[k - 1]

    def stmt(self, line: int) -> int | None:
        """The indentation of the statement that ``line`` is part of."""
        return self.of(self.start[line] if 0 < line < len(self.start) else line)

    def first_on_line(self, sp) -> bool:
        ln = self.lines[sp.line - 1]
        return not ln[:sp.col - 1].strip()

    def next_code(self, line: int) -> int | None:
        """The first line after ``line`` with code on it."""
        for k in range(line + 1, len(self.indent) + 1):
            if self.indent[k - 1] is not None:
                return k
        return None

    def prev_code(self, line: int) -> int | None:
        for k in range(line - 1, 0, -1):
            if self.indent[k - 1] is not None:
                return k
        return None


def _bracket_problems(text: str, path: str) -> list:
    """Where the brackets of ``text`` (comments masked) do not balance: a list of
    ``((lo, hi), code, message, span, hint, labels)``, in the order found, the parser's own
    errors at offsets ``lo..hi`` being consequences of this one; ``[]`` when every bracket is
    matched (or the lexer stopped early: E0002 says why).

    Plain matching decides whether there is a problem.  Where it is: at each closing bracket
    that does not simply close the innermost open one, the readings -- it closes an open
    bracket further out (those in between were never closed) or it closes nothing -- are
    compared by how many problems the rest of the file then has under plain matching, the
    fewest winning; a tie goes by indentation (a ``}`` first on its line belongs to the ``{``
    on a line indented like it; a ``}`` indented deeper than the innermost open ``{``'s line
    closes nothing).  So ``hole bore {`` missing its ``}`` is reported at ``hole bore {``, not
    at the end of the file, with the line where the indentation comes back to it; a ``}``
    whose ``{`` was left out is reported with the line whose indentation it matches."""
    types, spans, err = _lex_lists(text, path=path)
    if err is not None:
        return []
    toks = [(t, sp) for t, sp in zip(types, spans) if t in _CLOSER_OF or t in _PAIR]
    if _plain_cost(toks, 0, []) == 0:
        return []
    L = _Lines(text)
    L.continued(toks)
    out: list = []
    net_of: dict = {}               # line -> opened minus closed ( and [ on it
    for t, sp in toks:
        if t in ("LPAR", "LSQB"):
            net_of[sp.line] = net_of.get(sp.line, 0) + 1
        elif t in ("RPAR", "RSQB"):
            net_of[sp.line] = net_of.get(sp.line, 0) - 1

    def unclosed(t, sp) -> None:
        ch, close = _CHAR[t], _CLOSER_OF[t]
        ind = L.stmt(sp.line) or 0
        k = L.next_code(sp.line)          # the first line back at the opener's indentation
        while k is not None and (L.of(k) or 0) > ind:
            k = L.next_code(k)
        last = (L.prev_code(k) or sp.line) if k is not None else (
            L.prev_code(len(L.lines) + 1) or sp.line)
        labels = []
        lo = sp.start               # the parser's errors from here on follow from it
        if t == "LBRACE":
            if k is None:
                hint = f"add `{close}` at the end of the file"
            else:
                hint = (f"add `{close}` after line {last}, where the block probably ends (line "
                        f"{k} is back at the indentation of line {sp.line})")
                labels = [_line_label(L, path, k, "the block probably ends before this line")]
        else:
            # a continuation line that opens more than it closes and ends with `,` (an
            # argument list goes on) is where a `)` went missing; else the statement's end
            for ln in range(sp.line + 1, last + 1):
                net = net_of.get(ln, 0)
                code = L.lines[ln - 1].split("#", 1)[0].rstrip()
                if net > 0 and code.endswith(","):
                    hint = (f"a `)` or `]` is probably missing in line {ln}: it opens "
                            f"{net} more than it closes")
                    labels = [Label(_line_end_span(L, path, ln), "a closing bracket is "
                                    "probably missing in this line", primary=False)]
                    lo = labels[0].span.start
                    break
            else:
                hint = (f"add `{close}` at the end of line {last}, where the statement ends" +
                        (" (the next line starts a new one)" if k is not None else ""))
                labels = [Label(_line_end_span(L, path, last), f"`{close}` probably missing here",
                                primary=False)]
                # a mistake inside the statement itself (`height= }`) is its own: kept
                lo = labels[0].span.start
        out.append(((lo, len(text) + 1), "E0001", f"`{ch}` is never closed", sp, hint,
                    labels))

    def stray(t, sp) -> None:
        ch, want = _CHAR[t], _CHAR[_PAIR[t]]
        guess = sp.line
        if L.first_on_line(sp):
            ind = L.of(sp.line)
            k = L.prev_code(sp.line)
            while k is not None and L.of(k) != ind:
                k = L.prev_code(k)
            guess = k
        labels = [Label(sp, f"`{ch}` closes nothing", primary=False)]
        if guess is not None and guess != sp.line:
            where = _line_end_span(L, path, guess)
            out.append(((where.start, _line_end(text, sp.start)), "E0001",
                        f"`{ch}` on line {sp.line} closes nothing: the `{want}` that it closes is "
                        f"probably missing here", where,
                        f"add `{want}` at the end of line {guess} (line {sp.line}'s `{ch}` is at its "
                        "indentation), or remove the extra `" + ch + "`", labels))
        else:
            out.append(((text.rfind("\n", 0, sp.start) + 1, _line_end(text, sp.start)),
                        "E0001", f"`{ch}` closes nothing", sp,
                        f"remove it, or add the `{want}` it should close", []))

    stack: list = []                # (type, span)
    decisions = 0
    for i, (t, sp) in enumerate(toks):
        if t in _CLOSER_OF:
            stack.append((t, sp))
            continue
        want = _PAIR[t]
        first = L.first_on_line(sp)
        ind = L.of(sp.line) if first else None
        top_ok = bool(stack) and stack[-1][0] == want
        same = [k for k in range(len(stack)) if stack[k][0] == want]
        by_indent = [k for k in same if first and L.stmt(stack[k][1].line) == ind]
        top_line = stack[-1][1].line if stack else None
        if top_ok and (not first or not by_indent or by_indent[-1] == len(stack) - 1) and \
                (t != "RBRACE" or (first and L.stmt(top_line) == ind)
                 or (not first and top_line == sp.line)):
            stack.pop()             # the plain case
            continue
        # a `}` after code on its line closing a `{` of an earlier line: perhaps its own `{`
        # on this line was left out (`hole h { c = ... }`)
        inline = t == "RBRACE" and not first and top_ok and top_line != sp.line
        if len(out) >= MAX_ERRORS:
            break
        decisions += 1
        if decisions > MAX_BRACKET_DECISIONS:    # hostile input: plain matching from here
            k = next((k for k in range(len(stack) - 1, -1, -1) if stack[k][0] == want), None)
            if k is None:
                stray(t, sp)
            else:
                for ot, osp in stack[k + 1:]:
                    unclosed(ot, osp)
                del stack[k:]
            continue
        # the readings: close one of the open brackets of this kind, or close nothing
        rest = [(st[0], None) for st in stack]
        options = []
        for k in same:
            cost = len(stack) - 1 - k + _plain_cost(toks, i + 1, [x for x, _ in rest[:k]])
            pref = 0 if k in by_indent else (1 if k == len(stack) - 1 else 3)
            options.append((cost, pref, k))
        deeper = first and t == "RBRACE" and stack and L.stmt(top_line) is not None \
            and ind is not None and ind > L.stmt(top_line)
        options.append((1 + _plain_cost(toks, i + 1, [x for x, _ in rest]),
                        0 if deeper or inline else 2, None))
        _cost, _pref, k = min(options, key=lambda o: (o[0], o[1]))
        if k is None:
            stray(t, sp)
            continue
        for ot, osp in stack[k + 1:]:
            unclosed(ot, osp)
        del stack[k:]
    for ot, osp in stack[:max(0, MAX_ERRORS - len(out))]:
        unclosed(ot, osp)
    return out


def _plain_cost(toks: list, i: int, stack: list) -> int:
    """How many bracket problems plain matching finds in ``toks[i:]`` with ``stack`` (types)
    open: a closer that closes an open bracket further out counts those in between, one that
    closes nothing counts one, and what is open at the end counts."""
    stack = list(stack)
    n = 0
    for t, _sp in toks[i:]:
        if t in _CLOSER_OF:
            stack.append(t)
            continue
        want = _PAIR[t]
        if stack and stack[-1] == want:
            stack.pop()
            continue
        for k in range(len(stack) - 1, -1, -1):
            if stack[k] == want:
                n += len(stack) - 1 - k
                del stack[k:]
                break
        else:
            n += 1
    return n + len(stack)


def _line_end(text: str, pos: int) -> int:
    end = text.find("\n", pos)
    return len(text) if end < 0 else end


def _line_end_span(L: "_Lines", path: str, line: int) -> Span:
    """A one-character span just after the code of ``line``."""
    start = sum(len(x) + 1 for x in L.lines[:line - 1])
    body = L.lines[line - 1].split("#", 1)[0].rstrip()
    col = len(body) + 1
    return Span(path, line, col, line, col + 1, start + col - 1, start + col)


def _line_label(L: "_Lines", path: str, line: int, message: str):
    start = sum(len(x) + 1 for x in L.lines[:line - 1])
    ind = L.of(line) or 0
    width = max(1, len(L.lines[line - 1].rstrip()) - ind)
    return Label(Span(path, line, ind + 1, line, ind + 1 + width, start + ind,
                      start + ind + width), message, primary=False)


def _report_brackets(text: str, path: str, sink: DiagnosticSink, first: int) -> None:
    """After a failed parse: when the brackets do not balance, report where
    (:func:`_bracket_problems`) instead of the parser's errors that follow from it (those in
    each problem's range; the others are kept).  ``first``: the index
    of this parse's first diagnostic in ``sink.items``."""
    problems = _bracket_problems(text, path)
    if not problems:
        return
    def consequence(d) -> bool:             # E0116: a `def` after a block never closed
        return d.code in ("E0001", "E0116") and d.span is not None and any(
            lo <= d.span.start <= hi for (lo, hi), *_rest in problems)
    mine = sink.items[first:]
    keep = [d for d in mine if not consequence(d)]
    del sink.items[first:]
    sink.items.extend(keep)
    for _off, code, message, span, hint, labels in problems[:MAX_ERRORS]:
        sink.error(code, message, span, hint, labels=labels)
    sink.items[first:] = sorted(sink.items[first:],
                                key=lambda d: d.span.start if d.span is not None else -1)


def parse(source: str, path: str, sink: DiagnosticSink) -> A.Program:
    """Parse ``source`` (from ``path``) into a :class:`Program`; syntax errors go to ``sink``.

    On syntax errors the returned program holds the statements that did parse.

    The cyclic garbage collector is paused while parsing: the parse makes tens of thousands
    of tokens, tuples and nodes but no reference cycles, and the collector's passes over them
    were a quarter of the time (a 178 KB program: 358 -> 265 ms).
    """
    with gc_paused():
        return _parse(source, path, sink)


IMPORTS_KEPT = 16          # imported files whose parse is remembered (parse_import) ...
IMPORTS_KEPT_CHARS = 1_000_000     # ... and their source characters in all (~40 MB of trees)
_IMPORTED: dict = {}       # (path, source) -> Program, oldest first
_IMPORTED_LOCK = threading.Lock()       # the server compiles on more than one thread


def parse_import(source: str, path: str, sink: DiagnosticSink) -> A.Program:
    """:func:`parse` for an imported file, remembered by its path and text: a file read again
    with the same text (``std/gears.aidl`` on every slider move of the live preview) gives
    the same :class:`Program` without a parse.  Only a parse without diagnostics is kept (a
    hit adds nothing to ``sink`` but the source); the last :data:`IMPORTS_KEPT` files, at
    most :data:`IMPORTS_KEPT_CHARS` characters of source in all (a tree takes some 35-60
    bytes a character), are kept.  The interpreter only reads the tree, as it reads the main
    file's again on each move."""
    key = (path, source)
    prog = _IMPORTED.get(key)
    if prog is not None:
        sink.sources[path] = source
        return prog
    first = len(sink.items)
    prog = parse(source, path, sink)
    if len(sink.items) == first and len(source) <= IMPORTS_KEPT_CHARS:
        with _IMPORTED_LOCK:
            _IMPORTED[key] = prog
            while len(_IMPORTED) > IMPORTS_KEPT or sum(
                    len(text) for _p, text in _IMPORTED) > IMPORTS_KEPT_CHARS:
                del _IMPORTED[next(iter(_IMPORTED))]
    return prog


def _parse(source: str, path: str, sink: DiagnosticSink) -> A.Program:
    first = len(sink.items)
    program, text = _parse_text(source, path, sink)
    if len(sink.items) > first and text is not None:
        _report_brackets(text, path, sink, first)
    return program


def _parse_text(source: str, path: str, sink: DiagnosticSink):
    """The parse with error recovery: ``(program, masked text)`` (text ``None`` when
    nesting was refused)."""
    # a lone CR ends a line as LF does (diagnostics.LINE_BREAK: as an editor shows it), a `#`
    # comment with it; offsets, lines and columns are the same in both texts
    source = as_lf(source)
    sink.sources[path] = source
    if "\x00" in source:
        source = source.replace("\x00", " ")
    slashes: list = []
    text = masked = mask_comments(source, slashes)
    check_controls(source, masked, path, sink)       # W0111: bidi controls, U+2028 / U+2029
    # the deepest nesting, in C (a running sum of +1/-1); the loop below only finds where
    if max(accumulate(map(_BRACKET_STEP.__getitem__, _ANY_BRACKET.findall(text))),
           default=0) > MAX_NESTING:
        depth = 0
        for m in _ANY_BRACKET.finditer(text):
            if m.group() in "([{":
                depth += 1
                if depth > MAX_NESTING:
                    i = m.start()
                    line = text.count("\n", 0, i) + 1
                    col = i - text.rfind("\n", 0, i)
                    sink.error("E0003", f"brackets nested more than {MAX_NESTING} deep",
                               Span(path, line, col, line, col + 1, i, i + 1),
                               "split the expression into named constants")
                    return A.Program(Span(path, 1, 1, 1, 1), path, source, []), None
            else:
                depth -= 1
    _tables()
    builder = _Builder(path, sink)
    prev, _STATE.builder = getattr(_STATE, "builder", None), builder
    try:
        stmts = _recovering_parse(text, path, sink, slashes, builder)
        if stmts is None and not builder.failed:
            # the line-by-line recovery gave up (a bracket never closed, a brace too many, an
            # error it cannot step over): the statements of each top-level piece that parses
            # on its own are kept, every error in the others was reported or is beyond them
            stmts = _recover_by_pieces(masked, path, builder)
    finally:
        _STATE.builder = prev
    if builder.failed:
        sink.error(*builder.failed[0])
        return A.Program(Span(path, 1, 1, 1, 1), path, source, []), masked
    end_line = source.count("\n") + 1
    return A.Program(Span(path, 1, 1, end_line, 1, 0, len(source)), path, source, stmts), masked


def _recovering_parse(text: str, path: str, sink: DiagnosticSink, slashes: list,
                      builder: "_Builder") -> list | None:
    """The statements of ``text``, each syntax error reported to ``sink`` and its logical
    line blanked before the next try (:func:`_blank_logical_line`); None when it gives up: an
    error where one was already, at the end of the text, or more than :data:`MAX_ERRORS`."""
    return _recovered(text, path, sink, slashes, builder)[0]


def _recovered(text: str, path: str, sink: DiagnosticSink, slashes: list,
               builder: "_Builder") -> tuple[list | None, str]:
    """:func:`_recovering_parse`'s statements (or None) and the text it parsed last (its
    error lines blanked: of the same length as ``text``)."""
    seen: set[int] = set()
    for _attempt in range(MAX_ERRORS + 1):
        builder.failed.clear()
        try:
            return _run_lalr(text, "start"), text
        except (UnexpectedToken, UnexpectedCharacters) as e:
            pos = _error_pos(e, text)
            if pos in seen or len(seen) >= MAX_ERRORS:
                return None, text
            seen.add(pos)
            _report(e, text, path, pos, sink)
            _slash_hint(sink, slashes, text, pos)
            if pos >= len(text.rstrip()):
                return None, text
            text = _blank_logical_line(text, pos)
    return None, text


# a line that starts a top-level declaration whatever the braces before it say: `solid name {`,
# `def name(`, `name name(` (a template's short form), `param`, `import`, `units`
_DECLARATION = re.compile(r"(?:[A-Za-z_]\w*[ \t]+[A-Za-z_]\w*[ \t]*[({]|(?:def|param|import|units)\b)")
_NOT_CODE = re.compile(r"#[^\n]*|/\*(?:.|\n)*?(?:\*/|\Z)")


def _top_level_pieces(text: str) -> list[tuple[int, int]]:
    """``(start, end)`` offsets of what seem to be the top-level statements of ``text`` (masked,
    LF line breaks): a piece starts at a line that starts with a name at column 0 when every
    bracket before it is closed, or that starts a declaration (:data:`_DECLARATION`) whatever
    they are: a bracket or brace left open by a syntax error does not swallow what follows."""
    bare = _NOT_CODE.sub(lambda m: re.sub(r"[^\n]", " ", m.group()),
                         _STRINGS.sub(lambda m: " " * len(m.group()), text))
    starts, depth, pos = [], 0, 0
    for line in bare.split("\n"):
        if line[:1].isalpha() or line[:1] == "_":
            if depth <= 0 or _DECLARATION.match(line):
                starts.append(pos)
                depth = 0
        depth += sum(map(_BRACKET_STEP.__getitem__, _ANY_BRACKET.findall(line)))
        pos += len(line) + 1
    starts.append(len(text))
    return [(a, b) for a, b in zip(starts, starts[1:]) if text[a:b].strip()]


def _recover_by_pieces(text: str, path: str, builder: "_Builder") -> list:
    """The statements of every top-level piece of ``text`` (:func:`_top_level_pieces`) that
    parses on its own, with the line recovery of :func:`_recovering_parse` (its errors are not
    reported again), in order.  Each piece is first tried alone (:func:`_repaired_piece`); then
    the text is parsed once with every repair made and every piece that does not parse blanked
    (the same length, so every span is that of ``text``): linear in the pieces (parsing each
    piece after a blank as long as the text before it took 25 s for 12,000 structures)."""
    out, at = [], 0
    for a, b in _top_level_pieces(text):
        fixed = _repaired_piece(text[a:b], path, builder)
        out += [text[at:a], fixed if fixed is not None else _blank(text[a:b])]
        at = b
    out.append(text[at:])
    stmts, _ = _recovered("".join(out), path, DiagnosticSink(), [], builder)
    if stmts is None or builder.failed:
        builder.failed.clear()
        return []
    return stmts


def _repaired_piece(piece: str, path: str, builder: "_Builder") -> str | None:
    """``piece`` (one top-level piece) with the lines the line recovery blanks blanked, when it
    then parses on its own; a ``(`` or ``[`` never closed swallows the piece up to its end,
    where the error is found: its own line is blanked first.  None when it does not parse."""
    for attempt in (0, 1):
        if attempt:
            for at in reversed(_unclosed(piece)):
                piece = _blank_logical_line(piece, at)
        got, parsed = _recovered(piece, path, DiagnosticSink(), [], builder)
        ok = got is not None and not builder.failed
        builder.failed.clear()
        if ok:
            return parsed
    return None


def _blank(text: str) -> str:
    """``text`` as blanks of the same length, its line breaks kept."""
    return re.sub(r"[^\n]", " ", text)


def _unclosed(text: str) -> list[int]:
    """The offsets of the ``(`` and ``[`` of ``text`` (masked) that nothing closes, strings and
    comments aside."""
    bare = _NOT_CODE.sub(lambda m: " " * len(m.group()),
                         _STRINGS.sub(lambda m: " " * len(m.group()), text))
    stack: list[int] = []
    for m in _ANY_BRACKET.finditer(bare):
        c = m.group()
        if c in "([":
            stack.append(m.start())
        elif c in ")]" and stack:
            stack.pop()
    return stack


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


def _error_pos(e: ParseError, text: str) -> int:
    if isinstance(e, UnexpectedToken) and e.token.type == "$END":
        return len(text)
    p = getattr(e, "pos_in_stream", None)
    if p is None and isinstance(e, UnexpectedToken):
        p = e.token.start_pos
    return len(text) if p is None else p


def _report(e: ParseError, text: str, path: str, pos: int, sink: DiagnosticSink) -> None:
    line = text.count("\n", 0, pos) + 1
    col = pos - text.rfind("\n", 0, pos)
    if isinstance(e, UnexpectedCharacters):
        ch = text[pos] if pos < len(text) else ""
        if ch in "\"'":
            msg, hint = "unterminated string", "close the string on the same line"
        elif invisible(ch):
            msg, hint = (f"unexpected character {code_point(ch)}",
                         "delete it: it cannot start a name, a number or an operator, and it "
                         "shows nothing of its own (or moves the text around it)")
        else:
            msg, hint = f"unexpected character `{ch}`", None
        sink.error("E0002", msg, Span(path, line, col, line, col + 1, pos, pos + 1), hint)
        return
    expected = _expected_text(getattr(e, "expected", None) or getattr(e, "accepts", None))
    if isinstance(e, UnexpectedToken) and e.token.type == "$END":
        sink.error("E0001", "unexpected end of file" + (f"; {expected}" if expected else ""),
                   Span(path, line, col, line, col + 1, pos, pos + 1),
                   "a `{` or `(` is probably not closed")
        return
    tok = e.token
    width = max(1, len(str(tok)))
    what = "newline" if tok.type == "_NL" else f"`{tok}`"
    hint = None
    line_start = text.rfind("\n", 0, pos) + 1
    head = text[line_start:pos].strip().lstrip("}").strip()
    if tok.type in _TOP_ONLY:
        opener = _outermost_open_brace(text, pos)
        if opener is not None:
            _report_top_only(tok, text, path, pos, opener, sink)
            return
    if tok.type == "COLON" and re.match(r"(for|if|elif|else|while|def)\b", head):
        kw = head.split()[0]
        stmt = head.rstrip(":").rstrip()
        hint = (f"AIDL writes blocks with braces, not a colon and indentation: `{stmt} {{` on "
                f"this line and `}}` after the block's last line" +
                (" (`else if` or `elif`, `else` follow the `}` of the `if`)" if kw in ("if", "elif", "else") else "") +
                (" (templates: `def NAME(PARAMS) -> solid { ... }`)" if kw == "def" else ""))
        sink.error("E0001", f"unexpected `:` after `{kw}`: a block is written in braces",
                   Span(path, line, col, line, col + 1, pos, pos + 1), hint)
        return
    exp = getattr(e, "expected", None) or ()
    if tok.type in ("NAME", "NUMBER", "STRING", "FSTRING", "LPAR", "LSQB") and "COMMA" in exp \
            and _open_paren(text, pos):
        hint = f"a `,` is probably missing before `{tok}`"
    elif str(tok) == "=" and re.match(r"\s*units\s*$", head):
        hint = "`units` is a statement without `=`: `units mm` (or `in`, `cm`, ...)"
    elif str(tok) == "=" :
        hint = "use `==` for an equation constraint, `=` only to name a value"
    elif str(tok) == "{" :
        hint = "a structure is written `solid NAME { ... }`"
    elif tok.type == "_NL":
        # (an unclosed `(` is reported at the bracket instead: newlines inside it are dropped)
        hint = ("the statement ended early: an operand is missing before the line break; to "
                "go on with an expression on the next line, wrap it in `( )`")
    if tok.type == "_NL":
        width = 1
    sink.error("E0001", f"unexpected {what}" + (f"; {expected}" if expected else ""),
               Span(path, line, col, line, col + width, pos, pos + width), hint)


def _open_paren(text: str, pos: int) -> bool:
    """Whether a ``(`` or ``[`` is open at ``pos`` in its statement (arguments, a list)."""
    types, _spans, _err = _lex_lists(text[max(0, text.rfind("{", 0, pos)):pos])
    depth = 0
    for t in types:
        if t in ("LPAR", "LSQB"):
            depth += 1
        elif t in ("RPAR", "RSQB") and depth:
            depth -= 1
        elif t in ("RBRACE", "LBRACE"):
            depth = 0
    return depth > 0


# statements only the top level of a file may hold (E0116 inside a structure)
_TOP_ONLY = {"PARAM": "param", "UNITS": "units", "IMPORT": "import", "DEF": "def"}


def _outermost_open_brace(text: str, pos: int) -> int | None:
    """The offset of the outermost ``{`` still open at ``pos`` (``None`` at the top level)."""
    types, spans, _err = _lex_lists(text[:pos])
    stack: list = []
    for t, sp in zip(types, spans):
        if t == "LBRACE":
            stack.append(sp.start)
        elif t == "RBRACE" and stack:
            stack.pop()
    return stack[0] if stack else None


def _report_top_only(tok, text: str, path: str, pos: int, opener: int,
                     sink: DiagnosticSink) -> None:
    """E0116: ``param``, ``units``, ``import`` or ``def`` inside a structure; the hint says
    where it goes (above the structure that holds it)."""
    word = _TOP_ONLY[tok.type]
    line = text.count("\n", 0, pos) + 1
    col = pos - text.rfind("\n", 0, pos)
    end = text.find("\n", pos)
    stmt = text[pos:len(text) if end < 0 else end].split("#", 1)[0].strip()
    oline = text.count("\n", 0, opener) + 1
    ostart = text.rfind("\n", 0, opener) + 1
    head = text[ostart:opener + 1].strip()
    where = {"param": "params are declared at the top level of the file, before the structures",
             "units": "`units` is given once, at the top of the file",
             "import": "imports go at the top of the file",
             "def": "templates are defined at the top level of the file"}[word]
    short = stmt if len(stmt) <= 40 else stmt[:37] + "..."
    sink.error("E0116", f"`{word}` is only allowed at the top level of a file, not inside a "
               "structure", Span(path, line, col, line, col + len(word), pos, pos + len(word)),
               f"{where}: move `{short}` above line {oline} (`{head}`)"
               + ("; a value used only here can be a plain assignment, e.g. "
                  f"`{stmt.split(None, 1)[1].split(',')[0].strip()}`"
                  if word == "param" and len(stmt.split(None, 1)) > 1 else ""))


class _BuildError(ParseError):
    """A reduction could not build its node (an f-string whose expression does not parse)."""


def parse_number(text: str) -> tuple[float, str | None]:
    m = UNIT_RE.match(text.strip())
    if not m:
        return float(text), None
    unit = m.group("unit")
    if unit == "°":
        unit = "deg"
    return float(m.group("num")), unit


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

    # statements
    def start(self, meta, items):
        return [i for i in items if isinstance(i, A.Node)]

    def block(self, meta, items):
        return A.Block(meta, [i for i in items if isinstance(i, A.Node)])

    def units_decl(self, meta, items):
        return A.UnitsDecl(meta, self.tx(items[0]), items[0])

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
        msg = _unquote(self.tx(items[1])) if len(items) > 1 and items[1] is not None else None
        return A.Assert(meta, items[0], msg)

    def bare_block(self, meta, items):
        return items[0]

    # expressions
    def number(self, meta, items):
        tok = items[0]
        v, unit = parse_number(self.text[tok.start:tok.end])
        return A.Num(meta, v, unit)

    def string(self, meta, items):
        return A.Str(meta, _unquote(self.tx(items[0])))

    def fstring(self, meta, items):
        tok = items[0]
        body = _unquote(self.tx(tok)[1:])
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
        elt, var, it, cond = items
        return A.ListComp(meta, elt, self.tx(var), var, it, cond)

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


def _unquote(s: str) -> str:
    body = s[1:-1]
    return re.sub(r"\\(.)", lambda m: {"n": "\n", "t": "\t"}.get(m.group(1), m.group(1)), body)
