"""The part: the solved model in, the one exact output model out.

In: the solved :class:`~aidl_lang.geometry.core.model.Model` (exact outlines per structure, from the
interpreter and solver).  Out: :class:`~.booleans.Drawing` (Manifold's booleans per part, with
what each hole cut, which the checks read) and :class:`~.part.Output` (lines, arcs, circles,
splines per part, engraving strokes; mm, y up), which fabrication and every writer read.

* :mod:`.booleans`: the structures through Manifold's booleans (unions, cuts, engraving);
* :mod:`.outlines`: the exact outline of each shape kind (slots, sectors, rounded
  rectangles, a Stroke's band along a spline) that the booleans are made from;
* :mod:`.placement`: the 4x4 matrices of ``Place`` (the sheet to the assembled product);
* :mod:`.exact`: the provenance of each polygon edge, its exact curve;
* :mod:`.part`: the exact curves put back on the booleans' result (:func:`~.part.build`);
* :mod:`.extent`: exact extents of an output;
* :mod:`.nearby`: the spatial index (a grid) the checks and the layout search pairs with.

Nothing here imports the checks, fabrication or the writers (pyproject.toml's contract).
``aidl_lang.output.part.Output`` (docs/api.md before issue 63) still names the output model."""
from __future__ import annotations

from .part import MissingDependency, Output, OutputError, PartOutline, build

__all__ = ["Output", "PartOutline", "OutputError", "MissingDependency", "build"]
