"""HPGL for vinyl cutters and pen plotters (aidl_lang/output/writers/hpgl.py, issue 50): real
programs through the real compiler, every file re-read by an independent HP-GL interpreter
(``ezhpgl``, from PyPI: it runs the PU/PD/AA commands as a plotter does, in mm with y up at
40 units per mm, and tessellates each arc with the file's own chord angle) and compared with
the design: every drawn point within 0.025 mm (one plotter unit) of the exact loops and back,
arcs turning the design's way about the design's centre (whole units), coordinates whole and
>= 0, engraving first and no loop cut after a loop around it.  Broken writers (the arc's sweep
sign flipped, 1000 units per inch instead of 1016, the cut order reversed) fail the same
checks."""
import math

import numpy as np
import pytest

from aidl_lang.geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Spline
from aidl_lang.geometry.shapes.spline import bez_at
from aidl_lang.output import encode, for_cutting
from aidl_lang.output.part.extent import extent
from aidl_lang.output.fabrication.toolpath import plan
from aidl_lang.output.writers import hpgl

from conftest import ROOT

ezhpgl = pytest.importorskip("ezhpgl")
import ezhpgl.raw  # noqa: E402

TOL = hpgl.TOLERANCE / hpgl.UNITS_PER_MM          # 0.025 mm
UNIT = 1 / 40.0                                   # mm: HP's plotter unit


def _compile(name):
    import aidl_lang
    res = aidl_lang.compile(path=str(ROOT / "examples" / f"{name}.aidl"))
    assert res.ok, [d.message for d in res.diagnostics]
    return res


# ------------------------------------------------------------------ geometry
def _dense(s, step=0.02) -> np.ndarray:
    """Points along exact segment ``s`` (mm), at most ``step`` mm apart on the curve
    (a spline or ellipse by its own evaluation: no chord of ours)."""
    if isinstance(s, Line):
        n = max(1, math.ceil(s.length / step))
        t = np.linspace(0, 1, n + 1)[:, None]
        return np.asarray(s.start) * (1 - t) + np.asarray(s.end) * t
    if isinstance(s, (Arc, Circle)):
        a0, sw = (s.start_angle, s.sweep) if isinstance(s, Arc) else (0.0, 2 * math.pi)
        n = max(2, math.ceil(abs(sw) * s.radius / step))
        a = a0 + sw * np.linspace(0, 1, n + 1)
        return np.c_[s.center[0] + s.radius * np.cos(a), s.center[1] + s.radius * np.sin(a)]
    if isinstance(s, EllipticArc):
        n = max(2, math.ceil(s.length / step))
        return np.array([s.at(s.start_param + s.sweep * i / n) for i in range(n + 1)])
    if isinstance(s, Spline):
        out = []
        for b in s.spans:
            n = 400
            out += [bez_at(b, i / n) for i in range(n + 1)]
        return np.array(out)
    raise AssertionError(type(s))


