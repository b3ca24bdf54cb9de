"""`aidl lsp`: a `shutdown` that arrives while a document's diagnostics are still running
cancels them quietly (issue 58: the editor showed "aidl lsp: internal error in diagnostics"
with `EOFError: the analysis worker exited`, the worker having been stopped by the shutdown).
The server's own handlers, with an analysis that is still running when shutdown comes."""
import asyncio

import pytest

from aidl_lang.editor.lsp import server as S


class _Doc:
    version, source, path = 1, "solid s {\n}\n", "/tmp/large.aidl"


class _Workspace:
    """pygls' Workspace as the server uses it: every document asked for is open."""

    class _Open(dict):
        def __contains__(self, uri):
            return True

    text_documents = _Open()

    def get_text_document(self, uri):
        return _Doc()


class _Client:
    """What the server may say to the editor: every log or window message is kept."""

    def __init__(self):
        self.workspace = _Workspace()
        self.said = []

    def window_log_message(self, params):
        self.said.append(params.message)

    def window_show_message(self, params):
        self.said.append(params.message)

    def text_document_publish_diagnostics(self, params):
        self.said.append("published")


class _SlowAnalyzer:
    """A worker busy with a large document; closing it (shutdown) ends the job with the
    EOFError the real worker's reader gives (worker.Analyzer._reader)."""

    def __init__(self):
        self.stopped = asyncio.Event()
        self.facts, self.values = {}, {}

    async def diagnostics(self, text, path, uri, solve=True):
        await self.stopped.wait()
        raise EOFError("the analysis worker exited")

    def close(self):
        self.stopped.set()


@pytest.mark.asyncio
async def test_shutdown_during_an_analysis_says_nothing(monkeypatch):
    slow = _SlowAnalyzer()
    monkeypatch.setattr(S, "_analyzer", slow)
    monkeypatch.setattr(S, "_get_analyzer", lambda: slow)
    monkeypatch.setattr(S, "_closing", False, raising=False)
    monkeypatch.setattr(S, "_pending", {})
    ls = _Client()
    S._schedule(ls, "file:///tmp/large.aidl", 0.0)
    await asyncio.sleep(0.05)                   # the analysis is under way
    await S.shutdown(ls, None)
    await asyncio.sleep(0.1)                    # what the cancelled job would still say
    assert ls.said == [], ls.said
    S._schedule(ls, "file:///tmp/other.aidl", 0.0)   # after shutdown: nothing starts
    assert S._pending == {}
