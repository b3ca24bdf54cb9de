"""Through-cuts that cut a part into pieces (issue 70): a grid of cuts gives exactly its pieces,
each with its own exact outline, and every cutting output runs each shared edge once.

Before: a plate cut by a `#` (two lines each way, edge to edge) came out as `plate` 20 x 20 mm
with an 8-gon hole (the bands between the pieces cut off stayed in it) beside eight 10 x 10
pieces, its DXF a self-touching 8-gon plus a duplicate loop, and the G-code cut 880 mm (two
passes) where the design is 240 mm a pass; a 40 x 40 grid left `plate` 97.5 x 97.5 mm with
1,444 holes.  And a cut drawn along the outline was cut on top of the outline, with no word.

Every file here is re-read by an independent reader: ezdxf (DXF), GRBL's moves replayed from
``gcodeparser``'s reading (G-code), the path data of the SVG read by a plain tokenizer, the
``cut inner``/``cut outer`` shapes of the LightBurn project by the standard XML parser.
"""
from __future__ import annotations

import io
import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

import aidl_lang
from aidl_lang.output import encode, for_cutting
from aidl_lang.output.fabrication.machine import from_dict
from aidl_lang.output.writers import Options

# the budgets count CPU seconds (the cpu_clock fixture, tests/cpu_clock.py): big drawings
# compiled under the default budget reach the same stage however busy the machine is
pytestmark = [pytest.mark.timing, pytest.mark.usefixtures("cpu_clock")]

ezdxf = pytest.importorskip("ezdxf")

GRID = """units mm
solid plate {
    body = Rectangle(center=(15, 15), width=30, height=30)
    cut grid {
        a = Line((0, 10), (30, 10))
        b = Line((0, 20), (30, 20))
        c = Line((10, 0), (10, 30))
        d = Line((20, 0), (20, 30))
    }
}
"""
ONE_PASS = from_dict({"cut_inner": {"passes": 1}, "cut_outer": {"passes": 1}})


def _compile(src: str, tmp_path, name="t.aidl"):
    p = tmp_path / name
    p.write_text(src)
    return aidl_lang.compile(path=str(p))


def _grid_src(n: int, step: float = 10.0, edges: bool = False) -> str:
    """A plate ``n * step`` mm square cut by the lines of an ``n`` x ``n`` grid, edge to edge
    (``edges``: the outline's own four lines drawn as cuts too)."""
    size = n * step
    k = range(0, n + 1) if edges else range(1, n)
    return f"""units mm
solid plate {{
    body = Rectangle(center=({size / 2}, {size / 2}), width={size}, height={size})
    cut grid {{
        for i in [{", ".join(str(i) for i in k)}] {{
            h = Line((0, i * {step}), ({size}, i * {step}))
            v = Line((i * {step}, 0), (i * {step}, {size}))
        }}
    }}
}}
"""


def _unit_edges(p, q, step=10.0) -> list:
    """The grid's unit edges (``step`` long, keyed by their rounded ends) that the straight
    stretch ``p`` -> ``q`` covers; it must run along a grid line from grid point to grid point."""
    (x0, y0), (x1, y1) = p, q
    n = round(math.dist(p, q) / step)
    assert n >= 1 and abs(math.dist(p, q) - n * step) < 1e-6, (p, q)
    assert abs(x0 - x1) < 1e-9 or abs(y0 - y1) < 1e-9, (p, q)
    pts = [(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * i / n) for i in range(n + 1)]
    return [tuple(sorted(((round(a[0], 6), round(a[1], 6)), (round(b[0], 6), round(b[1], 6)))))
            for a, b in zip(pts, pts[1:])]


def _all_unit_edges(n: int, step=10.0) -> set:
    size = n * step
    out = set()
    for i in range(n + 1):
        out.update(_unit_edges((0, i * step), (size, i * step), step))
        out.update(_unit_edges((i * step, 0), (i * step, size), step))
    return out


def _count(stretches, step=10.0) -> dict:
    got: dict = {}
    for p, q in stretches:
        for e in _unit_edges(p, q, step):
            got[e] = got.get(e, 0) + 1
    return got


def _cut_entities(text: str) -> list:
    """The entities on a cut layer (CUT...) of a DXF, re-read by ezdxf."""
    doc = ezdxf.read(io.StringIO(text))
    return [e for e in doc.modelspace() if e.dxf.layer.startswith("CUT")]


def _dxf_stretches(text: str) -> list:
    """The straight stretches of every entity on a cut layer of a DXF (no arcs here)."""
    out = []
    for e in _cut_entities(text):
        if e.dxftype() == "LINE":
            out.append((tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]))
        elif e.dxftype() == "LWPOLYLINE":
            pts = [tuple(p) for p in e.get_points("xyb")]
            assert all(abs(b) < 1e-12 for _, _, b in pts)
            xy = [(x, y) for x, y, _ in pts] + ([pts[0][:2]] if e.closed else [])
            out += list(zip(xy, xy[1:]))
        else:
            raise AssertionError(f"unexpected {e.dxftype()} on {e.dxf.layer}")
    return out


