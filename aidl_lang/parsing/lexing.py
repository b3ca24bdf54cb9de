"""The lexer and post-lexer: Lark's basic lexer for ``grammar/aidl.lark`` run as one loop with
a first-character dispatch (:func:`_lex_lists`), and the post-lexer that drops newlines inside
brackets and before ``else`` and retypes ``thickness``/``kerf``/``min_wall`` statements
(:func:`_postlex`; :class:`_PostLex` is the same as a streaming Lark post-lexer, the tests'
reference).  Imports :mod:`.tokens` and :mod:`.tables`."""
from __future__ import annotations

import re
import threading

from ..base.diagnostics import Span
from . import tables
from .tokens import Token, UnexpectedCharacters, _new_span

_STATEMENT_START = frozenset(("_NL", "SEMICOLON", "LBRACE", "RBRACE"))
_THICKNESS_NEXT = frozenset(("NUMBER", "NAME", "ADD_OP"))
# the words that start a `WORD LENGTH` statement (retyped by the post-lexer) and their terminals
_DECL_WORDS = {"thickness": "THICKNESS", "kerf": "KERF", "min_wall": "MIN_WALL", "units": "UNITS"}
# what follows each to make it the statement (`units mm`, `units in`; run bs named a part
# `units`, the ones of a countdown, and got 13 E0116)
_DECL_NEXT = {w: _THICKNESS_NEXT for w in _DECL_WORDS} | {"units": frozenset(("NAME", "IN"))}
_BLOCK_FOLLOW = frozenset(("_NL", "SEMICOLON", "RBRACE", "ELSE", "ELIF"))
_OPEN = frozenset(("LPAR", "LSQB"))
_CLOSE = frozenset(("RPAR", "RSQB"))
_ELSE = frozenset(("ELSE", "ELIF"))
# a line ending in one of these cannot end its statement: the newline after it is dropped
# (runs aa, ad: an assert's message after its `,`; run ae: a condition broken after `and`)
CONTINUES = frozenset(("COMMA", "AND", "OR", "NOT", "COMP_OP", "ADD_OP", "MUL_OP", "POW",
                       "EQUAL"))
# a line starting with one of these (no statement can) goes on the line before it, at any
# indent (run ax: an assert broken before its `==`, E0001); `/` and `//` not (a comment may)
LEADS = frozenset(("AND", "OR", "COMP_OP", "POW"))
LEAD_MUL = frozenset(("*", "%"))


def _leads(t: str, text: str) -> bool:
    """Whether a token of type ``t`` and text ``text`` first on a line goes on the line before
    (:data:`LEADS`, and `*` or `%` of MUL_OP)."""
    return t in LEADS or t == "MUL_OP" and text in LEAD_MUL


