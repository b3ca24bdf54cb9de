"""The shapes a program builds and the curves they are made of: :mod:`.primitives` (Circle,
Rectangle, Polygon, Slot, ... as model points and scalars), :mod:`.curves` (exact lines, arcs,
ellipses and splines), :mod:`.ellipse`, :mod:`.spline`, :mod:`.biarc` (splines as arcs),
:mod:`.text` (the single-stroke font), :mod:`.drawing2d` (an imported drawing as shapes),
:mod:`.tessellate` (chords for arcs).  Imports :mod:`..core` only."""
