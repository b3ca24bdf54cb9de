"""The language server's workbench features, registered on the pygls server by
:func:`register` (called from :mod:`.server`):

* solved values in the code — ``textDocument/inlayHint`` (:func:`.hints.inlay_hints`) and
  ``textDocument/codeLens`` (degrees of freedom per structure, :func:`.hints.code_lenses`),
  from the facts the analysis worker computes with the diagnostics; after each analysis the
  server asks the client to refresh them (``workspace/inlayHint/refresh``,
  ``workspace/codeLens/refresh``) when the client supports it.  Inlay hints are on unless
  ``initializationOptions`` or the settings (``workspace/didChangeConfiguration``) say
  ``{"aidl": {"inlayHints": {"enabled": false}}}`` (or ``{"inlayHints": false}``); the code
  lens likewise with ``codeLens``;
* ``textDocument/foldingRange``, ``textDocument/documentHighlight``,
  ``textDocument/documentLink``, ``workspace/symbol`` (:mod:`.navigate`);
* ``aidl/explain`` — a custom request: ``{"code": "E0103"}`` -> ``{"code", "title",
  "explanation"`` (Markdown), ``"href"}`` (the text of ``aidl explain``); an unknown code is the
  error ``RequestFailed`` naming the codes of its group (``E01..``).
"""
from __future__ import annotations

from lsprotocol import converters
from lsprotocol import types as T

from . import hints, navigate, window
from .analysis import parse_tolerant

settings = {"inlayHints": True, "codeLens": True}
_programs: dict[str, tuple[int | None, str, object]] = {}    # uri -> (version, text, program)


def program_of(uri: str, d, path: str):
    """The document's syntax tree, parsed once per version (inlay hints are asked for on every
    scroll)."""
    hit = _programs.get(uri)
    if hit is not None and hit[0] == d.version and hit[1] is d.source:
        return hit[2]
    prog = parse_tolerant(d.source, path)
    _programs[uri] = (d.version, d.source, prog)
    return prog


def _flag(opts, key: str):
    """``opts[key]`` as a bool from ``{"aidl": {key: {"enabled": b}}}``, ``{key: {"enabled": b}}``
    or ``{key: b}``; None when not given."""
    if not isinstance(opts, dict):
        return None
    if isinstance(opts.get("aidl"), dict):
        got = _flag(opts["aidl"], key)
        if got is not None:
            return got
    v = opts.get(key)
    if isinstance(v, dict):
        v = v.get("enabled")
    return v if isinstance(v, bool) else None


def configure(opts) -> None:
    """Read the toggles from initialization options or settings (see the module doc)."""
    for key in settings:
        v = _flag(opts, key)
        if v is not None:
            settings[key] = v


def explain(code) -> dict:
    """The ``aidl/explain`` answer for ``code`` (raises ``KeyError`` with a message)."""
    from ...base.codes import CODES
    from ...base.diagnostics import did_you_mean
    from .plain import code_href
    c = str(code or "").strip().upper()
    if c not in CODES:
        near = [k for k in sorted(CODES) if k[:3] == c[:3]] or did_you_mean(c, list(CODES))
        raise KeyError(f"unknown code `{code}`" + (f"; codes near it: {', '.join(near)}" if near
                                                 else f"; known codes: {', '.join(sorted(CODES))}"))
    title, text = CODES[c]
    return {"code": c, "title": title, "explanation": text.strip(), "href": code_href(c)}


