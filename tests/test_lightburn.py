"""LightBurn projects (aidl_lang/output/writers/lightburn.py, issue 50): real programs through
the real compiler, every ``.lbrn2`` parsed by lxml and its shapes rebuilt from LightBurn's own
syntax (``<VertList>`` ``V x y c0x.. c0y.. c1x.. c1y..`` with ``c0x1`` for no control point,
``<PrimList>`` ``L i j`` / ``B i j`` from vertex i's c0 to vertex j's c1, ``Ellipse`` shapes
with ``Rx``, ``Ry`` and an ``XForm`` ``a b c d e f``) by the small reader below, written from
LightBurn-saved files, not from the writer; then compared with the design: lines, spline
pieces, circles and every primitive's ends to 1e-9 mm, every point of every arc's Bézier
within 1e-4 mm of the arc (sampled), the layers' speed (mm/s), power and passes the machine
profile's, one group per part named by the comment before it, shapes in the cut order.  Broken
writers (a Bézier control point off, speeds left in mm/min, outlines before holes) fail."""
import math
import re

import numpy as np
import pytest

from aidl_lang.geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Spline
from aidl_lang.output import encode, for_cutting
from aidl_lang.output.fabrication.machine import DEFAULTS, from_dict
from aidl_lang.output.fabrication.toolpath import plan
from aidl_lang.output.writers import Options, beziers, lightburn

from conftest import ROOT

etree = pytest.importorskip("lxml.etree")

EXACT = 1e-9                      # mm: what the format holds exactly (9 decimals)
BEZ = lightburn.BEZIER_TOL        # mm: an arc's Bézier from the arc
OPS = ("engrave", "score", "cut_inner", "cut_outer")


def _compile(name):
    import aidl_lang
    res = aidl_lang.compile(path=str(ROOT / "examples" / f"{name}.aidl"))
    assert res.ok, [d.message for d in res.diagnostics]
    return res


# ------------------------------------------------------------------ the reader
_NUM = r"(-?\d+(?:\.\d+)?)"
_VERT = re.compile(rf"V{_NUM} {_NUM}(?:c0x{_NUM}(?:c0y{_NUM})?)?(?:c1x{_NUM}(?:c1y{_NUM})?)?")
_PRIM = re.compile(r"([LB])(\d+) (\d+)")


def _xform(el):
    a, b, c, d, e, f = (float(v) for v in el.find("XForm").text.split())
    return lambda p: (a * p[0] + c * p[1] + e, b * p[0] + d * p[1] + f)


def _path(el) -> list:
    """A Path shape's primitives: ("L", p, q) or ("B", p, c0, c1, q), mm."""
    m = _xform(el)
    verts = []
    text = el.find("VertList").text
    assert _VERT.sub("", text) == "", "unread text in the VertList"
    for g in _VERT.finditer(text):
        x, y, c0x, c0y, c1x, c1y = g.groups()
        verts.append((m((float(x), float(y))),
                      m((float(c0x), float(c0y))) if c0y is not None else None,
                      m((float(c1x), float(c1y))) if c1y is not None else None))
    text = el.find("PrimList").text
    assert _PRIM.sub("", text) == "", "unread text in the PrimList"
    out = []
    for kind, i, j in _PRIM.findall(text):
        (p, c0, _), (q, _, c1) = verts[int(i)], verts[int(j)]
        if kind == "L":
            out.append(("L", p, q))
        else:
            assert c0 is not None and c1 is not None, "a Bézier without its control points"
            out.append(("B", p, c0, c1, q))
    return out


