"""Outputs: the solved model through Manifold booleans (:mod:`.booleans`) to the one exact
output model (:mod:`.part`: lines, arcs, circles per part, engraving), the writers (:mod:`.svg`,
:mod:`.dxf`, :mod:`.png`, :mod:`.mesh`, :mod:`.step`, by extension in :mod:`.formats`) and the geometry
checks on the final shape (:mod:`.checks`).  docs/outputs.md describes them.

The names below are imported on first use (PEP 562), so ``aidl check``, which needs only the
booleans and the checks, never loads the writers (issue 12: cold start)."""
from __future__ import annotations

import importlib

_WHERE = {"Drawing": "booleans", "Part": "booleans", "area": "booleans",
          "render_model": "booleans", "to_svg": "svg", "Output": "part", "build": "part",
          "MissingDependency": "part", "OutputError": "part", "FORMATS": "formats",
          "Options": "formats", "encode": "formats", "CUT_FORMATS": "formats",
          "for_cutting": "formats"}

__all__ = list(_WHERE)


def __getattr__(name: str):
    module = _WHERE.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(_WHERE))
