"""Cutting layouts: an assembly's parts placed flat on sheets, and kerf compensation
(docs/outputs.md, "Cutting an assembly").

:func:`lay_out` maps an :class:`~.part.Output` to one laid-out ``Output`` per sheet.  Every
solid part is placed once, by a rigid motion (a rotation about the origin, then a
translation) applied to each of its exact segments: a line's ends, an arc's center (its start
angle turned by the rotation; radius and sweep kept), a circle's center.  Nothing is
re-tessellated, so a placed part is the designed part to floating-point accuracy.  Engraving
moves with the part that holds it; engraving outside every part (an illustration at assembly
level) is left out.

Where the parts go is decided by true-shape nesting: ``spyrrow`` (Python bindings of
*sparrow*, the state-of-the-art strip packer built on the *jagua-rs* collision engine; MIT,
wheels for CPython 3.10+), in the ``layout`` extra.  Each part is given to it as its outer
outline cut into chords and grown by ``gap / 2`` plus :data:`SAFETY` (Manifold offset with
miter joins, which contains the round offset, so the grown polygon holds the exact curves and
the gap); it packs these polygons in a strip as high as the sheet.  Parts that end past the
sheet's width go to the next sheet, where the packer runs again on those that are left (any
subset of a packing is a packing, so every sheet is valid).  Holes are not used to nest small
parts (the packer takes outer outlines only).

:func:`compensate` offsets every cut by half the kerf (:func:`~..geometry.offset.offset_loop`).
"""
from __future__ import annotations

import math
import os

from ...geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Loop, Spline
from ...geometry.derived.offset import OffsetError, offset_loop
from ...geometry.shapes.biarc import as_arcs
from ..part.part import MissingDependency, Output, OutputError, PartOutline, Stroke
from ..part.edges.shared import shared_edges

SAFETY = 0.01        # mm added to the gap around each part: chords, the packer's f32 positions
INSTALL = "pip install 'aidl-lang[layout]'"


class LayoutError(OutputError):
    """The parts cannot be laid out as asked (a part larger than the sheet, a kerf larger than
    a feature); the message names the part."""


class KerfError(LayoutError):
    """A kerf the part's cuts cannot be offset by (a hole or slot narrower than the beam, an
    arc of a smaller radius than half the kerf): ``part`` (its name), ``where`` (the point,
    mm, the message names, or None) and ``kerf`` (mm); reported as a located ``E0504``
    (:meth:`diagnostic`, by ``aidl render`` and the MCP ``render`` tool)."""

    def __init__(self, message: str, part: str, where, kerf: float):
        super().__init__(message)
        self.part, self.where, self.kerf = part, where, kerf

    def diagnostic(self, drawing):
        """The ``E0504`` :class:`~aidl_lang.base.diagnostics.Diagnostic` of this error: at
        the hole of the part nearest the point the message names (a slot narrower than the
        beam), else at the part's structure (``drawing.part_of``), or unlocated without a
        drawing."""
        from ...base.diagnostics import Diagnostic
        part = (getattr(drawing, "part_of", None) or {}).get(self.part)
        at = part
        if part is not None and self.where is not None:
            x, y = self.where
            best = 0.5                  # mm: a hole this near the point, else the part
            for c in drawing.cuts:
                shape = drawing.shapes.get(c.hole)
                if shape is None or shape.is_empty() or getattr(c.hole, "span", None) is None \
                        or not c.owner.is_within(part):
                    continue
                x0, y0, x1, y1 = shape.bounds()
                gap = max(x0 - x, x - x1, y0 - y, y - y1, 0.0)
                if gap < best:
                    best, at = gap, c.hole
        k = self.kerf
        return Diagnostic("E0504", str(self), getattr(at, "span", None), "error", hint=(
            f"the beam is {k:g} mm wide, so an opening narrower than {k:g} mm, or a curve of "
            f"one with a radius under {k / 2:g} mm, cannot be cut to size: widen it to {k:g} "
            f"mm or more (a slit as wide as the beam is a `cut` line), give the curve a radius "
            f"of {k / 2:g} mm or more, or render with a narrower `--kerf`"))


# ------------------------------------------------------------------ rigid motions
def _rotation(deg: float) -> tuple[float, float]:
    """(cos, sin) of ``deg`` degrees, exact at multiples of 90."""
    q, r = divmod(deg, 90.0)
    if r == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(q) % 4]
    a = math.radians(deg)
    return math.cos(a), math.sin(a)


