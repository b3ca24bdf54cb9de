"""The Newton core: :mod:`.system` (rows), :mod:`.tape` (residuals, Jacobian), :mod:`.reduce`,
:mod:`.newton`, :mod:`.small`, :mod:`.batch`, :mod:`.hierarchy` (the post-order solve),
:mod:`.holds`, :mod:`.rank` (the rank and null-space linear algebra), :mod:`.arrays`. Imports
geometry and the base, never :mod:`..diagnosis`.
"""
