"""Front panels and grilles with a known design (issue 93, round five: "front panels of rows
and windows, grilles"), for benchmarks/imports/infer_edits.py ``--kinds panels``: each a
:class:`~gen_drawings.Design` of the features a maker puts on one, every feature's truth the
spec's as :mod:`gen_drawings` writes it (docs/import.md, "What an edit means"):

* ``front_panel``: four mounting holes or slots at the corners (``corners``), a row of pots,
  jacks or switches (``row``: holes, or slots), a window for a display or a meter
  (``cutout``), and one to three more of rows, windows and single holes, with labels above
  or below the holes and windows they name (or on the panel);
* ``grille``: a fan's or a speaker's grille, a hex grid clipped to a round or a rectangular
  field (``hexgrid``), four mounting holes at the corners, and up to three more holes, rows
  or grids (none of the grille's hole size: :func:`_one_reading`).

``Design.kind`` names the drawing's kind, so that the benchmark reports each kind of drawing
beside each kind of feature."""
from __future__ import annotations

import random

import gen_drawings as gen

PANEL_KINDS = ("front_panel", "grille")
PARTS = {"front_panel": (("corners", "row", "cutout"), ("row", "cutout", "hole")),
         "grille": (("hexgrid", "corners"), ("hole", "row", "grid"))}


def _one_reading(d: gen.Design) -> bool:
    """Whether no row or grid has the hole size of a hex grid: equal holes of two patterns
    are split by their neighbours (docs/import.md), which parts a grid of uneven pitches
    into its columns, so such a design is read otherwise than it is meant."""
    hexes = {f["d"] for f in d.features if f["kind"] == "hexgrid"}
    return not any(f["kind"] in ("row", "grid") and f.get("d") in hexes for f in d.features)


def random_panel(rng: random.Random, kind: str) -> gen.Design:
    """A random ``kind`` (module doc): its features first, then more from its pool."""
    first, pool = PARTS[kind]
    for _ in range(100):
        d = gen.random_design(rng, list(first), pool=pool)
        if _one_reading(d):
            d.kind = kind
            return d
    raise RuntimeError(f"no {kind} found")