def _gcode_stretches(text: str) -> list:
    pytest.importorskip("gcodeparser")
    from test_gcode import replay
    moves = [mv for mv in replay(text) if mv.on]
    assert all(mv.g == 1 for mv in moves)
    return [(mv.p, mv.q) for mv in moves]


def _svg_stretches(text: str) -> list:
    """The straight stretches of the laser SVG's cut group (``M``/``L``/``Z`` path data; y
    is flipped back)."""
    root = ET.fromstring(text)
    out = []
    for el in root.iter():
        if not el.tag.endswith("path") or "d" not in el.attrib:
            continue
        here = start = None
        for cmd, args in re.findall(r"([MLZ])([^MLZ]*)", el.attrib["d"]):
            nums = [float(v) for v in re.findall(r"-?[\d.]+(?:e-?\d+)?", args)]
            if cmd == "M":
                here = start = (nums[0], -nums[1])
            elif cmd == "L":
                q = (nums[0], -nums[1])
                out.append((here, q))
                here = q
            else:                               # a closed loop's own last edge ends there
                if math.dist(here, start) > 1e-9:
                    out.append((here, start))
                here = start
    return out


def test_a_grid_of_cuts_gives_exactly_its_nine_squares(tmp_path):
    res = _compile(GRID, tmp_path)
    assert res.ok and not res.diagnostics, [d.message for d in res.diagnostics]
    parts = res.output.parts
    assert sorted(p.name for p in parts) == ["plate"] + [f"plate.piece{k}" for k in range(1, 9)]
    cells = set()
    for p in parts:
        (lp,) = p.loops                                  # one outline, no hole
        assert not lp.is_hole and p.area == pytest.approx(100.0, abs=1e-9)
        xs = [c for s in lp.segments for c in (s.start[0], s.end[0])]
        ys = [c for s in lp.segments for c in (s.start[1], s.end[1])]
        assert len(lp.segments) == 4
        x0, y0 = min(xs), min(ys)
        assert max(xs) - x0 == pytest.approx(10.0, abs=1e-9)
        assert max(ys) - y0 == pytest.approx(10.0, abs=1e-9)
        assert all(abs(c - round(c / 10) * 10) < 1e-9 for c in xs + ys)   # on the cuts exactly
        cells.add((round(x0), round(y0)))
    assert cells == {(x, y) for x in (0, 10, 20) for y in (0, 10, 20)}
    # the parts list says the same: every part 10 x 10, none with a hole
    cli = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "parts", str(tmp_path / "t.aidl")],
                         capture_output=True, text=True, timeout=300)
    rows = [ln.split() for ln in cli.stdout.splitlines() if ln.startswith("plate")]
    assert len(rows) == 9, cli.stdout + cli.stderr
    for row in rows:                          # part shape copies width height area holes ...
        assert row[3:7] == ["10.000", "10.000", "100.000", "0"], row


def test_the_grid_cuts_each_shared_edge_once_in_every_cutting_output(tmp_path):
    res = _compile(GRID, tmp_path)
    out = for_cutting(res.output)
    every = _all_unit_edges(3)              # 24 edges of 10 mm: the design's 240 mm
    assert len(every) == 24
    once = {e: 1 for e in every}
    assert _count(_dxf_stretches(encode(out, ".dxf").decode())) == once
    assert _count(_svg_stretches(encode(res.output, ".svg", Options(style="laser")).decode())) \
        == once
    gcode = encode(out, ".gcode", Options(machine=ONE_PASS)).decode()
    stretches = _gcode_stretches(gcode)
    assert _count(stretches) == once
    assert sum(math.dist(p, q) for p, q in stretches) == pytest.approx(240.0, abs=1e-6)
    assert "; cut 240.0 mm" in gcode
    # two passes (the built-in laser's): each edge twice, 480 mm (880 before)
    two = _gcode_stretches(encode(out, ".gcode").decode())
    assert _count(two) == {e: 2 for e in every}
    assert sum(math.dist(p, q) for p, q in two) == pytest.approx(480.0, abs=1e-6)
    # LightBurn: the cut shapes' vertices walk each edge once
    root = ET.fromstring(encode(out, ".lbrn2").decode())
    shapes = [s for s in root.iter("Shape") if s.get("Type") == "Path"]
    walked = []
    for s in shapes:
        verts = [(float(a), float(b))
                 for a, b in re.findall(r"V(-?[\d.]+) (-?[\d.]+)", s.findtext("VertList"))]
        prims = s.findtext("PrimList")
        for a, b in re.findall(r"L(\d+) (\d+)", prims):
            walked.append((verts[int(a)], verts[int(b)]))
    assert _count(walked) == once
    # HP-GL too (the same toolpath; its pen-down paths re-read by ezhpgl): 240 mm, not 720
    pytest.importorskip("ezhpgl")
    from test_hpgl import _points, _read
    _, paths = _read(encode(out, ".plt"))
    hp = [(tuple(a), tuple(b)) for ops in paths for a, b in zip(_points(ops), _points(ops)[1:])]
    assert _count(hp) == once


