"""Text in a real font (issue 112): `Text(..., font=...)` draws the letters as the closed
outlines of the font (fontTools' outlines, HarfBuzz's shaping), material in a solid, openings
in a hole, engraved outlines in a drawing.  Through the real parser, solver and Manifold; the
SVG re-read by svgelements, the DXF by ezdxf, the STL by trimesh, and the DXF's curves
measured against the font's own outlines drawn by HarfBuzz (not fontTools, which the
compiler reads them with).  Deterministic; ~10 s CPU."""
from __future__ import annotations

import math
import shutil

import numpy as np
import pytest

import aidl_lang
from aidl_lang.cli.main import main


def _compile(src: str, path=None):
    r = aidl_lang.compile(source=src, path=str(path) if path else None)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    return r


def _codes(r) -> list[str]:
    return [d.code for d in r.diagnostics if d.severity != "note"]


def _loops(r):
    [part] = r.output.parts
    return [lp for lp in part.loops if lp.area > 0], [lp for lp in part.loops if lp.area < 0]


HAPPY = """units mm
solid word {
    t = Text("HAPPY", position=(0, 0), size=20, font="sans")
}
"""


def test_happy_in_a_solid_is_five_letters_of_eight_loops():
    """The issue's first done-when: five pieces (H, A, P, P, Y), eight loops (the counters of
    the A and the two Ps); W0504 names the letters of each piece and says how to join them."""
    r = _compile(HAPPY)
    outer, holes = _loops(r)
    assert (len(outer), len(holes)) == (5, 3)
    [w] = [d for d in r.diagnostics if d.code == "W0504"]
    assert "5 separate pieces" in w.message
    for ch in "HAPY":
        assert f'("{ch}")' in w.message
    assert "rail" in w.hint and "t.bb.width" in w.hint
    # the letters' curves are kept as curves (Bezier chains), not chords
    from aidl_lang.geometry.shapes.curves import Spline
    assert any(isinstance(s, Spline) for lp in holes for s in lp.segments)
    # size is the cap height: the H stands 20 mm tall on the baseline
    h = min(outer, key=lambda lp: lp.points()[:, 0].min())         # the leftmost letter
    ys = h.points()[:, 1]
    assert ys.min() == pytest.approx(0.0, abs=1e-9) and ys.max() == pytest.approx(20.0, abs=1e-9)


TOPPER = """units mm
thickness 3 mm
solid topper {
    word = Text("HAPPY 30", position=(0, 0), size=20, font="sans:Bold")
    rail = Rectangle(center=(word.center.x, -1 mm), width=word.bb.width, height=4 mm)
    stem = Rectangle(center=(0, -40), width=6, height=80)
}
"""


def test_cake_topper_is_one_piece(tmp_path):
    """"HAPPY 30" in bold, a rail as wide as the word (`word.bb.width`, the glyphs' true box)
    and a stem: one part in one piece, no warning (the windows between the A's legs and the
    rail are the font's); the rail is exactly as wide as the letters drawn; the STL, re-read
    by trimesh, is one watertight body of the part's area times its thickness."""
    import trimesh
    r = _compile(TOPPER)
    assert _codes(r) == []
    outer, holes = _loops(r)
    assert len(outer) == 1 and len(holes) >= 5
    [part] = r.output.parts
    P = np.vstack([lp.points() for lp in part.loops])
    word = r.values["topper.word.bb.width"] if "topper.word.bb.width" in r.values else None
    # the part's width is the word's (the rail is exactly as wide, centred on it)
    ink = P[P[:, 1] > 1.5]                     # above the rail: the letters alone
    assert P[:, 0].max() - P[:, 0].min() == pytest.approx(np.ptp(ink[:, 0]), abs=1e-3)
    if word is not None:
        assert float(word) == pytest.approx(np.ptp(P[:, 0]), abs=1e-6)
    p = tmp_path / "topper.aidl"
    p.write_text(TOPPER)
    assert main(["render", str(p), "-o", str(tmp_path / "topper.stl")]) == 0
    m = trimesh.load(str(tmp_path / "topper.stl"))
    assert m.is_watertight and len(m.split(only_watertight=False)) == 1
    area = sum(lp.area for lp in part.loops)
    assert m.volume == pytest.approx(3.0 * area, rel=2e-3)


