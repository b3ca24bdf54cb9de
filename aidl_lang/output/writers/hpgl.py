"""HPGL writer (``.plt`` / ``.hpgl``) for vinyl cutters and pen plotters, from the exact output
model (:class:`~..part.part.Output`) in the cut order of :func:`~..fabrication.toolpath.plan`
(docs/machines.md, "Vinyl cutter and pen plotter").

What it writes, one command a line (HP-GL/1, which cutters and plotters read alike)::

    IN;                         initialise
    SP1;                        the pen (a cutter's knife): one for everything
    VS25;                       the operation's speed, cm/s (the machine profile's mm/min / 600)
    PU1200,400;                 move with the pen up to a path's start
    PD1600,400,1600,800;        lines, and spline and ellipse pieces as short lines
    PD;                         the pen down where it is (before an arc that starts a path)
    AA1200,800,90,0.6;          an arc: centre, sweep in degrees (counter-clockwise positive),
                                chord angle in degrees (what the plotter draws it with)
    PU;SP0;                     at the end: pen up, pen put away

* **Units**: 40 plotter units per mm (1016 a inch, HP's unit of 0.025 mm), whole numbers: every
  written point is the design's point rounded to the nearest unit, at most half a unit
  (0.0125 mm) off in x and in y.  The origin is the drawing's lower-left corner (a cutting
  layout's sheet corner), so every coordinate is >= 0 (cutters refuse negative ones); y points
  up, as in the design and in HPGL.
* **Arcs** (``AA``) start at the pen and turn about the written centre by the written sweep:
  the centre is the design's centre rounded to whole units, or when the arc about it would
  stray more than :data:`TOLERANCE` from the design's (rounding moved its start), the
  neighbouring whole-unit point whose arc lies nearest (at most 1.5 units off), the sweep the exact angle in those units from the written start
  to the written end (4 decimals), and a ``PD`` to the written end follows when the plotter's
  arc ends off it (the next piece starts where the design says).  A whole circle is ``AA`` of
  +-360 degrees from its start (the direction kept: a hole's circle runs clockwise).  The chord
  angle asks the plotter for chords within :data:`CHORD_SAGITTA` of the arc.  An arc whose
  drawn path would be more than :data:`TOLERANCE` off the design (tiny radii) is written as
  lines instead.
* **Ellipse and spline pieces** are ``PD`` polylines whose chords are within
  :data:`POLY_SAGITTA` of the curve.
* The bound: every point the cutter or plotter draws is within :data:`TOLERANCE` = 1 unit
  (0.025 mm) of the design (rounding plus chords).
* **Order**: :func:`~..fabrication.toolpath.plan`: engraving and scoring first (an area
  engraved filled, ``Text(..., font=, fill=true)``, as its closed loops at the ``fill``
  operation's speed: a vinyl cutter cuts the letters out and weeding leaves them filled; a pen
  plotter's line fill is the G-code's, ``--machine plotter``), then part by part each
  part's inner loops before its outline.  One pen for everything: a vinyl cutter has one knife,
  and a pen plotter user who wants two pens changes the pen after the engraving (it all comes
  first).  ``VS`` sets each operation's speed from the machine profile (``--machine FILE``, the
  built-in ``plotter`` profile without one), and each path is run ``passes`` times.

Reference: HP's *The HP-GL/2 and HP RTL Reference Guide* (``IN``, ``SP``, ``VS``, ``PU``,
``PD``, ``AA``).
"""
from __future__ import annotations

import math

from ..fabrication import machine as machine_mod
from ..part.extent import extent
from ..part.part import Arc, Circle, EllipticArc, Line, Output, OutputError, Spline

