"""Filled engraved letters (issue 112): `Text(..., font=, fill=true)` in a drawing engraves the
letters' area: an SVG fill layer (re-read by svgelements), a solid DXF HATCH (ezdxf), a filled
PDF path (pdfplumber), a LightBurn Scan layer (xml), G-code line fill (gcodeparser); the area
each reader finds is the letters' area as a solid of the same Text has it (Manifold, another
path), and both are the area fontTools reads from the font itself (AreaPen).  Misuse is E0108 at `fill=`.  Also the rest of the issue: stencil letters along a
curve, `weight=` with a font, W0504 naming letters along a curve.  Deterministic; ~10 s CPU."""
from __future__ import annotations

import io
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import aidl_lang
from aidl_lang.geometry.shapes.curves import Loop

SIGN = """units mm
solid sign {{
    plate = RoundedRectangle(center=(0, 0), width=120, height=40, corner_radius=4)
    hole eye {{ c = Circle(center=(-52, 0), radius=2.5) }}
    drawing name {{
        t = Text("ROSA 8", position=(4, 0), size=15, font="sans:Bold", valign="middle"{extra})
    }}
}}
"""
# the same letters as material: their area by Manifold's union, the solid's way
LETTERS = """units mm
solid word {
    t = Text("ROSA 8", position=(4, 0), size=15, font="sans:Bold", valign="middle")
}
"""


def _compile(src: str):
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    return r


@pytest.fixture(scope="module")
def sign():
    return _compile(SIGN.format(extra=", fill=true"))


@pytest.fixture(scope="module")
def letters_area():
    r = _compile(LETTERS)
    return sum(lp.area for p in r.output.parts for lp in p.loops)


def _fills(r):
    return [st for st in r.output.engrave if st.style == "fill"]


def _shoelace(P) -> float:
    x, y = P[:, 0], P[:, 1]
    return 0.5 * float((x * np.roll(y, -1) - np.roll(x, -1) * y).sum())


def _inside(p, P) -> bool:
    x, y = P[:, 0], P[:, 1]
    x2, y2 = np.roll(x, -1), np.roll(y, -1)
    hit = (y > p[1]) != (y2 > p[1])
    xs = x[hit] + (p[1] - y[hit]) * (x2[hit] - x[hit]) / (y2[hit] - y[hit])
    return int((xs > p[0]).sum()) % 2 == 1


def _parity_area(polys) -> float:
    """The area of closed polygons filled by the even-odd rule (nested, not crossing): each
    polygon's area, added at an even depth and taken away at an odd one."""
    total = 0.0
    for i, P in enumerate(polys):
        depth = sum(_inside(P[0], Q) for j, Q in enumerate(polys) if j != i)
        total += abs(_shoelace(P)) * (-1) ** depth
    return total


def _off(Q, loops) -> float:
    """The largest distance (mm) of points ``Q`` from the closed polylines ``loops`` (each
    within 0.005 mm of its exact loop)."""
    A = np.vstack(loops)
    B = np.vstack([np.roll(P, -1, axis=0) for P in loops])
    AB = B - A
    L2 = np.maximum((AB ** 2).sum(1), 1e-30)
    best = np.full(len(Q), np.inf)
    for k in range(0, len(Q), 256):
        q = Q[k:k + 256, None, :]
        t = np.clip(((q - A) * AB).sum(2) / L2, 0, 1)
        d = np.hypot(*(A + t[..., None] * AB - q).transpose(2, 0, 1))
        best[k:k + 256] = d.min(1)
    return float(best.max())


@pytest.fixture(scope="module")
def font_area():
    """The letters' area (mm^2) as the font itself has it, read without our code: fontTools'
    AreaPen over each glyph of "ROSA8" in Noto Sans at its Bold instance (the variable font
    instanced at wght 700 by fontTools' instancer), scaled so that the cap height (OS/2
    sCapHeight) is the Text's size, 15 mm (docs/language.md: `size` is the cap height)."""
    from fontTools.pens.areaPen import AreaPen
    from fontTools.ttLib import TTFont
    from fontTools.varLib import instancer
    from aidl_lang.geometry.shapes.font import resolve
    face = resolve("sans:Bold")
    tt = TTFont(io.BytesIO(face.data) if face.data is not None else face.path,
                fontNumber=face.index)
    if "fvar" in tt:
        tt = instancer.instantiateVariableFont(tt, {"wght": 700})
    k = 15 / tt["OS/2"].sCapHeight
    glyphs, cmap = tt.getGlyphSet(), tt.getBestCmap()
    total = 0.0
    for ch in "ROSA8":
        pen = AreaPen(glyphs)
        glyphs[cmap[ord(ch)]].draw(pen)
        total += abs(pen.value)          # a glyph's contours signed: its counters subtracted
    return total * k * k