def read(data: bytes) -> dict:
    """The project: its root, cut settings (index -> {key: value}) and shapes in file order,
    each (part name or "", element, primitives or ("E", centre, rx, ry, xform))."""
    root = etree.fromstring(data, etree.XMLParser(remove_comments=False))
    assert root.tag == "LightBurnProject"
    settings = {}
    for cs in root.findall("CutSetting"):
        v = {c.tag: c.get("Value") for c in cs}
        settings[int(v["index"])] = dict(v, type=cs.get("type"))
    shapes = []
    part = ""

    def shape(el, part):
        t = el.get("Type")
        if t == "Group":
            for ch in el.find("Children").findall("Shape"):
                shape(ch, part)
        elif t == "Path":
            shapes.append((part, el, _path(el)))
        elif t == "Ellipse":
            m = _xform(el)
            shapes.append((part, el, ("E", m((0.0, 0.0)), float(el.get("Rx")),
                                      float(el.get("Ry")), m)))
        else:
            raise AssertionError(f"unexpected shape {t}")
    for el in root:
        if isinstance(el, etree._Comment):
            got = re.match(r"\s*part (.*?)\s*$", el.text)
            part = got.group(1) if got else part
        elif el.tag == "Shape":
            shape(el, part if el.get("Type") == "Group" else "")
            part = ""
    return {"root": root, "settings": settings, "shapes": shapes}


