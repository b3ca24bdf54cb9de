"""Law 2 (issue 109): every output is the same part.

One program is compiled once (the public API, ``aidl_lang.compile``) and written in every
format ``aidl render`` writes: SVG (the laser style), DXF, PDF and G-code (the built-in laser
profile) with no kerf, STL, 3MF and GLB (STEP too when the ``step`` extra's OCP is importable;
skipped otherwise).  Each file is read back by an independent reader (svgelements, ezdxf,
pdfplumber, gcodeparser, trimesh) and compared with the exact output model every writer reads
(``Result.output``):

* the 2D files hold each closed loop of every part once (as many pieces and holes), each loop's
  box within :data:`TOL_2D` of the exact loop's (PDF: within :data:`TOL_PDF` of the others,
  relative to the drawing's corner: its arcs are Béziers within 1e-3 mm, docs/outputs.md);
* each 3D file holds one watertight body per piece, of volume ``area x thickness`` less what
  the countersinks and counterbores remove, within the chords' bound (:func:`volume_tolerance`);
* a format that refuses the design (an ``OutputError``) is refused by every other: a design
  that leaves nothing to make in one format is an error in all (E0503), nothing written.  Two
  documented exceptions: a machine file refuses parts drawn over each other (E0501) where a
  picture is written as drawn, and a missing optional library (``MissingDependency``) skips
  its format.
"""
from __future__ import annotations

import io
import math

try:                                    # helper corpus's module, once merged
    from benchmarks.laws.common import NotApplicable
except ImportError:                     # pragma: no cover - the same one-line class
    class NotApplicable(Exception):
        pass

NAME = "Every output is the same part: SVG, DXF, PDF, G-code, STL, 3MF, GLB (and STEP) agree"
TOLERANCE = ("2D: each loop's box within 1e-6 mm (PDF 1e-3 mm: Béziers); 3D: volume within "
             "CHORD_TOL (0.005 mm) x (curves' length x thickness + the heads' sides), plus "
             "float32's rounding in STL and GLB; one watertight "
             "body per piece; a refusal in one format is a refusal in all (E0501 and a missing "
             "extra excepted)")
TOL_2D = 1e-6          # mm: SVG, DXF, G-code write exact lines and arcs (10 decimals)
TOL_PDF = 2e-3         # mm: a PDF's arcs are cubic Béziers within 1e-3 mm (docs/outputs.md),
#                        its boxes compared from the drawing's corner (itself within 1e-3 mm);
#                        a G-code's splines and ellipses are arcs within 1e-3 mm
FORMATS_2D = ("svg", "dxf", "pdf", "gcode")
FORMATS_3D = ("stl", "3mf", "glb")
MACHINE = ("gcode",)   # refuses parts drawn over each other (E0501): a documented exception


def applies(entry) -> bool:
    """Every program (one with no solid part is not applicable once compiled)."""
    return True


def check(entry) -> list[str]:
    """The violations of law 2 for ``entry`` (a corpus entry: ``source``, ``path``,
    ``overrides``); raises :class:`NotApplicable` for a program that does not compile."""
    return compare(compiled(entry))


def compiled(entry):
    """``entry`` compiled by the public API (:class:`aidl_lang.api.Result`), or
    :class:`NotApplicable` naming the error codes when it does not compile (never another
    exception: the runner counts it as skipped)."""
    import aidl_lang
    try:
        res = aidl_lang.compile(source=entry.source, path=entry.path,
                                overrides=dict(entry.overrides or {}))
        ok = res.ok
    except Exception as ex:                 # never raise past the runner
        raise NotApplicable(f"does not compile: {type(ex).__name__}") from None
    if not ok:
        raise NotApplicable("does not compile: " + ", ".join(
            sorted({d.code for d in res.diagnostics if d.severity == "error"})))
    return res


