"""Diagnostics as plain LSP JSON (dicts), without :mod:`lsprotocol`.

The server's start-up path (:mod:`.boot`) and the analysis worker (:mod:`.worker`) publish
diagnostics before (or without) importing pygls and lsprotocol, whose import is most of a cold
start (~0.4 s of ``lsprotocol.types``).  So the pipeline's diagnostics are turned into the
JSON the protocol sends here: ``{"range", "severity", "code", "codeDescription", "source",
"message", "relatedInformation", "data"}`` (LSP 3.17 ``Diagnostic``), positions in UTF-16 code
units as LSP requires.  :func:`aidl_lang.editor.lsp.analysis.diagnostics` structures the same
dicts into ``lsprotocol`` objects.

``codeDescription.href`` links each code to its explanation in ``docs/codes.md``
(``docs/codes.md#e0103``; :data:`DOCS_URL`, the file beside the package in a source checkout or
editable install, or the environment variable ``AIDL_DOCS_URL``; no link when neither exists).
The same text is ``aidl explain CODE`` and the server's ``aidl/explain`` request.
"""
from __future__ import annotations

import os
import re
from pathlib import Path

from ...base.diagnostics import Span, shown_path, split_lines

_SEVERITY = {"error": 1, "warning": 2, "note": 3}


def _docs_url() -> str | None:
    env = os.environ.get("AIDL_DOCS_URL")
    if env:
        return env.rstrip("/") + "/codes.md"
    doc = Path(__file__).resolve().parents[3] / "docs" / "codes.md"
    return doc.as_uri() if doc.is_file() else None


DOCS_URL = _docs_url()


def code_href(code: str) -> str | None:
    """The URL of the explanation of ``code`` (``.../codes.md#e0103``), or None."""
    if DOCS_URL is None or not re.fullmatch(r"[EWN]\d{4}", code or ""):
        return None
    return f"{DOCS_URL}#{code.lower()}"


def u16len(s: str) -> int:
    """Length of ``s`` in UTF-16 code units (LSP's default position encoding)."""
    return len(s) + sum(1 for c in s if ord(c) > 0xFFFF)


def pos(line: int, character: int) -> dict:
    return {"line": line, "character": character}


def rng(a: dict, b: dict) -> dict:
    return {"start": a, "end": b}


def span_range(src: str, sp: Span, lines: list[str] | None = None) -> dict:
    """The LSP range (a dict) of a :class:`Span` (1-based lines/columns, end column
    exclusive); never empty (an empty span covers one character)."""
    if lines is None:
        lines = split_lines(src)

    def at(line: int, col: int) -> tuple[int, int]:
        li = max(0, line - 1)
        text = lines[li] if li < len(lines) else ""
        return li, u16len(text[:max(0, col - 1)])

    a, b = at(sp.line, sp.col), at(sp.end_line, sp.end_col)
    if b <= a:
        b = (a[0], a[1] + 1)
    return rng(pos(*a), pos(*b))


def diagnostic_json(src: str, path: str, d, uri: str | None = None,
                    lines: list[str] | None = None, sources: dict | None = None) -> dict:
    """One pipeline :class:`~aidl_lang.base.diagnostics.Diagnostic` as an LSP ``Diagnostic`` dict
    (see the module doc). A diagnostic raised inside a template of another file is at its
    call in the document already (the pipeline moved it: issue 86), the template's place a
    label; one still located in another file is put on line 1 with its location in the
    message.  ``uri`` (the document's) enables ``relatedInformation`` for the labels (those
    in other files with their file's URI, placed by ``sources``); suggested fixes go in
    ``data.fixes`` (:func:`fix_edits`)."""
    if lines is None:
        lines = split_lines(src)
    msg = d.message
    if d.hint:
        msg += f"\nhint: {d.hint}"
    if d.span is None or d.span.file != path:
        if d.span is not None:
            msg = f"{shown_path(d.span.file)}:{d.span.line}:{d.span.col}: {msg}"
        r = rng(pos(0, 0), pos(0, 1))
    else:
        r = span_range(src, d.span, lines)
    out = {"range": r, "message": msg, "source": "aidl"}
    sev = _SEVERITY.get(d.severity)
    if sev is not None:
        out["severity"] = sev
    if d.code:
        out["code"] = d.code
        href = code_href(d.code)
        if href:
            out["codeDescription"] = {"href": href}
    if uri is not None:
        related = [{"location": _location(src, path, uri, lab.span, lines, sources),
                    "message": lab.message or "here"} for lab in d.labels
                   if lab.span.file == path or _file_uri(lab.span.file)]
        if related:
            out["relatedInformation"] = related
    fixes = fix_edits(src, path, d, lines) if d.span is not None and d.span.file == path else []
    if fixes:
        out["data"] = {"fixes": fixes}
    return out


