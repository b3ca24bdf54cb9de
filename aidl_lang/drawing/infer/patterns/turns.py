"""``aidl import --infer``: which turn of a pattern's loop writes a given hole, as the loop's
variables, so that a mark on some of the holes (three of four corner holes countersunk) is
written in the loop under an ``if`` naming those turns (:func:`~.sinks.condition`) and
follows its hole under every edit.  Each function returns ``index(Shape) -> ((variable,
value), ...)`` for the loop its pattern writer emits (:class:`~.infer._Part`); coordinates in
mm, angles in radians."""
from __future__ import annotations

import math
import re


def _k(v: float, v0: float, step: float) -> int:
    return round((v - v0) / step)


def _sign(v: float) -> int:
    return 1 if v > 0 else -1


def corners(mid) -> callable:
    """``for sx in [-1, 1] { for sy in [-1, 1] { ... } }`` about ``mid``."""
    return lambda sh: (("sx", _sign(sh.center[0] - mid[0])), ("sy", _sign(sh.center[1] - mid[1])))


def mirrored(B, along_x: bool) -> callable:
    """``for s in [-1, 1]`` mirrored about ``B`` across x (``along_x``) or y."""
    axis = 0 if along_x else 1
    return lambda sh: (("s", _sign(sh.center[axis] - B[axis])),)


def polar(C, start: float, n: int) -> callable:
    """``for i in range(n)`` round ``C``, hole ``i`` at ``start + i 360/n``."""
    step = 2 * math.pi / n
    return lambda sh: (("i", _k(math.atan2(sh.center[1] - C[1], sh.center[0] - C[0]),
                                start, step) % n),)


def row(p0, d) -> callable:
    """``for i in range(n)`` from ``p0`` in steps ``d`` (a vector)."""
    L2 = d[0] * d[0] + d[1] * d[1]
    return lambda sh: (("i", round(((sh.center[0] - p0[0]) * d[0] +
                                    (sh.center[1] - p0[1]) * d[1]) / L2)),)


def grid(x0: float, y0: float, dx: float, dy: float, nx: int, ny: int) -> callable:
    """``for i in range(nx) { for j in range(ny) ... }`` (a variable only where its count is
    above 1)."""
    def index(sh):
        out = []
        if nx > 1:
            out.append(("i", _k(sh.center[0], x0, dx)))
        if ny > 1:
            out.append(("j", _k(sh.center[1], y0, dy)))
        return tuple(out)
    return index


def stagger(xa: float, xb: float, pitch: float, y0: float, dy: float) -> callable:
    """``for j in range(rows) { for i in range(...) }``: rows from ``y0`` by ``dy``, even
    rows from ``xa``, odd ones from ``xb``, by ``pitch``."""
    def index(sh):
        j = _k(sh.center[1], y0, dy)
        return ("j", j), ("i", _k(sh.center[0], xa if j % 2 == 0 else xb, pitch))
    return index


def hex_nodes(c, pitch: float, shift: bool) -> callable:
    """``for j in range(-k, k + 1) { for i in range(-k, k + 1) }`` of a hex field about
    ``c``: a node at ``((i + par / 2) pitch, j pitch sqrt(3) / 2)``, ``par`` ``j % 2`` (or
    ``(j + 1) % 2`` when ``shift``)."""
    def index(sh):
        j = round((sh.center[1] - c[1]) / (pitch * math.sqrt(3) / 2))
        par = (j + 1) % 2 if shift else j % 2
        return ("j", j), ("i", round((sh.center[0] - c[0]) / pitch - par / 2))
    return index


def grid_nodes(c, d, half) -> callable:
    """``for j in range(-k, k + 1) { for i in range(-k, k + 1) }`` of a square-set field
    about ``c``: a node at ``((i + hx / 2) dx, (j + hy / 2) dy)``, ``hx`` 1 when ``half[0]``."""
    def index(sh):
        return (("j", round((sh.center[1] - c[1]) / d[1] - half[1] / 2)),
                ("i", round((sh.center[0] - c[0]) / d[0] - half[0] / 2)))
    return index


def _split(point: str) -> tuple[str, str] | None:
    """``(x, y)`` of a point written ``(x, y)``, split at its top-level comma; None when it
    is written otherwise (``polar(...)``)."""
    if not (point.startswith("(") and point.endswith(")")):
        return None
    level = 0
    for k, ch in enumerate(point[1:-1], start=1):
        level += ch in "([" and 1 or ch in ")]" and -1 or 0
        if level < 0:
            return None             # `(a) + (b)`: not one point's brackets
        if ch == "," and level == 0:
            return point[1:k].strip(), point[k + 1:-1].strip()
    return None


def at_turn(center: str, turn: tuple) -> tuple[str, str]:
    """The x and y text of the hole a loop writes at ``center`` (program text over its
    variables) on the turn ``turn`` (``((variable, value), ...)``): each variable replaced
    by its value, so that a label beside one member of a pattern follows that member
    (a corner pattern's inset, a row's pitch)."""
    for var, val in turn:
        text = str(val)
        center = re.sub(rf"\b{re.escape(var)}\b", text if not text.startswith("-")
                        else f"({text})", center)
    # `x + (-52.1)`: `x - 52.1` (a value put in for a variable)
    center = re.sub(r"\+ \(-([\d.]+(?:e-?\d+)?)\)(?! \*)", r"- \1", center)
    center = re.sub(r"- \(-([\d.]+(?:e-?\d+)?)\)(?! \*)", r"+ \1", center)
    for a, b in (("+ (-1) * ", "- "), ("- (-1) * ", "+ "), ("(-1) * ", "-"), ("+ 1 * ", "+ "),
                 ("- 1 * ", "- "), ("(1 * ", "(")):
        center = center.replace(a, b)
    xy = _split(center)
    return xy if xy is not None else (f"{center}.x", f"{center}.y")