class Motion:
    """``p -> R(deg) (p - about) + to``: a rotation by ``deg`` degrees about ``about``, then a
    translation that takes ``about`` to ``to`` (mm)."""

    def __init__(self, deg: float = 0.0, about=(0.0, 0.0), to=(0.0, 0.0)):
        self.deg = deg
        self.cs, self.sn = _rotation(deg)
        self.about = (float(about[0]), float(about[1]))
        self.to = (float(to[0]), float(to[1]))

    def point(self, p):
        x, y = p[0] - self.about[0], p[1] - self.about[1]
        return (self.cs * x - self.sn * y + self.to[0], self.sn * x + self.cs * y + self.to[1])

    def segment(self, s):
        if isinstance(s, Spline):          # a rigid motion of the control points is exact
            from ...geometry.shapes.spline import CubicSpline
            c = s.curve
            moved = CubicSpline(tuple(self.point(p) for p in c.ctrl), c.h, c.closed)
            return Spline(moved, s.u0, s.u1)
        if isinstance(s, EllipticArc):     # the same ellipse turned: its parameter is kept
            e = s.curve
            from ...geometry.shapes.ellipse import ellipse
            moved, shift = ellipse(self.point(e.center), e.rx, e.ry,
                                   e.rotation + math.radians(self.deg))
            return EllipticArc(moved, s.start_param - shift, s.sweep)
        if isinstance(s, Line):
            return Line(self.point(s.start), self.point(s.end))
        if isinstance(s, Circle):
            return Circle(self.point(s.center), s.radius, s.ccw)
        return Arc(self.point(s.center), s.radius, s.start_angle + math.radians(self.deg),
                   s.sweep)

    def loop(self, lp: Loop) -> Loop:
        return Loop([self.segment(s) for s in lp.segments])

    def part(self, p: PartOutline) -> PartOutline:
        return PartOutline(p.name, p.kind, [self.loop(lp) for lp in p.loops], p.thickness)

    def stroke(self, st: Stroke) -> Stroke:
        moved = [self.segment(s) for s in st.segments]
        if hasattr(st, "moved"):            # a countersink's head keeps its record
            return st.moved(moved)
        return Stroke(moved, st.style, st.closed, st.source, st.part)


def part_box(p: PartOutline) -> tuple[float, float, float, float]:
    """The exact bounding box (x0, y0, x1, y1, mm) of a part's loops."""
    x0 = y0 = math.inf
    x1 = y1 = -math.inf
    for lp in p.loops:
        for s in lp.segments:
            a, b, c, d = s.box()
            x0, y0, x1, y1 = min(x0, a), min(y0, b), max(x1, c), max(y1, d)
    return x0, y0, x1, y1


# ------------------------------------------------------------------ kerf
def for_cutting(output: Output, kerf: float | dict | None = None, deadline=None,
                apart: bool = False) -> Output:
    """``output`` as a cutter reads it: every cut of a solid part offset by half the kerf
    (:func:`compensate`; ``apart``: each part offset whole, an edge it shares with another
    too, for parts a layout puts apart).  ``kerf``: mm, or a dict part name -> mm; ``None`` takes
    the program's ``kerf`` statements (``output.drawing.kerf``); 0 or no kerf anywhere returns
    ``output`` itself.  Raises :class:`LayoutError` (an :class:`~.part.OutputError`)
    naming the part where a feature is smaller than the offset, and an
    :class:`~.part.OutputError` with its ``budget`` when the compile's ``deadline`` (or None)
    passes before every part is offset."""
    if kerf is None and output.drawing is not None:
        kerf = output.drawing.kerf
    if not kerf:
        return output
    from ...base.limits import OutOfBudget, OutOfMemory, is_out_of_memory
    try:
        try:
            return compensate(output, kerf, deadline, apart)
        except (MemoryError, SystemError) as ex:
            if not is_out_of_memory(ex):
                raise
        where = output.drawing.part_of if output.drawing is not None else {}
        big = max(output.parts, key=lambda p: sum(len(lp.segments) for lp in p.loops),
                  default=None)
        raise OutOfMemory("the kerf offset", where.get(big.name) if big else None)
    except OutOfBudget as ex:
        raise OutputError(f"the kerf offset ran past the budget ({ex.what}); build less or "
                          "raise the budget (`--budget 2`)", ex) from None