def _bez(b, n=64) -> np.ndarray:
    t = np.linspace(0, 1, n + 1)[:, None]
    p0, p1, p2, p3 = (np.asarray(p) for p in b)
    return ((1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * p1 + 3 * (1 - t) * t * t * p2
            + t ** 3 * p3)


# ------------------------------------------------------------------ geometry
def _segment_distance(pts: np.ndarray, s) -> np.ndarray:
    """Exact distance of each point to segment ``s`` (lines, arcs, circles analytically;
    spline and ellipse pieces to a polyline of 4,000 points a span or 50,000 on the arc)."""
    if isinstance(s, Circle):
        return np.abs(np.hypot(*(pts - s.center).T) - s.radius)
    if isinstance(s, Arc):
        v = pts - s.center
        ang = np.arctan2(v[:, 1], v[:, 0])
        lo = s.start_angle if s.sweep > 0 else s.start_angle + s.sweep
        inside = np.mod(ang - lo + 1e-12, 2 * math.pi) <= abs(s.sweep) + 2e-12
        radial = np.abs(np.hypot(*v.T) - s.radius)
        ends = np.minimum(np.hypot(*(pts - s.start).T), np.hypot(*(pts - s.end).T))
        return np.where(inside, radial, ends)
    if isinstance(s, Line):
        a, b = np.asarray(s.start), np.asarray(s.end)
        ab = b - a
        t = np.clip(((pts - a) @ ab) / max(ab @ ab, 1e-300), 0, 1)
        return np.hypot(*(pts - (a + t[:, None] * ab)).T)
    if isinstance(s, Spline):
        dense = np.vstack([_bez(b, 4000) for b in s.spans])
    else:
        dense = np.array([s.at(s.start_param + s.sweep * i / 50000) for i in range(50001)])
    return _to_polyline(pts, dense)


def _to_polyline(pts: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Each point's distance to the polyline ``poly`` (its chords 0.002 mm or less here: off
    the curve by 1e-7 mm at most)."""
    a, b = poly[:-1], poly[1:]
    ab = b - a
    L2 = np.maximum((ab ** 2).sum(1), 1e-300)
    best = np.full(len(pts), np.inf)
    for i in range(len(pts)):
        t = np.clip(((pts[i] - a) * ab).sum(1) / L2, 0, 1)
        best[i] = np.hypot(*(pts[i] - (a + t[:, None] * ab)).T).min()
    return best


def _distance(pts, segments) -> np.ndarray:
    return np.min([_segment_distance(np.atleast_2d(pts), s) for s in segments], axis=0)


def _expected_order(cuts):
    """The documented file order: engraving outside every part, then each part (in the
    order of its first cut) with its shapes in plan order."""
    loose = [c for c in cuts if not c.part]
    parts = []
    for c in cuts:
        if c.part and c.operation.startswith("cut") and c.part not in parts:
            parts.append(c.part)
    parts += [c.part for c in cuts if c.part and c.part not in parts]
    parts = list(dict.fromkeys(parts))
    return loose + [c for p in parts for c in cuts if c.part == p]


def check_lbrn2(out, data: bytes, machine=None) -> dict:
    """Re-read ``data`` (the project of output ``out``) and check it against the design and
    the machine profile; returns counts and the largest arc error."""
    machine = machine or DEFAULTS["laser"]
    doc = read(data)
    root = doc["root"]
    assert root.get("FormatVersion") == "1" and root.get("AppVersion")
    cuts = plan(out)
    used = [op for op in OPS if any(c.operation == op for c in cuts)]
    # the layers: one per operation used, named, with the profile's settings in mm/s
    assert len(doc["settings"]) == len(used)
    by_name = {v["name"]: (i, v) for i, v in doc["settings"].items()}
    layer_op = {}
    prio = []
    for op in used:
        i, v = by_name[op.replace("_", " ")]
        assert 0 <= i <= 29 and v["type"] == "Cut"
        o = machine.operation(op)
        assert float(v["speed"]) * 60 == pytest.approx(o.speed, abs=1e-6)      # mm/s in file
        assert float(v["maxPower"]) == pytest.approx(o.power)
        assert int(v["numPasses"]) == o.passes
        layer_op[i] = op
        prio.append(int(v["priority"]))
    assert prio == sorted(prio)          # engrave, score, inner, outer: LightBurn's order
    # the shapes: one per cut, in the documented order, each on its operation's layer
    want = _expected_order(cuts)
    assert len(doc["shapes"]) == len(want)
    n_groups = len([e for e in root if e.tag == "Shape" and e.get("Type") == "Group"])
    assert n_groups == len({c.part for c in cuts if c.part})
    stats = {"arc_pieces": 0, "max_arc_error": 0.0, "ellipses": 0}
    for (part, el, prims), cut in zip(doc["shapes"], want):
        assert part == cut.part and layer_op[int(el.get("CutIndex"))] == cut.operation
        if prims[0] == "E":
            _, c, rx, ry, m = prims
            (s,) = cut.segments
            if isinstance(s, Circle):
                assert math.dist(c, s.center) <= EXACT and abs(rx - s.radius) <= EXACT \
                    and abs(ry - s.radius) <= EXACT
            else:                          # a whole ellipse: axes, centre, rotation
                assert isinstance(s, EllipticArc) and s.whole
                e = s.curve
                assert math.dist(c, e.center) <= EXACT
                assert (abs(rx - e.rx), abs(ry - e.ry)) <= (EXACT, EXACT)
                t = np.linspace(0, 2 * math.pi, 721)
                pts = np.array([m((rx * math.cos(a), ry * math.sin(a))) for a in t])
                assert _distance(pts, [s]).max() <= 1e-6     # the XForm's cos, sin: 1e-9
            stats["ellipses"] += 1
            continue
        # chained, closed where the design is, and as long as the design
        for a, b in zip(prims, prims[1:]):
            assert a[-1] == b[1]
        assert (prims[-1][-1] == prims[0][1]) == bool(cut.closed) or not cut.closed
        if cut.closed:
            assert prims[-1][-1] == prims[0][1]
        assert math.dist(prims[0][1], cut.start) <= EXACT
        length = 0.0
        # an ellipse is measured against 50,000 chords of it: 1e-7 mm
        exact = 2e-7 if any(isinstance(s, EllipticArc) for s in cut.segments) else EXACT
        for pr in prims:
            ends = np.array([pr[1], pr[-1]])
            assert _distance(ends, cut.segments).max() <= exact
            if pr[0] == "L":
                length += math.dist(pr[1], pr[2])
                pts = np.array([pr[1], pr[2], np.add(pr[1], pr[2]) / 2])
                assert _distance(pts, cut.segments).max() <= EXACT
                continue
            pts = _bez(pr[1:], 200)
            length += np.hypot(*np.diff(pts, axis=0).T).sum()
            d = _distance(pts, cut.segments)
            # an arc's Bézier within the stated bound; a spline's span is the curve itself
            assert d.max() <= BEZ + EXACT, (cut.part, d.max())
            if any(isinstance(s, (Arc, Circle)) for s in cut.segments):
                stats["arc_pieces"] += 1
                stats["max_arc_error"] = max(stats["max_arc_error"], float(d.max()))
        assert length == pytest.approx(sum(s.length for s in cut.segments), rel=1e-5)
    # inside each part: no cut after one around it (holes before the outline)
    for part in {c.part for c in cuts if c.part}:
        mine = [(prims, c) for (p, _, prims), c in zip(doc["shapes"], want)
                if p == part and c.operation.startswith("cut")]
        for i, (pi, ci) in enumerate(mine):
            for pj, cj in mine[:i]:
                assert not _encloses(pj, pi), f"{part}: {ci.operation} after {cj.operation}"
    return stats


def _outline(prims) -> np.ndarray:
    if prims[0] == "E":
        _, c, rx, ry, m = prims
        a = np.linspace(0, 2 * math.pi, 256)
        return np.array([m((rx * math.cos(t), ry * math.sin(t))) for t in a])
    return np.vstack([np.array([p[1], p[-1]]) if p[0] == "L" else _bez(p[1:], 16)
                      for p in prims])


def _encloses(outer, inner) -> bool:
    import shapely
    poly = _outline(outer)
    if len(poly) <= 2:
        return False
    ring = shapely.Polygon(poly)
    if not ring.is_valid:                  # a self-touching outline: its valid equivalent
        ring = shapely.make_valid(ring)
    return bool(ring.contains(shapely.Point(_outline(inner)[0])))


# ------------------------------------------------------------------ the examples
@pytest.mark.parametrize("name", ["laser_box", "gear", "name_tag"])
def test_examples_reread_equal_the_design(name):
    out = for_cutting(_compile(name).output, None)
    data = encode(out, ".lbrn2")
    stats = check_lbrn2(out, data)
    if name == "gear":
        # the teeth's arcs: Béziers measurably off the arc, and within the bound
        assert stats["arc_pieces"] > 40 and 1e-9 < stats["max_arc_error"] <= BEZ
        assert stats["ellipses"] == 5                # the gear's five round holes
    assert data.startswith(b'<?xml version="1.0" encoding="UTF-8"?>\n<LightBurnProject ')


def test_arc_beziers_meet_the_stated_bound_for_any_radius_and_sweep():
    """Every piece, sampled at 2,001 points, within BEZIER_TOL of its arc; the bound formula
    is at least the true error (it is twice it)."""
    for r in (0.05, 1.0, 12.5, 300.0, 5000.0):
        for sweep in (0.01, 1.0, math.pi / 2, math.pi, -4.0, 2 * math.pi):
            a = Arc((3.0, -7.0), r, 0.3, sweep)
            bs = beziers.arc_beziers(a, BEZ)
            assert math.dist(bs[0][0], a.start) == 0 and math.dist(bs[-1][3], a.end) == 0
            worst = 0.0
            for b in bs:
                p = _bez(b, 2000)
                worst = max(worst, np.abs(np.hypot(*(p - a.center).T) - r).max())
            assert worst <= BEZ
            phi = sweep / len(bs)
            assert worst <= beziers.arc_error(r, phi) + 1e-12 * max(1.0, r)   # rounding


def test_the_sheet_layout():
    pytest.importorskip("spyrrow")
    lay = _compile("laser_box").layout(sheet=(300.0, 200.0))
    for out, data in zip(lay._cut, lay.encode("lbrn2")):
        check_lbrn2(out, data)


def test_the_cli_and_the_api(tmp_path):
    import aidl_lang
    from aidl_lang.cli import main
    prog = ROOT / "examples" / "gear.aidl"
    dest = tmp_path / "g.lbrn2"
    assert main(["render", str(prog), "-o", str(dest)]) == 0
    res = aidl_lang.compile(path=str(prog))
    assert dest.read_bytes() == res.encode("lbrn2")
    check_lbrn2(for_cutting(res.output, None), dest.read_bytes())
    assert main(["render", str(ROOT / "examples" / "laser_box.aidl"), "--layout", "sheet",
                 "--sheet", "300x200mm", "-o", str(tmp_path / "sheet.lbrn2")]) == 0
    assert sorted(tmp_path.glob("sheet*.lbrn2"))


def test_serve_downloads_and_the_mcp_render_tool_write_it(tmp_path):
    from aidl_lang.pipeline import compile_source
    from aidl_lang.serve import app
    prog = ROOT / "examples" / "name_tag.aidl"
    c = compile_source(prog.read_text(), str(prog))
    assert app.TYPES["lbrn2"] == "application/x-lightburn"
    data = app.writers()["lbrn2"](c.drawing, "tag")
    check_lbrn2(for_cutting(_compile("name_tag").output, None), data)
    pytest.importorskip("mcp")
    from aidl_lang.mcp import server, tools as T
    assert ".lbrn2" in server.Output.__metadata__[0].description.split(", ")
    doc, _ = T.render(T.Workspace(tmp_path), source=prog.read_text(), output="tag.lbrn2")
    assert doc["ok"], doc
    check_lbrn2(for_cutting(_compile("name_tag").output, None),
                (tmp_path / "tag.lbrn2").read_bytes())


def test_the_machine_profile_sets_the_layers():
    out = for_cutting(_compile("name_tag").output, None)
    m = from_dict({"kind": "laser", "engrave": {"power": 15, "speed": 6000},
                   "cut_outer": {"power": 85, "speed": 300, "passes": 3},
                   "cut_inner": {"power": 70, "speed": 450, "passes": 1}})
    o = Options()
    o.machine = m                         # `--machine FILE` (Options.machine) when it lands
    data = encode(out, ".lbrn2", o)
    check_lbrn2(out, data, m)
    s = {v["name"]: v for v in read(data)["settings"].values()}
    assert s["engrave"]["speed"] == "100" and s["cut outer"]["numPasses"] == "3"


# ------------------------------------------------------------------ broken writers
def test_a_bezier_control_point_off_is_caught(monkeypatch):
    out = for_cutting(_compile("gear").output, None)
    real = beziers.unit_arc_beziers

    def off(start, sweep, n):
        bs = real(start, sweep, n)
        b = bs[len(bs) // 2]
        bs[len(bs) // 2] = (b[0], (b[1][0] * 1.002, b[1][1] * 1.002), b[2], b[3])
        return bs
    monkeypatch.setattr(beziers, "unit_arc_beziers", off)
    with pytest.raises(AssertionError):
        check_lbrn2(out, encode(out, ".lbrn2"))


def test_speeds_in_mm_per_minute_are_caught(monkeypatch):
    out = for_cutting(_compile("name_tag").output, None)
    monkeypatch.setattr(lightburn, "SPEED_DIVISOR", 1.0)
    with pytest.raises(AssertionError):
        check_lbrn2(out, encode(out, ".lbrn2"))


def test_outlines_before_holes_are_caught(monkeypatch):
    out = for_cutting(_compile("laser_box").output, None)
    from aidl_lang.output.fabrication import toolpath
    real = toolpath.plan
    monkeypatch.setattr(toolpath, "plan",
                        lambda o, *a: sorted(real(o, *a), key=lambda c: c.operation != "cut_outer"))
    bad = encode(out, ".lbrn2")
    monkeypatch.setattr(toolpath, "plan", real)
    with pytest.raises(AssertionError):
        check_lbrn2(out, bad)


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
    check_lbrn2(out, encode(out, ".lbrn2"))
