"""G-code writer (GRBL dialect) for lasers, routers and pen plotters (docs/machines.md, "GRBL
laser", "CNC router").

The program runs the cuts of :func:`~..fabrication.toolpath.plan` in its order (engraving first, then part
by part every loop inside another before the loop around it, a nearest-neighbour tour) with
the settings of a machine profile (:mod:`~..fabrication.machine`; ``Options.machine``, ``aidl render
--machine FILE``; the built-in laser profile when none is given).  What it writes:

* ``G21 G90 G17``: millimetres, absolute coordinates, the XY plane; a header of ``;``
  comments with the program, the profile and the estimates (cut and travel length, job time).
* every line as ``G1``, every arc as ``G2`` (clockwise) or ``G3`` (counter-clockwise) to its
  end with ``I`` / ``J`` the centre relative to the start; an arc of more than half a turn is
  written as two halves, a whole circle as two half-circles from its point of angle 0 (a
  full-circle ``G2`` whose end is its start is legal, but two halves leave no doubt about the
  end point).  Numbers have :data:`DECIMALS` decimals (trailing zeros dropped), no exponent:
  the file holds the exact output to 1e-10 mm; I / J are taken from the start as written,
  so the centre a reader finds is the exact centre to 1e-10 mm.  GRBL reads any number of
  digits and keeps 8 significant ones (``read_float``), in single precision: a controller
  lands within about 1e-5 mm of the file, far below a step.  A move line stays under GRBL's
  80-character line buffer for coordinates under 10 m (``F`` and ``S`` are on lines of their
  own: ``G1 F400 S1000`` sets them without moving);
* ellipse pieces and spline pieces as arcs: each piece is cut into biarcs (two tangent arcs
  from each end's position and direction, equal tangent lengths), split in half until every
  sample of the curve lies within :data:`CURVE_TOL` mm of them; the ends are the exact ends.

Laser (``kind = "laser"``): ``M4`` (dynamic power, GRBL's laser mode ``$32=1``; or ``M3``
per the profile's ``laser_mode``) once, then for each cut ``G0`` to its start with ``S0``,
``G1 F<speed> S<power % x max_power>``, the path, repeated ``passes`` times (a closed loop
ends where it starts; an open path, a through-cut's slit, runs back from its end on every
second pass: no travel between passes).  In laser mode GRBL
turns the beam off on every ``G0`` anyway; the ``S0`` on the travel lines keeps the beam off
also on a controller with laser mode off (``$32=0``), where ``G0`` would keep it on.  Holding
tabs (profile ``tabs``, ``tab_width``) on the outer cuts are gaps run with ``S0``.  The job
ends ``M5``, ``G0 X0 Y0``, ``M2``.

Router (``kind = "router"``): the paths are the cuts offset by the tool radius (outside the
outlines, inside the holes: :func:`~..fabrication.layout.compensate` with a kerf of ``tool_diameter``,
exact lines and arcs; an edge two pieces share on its own line, cut once, with a note), run in the loops' own direction (outlines counter-clockwise, holes
clockwise: conventional milling with a clockwise spindle); at every inside corner between
two straight edges the bit runs into the corner and back until its edge touches the drawn
corner (profile ``relief``: ``dogbone`` along the bisector, the built-in router's default,
``tbone`` along the longer edge; ``none``: a warning naming the corners, :func:`routed_path`).
``M3 S<spindle>``, travel at
``safe_height`` (``G0 Z``), then down ``depth_per_pass`` at a time (``G1 Z.. F<plunge>``) to
the part's thickness (``Options.thickness``, else the program's ``thickness``, else 3 mm),
each depth one run of the path; over a tab the tool rises to ``tab_height`` above the bottom.
Engraving runs at its operation's ``depth_per_pass`` (one pass).

Fill (issue 112: ``Text(..., font=, fill=true)``, the output's areas engraved filled): after
the engraving, each area as parallel lines ``fill.interval`` mm apart run to and fro
(:func:`~..fabrication.hatch.hatch_lines`), each a ``G1`` at the ``fill`` operation's power
and feed, a laser's or a plotter's; a router's fill (a pocket) is refused with an
:class:`~..part.part.OutputError` that says what to do instead.

Plotter (``kind = "plotter"``): the pen is Z: up at ``safe_height`` (``G0 Z``), down at
``Z0`` (``G1 Z0``); paths as the laser's, ``passes`` times.

Lead-in (profile ``lead_in`` mm, lasers and routers): each closed cut starts that far off its
path on the scrap side (to the right of the direction of travel: outside an outline, inside
a hole), a straight ``G1`` onto it, every point of which keeps :data:`LEAD_CLEARANCE` from
every other cut and the sheet's edge (:func:`lead_in`: shortened, moved to another entry of
the loop, or left out, with a note).  The first travel is always written, also to X0 Y0:
where the head is when the program starts is unknown.  A router's bit that cuts a part apart
(through-cuts nearer its edges than the bit's reach) is a warning (:func:`router_notes`), and so is
a bridge or strip beside a through-cut that the bit leaves thinner than the minimum wall.
Tabs that do not fit a cut are fewer or smaller (:func:`fit_tabs`, with a note).  The notes
are ``; note:`` lines of the header (:func:`read_summary`).

:func:`job` gives the program with its numbers (:class:`Job`: cut and travel lengths, the
time at the profile's speeds, warnings); :func:`write` is the registry's entry.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from ...geometry.shapes.curves import reverse
from ..part.part import Arc, EllipticArc, Line, Output, OutputError, Spline, fill_regions
from ..fabrication.machine import MAX_DEPTH_PASSES, MAX_JOB_MOVES, too_long
from .gcode_curves import CURVE_TOL, as_arcs  # noqa: F401  (CURVE_TOL: the module's own)
from ..part.build.sunk import DEFAULT_THICKNESS

GCODE_FORMATS = (".gcode", ".nc")
DECIMALS = 10          # digits after the point: 1e-10 mm


class Move:
    """One motion: ``g`` (0 travel, 1 line, 2 clockwise arc, 3 counter-clockwise arc) to
    ``(x, y)`` (None: unchanged) and ``z`` (None: unchanged); ``center`` for arcs; ``cut``:
    the tool cuts (laser on, tool or pen down)."""
    __slots__ = ("g", "x", "y", "z", "center", "cut")

    def __init__(self, g, x=None, y=None, z=None, center=None, cut=False):
        self.g, self.x, self.y, self.z, self.center, self.cut = g, x, y, z, center, cut


@dataclass
class Job:
    """A G-code program and its numbers: ``text``; ``cut`` (mm run cutting, every pass and
    depth), ``travel`` (mm of ``G0`` in XY), ``seconds`` (the job's time at the profile's
    feeds and travel speed, acceleration ignored), ``warnings`` (a profile's ``kerf`` or
    ``thickness`` unlike the program's), ``notes`` (what the program does that the drawing
    does not say: a shared cut cut once, a lead-in shortened, tabs fitted); ``dark`` (mm a
    laser ran at an operation's power 0: not cut, not in ``cut``); ``path`` (mm cut in the
    first pass of every cut: ``cut`` is ``path`` times the passes when every cut has as
    many)."""
    text: str
    cut: float
    travel: float
    seconds: float
    warnings: list = field(default_factory=list)
    notes: list = field(default_factory=list)
    dark: float = 0.0
    path: float = 0.0
    runs: dict = field(default_factory=dict)

    def summary(self, name: str) -> str:
        """``box.gcode: cut 2444.8 mm, travel 606.5 mm, about 11 min 54 s at the profile's
        speeds``."""
        return f"{name}: {estimate_text(self.cut, self.travel, self.seconds, self.dark, self.runs)}"


def passes(runs: dict) -> int | None:
    """How many times a job runs its whole path (``runs``: :attr:`Job.runs`, passes -> [mm of
    path, mm cut]), when every cut is run as many times; else None (cuts of different
    operations run a different number of times, or nothing is cut)."""
    used = [n for n, (path, _) in runs.items() if path > 1e-9]
    return used[0] if len(used) == 1 else None


def _plural(n: int) -> str:
    return f"{n} pass{'es' if n != 1 else ''}"


def estimate_text(cut: float, travel: float, seconds: float, dark: float = 0.0,
                  runs: dict | None = None) -> str:
    """The job's numbers in words (``cut``, ``travel``, ``dark``: mm; ``seconds``); ``dark``:
    the mm run with the beam off at an operation's power 0, said apart from the cut;
    ``runs`` (passes -> [mm of path, mm cut], :attr:`Job.runs`): the path said with its
    passes when some of it is run more than once (``cut 654.8 mm path x 2 passes = 1309.6
    mm``; ``cut 4800.1 mm (2355.3 mm path x 2 passes + 89.5 mm path x 1 pass)``: the
    built-in laser cuts twice, and the cut's length alone misled, issue 86)."""
    s = int(round(seconds))
    t = f"{s // 3600} h {s % 3600 // 60} min" if s >= 3600 else \
        f"{s // 60} min {s % 60} s" if s >= 60 else f"{s} s"
    off = f" ({dark:.1f} mm more with the beam off: power 0)" if dark > 0 else ""
    used = sorted(((n, path) for n, (path, _) in (runs or {}).items() if path > 1e-9),
                  reverse=True)
    if len(used) == 1 and used[0][0] > 1:
        said = f"cut {used[0][1]:.1f} mm path x {_plural(used[0][0])} = {cut:.1f} mm"
    elif len(used) > 1:
        said = f"cut {cut:.1f} mm (" + " + ".join(f"{path:.1f} mm path x {_plural(n)}"
                                                 for n, path in used) + ")"
    else:
        said = f"cut {cut:.1f} mm"
    return f"{said}{off}, travel {travel:.1f} mm, about {t} at the profile's speeds"


def read_summary(data: bytes) -> tuple[str, list[str], list[str]]:
    """The estimate line, the warnings and the notes of a program :func:`write` wrote (its
    header, the ``;`` lines before ``G21``), for ``aidl render`` to print."""
    estimate, warnings, notes = "", [], []
    for line in data.decode("ascii", "replace").splitlines():
        if not line.startswith(";"):
            break
        if line.startswith("; cut "):
            estimate = line[2:]
        elif line.startswith("; warning: "):
            warnings.append(line[len("; warning: "):])
        elif line.startswith("; note: "):
            notes.append(line[len("; note: "):])
    return estimate, warnings, notes


def machine_of(options):
    """The :class:`~..fabrication.machine.Machine` of ``options.machine`` (:func:`~..fabrication.machine.resolve`;
    None: the built-in laser).  Raises :class:`~..fabrication.machine.MachineError`."""
    from ..fabrication.machine import resolve
    return resolve(getattr(options, "machine", None), "laser")


# ------------------------------------------------------------------ numbers
def num(v: float) -> str:
    """``v`` with :data:`DECIMALS` decimals, trailing zeros and a bare point dropped."""
    t = f"{v:.{DECIMALS}f}".rstrip("0").rstrip(".")
    return "0" if t in ("-0", "") else t


def _round(v: float) -> float:
    return float(num(v))


# ------------------------------------------------------------------ tabs and lead-ins
def _split_at(seg, u: float):
    """``seg`` (a line or an arc) cut at length ``u`` from its start: (before, after)."""
    L = seg.length
    if isinstance(seg, Line):
        k = u / L
        m = (seg.start[0] + (seg.end[0] - seg.start[0]) * k,
             seg.start[1] + (seg.end[1] - seg.start[1]) * k)
        return Line(seg.start, m), Line(m, seg.end)
    k = u / L
    a = seg.sweep * k
    return (Arc(seg.center, seg.radius, seg.start_angle, a),
            Arc(seg.center, seg.radius, seg.start_angle + a, seg.sweep - a))


def fit_tabs(total: float, n: int, width: float) -> tuple[int, float]:
    """The tabs that fit a cut ``total`` mm long when ``n`` tabs of ``width`` mm are asked
    for: (count, width).  The tabs take at most half the cut: as many of ``width`` as fit
    that (fewer than ``n`` when they do not all fit), or where not even one does, one tab of a
    quarter of the cut; (0, 0) when no tabs are asked for."""
    if n <= 0 or width <= 0 or total <= 0:
        return 0, 0.0
    if total > 2 * n * width:
        return n, width
    k = min(n, int(total / (2 * width) * (1 - 1e-12)))
    return (k, width) if k >= 1 else (1, total / 4)


def with_tabs(path: list, n: int, width: float) -> list[tuple]:
    """``path`` (lines and arcs of a cut) as ``(segment, on_tab)`` pieces with ``n`` tabs
    of ``width`` mm, their middles evenly spaced along it, the first half a spacing from the
    start; the count and width as :func:`fit_tabs` fits them to the path's length."""
    total = sum(s.length for s in path)
    n, width = fit_tabs(total, n, width)
    if n <= 0:
        return [(s, False) for s in path]
    step = total / n
    marks = []
    for k in range(n):
        mid = step * (k + 0.5)
        marks += [(mid - width / 2, True), (mid + width / 2, False)]
    out, at, i = [], 0.0, 0
    on = False
    for s in path:
        L = s.length
        rest, base = s, at
        while i < len(marks) and marks[i][0] < base + rest.length - 1e-12:
            u = marks[i][0] - base
            if u > 1e-12:
                a, rest = _split_at(rest, u)
                out.append((a, on))
                base += a.length
            on = marks[i][1]
            i += 1
        out.append((rest, on))
        at += L
    return out


# mm: every point of a lead-in keeps at least this far from every other cut and the sheet's edge
LEAD_CLEARANCE = 0.5
LEAD_TRIES = 16        # entries of a loop tried for a lead-in that fits whole
LEAD_CHORD_TOL = 0.01  # mm: added to the clearance for the chords the cuts are sampled as


class _Paths:
    """Every cut path of a job as chords (the machine's cuts: other parts' material lies
    beyond them), each with the index of its cut, the lead-ins chosen so far, and the sheet
    (``page``: (x0, y0, x1, y1) mm, or None), for the lead-ins: :meth:`room` is how long a
    straight lead-in from a point can be and keep :data:`LEAD_CLEARANCE` from all of them."""

    def __init__(self, cuts, page, reach: float):
        """``reach``: the longest lead-in :meth:`room` is asked about (mm): the size of the
        grid cells the chords are filed in, so that a question looks at a few cells."""
        import numpy as np
        from ...geometry.shapes.curves import sample_xy
        a, b, owner = [], [], []
        self.index = {}
        for k, c in enumerate(cuts):
            self.index[id(c)] = k
            if not c.operation.startswith("cut"):
                continue
            xs, ys = [], []
            sample_xy(c.segments, xs, ys)
            if c.closed:
                xs.append(xs[0])
                ys.append(ys[0])
            else:
                xs.append(c.end[0])
                ys.append(c.end[1])
            a += list(zip(xs[:-1], ys[:-1]))
            b += list(zip(xs[1:], ys[1:]))
            owner += [k] * (len(xs) - 1)
        self.a = np.asarray(a, dtype=float).reshape(-1, 2)
        self.b = np.asarray(b, dtype=float).reshape(-1, 2)
        self.owner = np.asarray(owner, dtype=np.int64)
        self.page = page
        self.cell = max(float(reach), 1e-3)
        self.grid: dict = {}
        for k in range(len(self.a)):
            self._file(k, self.a[k], self.b[k])
        self.leads: list = []          # the lead-ins chosen: (start, end), owner -1

    def _file(self, k: int, p, q) -> None:
        lo = [math.floor(min(p[i], q[i]) / self.cell) for i in (0, 1)]
        hi = [math.floor(max(p[i], q[i]) / self.cell) for i in (0, 1)]
        for i in range(lo[0], hi[0] + 1):
            for j in range(lo[1], hi[1] + 1):
                self.grid.setdefault((i, j), []).append(k)

    def add_lead(self, p, q) -> None:
        """A lead-in from ``p`` to ``q`` is cut: the next lead-ins keep clear of it too."""
        self.leads.append((tuple(p), tuple(q)))
        self._file(-len(self.leads), p, q)

    def room(self, p, u, length: float, own=None) -> float:
        """How long (mm, at most ``length``) a straight move from ``p`` (a point of cut
        ``own``'s path) along unit ``u`` can be while every point of it stays at least
        :data:`LEAD_CLEARANCE` from every other cut's path and lead-in (0 when ``p`` itself
        is nearer than that to one), from its own cut's path once it is that far from ``p``
        (a hole's far side), and from the sheet's edge.  The set of points of the move
        nearer than the clearance to one chord is an interval of it (the move's line through
        the chord's capsule): the move stops where the first interval begins."""
        import numpy as np
        c = LEAD_CLEARANCE + LEAD_CHORD_TOL
        t = float(length)
        if self.page is not None:
            x0, y0, x1, y1 = self.page
            for k, (lo, hi) in enumerate(((x0, x1), (y0, y1))):
                if u[k] > 1e-15:           # towards the high edge: stop the clearance short
                    t = min(t, (hi - c - p[k]) / u[k])
                elif u[k] < -1e-15:
                    t = min(t, (lo + c - p[k]) / u[k])
        if t <= 0:
            return 0.0
        q = (p[0] + u[0] * t, p[1] + u[1] * t)
        x0, y0 = (math.floor((min(p[i], q[i]) - c) / self.cell) for i in (0, 1))
        x1, y1 = (math.floor((max(p[i], q[i]) + c) / self.cell) for i in (0, 1))
        near = {k for i in range(x0, x1 + 1) for j in range(y0, y1 + 1)
                for k in self.grid.get((i, j), ())}
        if not near:
            return t
        idx = np.fromiter(near, dtype=np.int64, count=len(near))
        mine = idx >= 0
        A = np.empty((len(idx), 2))
        B = np.empty((len(idx), 2))
        A[mine], B[mine] = self.a[idx[mine]], self.b[idx[mine]]
        if not mine.all():                     # lead-ins, filed as -1, -2, ...
            got = np.array([self.leads[-k - 1] for k in idx[~mine].tolist()], dtype=float)
            A[~mine], B[~mine] = got[:, 0], got[:, 1]
        lo, hi = _capsule_spans(np.asarray(p, dtype=float), np.asarray(u, dtype=float),
                                A, B, c)
        ownk = np.zeros(len(idx), dtype=bool)
        if own is not None:
            ownk[mine] = self.owner[idx[mine]] == own
        # its own path: only beyond the clearance from p (the move starts on it)
        start = np.where(ownk, c + LEAD_CHORD_TOL, 0.0)
        hit = hi > start
        if hit.any():
            t = min(t, float(np.maximum(lo[hit], start[hit]).min()) - 1e-9)
        return max(t, 0.0)


def _capsule_spans(p, u, A, B, r):
    """For each chord ``A[k]``-``B[k]`` (n x 2), the span ``[lo, hi]`` of the parameters s
    of the line ``p + s u`` (``u`` a unit vector) whose points are nearer than ``r`` to the
    chord (its capsule of radius ``r``); ``lo = inf``, ``hi = -inf`` where none is.  The
    capsule is convex: its span is the union of those of its two end discs and its middle
    rectangle."""
    import numpy as np
    inf = np.inf
    lo = np.full(len(A), inf)
    hi = np.full(len(A), -inf)
    for E in (A, B):                         # the discs at the ends
        d = p - E
        bb = d @ u
        disc = bb * bb - ((d * d).sum(1) - r * r)
        ok = disc > 0
        root = np.sqrt(np.where(ok, disc, 0.0))
        lo = np.where(ok, np.minimum(lo, -bb - root), lo)
        hi = np.where(ok, np.maximum(hi, -bb + root), hi)
    e = B - A
    L = np.hypot(e[:, 0], e[:, 1])
    good = L > 0
    eh = np.where(good[:, None], e / np.where(good, L, 1.0)[:, None], 0.0)
    nh = np.column_stack([-eh[:, 1], eh[:, 0]])
    d = p - A
    s_lo = np.full(len(A), -inf)
    s_hi = np.full(len(A), inf)
    for f0, f1, a, b in (((d * eh).sum(1), eh @ u, 0.0, L),
                         ((d * nh).sum(1), nh @ u, -r, r)):
        flat = np.abs(f1) < 1e-15
        inside = (a <= f0) & (f0 <= b)
        with np.errstate(divide="ignore", invalid="ignore"):
            t0 = (a - f0) / np.where(flat, 1.0, f1)
            t1 = (b - f0) / np.where(flat, 1.0, f1)
        s_lo = np.where(flat, np.where(inside, s_lo, inf), np.maximum(s_lo, np.minimum(t0, t1)))
        s_hi = np.where(flat, np.where(inside, s_hi, -inf), np.minimum(s_hi, np.maximum(t0, t1)))
    rect = good & (s_lo < s_hi)
    lo = np.where(rect, np.minimum(lo, s_lo), lo)
    hi = np.where(rect, np.maximum(hi, s_hi), hi)
    return lo, hi


def lead_in(cut, path: list, lead: float, paths: "_Paths"):
    """A closed cut's lead-in (profile ``lead_in``: ``lead`` mm): ``(path, start, length)``,
    the path turned to start where the lead-in meets it and the point it starts from, ``lead``
    mm to the right of the path (the scrap side: outside an outline, inside a hole), or
    shortened so that every point of it keeps :data:`LEAD_CLEARANCE` from every other cut,
    lead-in and the sheet's edge, and from its own path's far side (:meth:`_Paths.room`: it
    never crosses nor runs beside another part, a hole's far side or the sheet's edge).  The
    path's own start is tried first, then its other segment ends (up to :data:`LEAD_TRIES`):
    the first where the whole lead-in fits, else the longest.  ``(path, None, 0)`` when none
    is at least a quarter of ``lead`` (the cut starts on its path)."""
    from ...geometry.shapes.curves import Loop, tangent_at
    from ..fabrication.toolpath import _inside
    import numpy as np
    poly = None
    best = (path, None, 0.0)
    own = paths.index.get(id(cut))
    for j in range(min(len(path), LEAD_TRIES)):
        s = path[j]
        tx, ty = tangent_at(s, False)
        p0 = s.start
        u = (ty, -tx)                                 # the right of the direction of travel
        t = paths.room(p0, u, lead, own)
        if t <= best[2] or t < lead / 4:
            continue
        q = (p0[0] + t * u[0], p0[1] + t * u[1])
        if poly is None:
            poly = np.asarray(Loop(cut.segments).points())
        if (cut.operation == "cut_inner") != _inside(q, poly):
            continue                                  # not the scrap side (a sharp corner)
        best = (path[j:] + path[:j], q, t)
        if t >= lead * (1 - 1e-12):
            break
    if best[1] is not None:
        paths.add_lead(best[1], best[0][0].start)
    return best


# ------------------------------------------------------------------ the program
class _Writer:
    def __init__(self, machine):
        self.m = machine
        self.lines: list[str] = []
        # where the head is: unknown (None) until the first travel, which is therefore always
        # written, beam off / tool up, even to X0 Y0 (a job used to start cutting wherever
        # the head was); the estimates count that travel from the origin
        self.x = self.y = None
        self.z = None
        self.cut = self.travel = self.seconds = 0.0
        self.path = 0.0                # mm cut in the first pass of each cut
        self.first = True              # the pass being written is the first of its cut
        self.runs: dict = {}           # passes -> [mm of path cut that many times, mm cut]
        self.passes = 1                # how many passes the cut being written has
        self.feed = None
        self.power = None
        self.notes: list[str] = []
        self.changed: dict = {}        # (what, part) -> what _prepare changed (_changes)
        self.dark: dict = {}           # operation -> mm a laser ran at power 0 (no cut)

    def out(self, line: str) -> None:
        if len(self.lines) >= MAX_JOB_MOVES:
            raise too_long("G-code lines")
        self.lines.append(line)

    def setting(self, feed: float, power: float | None = None) -> None:
        """``G1 F.. S..`` (no motion) when the feed or power changes."""
        words = []
        if feed != self.feed:
            words.append(f"F{num(feed)}")
            self.feed = feed
        if power is not None and power != self.power:
            words.append(f"S{num(power)}")
            self.power = power
        if words:
            self.out("G1 " + " ".join(words))

    def rapid(self, x=None, y=None, z=None, off: bool = False) -> None:
        w = ["G0"]
        d = 0.0
        if x is not None:
            x, y = _round(x), _round(y)
            if (x, y) == (self.x, self.y) and z is None:
                return
            w += [f"X{num(x)}", f"Y{num(y)}"]
            d = math.hypot(x - (self.x or 0.0), y - (self.y or 0.0))
            self.travel += d
            self.x, self.y = x, y
        if z is not None:
            z = _round(z)
            if z == self.z and x is None:
                return
            w.append(f"Z{num(z)}")
            d = math.hypot(d, z - (self.z if self.z is not None else z))
            self.z = z
        if off:
            w.append("S0")
            self.power = 0.0
        self.seconds += d / self.m.travel_speed * 60.0
        self.out(" ".join(w))

    def plunge(self, z: float, feed: float) -> None:
        z = _round(z)
        if z == self.z:
            return
        self.setting(feed)
        d = abs(z - (self.z if self.z is not None else z))
        self.z = z
        self.seconds += d / feed * 60.0
        self.out(f"G1 Z{num(z)}")

    def segment(self, s, cutting: bool = True) -> None:
        """A line or an arc (of at most half a turn) from the current point."""
        ex, ey = _round(s.end[0]), _round(s.end[1])
        if isinstance(s, Line):
            L = math.hypot(ex - self.x, ey - self.y)
            if L == 0.0:
                return 0.0
            self.out(f"G1 X{num(ex)} Y{num(ey)}")
        else:
            if (ex, ey) == (self.x, self.y):
                # an arc too short for 1e-10 mm: G2/G3 to its own start is a whole circle
                return 0.0
            i, j = _round(s.center[0] - self.x), _round(s.center[1] - self.y)
            L = s.length
            self.out(f"{'G3' if s.sweep > 0 else 'G2'} X{num(ex)} Y{num(ey)} "
                     f"I{num(i)} J{num(j)}")
        if cutting:
            self.cut += L
            run = self.runs.setdefault(self.passes, [0.0, 0.0])
            run[1] += L
            if self.first:
                self.path += L
                run[0] += L
        self.seconds += L / self.feed * 60.0
        self.x, self.y = ex, ey
        return L


def job(output: Output, machine=None, thickness: float | None = None) -> Job:
    """The G-code :class:`Job` of ``output`` (as a cutter reads it: the program's kerf
    already applied) on ``machine`` (a :class:`~..fabrication.machine.Machine`; None: the built-in
    laser).  ``thickness``: mm a router cuts down to (None: each part's, else
    :data:`DEFAULT_THICKNESS`).  Raises :class:`~..part.part.OutputError` (a tool too large for a
    feature, naming the part)."""
    from ..fabrication import machine as M
    from ..fabrication.toolpath import plan
    m = machine or M.default("laser")
    fills = fill_regions(output.engrave)
    if fills and m.kind == "router":
        raise OutputError(f"a router does not fill `{fills[0][0]}` (its letters' area: a "
                          "pocket the bit's width inside the letters is not written); engrave "
                          "the outlines with a router (leave out fill=), or fill with a laser "
                          "or plotter profile (`--machine laser`)")
    warnings, notes, heads = _warnings(output, m), [], []
    if m.kind == "router":
        from ..part.edges.shared import shared_note
        notes += [n[len("note: "):] for n in shared_note(output, m.tool_diameter, "the bit")]
        more, split = router_notes(output, m.tool_diameter)
        notes += more
        warnings += split
        output, said, warned = routed_path(output, m)
        notes, warnings = notes + said, warnings + warned
        from .gcode_sinks import split as split_heads
        rest, heads = split_heads(output)       # sunk by a second operation, not engraved
        output = Output(output.parts, rest, output.title, output.drawing, output.page)
    # a laser runs an open path there and back (_body): an even number of passes ends it
    # where it started, and the tour goes on from there
    back = tuple(op for op in M.OPERATIONS
                 if m.kind == "laser" and m.operation(op).passes % 2 == 0)
    cuts = plan(output, back=back, hatch=m.operation("fill").interval)
    thick = {p.name: (thickness or p.thickness or DEFAULT_THICKNESS) for p in output.parts}
    w = _Writer(m)
    w.heads = heads if m.kind == "router" else []
    w.warnings = warnings
    w.notes = notes
    body = _body(w, cuts, m, thick, output)
    w.notes += _changes(w)
    w.warnings += _dark_warnings(w)
    head = _header(output, m, w)
    return Job("\n".join(head + body) + "\n", w.cut, w.travel, w.seconds, warnings, w.notes,
               sum(w.dark.values()), w.path, w.runs)


W0510_TAG = " (W0510)"      # ends a warning `aidl render` gives as a located W0510 instead
W0507_TAG = " (W0507)"      # ... and as a located W0507 (the material the bit leaves)
W0527_TAG = " (W0527)"      # ... and as a located W0527 (inside corners the bit leaves)
LOCATED_TAGS = (W0510_TAG, W0507_TAG, W0527_TAG)


def router_notes(output: Output, diameter: float) -> tuple[list[str], list[str]]:
    """What a router's bit of ``diameter`` mm does to ``output``'s through-cuts beyond the
    design: the warnings of the parts it cuts into more pieces
    (:func:`~..fabrication.bridges.router_bridges`, each ending :data:`W0510_TAG`) and, in
    the other parts, of the bridges and strips it leaves thinner than the program's minimum
    wall or cuts away (:func:`~..checks.toolpath_walls.eaten_walls`, each ending
    :data:`W0507_TAG`); ``(notes, warnings)``, the notes empty (kept for the callers)."""
    from ..checks import part_min_wall
    from ..checks.material.toolpath_walls import eaten_message, eaten_walls
    from ..fabrication.bridges import router_bridges, split_message
    _, splits = router_bridges(output, diameter)
    split = {s.part for s in splits if s.bridges}       # else W0507 names the bridges
    d = output.drawing

    def min_wall_of(name):
        return part_min_wall(d, d.part_of.get(name)) if d is not None else 0.5
    eaten = [e for e in eaten_walls(output, diameter, min_wall_of) if e.part not in split]
    return [], [split_message(s, diameter) + W0510_TAG for s in splits] + \
        [eaten_message(e, diameter, True)[0] + W0507_TAG for e in eaten]


def tool_path(output: Output, diameter: float) -> Output:
    """``output`` offset by a router's tool radius (:func:`~..fabrication.layout.compensate` with a kerf
    of ``diameter``: outlines outward, holes inward, exact lines and arcs); ellipse and
    spline pieces are first made arcs (:func:`as_arcs`, within :data:`CURVE_TOL`), whose
    offset is exact.  Raises :class:`~..part.part.OutputError` naming the part where the tool is
    too large for a feature."""
    from ...geometry.shapes.curves import Loop
    from ..fabrication.layout import LayoutError, compensate
    from ..part.part import PartOutline
    parts = []
    for p in output.parts:
        if any(isinstance(g, (EllipticArc, Spline)) for lp in p.loops for g in lp.segments):
            p = PartOutline(p.name, p.kind, [Loop([g for s in lp.segments for g in as_arcs(s)])
                                              for lp in p.loops], p.thickness)
        parts.append(p)
    try:
        tooled = compensate(Output(parts, output.engrave, output.title, output.drawing,
                                   output.page), diameter)
    except LayoutError as e:
        msg = str(e).replace(f"kerf {diameter:g} mm on part", "the router's tool "
                             f"({diameter:g} mm across) does not fit part", 1)
        raise OutputError(f"{msg}; use a smaller tool (the profile's `tool_diameter`)") \
            from None
    return tooled


def routed_path(output: Output, m) -> tuple[Output, list[str], list[str]]:
    """What router profile ``m``'s bit runs on ``output``: :func:`tool_path` with the reliefs
    that fit the program's `min_wall` (:func:`~..fabrication.reliefs.relieved`), its words."""
    from ..checks.common import part_min_wall as wall
    from ..fabrication.reliefs import relieved
    return relieved(output, tool_path(output, m.tool_diameter), m, W0527_TAG, lambda n: wall(
        output.drawing, (getattr(output.drawing, "part_of", None) or {}).get(n)))


def _warnings(output: Output, m) -> list[str]:
    """A profile's ``kerf`` / ``thickness`` unlike the program's: one line each."""
    out = []
    d = output.drawing
    src = f"the machine profile `{m.source}`" if m.source else "the machine profile"
    if m.kerf is not None:
        prog = d.kerf if d is not None else None
        vals = set(prog.values()) if isinstance(prog, dict) else {prog or 0.0}
        vals = vals or {0.0}
        if any(abs(v - m.kerf) > 1e-9 for v in vals):
            shown = ", ".join(f"{v:g}" for v in sorted(vals))
            out.append(f"{src} says `kerf = {m.kerf:g}` mm but the program's kerf is {shown} mm; "
                       "the program's is used (set `kerf` in the program, or --kerf)")
    if m.thickness is not None:
        vals = {p.thickness for p in output.parts if p.thickness is not None}
        if any(abs(v - m.thickness) > 1e-9 for v in vals):
            shown = ", ".join(f"{v:g}" for v in sorted(vals))
            out.append(f"{src} says `thickness = {m.thickness:g}` mm but the program's "
                       f"thickness is {shown} mm; the program's is used (set `thickness` in "
                       "the program, or --thickness)")
    return out


def _header(output: Output, m, w: _Writer) -> list[str]:
    src = m.source or f"built-in {m.kind} profile"
    filled = any(st.style == "fill" for st in output.engrave)
    h = [f"; {output.title or 'aidl'}: G-code (GRBL) written by aidl",
         f"; machine: {m.kind} ({src})" + (f"\n; tool: {m.tool_text()}" if m.kind == "router" else ""),
         f"; {estimate_text(w.cut, w.travel, w.seconds, sum(w.dark.values()), w.runs)}",
         *[f"; warning: {x}" for x in w.warnings],
         *[f"; note: {x}" for x in w.notes],
         "; units mm, absolute; arcs G2/G3 with I/J relative to the start",
         "G21 G90 G17"]
    for name in ("engrave", "score", "cut_inner", "cut_outer") + (("fill",) if filled else ()):
        op = m.operation(name)
        lines = f", lines {op.interval:g} mm apart" if name == "fill" else ""
        if m.kind == "laser":
            h.insert(-1, f"; {name}: {op.power:g} % power, F{op.speed:g}, {op.passes} pass"
                     + ("es" if op.passes != 1 else "") + lines)
        elif m.kind == "router":
            h.insert(-1, f"; {name}: F{op.speed:g}, plunge F{op.plunge:g}, "
                     f"{op.depth_per_pass:g} mm per pass, S{op.spindle:g} rpm")
        else:
            h.insert(-1, f"; {name}: F{op.speed:g}, {op.passes} pass"
                     + ("es" if op.passes != 1 else "") + lines)
    return h


def _prepare(w: _Writer, cut, path: list, paths) -> tuple:
    """A cut's path turned to start at its lead-in (:func:`lead_in`; ``paths``: None without
    one), the lead-in's start (None: none) and the path as ``(segment, on_tab)`` pieces
    (:func:`with_tabs` on outer cuts).  What differs from the profile (a lead-in shortened or
    left out, tabs that do not fit) is kept in ``w.changed`` for :func:`_changes`."""
    m = w.m
    lead = None
    if paths is not None and cut.closed and cut.operation.startswith("cut"):
        path, lead, t = lead_in(cut, path, m.lead_in, paths)
        if t < m.lead_in * (1 - 1e-9):
            w.changed.setdefault(("lead", cut.part), []).append(t)
    tabs = m.tabs if cut.operation == "cut_outer" else 0
    if tabs:
        total = sum(s.length for s in path)
        got = fit_tabs(total, tabs, m.tab_width)
        if got != (tabs, m.tab_width):
            w.changed.setdefault(("tabs", cut.part), []).append((total, *got))
    pieces = with_tabs(path, tabs, m.tab_width) if tabs else [(s, False) for s in path]
    return path, lead, pieces


def _dark_warnings(w: _Writer) -> list[str]:
    """A laser operation at power 0 (``w.dark``): its moves run with the beam off and cut
    nothing; one warning naming the profile's setting, the length not counted as cut."""
    m = w.m
    src = f"the machine profile `{m.source}`" if m.source else "the machine profile"
    return [f"{src} gives `{op}.power = 0`: the {mm:.1f} mm of {op.replace('_', ' ')} run with "
            f"the beam off and cut nothing (not counted as cut); give `{op}.power` above 0, "
            "up to 100 %, to cut them" for op, mm in w.dark.items()]


def _changes(w: _Writer) -> list[str]:
    """The notes of what the program does other than the profile says (``w.changed``): a
    lead-in shortened or left out where another part or the sheet's edge is nearer than it,
    tabs fewer or smaller where they do not fit the cut."""
    m, out = w.m, []
    tabs = [(part, *g) for (what, part), got in w.changed.items() if what == "tabs"
            for g in got]
    for part, total, n, width in tabs[:3]:
        out.append(f"{m.tabs} tabs of {m.tab_width:g} mm do not fit the {total:.4g} mm cut of "
                   f"`{part}` (tabs take at most half of it): cut with {n} tab"
                   f"{'s' if n != 1 else ''} of {width:.3g} mm")
    if len(tabs) > 3:
        k = len(tabs) - 3
        out.append(f"and {k} more cut{'s' if k != 1 else ''} with fewer or smaller tabs than "
                   "the profile's")
    for (what, part), got in w.changed.items():
        who = f"`{part}`" if part else "the drawing"
        if what == "lead":
            cut_ = [t for t in got if t > 0]
            if cut_:
                out.append(f"{len(cut_)} lead-in{'s' if len(cut_) != 1 else ''} of {who} "
                           f"shortened to {min(cut_):.3g} mm (of {m.lead_in:g} mm): another "
                           "cut or the sheet's edge is nearer; a lead-in keeps "
                           f"{LEAD_CLEARANCE:g} mm from every other cut and the sheet's edge")
            if len(cut_) < len(got):
                k = len(got) - len(cut_)
                out.append(f"{k} cut{'s' if k != 1 else ''} of {who} start{'s' if k == 1 else ''}"
                           f" on {'its' if k == 1 else 'their'} path without a lead-in: no room "
                           f"for one of {m.lead_in / 4:g} mm or more that keeps "
                           f"{LEAD_CLEARANCE:g} mm from the other cuts")
    return out


def _body(w: _Writer, cuts, m, thick: dict, output: Output) -> list[str]:
    if m.kind == "laser":
        w.out(f"{m.laser_mode} S0")
        w.power = 0.0
    elif m.kind == "router":
        op0 = m.operation("cut_outer")
        w.out(f"M3 S{num(op0.spindle)}")
        w.rapid(z=m.safe_height)
    else:
        w.rapid(z=m.safe_height)
    spindle = m.operation("cut_outer").spindle if m.kind == "router" else None
    paths = _Paths(cuts, output.page, m.lead_in + LEAD_CLEARANCE) if m.lead_in > 0 else None
    for cut in cuts:
        op = m.operation(cut.operation)
        path = [g for s in cut.segments for g in as_arcs(s)]
        if not path:
            continue
        path, lead, pieces = _prepare(w, cut, path, paths)
        start = lead or path[0].start
        if m.kind == "laser":
            power = op.power / 100.0 * m.max_power
            lit = power > 0          # at power 0 the moves cut nothing (_dark_warnings)
            dark = 0.0
            back = [] if cut.closed else [(reverse(s), tab) for s, tab in reversed(pieces)]
            w.passes = max(1, op.passes)
            for k in range(max(1, op.passes)):
                w.first = k == 0
                if k == 0 or lead:
                    w.rapid(*start, off=True)
                if lead:
                    w.setting(op.speed, power)
                    dark += w.segment(Line(lead, path[0].start), lit)
                for s, on_tab in (back if back and k % 2 else pieces):
                    w.setting(op.speed, 0.0 if on_tab else power)
                    got = w.segment(s, lit and not on_tab)
                    dark += 0.0 if on_tab else got
            if not lit:
                w.dark[cut.operation] = w.dark.get(cut.operation, 0.0) + dark
        elif m.kind == "plotter":
            w.passes = max(1, op.passes)
            for k in range(max(1, op.passes)):
                w.first = k == 0
                if k == 0 or not cut.closed:
                    w.rapid(z=m.safe_height)
                    w.rapid(*start)
                    w.plunge(0.0, op.speed)
                if lead:
                    w.setting(op.speed)
                    w.segment(Line(lead, path[0].start))
                w.setting(op.speed)
                for s, _ in pieces:
                    w.segment(s)
            w.rapid(z=m.safe_height)
        else:
            if op.spindle != spindle:
                spindle = op.spindle
                w.out(f"M3 S{num(spindle)}")
            if cut.operation in ("engrave", "score"):
                depths = [op.depth_per_pass]
            else:
                t = thick.get(cut.part) or DEFAULT_THICKNESS
                n = max(1, math.ceil(t / op.depth_per_pass - 1e-9))
                if n > MAX_DEPTH_PASSES:
                    raise OutputError(
                        f"the router would cut part `{cut.part}` ({t:g} mm thick) in {n:,} "
                        f"passes of {op.depth_per_pass:g} mm (`{cut.operation}.depth_per_pass`"
                        f"); at most {MAX_DEPTH_PASSES:,}: raise depth_per_pass or cut "
                        "thinner material (--thickness); nothing was written")
                depths = [t * (k + 1) / n for k in range(n)]
            t_part = thick.get(cut.part) or DEFAULT_THICKNESS
            w.passes = len(depths)
            for k, dz in enumerate(depths):
                w.first = k == 0
                if k == 0 or not cut.closed or lead:
                    w.rapid(z=m.safe_height)
                    w.rapid(*start)
                w.plunge(-dz, op.plunge)
                if lead:
                    w.setting(op.speed)
                    w.segment(Line(lead, path[0].start))
                w.setting(op.speed)
                tab_z = -(t_part - m.tab_height)
                for s, on_tab in pieces:
                    if on_tab and -dz < tab_z:
                        w.plunge(tab_z, op.plunge)
                        w.setting(op.speed)
                        w.segment(s, False)
                        w.plunge(-dz, op.plunge)
                        w.setting(op.speed)
                    else:
                        w.segment(s)
            w.rapid(z=m.safe_height)
    if getattr(w, "heads", None):           # the router's countersinks and counterbores
        from .gcode_sinks import write as sink_ops
        w.notes += sink_ops(w, m, w.heads, output, thick, DEFAULT_THICKNESS)
    if m.kind == "laser":
        w.out("M5")
        w.rapid(0.0, 0.0, off=True)
    else:
        w.rapid(z=m.safe_height)
        if m.kind == "router":
            w.out("M5")
        w.rapid(0.0, 0.0)
    w.out("M2")
    return w.lines


def write(output: Output, options) -> bytes:
    """The registry's entry (:data:`~.FORMATS`): :func:`job` on ``options.machine``
    (:func:`machine_of`) and ``options.thickness``, ASCII."""
    return job(output, machine_of(options), options.thickness).text.encode("ascii")
