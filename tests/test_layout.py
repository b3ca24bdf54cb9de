"""Issue 22, "From assembly to cutting sheet": the assembly view's colours, cutting layouts
(true-shape nesting with spyrrow), kerf compensation and ``aidl parts``.

Real .aidl sources go through ``aidl render`` / ``aidl parts`` (``main``); the files are re-read
by independent readers (ezdxf, svgelements) and checked with shapely: no two parts of a sheet
overlap, every part lies on its sheet, and every placed part is its assembly-view shape moved
rigidly (area and perimeter within 1e-6, from the exact output model and from the DXF).
"""
from __future__ import annotations

from aidl_lang.base.limits import now as budget_clock      # the budget's clock: CPU seconds

import json
import math
import re
import sys

import pytest
import shapely
from shapely.geometry import Polygon, box as shapely_box

from aidl_lang.cli.main import main
from exact_geometry import DXF_TOL, SVG_TOL, A, C, L, read_dxf, read_svg_loops

BOX = """
# a laser-cut box: six panels laid side by side
units mm
param w = 80 mm
param d = 60 mm
param h = 40 mm
thickness 3 mm

assembly box {
    solid bottom {
        body = Rectangle(center=(0, 0), width=w, height=d)
    }
    solid lid {
        body = Rectangle(center=(0, d + 10), width=w, height=d)
        hole grip {
            s = Slot(center=(0, d + 10), length=30, width=8)
        }
    }
    solid front {
        body = Rectangle(center=(w + 10, 0), width=w, height=h)
        hole window {
            c = Circle(center=(w + 10, 0), radius=8)
        }
    }
    solid back {
        body = Rectangle(center=(w + 10, h + 10), width=w, height=h)
        hole window {
            c = Circle(center=(w + 10, h + 10), radius=8)
        }
    }
    solid left {
        body = RoundedRectangle(center=(2 * w + 20, 0), width=d, height=h, corner_radius=4)
    }
    solid right {
        body = RoundedRectangle(center=(2 * w + 20, h + 10), width=d, height=h, corner_radius=4)
    }
}
"""

CLOCK = """
# a wall clock: a face and two hands
units mm
assembly clock {
    solid face {
        # the hands sit on the face in the assembly view; laid out, they come apart
        rim = Circle(center=(0, 0), radius=60)
        hole shaft {
            c = Circle(center=(0, 0), radius=4)
        }
        drawing marks {
            t = Text("XII", center=(0, 45), size=8)
        }
    }
    solid hour_hand {
        s = Slot(start=(0, 4), end=(0, 36), width=8)
        hole pin {
            c = Circle(center=(0, 4), radius=2)
        }
    }
    solid minute_hand {
        p = Polygon(points=[(-3, -6), (3, -6), (1.5, 52), (-1.5, 52)])
        hole pin {
            c = Circle(center=(0, 0), radius=2)
        }
    }
}
"""


# ------------------------------------------------------------------ helpers
def write(tmp_path, name: str, src: str):
    p = tmp_path / f"{name}.aidl"
    p.write_text(src)
    return p


def output_of(src: str, tmp_path, name="prog"):
    from aidl_lang.output import build
    from aidl_lang.pipeline import compile_source
    p = write(tmp_path, name, src)
    res = compile_source(src, str(p))
    assert res.ok, [d.message for d in res.sink.items]
    assert not [d for d in res.sink.items if d.severity == "warning"], \
        [d.message for d in res.sink.items]
    return build(res.drawing, res.model.root.name)


def sample(segs, n_arc: int = 64) -> list:
    """Points along the re-read segments (arcs and circles finely sampled)."""
    pts = []
    for s in segs:
        if isinstance(s, L):
            pts.append(s.start)
        elif isinstance(s, A):
            (cx, cy), r = s.center, s.radius
            a0 = math.atan2(s.start[1] - cy, s.start[0] - cx)
            pts += [(cx + r * math.cos(a0 + s.sweep * i / n_arc),
                     cy + r * math.sin(a0 + s.sweep * i / n_arc)) for i in range(n_arc)]
        else:
            (cx, cy), r = s.center, s.radius
            pts += [(cx + r * math.cos(2 * math.pi * i / 256),
                     cy + r * math.sin(2 * math.pi * i / 256)) for i in range(256)]
    return pts