def test_a_part_cut_in_three_with_a_t_shares_each_stretch_once(tmp_path):
    """A cut ending on another: the big piece's edge meets two smaller pieces' edges (a
    stretch shared in part, not edge for edge): 120 + 30 + 20 = 170 mm in all."""
    src = """units mm
solid plate {
    body = Rectangle(center=(15, 15), width=30, height=30)
    cut t {
        a = Line((20, 0), (20, 30))
        b = Line((0, 15), (20, 15))
    }
}
"""
    res = _compile(src, tmp_path)
    assert res.ok and not res.diagnostics, [d.message for d in res.diagnostics]
    assert sorted(round(p.area, 6) for p in res.output.parts) == [300.0, 300.0, 300.0]
    out = for_cutting(res.output)
    g = _gcode_stretches(encode(out, ".gcode", Options(machine=ONE_PASS)).decode())
    assert sum(math.dist(p, q) for p, q in g) == pytest.approx(170.0, abs=1e-6)
    d = _dxf_stretches(encode(out, ".dxf").decode())
    assert sum(math.dist(p, q) for p, q in d) == pytest.approx(170.0, abs=1e-6)
    # no stretch twice: every 5 mm step of the design's lines covered once
    assert _count(g, 5.0) == _count(d, 5.0) and set(_count(g, 5.0).values()) == {1}


def test_a_curved_cut_between_two_pieces_is_cut_once(tmp_path):
    """A quarter circle from edge to edge: the arc is in both outlines and cut once, 120 mm
    of outline and 7.5 pi mm of arc."""
    src = """units mm
solid plate {
    body = Rectangle(center=(15, 15), width=30, height=30)
    cut c { a = Arc(center=(0, 0), radius=15, start_angle=0, end_angle=90) }
}
"""
    res = _compile(src, tmp_path)
    assert res.ok and not res.diagnostics, [d.message for d in res.diagnostics]
    assert sorted(p.area for p in res.output.parts) == pytest.approx(
        [225 * math.pi / 4, 900 - 225 * math.pi / 4], abs=1e-6)
    pytest.importorskip("gcodeparser")
    from test_gcode import replay
    moves = [mv for mv in replay(encode(for_cutting(res.output), ".gcode",
                                        Options(machine=ONE_PASS)).decode()) if mv.on]
    assert sum(mv.length for mv in moves) == pytest.approx(120 + 7.5 * math.pi, abs=1e-6)
    assert sum(mv.g in (2, 3) for mv in moves) == 1          # the arc once
    doc = ezdxf.read(io.StringIO(encode(for_cutting(res.output), ".dxf").decode()))
    arcs = [e for e in doc.modelspace() if e.dxftype() == "ARC"]
    bulges = [b for e in doc.modelspace() if e.dxftype() == "LWPOLYLINE"
              for *_, b in e.get_points("xyb") if b]
    assert len(arcs) + len(bulges) == 1


def test_a_40_by_40_grid_gives_1600_squares_and_the_design_length(tmp_path):
    """41 lines each way (the outline's four among them: W0522): 1,600 squares of
    10 mm, none with a hole (before: the part keeping the name 97.5 x 97.5 mm with 1,444
    holes); the G-code cuts 41 x 2 x 400 mm once.  The piece finding and the shared edges
    stay O(n log n) (boxes, sorted ranges): the compile ends ok within its default budget."""
    res = _compile(_grid_src(40, edges=True), tmp_path)
    assert res.ok, [d.message for d in res.diagnostics]
    # the outline's lines (i = 0 and 40 of the loop's `h` and `v`): one W0522 at each line
    assert sorted((d.code, d.message.split("`")[1]) for d in res.diagnostics) == \
        [("W0522", "plate.grid.h"), ("W0522", "plate.grid.v")]
    parts = res.output.parts
    assert len(parts) == 1600
    assert all(len(p.loops) == 1 and len(p.loops[0].segments) == 4 for p in parts)
    assert all(abs(p.area - 100.0) < 1e-6 for p in parts)
    (plate,) = [p for p in parts if p.name == "plate"]
    xs = [c for s in plate.loops[0].segments for c in (s.start[0], s.end[0])]
    assert max(xs) - min(xs) == pytest.approx(10.0, abs=1e-9)
    g = _gcode_stretches(encode(for_cutting(res.output), ".gcode",
                                Options(machine=ONE_PASS)).decode())
    assert sum(math.dist(p, q) for p, q in g) == pytest.approx(41 * 2 * 400.0, abs=1e-6)
    assert set(_count(g).values()) == {1} and len(_count(g)) == len(_all_unit_edges(40))


