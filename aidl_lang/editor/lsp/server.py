"""``aidl lsp``: the language server (pygls, JSON-RPC over stdin/stdout).

Thin handlers over :mod:`.analysis` (hover, completion, definition, references, outline,
formatting), :mod:`.semantic` (semantic tokens), :mod:`.signature` (signature help),
:mod:`.edits` (quick fixes, rename) and :mod:`.features` (inlay hints, code lenses, folding,
highlight, links, workspace symbols, ``aidl/explain``). Documents sync incrementally.
``aidl lsp`` starts in :mod:`.boot`, which answers ``initialize`` and publishes the first
diagnostics before this module (pygls) is imported, then calls :func:`main`.

Diagnostics are computed by a worker process (:mod:`.worker`) so that a newer version of a
document stops a stale analysis: they are published when a document is opened or saved, and
after each change once typing pauses for :data:`DEBOUNCE` seconds (``initializationOptions``
``{"debounce": seconds}`` changes it; 0 analyses every change).

Every handler is guarded: an exception in the analysis is logged to the client and answered
with an empty result, so a malformed document never stops the server. A request whose
parameters do not match the protocol gets the JSON-RPC error ``-32602`` (invalid params)
naming the field. Documents over :data:`.window.LARGE` characters are analysed through a view
(:mod:`.window`) so that no request takes minutes.
"""
from __future__ import annotations

import asyncio
import functools
import logging
import re
import traceback

from lsprotocol import converters
from lsprotocol import types as T
from pygls.exceptions import JsonRpcException, JsonRpcInternalError, JsonRpcInvalidParams
from pygls.lsp.server import LanguageServer
from pygls.protocol import LanguageServerProtocol
from pygls.protocol.language_server import lsp_method
from pygls.workspace import TextDocument

from ...base.diagnostics import as_lf
from ..fmt import newline_of
from . import analysis, edits, features, preview, semantic, signature, window
from .worker import AnalysisTimeout, Analyzer

DEBOUNCE = 0.3          # seconds of quiet after a change before diagnostics are recomputed

log = logging.getLogger("aidl.lsp")


class RequestFailed(JsonRpcException):
    """LSP ``RequestFailed`` (-32803): a valid request the server refuses (e.g. a rename of a
    built-in name), with the reason shown to the user."""
    code = -32803


class Protocol(LanguageServerProtocol):
    """pygls' protocol, plus an error response for a request whose params do not structure,
    and positions always in UTF-16 (what :mod:`.analysis` counts; pygls would otherwise pick
    the client's first preference, e.g. Neovim's UTF-8)."""

    @lsp_method(T.INITIALIZE)
    def lsp_initialize(self, params: T.InitializeParams):
        if params.capabilities.general is not None:
            params.capabilities.general.position_encodings = None
        return (yield from super().lsp_initialize(params))

    def structure_message(self, data):
        try:
            return super().structure_message(data)
        except (JsonRpcInvalidParams, JsonRpcInternalError) as exc:
            if isinstance(data, dict) and "id" in data and "method" in data:
                err = JsonRpcInvalidParams(_why(exc))
                self._send_response(data["id"], None, err.to_response_error())
            raise


def _why(exc: Exception) -> str:
    cause = exc.__cause__
    try:
        from cattrs import transform_error
        details = transform_error(cause) if cause is not None else []
    except Exception:
        details = []
    return "invalid params: " + ("; ".join(details) if details else str(cause or exc))


server = LanguageServer("aidl", "0.2.0", text_document_sync_kind=T.TextDocumentSyncKind.Incremental,
                        protocol_cls=Protocol)
_pending: dict[str, asyncio.Task] = {}
_published: dict[str, list[T.Diagnostic]] = {}      # uri -> the diagnostics last published
_settings = {"debounce": DEBOUNCE}
_analyzer: Analyzer | None = None
_closing = False          # set by shutdown: pending analyses end quietly
_early: dict = {}          # uri -> (version, text, worker answer) from :mod:`.boot`
_newline: dict[str, str] = {}   # uri -> the line ending the client's text has first