def dxf_parts(path) -> dict:
    """Layer -> shapely polygon (largest loop the shell, the others holes) of a DXF's cuts."""
    by_layer: dict = {}
    for e in read_dxf(path):
        if e.layer.startswith("CUT"):
            by_layer.setdefault(e.layer, []).append(Polygon(sample(e.segments)))
    out = {}
    for layer, polys in by_layer.items():
        polys.sort(key=lambda p: -p.area)
        out[layer] = Polygon(polys[0].exterior, [p.exterior for p in polys[1:]])
    return out


def check_sheets(sheets, view, W, H, gap):
    """No overlap, inside the sheet (and ``gap`` from its edge), each part once and the same
    shape as in the assembly view."""
    from aidl_lang.output.checks.reports.inventory import same_shape
    from aidl_lang.output.fabrication.layout import part_box
    solids = {p.name: p for p in view.parts if p.kind == "solid"}
    seen = []
    for sh in sheets:
        polys = []
        for p in sh.parts:
            seen.append(p.name)
            x0, y0, x1, y1 = part_box(p)
            assert x0 >= gap - 1e-9 and y0 >= gap - 1e-9, (p.name, x0, y0)
            assert x1 <= W - gap + 1e-9 and y1 <= H - gap + 1e-9, (p.name, x1, y1)
            orig = solids[p.name]
            assert abs(p.area - orig.area) <= 1e-6 and abs(p.perimeter - orig.perimeter) <= 1e-6
            assert same_shape(p, orig)
            outer = [lp for lp in p.loops if not lp.is_hole]
            poly = shapely.union_all([Polygon(lp.points()) for lp in outer])
            assert shapely_box(0, 0, W, H).contains(poly)
            polys.append((p.name, poly))
        for i in range(len(polys)):
            for j in range(i + 1, len(polys)):
                a, b = polys[i][1], polys[j][1]
                assert a.intersection(b).area <= 1e-9, (polys[i][0], polys[j][0])
                assert a.distance(b) >= gap - 1e-6, (polys[i][0], polys[j][0], a.distance(b))
    assert sorted(seen) == sorted(solids)


# ------------------------------------------------------------------ layout
@pytest.mark.parametrize("src,n", [(BOX, 6), (CLOCK, 3)], ids=["box", "clock"])
def test_layout_places_every_part_once_without_overlap(src, n, tmp_path):
    from aidl_lang.output.fabrication.layout import lay_out
    view = output_of(src, tmp_path)
    assert len(view.parts) == n
    sheets, dropped = lay_out(view, (300.0, 200.0), 3.0, (0.0, 90.0))
    assert len(sheets) == 1 and dropped == 0
    check_sheets(sheets, view, 300.0, 200.0, 3.0)
    # engraving moves with its part: the clock's XII stays on the face
    for sh in sheets:
        for st in sh.engrave:
            face = next(p for p in sh.parts if p.name == st.part)
            poly = Polygon(face.loops[0].points())
            for s in st.segments:
                assert poly.buffer(1e-6).contains(shapely.Point(s.start))


def test_layout_through_the_cli_reads_back_from_dxf_and_svg(tmp_path):
    prog = write(tmp_path, "box", BOX)
    dxf, svg = tmp_path / "cut.dxf", tmp_path / "cut.svg"
    assert main(["render", str(prog), "--layout", "sheet", "--sheet", "300x200mm",
                 "--gap", "2mm", "-o", str(dxf), "-o", str(svg)]) == 0
    view = output_of(BOX, tmp_path, "view")
    parts = dxf_parts(dxf)
    assert len(parts) == 6
    sheet = shapely_box(0, 0, 300, 200)
    names = list(parts)
    for i, a in enumerate(names):
        assert sheet.contains(parts[a])
        orig = next(p for p in view.parts if "CUT-" + p.name == a)
        assert parts[a].area == pytest.approx(orig.area, abs=0.05)    # sampled arcs
        for b in names[i + 1:]:
            assert parts[a].intersection(parts[b]).area <= 1e-9
    loops = read_svg_loops(svg)
    assert len(loops) == sum(len(p.loops) for p in view.parts)
    head = svg.read_text()[:600]
    assert 'width="300mm"' in head and 'height="200mm"' in head