def test_a_cut_along_the_outline_is_cut_once_and_w0522(tmp_path):
    src = GRID.replace("cut grid {", "cut grid {\n        e = Line((0, 0), (30, 0))")
    edge = """units mm
solid plate {
    body = Rectangle(center=(15, 15), width=30, height=30)
    cut edge {
        a = Line((0, 0), (30, 0))
    }
}
"""
    for text, total, line in ((edge, 120.0, 5), (src, 240.0, 5)):
        res = _compile(text, tmp_path)
        assert res.ok
        (w,) = res.diagnostics
        assert w.code == "W0522" and w.span.line == line and w.severity == "warning"
        assert "lies along the outline of `plate`" in w.message and "delete it" in w.hint
        assert not res.output.cuts                   # no stroke on top of the outline
        out = for_cutting(res.output)
        g = _gcode_stretches(encode(out, ".gcode", Options(machine=ONE_PASS)).decode())
        assert sum(math.dist(p, q) for p, q in g) == pytest.approx(total, abs=1e-6)
        assert set(_count(g).values()) == {1}
        d = _dxf_stretches(encode(out, ".dxf").decode())
        assert _count(d) == _count(g)
    # a cut that crosses the material next to the outline still cuts (no W0522)
    inside = _compile(edge.replace("Line((0, 0), (30, 0))", "Line((0, 1), (30, 1))"), tmp_path)
    assert inside.ok and not [d for d in inside.diagnostics if d.code == "W0522"]
    assert len(inside.output.parts) == 2


def test_the_kerf_offsets_the_grid_outside_and_cuts_each_shared_edge_once_on_its_line(tmp_path):
    """Before: each piece offset on its own, every shared edge cut twice a kerf apart (at
    0.2 mm: 10.1 and 9.9), the middle square 9.6 mm wide, no word.  Now the plate's outline is
    offset by half the kerf, each shared edge stays on its line (run on to the offset outline)
    and is cut once, and one note says that each side loses half a kerf along them."""
    res = _compile(GRID, tmp_path)
    out = for_cutting(res.output, 0.2)
    pytest.importorskip("gcodeparser")
    from test_gcode import replay
    moves = [mv for mv in replay(encode(out, ".gcode", Options(machine=ONE_PASS)).decode())
             if mv.on]
    # the offset outline (120 mm of sides, four quarter circles of 0.1 mm) and the four
    # lines carried on to it (30.2 mm each)
    assert sum(mv.length for mv in moves) == pytest.approx(120 + 0.2 * math.pi + 4 * 30.2,
                                                           abs=1e-6)
    for mv in moves:
        if mv.g != 1:
            continue
        (x0, y0), (x1, y1) = mv.p, mv.q
        on_line = (x0 == x1 and x0 in (10, 20, -0.1, 30.1)) or \
            (y0 == y1 and y0 in (10, 20, -0.1, 30.1))
        assert on_line, (mv.p, mv.q)                # nothing at 9.9 or 10.1: no double cut
    d = _dxf_stretches_any(encode(out, ".dxf").decode())
    assert sum(d) == pytest.approx(120 + 0.2 * math.pi + 4 * 30.2, abs=1e-6)
    cli = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "render",
                          str(tmp_path / "t.aidl"), "-o", str(tmp_path / "g.nc"), "--kerf",
                          "0.2"], capture_output=True, text=True, timeout=300)
    assert cli.returncode == 0, cli.stderr
    said = cli.stdout + cli.stderr
    assert ("note: the 12 shared cuts between the 9 pieces of `plate` are each cut once along "
            "their line; each side loses 0.1 mm (half the kerf, 0.2 mm) along each") in said
    assert said.count("shared cut") == 1            # one note for the cut part, not 12
    # two passes of 241.43 mm, said as such (issue 86)
    assert "cut 241.4 mm path x 2 passes = 482.9 mm" in said


def _dxf_stretches_any(text: str) -> list:
    """The length of each entity on a cut layer (lines, arcs, bulged polylines), mm."""
    out = []
    for e in _cut_entities(text):
        if e.dxftype() == "LINE":
            out.append(math.dist(tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]))
        elif e.dxftype() == "ARC":
            sweep = (e.dxf.end_angle - e.dxf.start_angle) % 360
            out.append(math.radians(sweep) * e.dxf.radius)
        elif e.dxftype() == "LWPOLYLINE":
            pts = [tuple(p) for p in e.get_points("xyb")]
            pairs = list(zip(pts, pts[1:] + (pts[:1] if e.closed else [])))
            for (x0, y0, b), (x1, y1, _) in pairs:
                c = math.dist((x0, y0), (x1, y1))
                if b == 0:
                    out.append(c)
                else:
                    theta = 4 * math.atan(abs(b))
                    out.append(theta * c / (2 * math.sin(theta / 2)))
        else:
            raise AssertionError(e.dxftype())
    return out


# (the kerf on a sheet of 2,000 discs cut in two: tests/test_slit_sheets.py, which compiles
# that sheet once for its tests)


