"""Outputs: the solved model through Manifold booleans (:mod:`.booleans`) to the writers
(:mod:`.svg`)."""
from .booleans import Drawing, Part, area, render_model
from .svg import to_svg

__all__ = ["Drawing", "Part", "area", "render_model", "to_svg"]