def _get_analyzer() -> Analyzer:
    global _analyzer
    if _analyzer is None:
        _analyzer = Analyzer()
    return _analyzer


def _safe(default=None):
    def wrap(fn):
        if asyncio.iscoroutinefunction(fn):
            @functools.wraps(fn)
            async def run_async(ls, params):
                try:
                    return await fn(ls, params)
                except (asyncio.CancelledError, JsonRpcException):
                    raise
                except NotOpen:
                    return default
                except Exception:          # never let the analysis take the server down
                    _report(ls, fn.__name__)
                    return default
            return run_async

        @functools.wraps(fn)
        def run(ls, params):
            try:
                return fn(ls, params)
            except JsonRpcException:
                raise
            except NotOpen:
                return default
            except Exception:
                _report(ls, fn.__name__)
                return default
        return run
    return wrap


def _report(ls: LanguageServer, where: str) -> None:
    msg = f"aidl lsp: internal error in {where}:\n{traceback.format_exc()}"
    log.error(msg)
    try:
        ls.window_log_message(T.LogMessageParams(type=T.MessageType.Error, message=msg))
    except Exception:
        pass


class NotOpen(Exception):
    """A request about a document the client never opened (or has closed): answered with
    the request's empty answer (no hover, no completions), not as an internal error."""


def _doc(ls: LanguageServer, uri: str):
    """The open document ``uri`` and its path; :class:`NotOpen` when it is not open."""
    if uri not in ls.workspace.text_documents:
        raise NotOpen(uri)
    doc = ls.workspace.get_text_document(uri)
    return doc, (doc.path or "untitled.aidl")


def _at(ls: LanguageServer, params):
    """(text to analyse, path, line, character) for a position request: the document, or its
    view around the position when it is large (same line and column numbers)."""
    doc, path = _doc(ls, params.text_document.uri)
    line, ch = params.position.line, params.position.character
    return window.view(doc.source, line), path, line, ch


async def _publish(ls: LanguageServer, uri: str, delay: float = 0.0) -> None:
    if delay:
        await asyncio.sleep(delay)
    doc, path = _doc(ls, uri)
    version, text = doc.version, doc.source
    try:
        raw = await _get_analyzer().diagnostics(text, path, uri, True)
        diags = converters.get_converter().structure(raw, list[T.Diagnostic])
    except AnalysisTimeout as e:
        diags = [T.Diagnostic(
            range=T.Range(start=T.Position(line=0, character=0), end=T.Position(line=0, character=1)),
            message=f"aidl lsp: {e}; stopped (run `aidl check` for the full report)",
            severity=T.DiagnosticSeverity.Warning, source="aidl")]
    doc, _ = _doc(ls, uri)
    if doc.version != version or doc.source != text:
        return                      # stale: a newer change will publish
    _published[uri] = diags
    ls.text_document_publish_diagnostics(
        T.PublishDiagnosticsParams(uri=uri, diagnostics=diags, version=version))
    features.refresh(ls, uri, _get_analyzer().facts.get(uri))   # hints and lenses, if changed


def _schedule(ls: LanguageServer, uri: str, delay: float) -> None:
    old = _pending.pop(uri, None)
    if old is not None:
        old.cancel()                # abandons its analysis (see worker.Analyzer)

    async def run():
        try:
            await _publish(ls, uri, delay)
        except (asyncio.CancelledError, NotOpen):      # closed meanwhile: nothing to say
            pass
        except Exception:
            if not _closing:        # after shutdown, a job whose worker was stopped: quiet
                _report(ls, "diagnostics")
    if _closing:
        return
    _pending[uri] = asyncio.ensure_future(run())


@server.feature(T.INITIALIZED)
@_safe()
async def initialized(ls: LanguageServer, params: T.InitializedParams):
    _get_analyzer().start()                # adopt the worker started with the server