# ------------------------------------------------------------------ crossing slits at scale
def _slit_grid_src(n: int, span: bool, step: float = 2.0) -> str:
    """A plate ``(n + 1) * step`` mm square crossed by ``n`` horizontal and ``n`` vertical
    slits ``step`` apart, written with a ``for`` loop: from edge to edge (``span``) or
    stopping 0.5 mm short of the edges."""
    size = (n + 1) * step
    lo, hi = (0.0, size) if span else (0.5, size - 0.5)
    return f"""units mm
solid plate {{
    body = Rectangle(center=({size / 2}, {size / 2}), width={size}, height={size})
    cut grid {{
        for i in range(1, {n + 1}) {{
            h = Line(({lo}, i * {step}), ({hi}, i * {step}))
            v = Line((i * {step}, {lo}), (i * {step}, {hi}))
        }}
    }}
    Fixed(body)
}}
"""


def shapely_parts(outline, cuts, width: float = 1e-3) -> list:
    """The areas (mm^2, ascending) of the parts a plate with outer outline ``outline`` (a
    closed polyline, mm) comes out as, cut along the polylines ``cuts`` (zero width), by
    Shapely alone: the faces of the outline and the cuts noded together (``polygonize``;
    a cut that ends inside a face, a slit, splits nothing), less those that fall out.  A face
    falls out (a hole of another) when, on the plate less the cuts drawn ``width`` mm wide
    (square ends, as the laser cuts them, however fine), its piece lies inside another
    piece's outer outline: a face that a cut joins to the outside, or whose corner lies where
    cuts cross, is a part of its own (no piece closes round it)."""
    import shapely
    from shapely.geometry import LineString, Polygon
    plate = Polygon(outline)
    lines = [plate.exterior] + [LineString(c).intersection(plate) for c in cuts]
    faces = list(shapely.polygonize([shapely.union_all(lines)]).geoms)
    strips = [LineString(c).buffer(width / 2, cap_style="square") for c in cuts]
    cutaway = shapely.union_all(strips)
    by_strip = shapely.STRtree(strips)
    material = plate.difference(cutaway)
    pieces = list(getattr(material, "geoms", [material]))
    filled = [Polygon(p.exterior) for p in pieces]
    by_piece, by_filled = shapely.STRtree(pieces), shapely.STRtree(filled)
    parts = []
    for f in faces:
        shrunk = f.buffer(-width)               # clear of a slit that ends in f: the
        near = [strips[j] for j in by_strip.query(shrunk)]   # strips that reach f, not all
        inner = shrunk.difference(shapely.union_all(near)) if near else shrunk
        p = (inner if not inner.is_empty else f).representative_point()
        (k,) = [j for j in by_piece.query(p) if pieces[j].contains(p)]
        if not any(j != k and filled[j].contains(pieces[k])
                   for j in by_filled.query(pieces[k])):
            parts.append(f.area)
    return sorted(parts)


@pytest.mark.parametrize("span", [True, False], ids=["edge to edge", "stopping short"])
def test_a_100_by_100_grid_of_crossing_slits_gives_its_pieces_within_the_budget(tmp_path, span):
    """100 slits each way across a 202 mm plate.  Before: `parts` and `render` refused at any
    `--budget` ("more than 10,000,000 (edge, chord) pairs to match (thousands of curves drawn
    on top of each other)"): the exact outlines' grid of chords took cells of the median
    chord, here a whole slit (202 mm), so each of the 40,804 result edges met every slit.
    Now: 101 x 101 squares of 4 mm^2 (edge to edge), or one part, the frame 2 mm wide whose
    10,000 cells fall out (stopping short), each edge cut once."""
    import json

    from aidl_lang.output.checks.reports.inventory import parts_text
    (tmp_path / "t.aidl").write_text(_slit_grid_src(100, span))
    size = 202.0
    # the pieces by arithmetic: edge to edge, the 101 x 101 cells 2 mm square between the
    # slits and the edges; stopping short, the frame 2 mm wide round the 198 mm square whose
    # cells fall out.  (Shapely's count, shapely_parts, gives exactly these two lists; it took
    # 3 s of CPU here, and the random cut programs below hold the compiler to it.)
    want = [4.0] * 10201 if span else [size ** 2 - 198.0 ** 2]
    # two compiles, each by the command line at its default budget: the parts list (its
    # areas, as JSON, and the text it prints for them), then one `render` writing the laser
    # SVG and, edge to edge, the G-code too (one budget for both files)
    cli = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "parts", "--json",
                          str(tmp_path / "t.aidl")], capture_output=True, text=True, timeout=300)
    assert cli.returncode == 0, cli.stderr
    rows = json.loads(cli.stdout)["parts"]
    got = sorted(r["area"] for r in rows)
    assert len(got) == len(want)
    assert got == pytest.approx(want, abs=1e-6)
    assert f"{len(want)} part{'s' if span else ''}, 1 shape" in parts_text(rows)
    svg, nc = tmp_path / "g.svg", tmp_path / "g.nc"
    cli = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "render", str(tmp_path / "t.aidl"),
                          "-o", str(svg)] + (["-o", str(nc)] if span else [])
                         + ["--svg-style", "laser"], capture_output=True, text=True, timeout=300)
    assert cli.returncode == 0, cli.stderr
    if span:                                   # each 2 mm edge of the 101 x 101 cells once
        counted = _count(_svg_stretches(svg.read_text()), 2.0)
        assert counted == {e: 1 for e in _all_unit_edges(101, 2.0)}
        # the G-code too (refused before as "about 18.9 s more would end past the 15 s": the
        # writer's estimate was 300 us an item, it takes about 17 us here): each edge once a
        # pass, the built-in laser's two passes
        counted = _count(_gcode_stretches(nc.read_text()), 2.0)
        assert counted == {e: 2 for e in _all_unit_edges(101, 2.0)}


