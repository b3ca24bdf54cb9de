"""DXF reading of issue 49: blocks (scaled, turned, mirrored, nested, MINSERT arrays,
anonymous ``*U`` blocks) under a copy budget; planes (+Z read, -Z mirrored, tilted UCS
skipped and counted); formats (every DXF version R12..R2018, ASCII and binary; R12 POLYLINE
bulges and widths; 3D polylines in a plane parallel to XY; HATCH boundaries with islands);
bad numbers skipped and counted; ezdxf's own log lines as W0130 notes.

Every file is written at test time by ezdxf (a real CAD library, version printed by
``ezdxf.__version__``) with its own API; each test states the entity counts and the exact
geometry it must read (1e-9 mm), and the expected positions are computed here from the
DXF definitions (insert point, scale, rotation, grid), not by ezdxf."""
from __future__ import annotations

import io
import math
import os
import pathlib
import subprocess
import sys

import ezdxf
import pytest

from aidl_lang.drawing import DrawingError, read_drawing

ROOT = pathlib.Path(__file__).resolve().parent.parent
AIDL = [sys.executable, "-m", "aidl_lang.cli"]
ENV = {**os.environ, "PYTHONPATH": str(ROOT)}
TOL = 1e-9
VERSIONS = ["R12", "R2000", "R2004", "R2007", "R2010", "R2013", "R2018"]


def run(*args, cwd):
    return subprocess.run(AIDL + [str(a) for a in args], capture_output=True, text=True,
                          cwd=cwd, timeout=120, env=ENV)


def new(version="R2010"):
    doc = ezdxf.new(version)
    if version != "R12":
        doc.units = 4                      # mm
    return doc, doc.modelspace()


def save(doc, path, fmt="asc") -> bytes:
    doc.saveas(path, fmt=fmt)
    return pathlib.Path(path).read_bytes()


def text_of(doc) -> bytes:
    s = io.StringIO()
    doc.write(s)
    return s.getvalue().encode()


def close(p, q, tol=TOL) -> bool:
    return all(abs(a - b) <= tol for a, b in zip(p, q))


def place(p, at=(0, 0), s=(1, 1), rot=0.0):
    """The point ``p`` of a block placed at ``at``, scaled by ``s`` and turned by ``rot``
    degrees (DXF INSERT: scale, then rotate, then move)."""
    x, y = p[0] * s[0], p[1] * s[1]
    c, sn = math.cos(math.radians(rot)), math.sin(math.radians(rot))
    return (at[0] + c * x - sn * y, at[1] + sn * x + c * y)


def centres(d):
    return sorted((round(c.center[0], 9), round(c.center[1], 9)) for c in d.circles)


def match(got, want):
    got, want = sorted(got), sorted(want)
    assert len(got) == len(want), (got, want)
    for g, w in zip(got, want):
        assert close(g, w), (g, w)


# ------------------------------------------------------------------ blocks
def test_minsert_4_by_3_gives_all_12_holes_at_their_centres():
    """Before: 1 of 12 circles, no message."""
    doc, msp = new()
    doc.blocks.new("HOLE").add_circle((0, 0), 2)
    m = msp.add_blockref("HOLE", (10, 10), dxfattribs={"rotation": 30})
    m.grid(size=(4, 3), spacing=(25, 20))          # 4 rows 25 apart, 3 columns 20 apart
    msp.add_lwpolyline([(-100, -10), (100, -10), (100, 150), (-100, 150)], close=True)
    d = read_drawing(text_of(doc), "holes.dxf")
    assert len(d.circles) == 12 and all(c.radius == 2 for c in d.circles)
    want = [place((col * 20, row * 25), (10, 10), rot=30) for row in range(4)
            for col in range(3)]
    match([c.center for c in d.circles], want)
    assert not d.notes


