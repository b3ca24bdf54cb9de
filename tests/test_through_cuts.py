"""Through-cuts along open paths (issue 59, part A): the `cut` structure kind, real programs
through the real compiler, every file re-read by an independent reader.

The flex box of std/boxes.aidl (its living hinges are `cut`s of one Line per slit): the slits
the generator must draw are counted here from its own arithmetic (4 hinges, 15 columns 2 mm
apart over each corner's arc, 2 rows of 15 mm cuts and 3 mm bridges in a 44 mm wall, a
shifted column's end cuts reaching the wall's edges: 37 a hinge, 148 in all) and each must be
ONE pass along ONE line at cut power in the G-code (replayed from ``gcodeparser``'s reading:
a 0.5 mm rectangle would be two cutting moves along its long sides, neither from end to end
of the slit), ONE two-vertex path on the ``cut inner`` layer in the LightBurn project (read
with the standard library's XML parser), one pen-down line in HP-GL (ezhpgl, one plotter
unit), one ``LINE`` on the wall's cut layer in the DXF (ezdxf), a black line in the PDF
(pdfplumber).  A slit that runs from edge to edge frees the corner as a part of its own (both
outlines exact, no stroke left on the cut); three lines closing a triangle cut a hole; a
line, an arc and a polyline come out of the DXF to 1e-9 mm.  Each new message has its test:
E0125 wherever a cut cuts nothing, W0522, W0507 for a thin web, the kerf note; a `cut` in an
assembly is a sheet-level cut (W0525 where it crosses a part)."""
import io
import math
import re
import xml.etree.ElementTree as ET

import pytest

import aidl_lang
from aidl_lang.output import encode, for_cutting
from aidl_lang.output.fabrication.machine import from_dict

from conftest import ROOT

ezdxf = pytest.importorskip("ezdxf")

TOL = 1e-9
WALL = "round_box.box.wall"


def _compile(src: str, tmp_path, name="t.aidl"):
    p = tmp_path / name
    p.write_text(src)
    return aidl_lang.compile(path=str(p))


def _slits_expected():
    """The flex box's slits from the generator's arithmetic (std/plates.aidl, std/boxes.aidl)
    for examples/generators/flex_box.aidl: (length 120, width 80, height 50, radius 20, t 3)."""
    t, ro, ho = 3.0, 20.0, 50.0
    arc = math.pi * (ro - t / 2) / 2          # each hinge is as wide as the corner's arc
    hw = ho - 2 * t                           # the wall's height: the hinge's band
    pitch, cut, bridge = 2.0, 15.0, 3.0
    rows = max(1, math.floor((hw - bridge) / (cut + bridge)))
    cols = max(1, math.floor(arc / pitch) + 1)
    per = sum(rows if i % 2 == 0 else rows - 1 + 2 for i in range(cols))
    return 4 * per, hw


@pytest.fixture(scope="module")
def flex():
    res = aidl_lang.compile(path=str(ROOT / "examples" / "generators" / "flex_box.aidl"))
    assert res.ok and not res.diagnostics, [d.message for d in res.diagnostics]
    out = res.output
    return res, out, for_cutting(out)


def _slits(out):
    return [st.segments[0] for st in out.cuts]


def test_the_flex_box_cuts_every_slit_as_one_line(flex):
    _, out, cut = flex
    n, hw = _slits_expected()
    assert n == 148
    slits = _slits(out)
    assert len(out.cuts) == n and all(len(st.segments) == 1 for st in out.cuts)
    assert {type(s).__name__ for s in slits} == {"Line"}
    assert {st.part for st in out.cuts} == {WALL}
    # vertical, 15 mm long, or an end cut from the shifted column's inner end (half a
    # period's rows less half a cut from the middle) to the wall's edge: 22 - 10.5 mm
    lengths = sorted({round(math.dist(s.start, s.end), 9) for s in slits})
    assert lengths == pytest.approx([hw / 2 - (2 / 2 * 18 - 15 / 2), 15.0], abs=TOL)
    assert all(abs(s.start[0] - s.end[0]) <= TOL for s in slits)
    # zero width: the wall's outline is the strip alone, one loop, its area the strip's
    (wall,) = [p for p in out.parts if p.name == WALL]
    assert len(wall.loops) == 1 and len(wall.loops[0].segments) == 4
    # the kerf offsets the outline, never the slits
    assert [st.segments for st in cut.cuts] == [st.segments for st in out.cuts]


