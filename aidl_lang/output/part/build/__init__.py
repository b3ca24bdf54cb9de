"""The solved model made into Manifold shapes: :mod:`.booleans` (``Drawing``: the tree walk,
the unions, the cuts), :mod:`.faces` (one geometry's exact curves and its face), :mod:`.result`
(the records they make), :mod:`.outlines`, :mod:`.placement`, :mod:`.scanwork`,
:mod:`.hole_outlines`, :mod:`.stencil`.  Imports :mod:`..edges`, :mod:`..measure` and geometry.
"""