# ------------------------------------------------------------------ each place cut once
PLATE = """units mm
solid plate {{
    body = Rectangle(center=(15, 15), width=30, height=30)
    cut c {{
        {cut}
    }}
    Fixed(body)
}}
"""


@pytest.mark.parametrize("cut, along, extra", [
    # the first side on the bottom edge, the second up into the plate
    ("p = Polyline([(0, 0), (10, 0), (10, 10)])", "segment 1 of 2, from (0, 0) to (10, 0)",
     [((10, 0), (10, 10))]),
    # the last side on the right edge
    ("p = Polyline([(20, 10), (30, 10), (30, 20)])", "segment 2 of 2, from (30, 10) to (30, 20)",
     [((20, 10), (30, 10))]),
    # the middle side on the bottom edge, between two slits up into the plate
    ("p = Polyline([(10, 10), (10, 0), (20, 0), (20, 10)])",
     "segment 2 of 3, from (10, 0) to (20, 0)", [((10, 0), (10, 10)), ((20, 0), (20, 10))]),
    # a closed run of two sides on the outline, from the left edge round the corner
    ("p = Polyline([(0, 20), (0, 30), (10, 30), (10, 20)])",
     "segments 1 to 2 of 3, from (0, 20) to (10, 30)", [((10, 30), (10, 20))]),
], ids=["first", "last", "middle", "two"])
def test_a_polyline_side_along_the_outline_is_w0522_on_its_line_and_cut_once(
        tmp_path, cut, along, extra):
    """Before: the side of a Polyline drawn on the plate's edge was cut with the edge, twice a
    pass (4 times with the laser's two passes), with no word; a Line there was W0522 and cut
    once.  Every segment is now judged as a Line would be: W0522 on the Polyline's line,
    naming the segment, and the G-code (replayed) and the DXF (ezdxf) cut each 10 mm of the
    design once: the outline's 120 mm and the sides off the outline."""
    res = _compile(PLATE.format(cut=cut), tmp_path)
    assert res.ok
    (w,) = res.diagnostics
    assert (w.code, w.span.line, w.span.col) == ("W0522", 5, 13)
    assert f"`plate.c.p` adds nothing along {along}" in w.message
    assert "lies along the outline of `plate`" in w.message
    assert len(res.output.parts) == 1
    want = _count([((0, 0), (30, 0)), ((30, 0), (30, 30)), ((30, 30), (0, 30)),
                   ((0, 30), (0, 0))] + extra)
    assert set(want.values()) == {1}
    out = for_cutting(res.output)
    g = _gcode_stretches(encode(out, ".gcode", Options(machine=ONE_PASS)).decode())
    assert _count(g) == want
    assert sum(math.dist(p, q) for p, q in g) == pytest.approx(120 + 10 * len(extra), abs=1e-6)
    assert _count(_dxf_stretches(encode(out, ".dxf").decode())) == want
    two = _gcode_stretches(encode(out, ".gcode").decode())       # two passes: each twice
    assert _count(two) == {e: 2 for e in want}


def test_overlapping_collinear_slits_are_w0522_naming_both_and_cut_once(tmp_path):
    """Two slits on one line, overlapping by 8 mm.  Before: the 8 mm were cut twice a pass
    (296 mm for the laser's two passes, where the design is 2 x 140), with no word.  Now
    W0522 names both, on the later one's line, and the G-code, DXF and SVG cut each
    millimetre of [5, 28] once; a slit that only meets another end to end is no overlap."""
    res = _compile(PLATE.format(cut="a = Line((5, 15), (20, 15))\n        "
                                    "b = Line((12, 15), (25, 15))\n        "
                                    "e = Line((25, 15), (28, 15))"), tmp_path)
    assert res.ok
    (w,) = res.diagnostics
    assert (w.code, w.span.line) == ("W0522", 6)
    assert "`plate.c.b` runs along through-cut `plate.c.a` for 8 mm" in w.message
    out = for_cutting(res.output)
    want = _count([((0, 0), (30, 0)), ((30, 0), (30, 30)), ((30, 30), (0, 30)),
                   ((0, 30), (0, 0)), ((5, 15), (28, 15))], 1.0)
    assert set(want.values()) == {1}
    g = _gcode_stretches(encode(out, ".gcode", Options(machine=ONE_PASS)).decode())
    assert _count(g, 1.0) == want
    assert sum(math.dist(p, q) for p, q in g) == pytest.approx(143.0, abs=1e-6)
    assert _count(_dxf_stretches(encode(out, ".dxf").decode()), 1.0) == want
    assert _count(_svg_stretches(encode(res.output, ".svg", Options(style="laser")).decode()),
                  1.0) == want
    # copies of one slit at one place (a loop that does not move it): cut once, one warning
    res = _compile(PLATE.format(cut="for i in range(3) { s = Line((5, 15), (20, 15)) }"),
                   tmp_path)
    assert [d.code for d in res.diagnostics] == ["W0522"]
    g = _gcode_stretches(encode(for_cutting(res.output), ".gcode",
                                Options(machine=ONE_PASS)).decode())
    assert sum(math.dist(p, q) for p, q in g) == pytest.approx(135.0, abs=1e-6)