def test_inserts_scaled_turned_mirrored_nested_and_anonymous():
    doc, msp = new()
    b = doc.blocks.new("B")
    b.add_circle((1, 0), 1)
    b.add_arc((0, 0), 3, 0, 90)
    a = doc.blocks.new("A")
    a.add_blockref("B", (10, 0), dxfattribs={"rotation": 90})
    msp.add_blockref("A", (100, 0), dxfattribs={"xscale": 2, "yscale": 2})     # nested
    msp.add_blockref("B", (0, 50), dxfattribs={"xscale": -1})                  # mirrored
    msp.add_blockref("B", (0, -50), dxfattribs={"xscale": 2, "yscale": 1, "rotation": 30})
    u = doc.blocks.new_anonymous_block()            # what an ARRAY command writes: *U1
    for i in range(3):
        u.add_blockref("B", (i * 20, 100))
    msp.add_blockref(u.name, (0, 0))
    assert u.name.startswith("*U")
    d = read_drawing(text_of(doc), "blocks.dxf")
    # circles: nested (A at 100,0 x2; B at 10,0 turned 90), mirrored, three of the *U array
    nested = place(place((1, 0), (10, 0), rot=90), (100, 0), (2, 2))
    match([c.center for c in d.circles],
          [nested, place((1, 0), (0, 50), (-1, 1))] + [(1 + 20 * i, 100) for i in range(3)])
    assert sorted(c.radius for c in d.circles) == [1, 1, 1, 1, 2]
    # the circle under a scale of (2, 1) turned 30 degrees: an exact ellipse
    (e,) = d.ellipses
    assert close(e[:2], place((1, 0), (0, -50), (2, 1), 30)) and close(e[2:4], (2, 1))
    assert abs(e[4] - math.radians(30)) <= 1e-12
    # the arcs: the mirrored one runs clockwise about (0, 50) from (0, 53) to (-3, 50)
    arcs = [p.segments[0] for p in d.paths if type(p.segments[0]).__name__ == "Arc"]
    (mir,) = [s for s in arcs if close(s.center, (0, 50))]
    assert close(mir.start, (-3, 50)) and close(mir.end, (0, 53)) and mir.radius == 3 \
        and abs(mir.sweep + math.pi / 2) <= 1e-12
    at = place(place((0, 0), (10, 0), rot=90), (100, 0), (2, 2))      # (120, 0)
    (big,) = [s for s in arcs if close(s.center, at)]
    assert abs(big.radius - 6) <= TOL
    ell = [p.segments[0] for p in d.paths if type(p.segments[0]).__name__ == "EllipticArc"]
    assert len(ell) == 1 and close(ell[0].curve.center, (0, -50)) \
        and close((ell[0].curve.rx, ell[0].curve.ry), (6, 3))
    assert not [n for n in d.notes if "skipped" in n.message]


def test_a_huge_array_is_a_located_e0304_naming_it(tmp_path):
    doc, msp = new()
    doc.blocks.new("HOLE").add_circle((0, 0), 2)
    m = msp.add_blockref("HOLE", (0, 0))
    m.grid(size=(10_000, 10_000), spacing=(5, 5))   # 10^8 copies
    save(doc, tmp_path / "array.dxf")
    with pytest.raises(DrawingError) as ex:
        read_drawing((tmp_path / "array.dxf").read_bytes(), "array.dxf")
    e = ex.value
    assert e.code == "E0304" and e.message.startswith(f"MINSERT (handle {m.dxf.handle}, line")
    assert "10000 x 10000 copies of block `HOLE`" in e.message and "100,000,000" in e.message
    text = (tmp_path / "array.dxf").read_text().splitlines()
    assert text[e.line - 1].strip() == "INSERT"
    r = run("import", "array.dxf", "-o", "a.aidl", cwd=tmp_path)
    assert r.returncode == 1 and r.stderr.startswith(f"array.dxf:{e.line}: error[E0304]"), \
        r.stderr
    assert not (tmp_path / "a.aidl").exists()
    (tmp_path / "p.aidl").write_text('units mm\nsolid s {\n    d = Drawing2D("array.dxf")\n}\n')
    r = run("check", "p.aidl", cwd=tmp_path)
    assert r.returncode == 1 and r.stderr.startswith("p.aidl:3:19: error[E0304]: MINSERT"), \
        r.stderr


def test_a_block_that_inserts_itself_is_e0304():
    doc, msp = new()
    a = doc.blocks.new("A")
    a.add_circle((0, 0), 1)
    a.add_blockref("A", (5, 0))
    a.add_blockref("A", (0, 5))
    msp.add_blockref("A", (0, 0))
    with pytest.raises(DrawingError) as ex:
        read_drawing(text_of(doc), "loop.dxf")
    assert ex.value.code == "E0304" and "inserts itself (`A` > `A`)" in ex.value.message


