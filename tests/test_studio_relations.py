"""An imported drawing's inferred relations as the studio's sliders (issue 94,
aidl_lang/studio/relations/): a round flange opened as an editable design has a bolt circle
whose range follows the outline's diameter and the bore, so the holes follow a smaller flange
instead of breaking through its edge; a rectangular plate (a NEMA 17 mount's hole square
about its bore, a grid, corner holes) keeps its holes centred or at their inset and inside
its edges at any width and height; and a download is the design or an error, never an
empty file.

Every drawing is re-read by ezdxf (the outline, the bore and the holes as the DXF holds them).
Cost: four imports and about 60 compiles (about 4 s of CPU on a loaded 2-core machine).
"""
from __future__ import annotations

import io
import math
from collections import OrderedDict

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from aidl_lang.studio import compiler
from aidl_lang.studio.relations import WALL, with_relations
from maker_drawings import flange, lcd_panel, nema17, rpi

ezdxf = pytest.importorskip("ezdxf")


@pytest.fixture(scope="module")
def imported(tmp_path_factory):
    """The flange (100 mm, 40 mm bore, 8 holes of 8 mm on 75 mm) as the studio opens it."""
    folder = tmp_path_factory.mktemp("flange")
    (folder / "flange.dxf").write_bytes(flange())
    doc = compiler.import_upload(str(folder), "flange.dxf", True)
    assert "program" in doc, doc
    return str(folder), doc


def circles(data: bytes) -> list[tuple[float, float, float]]:
    """``(x, y, r)`` of every circle of a DXF download, the largest first."""
    d = ezdxf.read(io.StringIO(data.decode()))
    found = [(c.dxf.center.x, c.dxf.center.y, c.dxf.radius) for c in d.modelspace().query("CIRCLE")]
    return sorted(found, key=lambda c: -c[2])


def test_the_bolt_circle_follows_the_diameter(imported):
    folder, doc = imported
    src = doc["program"]
    assert any("bolt circle follows" in n for n in doc["notes"])
    assert "param bolt_circle_pcd = 75 mm, min = bore_d + bolt_circle_d + 2 mm, " \
           "max = diameter - bolt_circle_d - 2 mm" in src
    sessions = OrderedDict()
    view = compiler.view(sessions, "f", folder, src, {"diameter": "70mm"})
    assert view["ok"], view["diagnostics"]
    assert view["clamped"] == {"bolt_circle_pcd": pytest.approx(60)}       # 70 - 8 - 2 x 1
    assert not [d for d in view["diagnostics"] if d["severity"] == "warning"]
    data, name, _ = compiler.download(folder, src, view["values"], "dxf", {})
    (cx, cy, big), *rest = circles(data)
    assert big == pytest.approx(35) and len(rest) == 9                     # 8 holes, the bore
    holes = [c for c in rest if c[2] == pytest.approx(4)]
    assert len(holes) == 8
    for x, y, r in holes:           # on the 60 mm circle, 1 mm of material to the edge
        assert math.hypot(x - cx, y - cy) == pytest.approx(30)
        assert big - (math.hypot(x - cx, y - cy) + r) == pytest.approx(WALL)


def test_the_drawing_s_own_program_is_kept_when_nothing_is_related():
    text = "units mm\nparam width = 40 mm\nsolid s { r = Rectangle(center=(0, 0), width=width, height=20) }\n"
    assert with_relations(text) == (text, [])


