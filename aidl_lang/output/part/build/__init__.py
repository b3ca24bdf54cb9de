"""The solved model made into Manifold shapes: :mod:`.booleans` (``Drawing``), :mod:`.result` (its
records), :mod:`.outlines`, :mod:`.placement`, :mod:`.scanwork`, :mod:`.hole_outlines`,
:mod:`.stencil`. Imports :mod:`..edges`, :mod:`..measure` and geometry.
"""