def test_the_flex_box_gcode_runs_each_slit_once_along_its_line(flex):
    gcodeparser = pytest.importorskip("gcodeparser")
    from test_gcode import replay
    _, out, cut = flex
    slits = _slits(out)
    wall_outline = [p for p in cut.parts if p.name == WALL][0].loops[0].segments
    for passes in (1, 2):
        m = from_dict({"cut_inner": {"passes": passes, "power": 90}})
        text = encode(cut, ".gcode", _opts(m)).decode()
        assert gcodeparser                                    # the replay reads with it
        moves = [mv for mv in replay(text) if mv.on]
        on_slit = {i: [] for i in range(len(slits))}
        for k, mv in enumerate(moves):
            for i, s in enumerate(slits):
                if _on(mv.p, s) and _on(mv.q, s):
                    on_slit[i].append((k, mv))
        for i, s in enumerate(slits):
            got = on_slit[i]
            # `passes` cutting moves, each one G1 from one end of the slit to the other
            assert len(got) == passes, (s, [(g.p, g.q) for _, g in got])
            for _, mv in got:
                assert mv.g == 1 and {_key(mv.p), _key(mv.q)} == {_key(s.start), _key(s.end)}
                assert mv.s == pytest.approx(0.9 * m.max_power)
        # every slit before the wall's outline (the part is still held while they are cut)
        last_slit = max(k for got in on_slit.values() for k, _ in got)
        first_outline = min(k for k, mv in enumerate(moves)
                            if any(_on(mv.p, sg) and _on(mv.q, sg) for sg in wall_outline))
        assert last_slit < first_outline


def test_the_flex_box_lightburn_holds_every_slit_as_one_line_on_the_cut_layer(flex):
    _, out, cut = flex
    root = ET.fromstring(encode(cut, ".lbrn2"))
    layers = {int(cs.find("index").get("Value")): cs.find("name").get("Value")
              for cs in root.iter("CutSetting")}
    inner = [i for i, name in layers.items() if name == "cut inner"]
    assert len(inner) == 1
    lines = []
    for sh in root.iter("Shape"):
        if sh.get("Type") != "Path" or int(sh.get("CutIndex")) != inner[0]:
            continue
        assert sh.find("XForm").text.split() == ["1", "0", "0", "1", "0", "0"]
        verts = [(float(x), float(y)) for x, y in
                 re.findall(r"V(-?[\d.]+) (-?[\d.]+)", sh.find("VertList").text)]
        prims = sh.find("PrimList").text
        if prims == "L0 1" and len(verts) == 2:
            lines.append((_key(verts[0]), _key(verts[1])))
    want = sorted(tuple(sorted((_key(s.start), _key(s.end)))) for s in _slits(out))
    assert sorted(tuple(sorted(ln)) for ln in lines) == want