def test_arcs_along_a_round_outline_or_each_other_are_w0522_and_cut_once(tmp_path):
    """A quarter Arc on a disc's own circle, and two half circles of one radius overlapping
    by a quarter.  Before: neither was said (the Arc's chords and the outline's differ, so its
    band reached past the test's 1 um strip) and the overlap was cut twice.  Now each is
    W0522 and the G-code (replayed, arcs as G2/G3) cuts the outline and three quarters of
    the inner circle, once."""
    src = """units mm
solid disc {
    body = Circle(center=(0, 0), radius=20)
    cut c {
        a = Arc(center=(0, 0), radius=20, start_angle=0, end_angle=90)
        b = Arc(center=(0, 0), radius=10, start_angle=0, end_angle=180)
        e = Arc(center=(0, 0), radius=10, start_angle=90, end_angle=270)
    }
    Fixed(body)
}
"""
    res = _compile(src, tmp_path)
    assert res.ok
    got = sorted((d.code, d.span.line, d.message.split(":")[0]) for d in res.diagnostics)
    assert got == [("W0522", 5, "through-cut `disc.c.a` adds nothing"),
                   ("W0522", 7, "through-cut `disc.c.e` runs along through-cut `disc.c.b` "
                                "for 15.71 mm")]
    pytest.importorskip("gcodeparser")
    from test_gcode import replay
    moves = [mv for mv in replay(encode(for_cutting(res.output), ".gcode",
                                        Options(machine=ONE_PASS)).decode()) if mv.on]
    assert sum(mv.length for mv in moves) == pytest.approx(40 * math.pi + 15 * math.pi,
                                                           abs=1e-6)
    inner = [mv for mv in moves if mv.g in (2, 3) and abs(mv.radius - 10) < 1e-9]
    assert sum(abs(mv.sweep) for mv in inner) == pytest.approx(1.5 * math.pi, abs=1e-9)


# ------------------------------------------------------------------ the law, against Shapely
from hypothesis import given, settings, strategies as st  # noqa: E402

W, H, STEP = 40, 30, 5          # the plate, and the lattice every cut's corners lie on