def through_cut_note(output: Output, cut: Output) -> str:
    """The note the kerf offset gives when ``output`` has through-cuts (a ``cut``
    structure's curves) and ``cut`` (:func:`for_cutting` of it) is offset: they stay where
    they are drawn (a line has no side to offset: the beam runs on it, and the slit is one
    kerf wide); "" when there is nothing to say."""
    if cut is output:
        return ""
    n = len(output.cuts)
    if not n:
        return ""
    return (f"note: the kerf offset leaves the {n} through-cut{'s' if n != 1 else ''} where "
            f"{'they are' if n != 1 else 'it is'} drawn: a cut along a line has no side to "
            "offset (its slit is one kerf wide)")


def compensate(output: Output, kerf, deadline=None, apart: bool = False) -> Output:
    """``output`` with every cut of its solid parts offset by half the kerf: outer loops
    outward, holes inward, so the parts come out at their designed size.  An edge two pieces
    share (:func:`~..part.shared.shared_edges`: a cut from edge to edge freed one of them) is
    left on its line, not offset into the neighbour, and so cut once: each side of it loses
    half the kerf (:func:`~..part.shared.shared_note`); ``apart``: not so (each part is cut
    on its own, as a layout places them).  ``kerf``: mm for every part, or a dict part name ->
    mm (parts missing from it are not offset).  Engraving and through-cuts (:func:`through_cut_note`)
    are not offset.  Raises :class:`LayoutError` naming the part where a feature is smaller
    than the offset; ``deadline`` (a :class:`~aidl_lang.base.limits.Deadline`, or None) is looked
    at before each part (:class:`~aidl_lang.base.limits.OutOfBudget` naming the part's structure)."""
    parts = []
    where = output.drawing.part_of if output.drawing is not None else {}
    shared = {} if apart else shared_edges(output)
    for i, p in enumerate(output.parts):
        if deadline is not None:
            deadline.check("the kerf offset", where.get(p.name))
        k = kerf.get(p.name, 0.0) if isinstance(kerf, dict) else kerf
        if p.kind != "solid" or not k:
            parts.append(p)
            continue
        split = shared.get(i)
        try:
            # an Ellipse, a Spline, a font's letters: offset as their biarcs (within
            # biarc.BIARC_TOL of the curve; the offset of an ellipse or a cubic is neither)
            drawn = [as_arcs(lp, keep) for lp, keep in
                     ([(lp, frozenset()) for lp in p.loops] if split is None else
                      [(lp, keep) for lp, keep, _ in split])]
            loops = [offset_loop(lp, k / 2, keep) for lp, keep in drawn]
        except ValueError as e:         # OffsetError; a curve no arcs follow (biarc.py)
            raise KerfError(f"kerf {k:g} mm on part `{p.name}`: {e}"
                            f"{_spline_fix(output, e) if isinstance(e, OffsetError) else ''}",
                            p.name, getattr(e, "where", None), k) from None
        narrow = _narrow([lp for lp, _ in drawn], loops, k / 2) if split is None else None
        if narrow is not None:
            g, (x, y) = narrow
            raise KerfError(f"kerf {k:g} mm on part `{p.name}`: a slot or notch near "
                            f"({x:.4g}, {y:.4g}) is narrower than the cut: the offset path "
                            f"comes {k / 2 - g:.3g} mm into the material there", p.name,
                            (x, y), k)
        parts.append(PartOutline(p.name, p.kind, loops, p.thickness))
    out = Output(parts, list(output.engrave), output.title, output.drawing, output.page)
    out.stray = output.stray            # (cut by nothing: the preview draws them as they lie)
    return out


def _narrow(drawn: list, offset: list, d: float):
    """Where the ``offset`` loops (``drawn`` offset by ``d`` mm) come nearer the drawn loops
    than ``d`` (a slot or a notch narrower than twice ``d``, whose offset crosses itself:
    each segment's own offset is sound, the loop is not; issue 109, law 1): ``(distance,
    point)``, the nearest, or None.  Exact (:func:`~..part.measure.gaps.piece_gap`) over the
    pairs of pieces whose boxes lie within ``d``."""
    import numpy as np
    from ..part.measure.gaps import pieces, piece_gap
    from ..part.measure.nearby import box_pairs_between
    a = pieces([s for lp in offset for s in lp.segments])
    b = pieces([s for lp in drawn for s in lp.segments])
    if not a or not b:
        return None
    boxes = [np.array([_piece_box(q) for q in ps]) for ps in (a, b)]
    scale = max(1.0, float(np.abs(boxes[1]).max()))
    best = None
    for i, j in box_pairs_between(boxes[0], boxes[1], d / 2):
        g, pa, _ = piece_gap(a[int(i)], b[int(j)])
        if g < d - 1e-7 * scale and (best is None or g < best[0]):
            best = (g, pa)
    return best


