"""``aidl import --infer``: how a recognised thing is written as text (issue 60; docs/import.md,
"Inferring the design"; used by :mod:`.infer` and its pattern finders).

In: numbers in mm (angles in radians) and :class:`~.infer_shapes.Shape` s.  Out: program text:
a number as the shortest decimal within :data:`~.infer_shapes.ROUND_TOL` (:func:`_r`; an angle
in degrees, :func:`_deg`), ``base + term`` (:func:`_plus`), a point (:func:`_center`), the
program's ``param`` lines each named once (:class:`_Params`), a shape's constructor with its
sizes as params (:func:`_ctor`) and the name a hole gets for its kind (:func:`_hole_name`).
"""
from __future__ import annotations

import math

from .shapes import ROUND_TOL, Shape
from ..write.writer import _Names, _ident, _num, _pt


def _r(v: float) -> str:
    """A parameter's value: the shortest decimal within ROUND_TOL."""
    return _num(v, ROUND_TOL)


def _deg(a: float) -> str:
    return _num(math.degrees(a), 1e-10) + " deg"


class _Params:
    """The program's ``param`` lines, named once (``prefix`` the part's name when several)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.used: set = _Names()

    def add(self, name: str, value: float, comment: str = "", unit: str = "mm",
            times: int = 1) -> str:
        """A param of ``value``, rounded within ROUND_TOL / ``times`` (a pitch taken ``times``
        over moves its last copy by at most ROUND_TOL)."""
        nm = _ident(name, self.used)
        if unit == "mm":            # a length: in the unit the program is written in
            from ..write.units import UNIT
            unit = UNIT.get()
        u = f" {unit}" if unit else ""
        v = _num(value, ROUND_TOL / max(times, 1))
        self.lines.append(f"param {nm} = {v}{u}" + (f"  # {comment}" if comment else ""))
        return nm


    def bound(self, name: str, lo: str, hi: str, why: str) -> None:
        """Give the param ``name`` (a line of :attr:`lines`) the range ``min=lo, max=hi``
        (program text: ``hi`` may follow a param above it, ``d_hole_d / 2``) and an
        ``assert`` that it stays short of ``hi`` (``why``: what holds it there), so that a
        ``--set`` past it is one located error naming the param and its range (issue 91:
        an inferred D-hole's flat past its radius was a math domain error)."""
        for k, line in enumerate(self.lines):
            if line.startswith(f"param {name} = "):
                head, _, note = line.partition("  # ")
                if "min=" in head:
                    return
                self.lines[k] = f"{head}, min={lo}, max={hi}" + (f"  # {note}" if note else "")
                self.lines.insert(k + 1, f'assert {name} < {hi}, "{why}"')
                return


def _plus(base: float, term: str) -> str:
    """``base + term`` as text (``term`` alone when base is 0)."""
    if abs(base) <= ROUND_TOL:
        return term
    b = _r(base)
    if term.startswith("-"):
        return f"{b} - {term[1:]}"
    return f"{b} + {term}"


def _center(c) -> str:
    return f"({_r(c[0])}, {_r(c[1])})"


def _size_args(sh: Shape, sizes: dict | None = None) -> str:
    """The keyword arguments of ``sh`` after its centre; ``sizes`` maps an argument to the
    param written for it."""
    sizes = sizes or {}
    a = sh.args
    out = []
    if sh.kind == "Circle":
        out.append(f"diameter={sizes['diameter']}" if "diameter" in sizes
                   else f"radius={_r(a['radius'])}")
    elif sh.kind == "Polygon":
        return ""
    else:
        for k, v in a.items():
            if k == "rotation":
                if abs(v) > 1e-15:
                    out.append(f"rotation={_deg(v)}")
            elif k in ("start_angle", "end_angle"):
                out.append(f"{k}={_deg(v)}")
            elif k == "sides":
                out.append(f"sides={v}")
            elif k == "corner_radii":
                out.append("corner_radii=[" + ", ".join(_r(x) for x in v) + "]")
            else:
                out.append(f"{k}={sizes.get(k, _r(v))}")
    return ", ".join(out)


def _ctor(sh: Shape, center: str, sizes: dict | None = None) -> str:
    if sh.kind == "Polygon":
        return "Polygon([" + ", ".join(_pt(p) for p in sh.args["points"]) + "])"
    rest = _size_args(sh, sizes)
    return f"{sh.kind}(center={center}" + (f", {rest}" if rest else "") + ")"


_HOLE_NAMES = {"Circle": "hole", "Slot": "slot", "Rectangle": "window",
               "RoundedRectangle": "window", "Polygon": "cutout", "Sector": "sector",
               "Ellipse": "oval"}


def _hole_name(sh: Shape) -> str:
    if sh.kind == "RegularPolygon":
        return "hex" if sh.args["sides"] == 6 else "polygon"
    return _HOLE_NAMES.get(sh.kind, "cutout")


def _add0(base: str, term: str) -> str:
    """``base + term`` as text, ``term`` alone when ``base`` is ``0``."""
    return term if base == "0" else f"{base} + {term}"