def _postlex(types: list, spans: list, text: str, complete: bool = True) -> tuple[list, list]:
    """The post-lexer, on the lexer's terminal names and spans (:func:`_lex_lists`; ``text`` is
    what they index), returning the parser's names and spans (``complete=False``: the lexer
    stopped at an error after these tokens, so what the streaming post-lexer would still hold
    back -- a trailing newline or ``thickness`` -- is not passed on):

    - ``thickness`` at the start of a statement and followed by a number, a name or a sign is
      the ``thickness 3 mm`` statement (THICKNESS); anywhere else it is an ordinary NAME;
      ``kerf`` and ``min_wall`` likewise (KERF, MIN_WALL: ``kerf 0.15 mm``, ``min_wall 0.3 mm``),
      and ``units`` before a name or ``in`` (UNITS: ``units mm``);
    - ``_NL`` is dropped inside () and [] and before ``else``/``elif``, and after a ``,``, an
      operator or ``=`` (:data:`CONTINUES`) before a line indented deeper than the statement's
      first (it goes on, as `assert COND,` with the message on the next line or a condition
      broken after `and`; at the statement's own indent, a new statement: the operand
      missing), and before a line that starts with an operator no statement starts with
      (:data:`LEADS`: `==`, `<`, `and`, `or`, `*`, `%`, `**`), and repeats collapse;
    - a closing ``}`` ends a statement even without a newline (``} stmt`` on one line): an
      ``_NL`` at the ``}``'s span is put in (its text is ``"\n"``, see :func:`_token`).

    :class:`_PostLex` is the same as Lark's streaming post-lexer (the tests' reference)."""
    out_t: list = []
    out_s: list = []
    push_t, push_s = out_t.append, out_s.append
    depth = 0
    pending = None          # the span of a newline held back: dropped before else/elif
    cont = False            # ... and after a token of CONTINUES, before a line indented deeper
    col = 0                 # the column of the current statement's first token
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
            if k + 1 < n and types[k + 1] in _DECL_NEXT[text[sp[5]:sp[6]]]:
                t = _DECL_WORDS[text[sp[5]:sp[6]]]
        if prev_type == "RBRACE" and depth == 0 and pending is None and t not in _BLOCK_FOLLOW:
            push_t("_NL")
            push_s(prev_span)
        after = prev_type
        prev_type, prev_span = t, sp
        if t == "_NL":
            if depth == 0 and pending is None:
                pending, cont = sp, after in CONTINUES
            continue
        if pending is not None:
            if t not in _ELSE and not (cont and sp[2] > col) and not _leads(
                    t, text[sp[5]:sp[6]]):
                push_t("_NL")   # (a line after `,` or `and`, indented deeper, goes on; so
                push_s(pending)  # does one starting with `==` or `and`)
            pending = None
        if not out_t or out_t[-1] in _STATEMENT_START:
            col = sp[2]
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
        cont = False
        col = 0
        last = None             # the type of the last token given out
        prev = None
        for tok in stream:
            if (prev is not None and prev.type == "RBRACE" and depth == 0 and pending is None
                    and tok.type not in ("_NL", "SEMICOLON", "RBRACE", "ELSE", "ELIF")):
                # `} stmt` on one line: a block ends a statement
                last = "_NL"
                yield type(prev).new_borrow_pos("_NL", "\n", prev)
            after = prev.type if prev is not None else None
            prev = tok
            if tok.type == "_NL":
                if depth == 0 and pending is None:
                    pending, cont = tok, after in CONTINUES
                continue
            if pending is not None:
                if tok.type not in ("ELSE", "ELIF") and not (cont and tok.column > col) and \
                        not _leads(tok.type, tok.value):
                    last = "_NL"
                    yield pending
                pending = None
            if last is None or last in _STATEMENT_START:
                col = tok.column
            last = tok.type
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
            if tok.type in _DECL_NEXT[str(held)]:
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


class _LexTables:
    """What :func:`_lex_lists` runs, made from Lark's basic lexer for ``grammar/aidl.lark``
    (:func:`aidl_lang.parsing.tables.data`'s ``"lexer"``): ``mres``, the lexer's compiled
    alternations of every terminal (named groups, Lark's order and priorities); ``ignore`` /
    ``newline``: terminal names skipped / counted for lines; ``keywords``: per terminal
    (``NAME``), what retypes a token as a keyword (Lark's ``UnlessCallback``): a dict text ->
    keyword when every keyword is a plain string (as in this grammar), else the whole-match
    patterns; the first-character dispatch of :meth:`regex_for`."""

    def __init__(self, lx: dict):
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


_LEXER: _LexTables | None = None
_LEXER_LOCK = threading.Lock()


def _lexer() -> _LexTables:
    """The lexer's tables, made once from the cached table data (:func:`tables.data`)."""
    global _LEXER
    if _LEXER is None:
        with _LEXER_LOCK:
            if _LEXER is None:
                _LEXER = _LexTables(tables.data()["lexer"])
    return _LEXER


def _lex_lists(text: str, keep_ignored: bool = False,
               path: str = "") -> tuple[list, list, "UnexpectedCharacters | None"]:
    """:func:`_lex_from` from the text's start to its end."""
    types, spans, err, _ = _lex_from(text, keep_ignored, path)
    return types, spans, err


