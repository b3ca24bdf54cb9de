"""The expression and structure model everything else is written in: :mod:`.expr` (residual
expressions and their derivatives), :mod:`.model` (structures, points, scalars, equations: what
the solver solves), :mod:`.values` (the interpreter's values with units).  Imports nothing of
geometry (the contract in pyproject.toml)."""