def register(server, safe, doc, facts, failed) -> None:
    """Register the handlers on ``server``. ``safe``: the server's handler guard;
    ``doc(ls, uri)`` -> (document, path); ``facts(uri)`` -> the last analysis' facts (or
    None); ``failed(message)`` -> the exception for a refused request."""
    conv = converters.get_converter()

    def solved(ls, setting: str, uri: str):
        """(source, program, facts) for a hint or lens request, or None: turned off, not
        solved yet, or too large."""
        f = settings[setting] and facts(uri)
        if not f:
            return None
        d, path = doc(ls, uri)
        if len(d.source) > window.LARGE:
            return None
        return d.source, program_of(uri, d, path), f

    @server.feature(T.TEXT_DOCUMENT_INLAY_HINT, T.InlayHintOptions())
    @safe([])
    def inlay_hint(ls, params: T.InlayHintParams):
        got = solved(ls, "inlayHints", params.text_document.uri)
        if got is None:
            return []
        out = hints.inlay_hints(*got, params.range.start.line, params.range.end.line)
        return conv.structure(out, list[T.InlayHint])

    @server.feature(T.TEXT_DOCUMENT_CODE_LENS, T.CodeLensOptions(resolve_provider=False))
    @safe([])
    def code_lens(ls, params: T.CodeLensParams):
        got = solved(ls, "codeLens", params.text_document.uri)
        if got is None:
            return []
        return conv.structure(hints.code_lenses(*got), list[T.CodeLens])

    @server.feature(T.TEXT_DOCUMENT_FOLDING_RANGE)
    @safe([])
    def folding_range(ls, params: T.FoldingRangeParams):
        d, _ = doc(ls, params.text_document.uri)
        if len(d.source) > window.HUGE:
            return []
        return navigate.folding_ranges(d.source)

    @server.feature(T.TEXT_DOCUMENT_DOCUMENT_HIGHLIGHT)
    @safe([])
    def document_highlight(ls, params: T.DocumentHighlightParams):
        d, path = doc(ls, params.text_document.uri)
        src = window.view(d.source, params.position.line)
        return navigate.highlights(src, params.position.line, params.position.character, path)

    @server.feature(T.TEXT_DOCUMENT_DOCUMENT_LINK, T.DocumentLinkOptions(resolve_provider=False))
    @safe([])
    def document_link(ls, params: T.DocumentLinkParams):
        d, path = doc(ls, params.text_document.uri)
        if len(d.source) > window.LARGE:
            return []
        caps = getattr(getattr(ls.client_capabilities, "text_document", None), "document_link", None)
        return navigate.document_links(d.source, path, bool(getattr(caps, "tooltip_support", False)))

    @server.feature(T.WORKSPACE_SYMBOL)
    @safe([])
    def workspace_symbol(ls, params: T.WorkspaceSymbolParams):
        opened = {}
        for uri, d in ls.workspace.text_documents.items():
            if len(d.source) <= window.LARGE:
                opened[uri] = (d.path, d.source)
        roots = []
        for folder in ls.workspace.folders.values():
            from pygls.uris import to_fs_path
            p = to_fs_path(folder.uri)
            if p:
                roots.append(p)
        if not roots and ls.workspace.root_path:
            roots.append(ls.workspace.root_path)
        return navigate.workspace_symbols(params.query, opened, roots)

    @server.feature(T.WORKSPACE_DID_CHANGE_CONFIGURATION)
    @safe()
    def did_change_configuration(ls, params: T.DidChangeConfigurationParams):
        configure(params.settings)
        _refresh(ls)

    @server.feature("aidl/explain")
    @safe()
    def aidl_explain(ls, params):
        code = params.get("code") if isinstance(params, dict) else getattr(params, "code", None)
        try:
            return explain(code)
        except KeyError as e:
            raise failed(e.args[0]) from None


def forget(uri: str) -> None:
    """Drop what is kept for a closed document."""
    _programs.pop(uri, None)
    _shown.pop(uri, None)


def dof_hover(uri: str, d, path: str, line: int, character: int, f: dict | None) -> str | None:
    """Markdown for a hover on a structure's name: its degrees of freedom (the code lens text)."""
    if not f or len(d.source) > window.LARGE:
        return None
    for L in hints.code_lenses(d.source, program_of(uri, d, path), f):
        r = L["range"]
        if r["start"]["line"] == line and r["start"]["character"] <= character <= r["end"]["character"]:
            return f"degrees of freedom: **{L['command']['title']}**"
    return None


def _refresh(ls) -> None:
    """Ask the client to re-request inlay hints and code lenses, when it can."""
    caps = getattr(ls, "client_capabilities", None)
    ws = getattr(caps, "workspace", None)
    try:
        if ws is not None and ws.inlay_hint is not None and ws.inlay_hint.refresh_support:
            ls.workspace_inlay_hint_refresh(None)
        if ws is not None and ws.code_lens is not None and ws.code_lens.refresh_support:
            ls.workspace_code_lens_refresh(None)
    except Exception:
        pass


_shown: dict[str, object] = {}        # uri -> the facts hints and lenses were last refreshed for


def refresh(ls, uri: str, facts) -> None:
    """After an analysis of ``uri``: ask for fresh hints and lenses if either is on and the
    solved facts changed."""
    if (settings["inlayHints"] or settings["codeLens"]) and _shown.get(uri) != facts:
        _shown[uri] = facts
        _refresh(ls)