def _lex_from(text: str, keep_ignored: bool = False, path: str = "",
              at: tuple = (0, 1, 0), stops: dict | None = None,
              stop_from: int = 0) -> tuple[list, list, "UnexpectedCharacters | None", int]:
    """Lark's basic lexer over ``text`` (same terminals, same order, same keyword retyping,
    same positions), as one loop: at each position the alternation of only the terminals that
    can start with the character there (:meth:`_LexTables.regex_for`; the whole alternations
    where there is no entry), since trying two dozen alternatives in turn was half the
    lexer's time.  Returns the terminal names, their :class:`Span` s (``file`` = ``path``) and
    the :class:`UnexpectedCharacters` where no terminal matched (the tokens then stop there),
    else ``None``.  No token object is made: a token's text is ``text[span.start:span.end]``
    (a str subclass with a ``__dict__`` per token was a third of the lexer's time).
    ``keep_ignored``: also the whitespace and comment tokens the parser skips (Lark's
    ``lex(dont_ignore=True)``; used by ``aidl fmt``).

    ``at``: where to start, ``(offset, line, offset of that line's start)``; ``stops``: the
    offsets (at or past ``stop_from``) at which to stop, when a token would start there
    (:func:`relex_blanked`).  The fourth value is the offset it stopped at (-1: the end, or
    the error)."""
    tb = _lexer()
    by_first, regex_for = tb.by_first, tb.regex_for
    ignore, newline, keywords = tb.ignore, tb.newline, tb.keywords
    plain = tb.plain                # terminals that are neither skipped, multi-line nor retyped
    literal = tb.literal_keywords
    skip = frozenset() if keep_ignored else ignore - newline
    (pos, line, line_start), end = at, len(text)
    if stops is None:
        stops, stop_from = {}, end + 1
    types: list = []
    spans: list = []
    push_t, push_s = types.append, spans.append
    span = _new_span
    while pos < end:
        if pos >= stop_from and pos in stops:
            return types, spans, None, pos
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
                return types, spans, UnexpectedCharacters(text, pos, line,
                                                          pos - line_start + 1), -1
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
    return types, spans, None, -1


def relex_blanked(text: str, lexed: tuple, a: int, b: int,
                  path: str = "") -> tuple[list, list, "UnexpectedCharacters | None"]:
    """The tokens of ``text`` when it differs from the text ``lexed`` was made of (its
    ``(types, spans, error)`` from :func:`_lex_lists`) only in ``[a, b)``, with every
    offset and line break kept (the recovery's blanked line, :func:`.recovery._recovered`):
    the tokens before are kept but the last two (a token's match may look a character or
    two past its end), the text is lexed again from there, and at the first token that
    starts where an old one did at or past ``b`` the old ones follow (the lexer is the same
    at the same offset of the same text).  The same lists :func:`_lex_lists` gives, without
    lexing the whole text again after each blanked line (a deleted brace in a 400-line file:
    50 lexings, 70 % of the recovery's time).  A text lexed with an error is lexed whole."""
    types, spans, err = lexed
    if err is not None:
        return _lex_lists(text, False, path)
    from bisect import bisect_left
    # from two tokens before the first old one that reaches a
    i = max(0, bisect_left(spans, a, key=lambda sp: sp.end) - 2)
    at = (0, 1, 0) if i == 0 else (spans[i].start, spans[i].line,
                                     spans[i].start - spans[i].col + 1)
    # to the first old one that starts at b or later, where the rest may follow
    j = bisect_left(spans, b, lo=i, key=lambda sp: sp.start)
    stops = {spans[k].start: k for k in range(j, len(spans))}
    new_t, new_s, new_err, stop = _lex_from(text, False, path, at, stops, b)
    if new_err is not None or stop < 0:
        return types[:i] + new_t, spans[:i] + new_s, new_err
    k = stops[stop]
    return types[:i] + new_t + types[k:], spans[:i] + new_s + spans[k:], None


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
