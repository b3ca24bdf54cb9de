"""Drawings brought in (issue 39): DXF and SVG read as exact curves, `aidl import` writing a
program that renders back to the same curves (re-read with ezdxf, 1e-9 mm)."""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import ezdxf
import pytest

import aidl_lang

from dxf_compare import curves, unmatched

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.aidl"))
AIDL = [sys.executable, "-m", "aidl_lang.cli"]


def run(*args, cwd=None):
    return subprocess.run(AIDL + [str(a) for a in args], capture_output=True, text=True,
                          cwd=cwd, timeout=120)


@pytest.mark.parametrize("example", EXAMPLES, ids=lambda p: p.stem)
def test_round_trip_every_example(example, tmp_path):
    """render -> DXF -> import -> render: the same curves to 1e-9 mm (both DXFs re-read with
    ezdxf alone), on every example: the logo plate's SVG cubics and the violin's Spline with
    `corners=` come back as `Bezier` chains of their control points."""
    import aidl_lang
    from aidl_lang.drawing.write.program import import_drawing
    first, second = tmp_path / "a.dxf", tmp_path / "b.dxf"
    res = aidl_lang.compile(path=example)
    assert res.ok
    first.write_text(res.to_dxf())
    text, notes = import_drawing(first.read_bytes(), "a.dxf")
    again = aidl_lang.compile(text, path=tmp_path / "a.aidl")
    assert again.ok, [str(d) for d in again.errors]
    second.write_text(again.to_dxf())
    a, b = curves(first), curves(second)
    assert a, "the example drew nothing"
    left, extra = unmatched(a, b)
    assert not extra, extra[:3]
    assert not notes, notes
    assert not left, left[:3]


def test_cli_import_writes_a_program_that_checks(tmp_path):
    """`aidl import FILE.dxf -o part.aidl`, then `aidl check` and `aidl render` of it."""
    doc = _doc()
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0, 0), (40, 0, 0.4), (40, 20, 0), (0, 20, 0)], format="xyb",
                       close=True)
    msp.add_circle((10, 10), 3)
    doc.saveas(tmp_path / "plate.dxf")
    r = run("import", "plate.dxf", "-o", "plate.aidl", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "plate.aidl").read_text()
    assert "Arc(center=" in text and "hole hole" in text and "Circle(center=(10, 10), radius=3)" in text
    r = run("render", "plate.aidl", "-o", "back.dxf", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    left, extra = unmatched(curves(tmp_path / "plate.dxf"), curves(tmp_path / "back.dxf"))
    assert not left and not extra


def _doc():
    doc = ezdxf.new("R2010")
    doc.units = 4
    return doc


def test_bulges_splines_and_units(tmp_path):
    """An LWPOLYLINE with a bulge, a SPLINE and $INSUNITS = inches come in exactly."""
    from aidl_lang.drawing import read_drawing
    from aidl_lang.geometry.shapes.curves import Arc, Spline
    doc = ezdxf.new("R2010")
    doc.units = 1                               # inches
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0, 0), (2, 0, 1), (2, 2, 0), (0, 2, 0)], format="xyb", close=True)
    msp.add_open_spline([(5, 0), (6, 1), (7, -1), (8, 0)], degree=3)
    msp.add_circle((1, 1), 0.25)
    p = tmp_path / "d.dxf"
    doc.saveas(p)
    d = read_drawing(p.read_bytes(), "d.dxf")
    (o,) = d.outlines
    arcs = [s for s in o.segments if isinstance(s, Arc)]
    assert len(arcs) == 1
    # bulge 1 from (2, 0) to (2, 2) inches: a half circle of radius 1 in about (2, 1) in
    assert arcs[0].radius == pytest.approx(25.4, abs=1e-12)
    assert arcs[0].center == pytest.approx((50.8, 25.4), abs=1e-12)
    assert abs(arcs[0].sweep) == pytest.approx(3.141592653589793, abs=1e-12)
    (c,) = d.circles
    assert c.center == pytest.approx((25.4, 25.4), abs=1e-12) and c.radius == pytest.approx(6.35)
    (path,) = d.paths
    (s,) = path.segments
    assert isinstance(s, Spline)
    assert s.spans[0][1] == pytest.approx((6 * 25.4, 25.4), abs=1e-12)
    assert d.box() == pytest.approx((0, -0.5 * 25.4 + 0.0, 8 * 25.4, 2 * 25.4), abs=0.5 * 25.4)


# ------------------------------------------------------------------ Drawing2D in programs
BOARD = ROOT / "examples" / "parts" / "pcb_board.dxf"


