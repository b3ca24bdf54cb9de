"""Edits the server offers: quick fixes (``textDocument/codeAction``) and rename
(``textDocument/prepareRename``, ``textDocument/rename``).

Quick fixes are generic: every pipeline diagnostic that carries a suggested fix
(:class:`aidl_lang.base.diagnostics.Fix`, e.g. the did-you-mean renames of ``E0101``-``E0103``)
publishes it in ``Diagnostic.data["fixes"]`` (:func:`~aidl_lang.editor.lsp.analysis.fix_edits`),
and a code action request turns each into a ``quickfix`` action (the first one preferred), so
new checks that attach a ``Fix`` show up in editors with no change here.

Rename works on user names (params, templates, structures, variables, loop variables, template
parameters, import namespaces): the definition and every reference in the document, in the file
that defines it when it came in by ``import``, and in the other ``.aidl`` files beside either
that import the defining file (open editors' unsaved text wins over the disk).
"""
from __future__ import annotations

import re
from pathlib import Path

from lsprotocol import types as T

from ... import registry as R
from .analysis import Index, _sym_at, _word_at, offset_at, position_at, span_range

MAX_FILES = 200            # .aidl files scanned for importers when renaming


# ------------------------------------------------------------------ quick fixes
def code_actions(uri: str, diagnostics: list[T.Diagnostic], rng: T.Range | None = None) -> list[T.CodeAction]:
    """A ``quickfix`` code action per suggested fix of the given diagnostics (those the client
    sends in the request's context, which carry ``data["fixes"]`` as published)."""
    out = []
    for d in diagnostics:
        data = d.data if isinstance(d.data, dict) else {}
        for k, f in enumerate(data.get("fixes") or []):
            try:
                r = f["range"]
                edit_range = T.Range(start=T.Position(**r["start"]), end=T.Position(**r["end"]))
                title, text = str(f["title"]), str(f["newText"])
            except (KeyError, TypeError):
                continue                           # not ours (a client echoed something else)
            out.append(T.CodeAction(
                title=title, kind=T.CodeActionKind.QuickFix, diagnostics=[d], is_preferred=k == 0,
                edit=T.WorkspaceEdit(changes={uri: [T.TextEdit(range=edit_range, new_text=text)]})))
    return out


# ------------------------------------------------------------------ rename
_IDENT = re.compile(r"[A-Za-z_]\w*\Z")


class RenameError(ValueError):
    """Why a rename is refused (shown to the user by the client)."""


def _key(sym) -> tuple[str, int]:
    origin = sym.origin
    return (str(Path(origin.path).resolve()) if origin is not None else "", sym.span.start)


def _renamable(src: str, line: int, character: int, path: str):
    ix = Index(src, path)
    off = offset_at(src, line, character)
    sym = _sym_at(ix, off)
    w = _word_at(src, off)
    if sym is None or w is None:
        word = w[0] if w else ""
        if word and (R.lookup(word) or word in R.FUNCTIONS or word in R.CONSTANTS
                     or word in R.KEYWORDS or word in R.STRUCTURE_KINDS):
            raise RenameError(f"`{word}` is part of the language, not a name of this program")
        raise RenameError("no name of this program here")
    return ix, sym, w


def prepare_rename(src: str, line: int, character: int, path: str = "doc.aidl") -> T.Range:
    """The range of the name to rename at the position; :class:`RenameError` if none."""
    _, _, (word, a, b) = _renamable(src, line, character, path)
    return T.Range(start=position_at(src, a), end=position_at(src, b))


def _uses_in(ix: Index, key, name: str) -> list:
    out = []
    for s in ix.scopes:                       # the definition, when this file has it
        sym = s.names.get(name)
        if sym is not None and sym.origin is ix and _key(sym) == key:
            out.append(sym.span)
            break
    for sp, node in ix.uses:
        if getattr(node, "id", getattr(node, "name", None)) != name:
            continue
        sym = ix.resolve(node)
        if sym is not None and _key(sym) == key:
            out.append(sp)
    return sorted(set(out), key=lambda sp: sp.start)


