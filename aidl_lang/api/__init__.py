"""The public Python API: compile an AIDL program and read what it made.

>>> import aidl_lang
>>> r = aidl_lang.compile(source="solid plate { body = Rectangle(center=(0, 0), width=40, height=20) }")
>>> r.ok
True
>>> r.value("plate.body.width").text()
'plate.body.width = 40.000 mm'
>>> r.parts[0].bbox
(-20.0, -10.0, 20.0, 10.0)

The package's rooms: :mod:`.compiling` (:func:`compile`, :func:`set_params`),
:mod:`.result` (:class:`Result`), :mod:`.values` (the records a result reports in: values,
parts, layouts), each importing only those after it (pyproject.toml's contract).

Every front end (``aidl check``/``render``, the MCP server, editors) goes through
:func:`compile` and :class:`Result`; docs/api.md describes them.  A mistake in the program is
never an exception: it is a :class:`~aidl_lang.base.diagnostics.Diagnostic` in
:attr:`Result.diagnostics` and ``ok`` is False.  Exceptions are kept for mistakes in the
*call* (:class:`TypeError`, :class:`ValueError`), for asking a failed result for geometry
(:class:`NotCompiled`), and for outputs that cannot be made or written
(:class:`~aidl_lang.output.part.part.OutputError`, :class:`~aidl_lang.output.writers.write.WriteError`).

Units: the model is solved in millimetres and radians.  :attr:`Result.parts` and
:meth:`Result.to_svg`/``write`` are in millimetres; :attr:`Result.values` are given in the
file's own units (``units in`` / ``cm`` / ...; mm when the file declares none) and degrees,
with the unit named in :attr:`Value.unit`.
"""
from __future__ import annotations

from .compiling import ParamsRefused, compile, set_params
from .result import REDUNDANCY_ROWS, REDUNDANCY_SECONDS, NotCompiled, Result
from .values import Layout, PartInfo, Value, _values, exact_bbox, file_units

__all__ = ["compile", "Result", "Value", "PartInfo", "Layout", "NotCompiled", "WriteError",
           "set_params", "ParamsRefused"]
# read by the front ends beside the public names: the bounds of the redundancy search, the
# units of a file, exact boxes, the values of a model
_SHARED = (REDUNDANCY_ROWS, REDUNDANCY_SECONDS, _values, exact_bbox, file_units)


def __getattr__(name: str):
    # WriteError lives with the output-file rules (aidl_lang.output.writers.write); imported on first
    # use, as the output package loads Manifold (0.3 s) and this facade stays quick to import
    if name == "WriteError":
        from ..output.writers.write import WriteError
        return WriteError
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
