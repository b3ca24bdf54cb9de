"""Finding one's way in and between documents: folding ranges, document highlight, document
links for ``import`` paths, workspace symbols.  Pure functions over source text (like
:mod:`.analysis`), returning :mod:`lsprotocol` values; positions in UTF-16.

* :func:`folding_ranges` — every ``{ ... }`` block over more than one line (structures,
  templates, loops, ``if``), every run of two or more comment lines and every ``/* */``
  comment over more than one line (kind ``comment``), every run of ``import`` lines (kind
  ``imports``); found lexically, so a document that does not parse folds too;
* :func:`highlights` — the occurrences of the name under the cursor: a user name's definition
  (``Write``) and references (``Read``) as :func:`.analysis.references` finds them (scopes
  respected); any other word (``Circle``, ``mm``) every occurrence as a whole word outside
  comments and strings (``Text``);
* :func:`document_links` — the path of each ``import "file.aidl"`` links to the file it
  resolves to (:func:`aidl_lang.library.sources.resolve_import`: the importer's folder, then the
  standard library); an import that does not resolve gets no link (its diagnostic says why);
* :func:`workspace_symbols` — structures, params, templates (and named geometry) of the open
  documents and of the ``.aidl`` files under the workspace folders, whose name contains the
  query's characters in order (case-insensitive, as editors filter).
"""
from __future__ import annotations

import os
import re
from pathlib import Path

from lsprotocol import types as T

from .analysis import (Index, _sym_at, _word_at, document_symbols, offset_at, parse_tolerant,
                       position_at, span_range)

_LEX = re.compile(r"""
    (?P<block>/\*.*?(?:\*/|\Z))
  | (?P<line>(?:\#|//)[^\n]*)
  | (?P<str>[fF]?(?:"(?:\\.|[^"\\\n])*"?|'(?:\\.|[^'\\\n])*'?))
  | (?P<open>\{)
  | (?P<close>\})
""", re.VERBOSE | re.DOTALL)

MAX_WORKSPACE_FILES = 2000          # .aidl files read for workspace symbols
MAX_FILE_CHARS = 1_000_000          # larger files are left out of workspace symbols
SKIP_DIRS = {".git", ".hg", ".svn", "node_modules", ".venv", "venv", "__pycache__", ".tox",
             "build", "dist"}


def _line_of(starts: list[int], off: int) -> int:
    import bisect
    return bisect.bisect_right(starts, off) - 1


def folding_ranges(src: str) -> list[T.FoldingRange]:
    """See the module doc.  Comments are ``#``, ``/* */`` and ``//`` at the start of a line
    (a ``//`` after code may be floor division; such lines are not folded as comments)."""
    starts = [0] + [m.end() for m in re.finditer("\n", src)]
    out: list[T.FoldingRange] = []
    stack: list[int] = []
    comment_lines: set[int] = set()
    for m in _LEX.finditer(src):
        kind = m.lastgroup
        if kind == "open":
            stack.append(_line_of(starts, m.start()))
        elif kind == "close":
            if stack:
                a = stack.pop()
                b = _line_of(starts, m.start())
                # fold up to the line before the closing brace, so `}` stays visible
                if b - 1 > a:
                    out.append(T.FoldingRange(start_line=a, end_line=b - 1))
        elif kind == "block":
            a, b = _line_of(starts, m.start()), _line_of(starts, m.end() - 1)
            if b > a:
                out.append(T.FoldingRange(start_line=a, end_line=b,
                                          kind=T.FoldingRangeKind.Comment))
        elif kind == "line":
            line = _line_of(starts, m.start())
            if not src[starts[line]:m.start()].strip():      # a comment on its own line
                comment_lines.add(line)
    out += _runs(comment_lines, T.FoldingRangeKind.Comment)
    imports = {i for i, ln in enumerate(src.split("\n")) if re.match(r"\s*import\b", ln)}
    out += _runs(imports, T.FoldingRangeKind.Imports)
    out.sort(key=lambda r: (r.start_line, -r.end_line))
    return out


def _runs(lines: set[int], kind) -> list[T.FoldingRange]:
    out = []
    run: list[int] = []
    for ln in sorted(lines) + [None]:
        if run and (ln is None or ln != run[-1] + 1):
            if len(run) >= 2:
                out.append(T.FoldingRange(start_line=run[0], end_line=run[-1], kind=kind))
            run = []
        if ln is not None:
            run.append(ln)
    return out


def highlights(src: str, line: int, character: int, path: str = "doc.aidl") -> list[T.DocumentHighlight]:
    """See the module doc."""
    off = offset_at(src, line, character)
    w = _word_at(src, off)
    if w is None:
        return []
    ix = Index(src, path)
    sym = _sym_at(ix, off)
    if sym is not None:
        out = []
        if sym.origin is None or sym.origin is ix:
            out.append(T.DocumentHighlight(range=span_range(src, sym.span),
                                           kind=T.DocumentHighlightKind.Write))
        out += [T.DocumentHighlight(range=span_range(src, sp), kind=T.DocumentHighlightKind.Read)
                for sp in ix.references(sym) if sp.start != sym.span.start]
        return out
    word = w[0]
    bare = _bare(src)
    return [T.DocumentHighlight(range=T.Range(start=position_at(src, m.start()),
                                              end=position_at(src, m.end())),
                                kind=T.DocumentHighlightKind.Text)
            for m in re.finditer(rf"(?<![\w.]){re.escape(word)}\b", bare)]


