"""``aidl fmt``: the canonical layout of an AIDL file.

The formatter works on the token stream of ``grammar/aidl.lark`` (the parser's copy of
Lark's basic lexer, :func:`aidl_lang.parsing.lexing._lex`, with comments and whitespace kept) rather
than on the AST, so every comment survives where it was:

* one statement per line, blocks indented by 4 spaces, ``{`` at the end of its line and ``}``
  on its own line (``} else {`` joined); ``;`` separators become line breaks;
* at most one blank line in a row, none after ``{``, before ``}`` or at the ends of the file;
* one space around binary operators, ``=`` of assignments and ``->``; none around the ``=`` of a
  keyword argument or parameter default, after ``(``/``[``, before ``)``/``]``/``,``, around
  ``.``, or after a unary ``-``; one space after ``,`` and ``:``;
* numbers with a unit: one space before a word unit (``10 mm``, ``30 deg``), ``°`` attached;
* line breaks inside ``()`` and ``[]`` are kept; a continuation line is aligned one column
  after its open bracket, or indented 4 more than the bracket's line when the bracket ends it;
  a line after a ``,``, an operator or ``=`` outside brackets (an assert's message, a
  condition broken after ``and``) is indented 4 more than its statement;
* trailing comments of consecutive lines are aligned two columns after the longest code.

The result is checked before it is returned: it must parse to the same AST (spans ignored) and
carry the same comments, or :class:`FormatError` is raised (the file is never rewritten then).
Formatting is idempotent: ``format_source(format_source(s)) == format_source(s)``.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from .. import ast as A
from ..base.diagnostics import LINE_BREAK, DiagnosticSink
from ..parser import mask_comments, parse
from ..parsing.lexing import CONTINUES, _lex

INDENT = 4



def _tokens(masked: str) -> list:
    """Every token of ``masked`` (comments masked as ``#``), whitespace and comments included,
    without the post-lexer (it drops newlines); the text has parsed, so it lexes."""
    tokens, error = _lex(masked, keep_ignored=True)
    if error is not None:
        raise error
    return tokens


class FormatError(Exception):
    """The source cannot be formatted: ``sink`` holds its syntax errors."""

    def __init__(self, sink: DiagnosticSink):
        super().__init__("; ".join(d.message for d in sink.items))
        self.sink = sink


class FormatterBug(RuntimeError):
    """The formatted text would not mean the same as the source (a bug in the formatter); the
    source is left as it is."""


@dataclass(eq=False)
class _Item:
    """A token or comment to write, with its source offsets."""
    kind: str          # token type, or COMMENT / BLOCK_COMMENT
    text: str          # text as it will be written
    start: int
    end: int


KEYWORDS = {"UNITS", "IMPORT", "AS", "PARAM", "DEF", "FOR", "IN", "IF", "ELSE", "ELIF", "AND", "ASSERT",
            "OR", "NOT"}
OPEN = {"LPAR": "RPAR", "LSQB": "RSQB"}
CLOSE = {"RPAR", "RSQB"}
# after these an ADD_OP is unary
_UNARY_AFTER = {None, "LPAR", "LSQB", "COMMA", "EQUAL", "COLON", "COMP_OP", "ADD_OP", "MUL_OP",
                "POW", "LBRACE", "SEMICOLON", "__ANON_0", "UNARY"} | KEYWORDS
_VALUE_END = {"NAME", "NUMBER", "STRING", "FSTRING", "RPAR", "RSQB"}
_NUM_RE = re.compile(r"^(?P<num>[0-9.eE+-]+?)[ \t]*(?P<unit>[A-Za-z]+|°)?$")


def _number(text: str) -> str:
    m = _NUM_RE.match(text)
    if not m or not m.group("unit"):
        return text.strip()
    unit = m.group("unit")
    return m.group("num") + (unit if unit == "°" else " " + unit)


def _items(source: str) -> list[_Item]:
    masked = mask_comments(source)
    out = []
    for tok in _tokens(masked):
        if tok.type in ("WS", "_NL"):
            continue
        s, e = tok.start_pos, tok.end_pos
        text = source[s:e]
        if tok.type == "COMMENT":
            text = text.rstrip()
        elif tok.type == "NUMBER":
            text = _number(text)
        out.append(_Item(tok.type, text, s, e))
    return out


def _space(prev: _Item, cur: _Item, prev_kind: str | None, in_parens: bool) -> str:
    """The separator between two items on one line (``prev_kind``: the previous token's kind,
    ``UNARY`` for a unary sign)."""
    p, c = prev_kind, cur.kind
    if prev.kind == "BLOCK_COMMENT" or c == "BLOCK_COMMENT":
        return " "
    if p in OPEN or c in CLOSE or c in ("COMMA", "COLON", "DOT") or p == "DOT":
        return ""
    if p == "UNARY":
        return ""
    if c == "LPAR" and p in ("NAME", "RPAR", "RSQB", "STRING"):
        return ""
    if c == "LSQB" and p in ("NAME", "RPAR", "RSQB", "STRING", "FSTRING"):
        return ""
    if (c == "EQUAL" or p == "EQUAL") and in_parens:
        return ""
    return " "


def newline_of(text: str) -> str:
    """The line ending ``aidl fmt`` writes for ``text``: its first line break's (CR LF, CR or
    LF: :data:`aidl_lang.base.diagnostics.LINE_BREAK`), LF when it has none."""
    m = LINE_BREAK.search(text)
    return m.group() if m else "\n"


def format_file_text(text: str, path: str = "<stdin>", newline: str | None = None) -> str:
    """:func:`format_source` for a file's whole text, keeping what the file had: a UTF-8 byte
    order mark stays, and every line ends as its first line does (CR LF, CR or LF:
    :func:`newline_of`; ``newline`` given, as that says), so a file of mixed line endings
    comes out with one kind.  The program is read with the line breaks the compiler reads
    (``aidl check``'s: a lone CR ends a line, and a ``#`` comment)."""
    bom = text.startswith("\ufeff")
    if bom:
        text = text[1:]
    if newline is None:
        newline = newline_of(text)
    out = format_source(text, path)
    if newline != "\n":
        out = out.replace("\n", newline)
    return ("\ufeff" if bom else "") + out


def format_source(source: str, path: str = "<stdin>") -> str:
    """Return the canonical layout of ``source`` (AIDL text).

    Raises :class:`FormatError` (with the syntax errors in ``.sink``) if ``source`` does not
    parse, :class:`FormatterBug` if the result would not parse to the same AST with the same
    comments (checked on every call).
    """
    from ..pipeline import run_deep
    # on the compiler's deep-stack thread: what `aidl check` compiles (a 400-term `**` chain,
    # a 600-term conditional) formats too
    return run_deep(lambda: _format(source, path))


def _format(source: str, path: str) -> str:
    source = source.replace("\r\n", "\n").replace("\r", "\n")
    sink = DiagnosticSink()
    before = parse(source, path, sink)
    if sink.has_errors:
        raise FormatError(sink)
    try:
        items = _items(source)
        out = _layout(source, items)
        # the safety net: same program, same comments
        sink2 = DiagnosticSink()
        after = parse(out, path, sink2)
        same = (not sink2.has_errors and dump(after) == dump(before)
                and comments(out) == comments(source))
    except RecursionError:
        # an expression too deep to walk (a 20,000-term `1+1+...`): the statement `aidl
        # check` names, with its error
        from ..pipeline import _deep_span
        st = _deep_statement(before.stmts)
        sink.error("E0302", "expression nested too deeply",
                   st.span if st is not None else _deep_span(None, path, source),
                   hint="split it into named constants")
        raise FormatError(sink) from None
    if not same:
        raise FormatterBug(f"formatting `{path}` would change its program or comments")
    return out


def _deep_statement(stmts: list):
    """The innermost of ``stmts`` (or of their bodies) whose AST is too deep to walk
    (:func:`dump` raises RecursionError), or None."""
    for st in stmts:
        inner = [x for name in ("body", "orelse")
                 if isinstance(b := getattr(st, name, None), A.Block) for x in b.stmts]
        found = _deep_statement(inner) if inner else None
        if found is not None:
            return found
        try:
            dump(st)
        except RecursionError:
            return st
    return None


def _layout(source: str, items: list[_Item]) -> str:
    lines: list[list] = []          # [indent, code, trailing comment | None]
    level = 0                       # block depth
    brackets: list[tuple[str, int, int]] = []   # (close type, continuation col, opener indent)
    prev: _Item | None = None       # the previous item (comments included)
    code_kind: str | None = None    # kind of the previous token; a unary ADD_OP is "UNARY"
    force_break = True              # the next item starts a new line
    no_blank = True                 # no blank line before the next line
    for i, it in enumerate(items):
        nl = source.count("\n", prev.end, it.start) if prev is not None else 0
        k = it.kind
        if k == "SEMICOLON" and not brackets:      # a statement separator: a line break
            force_break = True
            code_kind = "SEMICOLON"
            prev = it
            continue
        if (k == "COMMENT" and nl == 0 and lines and lines[-1][1] and lines[-1][2] is None
                and prev is not None):
            lines[-1][2] = it.text                  # a trailing comment
            force_break = True
            prev = it
            continue
        # does this item start a new line?
        if (k in ("ELSE", "ELIF") and not brackets and prev is not None
                and prev.kind not in ("COMMENT", "BLOCK_COMMENT") and not force_break):
            brk = False             # `} else`, or a ternary continued on the next line
        elif k == "RBRACE" or prev is None or force_break:
            brk = True
        elif prev.kind in ("LBRACE", "RBRACE", "COMMENT"):
            brk = True
        else:
            brk = nl > 0
        if k == "RBRACE":
            level = max(0, level - 1)
        if brk:
            if brackets:
                close, col, opener = brackets[-1]
                ind = opener if k == close else col
            else:               # a line after a `,` goes on the statement: one step in
                ind = level * INDENT + (INDENT if code_kind in CONTINUES else 0)
            if nl >= 2 and not no_blank and k != "RBRACE" and lines:
                lines.append([0, "", None])
            lines.append([ind, it.text, None])
        else:
            lines[-1][1] += _space(prev, it, code_kind, bool(brackets)) + it.text
        force_break = False
        no_blank = False
        if k == "ADD_OP" and (code_kind in _UNARY_AFTER or (brk and not brackets)):
            kind_now = "UNARY"
        else:
            kind_now = k
        if k in OPEN:
            ind = lines[-1][0]
            nxt = items[i + 1] if i + 1 < len(items) else None
            hanging = nxt is None or "\n" in source[it.end:nxt.start] or nxt.kind == "COMMENT"
            col = ind + INDENT if hanging else ind + len(lines[-1][1])
            brackets.append((OPEN[k], col, ind))
        elif k in CLOSE and brackets:
            brackets.pop()
        elif k == "LBRACE":
            level += 1
            no_blank = True
            force_break = True
        elif k == "RBRACE":
            no_blank = False
        elif k == "COMMENT":
            force_break = True
        prev = it
        if k not in ("COMMENT", "BLOCK_COMMENT"):
            code_kind = kind_now
    return _render(lines)


def _render(lines: list[list]) -> str:
    text_lines: list[str] = []
    n = len(lines)
    i = 0
    # align trailing comments in runs of consecutive lines that have them
    widths = [ind + len(code) for ind, code, _ in lines]
    while i < n:
        if lines[i][2] is None:
            i += 1
            continue
        j = i
        while j < n and lines[j][2] is not None and lines[j][1]:
            j += 1
        col = max(widths[i:j]) + 2
        for k in range(i, j):
            lines[k][2] = " " * (col - widths[k]) + lines[k][2]
        i = max(j, i + 1)
    for ind, code, com in lines:
        s = (" " * ind + code if code else "") + (com or "")
        text_lines.append(s.rstrip())
    while text_lines and not text_lines[-1]:
        text_lines.pop()
    return "\n".join(text_lines) + "\n" if text_lines else ""


# ----------------------------------------------------------------- checks used by tests too
def dump(node) -> object:
    """A span-free nested-tuple form of an AST node, for comparing programs."""
    if isinstance(node, A.Program):
        return ("Program", tuple(dump(s) for s in node.stmts))
    if isinstance(node, A.Node):
        fields = []
        for name in type(node).__slots__:
            if name == "span" or name.endswith("_span"):
                continue
            fields.append((name, dump(getattr(node, name))))
        return (type(node).__name__, tuple(fields))
    if isinstance(node, (list, tuple)):
        return tuple(dump(x) for x in node)
    return node


_COMMENT_RE = re.compile(r"#[^\n]*|/\*.*?\*/", re.S)


def comments(source: str) -> list[str]:
    """The comments of ``source`` in order, as written (trailing spaces dropped)."""
    masked = mask_comments(source)
    out = []
    for tok in _tokens(masked):
        if tok.type in ("COMMENT", "BLOCK_COMMENT"):
            out.append(source[tok.start_pos:tok.end_pos].rstrip())
    return out


# ----------------------------------------------------------------- the command
def main(files: list[str], check: bool = False) -> int:
    """``aidl fmt FILE... [--check]``; ``-`` reads stdin and writes stdout.

    Returns the exit status: 0 all formatted (or, with ``check``, nothing would change), 1 a
    file has syntax errors (printed; the file is not touched) or, with ``check``, would change;
    3 the formatter found it would change a program's meaning (a bug; nothing written).
    Files are rewritten atomically (a temporary file beside it, then renamed:
    :func:`aidl_lang.output.writers.write.edit_program`: a link's target, never over a
    read-only file, a FIFO or a device) and only if their text changes.
    """
    import sys
    from pathlib import Path

    from ..base.diagnostics import render_text
    from ..output.writers.write import WriteError, edit_program
    from ..library.sources import SourceRefused, read_program

    status = 0
    for f in files:
        try:
            if f == "-":
                src = sys.stdin.read()
            else:
                # as `aidl check` reads a program: a regular file only (a FIFO or /dev/zero is
                # refused, E0004, not waited on), at most 1000000 bytes, UTF-8; the byte order
                # mark and CR / CRLF kept as they are
                src = read_program(f, keep_bom=True)
        except SourceRefused as e:
            print(render_text(e.diagnostic(f), {}), file=sys.stderr)
            print(f"aidl: `{f}` not formatted: it cannot be read", file=sys.stderr)
            status = max(status, 1)
            continue
        except (OSError, UnicodeDecodeError) as e:        # stdin
            print(f"aidl: error: cannot read `{f}`: {getattr(e, 'strerror', None) or e}",
                  file=sys.stderr)
            status = max(status, 1)
            continue
        if "\0" in src:
            i = src.index("\0")
            line = src.count("\n", 0, i) + 1
            col = i - (src.rfind("\n", 0, i) + 1) + 1
            print(f"aidl: `{f}` not formatted: it contains a NUL byte (line {line}, column "
                  f"{col}); the file is left as it is", file=sys.stderr)
            status = max(status, 1)
            continue
        try:
            out = format_file_text(src, "<stdin>" if f == "-" else f)
        except FormatterBug as e:
            print(f"aidl: internal error: {e}; the file is left as it is. This is a bug in "
                  "aidl fmt, please report it with the input file.", file=sys.stderr)
            status = 3
            continue
        except FormatError as e:
            for d in e.sink.items:
                print(render_text(d, e.sink.sources), file=sys.stderr)
                print(file=sys.stderr)
            print(f"aidl: `{f}` not formatted: it has errors", file=sys.stderr)
            status = max(status, 1)
            continue
        if f == "-":
            if check:
                status = status or int(out != src)
            else:
                sys.stdout.write(out)
            continue
        if out == src:
            continue
        if check:
            print(f"would reformat {f}")
            status = max(status, 1)
            continue
        # a symlink stays a link: its target is rewritten; the mode is kept; only a regular
        # file is replaced (one swapped for a FIFO or a device since it was read is left)
        try:
            edit_program(Path(f), out.encode("utf-8"))
        except WriteError as e:
            print(f"aidl: error: {e}", file=sys.stderr)
            status = max(status, 1)
            continue
        print(f"formatted {f}")
    return status