def test_enclosure_holes_sit_on_the_board_holes(tmp_path):
    """examples/pcb_enclosure.aidl: every standoff hole of the lid's DXF is centred on a
    mounting hole of the board's DXF to 1e-9 mm, and the lid is the board outline + 3 mm."""
    import aidl_lang
    res = aidl_lang.compile(path=ROOT / "examples" / "pcb_enclosure.aidl")
    assert res.ok and not res.diagnostics, [str(d) for d in res.diagnostics]
    out = tmp_path / "lid.dxf"
    out.write_text(res.to_dxf())
    board = [e for e in ezdxf.readfile(BOARD).modelspace().query("CIRCLE")]
    lid = [e for e in ezdxf.readfile(out).modelspace().query("CIRCLE")]
    assert len(board) == len(lid) == 4
    for b in board:
        d = min(abs(complex(l.dxf.center.x, l.dxf.center.y) - complex(b.dxf.center.x, b.dxf.center.y)) for l in lid)
        assert d <= 1e-9
    assert all(l.dxf.radius == pytest.approx(1.7, abs=1e-12) for l in lid)
    ext = ezdxf.readfile(out).header
    x0, y0 = list(ext["$EXTMIN"])[:2]
    x1, y1 = list(ext["$EXTMAX"])[:2]
    # the board is 64 x 42 mm from (0, 0); the lid 3 mm more all round, the USB notch inside
    assert (x0, y0, x1, y1) == pytest.approx((-3, -3, 67, 45), abs=1e-9)


def _compile(tmp_path, src):
    import shutil
    import aidl_lang
    shutil.copyfile(BOARD, tmp_path / "board.dxf")
    shutil.copyfile(ROOT / "examples" / "parts" / "logo.svg", tmp_path / "logo.svg")
    return aidl_lang.compile(src, path=tmp_path / "main.aidl")


def test_drawing_moves_rigidly_with_its_constraints(tmp_path):
    res = _compile(tmp_path, """solid s {
    d = Drawing2D("board.dxf", layer="Edge.Cuts")
    d.bb.left == 30
    d.bb.bottom == -10
    assert d.bb.width == 64 mm
    assert d.circles[0].radius == 1.6 mm
    assert d.circles[0].center.x == 33.5 mm
}""")
    assert res.ok and not res.errors, [str(d) for d in res.diagnostics]
    out = tmp_path / "s.dxf"
    out.write_text(res.to_dxf())
    cs = sorted((round(c.dxf.center[0], 9), round(c.dxf.center[1], 9))
                for c in ezdxf.readfile(out).modelspace().query("CIRCLE"))
    assert cs == [(33.5, -6.5), (33.5, 28.5), (90.5, -6.5), (90.5, 28.5)]


def test_drawing_as_a_hole_and_turned(tmp_path):
    res = _compile(tmp_path, """solid s {
    body = Rectangle(center=(0, 0), width=160, height=160)
    Fixed(body)
    hole cut { d = Drawing2D("board.dxf", layer="Edge.Cuts", rotation=90 deg) }
    Fixed(cut.d.origin)
}""")
    assert res.ok, [str(d) for d in res.diagnostics]
    assert {d.code for d in res.diagnostics} == {"W0504"}     # the four islands
    out = tmp_path / "s.dxf"
    out.write_text(res.to_dxf())
    from aidl_lang.drawing import read_drawing
    d = read_drawing(out.read_bytes(), "s.dxf")
    # the plate, and the board's outline turned 90 degrees about the origin cut out of it
    # (the board's own holes are holes of the cut: material again, as islands)
    assert d.box() == pytest.approx((-80, -80, 80, 80), abs=1e-9)
    inner = d.outlines[1]
    from aidl_lang.drawing.model import _segs_box
    assert _segs_box(inner.segments) == pytest.approx((-42, 0, 0, 64), abs=1e-9)
    assert sorted((round(c.center[0], 9), round(c.center[1], 9)) for c in d.circles) == \
        [(-38.5, 3.5), (-38.5, 60.5), (-3.5, 3.5), (-3.5, 60.5)]


def test_svg_logo_keeps_its_cubics_and_units(tmp_path):
    """24 mm over a 240-unit viewBox: 0.1 mm per unit, y turned up; the path's C commands
    come out as DXF SPLINE pieces with the same control points."""
    res = _compile(tmp_path, """drawing s {
    d = Drawing2D("logo.svg", id="leaf")
    Fixed(d.origin)
}""")
    assert res.ok and not res.diagnostics, [str(x) for x in res.diagnostics]
    out = tmp_path / "s.dxf"
    out.write_text(res.to_dxf())
    ctrl = [[(round(p[0], 9), round(p[1], 9)) for p in e.control_points]
            for e in ezdxf.readfile(out).modelspace().query("SPLINE")]
    want = [(12.0, -2.0), (19.0, -6.0), (21.0, -15.0), (12.0, -22.0)]
    assert any(c == want or c == want[::-1] for c in ctrl), ctrl