def compare(res) -> list[str]:
    """The violations of law 2 for a compiled ``res`` (:class:`aidl_lang.api.Result`)."""
    from aidl_lang.output import MissingDependency, OutputError
    from aidl_lang.output.writers import StackedParts
    try:
        output = res.output
    except OutputError as ex:
        raise NotApplicable(f"no output model: {ex}") from None
    want = expected(output)
    if not want["loops"]:
        raise NotApplicable("no part outline")
    wrote, refused, out = {}, {}, []
    formats = FORMATS_2D + FORMATS_3D + (("step",) if _has_step() else ())
    for fmt in formats:
        try:
            wrote[fmt] = res.encode(fmt, kerf=0, **({"style": "laser"} if fmt == "svg" else {}))
        except MissingDependency:
            continue
        except OutputError as ex:
            refused[fmt] = ex
    if refused:
        real = {f: e for f, e in refused.items()
                if not (f in MACHINE and isinstance(e, StackedParts))}
        if real and wrote.keys() - MACHINE:
            f, e = next(iter(real.items()))
            out.append(f"{f} refused ({e}) while {', '.join(sorted(wrote))} were written")
    # parts drawn over each other (an assembly at the origin: the machine's E0501): one part's
    # loops lie inside another's, so holes by nesting and bodies by touching are not counted
    stacked = any(isinstance(e, StackedParts) for e in refused.values())
    want["stacked"] = stacked
    readers = {"svg": svg_loops, "dxf": dxf_loops, "gcode": gcode_loops, "pdf": pdf_loops}
    for fmt, read in readers.items():
        if fmt in wrote:
            try:
                got = read(wrote[fmt])
            except Exception as ex:         # an unreadable file is a violation, not a crash
                out.append(f"{fmt}: unreadable ({type(ex).__name__}: {ex})")
                continue
            tol = TOL_PDF if fmt == "pdf" or (fmt == "gcode" and want["curved"]) else TOL_2D
            out += same_loops(fmt, want, got, tol, nested=not stacked)
    if want["heads"] and "svg" in wrote:
        try:
            out += same_heads(res, wrote["svg"])
        except Exception as ex:
            out.append(f"router gcode: unreadable ({type(ex).__name__}: {ex})")
    for fmt in FORMATS_3D + ("step",):
        if fmt in wrote:
            try:
                out += same_solid(fmt, want, wrote[fmt])
            except Exception as ex:
                out.append(f"{fmt}: unreadable ({type(ex).__name__}: {ex})")
    return out


# ------------------------------------------------------------------ what the program drew
def expected(output) -> dict:
    """The exact output model's loops (``(box, is_hole)``), pieces, and per solid part its
    area, perimeter, thickness and heads (:func:`~aidl_lang.output.part.part.sink_heads`)."""
    from aidl_lang.output.part.part import Line, sink_heads
    loops, solids = [], []
    heads = sink_heads(output)
    for p in output.parts:
        for lp in p.loops:
            loops.append((_loop_box(lp), bool(lp.is_hole)))
        if p.kind == "solid" and p.loops:
            solids.append({"name": p.name, "area": float(p.area),
                           "curved": float(sum(seg.length for lp in p.loops
                                               for seg in lp.segments
                                               if not isinstance(seg, Line))),
                           "t": float(p.thickness or 3.0),
                           "pieces": sum(1 for lp in p.loops if not lp.is_hole),
                           "shape": p.shape,
                           "perimeter": float(sum(lp.perimeter for lp in p.loops)),
                           "size": max(abs(v) for lp in p.loops for v in _loop_box(lp)),
                           "heads": [h for c, h in heads if h.part == p.name]})
    from aidl_lang.output.part.part import Arc, Circle, Line
    curved = any(not isinstance(seg, (Arc, Circle, Line))
                 for p in output.parts for lp in p.loops for seg in lp.segments)
    return {"loops": loops, "solids": solids, "curved": curved, "heads": heads,
            "pieces": sum(s["pieces"] for s in solids)}


def _loop_box(lp) -> tuple:
    bs = [seg.box() for seg in lp.segments]
    return (min(b[0] for b in bs), min(b[1] for b in bs), max(b[2] for b in bs),
            max(b[3] for b in bs))


