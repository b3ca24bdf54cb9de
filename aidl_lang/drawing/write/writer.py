"""How ``aidl import`` writes (docs/import.md): numbers as the shortest decimal that reads
back within a snap (:func:`_num`), strings, points and names (:func:`_ident`, never a
keyword, each once: :class:`_Names`), spline and Bézier pieces as their points, the
:class:`_Writer` that emits a program's lines and chains of pieces sharing their ends, and
the holds that keep each piece where the file puts it (:func:`_holds`, :func:`_emit_holds`:
``aidl check`` says ``fully constrained``).  Split out of :mod:`.program` (issue 96), which
writes a drawing's structures with it; the inference (``infer/``) writes with it too."""
from __future__ import annotations

import math
import re

from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Spline
from ..model import Note

COPIES_PER_LOOP = 1000      # places in one `for` (a loop holds at most 10 000 items: E0301)
SNAP = 1e-12    # mm: a coordinate within this of a shorter decimal is written as that decimal


def _num(v: float, snap: float = SNAP) -> str:
    """``v`` (mm or degrees) as the shortest decimal within ``snap`` of it, so that float
    noise from the reader (``43.99999999999999``, ``25.000000000000004``) is written as the
    number the drawing meant (``44``, ``25``); the error stays far inside the round trip's
    1e-9 mm.  Angles in radians pass ``snap=0`` (exact: 1e-12 rad is 1e-9 mm at 1 m)."""
    v = float(v)
    if not math.isfinite(v) or abs(v) > 1e15:     # never written into a program
        from ..model import DrawingError
        raise DrawingError("E0130", f"the drawing has a number {v!r} that is not finite or "
                                    f"beyond the model extent: not written",
                           "fix the entity in the drawing")
    if abs(v) < 1e-12:
        return "0"
    for digits in range(13):
        r = round(v, digits)
        if abs(r - v) <= snap:
            v = r
            break
    if v == 0:
        return "0"
    s = repr(v)
    if s.endswith(".0"):
        s = s[:-2]
    return s


def _string(text: str) -> str:
    """``text`` as an AIDL string literal (one line: control characters dropped)."""
    clean = "".join(c for c in text if c >= " " and c != "\x7f")
    return '"' + clean.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _pt(p) -> str:
    return f"({_num(p[0])}, {_num(p[1])})"


class _Names(set):
    """A set of names given by :func:`_ident` that remembers, per base, the first suffix
    not yet tried (``next``), so the ``n``-th name of one base costs one look, not ``n``
    (20,000 holes of their own sizes: 2e8 looks); a name discarded forgets them all (it
    may be free again)."""

    def __init__(self, *names) -> None:
        super().__init__(*names)
        self.next: dict = {}

    def discard(self, name) -> None:
        super().discard(name)
        self.next.clear()


def _ident(s: str, used: set) -> str:
    """``s`` made an identifier (lower case, not a keyword), ``_2``, ``_3``, ... added until
    it is not in ``used``; added to ``used``.  A :class:`_Names` ``used`` starts from the
    suffix its last name of the base reached."""
    s = re.sub(r"[^A-Za-z0-9_]", "_", s).strip("_").lower() or "part"
    if s[0].isdigit():
        s = "l_" + s
    if s in _KEYWORDS:
        s += "_"
    hints = getattr(used, "next", None)
    base = s
    i = 2 if hints is None else hints.get(base, 2)
    while s in used:
        s = f"{base}_{i}"
        i += 1
    if hints is not None:
        hints[base] = i
    used.add(s)
    return s


_KEYWORDS = {"solid", "hole", "cut", "drawing", "assembly", "def", "for", "in", "if", "else", "import",
             "as", "param", "units", "true", "false", "self", "and", "or", "not", "thickness",
             "kerf", "assert", "model"}


def _spline_points(s: Spline, closed: bool):
    """The points a ``Spline(...)`` statement passes through to give piece ``s`` exactly, or
    None when the piece is not an interpolating spline of its span ends."""
    from ...geometry.shapes.spline import SplineError, interpolate
    spans = s.spans
    pts = [spans[0][0]] + [b[3] for b in spans]
    if closed:
        pts = pts[:-1]
    try:
        c = interpolate(pts, closed)
    except SplineError:
        return None
    got = [c.span(i) for i in range(c.n)]
    if len(got) != len(spans):
        return None
    for a, b in zip(got, spans):
        for p, q in zip(a, b):
            if math.dist(p, q) > 1e-9:
                return None
    return pts


def _bezier_points(spans) -> list:
    """The ``3 k + 1`` control points of cubic ``spans`` (end to end, in their direction):
    the points of a ``Bezier(...)`` statement that is that curve exactly."""
    pts = [spans[0][0]]
    for b in spans:
        pts += [b[1], b[2], b[3]]
    return pts


