"""Characters that make source text read otherwise than it runs ("Trojan Source", Boucher and
Anderson, 2021): the bidirectional embeddings, overrides and isolates (U+202A-U+202E,
U+2066-U+2069), which reorder how the rest of a line is displayed, and the line and
paragraph separators (U+2028, U+2029), which some editors show as a line break the compiler
does not count (lines end at LF, CR LF and a lone CR only: :data:`.diagnostics.LINE_BREAK`).

In code they cannot start a token (``E0002``, which names the code point); in a comment or a
string they would pass without a word, so :func:`check_controls` warns ``W0112`` at each
one, located with a caret, the code point named, and a fix that deletes it.  When a
diagnostic's source line is shown, each of them is shown as U+FFFD, one column wide, so the
terminal does not reorder the line under its caret (:func:`.diagnostics.shown_line`)."""
from __future__ import annotations

import re
import unicodedata

from ..base.diagnostics import CONTROLS, DiagnosticSink, Fix, Span

def code_point(ch: str) -> str:
    """``U+202E RIGHT-TO-LEFT OVERRIDE``: the character's code point and Unicode name."""
    return f"U+{ord(ch):04X} {unicodedata.name(ch, 'UNNAMED CHARACTER')}"


def invisible(ch: str) -> bool:
    """A character that shows nothing of its own, or moves what is around it: a control, a
    format character (bidi marks, zero-width joiners), a line or paragraph separator, a
    space other than the plain one."""
    return bool(ch) and (unicodedata.category(ch) in ("Cc", "Cf", "Zl", "Zp", "Co", "Cn")
                         or (unicodedata.category(ch) == "Zs" and ch != " "))


def _contexts(masked: str):
    """``(offset, "comment" | "string" | "code")`` of each :data:`CONTROLS` character of
    ``masked`` (the source with its ``//`` comments turned into ``#`` ones, same offsets:
    :func:`.parser.mask_comments`)."""
    spots = [m.start() for m in CONTROLS.finditer(masked)]
    if not spots:
        return
    k, n, state, quote = 0, len(masked), "code", ""
    want = iter(spots)
    nxt = next(want, None)
    while k < n and nxt is not None:
        ch = masked[k]
        if k == nxt:
            yield k, "comment" if state in ("line", "block") else state
            nxt = next(want, None)
        if state == "code":
            if ch in "\"'":
                state, quote = "string", ch
            elif ch == "#":
                state = "line"
            elif masked.startswith("/*", k):
                state = "block"
                k += 1
        elif state == "string":
            if ch == "\\":
                k += 1
                if k == nxt:
                    yield k, "string"
                    nxt = next(want, None)
            elif ch == quote or ch == "\n":
                state = "code"
        elif state == "line":
            if ch == "\n":
                state = "code"
        elif state == "block" and masked.startswith("*/", k):
            state = "code"
            k += 1
        k += 1


def check_controls(source: str, masked: str, path: str, sink: DiagnosticSink) -> None:
    """W0112 for each bidirectional control or line separator in a comment or a string of
    ``source`` (``masked``: :func:`.parser.mask_comments` of it); those in code are the
    lexer's ``E0002``."""
    if not CONTROLS.search(source):
        return
    starts = [0] + [m.end() for m in re.finditer(r"\r\n|\r|\n", source)]
    import bisect
    for pos, where in _contexts(masked):
        if where == "code":
            continue
        ch = source[pos]
        line = bisect.bisect_right(starts, pos)
        col = pos - starts[line - 1] + 1
        span = Span(path, line, col, line, col + 1, pos, pos + 1)
        if ch in "\u2028\u2029":
            why = ("an editor may show a line break there that the compiler does not count "
                   "(lines end at LF, CR LF and CR), so the line numbers it shows and the "
                   "diagnostics' would differ")
        else:
            why = ("it reorders how the rest of the line is displayed, so the text may not "
                   "read as it runs (\"Trojan source\")")
        sink.warning("W0112", f"{code_point(ch)} in a {where}: {why}", span,
                     hint="delete it (the suggested fix); it draws nothing and means nothing "
                          "to the compiler", fix=Fix(span, ""))