def test_the_letters_are_the_fonts_own_area(sign, letters_area, font_area):
    """The design's number, not our other output: the fill and the solid's letters each have
    the area fontTools reads from the font (522.448 mm^2; to 1e-4, the solid's union and the
    fill's loops are the outlines' curves)."""
    fill = sum(Loop(st.segments).area for st in _fills(sign))
    assert font_area == pytest.approx(522.448, abs=0.01)
    assert fill == pytest.approx(font_area, rel=1e-4)
    assert letters_area == pytest.approx(font_area, rel=1e-4)


def test_the_fill_is_the_letters_area(sign, letters_area):
    """The fill's loops are the letters' union: outer loops counter-clockwise, counters (R, O,
    A, 8) clockwise, their signed area the letters' area as a solid has it; the plate's cut
    and the eye are untouched, and no outline of the letters is engraved besides."""
    fills = _fills(sign)
    assert fills and all(st.closed for st in fills)
    holes = [st for st in fills if Loop(st.segments).area < 0]
    assert len(holes) == 5                           # R, O, A, and the two of the 8
    area = sum(Loop(st.segments).area for st in fills)
    assert area == pytest.approx(letters_area, rel=1e-6)
    assert 300 < area < 800
    assert [st.style for st in sign.output.engrave] == ["fill"] * len(fills)
    [plate] = sign.output.parts
    assert len(plate.loops) == 2


def test_svg_has_a_fill_layer_of_the_letters(sign, letters_area):
    """svgelements reads the laser SVG's `fill` group: one filled path (black, no stroke),
    whose subpaths enclose the letters' area (y flipped: the signed sum changes sign)."""
    import svgelements
    from aidl_lang.output.writers.svg import to_svg
    text = to_svg(sign.output, style="laser")
    root = ET.fromstring(text)
    ns = {"s": "http://www.w3.org/2000/svg"}
    [g] = [e for e in root.iter("{http://www.w3.org/2000/svg}g") if e.get("id") == "fill"]
    assert g.get("fill") == "#000000" and g.get("stroke") == "none"
    assert len(g.findall("s:path", ns)) == 1
    svg = svgelements.SVG.parse(io.StringIO(text), ppi=25.4)       # user units: mm
    paths = [e for e in svg.elements() if isinstance(e, svgelements.Path)
             and e.values.get("id") is None and str(e.fill) in ("#000000", "black")]
    assert len(paths) == 1
    polys = []
    for sub in paths[0].as_subpaths():
        sp = svgelements.Path(sub)
        n = 4000
        P = np.array([(q.x, q.y) for q in (sp.point(t) for t in np.linspace(0, 1, n,
                                                                          endpoint=False))])
        polys.append(P)
    assert len(polys) == len(_fills(sign))
    assert _parity_area(polys) == pytest.approx(letters_area, rel=2e-3)
    assert -sum(_shoelace(P) for P in polys) == pytest.approx(letters_area, rel=2e-3)


def test_dxf_hatch_holds_the_font_curves(sign, letters_area):
    """ezdxf re-reads one solid HATCH on layer FILL, one boundary path per loop, the curves as
    spline edges; the area it encloses (odd parity) is the letters' to 0.1 %, and every
    point of its boundary lies within 0.01 mm of the letters' exact outline."""
    import ezdxf
    from ezdxf import path as P
    from aidl_lang.output.writers.dxf import to_dxf
    doc = ezdxf.read(io.StringIO(to_dxf(sign.output)))
    [h] = doc.modelspace().query("HATCH")
    assert h.dxf.layer == "FILL" and h.dxf.solid_fill == 1
    assert len(h.paths) == len(_fills(sign))
    kinds = {type(e).__name__ for bp in h.paths for e in bp.edges}
    assert kinds == {"LineEdge", "SplineEdge"}
    polys = [np.array([(v.x, v.y) for v in P.from_hatch_edge_path(bp).flattening(0.0005)])
             for bp in h.paths]
    assert _parity_area(polys) == pytest.approx(letters_area, rel=1e-3)
    far = max(_off(Q, [Loop(st.segments).points() for st in _fills(sign)]) for Q in polys)
    assert far < 0.01
    assert not doc.modelspace().query("LWPOLYLINE[layer=='ENGRAVE']")