def _piece_box(q: tuple) -> tuple:
    """The box of a piece of :func:`~..part.measure.gaps.pieces`: an arc's own (its ends and
    the quadrant points it passes), not its circle's (a kerf's biarcs of a near-straight
    spline have radii of metres: their circles' boxes paired every piece with every other)."""
    if q[0] == "L":
        (ax, ay), (bx, by) = q[1], q[2]
        return (min(ax, bx), min(ay, by), max(ax, bx), max(ay, by))
    (cx, cy), r, a0, sw = q[1], q[2], q[3], q[4]
    if sw >= 2 * math.pi - 1e-12:
        return (cx - r, cy - r, cx + r, cy + r)
    xs = [cx + r * math.cos(a0), cx + r * math.cos(a0 + sw)]
    ys = [cy + r * math.sin(a0), cy + r * math.sin(a0 + sw)]
    k = math.ceil(a0 / (math.pi / 2))
    while k * math.pi / 2 <= a0 + sw:
        xs.append(cx + r * math.cos(k * math.pi / 2))
        ys.append(cy + r * math.sin(k * math.pi / 2))
        k += 1
    return (min(xs), min(ys), max(xs), max(ys))


def _spline_fix(output: Output, e: OffsetError) -> str:
    """Where the spline a kerf cannot offset was written, and what to do."""
    if e.curve is None:
        return ""
    src = getattr(output.drawing, "spline_source", {}).get(e.curve) \
        if output.drawing is not None else None
    at = ""
    kind = "Ellipse" if src is not None and src.kind == "Ellipse" else "Spline"
    if src is not None and src.span is not None:
        sp = src.span
        from ...base.diagnostics import shown_path
        at = f" (the {kind} `{src.label}` at {shown_path(sp.file)}:{sp.line}:{sp.col})"
    redraw = "an Ellipse with rx and ry grown" if kind == "Ellipse" else \
        "the spline through points moved out"
    return (f"{at}; set the kerf of this part to 0 (`kerf 0 mm` in its structure) and let the "
            f"cutter's software compensate, or draw {redraw} by half the kerf")


# ------------------------------------------------------------------ nesting
def parse_length(text: str, zero: bool = False) -> float | None:
    """``3``, ``3mm``, ``0.25 in``, ``1 cm`` -> mm (a bare number is mm); None when it is not
    a positive length (or 0 with ``zero``) up to the model extent (1e6 mm)."""
    import re
    m = re.fullmatch(r"\s*([0-9]*\.?[0-9]+(?:e[-+]?[0-9]+)?)\s*(mm|cm|m|in)?\s*", text, re.I)
    if not m:
        return None
    v = float(m.group(1)) * {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4}[
        (m.group(2) or "mm").lower()]
    from ...base.limits import MAX_EXTENT
    return v if (0 < v or zero and v == 0) and v <= MAX_EXTENT else None


def parse_sheet(text: str) -> tuple[float, float] | None:
    """``600x400mm``, ``600 x 400``, ``24x12in`` -> (width, height) in mm; None if not that."""
    import re
    m = re.fullmatch(r"\s*([0-9.e+-]+)\s*[x×*]\s*([0-9.e+-]+)\s*(mm|cm|m|in)?\s*", text, re.I)
    if not m:
        return None
    unit = m.group(3) or "mm"
    w, h = parse_length(m.group(1) + unit), parse_length(m.group(2) + unit)
    return None if w is None or h is None else (w, h)


def parse_rotate(text: str):
    """``0,90`` -> (0.0, 90.0); ``any`` -> None (free rotation).  Raises ValueError."""
    t = text.strip().lower()
    if t == "any":
        return None
    out = []
    for w in t.split(","):
        a = float(w)
        if not math.isfinite(a):
            raise ValueError(w)
        out.append(a % 360.0)
    if not out:
        raise ValueError(text)
    return tuple(dict.fromkeys(out))


def _outer(p: PartOutline) -> list:
    """The part's outer loops as N x 2 arrays of points on the exact curves (mm)."""
    outer = [lp.points() for lp in p.loops if not lp.is_hole]
    return [q for q in outer if len(q) >= 3]


