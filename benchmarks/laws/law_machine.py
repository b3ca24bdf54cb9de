"""Law 1, *the machine makes what was drawn* (issue 109; docs: docs/laws.md, law machine).

For a program with parts, the router G-code (the built-in router, dogbone reliefs; and a
T-bone profile) and the laser G-code (the program's kerf) are written as ``aidl render``
writes them, re-read by an independent reader (``gcodeparser``, replayed as GRBL runs it: G0,
G1, G2/G3 arcs with I/J from the start) and the tool swept along every move that cuts through
(shapely: each run of moves a polyline, arcs in chords within :data:`ARC_SAG`, buffered by the
tool's radius: the router's bit, the laser's kerf / 2).  Against the drawn material (each
part's exact loops, chords within ``CHORD_TOL``) it checks:

* **pieces**: each part is left in as many pieces (of at least :data:`CRUMB` mm^2) as drawn;
* **nothing else removed**: the closed cuts (outlines, holes) take no material deeper than
  :data:`DEPTH` mm, the reliefs' strokes apart (the open cuts -- through-cuts and edges two
  pieces share -- are cut as wide as the tool by design: W0507 / the shared-edge note);
* **each relief at most a disc beside its corner**: the stroke of every relief (a line out
  from a loop's path and straight back) takes at most pi r^2 + :data:`AREA_TOL` of material,
  all of it within 3 r of the stroke's tip (the tip is r from its corner; at 60 degrees, the
  sharpest corner relieved, a dogbone's reaches 2 r from its tip and a T-bone's 2.73 r).

``check(entry)`` returns one line per violation, ``[]`` when the law holds or the program is
not applicable (does not compile, has no part, or the writer refuses it with a located error).
"""
from __future__ import annotations

import math
import re

NAME = ("the machine makes what was drawn: router and laser G-code, replayed and swept with "
        "the tool, leaves each part in as many pieces as drawn, removes nothing but the "
        "reliefs beyond the drawn holes and outline, and each relief at most a disc of the "
        "tool's radius beside its corner")
# mm: an arc of the G-code is replayed as chords at most this far inside it
ARC_SAG = 1e-4
# mm: the material's chords (CHORD_TOL 0.005 mm) plus the swept discs' (quad_segs 64)
DEPTH = 0.005 + 2e-4
# mm^2: a piece smaller than this is a crumb, not counted
CRUMB = 1e-3
# mm^2: a relief's area may exceed pi r^2 by this (the chords of the discs and the material)
AREA_TOL = 1e-3
TOLERANCE = (f"removal deeper than {DEPTH:g} mm into the drawn material (its arcs in chords "
             f"within {ARC_SAG:g} mm, splines and ellipses 0.005 mm, the G-code's arcs "
             f"replayed within {ARC_SAG:g} mm, the swept discs 64 chords a quarter); pieces of "
             f"at least {CRUMB:g} mm^2 once slivers thinner than {2 * DEPTH:g} mm are left "
             f"out; a relief's area within "
             f"pi r^2 + {AREA_TOL:g} mm^2 + the band of {DEPTH:g} mm along its stroke, all of "
             "it within 3 r of its tip")
QUAD = 64                   # shapely's segments a quarter circle

# (label, profile dict for machine.from_dict)
MACHINES = (("router dogbone", {"kind": "router"}),
            ("router tbone", {"kind": "router", "relief": "tbone"}),
            ("laser", {"kind": "laser"}))
THICKNESS = 3.0             # mm: every part is cut to this depth (``--thickness 3mm``)


def applies(entry) -> bool:
    """A program that may have parts (a ``solid``, or a template that makes one)."""
    return "solid" in entry.source or "import" in entry.source


def check(entry, machines=MACHINES) -> list[str]:
    """The law over ``entry`` (``name``, ``source``, ``path``, ``overrides``) on each of
    ``machines``: one line per violation, prefixed with the entry's name and the machine."""
    try:
        return check_program(entry.source, entry.path, dict(entry.overrides or {}), machines,
                             entry.name)
    except Exception as e:              # a law never raises: the runner counts it apart
        return [f"{entry.name}: the law could not be judged: {type(e).__name__}: {e}"]