def test_pdf_fills_the_letters(sign):
    """pdfplumber finds the filled blue subpaths (no stroke), one per loop, together as wide
    and tall as the letters."""
    import pdfplumber
    from aidl_lang.output.writers.pdf import PT_PER_MM, to_pdf
    with pdfplumber.open(io.BytesIO(to_pdf(sign.output))) as pdf:
        page = pdf.pages[0]
        filled = [c for c in page.curves if c.get("fill") and not c.get("stroke")]
    assert len(filled) == len(_fills(sign))
    pts = np.vstack([Loop(st.segments).points() for st in _fills(sign)])
    w, hgt = np.ptp(pts[:, 0]), np.ptp(pts[:, 1])
    x0, x1 = min(c["x0"] for c in filled), max(c["x1"] for c in filled)
    top, bottom = min(c["top"] for c in filled), max(c["bottom"] for c in filled)
    assert (x1 - x0) / PT_PER_MM == pytest.approx(w, abs=0.05)
    assert (bottom - top) / PT_PER_MM == pytest.approx(hgt, abs=0.05)
    assert all(tuple(c["non_stroking_color"]) == (0, 0, 1) for c in filled)


def test_lightburn_scan_layer(sign):
    """The .lbrn2 (xml) has a CutSetting of type Scan (layer C00 "fill", the profile's line
    interval 0.1 mm, power 20 %), and one closed Path of that layer per loop of the letters."""
    from aidl_lang.output.writers.lightburn import to_lbrn2
    root = ET.fromstring(to_lbrn2(sign.output))
    scans = [c for c in root.iter("CutSetting") if c.get("type") == "Scan"]
    assert len(scans) == 1
    s = scans[0]
    assert s.find("index").get("Value") == "0" and s.find("name").get("Value") == "fill"
    assert float(s.find("interval").get("Value")) == 0.1
    assert float(s.find("maxPower").get("Value")) == 20
    shapes = [e for e in root.iter("Shape") if e.get("CutIndex") == "0"]
    assert len(shapes) == len(_fills(sign))
    assert all(e.find("PrimList").text.endswith(" 0") for e in shapes)     # closed
    assert {c.get("type") for c in root.iter("CutSetting")} == {"Scan", "Cut"}


def test_gcode_line_fill_covers_the_area(sign, letters_area):
    """gcodeparser reads the laser's fill: horizontal G1 lines at the fill's power and feed,
    rows 0.1 mm apart, run to and fro; their total length times the interval is the letters'
    area (to 1 %); every line lies inside the letters' outline (its middle, by parity)."""
    from gcodeparser import parse_gcode_lines
    from aidl_lang.output.writers import gcode
    text = gcode.job(sign.output).text
    assert "; fill: 20 % power, F6000, 1 pass, lines 0.1 mm apart" in text
    lines = parse_gcode_lines(text)
    x = y = None
    s_now, f_now = 0.0, None
    fills = []
    for ln in lines:
        p = ln.params
        s_now = p.get("S", s_now)
        f_now = p.get("F", f_now)
        nx, ny = p.get("X", x), p.get("Y", y)
        if ln.command == ("G", 1) and ("X" in p or "Y" in p) and f_now == 6000 and s_now > 0:
            fills.append(((x, y), (nx, ny)))
        x, y = nx, ny
    assert len(fills) > 100
    assert all(abs(a[1] - b[1]) < 1e-9 for a, b in fills)               # horizontal
    rows = sorted({round(a[1], 6) for a, _ in fills})
    assert np.allclose(np.diff(rows), 0.1, atol=1e-6)
    total = sum(abs(b[0] - a[0]) for a, b in fills)
    assert total * 0.1 == pytest.approx(letters_area, rel=0.01)
    dirs = {}
    for a, b in fills:
        dirs.setdefault(round(a[1], 6), set()).add(b[0] > a[0])
    assert {tuple(v) for v in dirs.values()} >= {(True,), (False,)}      # to and fro
    # letter by letter (each outer loop with its counters), not row by row across the word:
    # the head's moves between fill lines are a fraction of their length (row by row across
    # "ROSA 8" they were longer than the lines: 5,709 mm to 5,224 mm)
    hops = sum(math.dist(b, c) for (_, b), (c, _) in zip(fills, fills[1:]))
    assert hops < 0.5 * total
    polys = [Loop(st.segments).points() for st in _fills(sign)]
    for a, b in fills[::25]:
        mid = ((a[0] + b[0]) / 2, a[1])
        assert sum(_inside(mid, P) for P in polys) % 2 == 1