@settings(max_examples=8, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(diameter=st.floats(18, 200), hole=st.floats(2, 16), bore=st.floats(10, 80),
       pcd=st.floats(19, 150), n=st.integers(1, 16))
def test_at_any_slider_values_the_holes_stay_inside(imported, diameter, hole, bore, pcd, n):
    """Whatever the sliders hold (each within its slider's span), the worker moves the
    dependent ones into their ranges and the DXF's holes are inside the outline, clear of the
    bore and of each other."""
    folder, doc = imported
    values = {"diameter": f"{diameter:.3f}mm", "bolt_circle_d": f"{hole:.3f}mm",
              "bore_d": f"{bore:.3f}mm", "bolt_circle_pcd": f"{pcd:.3f}mm", "bolt_circle_n": str(n)}
    view = compiler.view(OrderedDict(), "f", folder, doc["program"], values)
    assert view["ok"], [d["message"] for d in view["diagnostics"]]
    got = compiler.download(folder, doc["program"], view["values"], "dxf", {})
    assert not isinstance(got, dict), got
    (cx, cy, big), *rest = circles(got[0])
    v = {p["name"]: p["value"] for p in view["params"]}
    assert big == pytest.approx(v["diameter"] / 2)
    bore_r = v["bore_d"] / 2
    holes = [c for c in rest if not (c[2] == pytest.approx(bore_r) and
                                     math.hypot(c[0] - cx, c[1] - cy) < 1e-6)]
    assert len(holes) == v["bolt_circle_n"]
    for i, (x, y, r) in enumerate(holes):
        at = math.hypot(x - cx, y - cy)
        assert at + r <= big - WALL + 1e-6 and at - r >= bore_r + WALL - 1e-6
        for x2, y2, r2 in holes[i + 1:]:
            assert math.hypot(x - x2, y - y2) >= r + r2 + WALL - 1e-6


def test_a_download_of_nothing_is_an_error_not_an_empty_file(imported):
    """The flange as ``aidl import --infer`` writes it (no ranges) at 25 mm: its 40 mm bore
    removes all of it. Before: a 15 kB DXF of 0 entities and a 22-byte ZIP, both HTTP 200."""
    folder, _ = imported
    from aidl_lang.drawing.infer import import_drawing
    bare, _ = import_drawing(flange(), "flange.dxf", infer=True)
    for settings_ in ({}, {"layout": True}):
        got = compiler.download(folder, bare, {"diameter": "25mm"}, "dxf", settings_)
        assert isinstance(got, dict) and got["error"].startswith("nothing to make"), got
        assert "removes all of" in got["error"]
        assert got["diagnostics"][0]["code"] == "W0503"


def test_a_bolt_circle_off_the_body_s_centre_is_not_related():
    """The ranges hold only for a bolt circle about the outline's centre."""
    from aidl_lang.drawing.infer import import_drawing
    text, _ = import_drawing(flange(), "flange.dxf", infer=True)
    moved = text.replace("bore_c = (50, 50)", "bore_c = (60, 50)")
    assert moved != text and with_relations(moved) == (moved, [])
    assert with_relations(text)[1]


# ---------------------------------------------------------------- rectangular plates
def plate(width: float, height: float, holes, hole: float) -> bytes:
    """A ``width`` x ``height`` plate (its corner at the origin) with holes of diameter
    ``hole`` at ``holes``, as ezdxf writes it."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (width, 0), (width, height), (0, height)], close=True)
    for at in holes:
        m.add_circle(at, hole / 2)
    s = io.StringIO()
    doc.write(s)
    return s.getvalue().encode()


def corner_plate(width=80.0, height=50.0, inset=5.0, hole=3.4) -> bytes:
    """A hole at each corner, ``inset`` in from both edges."""
    return plate(width, height, [(x, y) for x in (inset, width - inset)
                                 for y in (inset, height - inset)], hole)


def grid_plate(width=80.0, height=70.0, pitch=25.0, hole=5.0) -> bytes:
    """2 columns x 3 rows of holes about the plate's centre, ``pitch`` apart both ways."""
    return plate(width, height, [(width / 2 + i * pitch / 2, height / 2 + j * pitch)
                                 for i in (-1, 1) for j in (-1, 0, 1)], hole)


@pytest.fixture(scope="module")
def plates(tmp_path_factory):
    """The NEMA 17 mount (60 x 60, a 22 mm bore, 4 holes of 3.4 mm on a 31 mm square about
    it), a grid without a bore (2 x 3 holes of 5 mm on 80 x 70) and the corner plate (80 x
    50, 3.4 mm holes 5 mm in), as the studio opens them (imported with --infer, related)."""
    folder = tmp_path_factory.mktemp("plates")
    out = {}
    for name, data in (("nema17", nema17()),
                       ("grid", grid_plate()),
                       ("corners", corner_plate()),
                       ("nema17_42", nema17(42.0, 42.0)),
                       ("rpi", rpi()),
                       ("lcd", lcd_panel())):
        (folder / f"{name}.dxf").write_bytes(data)
        doc = compiler.import_upload(str(folder), f"{name}.dxf", True)
        assert "program" in doc, doc
        out[name] = doc
    return str(folder), out


def outline_and_holes(data: bytes):
    """The plate's box ``(x0, y0, x1, y1)`` and its circles ``(x, y, r)`` as ezdxf reads a
    DXF download."""
    d = ezdxf.read(io.StringIO(data.decode()))
    m = d.modelspace()
    pts = [p for e in m.query("LWPOLYLINE") for p in e.get_points("xy")]
    box = (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts),
           max(p[1] for p in pts))
    return box, [(c.dxf.center.x, c.dxf.center.y, c.dxf.radius) for c in m.query("CIRCLE")]


