"""The shapes a program builds and the curves they are made of: :mod:`.constructors` (``build``,
the one entry), :mod:`.primitives` (Circle, Rectangle, Slot, ... as model points and scalars),
:mod:`.point_shapes` (Polygon, Polyline, Spline, Bezier), :mod:`.composites` (Offset, Shell,
Hull, Intersect, Stroke: shapes made from shapes), :mod:`.curves` (exact lines, arcs, ellipses
and splines), :mod:`.ellipse`, :mod:`.spline`, :mod:`.biarc` (splines as arcs), :mod:`.text`
(the single-stroke font), :mod:`.drawing2d` (an imported drawing as shapes),
:mod:`.tessellate` (chords for arcs).  Imports :mod:`..core` only."""