def _outline(p: PartOutline, grow: float, outer=None):
    """The part's outer outline grown by ``grow`` mm, as an N x 2 array of points that
    contains the exact curves (one outline: the hull when the part has several);
    ``outer``: :func:`_outer` of the part, when it is at hand."""
    import manifold3d as mf
    import numpy as np
    outer = [q.tolist() for q in (_outer(p) if outer is None else outer)]
    cs = mf.CrossSection(outer, mf.FillRule.NonZero)
    if len(outer) > 1:
        cs = cs.hull()
    cs = cs.offset(grow, mf.JoinType.Miter, 2.0)
    polys = [np.asarray(q, dtype=float) for q in cs.to_polygons()]
    best = max(polys, key=lambda q: abs(_shoelace(q)))
    if len(polys) > 1:              # several pieces: their hull holds them all
        best = np.asarray(mf.CrossSection(polys, mf.FillRule.NonZero).hull().to_polygons()[0])
    return best


# two parts whose outer outlines, moved to a common corner, agree to COPY_TOL mm are copies:
# the packer is given the first one's grown outline once, with a demand of how many there are
# (far below SAFETY, which the grown outline holds beyond the exact curves)
COPY_TOL = 1e-6


def _copy_key(p: PartOutline, outer: list):
    """(key, corner): parts of equal keys are copies of one outer outline, each moved by
    the difference of their ``corner`` (the lowest x and y of its outline, mm); the key
    holds the thickness too (a sheet holds one material)."""
    import numpy as np
    if not outer:
        return None, (0.0, 0.0)
    allpts = np.concatenate(outer)
    corner = allpts.min(axis=0)
    key = (p.thickness, tuple(len(q) for q in outer),
           np.round((allpts - corner) / COPY_TOL).astype(np.int64).tobytes())
    return key, (float(corner[0]), float(corner[1]))


def _shoelace(q) -> float:
    x, y = q[:, 0], q[:, 1]
    return 0.5 * float((x * (list(y[1:]) + [y[0]])).sum() - (y * (list(x[1:]) + [x[0]])).sum())


def _too_big(p, pts, W: float, H: float, gap: float, rotate) -> str:
    """Why part ``p`` (its outline ``pts`` grown by half the gap, centred) does not fit on a
    ``W`` x ``H`` mm sheet, and only the remedies that help (issue 86): the sheet size that
    would hold it as it is turned now, a smaller --gap only when the part fits without one,
    --rotate any only when some angle fits it on this sheet."""
    import numpy as np
    x0, y0, x1, y1 = part_box(p)
    w, h = x1 - x0, y1 - y0
    turn = "turned by any angle" if rotate is None else \
        "at " + ", ".join(f"{a:g}" for a in rotate) + " degrees"
    both = " in both orders" if (w > W or h > H) and (h > W or w > H) else ""
    sw, sh = (np.ptp(pts[:, 0]) + gap, np.ptp(pts[:, 1]) + gap)
    if rotate is not None and 90.0 in rotate:
        sw, sh = min(sw, sh), max(sw, sh)
        sw, sh = (sw, sh) if W <= H else (sh, sw)
    helps = [f"a sheet of {sw:.6g} x {sh:.6g} mm or larger (--sheet {math.ceil(sw):d}x"
             f"{math.ceil(sh):d}mm)"]
    if gap > 0 and _fits(pts, W + gap, H + gap, rotate):     # the part without its gap
        helps.append("a smaller --gap")
    if rotate is not None and _fits(pts, W - gap, H - gap, None):
        helps.append("--rotate any")
    return (f"part `{p.name}` ({w:.6g} x {h:.6g} mm) is larger than the {W:g} x {H:g} mm "
            f"sheet{both} {turn} with a {gap:g} mm gap: use " + ", or ".join(helps))


def _fits(pts, w: float, h: float, angles) -> bool:
    import numpy as np
    for deg in (angles if angles is not None else [float(a) for a in range(180)]):
        cs, sn = _rotation(deg)
        x = cs * pts[:, 0] - sn * pts[:, 1]
        y = sn * pts[:, 0] + cs * pts[:, 1]
        if np.ptp(x) <= w and np.ptp(y) <= h:
            return True
    return False


