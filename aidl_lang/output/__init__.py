"""Outputs, one folder per stage of the pipeline below the solver (docs/architecture.md):

* :mod:`.part`: the solved model through Manifold's booleans back onto the exact curves, the
  one exact output model (:class:`~.part.part.Output`: lines, arcs, circles per part);
* :mod:`.checks`: the geometry checks on the final shape (W05xx), the description and parts list;
* :mod:`.fabrication`: layout on sheets and kerf, cut order, machine profiles, the assembled product;
* :mod:`.writers`: one module per format behind its registry :data:`~.writers.FORMATS`, and the
  output-file rules (:mod:`.writers.write`).

The import contract in pyproject.toml orders them: writers > checks > fabrication > part.
docs/outputs.md describes them.

Importing it loads the modules of the names below but no writer library: the registry imports
a writer module (with ``ezdxf``, ``cairosvg``, ``trimesh``, OCP) when that format is written,
and :func:`.writers.svg.to_svg` imports ``svgwrite`` when it is called.
(Until issue 27 these names were resolved on first use by a PEP 562 ``__getattr__``: 1.5-3%
of a cold ``aidl check``'s instructions, under the 5% rule's bar; docs/dev/performance.md.)"""
from __future__ import annotations

from .fabrication.layout import for_cutting
from .part.build.booleans import Drawing, Part, area, render_model
from .part.part import MissingDependency, Output, OutputError, build
from .writers import ASSEMBLED_FORMATS, CUT_FORMATS, FORMATS, TEXT_FORMATS, Options, encode
from .writers.svg import to_svg

__all__ = ["Drawing", "Part", "area", "render_model", "to_svg", "Output", "build",
           "MissingDependency", "OutputError", "FORMATS", "Options", "encode", "CUT_FORMATS",
           "ASSEMBLED_FORMATS", "TEXT_FORMATS", "for_cutting"]
