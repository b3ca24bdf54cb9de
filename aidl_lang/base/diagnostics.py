"""One diagnostic model for every pipeline stage, with text (rustc style) and JSON renderings.

A :class:`Diagnostic` has a stable ``code`` (see :mod:`aidl_lang.base.codes`), a severity, a message,
labelled source spans, a hint and an optional suggested fix.  Stages never raise Python
exceptions at the user: they append diagnostics to a :class:`DiagnosticSink`; a stage that
cannot go on raises :class:`Abort` after recording why.
"""
from __future__ import annotations

import functools
import os
import re
from collections import namedtuple
from collections.abc import Callable, Iterable
from pathlib import Path

from .records import Compared

# the bundled standard library (``import "std/NAME.aidl"``): beside the package in a source
# checkout, inside it in an installed wheel (aidl_lang.library.sources reads it from here)
# The package's own folder (a link to the repository's ``stdlib/`` in a checkout, the files in
# a wheel), resolved: never ``site-packages/stdlib``, which would be another package's
STDLIB = (Path(__file__).resolve().parents[1] / "stdlib").resolve()


# A line break, as the Language Server Protocol and every editor count lines: CR LF, a lone CR,
# or LF (not Python's ``str.splitlines``, which also breaks at form feeds, vertical tabs and
# U+2028).  The lexer, the line and column of every diagnostic, ``aidl fmt``, the language
# server's positions and edits and the editors' grammars all end lines here: what an editor
# shows as a line is a line to the compiler (a ``#`` comment ends at a lone CR too).
LINE_BREAK = re.compile(r"\r\n|\r|\n")

# Characters that make a line display otherwise than it reads (bidirectional embeddings,
# overrides and isolates) or that an editor may show as a line break the compiler does not
# count (U+2028, U+2029): warned in comments and strings (W0112, aidl_lang.parsing.controls), and
# shown as U+FFFD, one column wide, when a diagnostic prints its source line
CONTROLS = re.compile("[\u202a-\u202e\u2066-\u2069\u2028\u2029]")
_SHOWN = {c: "\ufffd" for c in [*range(0x202A, 0x202F), *range(0x2066, 0x206A), 0x2028, 0x2029]}


def shown_line(line: str) -> str:
    """``line`` as a diagnostic prints it: each character of :data:`CONTROLS` as U+FFFD (a
    right-to-left override would reorder the rest of the line under its caret)."""
    return line.translate(_SHOWN) if CONTROLS.search(line) else line


def as_lf(text: str) -> str:
    """``text`` with each lone CR (a line break of its own) as LF: the same length, so every
    offset, line and column holds, and every line break now ends in LF (a CR LF's CR stays,
    blank space to the lexer).  What the parser, the pipeline and the language server read."""
    return _LONE_CR.sub("\n", text) if "\r" in text else text


_LONE_CR = re.compile(r"\r(?!\n)")


def split_lines(text: str) -> list[str]:
    """The lines of ``text`` without their breaks (:data:`LINE_BREAK`); ``""`` has one line."""
    return LINE_BREAK.split(text)


@functools.cache
def _stdlib_roots() -> tuple[str, ...]:
    roots = {str(STDLIB), str(STDLIB.resolve())}
    return tuple(r.rstrip(os.sep) + os.sep for r in roots)


def in_stdlib(file: str | None) -> bool:
    """True when ``file`` (a span's file) is a file of the bundled standard library."""
    return bool(file) and any(file.startswith(r) for r in _stdlib_roots())


def shown_path(file: str) -> str:
    """``file`` as a message shows it: a standard-library file as the program imports it,
    ``std/joints.aidl`` (never the install's absolute path: issue 61), any other unchanged."""
    for r in _stdlib_roots():
        if file.startswith(r):
            return "std/" + file[len(r):].replace(os.sep, "/")
    return file


