"""Law 5 (issue 109): one thing is counted once.

A hole a program sinks (``Countersink``, ``Counterbore``: named once, twice in one list, or
again by another call with the same head) is one countersink or counterbore everywhere it is
counted: ``aidl parts --json`` (the real command line) lists it once, the DXF's ``COUNTERSINK``
/ ``COUNTERBORE`` layers (ezdxf) hold one circle at its centre, and a router's G-code
(gcodeparser) sinks it at one place after the tool change: one plunge for a countersink, one
per depth pass for a counterbore's pocket, each at one centre.  A hole sunk again with another
head is the compile's E0108 (naming the first call's line), so such a program is not
applicable here.  Every program is also held to what the DXF says once: no entity of a cut,
engrave or sink layer drawn twice over itself (the same type and the same numbers to 1e-9 mm).
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import tempfile

from benchmarks.laws.law_outputs import NotApplicable, compiled

NAME = "One thing is counted once: a sunk hole is one sink in `aidl parts`, the DXF and G-code"
TOLERANCE = ("centres compared to 1e-6 mm; a DXF entity is a repeat when its type and numbers "
             "agree to 1e-9 mm")
SINK_LAYERS = ("COUNTERSINK", "COUNTERBORE")


def applies(entry) -> bool:
    """Every program (the sink counts only where it sinks a hole)."""
    return True


def check(entry) -> list[str]:
    """The violations of law 5 for ``entry`` (``source``, ``path``, ``overrides``); raises
    :class:`NotApplicable` for a program that does not compile."""
    res = compiled(entry)
    return counted(res, entry)


def sunk_holes(res) -> dict:
    """The holes the program sinks, each once: ``{hole's Circle path: kind}`` from the
    model's ``Countersink`` / ``Counterbore`` records (one entry per Circle, however often
    it was named)."""
    model = res.compiled.model
    out = {}
    for sk in getattr(model, "sinks", None) or ():
        for g in sk.circles:
            out.setdefault(id(g), (g.label, sk.kind))
    return dict(out.values())


def counted(res, entry) -> list[str]:
    """The violations for a compiled ``res`` of ``entry``."""
    from aidl_lang.output import MissingDependency, OutputError
    out = []
    want = sunk_holes(res)
    try:
        dxf = res.encode("dxf", kerf=0)
    except (MissingDependency, OutputError) as ex:
        raise NotApplicable(f"no DXF: {ex}") from None
    out += dxf_repeats(dxf)
    if not want:
        return out
    rows = parts_json(entry)
    listed = [(s["hole"], s["kind"]) for r in rows for s in r.get("sinks", ())]
    if sorted(listed) != sorted(want.items()):
        extra = len(listed) - len(want)
        out.append(f"aidl parts lists {len(listed)} sinks for {len(want)} sunk holes"
                   + (f" ({extra} counted again)" if extra > 0 else ""))
    centres = dxf_sink_circles(dxf)
    if len(centres) != len(want):
        out.append(f"DXF: {len(centres)} circles on the sink layers for {len(want)} sunk holes")
    try:
        gcode = res.encode("gcode", kerf=0, machine="router")
    except (MissingDependency, OutputError):
        return out
    plunges = sink_plunges(gcode.decode())
    if len(plunges) != len(want):
        out.append(f"router G-code: sinks at {len(plunges)} places for {len(want)} sunk holes")
    for (x, y), n in sorted(plunges.items()):
        if n > 1:
            out.append(f"router G-code: the hole at ({x:g}, {y:g}) is sunk {n} times")
    return out


def parts_json(entry) -> list[dict]:
    """``aidl parts --json`` of the program (the real command line, in this process)."""
    from aidl_lang.cli.main import main
    path, made = entry.path, None
    try:
        with open(path, encoding="utf-8") as f:
            same = f.read() == entry.source
    except OSError:
        same = False
    if not same:
        fd, made = tempfile.mkstemp(suffix=".aidl")
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(entry.source)
        path = made
    args = ["parts", path, "--json"]
    for k, v in (entry.overrides or {}).items():
        args += ["--set", f"{k}={v}"]
    buf = io.StringIO()
    try:
        with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(io.StringIO()):
            main(args)
    finally:
        if made:
            os.unlink(made)
    return json.loads(buf.getvalue()).get("parts", [])


def _dxf(data: bytes):
    import ezdxf
    return ezdxf.read(io.StringIO(data.decode("utf-8", "replace")))


def dxf_sink_circles(data: bytes) -> list[tuple]:
    """The centres of the circles on the DXF's sink layers (ezdxf)."""
    return [tuple(e.dxf.center)[:2] for e in _dxf(data).modelspace()
            if e.dxftype() == "CIRCLE" and e.dxf.layer.upper() in SINK_LAYERS]


def dxf_repeats(data: bytes) -> list[str]:
    """One line per DXF entity drawn again over itself on its layer (its type and numbers
    equal to 1e-9 mm; a polyline the same either way round)."""
    seen: dict = {}
    out = []
    for e in _dxf(data).modelspace():
        key = _key(e)
        if key is None:
            continue
        n = seen.get(key, 0) + 1
        seen[key] = n
        if n == 2:
            out.append(f"DXF: a {e.dxftype()} on layer {e.dxf.layer} is drawn more than once")
    return out


def _key(e):
    r = lambda v: round(float(v), 9) + 0.0       # noqa: E731  (-0.0 and 0.0 alike)
    t, layer = e.dxftype(), e.dxf.layer
    if t == "CIRCLE":
        return (t, layer, *map(r, tuple(e.dxf.center)[:2]), r(e.dxf.radius))
    if t == "ARC":
        return (t, layer, *map(r, tuple(e.dxf.center)[:2]), r(e.dxf.radius),
                r(e.dxf.start_angle), r(e.dxf.end_angle))
    if t == "LINE":
        a, b = (tuple(map(r, tuple(p)[:2])) for p in (e.dxf.start, e.dxf.end))
        return (t, layer, *sorted((a, b)))
    if t == "LWPOLYLINE":
        pts = tuple(tuple(map(r, p)) for p in e.get_points("xyb"))
        return (t, layer, bool(e.closed), min(pts, pts[::-1]))
    return None


def sink_plunges(text: str) -> dict:
    """``{(x, y): plunges}`` of a router's G-code after its first tool change (``M0``): each
    place the tool goes down into the part (a ``G1`` to a ``Z`` below 0 from above it, or
    deeper at the same place: a counterbore's next pass), centres to 1e-6 mm."""
    import gcodeparser
    x = y = z = None
    after = False
    out: dict = {}
    for line in gcodeparser.parse_gcode_lines(text):
        letter, code = line.command
        prm = line.params
        if letter == "M" and code == 0:
            after = True
            continue
        if letter != "G" or code not in (0, 1, 2, 3):
            continue
        nx = float(prm["X"]) if "X" in prm else x
        ny = float(prm["Y"]) if "Y" in prm else y
        nz = float(prm["Z"]) if "Z" in prm else z
        if after and code == 1 and nz is not None and nz < 0 and (z is None or nz < z) and \
                (nx, ny) == (x, y):
            key = (round(nx, 6) + 0.0, round(ny, 6) + 0.0)
            if z is None or z >= 0:         # down from above the part: a new plunge
                out[key] = out.get(key, 0) + 1
            else:
                out.setdefault(key, 1)      # a pocket's next depth: the same place
        x, y, z = nx, ny, nz
    return out


__all__ = ["NAME", "TOLERANCE", "applies", "check", "counted", "sink_plunges",
           "dxf_repeats", "dxf_sink_circles", "NotApplicable"]
