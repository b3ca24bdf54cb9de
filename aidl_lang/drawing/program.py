"""``aidl import``: a drawing turned into an editable AIDL program (docs/import.md).

:func:`to_program` writes one structure per DXF layer (or one for an SVG): outer outlines are
chains of the language's own ``Line``, ``Arc``, ``Spline`` and ``Bezier`` statements sharing their end
points (so they close into faces), outlines inside them become ``hole`` children (a circle is a
``Circle``), outlines inside holes become solids of their own, full ellipses are ``Ellipse``
and open paths are drawn in a ``drawing`` child (engraving).  A layer whose name starts with
``ENGRAVE`` (as ``aidl render`` writes them) becomes a ``drawing``.  Coordinates are written
with Python's shortest round-trip ``repr``, so the program renders back to the same curves
(1e-9 mm).  A spline piece that is the interpolating cubic spline through its span ends is
written as a ``Spline`` through them; any other (an SVG's or DXF's free cubics, a Spline
with ``corners=``) as a ``Bezier`` chain of its own control points.
"""
from __future__ import annotations

import math
import re

from ..geometry.curves import Arc, Circle, EllipticArc, Line, Loop, Spline
from .read import Drawing, Note, Outline, Path


SNAP = 1e-12    # mm: a coordinate within this of a shorter decimal is written as that decimal


def _num(v: float, snap: float = SNAP) -> str:
    """``v`` (mm or degrees) as the shortest decimal within ``snap`` of it, so that float
    noise from the reader (``43.99999999999999``, ``25.000000000000004``) is written as the
    number the drawing meant (``44``, ``25``); the error stays far inside the round trip's
    1e-9 mm.  Angles in radians pass ``snap=0`` (exact: 1e-12 rad is 1e-9 mm at 1 m)."""
    v = float(v)
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


def _ident(s: str, used: set) -> str:
    s = re.sub(r"[^A-Za-z0-9_]", "_", s).strip("_").lower() or "part"
    if s[0].isdigit():
        s = "l_" + s
    if s in _KEYWORDS:
        s += "_"
    base, i = s, 2
    while s in used:
        s = f"{base}_{i}"
        i += 1
    used.add(s)
    return s


_KEYWORDS = {"solid", "hole", "drawing", "assembly", "def", "for", "in", "if", "else", "import",
             "as", "param", "units", "true", "false", "self", "and", "or", "not", "thickness",
             "kerf", "assert", "model"}


def _spline_points(s: Spline, closed: bool):
    """The points a ``Spline(...)`` statement passes through to give piece ``s`` exactly, or
    None when the piece is not an interpolating spline of its span ends."""
    from ..geometry.spline import SplineError, interpolate
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
    from ..geometry.spline import CubicSpline
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


class _Writer:
    def __init__(self) -> None:
        self.lines: list[str] = []
        self.notes: list[Note] = []

    def emit(self, depth: int, text: str) -> None:
        self.lines.append("    " * depth + text)

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
                out.append(f"{prefix}0 = Bezier(points=[{', '.join(_pt(p) for p in ctrl)}], "
                           f"closed=true)")
            else:
                out.append(f"{prefix}0 = Spline(points=[{', '.join(_pt(p) for p in pts)}], "
                           f"closed=true)")
            for t in out:
                self.emit(depth, t)
            return True
        first_start = None          # expression of the chain's first point
        prev_end = None
        n = len(segs)
        for i, s in enumerate(segs):
            nm = f"{prefix}{i}"
            start = prev_end if prev_end is not None else _pt(s.start)
            last = closed and i == n - 1
            end = first_start if last else _pt(s.end)
            if isinstance(s, Line):
                out.append(f"{nm} = Line(start={start}, end={end})")
                cs, ce = f"{nm}.start", f"{nm}.end"
            elif isinstance(s, Arc):
                if abs(abs(s.sweep) - 2 * math.pi) < 1e-12:
                    return False
                if s.sweep > 0:
                    out.append(f"{nm} = Arc(center={_pt(s.center)}, start={start}, end={end})")
                    cs, ce = f"{nm}.start", f"{nm}.end"
                else:           # an Arc runs counter-clockwise: swap the ends
                    out.append(f"{nm} = Arc(center={_pt(s.center)}, start={end}, end={start})")
                    cs, ce = f"{nm}.end", f"{nm}.start"
            elif isinstance(s, EllipticArc):
                if s.whole:
                    return False
                # an Ellipse's arc runs counter-clockwise from start_angle: a clockwise
                # piece is written from its end (as an Arc)
                t0, sw = (s.start_param, s.sweep) if s.sweep > 0 else (s.end_param, -s.sweep)
                e = s.curve
                out.append(f"{nm} = Ellipse(center={_pt(e.center)}, rx={_num(e.rx)}, "
                           f"ry={_num(e.ry)}, rotation={_num(e.rotation, 0)} rad, "
                           f"start_angle={_num(t0, 0)} rad, end_angle={_num(t0 + sw, 0)} rad)")
                cs, ce = (f"{nm}.start", f"{nm}.end") if s.sweep > 0 else \
                    (f"{nm}.end", f"{nm}.start")
            elif isinstance(s, Spline):
                pts = _spline_points(s, False)
                if pts is None:     # not through its span ends: its own control points
                    ctrl = _bezier_points(s.spans)
                    inner = ", ".join([start] + [_pt(p) for p in ctrl[1:-1]] + [end])
                    out.append(f"{nm} = Bezier(points=[{inner}])")
                else:
                    inner = ", ".join([start] + [_pt(p) for p in pts[1:-1]] + [end])
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