def same_loops(fmt: str, want: dict, got: list, tol: float, nested: bool = True) -> list[str]:
    """``got`` (the file's closed loops: ``(box, points)``) against ``want``'s loops: as
    many, as many holes (by nesting), each box within ``tol`` (PDF: relative to the drawing's
    lower-left corner, its page frame being the file's own)."""
    out = []
    boxes = [b for b, _ in want["loops"]]
    if len(got) != len(boxes):
        return [f"{fmt}: {len(got)} closed loops, the part has {len(boxes)}"]
    gb = [b for b, _ in got]
    if fmt == "pdf":
        boxes, gb = _relative(boxes), _relative(gb)
    worst, used = 0.0, set()
    for b in sorted(boxes):
        j, d = min(((j, max(abs(u - v) for u, v in zip(b, g))) for j, g in enumerate(gb)
                    if j not in used), key=lambda t: t[1])
        used.add(j)
        worst = max(worst, d)
    if worst > tol:
        out.append(f"{fmt}: a loop's box is {worst:.3g} mm from the exact outline's "
                   f"(tolerance {tol:g} mm)")
    if not nested:
        return out
    holes = sum(1 for _, h in want["loops"] if h)
    got_holes = _holes(got)
    if got_holes != holes:
        out.append(f"{fmt}: {got_holes} holes by nesting, the part has {holes}")
    return out


def _relative(boxes: list) -> list:
    x0 = min(b[0] for b in boxes)
    y0 = min(b[1] for b in boxes)
    return [(b[0] - x0, b[1] - y0, b[2] - x0, b[3] - y0) for b in boxes]


def _holes(loops: list) -> int:
    """How many of ``loops`` (``(box, points)``) lie inside an odd number of others."""
    from shapely.geometry import Point, Polygon
    polys = [Polygon(p).buffer(0) for _, p in loops]
    n = 0
    for i, (_, p) in enumerate(loops):
        q = Point(p[len(p) // 3])
        inside = sum(1 for j, P in enumerate(polys) if j != i and P.area > loops_area(p) and
                     P.contains(q))
        n += inside % 2
    return n


def loops_area(p) -> float:
    from shapely.geometry import Polygon
    return Polygon(p).area


# ------------------------------------------------------------------ the readers
def _arc_box(cx, cy, r, a0, sweep) -> tuple:
    """The exact box of the arc about (cx, cy) of radius r from angle a0 (rad) turning
    ``sweep`` (rad, counter-clockwise when positive)."""
    if sweep < 0:
        a0, sweep = a0 + sweep, -sweep
    pts = [a0, a0 + sweep]
    k = math.ceil(a0 / (math.pi / 2) - 1e-12)
    while k * math.pi / 2 <= a0 + sweep + 1e-12:
        pts.append(k * math.pi / 2)
        k += 1
    xs = [cx + r * math.cos(a) for a in pts]
    ys = [cy + r * math.sin(a) for a in pts]
    return min(xs), min(ys), max(xs), max(ys)


def _merge(boxes) -> tuple:
    boxes = list(boxes)
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes),
            max(b[3] for b in boxes))


def svg_loops(data: bytes) -> list:
    """The closed subpaths of the SVG's ``cut`` group (svgelements, in the file's user units,
    mm, y up):
    ``[(box, points)]``, the box svgelements' own (exact for lines, arcs and Béziers)."""
    import numpy as np
    import svgelements as se
    svg = se.SVG.parse(io.BytesIO(data), reify=False)
    page = ~se.Matrix(svg.viewbox_transform)    # the file's user units (mm) back
    cut = next(e for e in svg.elements() if isinstance(e, se.Group) and e.id == "cut")
    out = []
    for e in cut.select():
        if not isinstance(e, se.Shape) or isinstance(e, se.Group):
            continue
        path = se.Path(e)
        path.transform = e.transform * page
        path.reify()
        for sub in path.as_subpaths():
            sub = se.Path(sub)
            segs = [s for s in sub if not isinstance(s, se.Move)]
            if not segs:
                continue
            closed = any(isinstance(s, se.Close) for s in segs) or \
                abs(segs[0].start - segs[-1].end) < 1e-9
            if not closed:
                continue
            x0, y0, x1, y1 = sub.bbox()
            pts = np.asarray(sub.npoint(np.linspace(0, 1, 256)), dtype=float) * (1, -1)
            out.append(((x0, -y1, x1, -y0), pts))
    return out