def test_drawing_selects_by_colour_and_units_override(tmp_path):
    from aidl_lang.drawing import read_drawing
    doc = ezdxf.new("R2010")
    msp = doc.modelspace()
    msp.add_circle((0, 0), 1, dxfattribs={"color": 1})
    msp.add_circle((5, 0), 2, dxfattribs={"color": 3})
    p = tmp_path / "c.dxf"
    doc.saveas(p)
    d = read_drawing(p.read_bytes(), "c.dxf", color=3, unit="in")
    assert [(c.center, c.radius) for c in d.circles] == [((127.0, 0.0), 50.8)]


def test_cli_import_refuses_bad_input_and_writes_nothing(tmp_path):
    r = run("import", "nope.dxf", "-o", "x.aidl", cwd=tmp_path)
    assert r.returncode == 1 and "error[E0130]" in r.stderr and "nope.dxf" in r.stderr
    (tmp_path / "junk.dxf").write_bytes(b"\x00garbage")
    r = run("import", "junk.dxf", "-o", "x.aidl", cwd=tmp_path)
    assert r.returncode == 1 and "not a readable DXF" in r.stderr
    (tmp_path / "big.svg").write_bytes(b"<svg/>" + b" " * 20_000_001)
    r = run("import", "big.svg", "-o", "x.aidl", cwd=tmp_path)
    assert r.returncode == 1 and "larger than 20000000 bytes" in r.stderr
    assert not (tmp_path / "x.aidl").exists()


def test_too_many_entities_is_refused(tmp_path):
    """The reading's shape limit (``max_shapes``: MAX_ENTITIES, or `aidl import --budget`'s
    scaled one) refuses a DXF of more entities with a located E0130."""
    from aidl_lang.drawing import DrawingError, read_drawing
    doc = ezdxf.new("R2010")
    for i in range(30):
        doc.modelspace().add_line((i, 0), (i, 1))
    p = tmp_path / "many.dxf"
    doc.saveas(p)
    assert len(read_drawing(p.read_bytes(), "many.dxf", max_shapes=30).paths) == 30
    with pytest.raises(DrawingError) as e:
        read_drawing(p.read_bytes(), "many.dxf", max_shapes=20)
    assert e.value.code == "E0130" and "more than 20 entities" in e.value.message


def test_synonyms_name_the_drawing_form(tmp_path):
    res = _compile(tmp_path, 'solid s {\n    d = ImportDXF("board.dxf", layer="Edge.Cuts")\n'
                             '    Fixed(d.origin)\n}')
    assert res.ok and not res.diagnostics, [str(d) for d in res.diagnostics]


def test_svg_selects_by_inkscape_layer_and_colour(tmp_path):
    from aidl_lang.drawing import read_drawing
    svg = b"""<svg xmlns="http://www.w3.org/2000/svg"
     xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     width="100mm" height="50mm" viewBox="0 0 100 50">
  <g inkscape:label="Cut" id="layer1">
    <rect x="10" y="10" width="20" height="10" stroke="#ff0000" fill="none"/>
    <circle cx="50" cy="25" r="5" stroke="#0000ff" fill="none"/>
  </g>
  <g id="layer2"><path d="M 0 0 A 10 5 0 0 1 20 0" stroke="#ff0000" fill="none"/>
    <text x="1" y="1">hi</text></g>
</svg>"""
    d = read_drawing(svg, "a.svg", layer="Cut")
    assert len(d.outlines) == 1 and len(d.circles) == 1
    assert d.circles[0].center == pytest.approx((50, -25), abs=1e-12)
    assert d.outlines[0].area == pytest.approx(200, abs=1e-9)
    d = read_drawing(svg, "a.svg", layer="Cut", color="#0000ff")
    assert not d.outlines and len(d.circles) == 1
    d = read_drawing(svg, "a.svg")
    notes = sorted(n.message for n in d.notes)
    assert not notes and [t[0] for t in d.texts] == ["hi"]     # text is read (issue 59)
    (arc,) = [s for p in d.paths for s in p.segments if type(s).__name__ == "EllipticArc"]
    # A 10 5 0 0 1 20 0 from (0, 0): half the ellipse about (10, 0) with semi-axes 10 and 5,
    # through (10, -5) in the SVG (svgelements' point(0.5)); here y is up: through (10, 5)
    assert arc.curve.center == pytest.approx((10, 0), abs=1e-9)
    assert (arc.curve.rx, arc.curve.ry) == pytest.approx((10, 5), abs=1e-9)
    assert abs(arc.sweep) == pytest.approx(math.pi, abs=1e-9)
    assert arc.at(arc.start_param + arc.sweep / 2) == pytest.approx((10, 5), abs=1e-9)