def compiled(source: str, path: str, overrides: dict | None = None):
    """The compile, its design output and the output a cutter reads (the program's kerf
    applied), or None when it does not compile or has no part."""
    from aidl_lang.output import build, for_cutting
    from aidl_lang.output.part.part import OutputError
    from aidl_lang.pipeline import compile_source
    c = compile_source(source, path, overrides or None)
    if not c.ok or c.drawing is None:
        return None
    try:
        out = build(c.drawing, "law")
        cut = for_cutting(out, None)
    except OutputError:
        return None
    if not [p for p in out.parts if p.kind == "solid"]:
        return None
    return c, out, cut


def check_program(source: str, path: str, overrides: dict | None = None, machines=MACHINES,
                  name: str = "") -> list[str]:
    """:func:`check` of one program's text."""
    got = compiled(source, path, overrides)
    if got is None:
        return []
    c, out, cut = got
    bad = []
    for label, prof in machines:
        for line in judge(c, out, cut, prof):
            bad.append(f"{name or path} [{label}]: {line}")
    return bad


def judge(c, out, cut, prof: dict) -> list[str]:
    """The violations of one machine profile ``prof`` on the compiled program."""
    from aidl_lang.output.fabrication.machine import from_dict
    from aidl_lang.output.part.part import OutputError
    from aidl_lang.output.writers import Options, encode
    m = from_dict(prof)
    try:                            # as `aidl render -o x.gcode --machine ... --thickness 3mm`
        text = encode(cut, ".gcode", Options(machine=m, thickness=THICKNESS)).decode()
    except OutputError:
        return []                   # refused with its own message (a tool too large, E0501)
    router = m.kind == "router"
    kerf = getattr(out.drawing, "kerf", None)
    if router:
        r = m.tool_diameter / 2
    else:
        # the least kerf of the parts (a kerf per structure: an acrylic insert's 0.3 mm
        # beside a plate's 0.15 mm): the beam is swept no wider than any part's cut
        k = min(kerf.values()) if isinstance(kerf, dict) and kerf else (kerf or 0.0)
        r = max(float(k or 0.0) / 2, 1e-4)
    if router and "\n; tool change: " in text:
        # the countersinks and counterbores after the tool change: a V-bit's cone or a
        # pocket, not the end mill's through-cut (law 2 measures the heads against the drawing)
        text = text[:text.index("\n; tool change: ")] + "\n"
    moves = replay(text, m.kind)
    loops, opens, spikes = runs(moves, THICKNESS, router)
    return measure(out, loops, opens, spikes, r, _said_parts(c, out, cut, m, kerf or None))


def _said_parts(c, out, cut, m, kerf) -> set:
    """The parts ``aidl render`` says the tool cuts apart (W0510: a through-cut nearer an
    edge than the bit's reach) or into (W0531: parts nearer each other than the tool)."""
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.output.checks.material.toolpath_walls import machine_warnings
    sink = DiagnosticSink()
    router = m.kind == "router"
    width = m.tool_diameter if router else kerf
    if not width:
        return set()
    try:
        machine_warnings(c.drawing, cut, out, width, router, sink, None, False, "none")
    except Exception:
        return set()
    got = set()
    for d in sink.items:
        if d.code == "W0510":
            got |= set(re.findall(r"part `([^`]+)` comes out", d.message))
        elif d.code == "W0531":
            got |= set(re.findall(r"parts `([^`]+)` and `([^`]+)`", d.message)[0])
    return got


# -- the independent reading --------------------------------------------------------------

def replay(text: str, kind: str) -> list[tuple]:
    """Every XY motion of G-code ``text`` as GRBL runs it, read by ``gcodeparser``
    (docs/toolpath_picture.py's reader): ``(g, (x0, y0), (x1, y1), centre or None, z, power)``
    of the feed moves (G1, G2, G3) at one depth; ``power``: the S in force with the spindle or
    laser on (0 off)."""
    got = []
    for g, p, q, c, _, z0, z1, s in _picture().moves(text, kind):
        if g != 0 and z0 == z1:
            got.append((g, p, q, c, z1, s))
    return got