class Span(namedtuple("Span", "file line col end_line end_col start end", defaults=(0, 0))):
    """A source range. Lines and columns are 1-based; ``end_col`` is exclusive; offsets 0-based.

    Immutable, compared and hashed by its fields.  A named tuple rather than a record because
    the parser makes one per token and per node: its tokens carry their :class:`Span` as
    ``pos`` and a node's span is made in one call from the first and the last child's
    (``tuple.__new__(Span, ...)``, no Python ``__init__``: ~9% of a parse, issue 12)."""

    __slots__ = ()

    def to_json(self) -> dict:
        return {"file": self.file, "line": self.line, "column": self.col,
                "end_line": self.end_line, "end_column": self.end_col,
                "start": self.start, "end": self.end}

    def cover(self, other: "Span | None") -> "Span":
        if other is None or other.file != self.file:
            return self
        a, b = (self, other) if self.start <= other.start else (other, self)
        e = self if self.end >= other.end else other
        return Span(self.file, a.line, a.col, e.end_line, e.end_col, a.start, e.end)


class Label(Compared):
    """A secondary span with a message, shown under the primary caret (rustc's labels)."""
    __slots__ = ("span", "message", "primary")

    def __init__(self, span: Span, message: str = "", primary: bool = True):
        self.span = span
        self.message = message
        self.primary = primary


class Fix(Compared):
    """A suggested edit: replace the text at ``span`` with ``replacement``."""
    __slots__ = ("span", "replacement")

    def __init__(self, span: Span, replacement: str):
        self.span = span
        self.replacement = replacement

    def to_json(self) -> dict:
        return {"span": self.span.to_json(), "replacement": self.replacement}


class Diagnostic(Compared):
    """One located problem: code (aidl_lang.base.codes), message, span, severity, hint, labels, suggestions, fix."""
    __slots__ = ("code", "message", "span", "severity", "hint", "labels", "suggestions", "fix")

    def __init__(self, code: str, message: str, span: Span | None = None, severity: str = "error",
                 hint: str | None = None, labels: list[Label] | None = None,
                 suggestions: list[str] | None = None, fix: Fix | None = None):
        self.code = code
        self.message = message
        self.span = span
        self.severity = severity  # "error" | "warning" | "note"
        self.hint = hint
        self.labels = [] if labels is None else labels
        self.suggestions = [] if suggestions is None else suggestions
        self.fix = fix

    @property
    def is_error(self) -> bool:
        return self.severity == "error"

    def reword(self, word: Callable[[str | None], str | None]) -> None:
        """Pass the message, the hint and every label's message through ``word`` in place
        (the command line's phrases worded for agents or for a form); the rendered text
        follows."""
        self.message = word(self.message)
        self.hint = word(self.hint)
        for lab in self.labels:
            lab.message = word(lab.message)

    def to_json(self, sources: "dict[str, str] | None" = None) -> dict:
        return {
            "code": self.code, "severity": self.severity, "message": self.message,
            "span": self.span.to_json() if self.span else None,
            "labels": [{"span": l.span.to_json(), "message": l.message, "primary": l.primary}
                       for l in self.labels],
            "hint": self.hint, "suggestions": self.suggestions,
            "fix": self.fix.to_json() if self.fix else None,
            "rendered": render_text(self, sources or {}, color=False),
        }


class Abort(Exception):
    """Raised by a stage after it recorded the error diagnostics that stop the pipeline."""


class EvalError(Exception):
    """A located error found while evaluating (interpreter, operations): ``code`` (see
    :mod:`aidl_lang.base.codes`), message, span, hint, suggested fixes and extra labels.  The
    interpreter turns it into an error :class:`Diagnostic` and skips the statement."""

    def __init__(self, code: str, message: str, span: Span | None, hint: str | None = None,
                 suggestions=None, labels=None):
        super().__init__(message)
        self.code, self.message, self.span, self.hint = code, message, span, hint
        self.suggestions = suggestions or []
        self.labels = labels or []