def test_a_ttf_by_path_gives_the_same_loops(tmp_path):
    """The same word by the font file's path (beside the program) draws the same loops as by
    its family name; a font that is not installed is E0133, listing the families."""
    from aidl_lang.geometry.shapes import font as F
    face = F.resolve("sans")
    (tmp_path / "fonts").mkdir()
    shutil.copy(face.path, tmp_path / "fonts" / "Sans.ttf")
    by_name = _compile(HAPPY, tmp_path / "a.aidl")
    by_path = _compile(HAPPY.replace('"sans"', '"fonts/Sans.ttf"'), tmp_path / "a.aidl")
    a = sorted(by_name.output.parts[0].loops, key=lambda lp: (lp.points()[0][0], lp.area))
    b = sorted(by_path.output.parts[0].loops, key=lambda lp: (lp.points()[0][0], lp.area))
    assert len(a) == len(b) == 8
    for la, lb in zip(a, b):
        assert la.area == pytest.approx(lb.area, rel=1e-9)
        assert np.allclose(la.points(), lb.points(), atol=1e-9)
    r = aidl_lang.compile(source=HAPPY.replace('"sans"', '"Comic Sans"'))
    [e] = [d for d in r.diagnostics if d.code == "E0133"]
    assert "Comic Sans" in e.message and '"sans"' in e.hint and '"serif"' in e.hint
    r = aidl_lang.compile(source=HAPPY.replace('"sans"', '"../x.ttf"'), path=str(tmp_path / "a.aidl"))
    assert [d.code for d in r.diagnostics] == ["E0133"]


PLATE = """units mm
solid plate {{
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole letters {{
        t = Text("BOX", position=(0, 0), size=16, font="sans", valign="middle"{extra})
    }}
}}
"""


def test_an_o_cut_from_a_plate_is_warned_or_bridged():
    """Letters cut from a plate: the counters of B and O would fall out, W0504 names them and
    the fix (stencil=true); with stencil=true each counter is held by a bridge and the plate
    is one piece, its openings inside the letters."""
    r = _compile(PLATE.format(extra=""))
    [w] = [d for d in r.diagnostics if d.code == "W0504"]
    assert 'the counters of "B", "O"' in w.message and "stencil=true" in w.hint
    assert "X" not in w.message.split("counters of")[1]
    r = _compile(PLATE.format(extra=", stencil=true"))
    assert "W0504" not in _codes(r)
    outer, holes = _loops(r)
    assert len(outer) == 1
    # B: its two counters one above the other share one bridge band: 2 halves; O: 2; X: 1
    assert len(holes) == 2 + 2 + 1
    cut = -sum(lp.area for lp in holes)
    plain = _compile(PLATE.format(extra=""))
    o2, h2 = _loops(plain)
    letters = sum(lp.area for lp in o2[1:]) if len(o2) > 1 else 0.0
    whole = -sum(lp.area for lp in h2) - letters       # the letters' area, counters out
    assert 0.8 * whole < cut < whole                   # the bridges take a little


def test_max_width_is_honoured(tmp_path):
    """`Text("ROSEMARY", size=20, font="sans", max_width=60 mm)` engraves at most 60 mm wide
    (re-read from the SVG), at the size that makes it exactly 60 mm by the font's advances
    (the note W0113 says so); `t.size` is the size drawn."""
    import svgelements
    src = """units mm
solid tag {
    body = RoundedRectangle(center=(0, 0), width=90, height=30, corner_radius=3)
    drawing label {
        t = Text("ROSEMARY", position=(0, 0), size=20, font="sans", max_width=60 mm, valign="middle")
    }
}
"""
    p = tmp_path / "tag.aidl"
    p.write_text(src)
    r = _compile(src)
    assert [d.code for d in r.diagnostics] == ["W0113"]
    assert main(["render", str(p), "-o", str(tmp_path / "tag.svg")]) == 0
    svg = svgelements.SVG.parse(str(tmp_path / "tag.svg"), ppi=25.4)     # user units: mm
    boxes = [e.bbox() for e in svg.elements() if isinstance(e, svgelements.Path)]
    boxes = [b for b in boxes if b is not None and b[2] - b[0] < 85]      # not the tag's body
    assert len(boxes) >= 8                                 # R O S E M A R Y's outlines
    xs = [v for b in boxes for v in (b[0], b[2])]
    wide = max(xs) - min(xs)
    assert 58.0 < wide <= 60.0 + 1e-6           # the ink within the advances' 60 mm