# ------------------------------------------------------------------ planes
def _tilted(tmp_path, with_circle: bool) -> str:
    doc = ezdxf.new("R12")
    msp = doc.modelspace()
    for i in range(30):        # a CAD program's tilted UCS: the normal (0, 0.6, 0.8)
        msp.add_polyline2d([(i, 0), (i + 10, 0), (i + 10, 10)], close=True,
                           dxfattribs={"extrusion": (0, 0.6, 0.8), "layer": "TILT"})
    if with_circle:
        msp.add_circle((0, 0), 5)
    doc.saveas(tmp_path / "tilt.dxf")
    return "tilt.dxf"


def test_tilted_entities_are_counted_by_type_and_layer(tmp_path):
    name = _tilted(tmp_path, True)
    d = read_drawing((tmp_path / name).read_bytes(), name)
    assert len(d.circles) == 1 and not d.outlines
    (n,) = [n for n in d.notes if "POLYLINE" in n.message]
    assert n.code == "W0130" and n.message == (
        "30 POLYLINE entities of `tilt.dxf` skipped (layer `TILT`): not in the drawing plane: "
        "the extrusion (normal) is not +Z or -Z (drawn in a tilted UCS)")


def test_an_import_of_only_tilted_entities_is_the_same_error_everywhere(tmp_path):
    """Before: `aidl import` exited 0 and wrote an empty program; Drawing2D said "nothing to
    import" without what it saw."""
    name = _tilted(tmp_path, False)
    r = run("import", name, "-o", "t.aidl", cwd=tmp_path)
    assert r.returncode == 1 and not (tmp_path / "t.aidl").exists(), r.stderr
    said = ("error[E0132]: nothing to import from `tilt.dxf`: it holds 30 POLYLINE (layer "
            "`TILT`), left out: 30 POLYLINE: not in the drawing plane")
    assert said in r.stderr, r.stderr
    (tmp_path / "p.aidl").write_text('units mm\nsolid s {\n    d = Drawing2D("tilt.dxf")\n}\n')
    r2 = run("check", "p.aidl", cwd=tmp_path)
    assert r2.returncode == 1 and said in r2.stderr, r2.stderr


def test_extrusion_down_is_read_mirrored_exactly():
    from ezdxf.math import OCS
    doc, msp = new()
    down = {"extrusion": (0, 0, -1)}
    msp.add_circle((3, 4), 2, dxfattribs=down)
    msp.add_arc((3, 4), 5, 0, 90, dxfattribs=down)
    msp.add_lwpolyline([(0, 0, 0), (10, 0, 1), (10, 10, 0)], format="xyb", dxfattribs=down)
    d = read_drawing(text_of(doc), "down.dxf")
    ocs = OCS((0, 0, -1))
    (c,) = d.circles
    w = ocs.to_wcs((3, 4, 0))
    assert close(c.center, (w.x, w.y)) and c.radius == 2
    arc = [p for p in d.paths if len(p.segments) == 1][0].segments[0]
    ends = {(round(w.x, 9), round(w.y, 9)) for w in (
        ocs.to_wcs((3 + 5 * math.cos(a), 4 + 5 * math.sin(a), 0)) for a in (0, math.pi / 2))}
    assert {tuple(round(v, 9) for v in arc.start), tuple(round(v, 9) for v in arc.end)} == ends
    poly = [p for p in d.paths if len(p.segments) == 2][0].segments
    # the bulge 1 (a half turn) from OCS (10, 0) to (10, 10): centre (10, 5), mirrored (-10, 5)
    assert close(poly[0].end, (-10, 0)) and close(poly[1].center, (-10, 5))
    assert abs(abs(poly[1].sweep) - math.pi) <= 1e-12


# ------------------------------------------------------------------ formats
def _reference(version):
    """LINE, CIRCLE, ARC and a POLYLINE/LWPOLYLINE with a bulge in every version; SPLINE,
    ELLIPSE and HATCH from R2000."""
    doc, msp = new(version)
    msp.add_line((0, 0), (50, 0))
    msp.add_circle((20, 20), 4)
    msp.add_arc((80, 10), 10, -90, 90)
    pts = [(0, 40, 0), (30, 40, 0.5), (30, 60, 0), (0, 60, 0)]
    if version == "R12":
        msp.add_polyline2d([(x, y, 0, 0, b) for x, y, b in pts], format="xyseb", close=True)
    else:
        msp.add_lwpolyline(pts, format="xyb", close=True)
        msp.add_ellipse((80, 80), (10, 0), 0.5)
        msp.add_open_spline([(0, 100), (10, 110), (20, 100), (30, 110)])
    return doc


