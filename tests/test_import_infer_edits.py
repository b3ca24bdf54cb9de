"""`aidl import --infer` gives a program a person keeps (issue 71): role options infer as
without them, a pitch holds every instance to 1e-7 mm, holes on their own layer are the
part's holes, and the edits a maker makes through the params do what was meant (the maker
drawings of tests/maker_drawings.py; benchmarks/imports/infer_edits.py runs them all)."""
from __future__ import annotations

import ezdxf
import pytest

import aidl_lang
import dxf_compare
from aidl_lang.drawing.infer import import_drawing
from benchmarks.imports.infer_edits import run_one, same
from maker_drawings import front_panel


def _laser_plate(path) -> bytes:
    """A plate (black), four corner holes, a slit (blue: cut) and a stroke (green: engraved)."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (80, 0), (80, 50), (0, 50)], close=True, dxfattribs={"color": 7})
    for x in (5, 75):
        for y in (5, 45):
            m.add_circle((x, y), 1.5, dxfattribs={"color": 7})
    m.add_line((20, 25), (60, 25), dxfattribs={"color": 5})
    m.add_line((10, 10), (20, 10), dxfattribs={"color": 3})
    doc.saveas(path)
    return path.read_bytes()


@pytest.mark.parametrize("roles", [{"roles": "laser"}, {"cut": [7, 5], "engrave": 3}],
                         ids=["laser", "cut-engrave"])
def test_role_options_infer_as_without_them(tmp_path, roles):
    """`--infer --roles laser` (or --cut/--engrave) once wrote the plain import, its head
    claiming "recognised: 0 of 0 pieces": now the plate is a Rectangle with corner holes,
    the slit a through-cut, the stroke engraved, and the program renders as the plain
    import with the same roles (1e-7 mm) with no degree of freedom left."""
    data = _laser_plate(tmp_path / "l.dxf")
    text, notes = import_drawing(data, "l.dxf", infer=True, **roles)
    assert "# recognised: 8 of 8 pieces of outlines and holes in 5 shapes" in text, text
    assert "body = Rectangle(center=(width / 2, height / 2), width=width, height=height)" in text
    assert "hole corner_holes" in text and "cut cuts {" in text and "Polyline(" in text
    assert any("on a cut role written as through-cuts" in n.message for n in notes)
    out = []
    for infer in (False, True):
        t, _ = import_drawing(data, "l.dxf", infer=infer, **roles)
        res = aidl_lang.compile(t, path=tmp_path / f"l{infer}.aidl")
        assert res.ok, [str(d) for d in res.errors]
        out.append(tmp_path / f"l{infer}.dxf")
        out[-1].write_text(res.to_dxf())
    assert res.freedom()["dof"] == 0, res.freedom()["text"]
    dxf_compare.TOL = 1e-7
    left, extra = dxf_compare.unmatched(dxf_compare.curves(out[0]), dxf_compare.curves(out[1]))
    assert not left and not extra, (left[:3], extra[:3])


def test_a_pitch_holds_every_instance_to_1e_7(tmp_path):
    """The issue's row of 400 holes whose steps past the 200th are each 0.9e-7 mm longer:
    every step is within 1e-7 mm of the first, but the last hole is 1.8e-5 mm from where
    one pitch puts it.  Once one uniform `for i in range(400)`; now no pitch covers a hole
    it misses by more than 1e-7 mm (the rest listed), and the program renders exactly."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(-5, -5), (2010, -5), (2010, 5), (-5, 5)], close=True)
    x = 0.0
    for k in range(400):
        m.add_circle((x, 0), 1)
        x += 5 if k < 200 else 5 + 0.9e-7
    doc.saveas(tmp_path / "row.dxf")
    text, _ = import_drawing((tmp_path / "row.dxf").read_bytes(), "row.dxf", infer=True)
    assert "range(400)" not in text and "= 400" not in text
    assert "for c in [" in text             # the holes no pitch holds, listed
    res = aidl_lang.compile(text, path=tmp_path / "row.aidl")
    assert res.ok, [str(d) for d in res.errors]
    (tmp_path / "back.dxf").write_text(res.to_dxf())
    dxf_compare.TOL = 1e-7
    left, extra = dxf_compare.unmatched(dxf_compare.curves(tmp_path / "row.dxf"),
                                        dxf_compare.curves(tmp_path / "back.dxf"))
    assert not left and not extra, (left[:3], extra[:3])