def _hb_outline(text: str, size: float, path: str):
    """The font's outline of ``text`` at cap height ``size`` mm, drawn by HarfBuzz (shaping and
    glyph drawing): a dense point sample of its curves (mm, pen at 0 on the baseline)."""
    import uharfbuzz as hb
    blob = hb.Blob.from_file_path(path)
    font = hb.Font(hb.Face(blob))
    font.set_variations({"wght": 400.0})
    buf = hb.Buffer()
    buf.add_str(text)
    buf.guess_segment_properties()
    hb.shape(font, buf, {"kern": True, "liga": True})
    cap = font.get_glyph_extents(font.get_nominal_glyph(ord("H"))).y_bearing
    k = size / cap
    step = 0.002 / k                 # font units between samples: 0.002 mm
    pts = []

    def n_of(*ps):                   # samples for a piece of control polygon ps
        return max(2, int(sum(math.dist(a, b) for a, b in zip(ps, ps[1:])) / step) + 2)

    class Pen:
        def __init__(self, dx):
            self.dx, self.cur = dx, None

        def moveTo(self, p):
            self.cur = self.start = p

        def lineTo(self, p):
            a = self.cur
            for t in np.linspace(0, 1, n_of(a, p)):
                pts.append(((1 - t) * a[0] + t * p[0] + self.dx, (1 - t) * a[1] + t * p[1]))
            self.cur = p

        def qCurveTo(self, q, p):
            a = self.cur
            for t in np.linspace(0, 1, n_of(a, q, p)):
                s = 1 - t
                pts.append((s * s * a[0] + 2 * s * t * q[0] + t * t * p[0] + self.dx,
                            s * s * a[1] + 2 * s * t * q[1] + t * t * p[1]))
            self.cur = p

        def curveTo(self, c1, c2, p):
            a = self.cur
            for t in np.linspace(0, 1, n_of(a, c1, c2, p)):
                s = 1 - t
                pts.append((s ** 3 * a[0] + 3 * s * s * t * c1[0] + 3 * s * t * t * c2[0]
                            + t ** 3 * p[0] + self.dx,
                            s ** 3 * a[1] + 3 * s * s * t * c1[1] + 3 * s * t * t * c2[1]
                            + t ** 3 * p[1]))
            self.cur = p

        def closePath(self):
            if self.cur != self.start:
                self.lineTo(self.start)

    x = 0
    for info, pos in zip(buf.glyph_infos, buf.glyph_positions):
        font.draw_glyph_with_pen(info.codepoint, Pen(x + pos.x_offset))
        x += pos.x_advance
    return np.asarray(pts) * k