def test_parts_that_do_not_fit_go_on_more_sheets(tmp_path, capsys):
    prog = write(tmp_path, "box", BOX)
    out = tmp_path / "cut.svg"
    assert main(["render", str(prog), "--layout", "sheet", "--sheet", "100x100mm",
                 "--gap", "1mm", "-o", str(out)]) == 0
    files = sorted(tmp_path.glob("cut-*.svg"))
    assert len(files) >= 3 and not out.exists()
    assert "on %d sheets" % len(files) in capsys.readouterr().out
    ids = [i for f in files for i in re.findall(r'<g class="solid"[^>]*id="(part-[^"]+)"',
                                                f.read_text())]
    assert sorted(ids) == sorted("part-box_" + n for n in
                                 ("bottom", "lid", "front", "back", "left", "right"))
    from aidl_lang.output.fabrication.layout import lay_out
    view = output_of(BOX, tmp_path)
    sheets, _ = lay_out(view, (100.0, 100.0), 1.0, (0.0, 90.0))
    check_sheets(sheets, view, 100.0, 100.0, 1.0)


MIXED = """
units mm
assembly kit {
    solid plate {
        thickness 3 mm
        body = Rectangle(center=(0, 0), width=60, height=40)
    }
    solid spacer {
        thickness 6 mm
        body = Rectangle(center=(80, 0), width=20, height=20)
    }
    solid plate2 {
        thickness 3 mm
        body = Rectangle(center=(0, 60), width=30, height=30)
    }
}
"""


def test_each_sheet_holds_one_material_thickness(tmp_path, capsys):
    """Parts of 3 mm and 6 mm stock are never nested on one sheet (a laser cuts one material
    at a time), though all would fit on one: the 3 mm parts on sheet 1, the spacer on sheet
    2, each sheet's title and the note saying which."""
    prog = write(tmp_path, "kit", MIXED)
    out = tmp_path / "cut.svg"
    assert main(["render", str(prog), "--layout", "sheet", "--sheet", "200x150mm",
                 "-o", str(out)]) == 0
    assert "on 2 sheets of 200 x 150 mm (3 mm: sheet 1; 6 mm: sheet 2)" in capsys.readouterr().out
    one, two = (tmp_path / "cut-1.svg").read_text(), (tmp_path / "cut-2.svg").read_text()
    ids = [re.findall(r'<g class="solid"[^>]*id="(part-[^"]+)"', t) for t in (one, two)]
    assert sorted(ids[0]) == ["part-kit_plate", "part-kit_plate2"] and ids[1] == ["part-kit_spacer"]
    assert "<title>kit (sheet 1 of 2), 3 mm material</title>" in one
    assert "<title>kit (sheet 2 of 2), 6 mm material</title>" in two
    from aidl_lang.output.fabrication.layout import lay_out
    view = output_of(MIXED, tmp_path)
    sheets, _ = lay_out(view, (200.0, 150.0), 3.0, (0.0, 90.0))
    check_sheets(sheets, view, 200.0, 150.0, 3.0)
    assert [sorted({p.thickness for p in sh.parts}) for sh in sheets] == [[3.0], [6.0]]


def test_a_part_larger_than_the_sheet_is_an_error_naming_it(tmp_path, capsys):
    prog = write(tmp_path, "box", BOX)
    assert main(["render", str(prog), "--layout", "sheet", "--sheet", "70x70mm",
                 "-o", str(tmp_path / "c.svg")]) == 1
    err = capsys.readouterr().err
    assert "part `box.bottom` (80 x 60 mm) is larger than the 70 x 70 mm sheet" in err, err
    assert "Traceback" not in err and not list(tmp_path.glob("*.svg"))


def test_a_layout_error_suggests_only_what_helps(tmp_path):
    """A 100 x 80 part on a 50 x 50 sheet: no angle fits it, so no `--rotate any`; it is
    larger in both orders, and the sheet that holds it is named (issue 86). On 90 x 120 at
    0 degrees turning it fits; on 200 x 82 only a smaller gap does."""
    import aidl_lang
    from aidl_lang.output.fabrication.layout import LayoutError
    r = aidl_lang.compile(source="units mm\nsolid plate { body = Rectangle(center=(0, 0), "
                                 "width=100, height=80) }\n")

    def said(sheet, rotate):
        with pytest.raises(LayoutError) as e:
            r.layout(sheet, 3.0, rotate)
        return str(e.value)

    text = said((50.0, 50.0), (0.0, 90.0))
    assert "in both orders" in text and "--rotate any" not in text and "--gap" not in text
    assert "--sheet 87x107mm" in text
    r.layout((87.0, 107.0), 3.0, (0.0, 90.0))          # the sheet it names holds it
    text = said((90.0, 120.0), (0.0,))
    assert "--rotate any" in text and "in both orders" not in text
    text = said((200.0, 82.0), (0.0,))
    assert "a smaller --gap" in text and "--rotate any" not in text