def test_a_motor_mount_s_hole_square_stays_centred_and_inside(plates):
    """At 30 mm wide (drawn 60), the 31 mm hole square would reach 0.5 mm past both side
    edges (the program without its ranges: the four holes are notches in the outline,
    W0510); with them, the pitch
    follows to 24.5 (at most 30 - 3.4 - 2 x 1) and the bore to 19.1 (at most 19.18: clear of
    the holes by 1 mm), the square about the plate's centre."""
    folder, docs = plates
    doc = docs["nema17"]
    assert any("grid stays centred" in n for n in doc["notes"])
    src = doc["program"]
    assert "param width = 60 mm, min = 11.24 mm, max = 120 mm" in src
    view = compiler.view(OrderedDict(), "m", folder, src, {"width": "30mm"})
    assert view["ok"], view["diagnostics"]
    # onto the sliders' steps inside the ranges (bore 0.1 mm, pitch 0.2 mm from its min)
    assert view["clamped"] == {"bore_d": pytest.approx(19.1),
                               "motor_holes_pitch": pytest.approx(24.5)}
    assert not [d for d in view["diagnostics"] if d["severity"] == "warning"]
    box, circles = outline_and_holes(compiler.download(folder, src, view["values"], "dxf",
                                                       {})[0])
    assert box == pytest.approx((0, 0, 30, 60))
    holes = sorted(c for c in circles if c[2] == pytest.approx(1.7))
    assert [u for x, y, _ in holes for u in (x, y)] == pytest.approx(
        [2.75, 17.75, 2.75, 42.25, 27.25, 17.75, 27.25, 42.25])  # 24.5 apart about (15, 30)
    assert [c for c in circles if c[2] > 2] == [pytest.approx((15, 30, 9.55))]
    # 1.05 mm to the side edges, 1.05 mm from the bore's edge to each hole's
    from aidl_lang.drawing.infer import import_drawing
    bare, _ = import_drawing(nema17(), "nema17.dxf", infer=True)
    before = compiler.view(OrderedDict(), "b", folder, bare, {"width": "30mm"})
    assert [d["code"] for d in before["diagnostics"]] == ["W0510"]   # "now breaks through"
    got = compiler.download(folder, bare, {"width": "30mm"}, "dxf", {})
    box, circles = outline_and_holes(got[0])
    assert len(circles) == 1                        # the bore; the holes are notches now


def test_a_motor_face_s_corner_holes_keep_their_inset_and_clear_the_bore(plates):
    """The motor's own face, 42 x 42 mm: its four holes 5.5 mm in from the edges are read as
    corner holes (the import's rule), beside a 22 mm bore.  At 30 x 30 mm the bore's range
    follows to at most sqrt(2) (30 - 3.4 - 2) - 3.4 - 2.01 = 29.38 mm (22 stays) and the inset
    to at most 15 - (22 + 3.4 + 2) / (2 sqrt 2) = 5.313 mm (5.5 is moved there): 1 mm of
    material between each hole and the bore, as ezdxf reads the download.  Before, no
    relation was found (a bore beside corner holes): 0.73 mm of material at 30 x 30, and at
    26 x 26 the holes ran into the bore (W0508)."""
    folder, docs = plates
    doc = docs["nema17_42"]
    assert any("corner holes keep their inset" in n for n in doc["notes"]), doc["notes"]
    src = doc["program"]
    view = compiler.view(OrderedDict(), "q", folder, src, {"width": "30mm", "height": "30mm"})
    assert view["ok"], view["diagnostics"]
    v = {p["name"]: p["value"] for p in view["params"]}
    inset = 15 - (22 + 3.4 + 2) / (2 * math.sqrt(2))
    assert v["corner_inset"] <= inset + 1e-9 and v["corner_inset"] > inset - 0.1
    assert not [d for d in view["diagnostics"] if d["severity"] == "warning"]
    box, circles = outline_and_holes(compiler.download(folder, src, view["values"], "dxf",
                                                       {})[0])
    assert box == pytest.approx((0, 0, 30, 30))
    [bore] = [c for c in circles if c[2] == pytest.approx(11)]
    holes = [c for c in circles if c[2] == pytest.approx(1.7)]
    assert len(holes) == 4 and bore[:2] == pytest.approx((15, 15))
    for x, y, r in holes:
        assert min(x, 30 - x) == pytest.approx(v["corner_inset"])
        assert math.hypot(x - 15, y - 15) - r - 11 >= WALL - 1e-6


