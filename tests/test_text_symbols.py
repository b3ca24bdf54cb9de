"""The symbols of dimensions (issue 71): DXF import decodes `%%c %%d %%p` to `Ø ° ±` (MTEXT's
`\\U+2300` to `⌀`), and the single-stroke font draws them (and `ø × µ`), so a drawing exactly
as meant ("Ø5", "45°", "±0.1") gets no W0105 (a missing glyph).  Strokes are read back from the
DXF writer's output with ezdxf."""
from __future__ import annotations

import io

import ezdxf
import pytest

import aidl_lang

SIZE = 10.0
SRC = ('drawing labels {\n'
       '    a = Text("Ø5 45° ±0.1", (0, 0), size=10, anchor="start")\n'
       '    b = Text("°", (0, -40), size=10, anchor="start")\n'
       '    c = Text("Ø", (0, -80), size=10, anchor="start")\n'
       '    d = Text("/", (0, -120), size=10, anchor="start")\n'
       '    e = Text("ø6 ⌀8 2×M3 5µm", (0, -160), size=10, anchor="start")\n'
       '}\n')


_LINES: list = []          # the fixture's LINE entities (one-segment strokes)


@pytest.fixture(scope="module")
def compiled():
    r = aidl_lang.compile(SRC)
    doc = ezdxf.read(io.StringIO(r.to_dxf()))
    msp = doc.modelspace()
    pts = [(float(x), float(y)) for e in msp.query("LWPOLYLINE[layer=='ENGRAVE']")
           for x, y in e.get_points("xy")]
    lines = [((float(e.dxf.start.x), float(e.dxf.start.y)), (float(e.dxf.end.x), float(e.dxf.end.y)))
             for e in msp.query("LINE[layer=='ENGRAVE']")]       # one-segment strokes (`/`)
    _LINES[:] = lines
    return r, pts + [p for seg in lines for p in seg]


def _band(pts, y0):
    """The points of the text whose baseline is at ``y0`` (texts are 40 mm apart)."""
    return [p for p in pts if y0 - 15 < p[1] < y0 + 15]


def test_dimension_symbols_compile_without_a_missing_glyph(compiled):
    r, pts = compiled
    assert r.ok and not r.diagnostics, [str(d) for d in r.diagnostics]   # no W0105 (nor other)
    for y0 in (0, -40, -80, -120, -160):
        assert _band(pts, y0), y0                                        # every text is drawn


def test_the_strokes_lie_in_the_texts_extent(compiled):
    r, pts = compiled
    vals = {v.name: v.mm for v in r.values}
    band = _band(pts, 0)
    xs, ys = [p[0] for p in band], [p[1] for p in band]
    # the extent the compiler measured (the drawing's box is that of its texts): strokes fill it
    x0, _, x1, _ = vals["labels.bbox"]
    assert min(xs) == pytest.approx(x0, abs=1e-9) and max(xs) <= x1 + 1e-9
    assert min(ys) >= -1e-9 and max(ys) == pytest.approx(SIZE, abs=1e-9)   # baseline .. cap
    assert max(xs) > 80                      # 11 characters of a 10 mm font, none left out


def test_the_degree_sign_sits_at_the_cap_height(compiled):
    _, pts = compiled
    ys = [p[1] + 40 for p in _band(pts, -40)]
    assert min(ys) > 0.55 * SIZE             # above the baseline, in the top half
    assert max(ys) == pytest.approx(SIZE, abs=1e-9)


def test_the_diameter_sign_is_a_slashed_o_wider_than_a_slash(compiled):
    """`Ø` is futural's `O` (a ring, as wide as the O) and a slash from its lower left corner
    to its upper right one; a slash alone (`/`) is one line and no ring."""
    _, pts = compiled
    band = _band(pts, -80)
    xs, ys = [p[0] for p in band], [p[1] + 80 for p in band]
    assert min(ys) == pytest.approx(0, abs=1e-9) and max(ys) == pytest.approx(SIZE, abs=1e-9)
    width = max(xs) - min(xs)
    assert width == pytest.approx(16 / 21 * SIZE, abs=1e-9)       # the O's 16 of a 21 cap
    slash = [s for s in _LINES if -90 < s[0][1] < -70]
    assert slash == [((min(xs), -80.0), (max(xs), -70.0))] or \
        slash == [((max(xs), -70.0), (min(xs), -80.0))], slash
    # the ring: the O's stroke, a polyline of 21 points (the `/` is a lone line)
    assert [s for s in _LINES if -130 < min(s[0][1], s[1][1]) < -110]    # `/`
    assert sum(1 for p in band if p not in slash[0]) >= 20


def test_a_dxf_text_with_percent_codes_imports_without_a_missing_glyph(tmp_path):
    from aidl_lang.drawing.write.program import import_drawing
    doc = ezdxf.new("R2010")
    doc.units = 4
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (60, 0), (60, 30), (0, 30)], close=True)
    msp.add_text("%%c5 45%%d %%p0.1", height=4, dxfattribs={"insert": (5, 5)})
    msp.add_mtext("\\U+23008", dxfattribs={"insert": (5, 20), "char_height": 3,
                                          "attachment_point": 1})
    src = tmp_path / "t.dxf"
    doc.saveas(src)
    text, notes = import_drawing(src.read_bytes(), "t.dxf")
    assert not notes, notes
    assert 'Text("Ø5 45° ±0.1"' in text and 'Text("⌀8"' in text, text
    r = aidl_lang.compile(text, path=tmp_path / "t.aidl")
    assert r.ok, [str(d) for d in r.errors]
    assert not [d for d in r.diagnostics if d.code == "W0105"], [str(d) for d in r.diagnostics]


def test_engraved_symbols_read_back_as_text(tmp_path):
    """`aidl import` reads the strokes of the built-in font back as `Text` (docs/import.md):
    the symbols too; `⌀` is drawn as `Ø` is, so it reads back as `Ø` (the same strokes)."""
    from aidl_lang.drawing.infer import import_drawing
    r = aidl_lang.compile('drawing labels {\n    t = Text("MOTOR Ø5 45° ±0.1 2×M3 ⌀8", '
                          '(0, 0), size=10, anchor="start")\n}\n')
    text, notes = import_drawing(r.to_dxf().encode(), "x.dxf", infer=True)
    assert not notes and "Line(" not in text, text
    assert 'Text("MOTOR Ø5 45° ±0.1 2×M3 Ø8", position=(0, 0), size=10' in text, text