# spyrrow's first packing (no time to improve) costs about the same for every shape it is
# given, growing with its vertices (prepared for its collision checks; CPU on the shared
# 2-core test machine, 200 shapes: 1.6 ms at 4 vertices, 8.4 ms at 16, 39 ms at 64, 61 ms at
# 256), and less for each further copy of a shape (0.5 to 2 ms); linear in the parts (250 to
# 1,000).  Each sheet's nesting packs every part not yet on a sheet.  Low estimates (about a
# half to a sixth of those), so that only what surely cannot end in time is refused
NEST_SECONDS_PER_SHAPE = 5e-4
NEST_SECONDS_PER_VERTEX = 1e-4          # of each shape, up to NEST_VERTICES
NEST_VERTICES = 256
NEST_SECONDS_PER_COPY = 2e-4
# threads of spyrrow's exploration when it is given time to improve (``--nest-time S``): one a
# core, so S seconds of it are S x NEST_WORKERS CPU seconds of the compile's budget
NEST_WORKERS = os.cpu_count() or 1


def nest_cpu_seconds(seconds: float) -> float:
    """The CPU seconds (the budget's clock, :func:`aidl_lang.base.limits.now`) of ``seconds`` of
    spyrrow's improving: it runs :data:`NEST_WORKERS` threads for that long."""
    return seconds * NEST_WORKERS


def nest_seconds(vertices: list[int], parts: int, seconds: float = 0.0) -> float:
    """A low estimate of one nesting, in seconds: ``vertices``, the vertex count of each
    different outer outline given to the packer; ``parts``, the parts in all (the rest are
    copies); ``seconds``, the packer's time to improve, on top (:func:`nest_cpu_seconds`)."""
    return (nest_cpu_seconds(seconds) + NEST_SECONDS_PER_SHAPE * len(vertices)
            + NEST_SECONDS_PER_VERTEX * sum(min(v, NEST_VERTICES) for v in vertices)
            + NEST_SECONDS_PER_COPY * (parts - len(vertices)))


def _assembly(output: Output, solids: list):
    """The outermost written structure holding the first part (where a refused layout is
    reported)."""
    s = output.drawing.part_of.get(solids[0].name) if output.drawing is not None and solids \
        else None
    while s is not None and s.parent is not None and s.parent.span is not None:
        s = s.parent
    return s


def _nest(shapes: dict, height: float, angles, seconds: int, seed: int,
          demand: dict | None = None) -> list:
    """spyrrow's strip packing of ``shapes`` (id -> points; ``demand``: id -> how many
    copies, 1 when not given) in a strip ``height`` high: (id, rotation in degrees,
    translation) for each copy placed, in the packer's order."""
    import spyrrow
    items = [spyrrow.Item(k, [tuple(map(float, q)) for q in pts],
                          1 if demand is None else demand[k],
                          None if angles is None else list(angles))
             for k, pts in shapes.items()]
    inst = spyrrow.StripPackingInstance("aidl", float(height), items)
    if seconds > 0:
        cfg = spyrrow.StripPackingConfig(early_termination=True, total_computation_time=seconds,
                                         seed=seed, num_workers=NEST_WORKERS)
    else:
        cfg = spyrrow.StripPackingConfig(early_termination=True, total_computation_time=None,
                                         exploration_time=0, compression_time=0, seed=seed,
                                         num_workers=1)
    sol = inst.solve(cfg)
    return [(it.id, float(it.rotation), tuple(map(float, it.translation)))
            for it in sol.placed_items]


DEFAULT_SHEET = (600.0, 400.0)  # mm: the sheet `--layout sheet` fills when none is given
DEFAULT_GAP = 3.0               # mm: between parts and from the sheet's edges, by default


def fits(w: float, h: float, sheet=DEFAULT_SHEET, gap: float = DEFAULT_GAP) -> bool:
    """A part ``w`` x ``h`` mm (its box) fits on ``sheet`` with ``gap`` all round, as laid or
    turned 90 degrees (the layout's default turns)."""
    W, H = sheet[0] - 2 * gap, sheet[1] - 2 * gap
    return (w <= W and h <= H) or (h <= W and w <= H)


def lay_out(output: Output, sheet=DEFAULT_SHEET, gap: float = DEFAULT_GAP, rotate=(0.0, 90.0),
            seconds: int = 0, seed: int = 0) -> tuple[list[Output], int]:
    """Every solid part of ``output`` placed once on sheets ``sheet`` = (width, height) mm:
    :func:`place` of :func:`plan`.  Returns one Output per sheet (its page is the sheet: (0, 0)
    to (width, height)) and the number of engraving strokes left out (outside every part)."""
    return place(output, plan(output, sheet, gap, rotate, seconds, seed), sheet)