def test_the_flex_box_dxf_hpgl_pdf_and_svg_carry_the_slits(flex):
    _, out, cut = flex
    slits = _slits(out)
    want = sorted(tuple(sorted((_key(s.start), _key(s.end)))) for s in slits)
    # DXF: one LINE per slit on the wall's cut layer, exact
    doc = ezdxf.read(io.StringIO(encode(cut, ".dxf").decode()))
    got = sorted(tuple(sorted((_key(e.dxf.start), _key(e.dxf.end))))
                 for e in doc.modelspace() if e.dxftype() == "LINE")
    assert got == want
    assert {e.dxf.layer for e in doc.modelspace() if e.dxftype() == "LINE"} == {f"CUT-{WALL}"}
    # HP-GL: one pen-down line per slit (ezhpgl, 40 units a mm, from the drawing's corner)
    ezhpgl = pytest.importorskip("ezhpgl")
    from aidl_lang.output.part.extent import extent
    x0, y0, _, _ = extent(cut)
    plot = ezhpgl.parse(encode(cut, ".plt"))
    paths: dict = {}
    for op in plot.pages[0].operations:
        paths.setdefault(op.path_id, []).append(op)
    twos = [[(q.x + x0, q.y + y0) for op in ops for q in op.geometry.points]
            for ops in paths.values()]
    twos = [p for p in twos if len(p) == 2]
    for s in slits:
        hits = [p for p in twos if {_near(p[0], s.start), _near(p[1], s.end)} == {True}
                or {_near(p[1], s.start), _near(p[0], s.end)} == {True}]
        assert len(hits) == 1, s                # the plotter profile: one pass
    # PDF: each slit a black line, end to end (pdfplumber; 1e-6 mm as the writer states)
    pdfplumber = pytest.importorskip("pdfplumber")
    with pdfplumber.open(io.BytesIO(encode(cut, ".pdf"))) as pdf:
        (pg,) = pdf.pages
        h, k = float(pg.height), 72 / 25.4
        segs = [(tuple(float(v) for v in o["stroking_color"]), o["pts"])
                for o in pg.objects.get("line", []) + pg.objects.get("curve", [])]
    bx0, by0, _, _ = extent(cut)
    ox, oy = bx0 - 10.0, by0 - 10.0 - 22.0           # the page's corner: margin, footer
    found = 0
    for s in slits:
        for colour, pts in segs:
            if len(pts) != 2 or colour not in ((0.0,), (0.0, 0.0, 0.0)):
                continue
            a, b = ((x / k + ox, (h - y) / k + oy) for x, y in pts)
            if {_near(a, s.start, 1e-6), _near(b, s.end, 1e-6)} == {True} or \
                    {_near(b, s.start, 1e-6), _near(a, s.end, 1e-6)} == {True}:
                found += 1
                break
    assert found == len(slits)
    # SVG: in the cut group, unfilled
    svg = ET.fromstring(encode(cut, ".svg"))
    ns = "{http://www.w3.org/2000/svg}"
    (group,) = [g for g in svg.iter(f"{ns}g") if g.get("id") == "cut"]
    through = [p for p in group.iter(f"{ns}path") if p.get("class") == "through-cut"]
    assert len(through) == len(slits) and {p.get("fill") for p in through} == {"none"}


PANEL = """
solid panel {
    body = Rectangle(center=(0, 0), width=60, height=30)
    cut slits {
        a = Line(start=(-20, 0), end=(20, 0))
        b = Line(start=(20, 15), end=(30, 5))
        tri = [Line((-20, 5), (-10, 5)), Line((-10, 5), (-15, 12)), Line((-15, 12), (-20, 5))]
    }
    Fixed(body)
}
"""


def test_a_slit_from_edge_to_edge_frees_the_corner_and_a_closed_chain_cuts_a_hole(tmp_path):
    res = _compile(PANEL, tmp_path)
    assert res.ok and not res.diagnostics, [d.message for d in res.diagnostics]
    out = res.output
    assert sorted(p.name for p in out.parts) == ["panel", "panel.piece1"]
    (corner,) = [p for p in out.parts if p.name == "panel.piece1"]
    (panel,) = [p for p in out.parts if p.name == "panel"]
    assert corner.area == pytest.approx(50.0, abs=1e-6)            # the 10 x 10 triangle
    # the panel less the corner and the triangle's hole (5 x ... 10 wide, 7 high: 35)
    assert panel.area == pytest.approx(1800.0 - 50.0 - 35.0, abs=1e-6)
    assert len(panel.loops) == 2 and sum(lp.is_hole for lp in panel.loops) == 1
    # re-read from the DXF: the corner's three vertices exact, the slit `a` one LINE, and no
    # stroke left along the separating cut or the triangle (they are outlines now)
    doc = ezdxf.read(io.StringIO(encode(out, ".dxf").decode()))
    msp = doc.modelspace()
    (piece,) = [e for e in msp if e.dxf.layer == "CUT-panel.piece1"]
    assert sorted(_key(p[:2]) for p in piece.get_points("xy")) == \
        sorted([_key((30, 5)), _key((30, 15)), _key((20, 15))])
    outline = max((e for e in msp if e.dxf.layer == "CUT-panel" and e.dxftype() == "LWPOLYLINE"),
                  key=lambda e: len(e))
    assert {_key((20, 15)), _key((30, 5))} <= {_key(p[:2]) for p in outline.get_points("xy")}
    lines = [e for e in msp if e.dxftype() == "LINE"]
    assert [(_key(e.dxf.start), _key(e.dxf.end)) for e in lines] == [(_key((-20, 0)),
                                                                      _key((20, 0)))]
    # `aidl check --describe` says what is cut along
    assert "through-cut: Line `panel.slits.a` from (-20, 0) to (20, 0), 40 mm" in res.describe()