def _elliptic_dxf(path):
    """A plate whose top is half an ellipse (a partial ELLIPSE closed by a line), an open
    elliptic arc on an engraving layer, and one turned and written with its extrusion down."""
    doc = _doc()
    msp = doc.modelspace()
    msp.add_ellipse((20, 10), major_axis=(20, 0), ratio=0.4, start_param=0, end_param=math.pi,
                    dxfattribs={"layer": "cut"})
    msp.add_line((0, 10), (40, 10), dxfattribs={"layer": "cut"})
    msp.add_ellipse((60, 5), major_axis=(6, 4), ratio=0.5, start_param=-1.0, end_param=2.0,
                    dxfattribs={"layer": "ENGRAVE"})
    e = msp.add_ellipse((-30, 5), major_axis=(5, -2), ratio=0.3, start_param=0.5,
                        end_param=4.0, dxfattribs={"layer": "ENGRAVE"})
    e.dxf.extrusion = (0, 0, -1)
    doc.saveas(path)


def test_dxf_elliptic_arcs_are_read_exactly_and_imported_back(tmp_path):
    """Partial ELLIPSE entities come in as exact elliptic arcs (ends to 1e-9 mm of ezdxf's
    own, the mirrored one too), and `aidl import` writes them as `Ellipse(..., start_angle=,
    end_angle=)`: rendered back, the same ELLIPSE arcs (re-read with ezdxf)."""
    from aidl_lang.drawing import read_drawing
    from aidl_lang.drawing.write.program import import_drawing
    src = tmp_path / "e.dxf"
    _elliptic_dxf(src)
    d = read_drawing(src.read_bytes(), "e.dxf")
    assert not d.notes
    arcs = [s for o in d.outlines for s in o.segments if type(s).__name__ == "EllipticArc"]
    arcs += [s for p in d.paths for s in p.segments if type(s).__name__ == "EllipticArc"]
    assert len(arcs) == 3
    want = []
    for e in ezdxf.readfile(str(src)).modelspace():
        if e.dxftype() == "ELLIPSE":
            ct = e.construction_tool()
            # world coordinates (an ELLIPSE's centre and axis are not in the OCS)
            pts = [tuple(v)[:2] for v in ct.vertices([e.dxf.start_param, e.dxf.end_param])]
            want.append(sorted(pts))
    got = [sorted([a.start, a.end]) for a in arcs]
    for w in want:
        assert any(all(math.dist(p, q) <= 1e-9 for p, q in zip(w, g)) for g in got), (w, got)
    (o,) = d.outlines
    assert o.area == pytest.approx(math.pi * 20 * 8 / 2, abs=1e-9)
    text, notes = import_drawing(src.read_bytes(), "e.dxf")
    assert not notes and text.count("start_angle=") == 3, text
    again = aidl_lang.compile(text, path=tmp_path / "e.aidl")
    assert again.ok, [str(x) for x in again.errors]
    out = tmp_path / "back.dxf"
    out.write_text(again.to_dxf())
    b = curves(out)
    assert sum(1 for c in b if c[0] == "E") == 3
    # the render of the imported program against the drawing's own curves
    left, extra = unmatched([c for c in curves(src)], b)
    assert not left and not extra, (left, extra)


def test_svg_elliptic_arc_round_trip(tmp_path):
    """An SVG path with an elliptical arc (rx != ry, turned) closed by a line: imported,
    rendered, the SVG re-read by svgelements gives the same arc (centre, radii, ends)."""
    import svgelements as se
    from aidl_lang.drawing.write.program import import_drawing
    svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="60mm" height="40mm" '
           'viewBox="0 0 60 40"><path d="M10,30 A25,10 20 0 1 50,25 Z" fill="none" '
           'stroke="black"/></svg>')
    text, notes = import_drawing(svg.encode(), "a.svg")
    assert not notes and "start_angle=" in text, text
    r = aidl_lang.compile(text, path=tmp_path / "a.aidl")
    assert r.ok, [str(x) for x in r.errors]
    orig = [s for s in se.Path("M10,30 A25,10 20 0 1 50,25 Z") if isinstance(s, se.Arc)][0]
    out = r.to_svg()
    import re
    (d,) = [m for m in re.findall(r'<path d="([^"]*)"', out) if "A" in m]
    back = [s for s in se.Path(d) if isinstance(s, se.Arc)]   # the writer halves an arc
    # the writer's y is -y_model and the reader's model y is -y_svg: the same SVG frame
    for arc in back:
        assert sorted([arc.rx, arc.ry]) == pytest.approx(sorted([orig.rx, orig.ry]), abs=1e-9)
        assert (arc.center.x, arc.center.y) == pytest.approx((orig.center.x, orig.center.y),
                                                             abs=1e-9)
    ends = {(round(p.x, 6), round(p.y, 6)) for a in back for p in (a.start, a.end)}
    assert (round(orig.start.x, 6), round(orig.start.y, 6)) in ends
    assert (round(orig.end.x, 6), round(orig.end.y, 6)) in ends
    # the way round: svgelements' middle of the original arc is on the written arcs
    mid = orig.point(0.5)
    assert min(math.dist((mid.x, mid.y), (q.x, q.y)) for a in back
               for q in (a.point(i / 200) for i in range(201))) < 0.05


