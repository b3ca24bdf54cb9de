"""``aidl lsp``: the language server (pygls, JSON-RPC over stdin/stdout).

Thin handlers over :mod:`aidl_lang.lsp.analysis`. Diagnostics are published when a document
is opened or saved, and after each change once typing pauses for :data:`DEBOUNCE` seconds (the
full pipeline, solve included: about 20-200 ms on the bundled examples). Every handler is
wrapped so that an exception in the analysis is logged to the client and answered with an
empty result: a malformed document never stops the server.
"""
from __future__ import annotations

import asyncio
import functools
import logging
import traceback

from lsprotocol import types as T
from pygls.lsp.server import LanguageServer

from . import analysis

DEBOUNCE = 0.3          # seconds of quiet after a change before diagnostics are recomputed

log = logging.getLogger("aidl.lsp")
server = LanguageServer("aidl", "0.1.0", text_document_sync_kind=T.TextDocumentSyncKind.Full)
_pending: dict[str, asyncio.Task] = {}


def _safe(default=None):
    def wrap(fn):
        if asyncio.iscoroutinefunction(fn):
            @functools.wraps(fn)
            async def run_async(ls, params):
                try:
                    return await fn(ls, params)
                except asyncio.CancelledError:
                    raise
                except Exception:          # never let the analysis take the server down
                    _report(ls, fn.__name__)
                    return default
            return run_async

        @functools.wraps(fn)
        def run(ls, params):
            try:
                return fn(ls, params)
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


def _doc(ls: LanguageServer, uri: str):
    doc = ls.workspace.get_text_document(uri)
    return doc, (doc.path or "untitled.aidl")


async def _publish(ls: LanguageServer, uri: str, delay: float = 0.0) -> None:
    if delay:
        await asyncio.sleep(delay)
    doc, path = _doc(ls, uri)
    version, text = doc.version, doc.source
    diags = await asyncio.get_running_loop().run_in_executor(
        None, functools.partial(analysis.diagnostics, text, path, True, uri))
    doc, _ = _doc(ls, uri)
    if doc.version != version or doc.source != text:
        return                      # stale: a newer change will publish
    ls.text_document_publish_diagnostics(
        T.PublishDiagnosticsParams(uri=uri, diagnostics=diags, version=version))


def _schedule(ls: LanguageServer, uri: str, delay: float) -> None:
    old = _pending.pop(uri, None)
    if old is not None:
        old.cancel()

    async def run():
        try:
            await _publish(ls, uri, delay)
        except asyncio.CancelledError:
            pass
        except Exception:
            _report(ls, "diagnostics")
    _pending[uri] = asyncio.ensure_future(run())


@server.feature(T.TEXT_DOCUMENT_DID_OPEN)
@_safe()
def did_open(ls: LanguageServer, params: T.DidOpenTextDocumentParams):
    _schedule(ls, params.text_document.uri, 0.0)


@server.feature(T.TEXT_DOCUMENT_DID_CHANGE)
@_safe()
def did_change(ls: LanguageServer, params: T.DidChangeTextDocumentParams):
    _schedule(ls, params.text_document.uri, DEBOUNCE)


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
    ls.text_document_publish_diagnostics(
        T.PublishDiagnosticsParams(uri=params.text_document.uri, diagnostics=[]))


@server.feature(T.TEXT_DOCUMENT_HOVER)
@_safe()
def hover(ls: LanguageServer, params: T.HoverParams):
    doc, path = _doc(ls, params.text_document.uri)
    return analysis.hover(doc.source, params.position.line, params.position.character, path)


@server.feature(T.TEXT_DOCUMENT_COMPLETION, T.CompletionOptions(trigger_characters=["."]))
@_safe([])
def completion(ls: LanguageServer, params: T.CompletionParams):
    doc, path = _doc(ls, params.text_document.uri)
    return analysis.completions(doc.source, params.position.line, params.position.character, path)


@server.feature(T.TEXT_DOCUMENT_DEFINITION)
@_safe()
def definition(ls: LanguageServer, params: T.DefinitionParams):
    doc, path = _doc(ls, params.text_document.uri)
    return analysis.definition(doc.source, params.position.line, params.position.character,
                               params.text_document.uri, path)


@server.feature(T.TEXT_DOCUMENT_REFERENCES)
@_safe([])
def references(ls: LanguageServer, params: T.ReferenceParams):
    doc, path = _doc(ls, params.text_document.uri)
    return analysis.references(doc.source, params.position.line, params.position.character,
                               params.text_document.uri, params.context.include_declaration, path)


@server.feature(T.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
@_safe([])
def document_symbol(ls: LanguageServer, params: T.DocumentSymbolParams):
    doc, path = _doc(ls, params.text_document.uri)
    return analysis.document_symbols(doc.source, path)


@server.feature(T.TEXT_DOCUMENT_FORMATTING)
@_safe([])
def formatting(ls: LanguageServer, params: T.DocumentFormattingParams):
    doc, path = _doc(ls, params.text_document.uri)
    return analysis.formatting(doc.source, path)


def main() -> int:
    """Serve over stdin/stdout until the client exits."""
    logging.basicConfig(level=logging.WARNING)
    server.start_io()
    return 0