def _to_polyline_distance(pts: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Each point's distance to the polyline ``poly`` (k x 2)."""
    if len(poly) == 1:
        return np.hypot(*(pts - poly[0]).T)
    a, b = poly[:-1], poly[1:]
    ab = b - a
    L2 = (ab ** 2).sum(1)
    L2[L2 == 0] = 1e-300
    best = np.full(len(pts), np.inf)
    for i in range(0, len(pts), 512):
        p = pts[i:i + 512, None, :]
        t = np.clip(((p - a) * ab).sum(2) / L2, 0, 1)
        d = np.hypot(*(p - (a + t[..., None] * ab)).transpose(2, 0, 1))
        best[i:i + 512] = d.min(1)
    return best


def _segment_distance(pts: np.ndarray, s) -> np.ndarray:
    """Exact distance of each point to segment ``s`` (lines, arcs, circles analytically;
    splines and ellipses to a polyline of points 0.002 mm apart on them)."""
    if isinstance(s, Line):
        return _to_polyline_distance(pts, np.array([s.start, s.end]))
    if isinstance(s, Circle):
        return np.abs(np.hypot(*(pts - s.center).T) - s.radius)
    if isinstance(s, Arc):
        v = pts - s.center
        ang = np.arctan2(v[:, 1], v[:, 0])
        lo = s.start_angle if s.sweep > 0 else s.start_angle + s.sweep
        inside = np.mod(ang - lo, 2 * math.pi) <= abs(s.sweep)
        radial = np.abs(np.hypot(*v.T) - s.radius)
        ends = np.minimum(np.hypot(*(pts - s.start).T), np.hypot(*(pts - s.end).T))
        return np.where(inside, radial, ends)
    return _to_polyline_distance(pts, _dense(s, 0.002))


def _distance_to_cut(pts, segments) -> np.ndarray:
    return np.min([_segment_distance(pts, s) for s in segments], axis=0)


# ------------------------------------------------------------------ the re-read file
def _read(data: bytes):
    """ezhpgl's plot: its pen-down paths (one list of operations per path, in order)."""
    plot = ezhpgl.parse(data)
    assert plot.completeness == "complete", [d.message for d in plot.diagnostics]
    assert not plot.diagnostics, [d.message for d in plot.diagnostics]
    (page,) = plot.pages
    paths: dict = {}
    for op in page.operations:
        paths.setdefault(op.path_id, []).append(op)
    return plot, [paths[k] for k in sorted(paths)]


def _points(ops) -> np.ndarray:
    return np.array([(q.x, q.y) for op in ops for q in op.geometry.points])


def check_hpgl(out, data: bytes, passes: int = 1) -> dict:
    """Re-read ``data`` (the HPGL of output ``out``) with ezhpgl and check it against the
    design; returns counts for the callers."""
    x0, y0, _, _ = extent(out)
    cuts = plan(out)
    shift = np.array([x0, y0])
    # every coordinate a whole number of units and >= 0; the file's commands as expected
    raw = ezhpgl.raw.parse_commands(data)
    names = [c.name for c in raw.commands]
    assert names[:2] == ["IN", "SP"] and names[-2:] == ["PU", "SP"]
    assert set(names) <= {"IN", "SP", "VS", "PU", "PD", "AA"}
    for c in raw.commands:
        if c.name in ("PU", "PD"):
            assert all(v >= 0 and float(v).is_integer() for v in c.args), c.raw
        if c.name == "AA":
            assert all(v >= 0 and float(v).is_integer() for v in c.args[:2]), c.raw
    plot, paths = _read(data)
    assert len(paths) == len(cuts) * passes
    # the extent: the units are 40 a mm (a wrong scale moves the far side by 1.6 %)
    import copy
    b = plot.pages[0].bounds
    own = copy.copy(out)
    own.page = None
    X0, Y0, X1, Y1 = extent(own)                                      # the drawing's own box
    assert (b.min.x, b.min.y, b.max.x, b.max.y) == pytest.approx(
        (X0 - x0, Y0 - y0, X1 - x0, Y1 - y0), abs=TOL)
    stats = {"arcs": 0, "centres_rounded": 0}
    design_arcs = [(s, c) for c in cuts for s in c.segments if isinstance(s, (Arc, Circle))]
    read_arcs = [op for ops in paths[::passes] for op in ops if op.source.command == "AA"]
    assert len(read_arcs) == len(design_arcs)         # every arc an AA (none too small here)
    for (s, cut), op in zip(design_arcs, read_arcs):
        cv = op.geometry.curve
        sweep = math.degrees(s.sweep) if isinstance(s, Arc) else (360 if s.ccw else -360)
        # the centre: the design's in whole units (rounded, or a neighbour: 1.5 units)
        cx, cy = (np.asarray(s.center) - shift) * 40
        rx, ry = cv.center.x * 40, cv.center.y * 40
        assert rx.is_integer() if isinstance(rx, float) else True
        assert abs(rx - cx) <= 1.5 + 1e-9 and abs(ry - cy) <= 1.5 + 1e-9, (rx, ry, cx, cy)
        stats["centres_rounded"] += (rx, ry) == (round(cx), round(cy))
        # the sweep: the design's way round, as far as rounding allows
        assert math.copysign(1, cv.sweep_angle_deg) == math.copysign(1, sweep)
        r_units = s.radius * 40
        assert abs(cv.sweep_angle_deg - sweep) <= math.degrees(4.5 / r_units) + 1e-4
        # the chords the plotter is asked for: within 0.1 unit of the arc
        chord = math.radians(cv.chord_value)
        assert math.hypot(cv.axis_u.x, cv.axis_u.y) * (1 - math.cos(chord / 2)) \
            <= hpgl.CHORD_SAGITTA * UNIT * 1.01
        stats["arcs"] += 1
    # every path: what the plotter draws (ezhpgl's points, its arcs in the file's chords)
    # within one unit of the design's loop, and the loop within one unit of it
    for k, cut in enumerate(cuts):
        for j in range(passes):
            drawn = _points(paths[k * passes + j]) + shift
            d1 = _distance_to_cut(drawn, cut.segments)
            assert d1.max() <= TOL + 1e-9, (cut.part, cut.operation, d1.max())
            design = np.vstack([_dense(s) for s in cut.segments])
            d2 = _to_polyline_distance(design, drawn)
            assert d2.max() <= TOL + 1e-9, (cut.part, cut.operation, d2.max())
    # the order: engraving first (its speed), and no closed path after one around it
    from aidl_lang.output.fabrication.machine import DEFAULTS
    speeds = [c.args[0] for c in raw.commands if c.name == "VS"]
    want = []
    for c in cuts:
        v = round(DEFAULTS["plotter"].operation(c.operation).speed / 600, 1)
        if not want or want[-1] != v:
            want.append(v)
    assert speeds == want
    closed = [(_points(paths[k * passes]), cut) for k, cut in enumerate(cuts)
              if cut.operation.startswith("cut")]
    for i, (pi, ci) in enumerate(closed):
        for pj, cj in closed[:i]:
            if len(pj) > 2:
                assert not _inside(pj, pi[len(pi) // 2]), \
                    f"{ci.part} {ci.operation} cut after {cj.part} {cj.operation} around it"
    return stats


def _inside(polyline, point) -> bool:
    """Whether ``point`` lies inside the closed polyline ``polyline`` (shapely: the ring's
    interior, the boundary excluded; a self-touching ring is first made valid)."""
    import shapely
    poly = shapely.Polygon(polyline)
    if not poly.is_valid:
        poly = shapely.make_valid(poly)
    return bool(poly.contains(shapely.Point(point)))


# ------------------------------------------------------------------ the examples
@pytest.mark.parametrize("name", ["laser_box", "gear", "name_tag"])
def test_examples_reread_equal_the_design(name):
    out = for_cutting(_compile(name).output, None)
    data = encode(out, ".plt")
    stats = check_hpgl(out, data)
    if name == "gear":
        assert stats["arcs"] > 40
    # most centres are the design's rounded (a neighbour only where rounding moved the ends)
    assert stats["centres_rounded"] >= 0.7 * stats["arcs"]
    assert data.startswith(b"IN;\nSP1;\nVS")


def test_the_sheet_layout_keeps_the_sheet_origin(tmp_path):
    pytest.importorskip("spyrrow")
    lay = _compile("laser_box").layout(sheet=(300.0, 200.0))
    sheets = lay.encode("plt")
    assert len(sheets) >= 1
    for out, data in zip(lay._cut, sheets):
        assert out.page is not None and extent(out)[:2] == (0.0, 0.0)
        check_hpgl(out, data)


def test_the_cli_api_and_formats_list(tmp_path):
    import aidl_lang
    from aidl_lang.cli import main
    prog = ROOT / "examples" / "gear.aidl"
    for ext in ("plt", "hpgl"):
        dest = tmp_path / f"g.{ext}"
        assert main(["render", str(prog), "-o", str(dest)]) == 0
        res = aidl_lang.compile(path=str(prog))
        assert dest.read_bytes() == res.encode(ext)
        check_hpgl(for_cutting(res.output, None), dest.read_bytes())
    lay = tmp_path / "sheet.plt"
    assert main(["render", str(ROOT / "examples" / "laser_box.aidl"), "--layout", "sheet",
                 "--sheet", "300x200mm", "-o", str(lay)]) == 0
    assert sorted(tmp_path.glob("sheet*.plt"))
    from aidl_lang.output.writers import CUT_FORMATS, FORMATS
    assert ".plt" in CUT_FORMATS and ".hpgl" in CUT_FORMATS
    assert FORMATS[".plt"].media == "application/vnd.hp-hpgl"


def test_serve_downloads_and_the_mcp_render_tool_write_it(tmp_path):
    from aidl_lang.pipeline import compile_source
    from aidl_lang.serve import app
    prog = ROOT / "examples" / "gear.aidl"
    c = compile_source(prog.read_text(), str(prog))
    for ext in ("plt", "hpgl"):
        assert app.TYPES[ext] == "application/vnd.hp-hpgl"
        data = app.writers()[ext](c.drawing, "gear")
        check_hpgl(for_cutting(_compile("gear").output, None), data)
    pytest.importorskip("mcp")
    from aidl_lang.mcp import server, tools as T
    assert ".plt" in server.Output.__metadata__[0].description.split(", ")
    tag = (ROOT / "examples" / "name_tag.aidl").read_text()
    doc, _ = T.render(T.Workspace(tmp_path), source=tag, output="tag.plt")
    assert doc["ok"], doc
    check_hpgl(for_cutting(_compile("name_tag").output, None), (tmp_path / "tag.plt").read_bytes())


def test_the_machine_profile_sets_speeds_and_passes():
    from aidl_lang.output.fabrication.machine import from_dict
    from aidl_lang.output.writers import Options
    out = for_cutting(_compile("name_tag").output, None)
    o = Options()
    o.machine = from_dict({"kind": "plotter", "engrave": {"speed": 1800},
                           "cut_outer": {"speed": 600, "passes": 2},
                           "cut_inner": {"speed": 600, "passes": 2}})
    data = encode(out, ".plt", o)
    raw = ezhpgl.raw.parse_commands(data)
    speeds = [c.args[0] for c in raw.commands if c.name == "VS"]
    assert speeds == [3.0, 1.0]                     # mm/min / 600 = cm/s
    # the cuts run twice: every cut path twice over, and still within one unit
    plot, paths = _read(data)
    cuts = plan(out)
    n_eng = sum(c.operation == "engrave" for c in cuts)
    assert len(paths) == n_eng + 2 * (len(cuts) - n_eng)


# ------------------------------------------------------------------ broken writers
def _gear():
    return for_cutting(_compile("gear").output, None)


def test_a_flipped_arc_sweep_is_caught(monkeypatch):
    out = _gear()
    fit = hpgl._fit

    def flipped(*a):
        got = fit(*a)
        return None if got is None else got[:2] + (-got[2],) + got[3:]
    monkeypatch.setattr(hpgl, "_fit", flipped)
    with pytest.raises(AssertionError):
        check_hpgl(out, encode(out, ".plt"))


def test_wrong_units_per_mm_are_caught(monkeypatch):
    out = _gear()
    monkeypatch.setattr(hpgl, "UNITS_PER_MM", 1000 / 25.4)    # 1000 a inch, not 1016
    with pytest.raises(AssertionError):
        check_hpgl(out, encode(out, ".plt"))


def test_a_cut_order_with_outlines_first_is_caught(monkeypatch):
    out = for_cutting(_compile("laser_box").output, None)
    from aidl_lang.output.fabrication import toolpath
    real = toolpath.plan

    def outlines_first(o, *a, **k):
        cuts = real(o, *a, **k)
        return sorted(cuts, key=lambda c: c.operation != "cut_outer")
    data_bad = None
    monkeypatch.setattr(toolpath, "plan", outlines_first)
    data_bad = encode(out, ".plt")
    monkeypatch.setattr(toolpath, "plan", real)
    with pytest.raises(AssertionError):
        check_hpgl(out, data_bad)


def test_rounding_bound_holds_off_the_grid():
    """A drawing whose every point lies between plotter units: every written point within
    half a unit in x and y of the design, every drawn point within one unit."""
    from aidl_lang.output.part.part import Output, PartOutline
    from aidl_lang.geometry.shapes.curves import Loop
    segs = [Line((0.013, 0.0071), (30.0123, 0.0071)),
            Arc((30.0123, 10.0071), 10.0, -math.pi / 2, math.pi),
            Line((30.0123, 20.0071), (0.013, 20.0071)),
            Line((0.013, 20.0071), (0.013, 0.0071))]
    hole = [Circle((10.0061, 10.0123), 3.3337, ccw=False)]
    out = Output(parts=[PartOutline("p", "solid", [Loop(segs), Loop(hole)])])
    data = encode(out, ".plt")
    check_hpgl(out, data)
    raw = ezhpgl.raw.parse_commands(data)
    x0, y0, _, _ = extent(out)
    pts = [c.args for c in raw.commands if c.name in ("PU", "PD") and c.args]
    design = {(round((x - x0) * 40, 6), round((y - y0) * 40, 6))
              for x, y in [(0.013, 0.0071), (30.0123, 0.0071), (30.0123, 20.0071),
                           (0.013, 20.0071), (10.0061 + 3.3337, 10.0123)]}
    for a in pts:
        for x, y in zip(a[::2], a[1::2]):
            assert min(max(abs(x - dx), abs(y - dy)) for dx, dy in design) <= 0.5


ELLIPSES = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=50)
    hole a { e = Ellipse(center=(-20, 0), rx=12, ry=6, rotation=30) }
    hole b { e = Ellipse(center=(25, 20), rx=15, ry=8) }
}
"""


def test_ellipses_whole_and_cut(tmp_path):
    """A whole rotated ellipse (a hole) and elliptical arcs (one cut by the plate's edge)."""
    import aidl_lang
    prog = tmp_path / "ell.aidl"
    prog.write_text(ELLIPSES)
    out = aidl_lang.compile(path=str(prog)).output
    kinds = [type(s).__name__ for p in out.parts for lp in p.loops for s in lp.segments]
    assert kinds.count("EllipticArc") == 2
    check_hpgl(out, encode(out, ".plt"))
