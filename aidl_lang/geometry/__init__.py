"""Geometry: what a program builds and what the solver and the outputs read, in four rooms by
what a reader looks for, each importing only the rooms after it (the contract in
``pyproject.toml``):

- :mod:`.derived`: shapes made from shapes (mirror, patterns, fillets and chamfers; Offset,
  Hull, Clip);
- :mod:`.relations`: what a program says about shapes (members, constraints to equations,
  asserts, bounding boxes);
- :mod:`.shapes`: the shapes and the exact curves they are made of (primitives, lines, arcs,
  ellipses, splines, the font, drawings);
- :mod:`.core`: the expression and structure model (residual expressions, structures, points,
  scalars, equations, values with units).

Imports nothing above it but the core's diagnostics, registry and limits.
"""