def test_svg_ellipses_come_in_as_exact_ellipses_turned_by_their_transform(tmp_path):
    """A plain and a turned SVG `<ellipse>` are ELLIPSE entities in the DXF with the design's
    centre, semi-axes and turn (the turned one was read without its transform: 4 mm instead of
    15 mm, and both were polygons before the exact Ellipse)."""
    import math
    (tmp_path / "el.svg").write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm" '
        'viewBox="0 0 100 60"><rect x="0" y="0" width="100" height="60" fill="none" '
        'stroke="black"/><ellipse cx="30" cy="30" rx="20" ry="10" fill="none" stroke="black"/>'
        '<ellipse cx="75" cy="30" rx="8" ry="15" fill="none" stroke="black" '
        'transform="rotate(30 75 30)"/></svg>')
    (tmp_path / "el.aidl").write_text(
        'units mm\nsolid plate {\n    body = Drawing2D("el.svg")\n    Fixed(body.origin)\n}\n')
    r = run("render", "el.aidl", "-o", "el.dxf", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    got = []
    for e in ezdxf.readfile(tmp_path / "el.dxf").modelspace().query("ELLIPSE"):
        (cx, cy, _), (mx, my, _) = e.dxf.center, e.dxf.major_axis
        got.append((round(cx, 9), round(cy, 9), math.hypot(mx, my), e.dxf.ratio,
                    math.degrees(math.atan2(my, mx)) % 180))
    got.sort()
    assert len(got) == 2
    (x0, y0, a0, k0, t0), (x1, y1, a1, k1, t1) = got
    assert (x0, y0) == (30, -30) and abs(a0 - 20) < 1e-9 and abs(k0 - 0.5) < 1e-12 and t0 < 1e-9
    assert (x1, y1) == (75, -30) and abs(a1 - 15) < 1e-9 and abs(k1 - 8 / 15) < 1e-12
    assert abs(t1 - 60) < 1e-9                      # 90 deg turned 30 deg clockwise on screen


@pytest.mark.parametrize("sweep_deg", [90, 180, 200, 270, 359, -90, -200, -300])
def test_a_bulge_over_a_half_turn_keeps_its_centre(sweep_deg):
    """DXF bulge tan(sweep / 4) > 1 is an arc over 180 degrees, whose centre lies on the
    other side of the chord (read on the near side, the gear's bore came back as a small arc
    about the mirrored centre once the writer kept such arcs whole)."""
    import math

    from aidl_lang.drawing.read.dxf_entities import _bulge_arc
    c, r = (3.0, -2.0), 7.5
    a0 = math.radians(20)
    sweep = math.radians(sweep_deg)
    p = (c[0] + r * math.cos(a0), c[1] + r * math.sin(a0))
    q = (c[0] + r * math.cos(a0 + sweep), c[1] + r * math.sin(a0 + sweep))
    arc = _bulge_arc(p, q, math.tan(sweep / 4))
    assert math.dist(arc.center, c) < 1e-12 and abs(arc.radius - r) < 1e-12
    assert abs(arc.sweep - sweep) < 1e-12


def test_dxf_text_is_imported_as_text_engravings(tmp_path):
    """TEXT and MTEXT become `Text` engravings at the entity's insertion (or alignment) point,
    with its height as the cap height, its rotation and alignment; a layer of only text is a
    drawing.  Drawing2D engraves the same strokes on the part."""
    from aidl_lang.drawing import read_drawing
    from aidl_lang.drawing.write.program import import_drawing
    doc = _doc()
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (60, 0), (60, 30), (0, 30)], close=True)
    msp.add_text("R1", height=4, rotation=30, dxfattribs={"insert": (10, 10)})
    msp.add_text('say "hi"', height=3, dxfattribs={"insert": (1, 1), "halign": 1, "valign": 2,
                                                    "align_point": (30, 20)})
    msp.add_mtext("two\\Plines", dxfattribs={"insert": (5, 25), "char_height": 2,
                                             "attachment_point": 1})
    msp.add_text("LABEL", height=5, dxfattribs={"insert": (0, 40), "layer": "notes"})
    src = tmp_path / "t.dxf"
    doc.saveas(src)
    text, notes = import_drawing(src.read_bytes(), "t.dxf")
    assert not notes, notes
    assert 'Text("say \\"hi\\"", position=(30, 20), size=3, anchor="middle", valign="middle")' \
        in text, text
    assert "drawing notes {" in text
    r = aidl_lang.compile(text, path=tmp_path / "t.aidl")
    assert r.ok, [str(d) for d in r.errors]
    vals = {v.name: v.mm for v in r.values}
    t1 = next(k for k in vals if k.endswith("labels.t1.position"))
    assert vals[t1] == pytest.approx((10, 10), abs=1e-12)
    assert "size=4, anchor=\"start\", valign=\"baseline\", rotation=30 deg)" in text
    t4 = t1.replace("t1.position", "t4.position")          # MTEXT's second line, 5/3 h lower
    assert vals[t4] == pytest.approx((5, 25 - 5 / 3 * 2), abs=1e-12)
    assert any(k.endswith("notes.t1.position") and v == pytest.approx((0, 40)) for k, v in
               vals.items())
    # the engraving's strokes are there, turned: R1's box is not axis-aligned text's
    assert any(st.source.endswith("labels.t1") for st in r.output.engrave)
    # Drawing2D engraves the text on the part: the strokes of "R1", turned 30 degrees
    (tmp_path / "plate.aidl").write_text('units mm\nsolid plate {\n'
                                         '    d = Drawing2D("t.dxf", layer="0")\n}\n')
    r = aidl_lang.compile(path=tmp_path / "plate.aidl")
    assert r.ok and not r.diagnostics, [str(x) for x in r.diagnostics]
    strokes = [st for st in r.output.engrave if st.source == "plate.d"]
    from aidl_lang.geometry.shapes.text import text_strokes
    want = {(round(10 + a[0], 9), round(10 + a[1], 9)) for a, b in
            text_strokes("R1", 4, "start", "baseline", math.radians(30))}
    got = {(round(s.start[0], 9), round(s.start[1], 9)) for st in strokes
           for s in st.segments}
    assert want <= got