def test_dxf_curves_are_the_fonts_within_a_hundredth(tmp_path):
    """The letters' outlines in the DXF, re-read with ezdxf (SPLINEs evaluated by ezdxf, lines
    and polylines), lie within 0.01 mm of the font's curves as HarfBuzz draws them, and every
    stretch of the font's outline has DXF geometry within 0.01 mm (the letters do not overlap
    here, so the cut outline is the font's)."""
    import ezdxf
    from scipy.spatial import cKDTree
    from aidl_lang.geometry.shapes import font as F
    src = 'units mm\nsolid w {\n    t = Text("Go 30", position=(0, 0), size=20, font="sans", anchor="start")\n}\n'
    p = tmp_path / "w.aidl"
    p.write_text(src)
    assert main(["render", str(p), "-o", str(tmp_path / "w.dxf")]) == 0
    doc = ezdxf.readfile(str(tmp_path / "w.dxf"))
    got = []
    kinds = set()
    for e in doc.modelspace():
        kinds.add(e.dxftype())
        if e.dxftype() == "SPLINE":
            # ezdxf's chords (each within 0.0005 mm of the spline), sampled every 0.002 mm
            P = [(v.x, v.y) for v in e.construction_tool().flattening(0.0005, segments=16)]
            for a, b in zip(P, P[1:]):
                n = int(math.dist(a, b) / 0.002) + 2
                got += [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                        for t in np.linspace(0, 1, n)]
        elif e.dxftype() == "LINE":
            a, b = e.dxf.start, e.dxf.end
            n = int(math.dist((a.x, a.y), (b.x, b.y)) / 0.002) + 2
            got += [(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)) for t in np.linspace(0, 1, n)]
        elif e.dxftype() == "LWPOLYLINE":
            P = [tuple(v[:2]) for v in e.get_points()] + ([tuple(e.get_points()[0][:2])]
                                                           if e.closed else [])
            for a, b in zip(P, P[1:]):
                n = int(math.dist(a, b) / 0.002) + 2
                got += [(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
                        for t in np.linspace(0, 1, n)]
    assert "SPLINE" in kinds
    got = np.asarray(got)
    ref = _hb_outline("Go 30", 20.0, F.resolve("sans").path)
    ref[:, 0] += got[:, 0].min() - ref[:, 0].min()      # anchor="start": the ink's left edge
    d_got, _ = cKDTree(ref).query(got)
    d_ref, _ = cKDTree(got).query(ref)
    assert d_got.max() < 0.01
    assert d_ref.max() < 0.01


def test_anchor_valign_rotation_and_the_box():
    """`anchor`, `valign` and `rotation` place the outlines as they place the single-stroke
    font's; `.bb` is the glyphs' true box: asserts on it hold, and the drawn part is that box.
    "HI" with its ink's left end (start) and its cap line (top) at (10, 5), turned a quarter
    turn counter-clockwise: the cap line runs up x = 10, the baseline up x = 20."""
    src = """units mm
solid w {
    t = Text("HI", position=(10, 5), size=10, font="serif", anchor="start", valign="top", rotation=90 deg)
    assert t.bb.left == 10 mm
    assert t.bb.right == 20 mm
    assert t.bb.bottom == 5 mm
}
"""
    r = _compile(src)
    [part] = r.output.parts
    P = np.vstack([lp.points() for lp in part.loops])
    assert P[:, 0].min() == pytest.approx(10.0, abs=1e-9)
    assert P[:, 0].max() == pytest.approx(20.0, abs=1e-9)
    assert P[:, 1].min() == pytest.approx(5.0, abs=1e-9)
    top = r.values.get("w.t.bb.top") if hasattr(r.values, "get") else None
    if top is not None:
        assert float(top) == pytest.approx(P[:, 1].max(), abs=1e-6)


def test_turned_copies_keep_their_own_box():
    """A CircularPattern of a font Text: each turned copy's box is its own turned glyphs' (the
    letters W0504 names are found in every piece, not only the original's)."""
    src = """units mm
solid s {
    hub = Circle(center=(0, 0), radius=30)
    t = Text("HI", position=(0, 32), size=8, font="sans", valign="bottom")
    CircularPattern(t, count=4, center=(0, 0))
}
"""
    r = _compile(src)
    [w] = [d for d in r.diagnostics if d.code == "W0504"]
    assert "9 separate pieces" in w.message                  # the hub and 8 letters
    groups = w.message.split(": ", 1)[1].split("; ")[:6]
    assert all('("H")' in g or '("I")' in g for g in groups), groups
    outer, _ = _loops(r)
    boxes = [(lp.points()[:, 0].min(), lp.points()[:, 1].min()) for lp in outer]
    # the copy a quarter turn round: its letters lie left of the hub, x from -40 to -32
    assert any(abs(x + 40) < 1e-6 for x, _ in boxes)


def test_a_letter_thinner_than_the_wall_is_named():
    """Letters in a thin style at a small size: W0507 names the Text and the letter whose
    stroke is too thin, and its fix is a heavier style or a larger size (not `widen`)."""
    src = """units mm
solid s {
    t = Text("HELLO", position=(0, 0), size=6, font="sans:Thin")
    rail = Rectangle(center=(t.center.x, -0.5 mm), width=t.bb.width, height=1.5 mm)
}
"""
    r = _compile(src)
    walls = [d for d in r.diagnostics if d.code == "W0507"]
    assert walls and all("Text `s.t` (its \"" in d.message for d in walls)
    named = {d.message.split('(its "')[1][0] for d in walls}
    assert named <= set("HELO") and len(named) >= 2
    assert all("heavier" in d.hint and "sans:Bold" in d.hint for d in walls)


def test_text_in_a_font_along_a_circle():
    """`along=` lays a font's letters round a circle as it lays the single-stroke font's:
    each glyph upright on the circle, "AIDL" over the top on its baseline, "2026" read under
    it (flip=true, the letters' up toward the center); a text longer than the circle is
    W0111."""
    src = """units mm
solid seal {
    disc = Circle(center=(0, 0), radius=40)
    drawing marks {
        ring = Circle(center=(0, 0), radius=30, construction=true)
        top = Text("AIDL", along=ring, size=8, font="sans")
        bottom = Text("2026", along=ring, size=8, font="sans", flip=true, valign="top")
    }
}
"""
    r = _compile(src)
    assert _codes(r) == []
    by = {}
    for s in r.output.engrave:
        pts = np.vstack([np.asarray(Loop_points(s))])
        by.setdefault(s.source.rsplit(".", 1)[-1], []).append(pts)
    top, bottom = np.vstack(by["top"]), np.vstack(by["bottom"])
    rt, rb = np.hypot(*top.T), np.hypot(*bottom.T)
    assert rt.min() > 30 - 1e-6 and rt.max() < 38.3           # baseline on the circle, caps out
    # flip: up toward the center; valign="top" puts the cap line on the circle, the baseline
    # 8 mm out (as the single-stroke font lays it)
    assert rb.min() > 30 - 0.3 and rb.max() < 38 + 0.3
    assert top[:, 1].min() > 0 and bottom[:, 1].max() < 0     # over the top, under the bottom
    assert abs(top[:, 0].mean()) < 3 and abs(bottom[:, 0].mean()) < 3
    long = src.replace('"AIDL"', '"' + "AIDL " * 8 + '"')
    r = aidl_lang.compile(source=long)
    assert "W0111" in [d.code for d in r.diagnostics]


def Loop_points(stroke):
    """The points of an engraved stroke's exact segments (each sampled)."""
    from aidl_lang.geometry.shapes.curves import Loop
    return Loop(list(stroke.segments)).points()