def _bare(src: str) -> str:
    """``src`` with comments and strings blanked (same length)."""
    def blank(m):
        return re.sub(r"[^\n]", " ", m.group())
    return re.sub(r"/\*.*?(?:\*/|\Z)|#[^\n]*|//[^\n]*|\"(?:\\.|[^\"\\\n])*\"?|'(?:\\.|[^'\\\n])*'?",
                  blank, src, flags=re.DOTALL)


def document_links(src: str, path: str, tooltips: bool = False) -> list[T.DocumentLink]:
    """See the module doc; ``tooltips``: give each link the target's path as its tooltip (for
    clients that declare ``tooltipSupport``)."""
    from ... import ast as A
    from ...library.sources import ImportRefused, resolve_import
    prog = parse_tolerant(src, path)
    out = []
    for st in prog.stmts:
        if not isinstance(st, A.Import):
            continue
        try:
            target = resolve_import(st.path, path)
        except (ImportRefused, OSError, ValueError):
            continue
        sp = st.path_span
        rng = span_range(src, sp)
        text = src[sp.start:sp.end]
        if len(text) >= 2 and text[0] in "\"'" and text[-1] == text[0]:   # inside the quotes
            rng = T.Range(start=T.Position(line=rng.start.line, character=rng.start.character + 1),
                          end=T.Position(line=rng.end.line, character=rng.end.character - 1))
        out.append(T.DocumentLink(range=rng, target=Path(target).resolve().as_uri(),
                                  tooltip=str(target) if tooltips else None))
    return out


def _matches(query: str, name: str) -> bool:
    """The query's characters appear in ``name`` in order (case-insensitive)."""
    it = iter(name.lower())
    return all(c in it for c in query.lower())


_KIND = {T.SymbolKind.Struct, T.SymbolKind.Constant, T.SymbolKind.Function,
         T.SymbolKind.Variable}


def symbols_of(src: str, path: str, uri: str, with_geometry: bool = True) -> list[T.WorkspaceSymbol]:
    """Every symbol of one document (:func:`.analysis.document_symbols`, flattened), with the
    enclosing structure or template as ``container_name``."""
    out: list[T.WorkspaceSymbol] = []

    def walk(syms, container):
        for s in syms:
            if s.kind in _KIND and (with_geometry or s.kind != T.SymbolKind.Variable):
                out.append(T.WorkspaceSymbol(
                    name=s.name, kind=s.kind, container_name=container,
                    location=T.Location(uri=uri, range=s.selection_range)))
            walk(s.children or [], f"{container}.{s.name}" if container else s.name)
    walk(document_symbols(src, path), None)
    return out


def workspace_files(roots: list[str], limit: int = MAX_WORKSPACE_FILES) -> list[Path]:
    """The ``.aidl`` files under ``roots`` (skipping VCS, virtualenv and build folders), at
    most ``limit``."""
    out: list[Path] = []
    for root in roots:
        for d, dirs, files in os.walk(root):
            dirs[:] = sorted(x for x in dirs if x not in SKIP_DIRS and not x.startswith("."))
            for f in sorted(files):
                if f.endswith(".aidl"):
                    out.append(Path(d) / f)
                    if len(out) >= limit:
                        return out
    return out


_cache: dict[str, tuple[float, int, list]] = {}     # path -> (mtime, size, symbols)


def workspace_symbols(query: str, open_docs: dict[str, tuple[str, str]],
                      roots: list[str]) -> list[T.WorkspaceSymbol]:
    """See the module doc.  ``open_docs``: uri -> (path, text) of the open documents (their
    unsaved text wins over the file); ``roots``: workspace folder paths.  A file's symbols are
    kept while its modification time and size do not change."""
    out: list[T.WorkspaceSymbol] = []
    seen: set[str] = set()
    for uri, (path, text) in open_docs.items():
        if path:
            seen.add(os.path.realpath(path))
        out += symbols_of(text, path or "untitled.aidl", uri)
    for f in workspace_files(roots):
        real = os.path.realpath(f)
        if real in seen:
            continue
        seen.add(real)
        try:
            st = f.stat()
            if st.st_size > MAX_FILE_CHARS:
                continue
            hit = _cache.get(real)
            if hit is None or hit[0] != st.st_mtime or hit[1] != st.st_size:
                text = f.read_text(encoding="utf-8")
                hit = (st.st_mtime, st.st_size, symbols_of(text, str(f), f.resolve().as_uri()))
                _cache[real] = hit
        except (OSError, UnicodeDecodeError, ValueError):
            continue
        out += hit[2]
    if query:
        out = [s for s in out if _matches(query, s.name)]
    return out