def test_import_writes_the_numbers_the_drawing_meant_not_float_noise():
    """A reader's float noise (a hole centre read as 43.99999999999999 mm, an end as
    25.000000000000004) is written as the decimal it stands for, within 1e-12 mm; a number
    that really has more digits keeps them."""
    from aidl_lang.drawing.write.program import _num
    assert _num(43.99999999999999) == "44"
    assert _num(25.000000000000004) == "25"
    assert _num(-1.7000000000000002) == "-1.7"
    assert _num(-3e-13) == "0"
    assert _num(1000000.0000000001) == "1000000.0000000001"     # 1e-10 from a decimal: kept
    assert float(_num(21.666666666666668)) == pytest.approx(21.666666666666668, abs=1e-12)
    doc = _doc()
    doc.modelspace().add_circle((0.1 + 0.2, 43.99999999999999), 1.7000000000000002)
    from aidl_lang.drawing.write.program import import_drawing
    buf = __import__("io").StringIO()
    doc.write(buf)
    text, _notes = import_drawing(buf.getvalue().encode(), "noise.dxf")
    assert "Circle(center=(0.3, 44), radius=1.7)" in text


# ------------------------------------------------------------------ islands of any curve
# Issue 83: an ELLIPSE island inside a round hole (a DXF ELLIPSE, an SVG <ellipse>) was
# written into the part, where the hole cut it away: the island's cut was lost.  Whole
# ellipses are now loops like outlines and circles, so an island is one whatever its curve.
PLATE = 100 * 60 - math.pi * 20 ** 2            # 100 x 60 plate, a hole of r 20 at (50, 30)


def _dxf_lines(dxf_text: str) -> list:
    """The curves of a DXF as polylines, by ezdxf alone: each entity flattened to within
    1e-5 mm (ezdxf's own flattening of each curve, a polyline's by its lines and arcs), a
    closed one closed exactly (a circle's end is 1e-15 off its start); shapely LineStrings."""
    import io

    import shapely
    lines = []
    for e in ezdxf.read(io.StringIO(dxf_text)).modelspace():
        for g in (e.virtual_entities() if e.dxftype() in ("LWPOLYLINE", "POLYLINE") else [e]):
            pts = [g.dxf.start, g.dxf.end] if g.dxftype() == "LINE" else \
                list(g.flattening(1e-5))
            if pts[0].isclose(pts[-1], abs_tol=1e-9):
                pts[-1] = pts[0]
            lines.append(shapely.LineString([(v.x, v.y) for v in pts]))
    return lines


def _even_odd_area(dxf_text: str) -> float:
    """The area (mm2) the DXF's curves (:func:`_dxf_lines`) enclose by the even-odd rule,
    found with ezdxf and shapely alone: the faces of their linework (shapely.polygonize),
    each counted when a ray from a point inside it crosses the linework an odd number of
    times."""
    import numpy as np
    import shapely
    lines = _dxf_lines(dxf_text)
    segs = np.array([s for ln in lines for s in zip(ln.coords[:-1], ln.coords[1:])])
    (x1, y1), (x2, y2) = segs[:, 0].T, segs[:, 1].T
    area = 0.0
    for face in shapely.polygonize(shapely.unary_union(lines).geoms).geoms:
        px, py = face.representative_point().coords[0]
        up = (y1 > py) != (y2 > py)
        xs = x1[up] + (py - y1[up]) * (x2[up] - x1[up]) / (y2[up] - y1[up])
        if np.count_nonzero(xs > px) % 2:
            area += face.area
    return area