def _lattice(inner: bool = False):
    """A lattice point of the plate (on its edge too unless ``inner``)."""
    lo = 1 if inner else 0
    return st.tuples(st.integers(lo, W // STEP - lo), st.integers(lo, H // STEP - lo)).map(
        lambda ij: (ij[0] * STEP, ij[1] * STEP))


@st.composite
def _cut(draw):
    """One cut: ``(kind, points)``.  ``line``: between two lattice points (edge to edge, a
    slit, along an edge); ``along``: a Polyline whose first side runs along an edge of the
    plate and whose second goes in to an inner point; ``overlap``: two slits on one lattice
    line that overlap by at least one step."""
    kind = draw(st.sampled_from(["line", "line", "along", "overlap"]))
    if kind == "line":
        p, q = draw(_lattice()), draw(_lattice())
        if p == q:
            q = (W - p[0], H - p[1]) if (W - p[0], H - p[1]) != p else (0, 0)
        return kind, [[p, q]]
    if kind == "along":
        edge = draw(st.sampled_from(["bottom", "top", "left", "right"]))
        n = (W if edge in ("bottom", "top") else H) // STEP
        a = draw(st.integers(0, n - 1))
        b = draw(st.integers(a + 1, n))
        run = [(a * STEP, b * STEP), (b * STEP, a * STEP)][draw(st.integers(0, 1))]
        fixed = {"bottom": 0, "top": H, "left": 0, "right": W}[edge]
        ends = [((t, fixed) if edge in ("bottom", "top") else (fixed, t)) for t in run]
        return kind, [ends + [draw(_lattice(inner=True))]]
    across = draw(st.booleans())          # along x, else along y
    n = (W if across else H) // STEP
    fixed = draw(st.integers(1, (H if across else W) // STEP - 1)) * STEP
    a = draw(st.integers(0, n - 2))
    b = draw(st.integers(a + 2, n))
    c = draw(st.integers(a, b - 1))       # the second starts before the first ends ...
    d = draw(st.integers(max(c + 1, a + 1), n))     # ... and overlaps it by a step or more
    pts = [(a, b), (c, d)]
    return kind, [[((x * STEP, fixed) if across else (fixed, x * STEP)) for x in ab]
                  for ab in pts]


def _law_src(cuts: list) -> tuple[str, dict]:
    """The program of ``cuts`` (:func:`_cut`), and line number -> (kind, points) of each
    curve in it."""
    lines = ["units mm", "solid plate {",
             f"    body = Rectangle(center=({W / 2}, {H / 2}), width={W}, height={H})",
             "    cut c {"]
    where = {}
    for k, (kind, curves) in enumerate(cuts):
        for m, pts in enumerate(curves):
            text = ", ".join(f"({x}, {y})" for x, y in pts)
            where[len(lines) + 1] = (kind, pts)
            lines.append(f"        c{k}_{m} = " + (f"Polyline([{text}])" if len(pts) > 2 else
                                                    f"Line({text})"))
    lines += ["    }", "    Fixed(body)", "}", ""]
    return "\n".join(lines), where


@settings(max_examples=110, deadline=None)
@given(st.lists(_cut(), min_size=1, max_size=6))
def test_random_cut_programs_match_shapely_and_cut_each_place_once(tmp_path_factory, cuts):
    """Law: a 40 x 30 mm plate cut by random lines between points of a 5 mm lattice (edge
    to edge, slits, along an edge), Polylines whose first side runs along an edge, and
    collinear slits that overlap.  The parts (count and areas) are Shapely's (the faces of
    the noded outline and cuts, less those that fall out: :func:`shapely_parts`); the G-code
    (one pass, replayed) cuts exactly the union of the outline and the cuts, each place once
    (its length is the union's, Shapely's ``union_all``); W0522 is on the line of every
    Polyline whose side runs along the edge, on no line that has nothing along the outline or
    another cut, and some W0522 says "runs along" wherever two cuts overlap."""
    import shapely
    from shapely.geometry import LineString, Polygon
    tmp = tmp_path_factory.mktemp("law")
    src, where = _law_src(cuts)
    res = _compile(src, tmp)
    assert res.ok, src
    polylines = [pts for _, pts in where.values()]
    outline = [(0, 0), (W, 0), (W, H), (0, H)]
    want = shapely_parts(outline, polylines)
    got = sorted(p.area for p in res.output.parts)
    assert len(got) == len(want), src
    assert got == pytest.approx(want, abs=1e-6), src
    # each place once: the G-code's length is that of the union of the outline and the cuts
    plate = Polygon(outline)
    union = shapely.union_all([plate.exterior] + [LineString(p) for p in polylines])
    g = _gcode_stretches(encode(for_cutting(res.output), ".gcode",
                                Options(machine=ONE_PASS)).decode())
    assert sum(math.dist(p, q) for p, q in g) == pytest.approx(union.length, abs=1e-6), src
    # W0522: where a side lies along the outline, or a cut along another
    told = {d.span.line for d in res.diagnostics if d.code == "W0522"}
    segs = {ln: [LineString(pair) for pair in zip(pts, pts[1:])] for ln, (_, pts) in where.items()}
    on_edge = {ln for ln, ss in segs.items()
               if any(s.difference(plate.exterior).length < 1e-9 for s in ss)}
    overlaps = {ln for ln, ss in segs.items() for m, tt in segs.items() if m != ln
                for s in ss for t in tt
                if s.intersection(t).difference(plate.exterior).length > 1e-6}
    assert {ln for ln, (kind, _) in where.items() if kind == "along"} <= told, src
    assert told <= on_edge | overlaps, src
    if overlaps:
        assert any("runs along" in d.message for d in res.diagnostics), src


def test_a_bezier_span_along_the_outline_is_w0522_and_cut_once(tmp_path):
    """A Bezier of two spans, the first on the bottom edge (collinear control points), the
    second into the plate: judged span by span like a Polyline's sides.  Before: no word, and
    the first span cut with the edge (10 mm more a pass).  The G-code (replayed; the span as
    arcs within its tolerance) cuts the outline and the second span once: 120 mm plus the
    span's length, by 2,001 points of its Bernstein form."""
    res = _compile(PLATE.format(cut="b = Bezier(points=[(0, 0), (3, 0), (7, 0), (10, 0), "
                                    "(10, 5), (15, 10), (20, 10)])"), tmp_path)
    assert res.ok
    (w,) = res.diagnostics
    assert (w.code, w.span.line) == ("W0522", 5)
    assert "adds nothing along segment 1 of 2, from (0, 0) to (10, 0)" in w.message
    t = [i / 2000 for i in range(2001)]
    P = [(10, 0), (10, 5), (15, 10), (20, 10)]
    pts = [tuple(sum(c * p[d] for c, p in zip(((1 - s) ** 3, 3 * s * (1 - s) ** 2,
                                                 3 * s * s * (1 - s), s ** 3), P))
                 for d in (0, 1)) for s in t]
    span = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
    pytest.importorskip("gcodeparser")
    from test_gcode import replay
    moves = [mv for mv in replay(encode(for_cutting(res.output), ".gcode",
                                        Options(machine=ONE_PASS)).decode()) if mv.on]
    assert sum(mv.length for mv in moves) == pytest.approx(120 + span, abs=0.01)
