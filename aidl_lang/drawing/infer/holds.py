"""What ``aidl import --infer`` holds where the drawing put it: the ``Fixed`` statements (and
radius equations) of a chain of lines and arcs written as it is (:func:`_holds`), and how they
are written (:func:`_emit_holds`)."""
from __future__ import annotations

from ...geometry.curves import Arc, Line
from ..write.program import _Writer, _num


def _holds(segs: list, prefix: str, closed: bool = True) -> list[str]:
    """What to hold so that a chain written by :meth:`~.program._Writer.chain` with
    ``prefix`` stays where the file put it, and nothing twice (no ``W0401``): an arc between
    two lines ``Fixed`` whole (its ends with it); every other join of two pieces ``Fixed``
    (a point); and an arc that meets another arc by its radius (``NAME.radius == r``: its
    centre is then the one point at that distance from both held ends).  Returns the things
    to fix and those equations (each with `` == ``).  Only chains of lines and arcs, or one
    closed spline (held whole); a chain of splines and other pieces stays free as ``aidl
    import`` writes it."""
    if not all(isinstance(g, (Line, Arc)) for g in segs):
        from ...geometry.curves import Spline
        from ..write.program import _bezier_runs
        one = _bezier_runs(list(segs))
        if closed and len(one) == 1 and isinstance(one[0], Spline):
            return [f"{prefix}0"]       # one closed Bezier or Spline: rigid, held whole
        return []
    n = len(segs)

    def piece(i):
        return segs[i % n] if closed or 0 <= i < n else None

    def arc_alone(i):
        return isinstance(piece(i), Arc) and not isinstance(piece(i - 1), Arc) and \
            not isinstance(piece(i + 1), Arc)

    def start(i):       # the expression of piece i's start as written
        g = segs[i]
        return f"{prefix}{i}.end" if isinstance(g, Arc) and g.sweep < 0 else f"{prefix}{i}.start"

    def end(i):
        g = segs[i]
        return f"{prefix}{i}.start" if isinstance(g, Arc) and g.sweep < 0 else f"{prefix}{i}.end"
    out = [f"{prefix}{i}" for i in range(n) if arc_alone(i)]
    for i in range(n):                      # the join at the start of piece i
        if not (arc_alone(i) or (piece(i - 1) is not None and arc_alone(i - 1))):
            out.append(start(i))
    if not closed and not arc_alone(n - 1):
        out.append(end(n - 1))
    out += [f"{prefix}{i}.radius == {_num(g.radius)}" for i, g in enumerate(segs)
            if isinstance(g, Arc) and not arc_alone(i)]
    return out


def _emit_holds(w: _Writer, depth: int, holds: list[str], var: str = "x") -> None:
    fixed = [h for h in holds if " == " not in h]
    if len(fixed) == 1:
        w.emit(depth, f"Fixed({fixed[0]})")
    elif fixed:
        w.emit(depth, f"for {var} in [{', '.join(fixed)}] {{ Fixed({var}) }}")
    for h in holds:
        if " == " in h:
            w.emit(depth, h)


# ------------------------------------------------------------------ the writer