def _island_dxf(kind: str):
    """A plate (closed LWPOLYLINE) with a round hole holding an island of ``kind``, written
    by ezdxf (mm); and the island's area, from its own numbers (a spline's: shapely of
    ezdxf's flattening of it)."""
    import io

    import shapely
    from ezdxf import path as epath
    doc = _doc()
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (100, 0), (100, 60), (0, 60)], close=True)
    msp.add_circle((50, 30), 20)
    if kind == "circle":
        msp.add_circle((50, 30), 8)
        isl = math.pi * 64
    elif kind == "ellipse":                                  # semi-axes 10 and 5, turned
        msp.add_ellipse((50, 30), major_axis=(8, 6), ratio=0.5)
        isl = math.pi * 50
    elif kind == "spline":
        e = msp.add_open_spline([(40, 25), (50, 18), (62, 25), (62, 36), (50, 42), (38, 36),
                                 (40, 25)])                # closed by its ends
        isl = shapely.Polygon([(v.x, v.y) for v in
                               epath.make_path(e).flattening(1e-6)]).area
    elif kind == "polyline":                                 # a hexagon, one side bulged
        pts = [(50 + 9 * math.cos(k * math.pi / 3), 30 + 9 * math.sin(k * math.pi / 3))
               for k in range(6)]
        msp.add_lwpolyline([(*p, 0.0) for p in pts], format="xyb", close=True)
        isl = 3 * math.sqrt(3) / 2 * 81
    else:                                                    # a stadium: two arcs, two lines
        msp.add_line((45, 26), (55, 26))
        msp.add_arc((55, 30), 4, -90, 90)
        msp.add_line((55, 34), (45, 34))
        msp.add_arc((45, 30), 4, 90, 270)
        isl = 10 * 8 + math.pi * 16
    s = io.StringIO()
    doc.write(s)
    return s.getvalue().encode(), isl


ISLAND_SVG = {
    "ellipse": ('<ellipse cx="50" cy="30" rx="10" ry="5" transform="rotate(30 50 30)"/>',
                math.pi * 50),
    "circle": ('<circle cx="50" cy="30" r="8"/>', math.pi * 64),
    "polygon": ('<polygon points="42,24 58,24 58,36 42,36"/>', 16 * 12),
    "arc path": ('<path d="M 45 26 H 55 A 4 4 0 0 1 55 34 H 45 A 4 4 0 0 1 45 26 Z"/>',
                 10 * 8 + math.pi * 16),
}


def _writers():
    from aidl_lang.drawing.infer import import_drawing as infer_import
    from aidl_lang.drawing.write.program import import_drawing
    return {"plain": lambda b, n: import_drawing(b, n),
            "parts": lambda b, n: import_drawing(b, n, parts=True),
            "infer": lambda b, n: infer_import(b, n, infer=True)}


@pytest.mark.parametrize("writer", ["plain", "parts", "infer"])
@pytest.mark.parametrize("kind", ["ellipse", "circle", "spline", "polyline", "arcs"])
def test_an_island_of_any_curve_in_a_round_hole_stays_an_island_dxf(kind, writer):
    """A plate with a round hole holding an island of each curve type (DXF, written by
    ezdxf): `aidl import` (plain, --parts, --infer) writes the island as a solid of its own,
    so the compiled part's area is plate - hole + island (exact formulas; Manifold's area
    to 1e-6 mm2, the program's DXF re-read by ezdxf and measured by shapely to 0.01 mm2);
    the ellipse comes back as one ELLIPSE of its semi-axes.  The ellipse island was written
    into the part and cut away by the hole (area 4743.36 of 4900.44)."""
    data, isl = _island_dxf(kind)
    text, notes = _writers()[writer](data, "plate.dxf")
    assert not notes, [n.message for n in notes]
    res = aidl_lang.compile(source=text, path="plate.aidl")
    assert res.ok, [str(d) for d in res.errors]
    want = PLATE + isl
    tol = 1e-6 if kind != "spline" else 1e-3
    assert abs(sum(p.area for p in res.output.parts) - want) <= tol, text
    dxf = res.encode("dxf").decode()
    assert abs(_even_odd_area(dxf) - want) <= 0.01
    if kind == "ellipse":
        import io
        (e,) = ezdxf.read(io.StringIO(dxf)).modelspace().query("ELLIPSE")
        assert e.dxf.center.isclose((50, 30, 0), abs_tol=1e-9)
        assert abs(e.dxf.major_axis.magnitude - 10) <= 1e-9 and abs(e.dxf.ratio - 0.5) <= 1e-9