def dxf_loops(data: bytes) -> list:
    """The closed loops of the DXF's cut layers (``CUT``, ``CUT-PATH``; ezdxf): a CIRCLE, a
    closed LWPOLYLINE (bulges as exact arcs), or LINEs/ARCs/others chained end to end."""
    import ezdxf
    import numpy as np
    from ezdxf.math import bulge_to_arc
    doc = ezdxf.read(io.StringIO(data.decode("utf-8", "replace")))
    out, open_ = [], []
    for e in doc.modelspace():
        if not e.dxf.layer.upper().startswith("CUT"):
            continue
        t = e.dxftype()
        if t == "CIRCLE":
            (cx, cy, _), r = e.dxf.center, e.dxf.radius
            a = np.linspace(0, 2 * math.pi, 129)
            out.append(((cx - r, cy - r, cx + r, cy + r),
                        np.c_[cx + r * np.cos(a), cy + r * np.sin(a)]))
        elif t == "LWPOLYLINE":
            pts = [tuple(p) for p in e.get_points("xyb")]
            n = len(pts) if e.closed else len(pts) - 1
            boxes, sample = [], []
            for i in range(n):
                (x, y, b), (u, v, _) = pts[i], pts[(i + 1) % len(pts)]
                if abs(b) < 1e-15:
                    boxes.append((min(x, u), min(y, v), max(x, u), max(y, v)))
                    sample.append((x, y))
                else:
                    c, _, _, r = bulge_to_arc((x, y), (u, v), b)
                    a0 = math.atan2(y - c.y, x - c.x)
                    sweep = 4 * math.atan(b)        # the bulge's sign: the turn's direction
                    boxes.append(_arc_box(c.x, c.y, r, a0, sweep))
                    sample += [(c.x + r * math.cos(a), c.y + r * math.sin(a))
                               for a in a0 + sweep * np.linspace(0, 1, 17)[:-1]]
            if e.closed:
                out.append((_merge(boxes), np.array(sample)))
            else:
                open_.append((pts[0][:2], pts[-1][:2], _merge(boxes), sample + [pts[-1][:2]]))
        else:
            if hasattr(e, "flattening"):    # ELLIPSE, SPLINE: their own exact points
                fl = np.array([(v.x, v.y) for v in e.flattening(1e-7)])
            else:                           # (a path's ellipses are Bézier approximations)
                from ezdxf import path as ezpath
                fl = np.array([(v.x, v.y) for v in ezpath.make_path(e).flattening(1e-7)])
            if len(fl) < 2:
                continue
            if t == "ARC":
                (cx, cy, _), r = e.dxf.center, e.dxf.radius
                a0 = math.radians(e.dxf.start_angle)
                sweep = math.radians((e.dxf.end_angle - e.dxf.start_angle) % 360 or 360)
                box = _arc_box(cx, cy, r, a0, sweep)
            else:
                box = (*fl.min(0), *fl.max(0))
            if np.hypot(*(fl[0] - fl[-1])) < 1e-9 and len(fl) > 2:
                out.append((box, fl))
            else:
                open_.append((tuple(fl[0]), tuple(fl[-1]), box, [tuple(q) for q in fl]))
    return out + _chain(open_)