def test_a_through_cut_is_exact_in_the_dxf(tmp_path):
    src = """
solid panel {
    body = Rectangle(center=(0, 0), width=80, height=60)
    cut c {
        l = Line(start=(-20.123456789, 1 / 3), end=(7 / 3, 17.5))
        a = Arc(center=(10, -10), radius=sqrt(2) * 5, start_angle=10 deg, end_angle=100 deg)
        p = Polyline([(-30, -20), (-25, -10 / 3), (-20, -20)])
    }
    Fixed(body)
}
"""
    res = _compile(src, tmp_path)
    assert res.ok and not res.diagnostics, [d.message for d in res.diagnostics]
    doc = ezdxf.read(io.StringIO(encode(res.output, ".dxf").decode()))
    msp = list(doc.modelspace())
    assert {e.dxf.layer for e in msp} == {"CUT"}
    (ln,) = [e for e in msp if e.dxftype() == "LINE"]
    assert tuple(ln.dxf.start)[:2] == pytest.approx((-20.123456789, 1 / 3), abs=TOL)
    assert tuple(ln.dxf.end)[:2] == pytest.approx((7 / 3, 17.5), abs=TOL)
    (arc,) = [e for e in msp if e.dxftype() == "ARC"]
    assert tuple(arc.dxf.center)[:2] == pytest.approx((10, -10), abs=TOL)
    assert arc.dxf.radius == pytest.approx(math.sqrt(2) * 5, abs=TOL)
    assert (arc.dxf.start_angle, arc.dxf.end_angle) == pytest.approx((10, 100), abs=1e-9)
    polys = [e for e in msp if e.dxftype() == "LWPOLYLINE" and not e.closed]
    (pl,) = polys
    assert [v for p in pl.get_points("xy") for v in p[:2]] == pytest.approx(
        [-30, -20, -25, -10 / 3, -20, -20], abs=TOL)
    # zero width: the part is the rectangle alone
    (part,) = res.output.parts
    assert part.area == pytest.approx(4800.0, abs=1e-9)


# ------------------------------------------------------------------ the messages
@pytest.mark.parametrize("src,where", [
    ("cut slits { l = Line(start=(0, 0), end=(10, 0)) }\n", "top level"),
    ("solid p {\n    r = Rectangle(center=(0, 0), width=40, height=20)\n"
     "    drawing d { cut s { l = Line(start=(0, 0), end=(10, 0)) } }\n}\n", "drawing `d`"),
    ("solid p {\n    r = Rectangle(center=(0, 0), width=40, height=20)\n"
     "    hole h { c = Circle(center=(0, 0), radius=3)\n"
     "        cut s { l = Line(start=(0, 0), end=(10, 0)) } }\n}\n", "hole `h`"),
    ("solid p {\n    r = Rectangle(center=(0, 0), width=40, height=20)\n"
     "    cut s { solid x { c = Circle(center=(0, 0), radius=3) } }\n}\n", "not a solid"),
])
def test_a_cut_where_it_cuts_nothing_is_e0125(tmp_path, src, where):
    res = _compile(src, tmp_path)
    errs = [d for d in res.diagnostics if d.severity == "error"]
    assert [d.code for d in errs] == ["E0125"], [d.message for d in res.diagnostics]
    assert where in errs[0].message and errs[0].hint and errs[0].span is not None