def _picture():
    """docs/toolpath_picture.py, loaded from its file (docs/ is no package)."""
    import importlib.util
    import sys
    from pathlib import Path
    mod = sys.modules.get("aidl_toolpath_picture")
    if mod is None:
        path = Path(__file__).resolve().parents[2] / "docs" / "toolpath_picture.py"
        spec = importlib.util.spec_from_file_location("aidl_toolpath_picture", path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        sys.modules["aidl_toolpath_picture"] = mod
    return mod


def _arc_points(p, q, centre, cw: bool) -> list:
    """Points along an arc from ``p`` to ``q`` about ``centre`` (G2 ``cw``), chords within
    :data:`ARC_SAG` of it (``p`` left out, ``q`` included)."""
    cx, cy = centre
    R = math.dist(p, centre)
    a0 = math.atan2(p[1] - cy, p[0] - cx)
    a1 = math.atan2(q[1] - cy, q[0] - cx)
    sweep = (a0 - a1) % (2 * math.pi) if cw else (a1 - a0) % (2 * math.pi)
    if sweep == 0:
        sweep = 2 * math.pi
    step = 2 * math.acos(max(-1.0, 1 - ARC_SAG / R)) if R > ARC_SAG else math.pi / 2
    n = max(1, math.ceil(sweep / max(step, 1e-6)))
    sign = -1 if cw else 1
    pts = [(cx + R * math.cos(a0 + sign * sweep * i / n), cy + R * math.sin(a0 + sign * sweep * i / n))
           for i in range(1, n)]
    return pts + [q]


def runs(moves: list, thickness: float, router: bool):
    """The cuts through the material: runs of consecutive moves (each from where the last
    ended) at the full depth (router) or the job's cutting power (laser), as point lists.
    Returns ``(closed, open, spikes)``: the runs that come back to their start with every
    relief (a line out and straight back: router only) taken out of them, the other runs,
    and the reliefs ``(from, tip)``."""
    if router:
        cutting = [mv for mv in moves if mv[4] is not None and mv[4] <= -thickness + 1e-9]
    else:
        top = max((mv[5] for mv in moves), default=0.0)
        cutting = [mv for mv in moves if top > 0 and mv[5] >= top]
    seqs, cur = [], []
    for mv in cutting:
        if cur and cur[-1][2] != mv[1]:
            seqs.append(cur)
            cur = []
        cur.append(mv)
    if cur:
        seqs.append(cur)
    closed, opened, spikes = [], [], []
    def spike(a, b) -> bool:
        return a[0] == b[0] == 1 and a[1] == b[2] and a[2] == b[1]

    for seq in seqs:
        if router and len(seq) > 2 and seq[-1][2] == seq[0][1]:
            # a loop may begin inside a relief (at its tip): begin it after the relief
            k = 0
            while k < len(seq) and spike(seq[k - 1], seq[k]):
                k += 1
            seq = seq[k:] + seq[:k]
        kept = []
        i = 0
        while i < len(seq):
            mv = seq[i]
            nx = seq[i + 1] if i + 1 < len(seq) else None
            if router and nx is not None and spike(mv, nx):
                spikes.append((mv[1], mv[2]))
                i += 2
                continue
            kept.append(mv)
            i += 1
        if not kept:
            continue
        pts = [kept[0][1]]
        for mv in kept:
            if mv[0] == 1 or mv[3] is None:
                pts.append(mv[2])
            else:
                pts += _arc_points(mv[1], mv[2], mv[3], mv[0] == 2)
        # a laser runs an open path there and back: it comes back to its start on its own line
        back = all(math.dist(a, b) <= 1e-9 for a, b in zip(pts, reversed(pts)))
        shut = len(pts) > 2 and math.dist(pts[0], pts[-1]) <= 1e-9 and not back
        (closed if shut else opened).append(pts)
    return closed, opened, list(dict.fromkeys(spikes))


# -- the measure ----------------------------------------------------------------------------

def material(part):
    """The drawn material of ``part`` as a shapely geometry: its exact loops in chords
    (outer loops added, holes taken away, the largest first so nesting holds), arcs
    within :data:`ARC_SAG`, splines and ellipses within 0.005 mm."""
    from shapely.geometry import Polygon
    loops = sorted(part.loops, key=lambda lp: -abs(lp.area))
    got = None
    for lp in loops:
        pts = lp.points(ARC_SAG)
        if len(pts) < 3:
            continue
        poly = Polygon(pts).buffer(0)
        if got is None:
            got = poly if lp.area > 0 else None
        elif lp.area > 0:
            got = got.union(poly)
        else:
            got = got.difference(poly)
    return got


def _sweep(paths: list, r: float):
    """The region a disc of radius ``r`` covers along the point lists ``paths``."""
    from shapely.geometry import LineString, Point
    from shapely.ops import unary_union
    parts = [LineString(p).buffer(r, quad_segs=QUAD) if len(p) > 1 else
             Point(p[0]).buffer(r, quad_segs=QUAD) for p in paths]
    return unary_union(parts) if parts else None


def _pieces(geom) -> int:
    """The pieces of ``geom`` of at least :data:`CRUMB` mm^2, slivers thinner than twice
    :data:`DEPTH` (where chords of a curve and the tool's path on it meet) left out."""
    if geom is None or geom.is_empty:
        return 0
    geom = geom.buffer(-DEPTH, quad_segs=4)
    gs = getattr(geom, "geoms", [geom])
    return sum(1 for g in gs if g.area >= CRUMB)


def measure(out, loops: list, opens: list, spikes: list, r: float,
            said: set = frozenset()) -> list[str]:
    """The violations of the swept cuts against ``out``'s drawn parts (see the module's
    docstring); ``said``: the parts ``aidl render`` says the tool cuts apart or into
    (W0510, W0531): their pieces and removal are not judged."""
    import numpy as np
    import shapely
    from shapely.geometry import LineString
    from shapely.ops import unary_union
    bad = []
    swept_loops = _sweep(loops, r)
    swept_open = _sweep(opens, r)
    strokes = [(p, q, LineString([p, q]).buffer(r, quad_segs=QUAD)) for p, q in spikes]
    every = unary_union([g for g in (swept_loops, swept_open, *[s for _, _, s in strokes])
                         if g is not None])
    relief_zone = unary_union([s for _, _, s in strokes]) if strokes else None
    mats = [(p.name, material(p)) for p in out.parts if p.kind == "solid"]
    whole = unary_union([m for _, m in mats if m is not None])
    for name, mat in mats:
        if mat is None or mat.is_empty:
            continue
        drawn = _pieces(mat)
        left = mat.difference(every) if every is not None and not every.is_empty else mat
        now = _pieces(left)
        if now > drawn and name not in said:
            bad.append(f"part `{name}` comes out in {now} pieces, drawn as {drawn}")
    for name, mat in mats:
        if swept_loops is None or mat is None or name in said:
            continue
        took = mat.intersection(swept_loops)
        if relief_zone is not None:
            took = took.difference(relief_zone)
        deep = took.buffer(-DEPTH)
        if not deep.is_empty:
            c = deep.representative_point()
            bad.append(f"the closed cuts take {took.area:.4g} mm^2 of part `{name}`, deeper "
                       f"than {DEPTH:g} mm near ({c.x:.3f}, {c.y:.3f})")
    disc = math.pi * r * r
    for p, q, stroke in strokes:
        took = whole.intersection(stroke) if whole is not None else None
        if took is None or took.is_empty:
            continue
        allow = disc + AREA_TOL + DEPTH * (2 * math.dist(p, q) + 2 * math.pi * r)
        xy = shapely.get_coordinates(took)
        far = float(np.hypot(xy[:, 0] - q[0], xy[:, 1] - q[1]).max()) if len(xy) else 0.0
        if took.area > allow or far > 3 * r + DEPTH:
            bad.append(f"the relief to ({q[0]:.3f}, {q[1]:.3f}) takes {took.area:.4g} mm^2 "
                       f"({took.area / disc:.3g} of the tool's disc), reaching {far:.3g} mm "
                       f"from its tip (at most pi r^2 = {disc:.4g} mm^2 within 3 r = "
                       f"{3 * r:.4g} mm)")
    return bad


if __name__ == "__main__":          # python benchmarks/laws/law_machine.py FILE.aidl ...
    import sys
    import time
    from pathlib import Path
    held = 0
    for f in sys.argv[1:]:
        t = time.process_time()
        said = check_program(Path(f).read_text(), f, name=f)
        held += not said
        print(f"{f}: {'held' if not said else 'VIOLATED'} ({time.process_time() - t:.2f} s CPU)")
        for s in said:
            print("   ", s)
    print(f"{held} of {len(sys.argv) - 1} held")
