"""Where the brackets of a file do not balance (issue 28): after a failed parse, each bracket
never closed or closing nothing is reported at the line where it most likely went wrong (by
indentation and by how many problems each reading leaves), in place of the parser's errors that
follow from it.  Imports :mod:`.tokens` and :mod:`.lexing`."""
from __future__ import annotations

from ..base.diagnostics import DiagnosticSink, Label, Span
from .lexing import _lex_lists
from .tokens import MAX_BRACKET_DECISIONS, MAX_ERRORS

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
