"""The stdio transport of ``aidl mcp`` with JSON-RPC 2.0's answers to lines that are no message.

The SDK's ``stdio_server`` reads one JSON-RPC message a line and drops, without a word, a line
it cannot read (invalid JSON, ``[]``, a batch, a number) and reads a request whose id is no
string or integer (``{}``, ``true``, ``1.5``, ``null``) as a notification, so a client waits
forever.  JSON-RPC 2.0 (section 5) wants an error response with ``"id": null`` instead:
-32700 Parse error for invalid JSON, -32600 Invalid Request for anything else that is no
message (MCP 2025-06-18 removed batches: a batch is an Invalid Request too).

:func:`serve` hands the SDK's ``stdio_server`` a stdin of its own (:class:`CheckedLines`)
that passes each well-formed line on and answers the others through the SDK's own writer
(one writer: frames never tear), so the SDK is used as it is, not forked.
"""
from __future__ import annotations

import json
import os
from collections.abc import AsyncIterator
from contextlib import contextmanager
from io import TextIOWrapper

import anyio
import mcp_types as types
from mcp.server.stdio import stdio_server
from mcp.shared.message import SessionMessage
from mcp_types import INVALID_REQUEST, PARSE_ERROR


def rejection(line: str) -> types.ErrorData | None:
    """Why one line of stdin is no JSON-RPC message MCP takes, or None when it is one.

    -32700 Parse error: not JSON (NaN and Infinity are not), or nested deeper than Python's
    recursion limit.  -32600 Invalid Request: JSON but not one message object
    (an array: ``[]`` or a batch; a number, string, ...), an id that is no string or integer
    (MCP's RequestId; a bool, float, object, array or null), or an object no JSON-RPC message
    shape fits (``jsonrpc`` not "2.0", ``method`` not a string, ...).  A response (``result``
    or ``error``, no ``method``) is passed on as it is: a response is never answered.
    """
    try:
        doc = json.loads(line, parse_constant=_not_json)
    except ValueError as exc:
        return types.ErrorData(code=PARSE_ERROR, message=f"Parse error: the line is not JSON ({exc})")
    except RecursionError:      # RFC 8259, section 9: a parser may limit the nesting
        return types.ErrorData(code=PARSE_ERROR, message="Parse error: the line's JSON is "
                                                         "nested too deep")
    if isinstance(doc, list):
        what = "an empty array" if not doc else f"a batch of {len(doc)}"
        return types.ErrorData(code=INVALID_REQUEST, message=(
            f"Invalid Request: {what}; MCP (2025-06-18) takes no batches: send one JSON-RPC "
            f"message object per line"))
    if not isinstance(doc, dict):
        return types.ErrorData(code=INVALID_REQUEST, message=(
            f"Invalid Request: a JSON {_JSON_TYPES[type(doc)]}, not a JSON-RPC message "
            f"object"))
    if "method" not in doc and ("result" in doc or "error" in doc):
        return None     # a response (its id may be null): never answered, or two peers
        #                 as strict as this one would answer each other's answers forever
    if "id" in doc and not _is_request_id(doc["id"]):
        return types.ErrorData(code=INVALID_REQUEST, message=(
            f"Invalid Request: the id {json.dumps(doc['id'])} is neither a string nor an "
            f"integer"))
    try:
        types.jsonrpc_message_adapter.validate_python(doc, by_name=False)
    except ValueError:
        return types.ErrorData(code=INVALID_REQUEST, message=(
            'Invalid Request: not a JSON-RPC 2.0 message (a request is {"jsonrpc": "2.0", '
            '"id": 1, "method": "...", "params": {...}})'))
    return None


_JSON_TYPES = {int: "number", float: "number", str: "string", bool: "boolean", type(None): "null"}


def _not_json(word: str):
    raise ValueError(f"{word} is not a JSON value")     # Python's json reads NaN, Infinity


def _is_request_id(value) -> bool:
    return isinstance(value, str) or (isinstance(value, int) and not isinstance(value, bool))