def test_text_in_a_cut_is_e0120_with_the_fix(tmp_path):
    res = _compile("solid p {\n    r = Rectangle(center=(0, 0), width=40, height=20)\n"
                   "    cut c { t = Text(\"A\", position=(0, 0), size=5) }\n}\n", tmp_path)
    (err,) = [d for d in res.diagnostics if d.severity == "error"]
    assert err.code == "E0120" and "not in cut `c`" in err.message
    assert "solid around the cut" in err.hint


def test_cut_stays_an_ordinary_name(tmp_path):
    src = """
def hinge(cut = 15 mm, y = 0 mm) -> cut { l = Line(start=(0, y), end=(cut, y)) }
solid panel {
    body = Rectangle(center=(0, 0), width=60, height=30)
    cut = 10 mm
    h = hinge(cut=cut)
    cut c = hinge(y=5 mm)
    Fixed(body)
}
"""
    res = _compile(src, tmp_path)
    assert res.ok and not res.diagnostics, [d.message for d in res.diagnostics]
    got = sorted(round(math.dist(st.segments[0].start, st.segments[0].end), 9)
                 for st in res.output.cuts)
    assert got == [10.0, 15.0]


def test_a_through_cut_off_the_material_is_w0522(tmp_path):
    src = PANEL.replace("b = Line(start=(20, 15), end=(30, 5))",
                        "b = Line(start=(40, 0), end=(50, 0))")
    res = _compile(src, tmp_path)
    ws = [d for d in res.diagnostics if d.code == "W0522"]
    assert len(ws) == 1 and "`panel.slits.b`" in ws[0].message and ws[0].span.line == 6, \
        [d.message for d in res.diagnostics]
    assert [d.code for d in res.diagnostics] == ["W0522"]
    # one of no length
    nil = _compile(PANEL.replace("b = Line(start=(20, 15), end=(30, 5))",
                                 "b = Line(start=(5, 5), end=(5, 5))"), tmp_path, "n.aidl")
    assert [d.message for d in nil.diagnostics] == [
        "through-cut `panel.slits.b` has no length: it cuts nothing"]
    # a closed curve of a cut off the material: the hole's W0502, naming the cut
    closed = _compile(PANEL.replace("b = Line(start=(20, 15), end=(30, 5))",
                                    "b = Circle(center=(50, 0), radius=3)"), tmp_path, "c.aidl")
    assert [d.message for d in closed.diagnostics] == [
        "cut `panel.slits` cuts nothing: it lies outside solid `panel`"]


def test_a_web_thinner_than_the_minimum_between_cuts_is_w0507(tmp_path):
    two = PANEL.replace("b = Line(start=(20, 15), end=(30, 5))",
                        "b = Line(start=(-20, {gap}), end=(20, {gap}))")
    res = _compile(two.replace("{gap}", "0.3"), tmp_path)
    ws = [d for d in res.diagnostics if d.code == "W0507"]
    assert len(ws) == 1 and "`panel.slits.a` and `panel.slits.b`" in ws[0].message, \
        [d.message for d in res.diagnostics]
    assert "min_wall" in ws[0].hint
    ok = _compile(two.replace("{gap}", "0.8"), tmp_path, "ok.aidl")    # 0.8 mm: no warning
    assert not ok.diagnostics, [d.message for d in ok.diagnostics]


def test_the_kerf_leaves_the_through_cuts_and_says_so(tmp_path, capsys):
    from aidl_lang.cli.main import main
    p = tmp_path / "p.aidl"
    p.write_text(PANEL)
    assert main(["render", str(p), "--kerf", "0.2mm", "-o", str(tmp_path / "p.dxf")]) == 0
    err = capsys.readouterr().out                  # stdout: no drawing is written there
    assert "note: the kerf offset leaves the 1 through-cut where it is drawn" in err
    doc = ezdxf.readfile(str(tmp_path / "p.dxf"))
    (ln,) = [e for e in doc.modelspace() if e.dxftype() == "LINE"]
    assert (tuple(ln.dxf.start)[:2], tuple(ln.dxf.end)[:2]) == ((-20, 0), (20, 0))


# ------------------------------------------------------------------ helpers
def _opts(machine):
    from aidl_lang.output.writers import Options
    return Options(machine=machine)