@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("fmt", ["asc", "bin"])
def test_every_version_ascii_and_binary(tmp_path, version, fmt):
    """Before: every binary file was "not a readable DXF file"."""
    data = save(_reference(version), tmp_path / "ref.dxf", fmt)
    assert data.startswith(b"AutoCAD Binary DXF") == (fmt == "bin")
    d = read_drawing(data, "ref.dxf", unit="mm")
    (c,) = d.circles
    assert c.center == (20, 20) and c.radius == 4
    (o,) = d.outlines
    assert len(o.segments) == 4
    arc = [s for s in o.segments if type(s).__name__ == "Arc"][0]
    # bulge 0.5 from (30, 40) to (30, 60): sweep 4 atan(0.5), radius 10 / sin(2 atan 0.5)
    assert abs(arc.sweep - 4 * math.atan(0.5)) <= 1e-12
    assert abs(arc.radius - 10 / math.sin(2 * math.atan(0.5))) <= TOL
    kinds = sorted(type(p.segments[0]).__name__ for p in d.paths)
    assert kinds == (["Arc", "Line"] if version == "R12" else ["Arc", "Line", "Spline"])
    if version != "R12":
        assert d.ellipses == [(80.0, 80.0, 10.0, 5.0, 0.0)]
    if fmt == "bin":           # the same drawing as its ASCII twin, bit for bit
        a = read_drawing(save(_reference(version), tmp_path / "a.dxf"), "a.dxf", unit="mm")
        assert a.circles == d.circles and a.ellipses == d.ellipses
        assert [o.segments for o in a.outlines] == [o.segments for o in d.outlines]


