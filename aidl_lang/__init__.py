"""AIDL, a solver-aided hierarchical language for 2D CAD.

The public Python API (docs/api.md) is :func:`compile` and what it returns
(:class:`Result`, :class:`Value`, :class:`PartInfo`, :class:`Layout`), and :func:`set_params`
(param values rewritten in a program's text), from :mod:`aidl_lang.api`; it is
imported on first use (PEP 562), so ``import aidl_lang.cli`` stays as quick as before.
"""
from __future__ import annotations

_API = ("compile", "Result", "Value", "PartInfo", "Layout", "NotCompiled", "WriteError",
        "set_params", "ParamsRefused")

__all__ = list(_API)


def __getattr__(name: str):
    if name in _API:
        from . import api
        value = getattr(api, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