def test_free_rotation_and_rigid_motions_are_exact(tmp_path):
    from aidl_lang.output.fabrication.layout import Motion, lay_out
    view = output_of(CLOCK, tmp_path)
    sheets, _ = lay_out(view, (200.0, 200.0), 0.0, None)
    check_sheets(sheets, view, 200.0, 200.0, 0.0)
    m = Motion(90.0, (1.0, 2.0), (10.0, 20.0))
    assert m.point((2.0, 2.0)) == (10.0, 21.0)          # exact at multiples of 90 degrees
    from aidl_lang.geometry.shapes.curves import Arc
    a = m.segment(Arc((2.0, 2.0), 3.0, 0.25, 1.0))
    assert a.center == (10.0, 21.0) and a.radius == 3.0 and a.sweep == 1.0
    assert a.start_angle == pytest.approx(0.25 + math.pi / 2, abs=1e-15)


def test_missing_nesting_library_is_exit_2_with_the_install_line(tmp_path, capsys,
                                                                  monkeypatch):
    monkeypatch.setitem(sys.modules, "spyrrow", None)
    prog = write(tmp_path, "box", BOX)
    assert main(["render", str(prog), "--layout", "sheet", "-o", str(tmp_path / "c.svg")]) == 2
    assert "pip install 'aidl-lang[layout]'" in capsys.readouterr().err


def test_layout_options_without_layout_are_usage_errors(tmp_path, capsys):
    prog = write(tmp_path, "box", BOX)
    assert main(["render", str(prog), "--sheet", "10x10mm", "-o", str(tmp_path / "c.svg")]) == 2
    assert main(["render", str(prog), "--layout", "sheet", "--sheet", "big",
                 "-o", str(tmp_path / "c.svg")]) == 2
    assert main(["render", str(prog), "--layout", "sheet", "--rotate", "sideways",
                 "-o", str(tmp_path / "c.svg")]) == 2
    assert main(["render", str(prog), "--kerf=-1mm", "-o", str(tmp_path / "c.svg")]) == 2
    assert "Traceback" not in capsys.readouterr().err


# ------------------------------------------------------------------ kerf
PLATE = """
units mm
solid plate {
    body = Rectangle(center=(0, 0), width=20, height=20)
    hole bore {
        c = Circle(center=(0, 0), diameter=10)
    }
}
"""


def _check_kerf_dxf(path):
    ents = read_dxf(path)
    (outer,) = [e for e in ents if e.dxftype == "LWPOLYLINE"]
    (circle,) = [e for e in ents if e.dxftype == "CIRCLE"]
    assert abs(circle.segments[0].radius - 4.9) <= 1e-9
    xs = [p[0] for s in outer.segments for p in (s.start, s.end)]
    ys = [p[1] for s in outer.segments for p in (s.start, s.end)]
    assert abs(max(xs) - min(xs) - 20.2) <= 1e-9 and abs(max(ys) - min(ys) - 20.2) <= 1e-9
    arcs = [s for s in outer.segments if isinstance(s, A)]
    lines = [s for s in outer.segments if isinstance(s, L)]
    assert len(arcs) == 4 and len(lines) == 4
    for a in arcs:
        assert abs(a.radius - 0.1) <= 1e-9
        assert abs(abs(a.sweep) - math.pi / 2) <= 1e-9
        assert abs(abs(a.center[0]) - 10) <= 1e-9 and abs(abs(a.center[1]) - 10) <= 1e-9
    for s in lines:
        assert abs(s.length - 20) <= 1e-9