def _chain(pieces: list, tol: float = 1e-6) -> list:
    """Open pieces ``(start, end, box, points)`` joined end to start (either way) into closed
    loops; what does not close (a through-cut) is left out."""
    import numpy as np
    todo = list(pieces)
    out = []
    while todo:
        s, e, box, pts = todo.pop(0)
        boxes, chain = [box], list(pts)
        start, end = s, e
        grew = True
        while grew and math.dist(start, end) > tol:
            grew = False
            for i, (a, b, bx, ps) in enumerate(todo):
                if math.dist(a, end) <= tol:
                    chain += list(ps)[1:]
                    end = b
                elif math.dist(b, end) <= tol:
                    chain += list(ps)[::-1][1:]
                    end = a
                else:
                    continue
                boxes.append(bx)
                todo.pop(i)
                grew = True
                break
        if math.dist(start, end) <= tol and len(chain) > 2:
            out.append((_merge(boxes), np.array(chain)))
    return out


def gcode_loops(data: bytes) -> list:
    """The closed cut paths of a laser G-code (gcodeparser), each once however many passes cut
    it: a run of moves with the beam on at the job's cutting power (the most it uses), lines
    and G2/G3 arcs (I/J from the start) with their exact boxes."""
    import numpy as np
    from .law_machine import replay         # gcodeparser, as docs/toolpath_picture.py reads
    runs, run, at = [], [], None
    for g, (x, y), (nx, ny), centre, _, s in replay(data.decode(), "laser"):
        if s <= 0 or (x, y) != at:          # the beam off, or a rapid move between
            if run:
                runs.append(run)
            run = []
        at = (nx, ny)
        if s <= 0 or (nx, ny) == (x, y):
            continue
        if g == 1:
            run.append((s, (min(x, nx), min(y, ny), max(x, nx), max(y, ny)),
                        [(x, y), (nx, ny)]))
        else:
            cx, cy = centre
            r = math.hypot(x - cx, y - cy)
            a0, a1 = math.atan2(y - cy, x - cx), math.atan2(ny - cy, nx - cx)
            sweep = (a1 - a0) % (2 * math.pi) or 2 * math.pi
            if g == 2:
                sweep -= 2 * math.pi
            aa = np.linspace(a0, a0 + sweep, 17)
            run.append((s, _arc_box(cx, cy, r, a0, sweep),
                        [(cx + r * math.cos(a), cy + r * math.sin(a)) for a in aa]))
        if math.dist(run[0][2][0], (nx, ny)) <= 1e-9:
            runs.append(run)                # closed: a next pass starts a loop of its own
            run = []
    if run:
        runs.append(run)
    top = max((m[0] for r in runs for m in r), default=0.0)
    out, seen = [], set()
    for r in runs:
        if not r or min(m[0] for m in r) < 0.9 * top:
            continue                        # engraving or scoring (less power)
        pts = [p for m in r for p in m[2]]
        if math.dist(pts[0], pts[-1]) > 1e-6 or abs(_shoelace(pts)) < 1e-9:
            continue                        # a through-cut: open, or there and back
        box = _merge(m[1] for m in r)
        key = tuple(round(v, 6) for v in box) + (len(r),)
        if key in seen:
            continue                        # another pass of the same loop
        seen.add(key)
        out.append((box, np.array(pts)))
    return out


def _shoelace(pts) -> float:
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]))


def pdf_loops(data: bytes) -> list:
    """The closed black paths of the PDF (pdfplumber's paths: lines and cubic Béziers, each
    Bézier's exact box; pt as mm, y up) but the scale bar's and the footer's, which are open
    lines."""
    import numpy as np
    import pdfplumber
    k = 25.4 / 72
    out = []
    with pdfplumber.open(io.BytesIO(data)) as pdf:
        page = pdf.pages[0]
        h = float(page.height)
        for c in list(page.curves) + list(page.rects) + list(page.lines):
            if tuple(c.get("stroking_color") or ()) not in ((0.0, 0.0, 0.0), (0,), (0.0,)):
                continue
            path = c.get("path") or ()
            if not path or path[-1][0] != "h":
                continue                    # open: the scale bar, a through-cut
            boxes, pts, at = [], [], None
            for op, *q in path:
                q = [(float(x) * k, (h - float(y)) * k) for x, y in q]
                if op == "m":
                    at = q[0]
                    pts.append(at)
                elif op == "l":
                    boxes.append(_merge([(*at, *at), (*q[0], *q[0])]))
                    at = q[0]
                    pts.append(at)
                elif op == "c":
                    boxes.append(_bezier_box(at, *q))
                    pts += [_bezier(at, *q, t) for t in np.linspace(0, 1, 9)[1:]]
                    at = q[2]
            if boxes:
                out.append((_merge(boxes), np.array(pts)))
    return out


