"""The ``aidl`` command line (thin: it parses arguments and calls the stages).

:mod:`.main` holds ``render``, ``check``, ``explain``, ``fmt`` and ``lsp``; :mod:`.llm` adds
``prompt``, ``generate`` and ``eval``.
"""
from .main import main

__all__ = ["main"]