def place(output: Output, where: list[dict], sheet) -> tuple[list[Output], int]:
    """``output``'s parts moved as :func:`plan` says (``where``: one dict part name ->
    :class:`Motion` per sheet), with the engraving of each part; parts the plan does not name
    are left out.  Returns one Output per sheet and the number of engraving strokes left out."""
    W, H = float(sheet[0]), float(sheet[1])
    by_name = {p.name: p for p in output.parts}
    outs = []
    n = len(where)
    for j, moves in enumerate(where):
        parts = [m.part(by_name[name]) for name, m in moves.items()]
        strokes = [moves[st.part].stroke(st) for st in output.engrave if st.part in moves]
        title = output.title + (f" (sheet {j + 1} of {n})" if n > 1 else "")
        kinds = {p.thickness for p in parts}
        if len(kinds) == 1 and None not in kinds and \
                len({p.thickness for p in output.parts if p.kind == "solid"}) > 1:
            title += f", {kinds.pop():g} mm material"
        outs.append(Output(parts, strokes, title, None, (0.0, 0.0, W, H)))
    placed = {name for moves in where for name in moves}
    dropped = sum(1 for st in output.engrave if st.part not in placed)
    return outs, dropped


def plan(output: Output, sheet=DEFAULT_SHEET, gap: float = DEFAULT_GAP, rotate=(0.0, 90.0),
         seconds: int = 0, seed: int = 0, deadline=None) -> list[dict]:
    """Where every solid part of ``output`` goes: one dict part name -> :class:`Motion` per
    sheet (``sheet`` = (width, height) mm), the parts at least ``gap`` mm from each other and
    from the sheet's edges, turned only by the angles of ``rotate`` (degrees; None: any
    angle).  A sheet holds parts of one thickness (``thickness``/``kerf`` statements: one
    material per sheet), the thinnest first.  Copies (parts whose outer outlines agree, moved,
    to :data:`COPY_TOL`) are one shape for the packer with their number as its demand, so 1,000
    copies are prepared once.  ``seconds``: the packer's time to improve its first packing (0:
    the first packing, a fraction of a second).  Raises :class:`MissingDependency` without
    spyrrow and :class:`LayoutError` for a part larger than the sheet.  ``deadline`` (a
    :class:`~aidl_lang.base.limits.Deadline`, or None): spyrrow cannot be stopped once started, so
    each nesting is estimated first (:func:`nest_seconds` of its shapes and parts, plus
    ``seconds``) and refused when it would end past the deadline (an :class:`OutputError`
    whose ``budget`` names "the layout" and the assembly)."""
    try:
        import spyrrow  # noqa: F401
    except ImportError as e:
        raise MissingDependency(f"cutting layouts need spyrrow for true-shape nesting "
                                f"({e}): {INSTALL}") from None
    W, H = float(sheet[0]), float(sheet[1])
    inset = gap / 2
    Wu, Hu = W - 2 * inset, H - 2 * inset
    solids = [p for p in output.parts if p.kind == "solid"]
    if not solids:
        raise NothingToLayOut(_nothing_to_lay_out(output), _holds(output))
    # copies (one outer outline moved) are one shape for the packer, with their number
    shapes, about, members, first_of = {}, {}, {}, {}
    for i, p in enumerate(solids):
        outer = _outer(p)
        key, corner = _copy_key(p, outer)
        first = first_of.get(key) if key is not None else None
        if first is not None:
            j, c0 = first
            cx, cy = about[str(j)]
            about[str(i)] = (cx + corner[0] - c0[0], cy + corner[1] - c0[1])
            members[str(j)].append(i)
            continue
        pts = _outline(p, gap / 2 + SAFETY, outer)
        c = ((pts[:, 0].min() + pts[:, 0].max()) / 2, (pts[:, 1].min() + pts[:, 1].max()) / 2)
        pts = pts - c
        if not _fits(pts, Wu, Hu, rotate):
            raise LayoutError(_too_big(p, pts, W, H, gap, rotate))
        shapes[str(i)] = pts
        about[str(i)] = c
        members[str(i)] = [i]
        if key is not None:
            first_of[key] = (i, corner)
    sheets: list[list[tuple[int, Motion]]] = []
    # one material per sheet: the parts of each thickness are nested on sheets of their own
    # (thinnest first; parts of no stated thickness last)
    groups: dict = {}
    for k in shapes:
        groups.setdefault(solids[int(k)].thickness, {})[k] = members[k]

    def check(ids: list, parts: int) -> None:
        if deadline is None:
            return
        from ...base.limits import OutOfBudget, seconds_as_work
        try:
            deadline.check("the layout", _assembly(output, solids), seconds_as_work(
                nest_seconds([len(shapes[k]) for k in ids], parts, seconds)))
        except OutOfBudget as ex:
            ex.hint = ("each sheet's nesting packs every part not yet placed: lay out fewer "
                       "parts at a time (one assembly per run), or raise the budget with "
                       "`--budget 2`")
            raise OutputError(f"the nesting of {parts} parts would run past the budget "
                              f"({ex.what}); lay out fewer parts at a time or raise the budget "
                              "(`--budget 2`)", ex) from None
    for t in sorted(groups, key=lambda t: (t is None, t or 0.0)):
        sheets += _sheets(shapes, groups[t], about, Hu, Wu, inset, rotate, seconds, seed, check)
    return [{solids[i].name: m for i, m in placed} for placed in sheets]


