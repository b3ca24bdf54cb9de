"""Statement-level error recovery: each syntax error is reported, its logical line blanked
(braces kept) and the text parsed again (:func:`_recovered`); when that gives up, each
top-level piece that parses on its own is kept (:func:`_recover_by_pieces`).
Imports :mod:`.tokens`, :mod:`.comments`, :mod:`.lalr` and :mod:`.errors`."""
from __future__ import annotations

import re

from ..base.diagnostics import DiagnosticSink
from .comments import _ANY_BRACKET, _BRACKET_STEP, _STRINGS
from .errors import _error_pos, _report, _slash_hint
from .lalr import _Builder, _run_lalr
from .lexing import _lex_lists, relex_blanked
from .tokens import MAX_ERRORS, UnexpectedCharacters, UnexpectedToken

def _blank_logical_line(text: str, pos: int) -> str:
    """:func:`_blank_range`'s text."""
    start, end, seg = _blank_range(text, pos)
    return text[:start] + seg + text[end:]


def _blank_range(text: str, pos: int) -> tuple[int, int, str]:
    """Blank the logical line (bracket-balanced) around offset ``pos``, keeping braces/newlines:
    ``(start, end, blanked)``, ``text[start:end]`` to be replaced by ``blanked``, of its length.

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
    return start, end, seg


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
    lexed = _lex_lists(text, False, builder.path)     # the tokens of the text about to parse
    for _attempt in range(MAX_ERRORS + 1):
        builder.failed.clear()
        try:
            return _run_lalr(text, "start", lexed), text
        except (UnexpectedToken, UnexpectedCharacters) as e:
            pos = _error_pos(e, text)
            if pos in seen or len(seen) >= MAX_ERRORS:
                return None, text
            seen.add(pos)
            _report(e, text, path, pos, sink)
            _slash_hint(sink, slashes, text, pos)
            if pos >= len(text.rstrip()):
                return None, text
            start, end, seg = _blank_range(text, pos)
            text = text[:start] + seg + text[end:]
            # lexed again only from the blanked line to where the old tokens resume
            lexed = relex_blanked(text, lexed, start, end, builder.path)
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
