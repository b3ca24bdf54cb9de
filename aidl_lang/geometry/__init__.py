"""Geometry: what a program builds and what the solver and the outputs read.

:mod:`.expr` (residual expressions), :mod:`.model` (structures, points, scalars, equations),
:mod:`.values` (the interpreter's values with units), :mod:`.primitives` (shapes),
:mod:`.members` (their members: ``rect.top_left``, ``line.length``), :mod:`.constraints`
(constraints to equations), :mod:`.bbox` (bounding boxes), :mod:`.operations` (mirror,
patterns, fillets and chamfers), :mod:`.tessellate` (chords for arcs), :mod:`.text`
(single-stroke font).  Imports nothing above it but the core's
diagnostics, registry and limits (the contract in ``pyproject.toml``).
"""