def _bezier_runs(segs: list) -> list:
    """``segs`` with each run of consecutive spline pieces that are no interpolating spline
    through their span ends joined into one piece (one ``Bezier`` statement): its spans are
    the pieces' spans, end to end, each piece's start its predecessor's end bit for bit."""
    from ...geometry.shapes.spline import CubicSpline
    out: list = []
    run: list = []

    def flush():
        if len(run) == 1:
            out.append(run[0])
        elif run:
            spans = [b for s in run for b in s.spans]
            ctrl = _bezier_points(spans)
            h = [math.dist(b[0], b[3]) or 1.0 for b in spans]
            c = CubicSpline(tuple(ctrl), tuple(h), False)
            out.append(Spline(c, 0.0, float(c.n)))
        run.clear()
    for s in segs:
        if isinstance(s, Spline) and _spline_points(s, False) is None:
            run.append(s)
        else:
            flush()
            out.append(s)
    flush()
    return out


def _length(segs) -> float:
    """The length (mm) of a chain of segments."""
    return sum(2 * math.pi * s.radius if isinstance(s, Circle) else s.length for s in segs)


class _Writer:
    def __init__(self, deadline=None) -> None:
        self.lines: list[str] = []
        self.notes: list[Note] = []
        self.deadline = deadline
        self.cut_paths = 0          # open paths written as through-cuts, and their length
        self.cut_length = 0.0
        self.crossed = 0            # loops on a cut role that cross themselves: engraved
        self.compact = False        # a big drawing: repeated loops as loops, line loops
        self.rel = None             # (x, y): points written relative to `p` (a copy's place)
        self.overlaps: set = set()  # holes drawn overlapping on a cut role (hole_cuts)

    def emit(self, depth: int, text: str) -> None:
        self.lines.append("    " * depth + text)

    def pt(self, p) -> str:
        """The point ``p`` as written: ``(x, y)``, or relative to the loop variable ``p``
        of a copy written once (``(p[0] + 1.5, p[1] - 2)``, ``p``) when :attr:`rel` is the
        first point of the copy written."""
        if self.rel is None:
            return _pt(p)
        dx, dy = p[0] - self.rel[0], p[1] - self.rel[1]
        if _num(dx) == "0" and _num(dy) == "0":
            return "p"

        def rel(i, v):
            t = _num(v)
            return f"p[{i}]" if t == "0" else f"p[{i}] - {t[1:]}" if t.startswith("-") \
                else f"p[{i}] + {t}"
        return f"({rel(0, dx)}, {rel(1, dy)})"

    def chain(self, depth: int, segs: list, closed: bool, prefix: str) -> bool:
        """Statements for a chain of segments sharing end points; False (nothing written)
        when a spline piece has no exact form."""
        out: list[str] = []
        segs = _bezier_runs(segs)
        if closed and len(segs) == 1 and isinstance(segs[0], Spline):
            pts = _spline_points(segs[0], True)
            if pts is None:         # its own control points: a closed Bezier chain
                ctrl = _bezier_points(segs[0].spans)
                ctrl[-1] = ctrl[0]
                out.append(f"{prefix}0 = Bezier(points=[{', '.join(self.pt(p) for p in ctrl)}], "
                           f"closed=true)")
            else:
                out.append(f"{prefix}0 = Spline(points=[{', '.join(self.pt(p) for p in pts)}], "
                           f"closed=true)")
            for t in out:
                self.emit(depth, t)
            return True
        first_start = None          # expression of the chain's first point
        prev_end = None
        n = len(segs)
        for i, s in enumerate(segs):
            nm = f"{prefix}{i}"
            start = prev_end if prev_end is not None else self.pt(s.start)
            last = closed and i == n - 1
            end = first_start if last else self.pt(s.end)
            if isinstance(s, Line):
                out.append(f"{nm} = Line(start={start}, end={end})")
                cs, ce = f"{nm}.start", f"{nm}.end"
            elif isinstance(s, Arc):
                if abs(abs(s.sweep) - 2 * math.pi) < 1e-12:
                    return False
                if s.sweep > 0:
                    out.append(f"{nm} = Arc(center={self.pt(s.center)}, start={start}, end={end})")
                    cs, ce = f"{nm}.start", f"{nm}.end"
                else:           # an Arc runs counter-clockwise: swap the ends
                    out.append(f"{nm} = Arc(center={self.pt(s.center)}, start={end}, end={start})")
                    cs, ce = f"{nm}.end", f"{nm}.start"
            elif isinstance(s, EllipticArc):
                if s.whole:
                    return False
                # an Ellipse's arc runs counter-clockwise from start_angle: a clockwise
                # piece is written from its end (as an Arc)
                t0, sw = (s.start_param, s.sweep) if s.sweep > 0 else (s.end_param, -s.sweep)
                e = s.curve
                out.append(f"{nm} = Ellipse(center={self.pt(e.center)}, rx={_num(e.rx)}, "
                           f"ry={_num(e.ry)}, rotation={_num(e.rotation, 0)} rad, "
                           f"start_angle={_num(t0, 0)} rad, end_angle={_num(t0 + sw, 0)} rad)")
                cs, ce = (f"{nm}.start", f"{nm}.end") if s.sweep > 0 else \
                    (f"{nm}.end", f"{nm}.start")
            elif isinstance(s, Spline):
                pts = _spline_points(s, False)
                if pts is None:     # not through its span ends: its own control points
                    ctrl = _bezier_points(s.spans)
                    inner = ", ".join([start] + [self.pt(p) for p in ctrl[1:-1]] + [end])
                    out.append(f"{nm} = Bezier(points=[{inner}])")
                else:
                    inner = ", ".join([start] + [self.pt(p) for p in pts[1:-1]] + [end])
                    out.append(f"{nm} = Spline(points=[{inner}])")
                cs, ce = f"{nm}.start", f"{nm}.end"
            else:
                return False
            if first_start is None:
                first_start = cs
            prev_end = ce
        for t in out:
            self.emit(depth, t)
        return True