@pytest.mark.parametrize("writer", ["plain", "parts", "infer"])
@pytest.mark.parametrize("kind", sorted(ISLAND_SVG))
def test_an_island_of_any_curve_in_a_round_hole_stays_an_island_svg(kind, writer):
    """The same plate drawn in SVG (a rect, a circle, and the island an <ellipse> turned 30
    degrees, a <circle>, a <polygon>, a path of arcs and lines): the island is kept."""
    shape, isl = ISLAND_SVG[kind]
    data = ('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm" '
            'viewBox="0 0 100 60"><rect x="0" y="0" width="100" height="60"/>'
            f'<circle cx="50" cy="30" r="20"/>{shape}</svg>').encode()
    text, notes = _writers()[writer](data, "plate.svg")
    assert not notes, [n.message for n in notes]
    res = aidl_lang.compile(source=text, path="plate.aidl")
    assert res.ok, [str(d) for d in res.errors]
    assert abs(sum(p.area for p in res.output.parts) - (PLATE + isl)) <= 1e-6, text
    dxf = res.encode("dxf").decode()
    assert abs(_even_odd_area(dxf) - (PLATE + isl)) <= 0.01
    if kind == "ellipse":
        import io
        (e,) = ezdxf.read(io.StringIO(dxf)).modelspace().query("ELLIPSE")
        assert abs(e.dxf.major_axis.magnitude - 10) <= 1e-9 and abs(e.dxf.ratio - 0.5) <= 1e-9
        # rotate(30) turns clockwise on the page (SVG's y axis points down): -30 degrees
        turn = math.degrees(math.atan2(e.dxf.major_axis.y, e.dxf.major_axis.x)) % 180
        assert abs(turn - 150) <= 1e-7, turn


@pytest.mark.parametrize("writer", ["plain", "parts", "infer"])
def test_holes_in_an_elliptical_plate_are_holes(writer):
    """An elliptical plate (ELLIPSE, semi-axes 40 and 25) with a round hole and a slot: the
    ellipse is a loop like any other, the part's outline, so they are its holes (the
    circle was written as material beside it: area 3141.59 + 0)."""
    import io
    doc = _doc()
    msp = doc.modelspace()
    msp.add_ellipse((0, 0), major_axis=(40, 0), ratio=25 / 40)
    msp.add_circle((-15, 0), 6)
    msp.add_lwpolyline([(5, -3), (25, -3), (25, 3), (5, 3)], close=True)
    s = io.StringIO()
    doc.write(s)
    text, notes = _writers()[writer](s.getvalue().encode(), "oval.dxf")
    assert not notes, [n.message for n in notes]
    res = aidl_lang.compile(source=text, path="oval.aidl")
    assert res.ok, [str(d) for d in res.errors]
    want = math.pi * 40 * 25 - math.pi * 36 - 20 * 6
    assert abs(sum(p.area for p in res.output.parts) - want) <= 1e-6, text
    assert abs(_even_odd_area(res.encode("dxf").decode()) - want) <= 0.01


def test_a_circle_and_an_ellipse_hole_drawn_overlapping_on_a_cut_role_cut_every_line():
    """Boxes.py's way with holes drawn overlapping (Planetary2), with an ellipse among them
    (laser roles): the two cut one opening (`AllowOverlap`, no W0508), and the pieces of
    each inside the other are the sheet-level cut, so the program's DXF (re-read by ezdxf)
    cuts every line drawn: the plate's 320 mm, the circle's and both ellipses' perimeters
    (numpy, 400,000 chords), to 1e-4 mm.  The ellipse was no loop there: W0508 on the
    design as drawn, and its 30.64 mm inside the circle and the circle's inside it not cut."""
    import numpy as np
    from aidl_lang.drawing.write.program import import_drawing
    svg = b"""<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm"
    viewBox="0 0 100 60"><g stroke="#000000" fill="none">
    <rect x="0" y="0" width="100" height="60"/><ellipse cx="40" cy="30" rx="15" ry="8"/>
    <circle cx="55" cy="30" r="8"/><ellipse cx="80" cy="30" rx="6" ry="20"/></g></svg>"""
    text, notes = import_drawing(svg, "l.svg", roles="laser")
    assert "AllowOverlap(hole2, hole3)" in text, text
    (n,) = notes
    assert n.message.startswith("2 pieces of holes of `l.svg` on a cut role drawn "
                                "overlapping lie inside another hole of their part (30.6433 mm)")
    res = aidl_lang.compile(source=text, path="l.aidl")
    assert res.ok and not res.diagnostics, [str(d) for d in res.diagnostics]

    def perimeter(a, b):
        t = np.linspace(0, 2 * np.pi, 400_001)
        return float(np.hypot(np.diff(a * np.cos(t)), np.diff(b * np.sin(t))).sum())
    want = 320 + 2 * math.pi * 8 + perimeter(15, 8) + perimeter(6, 20)
    got = sum(ln.length for ln in _dxf_lines(res.encode("dxf").decode()))
    assert abs(got - want) <= 1e-4, (got, want)