def test_holes_on_their_own_layer_are_the_parts_holes(tmp_path):
    """A front panel as panel programs export it (OUTLINE and HOLES layers): once a solid of
    discs beside the plate (W0504); now one `plate` with a row of pot holes centred on it
    and corner holes, said in the head, no warning, exact.  A layer named otherwise (POCKET)
    stays a part of its own."""
    (tmp_path / "fp.dxf").write_bytes(front_panel())
    text, _ = import_drawing((tmp_path / "fp.dxf").read_bytes(), "fp.dxf", infer=True)
    assert "# holes: layer `HOLES` in `OUTLINE`" in text
    assert text.count("solid ") == 1 and "hole corner_holes" in text
    assert "Circle(center=(width / 2 + (i - (holes_n - 1) / 2) * holes_pitch, height / 2)" in text, text
    res = aidl_lang.compile(text, path=tmp_path / "fp.aidl")
    assert res.ok and not [d for d in res.diagnostics if d.severity == "warning"]
    (tmp_path / "back.dxf").write_text(res.to_dxf())
    assert same(tmp_path / "fp.dxf", tmp_path / "back.dxf", 1e-7)
    # a layer not named for holes (a pocket, a score line) is not made a through-hole: its
    # separate discs are parts of their own (two mirrored pairs named apart, issue 85)
    pocket = front_panel().replace(b"\nHOLES\n", b"\nPOCKET\n")
    text, _ = import_drawing(pocket, "fp.dxf", infer=True)
    assert "# holes:" not in text and "hole " not in text
    res = aidl_lang.compile(text, path=tmp_path / "pocket.aidl")
    assert res.ok and not [d for d in res.diagnostics if d.severity == "warning"], text


@pytest.mark.parametrize("name", ["nema17", "flange", "grille", "lcd_panel"])
def test_maker_edits_do_what_was_meant(tmp_path, name):
    """The key edits on four maker drawings: the plate's width (centred features stay
    centred, corner holes stay in the corners), the motor holes' spacing round their bore,
    a bolt circle's count, pcd and hole size, a hex grille's pitch (all rows as one), an LCD's
    screw spacing round its window; before: 4 of these 17 did what was meant."""
    exact, ok, n, failed = run_one(name, tmp_path)
    assert exact and ok == n, failed


def test_stroke_text_comes_back_as_text(tmp_path):
    """The name tag's engraved strokes (three texts, `l` and `I` one glyph in the font): three
    `Text(...)` with the words the example wrote, the rest of the drawing exact."""
    from pathlib import Path
    src = Path(__file__).resolve().parent.parent / "examples/name_tag.aidl"
    res = aidl_lang.compile(src.read_text(), path=src)
    (tmp_path / "nt.dxf").write_text(res.to_dxf())
    text, _ = import_drawing((tmp_path / "nt.dxf").read_bytes(), "nt.dxf", infer=True)
    for want in ("HELLO my name is", "ADA LOVELACE", "Analytical Engine Programmer"):
        assert f'Text("{want}", position=' in text, text
    assert "Polyline(" not in text and "Polygon(" not in text
    again = aidl_lang.compile(text, path=tmp_path / "nt.aidl")
    assert again.ok, [str(d) for d in again.errors]
    (tmp_path / "back.dxf").write_text(again.to_dxf())
    assert same(tmp_path / "nt.dxf", tmp_path / "back.dxf", 1e-7)


def test_a_slanted_row_has_its_pitch_and_count_as_params(tmp_path):
    """Five holes evenly along a slanted line: once `i * 12`, `i * 9` literals; now
    `polar(first, i * holes_pitch, angle)` on `holes_pitch = 15` and `holes_n = 5`, exact,
    and a new count adds holes along the same line."""
    src = """units mm
solid p {
    body = Rectangle(center=(50, 30), width=100, height=60)
    for i in range(5) { hole h { c = Circle(center=(10 + i * 12, 8 + i * 9), radius=2) } }
}
"""
    res = aidl_lang.compile(src, path=tmp_path / "s.aidl")
    (tmp_path / "s.dxf").write_text(res.to_dxf())
    text, _ = import_drawing((tmp_path / "s.dxf").read_bytes(), "s.dxf", infer=True)
    assert "param holes_pitch = 15 mm" in text and "for i in range(holes_n) {" in text, text
    again = aidl_lang.compile(text, path=tmp_path / "i.aidl", overrides={"holes_n": "6"})
    assert again.ok, [str(d) for d in again.errors]
    centres = sorted(round(c[1][0][0], 6) for c in _circles(again))
    assert centres == [10.0, 22.0, 34.0, 46.0, 58.0, 70.0]


def _circles(res) -> list:
    import tempfile
    from pathlib import Path
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "c.dxf"
        p.write_text(res.to_dxf())
        return [c for c in dxf_compare.curves(p) if c[0] == "C"]
