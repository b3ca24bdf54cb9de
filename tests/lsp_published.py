"""Every ``textDocument/publishDiagnostics`` a pytest-lsp client receives, kept in order.

pytest-lsp's ``wait_for_notification`` hands a notification to the one future registered
when it arrives and drops it when none is: two publishes read from the pipe together (a
loaded machine) give the first to the waiting loop and the second to nobody, and a loop
that waits for that second one then waits for ever (a full run once sat five minutes in
test_lsp_same_as_check).  :func:`keep` records every publish as it is handled;
:func:`published` looks through the record instead of waiting for the next notification.
"""
from __future__ import annotations

import asyncio

import pytest
from lsprotocol import types as T


def keep(client) -> None:
    """Record every publishDiagnostics ``client`` (a pytest-lsp LanguageClient) receives in
    ``client.published`` (PublishDiagnosticsParams, in the order received)."""
    client.published = []
    handle = client.protocol._handle_notification

    def recording(method, params):
        if method == T.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS:
            client.published.append(params)
        handle(method, params)
    client.protocol._handle_notification = recording


def mark(client) -> int:
    """Where the record stands: pass it as ``since`` to look only at what comes after."""
    return len(client.published)


async def published(client, uri: str, version: int | None = None, *, since: int | None = None,
                    where=lambda p: True, timeout: float = 240.0) -> list[T.Diagnostic]:
    """The diagnostics of the first publish for ``uri`` (of ``version`` if given, and for
    which ``where(params)`` holds) at index ``since`` of the record or after (default: the
    next one from now, as ``wait_for_notification`` would).  Fails the test naming ``uri``
    after ``timeout`` seconds without it (wall time: a guard against a hang, not a measure)."""
    start = mark(client) if since is None else since
    loop = asyncio.get_running_loop()
    end = loop.time() + timeout
    while True:
        for p in client.published[start:]:
            if p.uri == uri and (version is None or p.version == version) and where(p):
                return p.diagnostics
        if loop.time() > end:
            pytest.fail(f"no diagnostics published for {uri}"
                        + (f" (version {version})" if version is not None else "")
                        + f" in {timeout:g} s")
        await asyncio.sleep(0.01)
