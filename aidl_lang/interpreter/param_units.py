"""The unit a bare number given to a param from outside its file is in (issue 105): ``aidl
set x.aidl w=40``, MCP ``set_params``, ``--set w=40``, ``aidl_lang.compile(overrides=...)``,
the studio's and the notebook's forms.  It is the param's own unit: the one its value is
written in (``param w = 60 mm`` → mm, ``param tilt = 0.5 rad`` → rad), else the file's
``units`` for a length and degrees for an angle (docs/language.md, "param and --set").
"""
from __future__ import annotations

from .. import ast as A
from ..geometry.core.values import ANG, LEN
from ..registry import UNITS_ANGLE, UNITS_LENGTH


def own_unit(expr, dim, file_unit: str = "mm") -> str | None:
    """The unit (as written, ``"mm"``, ``"in"``, ``"deg"``) of a param whose value is the
    expression ``expr`` of dimension ``dim`` (``LEN``, ``ANG``): the one unit of that kind its
    number literals are written in, else ``file_unit`` for a length and ``"deg"`` for an angle
    (literals in several units: the same).  None for another dimension (a plain number keeps
    no unit)."""
    table = UNITS_LENGTH if dim == LEN else UNITS_ANGLE if dim == ANG else None
    if table is None:
        return None
    seen: list[str] = []
    for n in A.walk(expr) if expr is not None else ():
        if isinstance(n, A.Num) and n.unit in table:
            if not any(table[u] == table[n.unit] for u in seen):
                seen.append(n.unit)
    if len(seen) == 1:
        return seen[0]
    return file_unit if dim == LEN else "deg"


def unit_scale(unit: str) -> float:
    """Internal units (mm, radians) per one ``unit``."""
    return UNITS_LENGTH.get(unit) or UNITS_ANGLE[unit]
