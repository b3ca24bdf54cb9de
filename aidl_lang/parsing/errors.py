"""Syntax-error reports: E0001/E0002 with what was expected and a hint (:func:`_report`),
E0116 for a top-level statement inside a structure, and which way a nearby ``//`` was read.
Imports :mod:`.tokens` and :mod:`.lexing`."""
from __future__ import annotations

import re

from .controls import code_point, invisible
from ..base.diagnostics import DiagnosticSink, Span
from .lexing import _lex_lists
from .tokens import TOKEN_NAMES, ParseError, UnexpectedCharacters, UnexpectedToken

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


def _error_pos(e: ParseError, text: str) -> int:
    if isinstance(e, UnexpectedToken) and e.token.type == "$END":
        return len(text)
    p = getattr(e, "pos_in_stream", None)
    if p is None and isinstance(e, UnexpectedToken):
        p = e.token.start_pos
    return len(text) if p is None else p


# the words of grammar/aidl.lark no name may be (tests/test_checks_messages111k.py holds
# them to the grammar)
KEYWORDS = frozenset({"and", "as", "assert", "def", "elif", "else", "for", "if", "import", "in",
                      "not", "or", "param"})


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
    named = re.match(r"\s*(\w+)\s*=(?!=)", text[line_start:line_start + 200])
    if named is not None and named.group(1) in KEYWORDS and pos <= line_start + named.end():
        # run ef's ticket sign: `or = Circle(...)` ("outer ring") was told "use `==` for an
        # equation constraint" at the `=`, or of a leading `or`
        kw = named.group(1)
        at = line_start + named.start(1)
        kcol = at - line_start + 1
        sink.error("E0001", f"`{kw}` is a keyword: it cannot name a value",
                   Span(path, line, kcol, line, kcol + len(kw), at, at + len(kw)),
                   f"choose another name: a word that says what it is, or `{kw}_`; the "
                   "keywords are "
                   + ", ".join(f"`{k}`" for k in sorted(KEYWORDS)))
        return
    exp = getattr(e, "expected", None) or ()
    before = text[line_start:pos].rstrip()
    if tok.type == "IN" and not re.search(r"\bfor\s+\w+$", before) \
            and not re.search(r"\bunits\s*=?$", before):
        # run gn: `if k in hits`, Python's membership test: "unexpected `in`", no hint
        lhs = re.search(r"(\w+)$", before)
        rhs = re.match(r"\s*in\s+([\w.]+)", text[pos:pos + 200])
        x, xs = (lhs.group(1), rhs.group(1)) if lhs and rhs else ("k", "hits")
        hint = (f"AIDL has no `in` test: count the matches, `len([v for v in {xs} if v == "
                f"{x}]) > 0` (`== 0` for not in)")
    elif tok.type == "LPAR" and re.search(r"\bfor$", before):
        # run gp: `[... for (x, y) in rhomb_pts(60 deg)]`, "expected a name", no hint
        hint = ("a `for` takes one name, not a tuple: `for p in pts`, then `p[0]` and `p[1]` "
                "(a point's `p.x` and `p.y`)")
    elif tok.type == "NAME" and not _open_paren(text, pos) and ("_NL" in exp or "$END" in exp) \
            and re.search(r"[)\]\w\"']$", before) \
            and not re.search(r"\b(for|if|elif|else|assert|def|solid|hole|cut|drawing|assembly)"
                              r"\s*$", before):
        # run gp: `for i in range(1, 4) { RightOf(...) AlignBottom(...) }`: "expected end of
        # file, `+` or `-`, ..." six times and no hint
        hint = (f"one statement per line: break the line before `{tok}`, or write `;` "
                "between the two statements")
    elif tok.type in ("NAME", "NUMBER", "STRING", "FSTRING", "LPAR", "LSQB") and "COMMA" in exp \
            and _open_paren(text, pos):
        hint = f"a `,` is probably missing before `{tok}`"
    elif tok.type == "FSTRING" and re.match(r"assert\b", head):
        # (run t: `assert ..., f"... {x} ..."`: the message is said as written; E0405 shows
        # the values the condition reads)
        hint = ("an assert's message is a plain string (\"sail 70 wide\"): when the assert "
                "fails, E0405 shows the value of each name and member it reads")
    elif (str(tok) == "=" and re.match(r"\s*units\s*$", head)) or (
            tok.type == "IN" and re.match(r"\s*units\s*=\s*$", head)):
        hint = "`units` is a statement without `=`: `units mm` (or `in`, `cm`, ...)"
    elif str(tok) == "=" :
        hint = "use `==` for an equation constraint, `=` only to name a value"
    elif str(tok) == "{" :
        hint = "a structure is written `solid NAME { ... }`"
    elif tok.type == "_NL":
        # (an unclosed `(` is reported at the bracket instead: newlines inside it are dropped)
        hint = ("the statement ended early: an operand is missing before the line break; to "
                "go on with an expression on the next line, end this line with its operator "
                "(or `,`) and indent the next one deeper, or wrap it in `( )`")
    lead = re.match(r"\s*(\*\*|//|==|!=|<=|>=|[-+*/%<>]|and\b|or\b)",
                    text[line_start:line_start + 200])
    if hint is None and lead is not None and line > 1 and text[:line_start].strip():
        # run db: `assert (a) - (b)` then `- bar_w == 28 mm, "..."` on the next line: the
        # statement above ended at its line break, and the error fell on the `,`
        op = lead.group(1)
        hint = (f"line {line - 1} ended its statement at the line break, so this line's "
                f"leading `{op}` starts a new one: end line {line - 1} with the `{op}` (and "
                "indent this line deeper), or wrap the whole expression in `( )`")
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
_TOP_ONLY = {"PARAM": "param", "UNITS": "units", "IMPORT": "import"}


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