def _key(p):
    return (round(float(p[0]), 9), round(float(p[1]), 9))


def _near(p, q, tol=0.0125 + 1e-9):
    return math.dist(p, q) <= tol


def _on(p, line, tol=TOL) -> bool:
    """Point ``p`` on the segment ``line`` (an exact Line or Arc, by its ends and its
    distance)."""
    from aidl_lang.geometry.shapes.curves import Line
    if not isinstance(line, Line):
        return False
    (ax, ay), (bx, by) = line.start, line.end
    dx, dy = bx - ax, by - ay
    L2 = dx * dx + dy * dy
    u = ((p[0] - ax) * dx + (p[1] - ay) * dy) / L2 if L2 else 0.0
    if u < -1e-12 or u > 1 + 1e-12:
        return False
    return math.hypot(p[0] - ax - u * dx, p[1] - ay - u * dy) <= tol


# ------------------------------------------------------------------ sheet-level cuts
SHEET = """
assembly sheet {
    solid plate {
        r = Rectangle(center=(0, 0), width=60, height=40)
        hole h { c = Circle(center=(10, 0), radius=5) }
        Fixed(r)
    }
    cut scrap {
        a = Line(start=(40, -10), end=(40, 10))
        b = Arc(center=(50, 0), radius=5, start_angle=0 deg, end_angle=180 deg)
        c = Circle(center=(70, 0), radius=3)
        d = Line(start=(10, -5), end=(10, 5))
    }
    cut slits { e = Line(start=(-10, 0), end=(-20, 0)) }
}
"""


def test_a_cut_in_an_assembly_is_a_sheet_level_cut(tmp_path, capsys):
    """A `cut` directly in an assembly: every curve, open or closed, cut where it is drawn, in
    no part (a slot's rest off a plate's edge, scrap between parts: what `aidl import` writes).
    Off the material (beside the plate, inside its hole) it is said nothing; across the
    plate's material it is W0525 with the fix; the plate stays whole; `--layout sheet` leaves
    the sheet-level strokes out with a note."""
    from aidl_lang.cli.main import main
    res = _compile(SHEET, tmp_path)
    assert [(d.code, d.span.line) for d in res.diagnostics if d.severity != "info"] == \
        [("W0525", 14)], [d.message for d in res.diagnostics]
    (w,) = [d for d in res.diagnostics if d.code == "W0525"]
    assert "`sheet.slits.e`" in w.message and "`sheet.plate`" in w.message
    assert "move the curve into a `cut` inside solid `sheet.plate`" in w.hint
    (part,) = res.output.parts
    assert part.area == pytest.approx(2400 - 25 * math.pi, abs=1e-6)
    doc = ezdxf.read(io.StringIO(encode(for_cutting(res.output), ".dxf").decode()))
    got = sorted((e.dxftype(), e.dxf.layer.upper()[:3]) for e in doc.modelspace())
    assert got == sorted([("LWPOLYLINE", "CUT"), ("CIRCLE", "CUT"), ("CIRCLE", "CUT"),
                          ("LINE", "CUT"), ("LINE", "CUT"), ("LINE", "CUT"), ("ARC", "CUT")])
    (c3,) = [e for e in doc.modelspace() if e.dxftype() == "CIRCLE" and e.dxf.radius < 4]
    assert tuple(c3.dxf.center)[:2] == pytest.approx((70, 0), abs=TOL)
    assert c3.dxf.radius == pytest.approx(3, abs=TOL)
    (arc,) = [e for e in doc.modelspace() if e.dxftype() == "ARC"]
    assert (arc.dxf.start_angle, arc.dxf.end_angle) == pytest.approx((0, 180), abs=1e-9)
    f = tmp_path / "s.aidl"
    f.write_text(SHEET)
    pytest.importorskip("spyrrow")          # the nesting library is an extra
    assert main(["render", str(f), "--layout", "sheet", "-o", str(tmp_path / "s.dxf")]) == 0
    assert "note: 5 sheet-level cut strokes outside every part left out of the layout" \
        in capsys.readouterr().out
