"""``aidl mcp``: AIDL for agents over the Model Context Protocol (docs/mcp.md).

:mod:`.tools` holds what the tools do (over :mod:`aidl_lang.api`, no protocol code) and the
allowed-folder rules, :mod:`.wording` the messages' wording for agents; :mod:`.server` exposes
them with the official ``mcp`` SDK (the ``mcp`` extra: ``pip install 'aidl-lang[mcp]'``),
with the result shapes of :mod:`.schemas`, running the compiling tools in the worker
processes of :mod:`.worker`.
"""
