"""The LALR(1) table and basic lexer of ``grammar/aidl.lark`` as plain data: built with Lark
(:func:`_tables_data`, ~0.4 s, the only place Lark is imported) and cached as JSON (never a
pickle) in the user's own cache folder, owner-only (issue 15): :func:`data`.  The lexer
(:mod:`.lexing`) and the LALR loop (:mod:`.lalr`) each make their objects from it."""
from __future__ import annotations

import re
import threading
from pathlib import Path

from ..host.cache import cache_dir, read_checked, write_checked
from .tokens import GRAMMAR

_LARK_OPTIONS = dict(parser="lalr", lexer="basic", maybe_placeholders=True, start=["start", "expr"])
_TABLES_FORMAT = 5      # 5: a header line with the key, length and CRC-32 (cache.write_checked)


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


_DATA: dict | None = None
_DATA_LOCK = threading.Lock()


def data() -> dict:
    """The lexer's and the LALR table's data (:func:`_tables_data`), read from the user's cache
    folder (plain JSON, owner-only, see :mod:`aidl_lang.host.cache`) or built with Lark and written
    there; keyed by the grammar text, the options, the table format and Lark's version (all
    kept in the file and compared).  A cold ``aidl check`` so never imports Lark (~35 ms) nor
    unpacks its serialized parser."""
    global _DATA
    if _DATA is not None:
        return _DATA
    with _DATA_LOCK:
        if _DATA is None:
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
            got = None
            if text is not None:
                try:
                    got = json.loads(text)
                    _check_tables(got)
                except Exception:           # a stale or damaged cache: rebuild it below
                    got = None
            if got is None:
                got = _tables_data()
                if path is not None:
                    write_checked(path, key, json.dumps(got))
            _DATA = got
    return _DATA


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
