"""Outputs: the solved model through Manifold booleans (:mod:`.booleans`) to the one exact
output model (:mod:`.part`: lines, arcs, circles per part, engraving), the writers (:mod:`.svg`,
:mod:`.dxf`, :mod:`.png`, :mod:`.mesh`, :mod:`.step`, by extension in :mod:`.formats`) and the geometry
checks on the final shape (:mod:`.checks`).  docs/outputs.md describes them."""
from .booleans import Drawing, Part, area, render_model
from .formats import FORMATS, Options, encode
from .part import MissingDependency, Output, OutputError, build
from .svg import to_svg

__all__ = ["Drawing", "Part", "area", "render_model", "to_svg", "Output", "build", "FORMATS",
           "Options", "encode", "MissingDependency", "OutputError"]
