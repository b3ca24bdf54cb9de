"""Outputs: the solved model through Manifold booleans (:mod:`.booleans`) to the one exact
output model (:mod:`.part`: lines, arcs, circles per part, engraving), the writers (one module
per format in :mod:`.writers`, behind its registry :data:`~.writers.FORMATS`), the cutting
layout and kerf offset (:mod:`.layout`), the assembled product (:mod:`.assembly`) and the
geometry checks on the final shape (:mod:`.checks`).  docs/outputs.md describes them.

Importing it loads the modules of the names below but no writer library: the registry imports
a writer module (with ``ezdxf``, ``cairosvg``, ``trimesh``, OCP) when that format is written,
and :func:`.writers.svg.to_svg` imports ``svgwrite`` when it is called.
(Until issue 27 these names were resolved on first use by a PEP 562 ``__getattr__``: 1.5-3%
of a cold ``aidl check``'s instructions, under the 5% rule's bar; docs/dev/performance.md.)"""
from __future__ import annotations

from .booleans import Drawing, Part, area, render_model
from .layout import for_cutting
from .part import MissingDependency, Output, OutputError, build
from .writers import ASSEMBLED_FORMATS, CUT_FORMATS, FORMATS, TEXT_FORMATS, Options, encode
from .writers.svg import to_svg

__all__ = ["Drawing", "Part", "area", "render_model", "to_svg", "Output", "build",
           "MissingDependency", "OutputError", "FORMATS", "Options", "encode", "CUT_FORMATS",
           "ASSEMBLED_FORMATS", "TEXT_FORMATS", "for_cutting"]