def test_binary_dxf_through_aidl_import_and_drawing2d(tmp_path):
    save(_reference("R2018"), tmp_path / "bin.dxf", "bin")
    r = run("import", "bin.dxf", "-o", "b.aidl", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "Circle(center=(20, 20), radius=4)" in (tmp_path / "b.aidl").read_text()
    r = run("check", "b.aidl", cwd=tmp_path)
    assert r.returncode == 0, r.stderr


def test_r12_polyline_bulges_widths_and_flat_3d_polylines():
    doc = ezdxf.new("R12")
    msp = doc.modelspace()
    msp.add_polyline2d([(0, 0, 0.5, 0.5, 1), (20, 0, 0.5, 0.5, 0), (20, 20, 0.5, 0.5, 0)],
                       format="xyseb", close=True)
    msp.add_polyline3d([(40, 0, 5), (60, 0, 5), (60, 20, 5)], close=True)     # z = 5
    msp.add_polyline3d([(80, 0, 0), (90, 0, 5)])                               # tilted
    d = read_drawing(text_of(doc), "r12.dxf", unit="mm")
    assert len(d.outlines) == 2 and not d.paths
    bulged = [o for o in d.outlines if any(type(s).__name__ == "Arc" for s in o.segments)][0]
    (arc,) = [s for s in bulged.segments if type(s).__name__ == "Arc"]
    assert close(arc.center, (10, 0)) and abs(arc.radius - 10) <= TOL \
        and abs(abs(arc.sweep) - math.pi) <= 1e-12
    flat = [o for o in d.outlines if o is not bulged][0]
    assert sorted(s.start for s in flat.segments) == [(40, 0), (60, 0), (60, 20)]
    msgs = [n.message for n in d.notes]
    assert "1 POLYLINE entity of `r12.dxf` (layer `0`) has widths: read as their centre " \
           "lines, the widths ignored" in msgs, msgs
    assert "1 entity of `r12.dxf` (1 POLYLINE) lies off the XY plane (z = 5 mm): read in " \
           "the XY plane" in msgs, msgs
    assert "1 POLYLINE entity of `r12.dxf` skipped (layer `0`): not in the drawing plane: " \
           "its points lie at different z" in msgs, msgs


def _hatch_doc():
    doc, msp = new("R2018")
    h = msp.add_hatch(color=2)
    h.paths.add_polyline_path([(0, 0, 0), (100, 0, 0.25), (100, 60, 0), (0, 60, 0)],
                              is_closed=True, flags=1)
    ep = h.paths.add_edge_path(flags=16)                  # an island of lines and an arc
    ep.add_line((10, 10), (30, 10))
    ep.add_arc((30, 20), 10, -90, 90)
    ep.add_line((30, 30), (10, 30))
    ep.add_line((10, 30), (10, 10))
    h.paths.add_edge_path(flags=16).add_arc((70, 30), 8, 0, 360)       # a round island
    h.paths.add_edge_path(flags=16).add_ellipse((50, 45), major_axis=(6, 0), ratio=0.5)
    sp = h.paths.add_edge_path(flags=16)                  # a spline and a line
    sp.add_spline(control_points=[(40, 5), (45, 12), (55, 12), (60, 5)],
                  knot_values=[0, 0, 0, 0, 1, 1, 1, 1], degree=3)
    sp.add_line((60, 5), (40, 5))
    return doc


def test_hatch_boundaries_are_loops_and_islands_holes(tmp_path):
    """Before: "nothing to import"."""
    doc = _hatch_doc()
    d = read_drawing(text_of(doc), "hatch.dxf")
    assert len(d.outlines) == 3 and len(d.circles) == 1 and len(d.ellipses) == 1
    outer = d.outlines[0]
    assert abs(outer.area) > 5000 and len(outer.segments) == 4
    (arc,) = [s for s in outer.segments if type(s).__name__ == "Arc"]
    assert abs(arc.sweep - 4 * math.atan(0.25)) <= 1e-12 and close(arc.start, (100, 0))
    island = d.outlines[1]
    (iarc,) = [s for s in island.segments if type(s).__name__ == "Arc"]
    assert close(iarc.center, (30, 20)) and iarc.radius == 10
    assert d.circles[0].center == (70, 30) and d.circles[0].radius == 8
    assert d.ellipses == [(50.0, 45.0, 6.0, 3.0, 0.0)]
    sp = [s for s in d.outlines[2].segments if type(s).__name__ == "Spline"][0]
    pts = sorted(tuple(round(v, 9) for v in p) for p in sp.curve.ctrl)
    assert pts == sorted([(40, 5), (45, 12), (55, 12), (60, 5)])
    # aidl import: one solid, the islands its holes; it compiles
    save(doc, tmp_path / "hatch.dxf")
    r = run("import", "hatch.dxf", "-o", "h.aidl", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    prog = (tmp_path / "h.aidl").read_text()
    assert prog.count("solid ") == 1 and prog.count("hole ") == 4, prog   # 3 islands, a circle
    assert "e = Ellipse(center=(50, 45), rx=6, ry=3, rotation=0 deg)" in prog, prog
    assert run("check", "h.aidl", cwd=tmp_path).returncode == 0


def test_a_hatch_over_its_own_outline_is_read_once():
    doc, msp = new()
    pts = [(0, 0), (40, 0), (40, 30), (0, 30)]
    msp.add_lwpolyline(pts, close=True)
    msp.add_hatch().paths.add_polyline_path(pts, is_closed=True)
    d = read_drawing(text_of(doc), "h.dxf")
    assert len(d.outlines) == 1
    # said either as the hatch's repeat or, when the chaining's duplicate removal (the
    # closing pass of svg49) takes the repeated boundary's segments first, as drawn twice
    assert any("1 HATCH boundary of `h.dxf` repeats an outline" in n.message
               or "4 duplicate segments of `h.dxf` removed" in n.message for n in d.notes)


# ------------------------------------------------------------------ bad numbers
def test_bad_numbers_are_skipped_and_counted_and_the_program_compiles(tmp_path):
    """Before: circles of radius 0 and -1000 were written into a program that did not
    compile; a 1e300 coordinate stopped the import."""
    doc, msp = new()
    msp.add_lwpolyline([(0, 0), (100, 0), (100, 50), (0, 50)], close=True)
    msp.add_circle((20, 20), 3)
    msp.add_circle((30, 20), 0)
    msp.add_circle((40, 20), -1000)
    msp.add_line((5, 5), (5, 5))
    msp.add_line((0, 0), (1e300, 0))
    msp.add_line((0, 0), (float("nan"), 1))
    save(doc, tmp_path / "bad.dxf")
    d = read_drawing((tmp_path / "bad.dxf").read_bytes(), "bad.dxf")
    assert len(d.circles) == 1 and len(d.outlines) == 1 and not d.paths
    (n,) = [n for n in d.notes if "numbers" in n.message]
    assert n.code == "W0130" and n.message.startswith(
        "5 entities of `bad.dxf` skipped for numbers that give no shape:"), n.message
    assert "2 CIRCLE with a radius not above 0" in n.message and \
        "1 LINE of zero length" in n.message and "beyond 1e+15 mm" in n.message and \
        "not a number" in n.message
    r = run("import", "bad.dxf", "-o", "bad.aidl", cwd=tmp_path)
    assert r.returncode == 0 and "warning[W0130]: 5 entities" in r.stderr, r.stderr
    assert "Traceback" not in r.stderr and "internal error" not in r.stderr
    r = run("check", "bad.aidl", cwd=tmp_path)
    assert r.returncode == 0, r.stderr


def test_a_number_past_the_extent_but_not_noise_stays_e0130():
    doc, msp = new()
    line = msp.add_line((0, 0), (2e6, 0))
    with pytest.raises(DrawingError) as ex:
        read_drawing(text_of(doc), "big.dxf")
    assert ex.value.code == "E0130" and f"handle {line.dxf.handle}" in ex.value.message


# ------------------------------------------------------------------ ezdxf's log
def test_ezdxf_log_lines_become_notes_not_terminal_output(tmp_path):
    """Before: "Found non-unique entity handle #.., data validation is required." was printed
    raw to the terminal."""
    doc, msp = new()
    a = msp.add_line((0, 0), (10, 0))
    b = msp.add_line((10, 0), (10, 10))
    text = text_of(doc).decode().replace(f"\n  5\n{b.dxf.handle}\n", f"\n  5\n{a.dxf.handle}\n")
    (tmp_path / "dup.dxf").write_text(text)
    r = run("import", "dup.dxf", "-o", "dup.aidl", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    lines = r.stderr.splitlines()
    assert not [ln for ln in lines if ln.startswith("Found non-unique")], r.stderr
    assert any(ln.startswith("dup.dxf: warning[W0130]: ezdxf, reading `dup.dxf`, said: "
                             "\"Found non-unique entity handle") for ln in lines), r.stderr


def test_an_import_parses_the_dxf_once_and_keeps_ezdxfs_log_note(monkeypatch):
    """`aidl import` parsed a DXF three times (its layer names, then each role of each layer
    read it again): a 20,000-hole panel spent 10.6 of its 15 s budget in ezdxf's parser and
    was refused.  Now once per import; ezdxf's log lines of that parse still make the note
    of the read (said again on each later read)."""
    from aidl_lang.drawing.read import dxf as dxf_mod
    from aidl_lang.drawing.write.program import import_drawing
    doc, msp = new()
    a = msp.add_line((0, 0), (10, 0), dxfattribs={"layer": "CUT"})
    msp.add_line((10, 0), (10, 10), dxfattribs={"layer": "CUT"})
    msp.add_circle((5, 5), 2, dxfattribs={"layer": "HOLES"})
    b = msp.add_line((0, 20), (10, 20), dxfattribs={"layer": "MARKS"})
    text = text_of(doc).decode().replace(f"\n  5\n{b.dxf.handle}\n", f"\n  5\n{a.dxf.handle}\n")
    parses = []
    real = dxf_mod._parse_dxf
    monkeypatch.setattr(dxf_mod, "_parse_dxf", lambda data, name: parses.append(name) or
                        real(data, name))
    program, notes = import_drawing(text.encode(), "dup.dxf", engrave="MARKS")
    assert parses == ["dup.dxf"]
    assert sum("Found non-unique entity handle" in n.message for n in notes) == 1, notes
    assert "Circle(center=(5, 5), radius=2)" in program
    parses.clear()          # each import its own parse (nothing kept between them)
    import_drawing(text.encode(), "dup.dxf")
    assert parses == ["dup.dxf"]
    parses.clear()          # a Drawing2D's read with roles: its two roles, one parse
    read_drawing(text.encode(), "dup.dxf", engrave="MARKS")
    assert parses == ["dup.dxf"]