def test_a_router_does_not_fill_it_says_so(sign):
    from aidl_lang.output.fabrication import machine as M
    from aidl_lang.output.part.part import OutputError
    from aidl_lang.output.writers import gcode
    with pytest.raises(OutputError, match="router does not fill `sign.name.t`.*leave out fill="):
        gcode.job(sign.output, M.default("router"))
    plotter = gcode.job(sign.output, M.default("plotter")).text
    assert "; fill: F3000, 1 pass, lines 0.5 mm apart" in plotter


def test_a_hole_in_the_drawing_hides_part_of_the_fill(letters_area):
    """A hole child of the drawing hides the fill where it covers it: the area left is the
    letters' less the hole's (the same cut as a solid of the letters with that hole)."""
    band = "hole behind {{ r = Rectangle(center=(4, 0), width=10, height=60) }}"
    r = _compile(SIGN.format(extra=", fill=true").replace(
        '"middle", fill=true)\n', '"middle", fill=true)\n        ' + band.replace("{{", "{")
        .replace("}}", "}") + "\n"))
    cut = _compile(LETTERS.replace("\n}\n", "\n    hole behind { r = Rectangle(center=(4, 0), "
                                           "width=10, height=60) }\n}\n"))
    want = sum(lp.area for p in cut.output.parts for lp in p.loops)
    got = sum(Loop(st.segments).area for st in _fills(r))
    assert want < letters_area - 20
    assert got == pytest.approx(want, rel=1e-6)
    assert "W0526" not in [d.code for d in r.diagnostics]


@pytest.mark.parametrize("where, extra, words", [
    ("solid", ', font="sans", fill=true', "material already"),
    ("hole", ', font="sans", fill=true', "openings already"),
    ("drawing", ", fill=true", "single-stroke engraving font"),
    ("hole", ', font="sans", stencil=true, fill=true', "exclude each other"),
])
def test_fill_misused_is_e0108_at_fill(where, extra, words):
    src = ("units mm\nsolid s {\n    p = Rectangle(center=(0, 0), width=60, height=20)\n"
           f"    {where} x {{ t = Text(\"AB\", position=(0, 0), size=10{extra}) }}\n}}\n")
    r = aidl_lang.compile(source=src)
    [e] = [d for d in r.diagnostics if d.severity == "error"]
    assert e.code == "E0108" and words in e.message
    line = src.splitlines()[e.span.line - 1]
    assert line[e.span.col - 1:].startswith("true")
    assert src.splitlines()[e.span.line - 1][:e.span.col].endswith("fill=t")


def test_a_misspelt_fill_is_named():
    r = aidl_lang.compile(source='units mm\nsolid s {\n p = Rectangle(center=(0, 0), width=60, '
                          'height=20)\n drawing d { t = Text("AB", position=(0, 0), size=10, '
                          'font="sans", fil=true) }\n}\n')
    [e] = [d for d in r.diagnostics if d.severity == "error"]
    assert e.code == "E0105" and "`fill`" in e.hint


def test_filled_letters_along_a_curve(letters_area):
    """A filled Text along a circle engraves the same letters' area (each glyph rigid)."""
    r = _compile("units mm\nsolid seal {\n    p = Circle(center=(0, 0), radius=60)\n"
                 "    drawing d {\n        c = Circle(center=(0, 0), radius=40, "
                 "construction=true)\n        t = Text(\"ROSA 8\", along=c, size=15, "
                 "font=\"sans:Bold\", fill=true)\n    }\n}\n")
    area = sum(Loop(st.segments).area for st in _fills(r))
    assert area == pytest.approx(letters_area, rel=1e-6)


def test_stencil_letters_along_a_curve_keep_the_plate_whole():
    """stencil=true along a circle: each counter (B, O, B, 8, 0) bridged with its glyph, the
    disc one piece of 11 loops, no W0504; without stencil=, W0504 names the counters."""
    src = ("units mm\nsolid s {{\n    p = Circle(center=(0, 0), radius=40)\n    hole h {{\n"
           "        c = Circle(center=(0, 0), radius=28, construction=true)\n"
           "        t = Text(\"BOB 80\", along=c, size=9, font=\"sans:Bold\"{extra})\n"
           "    }}\n}}\n")
    r = _compile(src.format(extra=", stencil=true"))
    assert "W0504" not in [d.code for d in r.diagnostics]
    [part] = r.output.parts
    assert sum(lp.area > 0 for lp in part.loops) == 1 and len(part.loops) == 11
    r = _compile(src.format(extra=""))
    [w] = [d for d in r.diagnostics if d.code == "W0504"]
    assert 'the counters of "B", "O", "8", "0"' in w.message