def _bezier(p0, p1, p2, p3, t: float) -> tuple:
    u = 1 - t
    return tuple(u ** 3 * a + 3 * u * u * t * b + 3 * u * t * t * c + t ** 3 * d
                 for a, b, c, d in zip(p0, p1, p2, p3))


def _bezier_box(p0, p1, p2, p3) -> tuple:
    """The exact box of a cubic Bézier: its ends and the roots of its derivative."""
    ts = [0.0, 1.0]
    for i in range(2):
        a = -p0[i] + 3 * p1[i] - 3 * p2[i] + p3[i]
        b = 2 * (p0[i] - 2 * p1[i] + p2[i])
        c = p1[i] - p0[i]
        if abs(a) < 1e-15:
            if abs(b) > 1e-15:
                ts.append(-c / b)
        else:
            disc = b * b - 4 * a * c
            if disc >= 0:
                ts += [(-b + sgn * math.sqrt(disc)) / (2 * a) for sgn in (1, -1)]
    pts = [_bezier(p0, p1, p2, p3, t) for t in ts if 0 <= t <= 1]
    return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts),
            max(p[1] for p in pts))


def svg_heads(data: bytes) -> dict:
    """``{(x, y): diameter}`` of the circles on the SVG's ``countersink`` and ``counterbore``
    groups (svgelements; the file's numbers, mm, y up), centres to 1e-6 mm."""
    import svgelements as se
    svg = se.SVG.parse(io.BytesIO(data), reify=False)
    out = {}
    for g in svg.elements():
        if isinstance(g, se.Group) and g.id in ("countersink", "counterbore"):
            for c in g.select():
                if isinstance(c, se.Circle):
                    x, y = float(c.values["cx"]), -float(c.values["cy"])
                    out[(round(x, 6) + 0.0, round(y, 6) + 0.0)] = 2 * float(c.values["r"])
    return out


def router_heads(text: str, v_bit: float, pocket_r: float) -> dict:
    """``{(x, y): the top diameter the router leaves}`` from a router's G-code (gcodeparser)
    after its tool change (``M0``): at each place the tool goes down, the deepest ``z`` and
    the widest circle its arcs run round that place; a V-bit's (``v_bit`` deg) cone is
    ``2 (rho + |z| tan(v / 2))`` wide at the top, a pocket's ``2 (rho + pocket_r)``.  Which
    one: the V-bit's places are those plunged once with no arc or one circle at full depth,
    told by the tool-change comment before them."""
    import gcodeparser
    x = y = z = None
    tool, at = None, None
    places: dict = {}
    for raw in text.splitlines():
        if raw.startswith("; tool change:"):
            tool = "v" if "V-bit" in raw else "mill"
            continue
        for line in gcodeparser.parse_gcode_lines(raw):
            letter, code = line.command
            prm = line.params
            if letter != "G" or code not in (0, 1, 2, 3) or tool is None:
                continue
            nx = float(prm["X"]) if "X" in prm else x
            ny = float(prm["Y"]) if "Y" in prm else y
            nz = float(prm["Z"]) if "Z" in prm else z
            if code == 1 and nz is not None and nz < 0 and (z is None or z >= 0):
                at = (round(nx, 6) + 0.0, round(ny, 6) + 0.0)
                places[at] = [tool, nz, 0.0]
            elif at is not None and nz is not None and nz < 0:
                places[at][1] = min(places[at][1], nz)
                if code in (2, 3):
                    cx, cy = x + float(prm.get("I", 0.0)), y + float(prm.get("J", 0.0))
                    places[at][2] = max(places[at][2], math.hypot(x - cx, y - cy))
            if nz is not None and nz >= 0:
                at = None
            x, y, z = nx, ny, nz
    k = math.tan(math.radians(v_bit) / 2)
    return {p: 2 * (rho + abs(zz) * k) if t == "v" else 2 * (rho + pocket_r)
            for p, (t, zz, rho) in places.items()}