@server.feature(T.INITIALIZE)
@_safe()
def initialize(ls: LanguageServer, params: T.InitializeParams):
    # the workspace pygls has just made keeps each document as a _Document
    ls.workspace._create_text_document = functools.partial(_Document.made_by, ls.workspace)
    opts = params.initialization_options
    if isinstance(opts, dict) and isinstance(opts.get("debounce"), (int, float)):
        _settings["debounce"] = max(0.0, float(opts["debounce"]))
    features.configure(opts)


@server.feature(T.SHUTDOWN)
@_safe()
async def shutdown(ls: LanguageServer, params):
    """Cancel every pending analysis quietly (a large document's diagnostics may still be
    running: its worker is stopped, and that is no error to show), then stop the workers."""
    global _closing
    _closing = True
    for task in list(_pending.values()):
        task.cancel()
    _pending.clear()
    if _analyzer is not None:
        _analyzer.close()


class _Document(TextDocument):
    """pygls' document with the lines a client counts, ended by CR LF, a lone CR or LF only
    (:data:`aidl_lang.base.diagnostics.LINE_BREAK`): pygls splits with ``str.splitlines``, which
    also breaks at a form feed, a vertical tab, U+001C-U+001E, U+0085, U+2028 and U+2029, so
    an edit on a line after one of them (in a comment, in a string) landed a line late."""

    @property
    def lines(self) -> tuple[str, ...]:
        return tuple(_LINE.findall(self.source))

    @classmethod
    def made_by(cls, workspace, doc_uri: str, source=None, version=None, language_id=None):
        """What ``Workspace._create_text_document`` makes, as a :class:`_Document`."""
        return cls(doc_uri, source=source, version=version, language_id=language_id,
                   sync_kind=workspace._sync_kind, position_codec=workspace._position_codec)


_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z")     # a line with its break


def _lines_as_lf(ls: LanguageServer, uri: str) -> None:
    """After pygls applied an open or a change: the document as the server reads it has each
    lone CR as LF (:func:`aidl_lang.base.diagnostics.as_lf`: the same lines, columns and offsets as
    the client's, whose lines end at CR LF, CR or LF), so every feature counts lines as the
    client does; the line ending its formatting writes is kept (the client's first)."""
    doc = ls.workspace.get_text_document(uri)
    text = doc.source
    _newline[uri] = newline_of(text)
    if "\r" in text:
        doc._source = as_lf(text)


@server.feature(T.TEXT_DOCUMENT_DID_OPEN)
@_safe()
def did_open(ls: LanguageServer, params: T.DidOpenTextDocumentParams):
    d = params.text_document
    _lines_as_lf(ls, d.uri)
    early = _early.pop(d.uri, None)           # analysed by the start-up front already
    if early is not None and early[0] == d.version and early[1] == d.text:
        answer = early[2]
        _published[d.uri] = converters.get_converter().structure(answer["diagnostics"],
                                                                 list[T.Diagnostic])
        _get_analyzer().values[d.uri] = answer.get("values") or {}
        if answer.get("facts"):
            _get_analyzer().facts[d.uri] = answer["facts"]
        features.refresh(ls, d.uri, answer.get("facts"))
        return
    _schedule(ls, d.uri, 0.0)


@server.feature(T.TEXT_DOCUMENT_DID_CHANGE)
@_safe()
def did_change(ls: LanguageServer, params: T.DidChangeTextDocumentParams):
    _lines_as_lf(ls, params.text_document.uri)
    _get_analyzer().editing = True         # a warm spare worker is worth its start from now on
    _schedule(ls, params.text_document.uri, _settings["debounce"])


@server.feature(T.TEXT_DOCUMENT_DID_SAVE)
@_safe()
def did_save(ls: LanguageServer, params: T.DidSaveTextDocumentParams):
    _schedule(ls, params.text_document.uri, 0.0)