class DiagnosticSink:
    """Collects diagnostics; remembers source text per file for rendering.

    A diagnostic located in another file than the program compiled (``main``: a template of
    the standard library or of an imported file) is moved to the call in the program
    (:func:`at_call_site`): to the live call stack ``calls`` while the interpreter runs a
    template instance or loads an import; later (the solve, the shape checks) to the calls
    the stage gives, else to the instance the message names (``owners``), else to the first
    call of the template (or import of the file) whose text holds it (``callers``)."""

    def __init__(self) -> None:
        self.items: list[Diagnostic] = []
        self.sources: dict[str, str] = {}
        self._keys: set = set()      # (code, span, message) of ``items``, when ``_indexed`` long
        self._indexed = 0
        self.main: str | None = None                  # the file of the program compiled
        # the template instances and imports being run, outermost first: (what, call span),
        # what as a message names it ("`spur_gear`", "the file `lib.aidl`")
        self.calls: list[tuple[str, Span]] = []
        # (file, start, end, calls): a template's text (an imported file's: end -1) and the
        # calls of its first instance (import)
        self.callers: list[tuple[str, int, int, tuple]] = []
        self._called: set = set()                    # (file, start, end) of ``callers``
        # the path of each instance of a template of another file -> its calls: a later
        # stage's diagnostic naming a structure inside one is at that instance's call
        self.owners: dict[str, tuple] = {}

    def called(self, span: Span | None, calls, owner: str | None = None) -> None:
        """Record ``calls`` (outermost first) as how the text at ``span`` (a template's
        definition; an imported file: ``Span(file, ...)`` with ``end`` -1) was first reached
        from the program, unless already known or in the program's own file; ``owner``: the
        path of the instance they made (``plate.b``)."""
        if span is None or span.file == self.main or not calls or not span.file:
            return
        if owner is not None:
            self.owners[owner] = tuple(calls)
        key = (span.file, span.start, span.end if span.end > span.start else -1)
        if key not in self._called:      # once per template (a loop makes thousands)
            self._called.add(key)
            self.callers.append((*key, tuple(calls)))

    def follow(self, other: "DiagnosticSink") -> None:
        """Place diagnostics as ``other`` does (its program's file and the template calls it
        recorded): a later stage's own sink, such as a preview's deferred shape checks."""
        self.main, self.callers, self._called = other.main, other.callers, other._called
        self.owners = other.owners

    def instance_of(self, d: Diagnostic) -> tuple:
        """The calls that reach ``d``'s span in another file: those of the instance its
        message names (a structure inside an instance of the template holding the span:
        `plate.b.eye`), else the template's first call (:meth:`callers_of`)."""
        first = self.callers_of(d.span)
        if not first or not self.owners:
            return first
        for name in re.findall(r"`([A-Za-z_][\w.\[\]]*)`", d.message):
            parts = name.split(".")
            for k in range(len(parts), 0, -1):
                calls = self.owners.get(".".join(parts[:k]))
                if calls is not None and calls[-1][0] == first[-1][0]:
                    return calls
        return first

    def callers_of(self, span: Span) -> tuple:
        """The calls (outermost first) that reach ``span`` in another file: the innermost
        recorded template text holding it, else its file's import; () when none."""
        best, size = (), None
        for file, a, b, calls in self.callers:
            if file == span.file and a <= span.start and (b < 0 or span.start < b):
                n = float("inf") if b < 0 else b - a
                if size is None or n < size:
                    best, size = calls, n
        return best

    def add(self, d: Diagnostic, calls=None) -> Diagnostic:
        """Append ``d`` unless a diagnostic with the same code, span and message is already
        there (found by key: a flood of 100,000 errors stays linear).  A diagnostic located
        in another file than ``main`` is first moved to the program's call
        (:func:`at_call_site`) by ``calls`` (outermost first) when given, else by the live
        call stack, else by the instance its message names (:meth:`instance_of`)."""
        if d.fix is None and d.suggestions and d.span is not None and d.code in ("E0101", "E0102", "E0103"):
            d.fix = Fix(d.span, d.suggestions[0])      # the span is exactly the misspelt name
        if self.main and d.span is not None and d.span.file and d.span.file != self.main:
            at_call_site(d, calls or self.calls or self.instance_of(d), self.main)
        if self._indexed != len(self.items):            # ``items`` was edited in place
            self._keys = {(x.code, x.span, x.message) for x in self.items}
        key = (d.code, d.span, d.message)
        if key not in self._keys:
            self._keys.add(key)
            self.items.append(d)
        self._indexed = len(self.items)
        return d

    def error(self, code: str, message: str, span: Span | None, hint: str | None = None,
              calls=None, **kw) -> Diagnostic:
        return self.add(Diagnostic(code, message, span, "error", hint, **kw), calls)

    def warning(self, code: str, message: str, span: Span | None, hint: str | None = None,
                calls=None, **kw) -> Diagnostic:
        return self.add(Diagnostic(code, message, span, "warning", hint, **kw), calls)

    @property
    def has_errors(self) -> bool:
        return any(d.is_error for d in self.items)

    def errors(self) -> list[Diagnostic]:
        return [d for d in self.items if d.is_error]