def test_api_writes_the_programs_kerf_as_render_does(tmp_path):
    """`aidl_lang.compile(...).to_dxf()` / `write` / `encode` apply the program's `kerf` to the
    cutting formats as `aidl render` does (they used to ignore it); `kerf=` overrides it, 0 is
    none; STL keeps the designed size."""
    import aidl_lang
    prog = write(tmp_path, "plate", "kerf 0.2 mm\n" + PLATE)
    r = aidl_lang.compile(path=prog)
    api_dxf = tmp_path / "api.dxf"
    api_dxf.write_text(r.to_dxf())
    _check_kerf_dxf(api_dxf)
    r.write(tmp_path / "w.dxf")
    _check_kerf_dxf(tmp_path / "w.dxf")
    cli_svg = tmp_path / "cli.svg"
    assert main(["render", str(prog), "-o", str(cli_svg)]) == 0
    assert r.to_svg() == cli_svg.read_text()
    for kerf, radius in ((0, 5.0), (0.4, 4.8)):
        (tmp_path / "k.dxf").write_text(r.to_dxf(kerf=kerf))
        (circle,) = [e for e in read_dxf(tmp_path / "k.dxf") if e.dxftype == "CIRCLE"]
        assert abs(circle.segments[0].radius - radius) <= 1e-9
    assert r.encode("stl") == aidl_lang.compile(source=PLATE, path=prog).encode("stl")


@pytest.mark.parametrize("how", ["option", "statement"])
def test_kerf_offsets_cuts_exactly_dxf_and_svg(how, tmp_path):
    src = PLATE if how == "option" else "kerf 0.2 mm\n" + PLATE
    prog = write(tmp_path, "plate", src)
    dxf, svg, laser = tmp_path / "p.dxf", tmp_path / "p.svg", tmp_path / "l.svg"
    extra = ["--kerf", "0.2mm"] if how == "option" else []
    assert main(["render", str(prog), *extra, "-o", str(dxf), "-o", str(svg)]) == 0
    assert main(["render", str(prog), *extra, "--svg-style", "laser", "-o", str(laser)]) == 0
    _check_kerf_dxf(dxf)
    for path in (svg, laser):
        loops = read_svg_loops(path)
        assert len(loops) == 2
        outer = max(loops, key=len)
        inner = min(loops, key=len)
        rs = [s.radius for s in inner if isinstance(s, (A, C))]
        assert rs and all(abs(r - 4.9) <= SVG_TOL for r in rs)
        xs = [p[0] for s in outer for p in (s.start, s.end)]
        assert abs(max(xs) - min(xs) - 20.2) <= SVG_TOL
        arcs = [s for s in outer if isinstance(s, A)]
        assert len(arcs) == 4 and all(abs(a.radius - 0.1) <= SVG_TOL for a in arcs)


def test_kerf_on_arcs_and_concave_corners(tmp_path):
    """Arcs stay arcs with the radius changed by half the kerf; a concave corner is joined
    where the offset lines cross; the offset outline lies kerf/2 from the design (shapely)."""
    from aidl_lang.output.fabrication.layout import compensate
    src = """
units mm
solid ell {
    body = Polygon(points=[(0, 0), (30, 0), (30, 10), (10, 10), (10, 30), (0, 30)])
    tab = Circle(center=(30, 5), radius=5)
    hole slot {
        s = Slot(start=(3, 15), end=(3, 25), width=3)
    }
}
"""
    view = output_of(src, tmp_path)
    k = compensate(view, 0.4)
    (p0,), (p1,) = view.parts, k.parts
    r0 = sorted(round(s.radius, 9) for lp in p0.loops for s in lp.segments if hasattr(s, "radius"))
    r1 = sorted(round(s.radius, 9) for lp in p1.loops for s in lp.segments
                if hasattr(s, "radius") and abs(s.radius - 0.2) > 1e-9)
    assert r1 == sorted([1.3, 1.3, 5.2])  and r0 == [1.5, 1.5, 5.0]
    a = shapely.union_all([Polygon(lp.points()) for lp in p0.loops if not lp.is_hole])
    a = a.difference(shapely.union_all([Polygon(lp.points()) for lp in p0.loops if lp.is_hole]))
    b = shapely.union_all([Polygon(lp.points()) for lp in p1.loops if not lp.is_hole])
    b = b.difference(shapely.union_all([Polygon(lp.points()) for lp in p1.loops if lp.is_hole]))
    grown = a.buffer(0.2, quad_segs=64)
    assert b.symmetric_difference(grown).area < 0.05       # chords only
    assert b.hausdorff_distance(grown) < 0.006
    # the concave corner at (10, 10) is a sharp join at (10.2, 10.2)
    pts = [s.start for lp in p1.loops for s in lp.segments]
    assert any(math.dist(p, (10.2, 10.2)) < 1e-9 for p in pts)