class CheckedLines:
    """An async iterable of the stdin lines that are messages, for the SDK's reader; a line
    that is none (:func:`rejection`) is answered on ``answers`` (an error, id null) instead.
    Blank lines are no message and are skipped without an answer.  ``first``: lines read
    before (:mod:`.fast`), given before ``lines``; ``watch``: request id -> the method of each
    ``initialize`` (with its protocol version) and ``tools/list`` passed on, whose answers
    are kept for the next start."""

    def __init__(self, lines, answers: anyio.abc.ObjectSendStream, first: list[str] = (),
                 watch: dict | None = None) -> None:
        self.lines, self.answers = lines, answers
        self.first, self.watch = list(first), watch

    async def _all(self):
        for line in self.first:
            yield line
        async for line in self.lines:
            yield line

    def _note(self, line: str) -> None:
        if self.watch is None or ('"initialize"' not in line and '"tools/list"' not in line):
            return
        msg = json.loads(line)
        params = msg.get("params") if isinstance(msg.get("params"), dict) else {}
        if msg.get("method") == "initialize" and "id" in msg:
            self.watch[msg["id"]] = ("initialize", str(params.get("protocolVersion")))
        elif msg.get("method") == "tools/list" and "id" in msg and not params.get("cursor"):
            self.watch[msg["id"]] = ("tools/list", None)

    async def __aiter__(self) -> AsyncIterator[str]:
        async with self.answers:
            async for line in self._all():
                if not line.strip():
                    continue
                error = rejection(line)
                if error is None:
                    self._note(line)
                    yield line
                else:
                    reply = types.JSONRPCError(jsonrpc="2.0", id=None, error=error)
                    await self.answers.send(SessionMessage(reply))


@contextmanager
def _claimed_stdin():
    """The wire (fd 0) as a private binary file while fd 0 itself reads the null device, as the
    SDK does when it opens stdin itself: a handler or child that reads stdin meets EOF, not the
    client's messages.  fd 0 is restored after; the private copy is left open, since the
    reading thread may still block on it (the SDK's reason too)."""
    wire = os.dup(0)
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.close(null)
    try:
        yield os.fdopen(wire, "rb", closefd=False)
    finally:
        os.dup2(wire, 0)


async def serve(lowlevel, options, first=None) -> None:
    """Serve the SDK's low-level server ``lowlevel`` over stdin/stdout until stdin closes, every
    line that is no message answered as JSON-RPC 2.0 says (:func:`rejection`).  ``first``:
    ``(lines read, ids answered, keep, kept answers)`` from :mod:`.fast`: those lines are
    read first, the SDK's answers to those ids are dropped, and its answers to
    ``initialize`` and ``tools/list`` are given to ``keep`` for the next start."""
    read_first, answered, key, kept = first or ([], set(), None, {})
    watch: dict = {}
    answers, rejected = anyio.create_memory_object_stream[SessionMessage](0)
    ours, sent = anyio.create_memory_object_stream[SessionMessage](0)
    with _claimed_stdin() as wire:
        lines = anyio.wrap_file(TextIOWrapper(wire, encoding="utf-8", errors="replace"))
        checked = CheckedLines(lines, answers, read_first, watch if key else None)
        async with stdio_server(stdin=checked) as (read, write):
            async with anyio.create_task_group() as tg:
                tg.start_soon(_forward, rejected, write)
                tg.start_soon(_pass, sent, write, set(answered), watch, key, dict(kept))
                async with ours:
                    await lowlevel.run(read, ours, options)
                tg.cancel_scope.cancel()        # stdin is closed: nothing more to answer
            await write.aclose()                # (the SDK closes the stream it was given)


async def _pass(sent, write, answered: set, watch: dict, key, kept: dict) -> None:
    """Pass the server's messages on to the wire, but its answers to ids :mod:`.fast` answered
    already; keep its answers to ``initialize`` and ``tools/list`` for the next start."""
    async with sent:
        async for reply in sent:
            msg = reply.message
            rid = getattr(msg, "id", None)
            result = getattr(msg, "result", None)
            if rid is not None and not hasattr(msg, "method") and rid in watch:
                what, version = watch.pop(rid)
                if key and isinstance(result, dict):
                    if what == "initialize":
                        inits = dict(kept.get("initialize") or {})
                        inits[version] = result
                        kept["initialize"] = inits
                    else:
                        kept["tools/list"] = result
                    if kept.get("initialize") and kept.get("tools/list"):
                        key(kept)
            if rid is not None and not hasattr(msg, "method") and rid in answered:
                answered.discard(rid)
                continue
            try:
                await write.send(reply)
            except (anyio.ClosedResourceError, anyio.BrokenResourceError):
                return


async def _forward(rejected, write) -> None:
    async with rejected:
        async for reply in rejected:
            try:
                await write.send(reply)
            except (anyio.ClosedResourceError, anyio.BrokenResourceError):
                return
