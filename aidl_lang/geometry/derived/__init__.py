"""Shapes made from other shapes: :mod:`.operations` (mirror, patterns, fillets and chamfers),
:mod:`.corners` (the corner two edges name, found after the solve, and its
fillet or chamfer), :mod:`.offset` (Offset, Inset, Shell), :mod:`.hull`, :mod:`.clip`.  Imports the three packages
below it."""
