"""What a program says about its shapes: :mod:`.members` (``rect.top_left``, ``line.length``),
:mod:`.constraints` (constraints to residual equations), :mod:`.assertions` (``assert`` over
solved values), :mod:`.bbox` (bounding boxes as expressions).  Imports :mod:`..shapes` and
:mod:`..core`."""