def same_heads(res, svg: bytes) -> list[str]:
    """The router's G-code leaves each head as wide at the top as the SVG's circle of it
    (the meshes' cone and recess have that top too: :func:`sink_volume`), within
    :data:`TOL_2D`; as many places as circles."""
    from aidl_lang.output.fabrication.machine import default
    m = default("router")
    try:
        text = res.encode("gcode", kerf=0, machine="router").decode()
    except Exception:                       # the built-in router's bit cannot cut this part
        return []                           # (its tool too large): no heads to compare
    drawn = svg_heads(svg)
    made = router_heads(text, m.v_bit_angle, (m.pocket_tool or m.tool_diameter) / 2)
    out = []
    if sorted(drawn) != sorted(made):
        return [f"router gcode: sinks at {len(made)} places, the SVG draws {len(drawn)} heads"]
    worst = max(abs(drawn[p] - made[p]) for p in drawn)
    if worst > TOL_2D:
        p = max(drawn, key=lambda q: abs(drawn[q] - made[q]))
        out.append(f"router gcode: the head at ({p[0]:g}, {p[1]:g}) is {made[p]:.6g} mm wide "
                   f"at the top, the SVG draws {drawn[p]:.6g} mm")
    return out


# ------------------------------------------------------------------ 3D
def sink_volume(sk) -> float:
    """What head ``sk`` removes beside its hole (mm³): a countersink's frustum from the hole's
    diameter up to the head's, less the hole's cylinder; a counterbore's ring."""
    R, r, h = sk.diameter / 2, sk.hole_d / 2, sk.cone_depth()
    if sk.kind == "countersink":
        return math.pi * h / 3 * (R * R + R * r + r * r) - math.pi * r * r * h
    return math.pi * (R * R - r * r) * h


FLOAT32 = 2.0 ** -23    # STL and GLB store float32 coordinates: each within this x its size


def volume_tolerance(s: dict, fmt: str = "3mf") -> float:
    """The chords' bound on a part's mesh volume (mm³): each curve's chords within CHORD_TOL
    (0.005 mm) of it (docs/outputs.md), so the section's area within the curves' length x
    CHORD_TOL (lines are exact), times the thickness; each head's cone or recess, cut from
    its hole's chords scaled to the head, within pi D h CHORD_TOL D / d.  STL and GLB (``fmt``)
    round every coordinate to float32: each side face moves by at most FLOAT32 x the part's
    largest coordinate, the top and bottom by FLOAT32 x its thickness."""
    from aidl_lang.geometry.shapes.tessellate import CHORD_TOL
    v = s["curved"] * CHORD_TOL * s["t"]
    if fmt in ("stl", "glb"):
        v += (s["perimeter"] * s["t"] + 2 * s["area"]) * (s["size"] + s["t"]) * FLOAT32
    for sk in s["heads"]:
        v += math.pi * sk.diameter * sk.cone_depth() * CHORD_TOL * sk.diameter / sk.hole_d
    return v + 1e-9 * s["area"] * s["t"]


def _meshes(fmt: str, data: bytes, merge: bool = True) -> list:
    """The meshes of a 3D file (trimesh): an STL's one (its equal vertices merged, as
    ``trimesh.load`` does, unless ``merge`` is false), a 3MF's or GLB's each."""
    import trimesh
    got = trimesh.load(io.BytesIO(data), file_type=fmt, force=None, process=merge)
    if isinstance(got, trimesh.Scene):
        return list(got.dump())
    return [got]