@server.feature(T.TEXT_DOCUMENT_DID_CLOSE)
@_safe()
def did_close(ls: LanguageServer, params: T.DidCloseTextDocumentParams):
    old = _pending.pop(params.text_document.uri, None)
    if old is not None:
        old.cancel()
    _published.pop(params.text_document.uri, None)
    _newline.pop(params.text_document.uri, None)
    features.forget(params.text_document.uri)
    preview.SERVER_GOOD.forget(params.text_document.uri)
    if _analyzer is not None:
        _analyzer.facts.pop(params.text_document.uri, None)
    ls.text_document_publish_diagnostics(
        T.PublishDiagnosticsParams(uri=params.text_document.uri, diagnostics=[]))


@server.feature(T.TEXT_DOCUMENT_HOVER)
@_safe()
def hover(ls: LanguageServer, params: T.HoverParams):
    src, path, line, ch = _at(ls, params)
    h = analysis.hover(src, line, ch, path)
    values = _analyzer.values.get(params.text_document.uri) if _analyzer is not None else None
    solved = analysis.value_hover(src, line, ch, values, path) if values else None
    dof = features.dof_hover(params.text_document.uri, _doc(ls, params.text_document.uri)[0], path,
                             line, ch, _analyzer.facts.get(params.text_document.uri)
                             if _analyzer is not None else None)
    if dof is not None:
        solved = dof if solved is None else f"{solved}\n\n{dof}"
    if solved is None:
        return h
    if h is None:
        return T.Hover(contents=T.MarkupContent(kind=T.MarkupKind.Markdown, value=solved))
    return T.Hover(contents=T.MarkupContent(kind=T.MarkupKind.Markdown,
                                            value=f"{h.contents.value}\n\n---\n{solved}"),
                   range=h.range)


@server.feature(T.TEXT_DOCUMENT_COMPLETION, T.CompletionOptions(trigger_characters=["."]))
@_safe([])
def completion(ls: LanguageServer, params: T.CompletionParams):
    src, path, line, ch = _at(ls, params)
    return analysis.completions(src, line, ch, path)


@server.feature(T.TEXT_DOCUMENT_SIGNATURE_HELP,
                T.SignatureHelpOptions(trigger_characters=["(", ","], retrigger_characters=["="]))
@_safe()
def signature_help(ls: LanguageServer, params: T.SignatureHelpParams):
    src, path, line, ch = _at(ls, params)
    return signature.signature_help(src, line, ch, path)


@server.feature(T.TEXT_DOCUMENT_DEFINITION)
@_safe()
def definition(ls: LanguageServer, params: T.DefinitionParams):
    src, path, line, ch = _at(ls, params)
    return analysis.definition(src, line, ch, params.text_document.uri, path)


@server.feature(T.TEXT_DOCUMENT_REFERENCES)
@_safe([])
def references(ls: LanguageServer, params: T.ReferenceParams):
    src, path, line, ch = _at(ls, params)
    return analysis.references(src, line, ch, params.text_document.uri,
                               params.context.include_declaration, path)