@settings(max_examples=10, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(name=st.sampled_from(["nema17", "grid", "corners", "nema17_42", "rpi"]),
       width=st.floats(0, 1), height=st.floats(0, 1), d=st.floats(0.8, 12),
       other=st.floats(1, 60), n=st.integers(1, 8))
def test_at_any_plate_size_the_holes_stay_inside_and_in_their_pattern(plates, name, width,
                                                                     height, d, other, n):
    """Whatever the sliders hold (the plate's width and height within their sliders' spans,
    given as fractions of them), the worker moves the dependent ones into their ranges and
    the DXF's holes are inside the plate by WALL, clear of each other (and of the bore); a
    grid is centred on the plate with cols x rows holes, corner holes sit at the inset from
    both edges they are nearest."""
    folder, docs = plates
    src = docs[name]["program"]
    rows = compiler.view(OrderedDict(), "p", folder, src, {})["params"]
    values = {p["name"]: f"{p['min'] + k * (p['max'] - p['min']):.3f}mm"
              for p, k in zip(rows[:2], (width, height))}
    for p in rows[2:]:                  # a count on its slider's steps
        values[p["name"]] = (
            str(int(p["min"] + (p["step"] or 1) * (n - 1))) if not p["unit"] else
            f"{d:.3f}mm" if p["name"].endswith("_d") and "bore" not in p["name"] else
            f"{other:.3f}mm")
    view = compiler.view(OrderedDict(), "p", folder, src, values)
    assert view["ok"], [x["message"] for x in view["diagnostics"]]
    v = {p["name"]: p["value"] for p in view["params"]}
    got = compiler.download(folder, src, view["values"], "dxf", {})
    assert not isinstance(got, dict), got
    (x0, y0, x1, y1), circles = outline_and_holes(got[0])
    assert (x1 - x0, y1 - y0) == pytest.approx((v["width"], v["height"]))
    bore = [c for c in circles if "bore_d" in v and c[2] == pytest.approx(v["bore_d"] / 2)
            and (c[0], c[1]) == pytest.approx(((x0 + x1) / 2, (y0 + y1) / 2))]
    holes = [c for c in circles if c not in bore]
    for i, (x, y, r) in enumerate(holes):
        assert min(x - x0, x1 - x, y - y0, y1 - y) >= r + WALL - 1e-6
        for x2, y2, r2 in holes[i + 1:] + bore:
            assert math.hypot(x - x2, y - y2) >= r + r2 + WALL - 1e-6
    counts = [v[k] for k in v if k.endswith(("_cols", "_rows"))]
    if counts:                          # odd both ways about a bore: none on the bore
        assert len(holes) == counts[0] * counts[1] - (bool(bore) and counts[0] * counts[1] % 2)
        mid = (sum(h[0] for h in holes) / len(holes), sum(h[1] for h in holes) / len(holes))
        if name == "rpi":               # its first column holes_x (drawn 8 mm) from the left edge
            assert (min(h[0] for h in holes) - x0, mid[1]) == \
                pytest.approx((v["holes_x"], (y0 + y1) / 2))
        else:
            assert mid == pytest.approx(((x0 + x1) / 2, (y0 + y1) / 2))
    else:
        inset = next(v[k] for k in v if k.endswith("inset"))
        assert len(holes) == 4
        for x, y, _ in holes:
            assert min(x - x0, x1 - x) == pytest.approx(inset)
            assert min(y - y0, y1 - y) == pytest.approx(inset)


def test_every_count_the_ranges_allow_keeps_the_holes_off_the_bore(plates, tmp_path):
    """Issue 92: the counts about a bore went by 2 on the slider, but `--set` (and MCP
    set_params) take any whole count, and 3 x 3 put the middle hole on the bore (W0508: it
    cuts nothing of its own).  The grid's loop now leaves that hole out (`if 2 * i != cols - 1
    or 2 * j != rows - 1`), so the counts go by 1: at 120 x 120 mm, pitch 27.5 mm, every
    cols x rows of 2..5 compiles without a warning and the DXF ezdxf reads has cols x rows
    holes (one fewer when both are odd), each 1 mm clear of the bore, the edges and each
    other.  16 compiles, about 1 s of CPU."""
    import aidl_lang
    _, docs = plates
    src = docs["nema17"]["program"]
    assert "if 2 * i != motor_holes_cols - 1 or 2 * j != motor_holes_rows - 1 {" in src
    assert any("left out" in n for n in docs["nema17"]["notes"])
    assert "param motor_holes_cols = 2, min = 2, max = min(16, floor((width" in src
    sizes = {"width": "120 mm", "height": "120 mm", "motor_holes_pitch": "27.5 mm"}
    for name in ("motor_holes_cols", "motor_holes_rows"):     # (120 - 5.4) / 27.41 + 1
        over = aidl_lang.compile(source=src, path=str(tmp_path / "m.aidl"),
                                 overrides={**sizes, name: "6"})
        assert [d.code for d in over.errors] == ["E0124"] and "range 2 .. 5" in \
            over.errors[0].message
    for cols in range(2, 6):
        for rows in range(2, 6):
            r = aidl_lang.compile(source=src, path=str(tmp_path / "m.aidl"), overrides={
                **sizes, "motor_holes_cols": str(cols), "motor_holes_rows": str(rows)})
            assert r.ok and not [d for d in r.diagnostics if d.severity != "info"], \
                (cols, rows, [d.message for d in r.diagnostics])
            box, found = outline_and_holes(r.to_dxf().encode())
            [bore] = [c for c in found if c[2] == pytest.approx(11)]
            holes = [c for c in found if c[2] == pytest.approx(1.7)]
            assert len(holes) == cols * rows - (cols * rows) % 2, (cols, rows)
            for i, (x, y, rad) in enumerate(holes):
                assert min(x - box[0], box[2] - x, y - box[1], box[3] - y) >= rad + WALL - 1e-6
                for x2, y2, r2 in holes[i + 1:] + [bore]:
                    assert math.hypot(x - x2, y - y2) >= rad + r2 + WALL - 1e-6


def test_a_pi_mount_s_holes_keep_their_edge_and_stay_inside(plates):
    """Issue 92: a grid off the plate's centre (a Raspberry Pi's four 2.7 mm holes, 58 x 49
    mm apart, the first column 8 mm from the left edge of a 160 x 70 plate, centred on its
    height) had no relation: at 40 mm wide its right column sat at x = 66, off the plate.
    Now the x pitch follows the width from the end member (at most 40 - 8 - 1.35 - 1 =
    29.65 mm: 29.2 on its step), the end's distance (a param since issue 114, holes_x = 8 mm)
    stays between holes_d / 2 + 1 mm and what the width leaves for one pitch, and the DXF
    ezdxf reads has the first column at x = 8 and the last 1 mm or more inside the right
    edge."""
    folder, docs = plates
    doc = docs["rpi"]
    assert any("keeps its end holes_x from the left edge and stays centred on the height" in n
               for n in doc["notes"]), doc["notes"]
    src = doc["program"]
    assert "param holes_x = 8 mm, min = holes_d / 2 + 1 mm, max = width - 3 * holes_d / 2 " \
           "- 2.02 mm" in src
    assert "holes_pitch_x = 58 mm, min = holes_d + 1 mm, max = (width - holes_x - holes_d / 2 " \
           "- 1 mm) / max(holes_cols - 1, 1)" in src
    view = compiler.view(OrderedDict(), "r", folder, src, {"width": "40mm"})
    assert view["ok"] and not [d for d in view["diagnostics"] if d["severity"] == "warning"]
    assert view["clamped"] == {"holes_pitch_x": pytest.approx(29.2)}
    box, circles = outline_and_holes(compiler.download(folder, src, view["values"], "dxf",
                                                       {})[0])
    assert box == pytest.approx((0, 0, 40, 70))
    assert sorted((round(x, 6), round(y, 6)) for x, y, _ in circles) == \
        [(8, 10.5), (8, 59.5), (37.2, 10.5), (37.2, 59.5)]
    assert 40 - max(x + r for x, _, r in circles) >= WALL


@pytest.mark.parametrize("name", ["nema17", "rpi"])
def test_the_related_program_sweeps_clean(plates, name, tmp_path):
    """`aidl check --sweep` over the ranges the studio wrote (ends, middles, a seeded Latin
    hypercube of combinations) finds nothing: before, the NEMA 17's bore at its max (width
    43.5, hole 9.9 mm: bore 19.69 mm) left its counts' range empty (min 2, max 1: the bore's
    bound and the count's fit cancelled their EPS, W0110 naming E0124).  About 1.5 s of CPU
    each."""
    from aidl_lang.params.sweep import sweep
    rep = sweep(plates[1][name]["program"], str(tmp_path / "main.aidl"))
    assert rep.ok and rep.skipped == 0 and rep.findings == [], \
        [f.diagnostic.message for f in rep.findings]


def _rect_gap(x, y, box) -> float:
    """How far the point (x, y) is outside the box ``(x0, y0, x1, y1)``."""
    return math.hypot(max(box[0] - x, 0, x - box[2]), max(box[1] - y, 0, y - box[3]))


@settings(max_examples=8, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(k=st.lists(st.floats(0, 1), min_size=8, max_size=8))
def test_an_lcd_bezel_keeps_its_window_and_screws_at_any_slider_values(plates, k):
    """Issue 92: an LCD panel (140 x 90, a 71 x 24 window 35 mm below the top edge, centred
    on the width, four 3 mm screws 75 x 31 apart round it: each 2.5 mm clear of the window's
    corner, though 0.5 mm of the window's side in x) had no relation: at 60 mm wide the screws
    and the window left the plate.  Now, at sliders anywhere in their spans (fractions ``k``
    of them, the dependent ones moved into their ranges), the DXF ezdxf reads has the window
    centred on the width and window_y (drawn 35 mm; a slider since issue 114) from the top,
    it and the four screws 1 mm inside the
    edges, each screw 1 mm clear of the window.  8 settings, about 1 s of CPU (80 outside
    the suite passed)."""
    folder, docs = plates
    doc = docs["lcd"]
    assert any("window_y from the top edge" in n for n in doc["notes"]), doc["notes"]
    src = doc["program"]
    rows = compiler.view(OrderedDict(), "l", folder, src, {})["params"]
    values = {p["name"]: f"{p['min'] + f * (p['max'] - p['min']):.3f}mm"
              for p, f in zip([p for p in rows if p["unit"]], k)}
    view = compiler.view(OrderedDict(), "l", folder, src, values)
    assert view["ok"], [x["message"] for x in view["diagnostics"]]
    assert not [x for x in view["diagnostics"] if x["severity"] == "warning"]
    v = {p["name"]: p["value"] for p in view["params"]}
    got = compiler.download(folder, src, view["values"], "dxf", {})
    d = ezdxf.read(io.StringIO(got[0].decode()))
    boxes = sorted(((min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts),
                     max(p[1] for p in pts)) for e in d.modelspace().query("LWPOLYLINE")
                    for pts in [list(e.get_points("xy"))]), key=lambda b: b[2] - b[0])
    window, plate = boxes
    assert plate == pytest.approx((0, 0, v["width"], v["height"]))
    assert ((window[0] + window[2]) / 2, (window[1] + window[3]) / 2) == \
        pytest.approx((v["width"] / 2, v["height"] - v["window_y"]))
    assert min(window[0], window[1], v["width"] - window[2], v["height"] - window[3]) \
        >= WALL - 1e-6
    screws = [(c.dxf.center.x, c.dxf.center.y, c.dxf.radius)
              for c in d.modelspace().query("CIRCLE")]
    assert len(screws) == 4
    for x, y, r in screws:
        assert min(x, y, v["width"] - x, v["height"] - y) >= r + WALL - 1e-6
        assert _rect_gap(x, y, window) >= r + WALL - 1e-6


def test_an_lcd_bezel_at_60_mm_keeps_its_screws_round_its_window(plates):
    """At 60 mm wide (drawn 140) the window follows to 57.75 mm (at most 60 - 2) and the
    screws' x pitch to 55 mm (at most 60 - 3 - 2); their y pitch stays 31 mm (at least 24 +
    2 x 2.5: the screws now above and below the window, 2 mm clear of it).  Without
    the ranges: the four screws lie off the plate (W0502) and the window cuts it in two."""
    folder, docs = plates
    view = compiler.view(OrderedDict(), "l", folder, docs["lcd"]["program"], {"width": "60mm"})
    assert view["ok"] and view["clamped"] == {"window_width": pytest.approx(57.75),
                                              "screw_holes_pitch_x": pytest.approx(55)}
    assert not [x for x in view["diagnostics"] if x["severity"] == "warning"]