def at_call_site(d: Diagnostic, calls, main: str) -> Diagnostic:
    """Move ``d``, located in a template or an imported file, to the program's call (issue 86).

    ``calls`` are ``(what, span)`` outermost first: the call in ``main`` becomes the primary
    span; each call between (inside a template of another file) is a note ("inside
    `gear_train`: `spur_gear` is called here"), and the original place the last note
    ("inside `spur_gear`, at std/gears.aidl:22:5"), before ``d``'s own labels.  A fix in
    another file is dropped (the user edits the call), and a "line N" in the message or
    the hint names its file.  Unchanged when ``calls`` does not start in ``main``.  Returns ``d``."""
    calls = [c for c in calls if c[1] is not None]
    if not calls or calls[0][1].file != main or d.span is None:
        return d
    sp = d.span
    notes = [Label(s, f"inside {calls[i][0]}: {what} is "
                      f"{'imported' if what.startswith('the file') else 'called'} here",
                   primary=False)
             for i, (what, s) in enumerate(calls[1:])]
    where = f"{shown_path(sp.file)}:{sp.line}:{sp.col}"
    notes.append(Label(sp, f"inside {calls[-1][0]}, at {where}", primary=False))
    d.labels = notes + list(d.labels)
    d.span = calls[0][1]
    if d.fix is not None and d.fix.span is not None and d.fix.span.file != main:
        d.fix = None
    d.message, d.hint = _lines_of(d.message, sp.file), _lines_of(d.hint, sp.file)
    return d


def _lines_of(text: str | None, file: str) -> str | None:
    """``text`` with each "line N" that names no file said to be of ``file`` ("line 31 of
    std/gears.aidl"): a diagnostic moved to the call names lines of the template."""
    if not text or "line " not in text:
        return text
    shown = shown_path(file)
    return re.sub(r"(?<!\.aidl )\b(line \d+)\b(?! of )", lambda m: f"{m.group(1)} of {shown}",
                  text)


def did_you_mean(name: str, candidates: Iterable[str], n: int = 3) -> list[str]:
    """Nearest known names to ``name``: first those that differ only in case or word style
    (``SpurGear``, ``spur-gear`` and ``SPUR_GEAR`` for ``spur_gear``), then by difflib ratio.
    Remembered per name and candidates (an error flood asks the same question thousands of
    times: 3,000 `Bogus(1)` spent 2.7 ms each in difflib over the ~600 names of the language)."""
    return list(_nearest(name, tuple(sorted(set(c for c in candidates
                                                 if c and not c.startswith("_")))), n))


@functools.lru_cache(maxsize=256)
def _nearest(name: str, cands: tuple, n: int) -> tuple:
    """:func:`did_you_mean` over the sorted, de-duplicated ``cands`` (cached)."""
    import difflib
    import re
    lower = {c.lower(): c for c in cands}
    out: list[str] = []
    if name.lower() in lower and lower[name.lower()] != name:
        out.append(lower[name.lower()])
    key = re.sub(r"[^a-z0-9]", "", name.lower())
    for c in cands:
        if c != name and c not in out and key and re.sub(r"[^a-z0-9]", "", c.lower()) == key:
            out.append(c)
    for m in difflib.get_close_matches(name.lower(), list(lower), n=n, cutoff=0.6):
        if lower[m] not in out:
            out.append(lower[m])
    return tuple(out[:n])