def same_solid(fmt: str, want: dict, data: bytes) -> list[str]:
    """A 3D file against the parts: one watertight body per piece, the volume of each part's
    area x thickness less its heads (only where no head reaches past the material or through
    the part: there the law holds pieces and non-emptiness, which E0503 guards)."""
    if fmt == "step":
        return _same_step(want, data)
    meshes = _meshes(fmt, data)
    out = []
    tris = sum(len(m.faces) for m in meshes)
    if not tris:
        return [f"{fmt}: 0 triangles for {len(want['solids'])} solid parts"]
    if want.get("stacked"):
        meshes = _meshes(fmt, data, merge=False)
        bodies = meshes
    else:
        bodies = [b for m in meshes for b in m.split(only_watertight=False)]
    if len(bodies) != want["pieces"] and not want.get("stacked"):
        out.append(f"{fmt}: {len(bodies)} bodies, the parts have {want['pieces']} pieces")
    if not (want.get("stacked") and fmt == "stl") and not all(b.is_watertight for b in bodies):
        # (an STL of parts over each other is one soup of triangles: no body to judge)
        out.append(f"{fmt}: a body is not watertight")
    if all(_plain(s) for s in want["solids"]):
        vol = sum(abs(float(m.volume)) for m in meshes)
        should = sum(s["area"] * s["t"] - sum(sink_volume(h) for h in s["heads"])
                     for s in want["solids"])
        tol = sum(volume_tolerance(s, fmt) for s in want["solids"])
        if abs(vol - should) > tol:
            out.append(f"{fmt}: volume {vol:.6g} mm³, the parts' area x thickness less the "
                       f"heads is {should:.6g} mm³ (off by {abs(vol - should):.3g}, "
                       f"tolerance {tol:.3g})")
    return out


def _plain(s: dict) -> bool:
    """Whether part ``s``'s heads each lie within its material (W0528's test: no more than
    OFF_AREA of the head's ring off the part), above its bottom face (no W0529) and apart
    from each other: then each removes its closed-form volume."""
    from aidl_lang.output.checks.holes.sinks import OFF_AREA, _disc
    hs = s["heads"]
    for i, h in enumerate(hs):
        if h.cone_depth() >= s["t"] - 1e-9 or h.diameter <= h.hole_d:
            return False
        if ((_disc(h.center, h.diameter / 2) - _disc(h.center, h.hole_d / 2))
                - s["shape"]).area() > OFF_AREA:
            return False
        if any(math.dist(h.center, g.center) < (h.diameter + g.diameter) / 2 for g in hs[i + 1:]):
            return False
    return True


def _has_step() -> bool:
    try:
        import OCP  # noqa: F401
    except ImportError:
        return False
    return True


def _same_step(want: dict, data: bytes) -> list[str]:    # pragma: no cover - step extra
    """A STEP file's volume (OCP) against the parts' exact area x thickness less the heads,
    within 1e-6 relative (STEP keeps exact circles and cones)."""
    import os
    import tempfile
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps
    from OCP.STEPControl import STEPControl_Reader
    with tempfile.NamedTemporaryFile(suffix=".step", delete=False) as f:
        f.write(data)
    try:
        r = STEPControl_Reader()
        r.ReadFile(f.name)
        r.TransferRoots()
        props = GProp_GProps()
        BRepGProp.VolumeProperties_s(r.OneShape(), props)
        vol = props.Mass()
    finally:
        os.unlink(f.name)
    if not all(_plain(s) for s in want["solids"]):
        return []
    should = sum(s["area"] * s["t"] - sum(sink_volume(h) for h in s["heads"])
                 for s in want["solids"])
    if abs(vol - should) > 1e-6 * max(1.0, should):
        return [f"step: volume {vol:.9g} mm³, the parts' {should:.9g} mm³"]
    return []
