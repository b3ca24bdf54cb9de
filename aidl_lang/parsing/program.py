"""Parse a whole file (:func:`parse`) or an imported one, remembered by its text
(:func:`parse_import`): the nesting limit (E0003), the comments masked, the recovering parse,
then the bracket diagnostics.  The package's entry; imports the other modules."""
from __future__ import annotations

import threading
from itertools import accumulate

from .. import ast as A
from .controls import check_controls
from ..base.diagnostics import DiagnosticSink, Span, as_lf
from ..base.memory import gc_paused
from .brackets import _report_brackets
from .comments import _ANY_BRACKET, _BRACKET_STEP, mask_comments
from .lalr import _STATE, _Builder, _tables
from .recovery import _recover_by_pieces, _recovering_parse
from .tokens import MAX_NESTING

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
    check_controls(source, masked, path, sink)       # W0112: bidi controls, U+2028 / U+2029
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
    return A.Program(Span(path, 1, 1, end_line, 1, 0, len(source)), path, source,
                     hoist_defs(stmts)), masked


def hoist_defs(stmts: list) -> list:
    """The top-level statements with every ``def`` written inside a block (a structure, a
    loop, a branch, another template) moved out, just above the top-level statement that
    held it, its ``within`` the name of that structure or template: a template or function
    defined in a structure is one defined above it, reading the file's names and its own
    arguments (issue 111: seven first checks of models failed on `def rail() -> solid
    { ... }` in an assembly).  Each block keeps its other statements in their order."""
    out: list = []
    for st in stmts:
        found: list = []
        for block in _blocks(st):
            _take_defs(block, found)
        owner = getattr(st, "name", None) if isinstance(st, (A.StructDecl, A.Def)) else None
        for d in found:
            d.within = owner
        out.extend(found)
        out.append(st)
    return out


def _blocks(st) -> list:
    """The blocks a statement holds: a structure's, a template's or a loop's body, a branch's
    two, a bare block itself."""
    if isinstance(st, A.Block):
        return [st]
    if isinstance(st, (A.StructDecl, A.Def, A.For)):
        return [st.body]
    if isinstance(st, A.If):
        return [b for b in (st.body, st.orelse) if b is not None]
    return []


def _take_defs(block, found: list) -> None:
    """Move the ``def``s of ``block`` and the blocks in it into ``found``, in source order."""
    kept = []
    for st in block.stmts:
        if isinstance(st, (A.Def, A.Func)):
            found.append(st)
        else:
            kept.append(st)
        for inner in _blocks(st):
            _take_defs(inner, found)
    block.stmts[:] = kept
