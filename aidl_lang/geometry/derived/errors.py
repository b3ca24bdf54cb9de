"""The error of a bad operation call (:class:`OperationError`), shared by the operations and
the corners a ``Fillet(at, ...)`` names."""
from __future__ import annotations


class OperationError(Exception):
    """A bad operation call; the message is the diagnostic text (code E0108)."""