def test_kerf_larger_than_a_feature_is_a_clear_error(tmp_path, capsys):
    src = PLATE.replace("diameter=10", "diameter=0.4")
    prog = write(tmp_path, "plate", src)
    assert main(["render", str(prog), "--kerf", "0.5mm", "-o", str(tmp_path / "p.dxf")]) == 1
    err = capsys.readouterr().err
    assert "kerf 0.5 mm on part `plate`" in err and "radius 0.2 mm" in err


# ------------------------------------------------------------------ assembly view
def test_assembly_view_colours_each_part_and_names_it(tmp_path):
    from aidl_lang.output.part.part import PALETTE
    from aidl_lang.output.writers.svg import to_svg
    svg = to_svg(output_of(BOX, tmp_path))
    groups = re.findall(r'<g class="solid" fill="([^"]+)" fill-opacity="([^"]+)" '
                        r'id="part-([^"]+)" stroke="([^"]+)"><title>([^<]+)</title>', svg)
    assert len(groups) == 6
    assert [g[0] for g in groups] == list(PALETTE[:6]) and all(g[0] == g[3] for g in groups)
    assert all(0 < float(g[1]) < 0.5 for g in groups)
    assert [g[4] for g in groups] == ["box." + n for n in
                                      ("bottom", "lid", "front", "back", "left", "right")]
    laser = to_svg(output_of(BOX, tmp_path), style="laser")
    assert 'stroke="#ff0000"' in laser and not any(c in laser for c in PALETTE[:6])
    single = to_svg(output_of(PLATE, tmp_path))
    assert "<title>plate" not in single.split("<g", 1)[1] and "fill-opacity" not in single and "#cfd8dc" in single