def _file_uri(file: str | None) -> str | None:
    """The ``file://`` URI of a span's file (another than the document: a template's), or
    None when it is no absolute path."""
    if not file or not os.path.isabs(file):
        return None
    return Path(file).as_uri()


def _location(src: str, path: str, uri: str, sp: Span, lines: list[str],
              sources: dict | None) -> dict:
    """The LSP ``Location`` of a label's span: in the document, or in another file (a
    template's note, issue 86), its range in that file's text from ``sources`` (the
    columns as characters when it is not there)."""
    if sp.file == path:
        return {"uri": uri, "range": span_range(src, sp, lines)}
    other = (sources or {}).get(sp.file)
    if other is None:
        r = rng(pos(max(0, sp.line - 1), max(0, sp.col - 1)),
                pos(max(0, sp.end_line - 1), max(0, sp.end_col - 1)))
    else:
        r = span_range(other, sp)
    return {"uri": _file_uri(sp.file), "range": r}


def sink_json(src: str, path: str, items, uri: str | None = None,
              sources: dict | None = None) -> list[dict]:
    """Every diagnostic of a sink's ``items`` as LSP dicts (:func:`diagnostic_json`);
    ``sources`` (the sink's: file -> text) places the notes in other files."""
    lines = split_lines(src)
    return [diagnostic_json(src, path, d, uri, lines, sources) for d in items]


def fix_edits(src: str, path: str, d, lines: list[str] | None = None) -> list[dict]:
    """The suggested fixes of a pipeline diagnostic as ``{"title", "range", "newText"}`` dicts
    (LSP ranges in ``src``), preferred first: ``d.fix`` and, when it replaces a name with the
    first of ``d.suggestions``, the other suggestions as alternatives. A diagnostic with
    suggestions but no ``Fix`` gets them as replacements of the name its span starts with, when
    the message quotes that name (an unknown keyword argument). Fixes located in another file
    are left out. Carried in ``Diagnostic.data`` for ``textDocument/codeAction``."""
    from ...parsing.controls import code_point, invisible
    from ...base.diagnostics import Fix
    fix = d.fix
    if fix is None and d.suggestions and d.span is not None and d.span.file == path:
        # no Fix, but suggestions for the name the diagnostic is about: when its span starts
        # with that name (quoted in the message, e.g. "`Circle` has no argument `centre`" on
        # `centre=(0, 0)`), each suggestion replaces it
        m = re.match(r"[A-Za-z_]\w*", src[d.span.start:d.span.end])
        if m and f"`{m.group()}`" in d.message and all(
                re.fullmatch(r"[A-Za-z_]\w*", x) for x in d.suggestions):
            sp = d.span
            fix = Fix(Span(sp.file, sp.line, sp.col, sp.line, sp.col + len(m.group()),
                           sp.start, sp.start + len(m.group())), d.suggestions[0])
    if fix is None or fix.span is None or fix.span.file != path:
        return []
    fixes = [fix]
    if d.suggestions and fix.replacement == d.suggestions[0]:
        fixes += [Fix(fix.span, s) for s in d.suggestions[1:]]
    out = []
    for f in fixes:
        old = src[f.span.start:f.span.end]
        if old and not f.replacement and all(map(invisible, old)):
            old = ", ".join(map(code_point, old))   # (a bidi control shown raw reorders the menu)
        title = getattr(f, "title", None) or (
            f"Replace `{old}` with `{f.replacement}`" if old and f.replacement else
            f"Remove `{old}`" if old else f"Insert `{f.replacement}`")
        r = span_range(src, f.span, lines)
        if f.span.end <= f.span.start:             # an insertion: an empty range
            r = rng(r["start"], dict(r["start"]))
        out.append({"title": title, "newText": f.replacement, "range": r})
    return out


def quick_diagnostics(src: str, path: str, uri: str | None = None) -> list[dict] | None:
    """The diagnostics of parsing and checking ``src`` (no interpretation, no solve) as LSP
    dicts: what a program shows before the pipeline's heavier stages are loaded (the parser and
    checker import no numpy; ~15 ms for ``examples/telephone.aidl`` after ~70 ms of imports).
    When they hold an error they are exactly what the whole pipeline reports (it stops at the
    first stage with errors).  None if the program is too deep to check here (the pipeline
    checks it on a large stack)."""
    from ...base.diagnostics import DiagnosticSink
    from ...parser import parse
    from ...typecheck import check
    text = src[1:] if src.startswith("\ufeff") else src     # as the pipeline reads it
    sink = DiagnosticSink()
    try:
        program = parse(text, path, sink)
        if not sink.has_errors:
            check(program, sink)
    except (RecursionError, MemoryError):
        return None
    return sink_json(src, path, sink.items, uri)