UNITS_PER_MM = 40.0          # plotter units per mm (1016 per inch)
TOLERANCE = 1.0              # units: the most any drawn point is off the design (0.025 mm)
CHORD_SAGITTA = 0.1          # units: the plotter's chords of an arc (its chord angle)
POLY_SAGITTA = 0.25          # units: the chords of ellipse and spline pieces (and fallbacks)
MIN_CHORD_ANGLE = 0.5        # degrees: the smallest chord angle plotters take
MAX_POINTS = 64              # points per PD command (cutters' command buffers are short)
NEIGHBOURS = [(dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy]
MAX_UNITS = 2 ** 23          # 8388608 units = 210 m: past it a plotter's integers overflow


def _machine(options):
    """The machine profile of ``options.machine`` (:func:`~..fabrication.machine.resolve`: a profile, a
    kind, a TOML path or a table; None: the built-in plotter profile)."""
    return machine_mod.resolve(getattr(options, "machine", None), "plotter")


class _Writer:
    def __init__(self, x0: float, y0: float):
        self.x0, self.y0, self.k = x0, y0, UNITS_PER_MM
        self.out: list[str] = []
        self.pd: list = []
        self.pen = None          # where the pen is (whole units)
        self.lowered = False     # the pen is down (AA draws only with the pen down)

    # coordinates
    def u(self, p) -> tuple[float, float]:
        """A design point (mm) in plotter units, not rounded."""
        return ((p[0] - self.x0) * self.k, (p[1] - self.y0) * self.k)

    def r(self, p) -> tuple[int, int]:
        """A design point (mm) in whole plotter units."""
        x, y = self.u(p)
        return (int(round(x)), int(round(y)))

    # commands
    def flush(self) -> None:
        for i in range(0, len(self.pd), MAX_POINTS):
            pts = self.pd[i:i + MAX_POINTS]
            self.out.append("PD" + ",".join(f"{x},{y}" for x, y in pts) + ";")
            self.lowered = True
        self.pd = []

    def up(self, q) -> None:
        self.flush()
        self.out.append(f"PU{q[0]},{q[1]};")
        self.pen = q
        self.lowered = False

    def down(self, q) -> None:
        if q != self.pen:
            self.pd.append(q)
            self.pen = q

    def polyline(self, pts_mm) -> None:
        for p in pts_mm:
            self.down(self.r(p))

    # segments
    def segment(self, s) -> None:
        if isinstance(s, Line):
            self.down(self.r(s.end))
        elif isinstance(s, Circle):
            sweep = 2 * math.pi if s.ccw else -2 * math.pi
            self.arc(Arc(s.center, s.radius, 0.0, sweep))
        elif isinstance(s, Arc):
            self.arc(s)
        elif isinstance(s, EllipticArc):
            self.polyline(_ellipse_points(s, POLY_SAGITTA / self.k))
        elif isinstance(s, Spline):
            self.polyline(_spline_points(s, POLY_SAGITTA / self.k))
        else:                                           # pragma: no cover
            raise OutputError(f"HPGL cannot write a {type(s).__name__} segment")

    def arc(self, a: Arc) -> None:
        """Arc ``a`` from the pen (see the module docstring)."""
        whole = abs(abs(a.sweep) - 2 * math.pi) < 1e-12
        p = self.pen
        e = p if whole else self.r(a.end)
        c = self.u(a.center)
        rad = a.radius * self.k
        best = None
        if rad >= 2.0 and (whole or e != p):
            base = (int(round(c[0])), int(round(c[1])))
            best = _fit(p, e, base, c, rad, a.sweep, whole)
            if best is None or best[0] > TOLERANCE - 1e-3:
                for dx, dy in NEIGHBOURS:
                    cand = _fit(p, e, (base[0] + dx, base[1] + dy), c, rad, a.sweep, whole)
                    if cand is not None and (best is None or cand[0] < best[0]):
                        best = cand
        if best is None or best[0] > TOLERANCE - 1e-3:
            # lines within POLY_SAGITTA of the arc, each end rounded
            n = _chords(rad, abs(a.sweep), POLY_SAGITTA)
            self.polyline([a.at(a.start_angle + a.sweep * i / n) for i in range(1, n + 1)])
            if whole:
                self.down(p)
            return
        _, cr, sweep_deg, chord, end = best
        self.flush()
        if not self.lowered:             # an arc follows the pen: lower it where it is
            self.out.append("PD;")
            self.lowered = True
        self.out.append(f"AA{cr[0]},{cr[1]},{_num(sweep_deg, 4)},{_num(chord, 3)};")
        if abs(end[0] - e[0]) > 1e-6 or abs(end[1] - e[1]) > 1e-6:
            self.pd.append(e)            # the plotter ended between units: on to the written end
        self.pen = e


def _num(v: float, digits: int) -> str:
    s = f"{v:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _chords(radius: float, sweep: float, sagitta: float) -> int:
    """Chords of an arc of ``radius`` and ``sweep`` (radians) within ``sagitta``."""
    if radius <= sagitta:
        return max(1, math.ceil(sweep / (math.pi / 2)))
    step = 2 * math.acos(1 - sagitta / radius)
    return max(1, math.ceil(sweep / step - 1e-12))


def _fit(p, e, cr, c, rad, sweep, whole):
    """The arc from whole-unit start ``p`` about whole-unit centre ``cr`` to end ``e``
    (``whole``: the full turn): (its largest distance from the design circle ``c``, ``rad``
    plus the chords', ``cr``, the sweep in degrees, the chord angle, where the plotter ends);
    None when ``p`` is at ``cr``."""
    vx, vy = p[0] - cr[0], p[1] - cr[1]
    rho = math.hypot(vx, vy)
    if rho < 1.0:
        return None
    a0 = math.atan2(vy, vx)
    if whole:
        s = math.copysign(2 * math.pi, sweep)
    else:
        a1 = math.atan2(e[1] - cr[1], e[0] - cr[0])
        s = a1 - a0
        s += 2 * math.pi * round((sweep - s) / (2 * math.pi))
    sweep_deg = round(math.degrees(s), 4)
    s = math.radians(sweep_deg)
    chord = 2 * math.degrees(math.acos(max(-1.0, 1 - CHORD_SAGITTA / rho)))
    chord = min(180.0, max(MIN_CHORD_ANGLE, round(chord, 3)))
    sag = rho * (1 - math.cos(math.radians(chord) / 2))
    n = max(8, math.ceil(abs(s) / math.radians(5)))
    dev = 0.0
    for i in range(n + 1):
        t = a0 + s * i / n
        qx, qy = cr[0] + rho * math.cos(t), cr[1] + rho * math.sin(t)
        dev = max(dev, abs(math.hypot(qx - c[0], qy - c[1]) - rad))
    end = (cr[0] + rho * math.cos(a0 + s), cr[1] + rho * math.sin(a0 + s))
    return (dev + sag, cr, sweep_deg, chord, end)


def _ellipse_points(s: EllipticArc, tol: float) -> list:
    """Points after the start of elliptical arc ``s``, its chords within ``tol`` mm (equal
    parameter steps: each chord's sagitta at most that of the circle of the major semi-axis
    over the same angle)."""
    n = _chords(max(s.curve.rx, s.curve.ry), abs(s.sweep), tol)
    return [s.curve.at(s.start_param + s.sweep * i / n) for i in range(1, n + 1)]


def _spline_points(s: Spline, tol: float) -> list:
    """Points after the start of spline piece ``s``, its chords within ``tol`` mm."""
    from ...geometry.shapes.spline import bez_at, bez_pieces
    out = []
    for b in s.spans:
        k = bez_pieces(b, tol)
        out += [bez_at(b, i / k) for i in range(1, k + 1)]
    return out


def to_hpgl(output: Output, options=None) -> str:
    """The HPGL text of ``output`` (see the module docstring); speeds and passes from
    ``options.machine`` (a :class:`~..fabrication.machine.Machine`) or the built-in plotter profile.
    Raises :class:`~..part.part.OutputError` for a drawing too large for a
    plotter's coordinates."""
    from ..fabrication.toolpath import plan
    m = _machine(options)
    x0, y0, x1, y1 = extent(output)
    if max(x1 - x0, y1 - y0) * UNITS_PER_MM > MAX_UNITS:
        raise OutputError(f"the drawing is {x1 - x0:.0f} x {y1 - y0:.0f} mm, too large for "
                          f"HPGL's coordinates ({MAX_UNITS / UNITS_PER_MM / 1000:.0f} m at "
                          "most); make it smaller")
    cuts = plan(output)         # an area engraved filled: its loops (a cutter cuts them out)
    if sum(len(c.segments) * max(1, int(m.operation(c.operation).passes))
           for c in cuts) > machine_mod.MAX_JOB_MOVES:
        raise machine_mod.too_long("HPGL segments")
    w = _Writer(x0, y0)
    w.out += ["IN;", "SP1;"]
    speed = None
    for c in cuts:
        op = m.operation(c.operation)
        vs = _num(max(0.1, op.speed / 600.0), 1)        # mm/min -> cm/s
        if vs != speed:
            w.flush()
            w.out.append(f"VS{vs};")
            speed = vs
        for _ in range(max(1, int(op.passes))):
            w.up(w.r(c.start))
            for s in c.segments:
                w.segment(s)
            w.flush()
    w.out += ["PU;", "SP0;"]
    return "\n".join(w.out) + "\n"


def write(output: Output, options) -> bytes:
    """The registry's entry (:data:`~.FORMATS`): :func:`to_hpgl`, ASCII."""
    return to_hpgl(output, options).encode("ascii")