def _check_clash(ix: Index, sym, new: str, spans: list) -> None:
    """Raise :class:`RenameError` when renaming ``sym`` (defined in ``ix``; ``spans``: its
    definition and uses there) to ``new`` would change the program: the scope that defines it
    has a ``new`` already (two names of one structure, E0107), a use of another ``new``
    would then mean ``sym`` (it lies in ``sym``'s scope with no nearer ``new``), or a use of
    ``sym`` would then mean a nearer ``new``."""
    home = next((sc for sc in ix.scopes if sc.names.get(sym.name) is sym), None)
    if home is None:
        return
    where = f"`{home.owner.name}`" if home.owner is not None else "this file"
    other = home.names.get(new)
    if other is not None:
        raise RenameError(f"`{new}` is already a name in {where} (line {other.span.line}): "
                          f"renaming `{sym.name}` to it would define it twice (E0107)")

    def nearest(offset: int):
        """The scope of ``new`` seen from ``offset`` when it is ``home`` or nearer, else None
        (``home`` itself when nothing nearer defines it)."""
        sc = ix.scope_at(offset)
        while sc is not None:
            if new in sc.names or sc is home:
                return sc
            sc = sc.parent
        return None
    from ... import ast as A
    for sp, node in ix.uses:
        if isinstance(node, A.Name) and node.id == new and nearest(sp.start) is home:
            raise RenameError(f"`{new}` on line {sp.line} would then mean the renamed "
                              f"`{sym.name}` instead of what it means now; choose another name")
    mine = {sp.start for sp in spans}
    for sp, node in ix.uses:
        if sp.start in mine and isinstance(node, A.Name):
            sc = nearest(sp.start)
            if sc is not None and sc is not home:
                raise RenameError(f"`{sym.name}` on line {sp.line} would then mean another "
                                  f"`{new}` (defined nearer, line {sc.names[new].span.line}); "
                                  "choose another name")


def rename(src: str, line: int, character: int, new_name: str, uri: str, path: str = "doc.aidl",
           open_documents: dict[str, str] | None = None) -> T.WorkspaceEdit:
    """Rename the user name at the position to ``new_name`` everywhere it is visible.

    ``open_documents`` maps file paths to the unsaved text of documents open in the editor.
    Raises :class:`RenameError` for a position with no user name or an invalid new name.
    """
    if not _IDENT.match(new_name or ""):
        raise RenameError(f"`{new_name}` is not a name (letters, digits, `_`; not starting with a digit)")
    if new_name in R.KEYWORDS or new_name in R.CONSTANTS:      # `solid`, `cut`: ordinary names
        raise RenameError(f"`{new_name}` is a keyword")
    if R.lookup(new_name) is not None or new_name in R.FUNCTIONS:
        raise RenameError(f"`{new_name}` is a name of the language (a shape, constraint, "
                          f"operation or function): a name of the program may not hide it "
                          f"(a call `{new_name}(...)` would then fail, E0111); choose another "
                          "name")
    ix, sym, _ = _renamable(src, line, character, path)
    key, name = _key(sym), sym.name
    if sym.origin is ix and new_name != name:
        _check_clash(ix, sym, new_name, _uses_in(ix, key, name))
    opened = {str(Path(p).resolve()): t for p, t in (open_documents or {}).items()}
    here = str(Path(path).resolve())
    opened[here] = src
    files: dict[str, Index] = {here: ix}
    home = key[0] or here
    if home not in files:
        text = opened.get(home)
        if text is None:
            try:
                text = Path(home).read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError):
                text = None
        if text is not None:
            files[home] = Index(text, home)
    if sym.origin is not None and sym.origin.file.names.get(name) is sym:
        # top-level names can be imported: look at the .aidl files beside both ends
        dirs = {Path(home).parent, Path(here).parent}
        cands = sorted({p for d in dirs for p in d.glob("*.aidl")})[:MAX_FILES]
        stem = Path(home).stem
        for p in cands:
            rp = str(p.resolve())
            if rp in files:
                continue
            text = opened.get(rp)
            if text is None:
                try:
                    text = p.read_text(encoding="utf-8")
                except (OSError, UnicodeDecodeError):
                    continue
            if "import" not in text or stem not in text:
                continue                       # cheap filter before parsing
            files[rp] = Index(text, rp)
    changes: dict[str, list[T.TextEdit]] = {}
    for fpath, fix in files.items():
        spans = _uses_in(fix, key, name)
        if spans:
            furi = uri if fpath == here else Path(fpath).as_uri()
            changes[furi] = [T.TextEdit(range=span_range(fix.src, sp), new_text=new_name)
                             for sp in spans]
    return T.WorkspaceEdit(changes=changes)