class NothingToLayOut(LayoutError):
    """A layout of a design with no solid part; ``holds`` says what it has instead (the
    command line says it at the design: :func:`~aidl_lang.pipeline.report_nothing`)."""

    def __init__(self, message: str, holds: str):
        super().__init__(message)
        self.holds = holds


def _holds(output: Output) -> str:
    n = len(output.engrave)
    return f"only {n} engraved line{'s' if n != 1 else ''}" if n else "nothing to cut"


def _nothing_to_lay_out(output: Output) -> str:
    """The message for a layout of a design with no solid part (only engraving, or only
    drawings): a layout nests solid parts, so there is nothing to place and no sheet to write
    (issue 94: it wrote nothing and said "wrote ...")."""
    name = "this design" if output.title == "model" else f"`{output.title}`"
    return (f"nothing to lay out: {name} has no solid part to cut, {_holds(output)}; a "
            "cutting layout nests solid parts on sheets. Draw the design as it is (no sheet "
            "layout), or put the engraving on a `solid` plate")


def _sheets(shapes: dict, members: dict, about: dict, Hu: float, Wu: float, inset: float,
            rotate, seconds: int, seed: int, check=None) -> list[list[tuple[int, Motion]]]:
    """Sheets for the parts ``members`` (shape id -> the indices of the parts of that grown
    outline, ``shapes``: id -> points; ``about``: str(index) -> the point of the part that
    the outline's origin stands for): nest in the strip, keep what ends within the sheet's
    usable ``Wu`` x ``Hu``, nest the rest again on the next sheet.  ``check(ids, parts)`` is
    called before each nesting of ``parts`` parts of the shapes ``ids`` (it raises to refuse
    it)."""
    sheets: list[list[tuple[int, Motion]]] = []
    left = {k: list(v) for k, v in members.items()}
    while left:
        if check is not None:
            check(list(left), sum(len(v) for v in left.values()))
        placed = _nest({k: shapes[k] for k in left}, Hu, rotate, seconds, seed,
                       {k: len(v) for k, v in left.items()})
        here, taken = [], {k: 0 for k in left}
        for k, deg, (tx, ty) in placed:
            i = left[k][taken[k]]            # the copies of a shape in the order placed
            taken[k] += 1
            cs, sn = _rotation(deg)
            pts = shapes[k]
            xs = cs * pts[:, 0] - sn * pts[:, 1] + tx
            ys = sn * pts[:, 0] + cs * pts[:, 1] + ty
            if xs.max() <= Wu + 1e-3 and ys.max() <= Hu + 1e-3 and \
                    xs.min() >= -1e-3 and ys.min() >= -1e-3:
                here.append((i, k, Motion(deg, about[str(i)], (tx + inset, ty + inset))))
        if not here:                   # nothing ended inside: the largest part on its own
            k = max(left, key=lambda k: abs(_shoelace(shapes[k])))
            _, deg, (tx, ty) = _nest({k: shapes[k]}, Hu, rotate, seconds, seed)[0]
            i = left[k][0]
            here = [(i, k, Motion(deg, about[str(i)], (tx + inset, ty + inset)))]
        gone = {i for i, _, _ in here}
        for k in {k for _, k, _ in here}:
            left[k] = [i for i in left[k] if i not in gone]
            if not left[k]:
                del left[k]
        sheets.append(sorted(((i, m) for i, _, m in here), key=lambda t: t[0]))
    return sheets