def _inside(p, loop_pts) -> bool:
    import numpy as np
    x, y = p
    P = loop_pts
    X, Y = P[:, 0], P[:, 1]
    X2, Y2 = np.roll(X, -1), np.roll(Y, -1)
    cond = (Y > y) != (Y2 > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        xs = X + (y - Y) * (X2 - X) / (Y2 - Y)
    return bool(np.count_nonzero(cond & (x < xs)) % 2)


def _probe(segs) -> tuple[float, float]:
    s = segs[0]
    if isinstance(s, Circle):
        return (s.center[0] + s.radius, s.center[1])
    if isinstance(s, Arc):
        return s.at(s.start_angle + s.sweep / 2)
    if isinstance(s, Spline):
        return s.spans[0][3] if len(s.spans) > 1 else s.curve.at(0.5)
    return ((s.start[0] + s.end[0]) / 2, (s.start[1] + s.end[1]) / 2)


def _structure(w: _Writer, depth: int, kind: str, name: str, d: Drawing) -> None:
    loops = [("o", o.segments) for o in d.outlines] + [("c", [c]) for c in d.circles]
    import numpy as np
    polys = [np.asarray(Loop(list(segs)).points(), dtype=float) for _, segs in loops]
    # each loop's box first: a probe is tested only against the loops whose box holds it
    # (a MINSERT of 19 000 holes: seconds, where testing every pair took hours)
    boxes = np.array([[P[:, 0].min(), P[:, 1].min(), P[:, 0].max(), P[:, 1].max()]
                      if len(P) else [np.inf, np.inf, -np.inf, -np.inf] for P in polys]) \
        if polys else np.zeros((0, 4))
    depths = []
    for i, (_, segs) in enumerate(loops):
        p = _probe(segs)
        cand = np.nonzero((boxes[:, 0] <= p[0]) & (p[0] <= boxes[:, 2]) &
                          (boxes[:, 1] <= p[1]) & (p[1] <= boxes[:, 3]))[0]
        depths.append(sum(1 for j in cand if j != i and len(polys[j]) >= 3
                          and _inside(p, polys[j])))
    w.emit(depth, f"{kind} {name} {{")
    used: set = set()
    k = 0
    islands = []
    for (tag, segs), dep in zip(loops, depths):
        k += 1
        if kind == "drawing" or dep == 0:
            _loop(w, depth + 1, segs, f"{tag}{k}_", None)
        elif dep % 2 == 1:
            _loop(w, depth + 1, segs, "", _ident(f"hole{k}", used))
        else:
            islands.append((segs, k))
    for cx, cy, rx, ry, rot in d.ellipses:
        k += 1
        shape = (f"Ellipse(center={_pt((cx, cy))}, rx={_num(rx)}, ry={_num(ry)}, "
                 f"rotation={_num(math.degrees(rot))} deg)")
        inside = sum(1 for P in polys if len(P) >= 3 and _inside((cx, cy), P))
        if kind != "drawing" and inside % 2 == 1:      # an island in an outline: a hole
            w.emit(depth + 1, f"hole {_ident(f'hole{k}', used)} {{")
            w.emit(depth + 2, f"e = {shape}")
            w.emit(depth + 1, "}")
        else:
            w.emit(depth + 1, f"e{k} = {shape}")
    if d.texts:
        inner = depth + 1 if kind == "drawing" else depth + 2
        if kind != "drawing":
            w.emit(depth + 1, "drawing labels {")
        for i, (text, (x, y), h, rot, anchor, valign) in enumerate(d.texts):
            deg = round(math.degrees(rot), 9)      # the DXF's degrees (text is not exact)
            rot_txt = f", rotation={_num(deg)} deg" if deg else ""
            w.emit(inner, f"t{i + 1} = Text({_string(text)}, position={_pt((x, y))}, "
                          f"size={_num(h)}, anchor=\"{anchor}\", valign=\"{valign}\"{rot_txt})")
        if kind != "drawing":
            w.emit(depth + 1, "}")
    if d.paths:
        inner = depth + 1 if kind == "drawing" else depth + 2
        if kind != "drawing":
            w.emit(depth + 1, "drawing paths {")
        for i, p in enumerate(d.paths):
            closed = math.dist(p.start, p.end) <= 1e-6 and p.crossing is not None
            if not w.chain(inner, p.segments, closed, f"p{i + 1}_"):
                w.notes.append(Note("W0130", f"a path of `{name}` holds a piece no statement "
                                             f"writes (a whole circle or ellipse inside a "
                                             f"chain): left out"))
        if kind != "drawing":
            w.emit(depth + 1, "}")
    w.emit(depth, "}")
    for segs, k in islands:
        w.emit(depth, f"solid {name}_island{k} {{")
        _loop(w, depth + 1, segs, f"o{k}_", None)
        w.emit(depth, "}")


def _loop(w: _Writer, depth: int, segs: list, prefix: str, hole: str | None) -> None:
    if hole is not None:
        w.emit(depth, f"hole {hole} {{")
        depth += 1
        prefix = "c" if len(segs) == 1 and isinstance(segs[0], Circle) else "e"
    if len(segs) == 1 and isinstance(segs[0], Circle):
        c = segs[0]
        w.emit(depth, f"{prefix.rstrip('_') or 'c'} = Circle(center={_pt(c.center)}, "
                      f"radius={_num(c.radius)})")
    elif not w.chain(depth, segs, True, prefix):
        w.notes.append(Note("W0130", "an outline holds a piece no statement writes (a "
                                     "whole circle or ellipse inside a chain): left out"))
    if hole is not None:
        w.emit(depth - 1, "}")


def to_program(layers: list[tuple[str, Drawing]], source: str) -> tuple[str, list[Note]]:
    """The AIDL text of a drawing read layer by layer (``(layer name, Drawing)``, in order),
    and the notes of what was left out.  ``source``: the drawing's file name, for the
    header comment."""
    w = _Writer()
    w.emit(0, f"# imported from {source} by `aidl import`: edit freely")
    w.emit(0, "units mm")
    used: set = set()
    multi = len(layers) > 1
    if multi:
        w.emit(0, "assembly drawing_import {")
    for layer, d in layers:
        kind = "drawing" if layer.upper().startswith("ENGRAVE") or (
            d.texts and not (d.outlines or d.circles or d.ellipses or d.paths)) else "solid"
        name = _ident(layer or "part", used)
        _structure(w, 1 if multi else 0, kind, name, d)
    if multi:
        w.emit(0, "}")
    return "\n".join(w.lines) + "\n", w.notes


def layer_names(data: bytes, name: str) -> list[str]:
    """The DXF layers that hold entities, in the order they first appear (an entity in a
    block on layer ``0`` is on its INSERT's layer, as CAD programs draw it); ``[""]`` for
    SVG."""
    if not name.lower().endswith(".dxf"):
        return [""]
    from .read import DrawingError, MAX_BLOCK_DEPTH, _EzdxfLog, _open_dxf
    try:
        with _EzdxfLog():            # its log lines: a note of the read, not the terminal
            doc = _open_dxf(data, name)
    except DrawingError:
        return [""]
    seen: list[str] = []
    done: set = set()

    def walk(entities, inherited, depth) -> None:
        for e in entities:
            ly = e.dxf.get("layer", "0")
            if ly == "0" and inherited is not None:
                ly = inherited
            if e.dxftype() == "INSERT":
                key = (e.dxf.name, ly)
                blk = doc.blocks.get(e.dxf.name)
                if blk is not None and key not in done and depth < MAX_BLOCK_DEPTH:
                    done.add(key)
                    walk(blk, ly, depth + 1)
                continue
            if ly not in seen:
                seen.append(ly)
    walk(doc.modelspace(), None, 0)
    return seen or [""]


def import_drawing(data: bytes, name: str, unit: str | None = None, layer=None, color=None,
                   ident=None) -> tuple[str, list[Note]]:
    """``aidl import``: the program of the drawing ``data`` (``name``: its file name) and the
    notes (skipped entities, left-out loops).  Raises :class:`~.read.DrawingError`."""
    from .read import DrawingError, read_drawing
    layers = [layer] if layer is not None else layer_names(data, name)
    read: list[tuple[str, Drawing]] = []
    notes: list[Note] = []
    for ly in layers:
        try:
            d = read_drawing(data, name, layer=ly or None, color=color, ident=ident, unit=unit,
                             keep_text=True)
        except DrawingError as ex:
            if ex.code == "E0132" and layer is None:
                continue        # a layer of only skipped entities (none at all: below)
            raise
        # text is written as Text engravings here (Drawing2D skips it with this note)
        notes += [n for n in d.notes if not (d.texts and "text is not imported" in n.message)
                  and all(n.message != m.message for m in notes)]     # once, not per layer
        read.append((ly if isinstance(ly, str) else "_".join(ly), d))
    if not read:        # every layer empty: the whole drawing's E0132, as Drawing2D gives it
        read_drawing(data, name, color=color, ident=ident, unit=unit, keep_text=True)
    text, more = to_program(read, name.replace("\\", "/").rsplit("/", 1)[-1])
    return text, notes + more