@server.feature(T.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
@_safe([])
def document_symbol(ls: LanguageServer, params: T.DocumentSymbolParams):
    doc, path = _doc(ls, params.text_document.uri)
    if len(doc.source) > window.LARGE:
        return window.outline(doc.source)
    return analysis.document_symbols(doc.source, path)


def _too_large(doc, what: str) -> None:
    if len(doc.source) > window.LARGE:
        raise RequestFailed(f"aidl lsp: {what} is not offered for documents over "
                            f"{window.LARGE} characters (this one has {len(doc.source)}); "
                            f"use `aidl fmt` / edit by hand")


@server.feature(T.TEXT_DOCUMENT_FORMATTING)
@_safe([])
def formatting(ls: LanguageServer, params: T.DocumentFormattingParams):
    doc, path = _doc(ls, params.text_document.uri)
    _too_large(doc, "formatting")
    return analysis.formatting(doc.source, path, _newline.get(params.text_document.uri))


@server.feature(T.TEXT_DOCUMENT_CODE_ACTION,
                T.CodeActionOptions(code_action_kinds=[T.CodeActionKind.QuickFix]))
@_safe([])
def code_action(ls: LanguageServer, params: T.CodeActionParams):
    uri = params.text_document.uri
    published = _published.get(uri, [])
    diags = []
    for d in params.context.diagnostics or _overlapping(published, params.range):
        if not isinstance(d.data, dict):          # a client that does not echo `data`
            d = next((p for p in published if p.range == d.range and p.code == d.code), d)
        diags.append(d)
    return edits.code_actions(uri, diags, params.range)


def _overlapping(diags: list[T.Diagnostic], rng: T.Range) -> list[T.Diagnostic]:
    def key(p: T.Position):
        return (p.line, p.character)
    return [d for d in diags if key(d.range.start) <= key(rng.end) and key(rng.start) <= key(d.range.end)]


@server.feature(T.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL,
                T.SemanticTokensLegend(token_types=semantic.TOKEN_TYPES,
                                       token_modifiers=semantic.TOKEN_MODIFIERS))
@_safe()
def semantic_tokens(ls: LanguageServer, params: T.SemanticTokensParams):
    doc, path = _doc(ls, params.text_document.uri)
    n = len(doc.source)
    if n > window.HUGE:
        return None
    return T.SemanticTokens(data=semantic.semantic_tokens(doc.source, path,
                                                          lexical=n > window.LARGE))


@server.feature(T.TEXT_DOCUMENT_PREPARE_RENAME)
@_safe()
def prepare_rename(ls: LanguageServer, params: T.PrepareRenameParams):
    doc, path = _doc(ls, params.text_document.uri)
    _too_large(doc, "rename")
    try:
        return edits.prepare_rename(doc.source, params.position.line, params.position.character,
                                    path)
    except edits.RenameError as e:
        raise RequestFailed(str(e)) from None


@server.feature(T.TEXT_DOCUMENT_RENAME)
@_safe()
def rename(ls: LanguageServer, params: T.RenameParams):
    doc, path = _doc(ls, params.text_document.uri)
    _too_large(doc, "rename")
    opened = {}
    for uri, d in ls.workspace.text_documents.items():
        if d.path and uri != params.text_document.uri:
            opened[d.path] = d.source
    try:
        return edits.rename(doc.source, params.position.line, params.position.character,
                            params.new_name, params.text_document.uri, path, opened)
    except edits.RenameError as e:
        raise RequestFailed(str(e)) from None


features.register(server, _safe, _doc,
                  lambda uri: _analyzer.facts.get(uri) if _analyzer is not None else None,
                  RequestFailed)


@server.feature("aidl/preview")
@_safe()
async def aidl_preview(ls: LanguageServer, params):
    """The editor preview's picture of a document (:mod:`.preview`), compiled by the
    diagnostics' worker process."""
    return await preview.handle(ls, params, _get_analyzer())


def main(worker=None, stdin=None, stdout=None, published: dict | None = None,
         hold=None, early: dict | None = None) -> int:
    """Serve over stdin/stdout (or the streams given: :mod:`.boot` passes its own) until the
    client exits. ``worker``: a diagnostics worker process started before this module was
    imported (:func:`.worker.spawn`), so it warms up meanwhile. ``published``: uri -> the
    diagnostics (LSP dicts) already published for it (by :mod:`.boot`), for quick fixes;
    ``hold``: an event set once :mod:`.boot` has read the answer to the job it gave ``worker``;
    ``early``: uri -> (version, text, that answer), filled by :mod:`.boot` when it comes (a
    ``didOpen`` of that version and text is then not analysed again)."""
    global _analyzer, _early
    logging.basicConfig(level=logging.WARNING)
    _analyzer = Analyzer(worker, hold)
    if early is not None:
        _early = early
    conv = converters.get_converter()
    for uri, diags in list((published or {}).items()):
        _published.setdefault(uri, conv.structure(diags, list[T.Diagnostic]))
    try:
        server.start_io(stdin, stdout)
    finally:
        _analyzer.close()
    return 0