def _holds(segs: list, prefix: str, closed: bool = True) -> list[str]:
    """What to hold so that a chain written by :meth:`~.program._Writer.chain` with
    ``prefix`` stays where the file put it, and nothing twice (no ``W0401``): an arc between
    two lines ``Fixed`` whole (its ends with it); every other join of two pieces ``Fixed``
    (a point); and an arc that meets another arc by its radius (``NAME.radius == r``: its
    centre is then the one point at that distance from both held ends).  Returns the things
    to fix and those equations (each with `` == ``).  Only chains of lines and arcs, one
    closed spline (held whole), or a closed chain of lines and curves that does not start and
    end on a curve (each curve held whole, each join of two lines held: a font's letter); a
    chain of splines and arcs stays free as ``aidl import`` writes it."""
    if not all(isinstance(g, (Line, Arc)) for g in segs):
        one = _bezier_runs(list(segs))
        if closed and len(one) == 1 and isinstance(one[0], Spline):
            return [f"{prefix}0"]       # one closed Bezier or Spline: rigid, held whole
        n = len(one)
        if closed and all(isinstance(g, (Line, Spline)) for g in one) and not (
                isinstance(one[0], Spline) and isinstance(one[-1], Spline)):
            # lines and curves (a font's letter, issue 112): each curve held whole (its ends
            # with it), each join of two lines held; no point twice
            return [f"{prefix}{i}" for i, g in enumerate(one) if isinstance(g, Spline)] + \
                [f"{prefix}{i}.start" for i in range(n)
                 if isinstance(one[i], Line) and isinstance(one[i - 1], Line)]
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
    out += [_arc_hold(f"{prefix}{i}", g) for i, g in enumerate(segs)
            if isinstance(g, Arc) and not arc_alone(i)]
    return out


def _arc_hold(nm: str, g: Arc) -> str:
    """The equation that holds arc ``nm`` (``g``) once both its ends are held: its centre
    may only slide along the bisector of its chord, so one number pins it.  Its radius
    (``nm.radius == 12.5``) does, but not near a half turn (a slot's end cap): there the
    radius is least at the centre drawn, so the equation pins nothing to first order (the
    solver's rank: ``W0401`` and a free degree left); then the centre's coordinate most
    along the bisector (``nm.center.x == 36``) holds it."""
    if abs(math.cos(g.sweep / 2)) >= 0.5:
        return f"{nm}.radius == {_num(g.radius)}"
    (x0, y0), (x1, y1) = g.start, g.end
    axis = 0 if abs(y1 - y0) >= abs(x1 - x0) else 1     # the bisector is across the chord
    return f"{nm}.center.{'xy'[axis]} == {_num(g.center[axis])}"


def _emit_holds(w: _Writer, depth: int, holds: list[str], var: str = "x") -> None:
    fixed = [h for h in holds if " == " not in h]
    if len(fixed) == 1:
        w.emit(depth, f"Fixed({fixed[0]})")
    for k in range(0, len(fixed) if len(fixed) > 1 else 0, COPIES_PER_LOOP):
        run = fixed[k:k + COPIES_PER_LOOP]      # a loop holds at most 10 000 items (E0301)
        w.emit(depth, f"for {var} in [{', '.join(run)}] {{ Fixed({var}) }}" if len(run) > 1
               else f"Fixed({run[0]})")
    for h in holds:
        if " == " in h:
            w.emit(depth, h)