# ------------------------------------------------------------------ parts list
def test_parts_lists_paths_sizes_holes_and_copies(tmp_path, capsys):
    prog = write(tmp_path, "box", BOX)
    assert main(["parts", str(prog), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["unit"] == "mm"
    rows = {r["path"]: r for r in doc["parts"]}
    assert set(rows) == {"box." + n for n in ("bottom", "lid", "front", "back", "left", "right")}
    assert rows["box.front"]["copies"] == 2 and rows["box.back"]["shape"] == rows["box.front"]["shape"]
    assert rows["box.left"]["copies"] == 2 and rows["box.lid"]["copies"] == 1
    assert rows["box.bottom"]["copies"] == 1        # same size as the lid, but no grip hole
    assert rows["box.front"]["holes"] == 1 and rows["box.bottom"]["holes"] == 0
    assert rows["box.front"]["area"] == pytest.approx(80 * 40 - math.pi * 64, abs=1e-9)
    assert rows["box.bottom"]["bbox"] == pytest.approx([-40, -30, 40, 30], abs=1e-9)
    assert rows["box.front"]["thickness"] == 3.0
    assert main(["parts", str(prog)]) == 0
    text = capsys.readouterr().out
    assert "width mm" in text and "6 parts, 4 shapes" in text


def test_the_laser_box_example_checks_clean_and_lays_out(tmp_path):
    from conftest import EXAMPLES
    from aidl_lang.output.fabrication.layout import lay_out
    path = next(p for p in EXAMPLES if p.stem == "laser_box")
    view = output_of(path.read_text(), tmp_path, "laser_box")      # no warnings
    assert len(view.parts) == 6
    sheets, dropped = lay_out(view, (300.0, 200.0), 3.0, (0.0, 90.0))
    assert len(sheets) == 1 and dropped == 0
    check_sheets(sheets, view, 300.0, 200.0, 3.0)
    assert len(sheets[0].engrave) == len(view.engrave) > 0     # the lid's label went along


@pytest.mark.timing
def test_nest_time_is_added_to_the_wall_budget(tmp_path, monkeypatch, capsys, cpu_clock):
    """`--nest-time S` is the nesting's own time limit, on top of the compile's wall budget:
    a packer that uses its whole S (here the real plan, then S more seconds counted as spent:
    the deadline moved that much nearer, as a clock would have) does not leave the writers
    after it out of budget (E0304).  (A real wait of 4 s against a 3 s budget raced the
    compile on a loaded machine; the budget counts CPU seconds here, ``cpu_clock``.)"""
    from aidl_lang.output.fabrication import layout
    real = layout.plan

    def full_time(output, sheet, gap, rotate, seconds, *a, deadline=None, **k):
        where = real(output, sheet, gap, rotate, 0, *a, deadline=deadline, **k)
        deadline.at -= seconds                 # S seconds spent nesting
        return where
    monkeypatch.setattr(layout, "plan", full_time)
    prog = write(tmp_path, "box", BOX)
    out = tmp_path / "cut.svg"
    # the default 15 s of wall time; the nesting spends 20 s of its own
    assert main(["render", str(prog), "--layout", "sheet", "--sheet", "300x200mm",
                 "--nest-time", "20", "-o", str(out)]) == 0, capsys.readouterr().err
    assert out.read_text().count("<svg") == 1


@pytest.mark.timing
def test_a_nesting_that_cannot_end_in_time_is_refused_before_it_starts(monkeypatch, cpu_clock):
    """spyrrow cannot be stopped: 2,000 parts took 20 s past the 15 s budget and were blamed
    on the SVG writer.  The nesting is estimated (its shapes and parts: ``nest_seconds``) and
    refused as "the layout"."""
    import time
    from aidl_lang.base.limits import DEFAULT_BUDGET, Deadline
    from aidl_lang.output import build
    from aidl_lang.output.fabrication.layout import nest_seconds, plan
    from aidl_lang.output.part.part import OutputError
    from aidl_lang.pipeline import compile_source, report_out_of_budget
    n = 120
    # each part a shape of its own (no copies: widths 20.0, 20.1, ...)
    rows = "\n".join(f"    solid p{i} {{ body = Rectangle(center=({i * 30}, 0), "
                     f"width={20 + i / 10:g}, height=10) }}" for i in range(n))
    res = compile_source(f"units mm\nassembly parts {{\n{rows}\n}}\n", "many.aidl")
    assert res.ok
    out = build(res.drawing, res.model.root.name)
    from aidl_lang.output.fabrication import layout
    nested = []
    real_nest = layout._nest

    def nest(*a, **kw):
        nested.append(len(a[0]))
        return real_nest(*a, **kw)
    monkeypatch.setattr(layout, "_nest", nest)
    # CPU seconds (cpu_clock): the deadline is half the estimate after the same work, however
    # busy the machine (a wall deadline could pass before the estimate is even asked)
    from aidl_lang.base.limits import Work, seconds_as_work
    soon = Deadline(budget_clock() + 600, DEFAULT_BUDGET,     # work units: half the estimate
                    work=Work(0.5 * seconds_as_work(nest_seconds([4] * n, n))))
    with pytest.raises(OutputError) as e:
        plan(out, deadline=soon)
    assert nested == []                           # refused before spyrrow ran
    assert e.value.budget.stage == "the layout" and e.value.budget.where.path == "parts"
    report_out_of_budget(res.sink, e.value.budget)
    d = res.sink.items[-1]
    assert d.code == "E0304" and d.span.line == 2
    assert "in the layout of `parts`" in d.message and f"{n} parts" in str(e.value)
    # the same parts with time to spare are laid out (and the first few alone)
    later = Deadline(budget_clock() + 600, DEFAULT_BUDGET)
    few = build(compile_source("units mm\nassembly parts {\n" + "\n".join(rows.split("\n")[:3])
                               + "\n}\n", "few.aidl").drawing, "model")
    assert sum(len(s) for s in plan(few, deadline=later)) == 3


COPIES = """units mm
assembly a {
  for i in range(1000) {
    solid s {
      r = Rectangle(center=(i * 12, 0), width=10, height=6)
      hole h { c = Circle(center=(i * 12, 0), radius=1.5) }
    }
  }
}
"""


@pytest.mark.timing
def test_a_sheet_of_1000_copies_is_laid_out_within_the_default_budget(tmp_path, monkeypatch,
                                                                       capsys, cpu_clock):
    """Issue 74: 1,000 copies of a 10 x 6 mm plate were refused before nesting (E0304: the
    nesting estimated at 1.5e-4 s x parts² = 150 s), and given to the packer as 1,000 shapes
    it took 2.7 s of CPU.  Copies are now one shape with a demand of 1,000 (prepared once:
    0.6 s) and the estimate is linear in shapes and parts: `aidl render --layout sheet` ends
    ok within the default budget (counted in CPU seconds, ``cpu_clock``), one nesting of one
    shape, every part on the sheet, the gap kept (the DXF re-read)."""
    from shapely import STRtree
    from aidl_lang.output.fabrication import layout
    given = []
    real = layout._nest

    def nest(shapes, height, angles, seconds, seed, demand=None):
        given.append((len(shapes), sum(demand.values()) if demand else len(shapes)))
        return real(shapes, height, angles, seconds, seed, demand)
    monkeypatch.setattr(layout, "_nest", nest)
    prog = write(tmp_path, "copies", COPIES)
    out = tmp_path / "sheet.dxf"
    assert main(["render", str(prog), "--layout", "sheet", "-o", str(out)]) == 0, \
        capsys.readouterr().err
    assert "laid out 1000 parts on 1 sheet of 600 x 400 mm" in capsys.readouterr().out
    assert given == [(1, 1000)]                 # one shape, 1,000 copies, one nesting
    parts = dxf_parts(out)
    assert len(parts) == 1000
    polys = list(parts.values())
    sheet = shapely_box(0, 0, 600, 400)
    hole = math.pi * 1.5 ** 2
    for p in polys:
        assert sheet.contains(p) and len(p.interiors) == 1
        assert p.area == pytest.approx(60 - hole, abs=1e-3)    # the hole sampled
    tree = STRtree(polys)
    near = tree.query(polys, predicate="dwithin", distance=3.0 - 1e-6)
    assert [(i, j) for i, j in near.T if i < j] == []           # 3 mm apart, no overlap


def test_a_design_with_no_solid_part_lays_out_nothing_and_says_so(tmp_path, capsys):
    """Issue 94: `aidl render text_on_arc.aidl --layout sheet -o x.svg` printed "laid out 0
    parts on 0 sheets ... wrote x-sheet.svg", exited 0 and wrote nothing; the studio served a
    22-byte ZIP of no entries.  A design of engraving alone has nothing to nest: an error that
    says so, no file, and a good file already there kept."""
    prog = tmp_path / "sign.aidl"
    prog.write_text('import "std/plates.aidl"\ndrawing sign = text_on_arc()\n')
    out = tmp_path / "x.svg"
    out.write_text("<svg>kept</svg>")
    assert main(["render", str(prog), "--layout", "sheet", "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert "nothing to lay out" in err and "no solid part" in err and "5 engraved lines" in err
    # located at the design, named as written (issue 95: it said "`model`", unlocated)
    assert "sign.aidl:2:16: error[E0502]" in err and "drawing `sign` has no solid part" in err
    assert "`model`" not in err
    assert out.read_text() == "<svg>kept</svg>"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sign.aidl", "x.svg"]
    from aidl_lang.studio.compiler import download
    got = download(str(tmp_path), prog.read_text(), {}, "svg", {"layout": True})
    assert isinstance(got, dict) and "nothing to lay out" in got["error"], got
    assert "--" not in got["error"]                  # written for the page: no flag


def test_a_layout_of_loose_drawings_names_this_design_at_its_first_structure(tmp_path, capsys):
    """Two top-level drawings (the implicit root `model`): the error is at the first drawing's
    line, and says "this design", not the name no one wrote."""
    prog = tmp_path / "marks.aidl"
    prog.write_text('units mm\ndrawing a { t = Text("HI", position=(0, 0), size=5) }\n'
                    "drawing b { c = Circle(center=(20, 0), radius=4) }\n")
    assert main(["render", str(prog), "--layout", "sheet", "-o", str(tmp_path / "x.svg")]) == 1
    err = capsys.readouterr().err
    assert "marks.aidl:2:1: error[E0502]: nothing to lay out on a sheet: this design has no " \
        "solid part to cut, only 5 engraved lines" in err
    assert "`model`" not in err and "hint: render it without `--layout`" in err