def test_w0504_names_letters_along_a_curve_and_a_ring_joins_them():
    src = ("units mm\nsolid s {\n    c = Circle(center=(0, 0), radius=30, construction=true)\n"
           "    t = Text(\"HAPPY\", along=c, size=10, font=\"sans\")\n}\n")
    r = _compile(src)
    [w] = [d for d in r.diagnostics if d.code == "W0504"]
    assert "5 separate pieces" in w.message
    for ch in "HAPY":
        assert f'("{ch}")' in w.message
    fix = w.hint.split("`")[1]
    assert fix.startswith("ring = Shell(Circle(center=c.center")
    r = _compile(src.replace("\n}\n", f"\n    {fix}\n}}\n"))
    assert "W0504" not in [d.code for d in r.diagnostics]
    [part] = r.output.parts
    assert sum(lp.area > 0 for lp in part.loops) == 1


def test_weight_with_a_font_says_to_choose_a_style():
    src = ('units mm\nsolid s {\n    p = Rectangle(center=(0, 0), width=60, height=20)\n'
           '    hole h { t = Text("AB", position=(0, 0), size=10, font="sans", stencil=true, '
           'weight=2) }\n}\n')
    r = aidl_lang.compile(source=src)
    [e] = [d for d in r.diagnostics if d.severity == "error"]
    assert e.code == "E0108" and '"sans:Bold"' in e.hint
    assert src.splitlines()[e.span.line - 1][:e.span.col].endswith("weight=2")


def test_hatch_lines_of_a_square_with_a_hole():
    """The line fill of a 10 mm square less a 4 mm square hole (non-zero winding) at 0.5 mm:
    20 rows centred (first at 0.25 mm), the rows through the hole in two spans each."""
    from aidl_lang.geometry.shapes.curves import Line
    from aidl_lang.output.fabrication.hatch import hatch_lines

    def sq(x0, y0, x1, y1, ccw=True):
        p = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        if not ccw:
            p = p[::-1]
        return [Line(p[i], p[(i + 1) % 4]) for i in range(4)]
    got = hatch_lines([sq(0, 0, 10, 10), sq(3, 3, 7, 7, ccw=False)], 0.5)
    ys = sorted({a[1] for a, _ in got})
    assert len(ys) == 20 and ys[0] == pytest.approx(0.25) and ys[-1] == pytest.approx(9.75)
    total = sum(abs(b[0] - a[0]) for a, b in got)
    assert total * 0.5 == pytest.approx(100 - 16)
    assert got[0] == ((0.0, 0.25), (10.0, 0.25)) and got[1][0][0] > got[1][1][0]
    assert not math.isnan(total)


def test_the_dxf_imported_again_keeps_the_letters_engraved(sign, tmp_path):
    """`aidl import` of the DXF reads the FILL layer (as `aidl render` writes it) as a
    drawing: the letters engraved on the plate, not parts of their own."""
    from aidl_lang.cli.main import main
    from aidl_lang.output.writers.dxf import to_dxf
    (tmp_path / "sign.dxf").write_text(to_dxf(sign.output))
    assert main(["import", str(tmp_path / "sign.dxf"), "-o", str(tmp_path / "back.aidl")]) == 0
    text = (tmp_path / "back.aidl").read_text()
    assert "drawing fill {" in text and "solid fill" not in text
    assert "countersinks" not in text
    r = aidl_lang.compile(path=str(tmp_path / "back.aidl"))
    assert r.ok and len(r.output.parts) == 1


def test_hpgl_cuts_the_letters_outlines(sign):
    """HPGL (a vinyl cutter's) cuts the filled letters' loops, one path each, re-read by
    ezhpgl and checked as every HPGL (tests/test_hpgl.py's check)."""
    from test_hpgl import check_hpgl
    from aidl_lang.output.writers.hpgl import to_hpgl
    from aidl_lang.output.fabrication.toolpath import plan
    cuts = plan(sign.output)
    assert sum(c.operation == "fill" and c.closed for c in cuts) == len(_fills(sign))
    check_hpgl(sign.output, to_hpgl(sign.output, None).encode())