def _line_text(src: str, line: int) -> str:
    lines = split_lines(src)
    return lines[line - 1] if 0 < line <= len(lines) else ""


def render_texts(items, sources: dict[str, str], color: bool = False) -> list[str]:
    """Each diagnostic of ``items`` as :func:`render_text` says it, but one with the code,
    message and hint of one said before in full in one line: its place, "as above" and its
    own fix (issue 111, run cj: eight E0101 for one unknown name, each eight lines)."""
    out, seen = [], set()
    for d in items:
        key = (d.code, d.message, d.hint, d.severity)
        if key in seen and d.span is not None:
            where = f"{shown_path(d.span.file)}:{d.span.line}:{d.span.col}: "
            fix = (f"; fix: replace with `{d.fix.replacement}`"
                   if d.fix is not None and d.fix.replacement and d.fix.span.end > d.fix.span.start
                   else "")
            out.append(f"{where}{d.severity}[{d.code}]: {d.message} (as above{fix})")
            continue
        seen.add(key)
        out.append(render_text(d, sources, color=color))
    return out


def render_text(d: Diagnostic, sources: dict[str, str], color: bool = False) -> str:
    """``file:line:col: error[CODE]: message`` + source line + caret + labels + hint."""
    def c(code: str, s: str) -> str:
        return f"\x1b[{code}m{s}\x1b[0m" if color else s

    sev_color = {"error": "1;31", "warning": "1;33", "note": "1;36"}.get(d.severity, "1")
    where = f"{shown_path(d.span.file)}:{d.span.line}:{d.span.col}: " if d.span else ""
    out = [f"{where}{c(sev_color, f'{d.severity}[{d.code}]')}: {c('1', d.message)}"]
    spans = ([Label(d.span, "", True)] if d.span else []) + list(d.labels)
    for lab in spans:
        src = sources.get(lab.span.file)
        if src is None:
            if lab.message:
                out.append(f"  --> {shown_path(lab.span.file)}:{lab.span.line}:{lab.span.col}: "
                           f"{lab.message}")
            continue
        if lab is not spans[0]:
            out.append(f"  --> {shown_path(lab.span.file)}:{lab.span.line}:{lab.span.col}")
        text = shown_line(_line_text(src, lab.span.line).replace("\t", " "))
        num = str(lab.span.line)
        pad = " " * len(num)
        width = (lab.span.end_col - lab.span.col) if lab.span.end_line == lab.span.line \
            else max(1, len(text) - lab.span.col + 1)
        width = max(1, width)
        mark = "^" if lab.primary else "-"
        out.append(f"{pad} |")
        out.append(f"{num} | {text}")
        tail = f" {lab.message}" if lab.message else ""
        out.append(f"{pad} | " + " " * (lab.span.col - 1) + c(sev_color, mark * width) + tail)
    if d.hint:
        out.append(f"  = hint: {d.hint}")
    if d.suggestions and (not d.hint or "did you mean" not in d.hint):
        out.append("  = did you mean: " + ", ".join(f"`{s}`" for s in d.suggestions) + "?")
    if d.fix:
        if d.fix.span.start == d.fix.span.end and d.fix.replacement.strip():
            out.append(f"  = suggested fix: insert `{d.fix.replacement.strip()}` at "
                       f"{d.fix.span.line}:{d.fix.span.col}")
        elif not d.fix.replacement and d.fix.span.end > d.fix.span.start:
            n = d.fix.span.end - d.fix.span.start
            out.append(f"  = suggested fix: delete the {n} character{'s' if n > 1 else ''} at "
                       f"{d.fix.span.line}:{d.fix.span.col}")
        else:
            out.append(f"  = suggested fix: replace with `{d.fix.replacement}`")
    return "\n".join(out)
