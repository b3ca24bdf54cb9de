"""The public Python API (`aidl_lang.compile`, docs/api.md) and `aidl check --values`: solved
values in the file's units, parts, outputs and file safety, checked against the real writers
(the DXF re-read with ezdxf)."""
import io
import json
import os
import re
import subprocess
import sys

import ezdxf
import pytest

import aidl_lang
from aidl_lang.api import NotCompiled, WriteError
from conftest import ROOT

PLATE = ROOT / "examples" / "mounting_plate.aidl"

GOOD = """units in
param width = 4
solid plate {
    body = Rectangle(center=(0, 0), width=width, height=2)
    hole bore { c = Circle(center=(1, 0.5), radius=0.25) }
}
"""

BAD = """solid s {
    body = Rectangle(center=(0, 0), width=40, height=20)
    c = Circel(center=(0, 0), radius=5)
}
"""


def aidl(*args):
    env = dict(os.environ, NO_COLOR="1")
    env.pop("AIDL_DEBUG", None)
    return subprocess.run([sys.executable, "-m", "aidl_lang.cli", *map(str, args)],
                          capture_output=True, text=True, cwd=ROOT, env=env, timeout=120)


def test_compile_source_values_in_file_units():
    r = aidl_lang.compile(source=GOOD)
    assert r.ok and r.units == "in" and r.diagnostics == []
    assert r.value("plate.body.width").text() == "plate.body.width = 4.000 in"
    c = r.value("plate.bore.c.center")
    assert c.kind == "point" and c.value == pytest.approx((1, 0.5))
    assert c.mm == pytest.approx((25.4, 12.7))
    assert r.value("plate.bore.c.radius").mm == pytest.approx(6.35)
    assert r.value("plate.bbox").value == pytest.approx((-2, -1, 2, 1))
    assert [v.name for v in r.values_matching(["plate.bore"])] == [
        "plate.bore.origin", "plate.bore.bbox", "plate.bore.c.center", "plate.bore.c.radius"]
    with pytest.raises(KeyError, match="did you mean"):
        r.value("plate.bore.c.radiu")


def test_values_name_a_structures_numbers_and_points():
    """Template parameters and ``name = expression`` constants are values too (``aidl check
    --values pair.center_distance``): lengths in the file's unit, angles in degrees, points
    in the model frame (the structure's origin added)."""
    src = ("units inch\nsolid s {\n  b = Rectangle(center=(1, 0), width=2, height=1)\n"
           "  half = b.width / 2\n  k = 3\n  a = 30 deg\n  p = b.center + (half, 0)\n}\n"
           "def pair(teeth1 = 12, module = 4 mm) -> assembly {\n"
           "  center_distance = module * (teeth1 + 20) / 2\n"
           "  g = Circle(center=(0, 0), radius=module)\n}\n"
           "assembly top {\n  t = pair(teeth1=10)\n  t.g.center == (1, 1)\n}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok, r.diagnostics
    assert r.value("s.half").text() == "s.half = 1.000 in"
    assert r.value("s.half").mm == pytest.approx(25.4)
    assert (r.value("s.k").kind, r.value("s.k").value, r.value("s.k").unit) == ("number", 3, "")
    assert r.value("s.a").text() == "s.a = 30.000 deg"
    assert r.value("s.p").value == pytest.approx((2, 0))
    assert r.value("top.t.center_distance").mm == pytest.approx(4 * 30 / 2)
    assert r.value("top.t.teeth1").value == 10
    # a structure: its origin, its geometry, then its named numbers
    assert [v.name for v in r.values_matching(["top.t"]) if v.kind != "box"][:2] == [
        "top.t.origin", "top.t.g.center"]


def test_values_name_the_files_params_and_constants():
    """A file's top-level params and constants are values too, first, in the file's unit and
    with ``--set`` overrides applied (they were missing: only structures were listed)."""
    src = ("units cm\nparam width = 4 cm\nlength = width * 2 + 1 cm\nturn = 15 deg\n"
           "solid plate { body = Rectangle(center=(0, 0), width=width, height=length) }\n")
    r = aidl_lang.compile(source=src, overrides={"width": "5cm"})
    assert r.ok, r.diagnostics
    assert [v.text() for v in r.values[:3]] == [
        "width = 5.000 cm", "length = 11.000 cm", "turn = 15.000 deg"]
    assert r.value("length").mm == pytest.approx(110)
    assert r.value("plate.body.height").mm == pytest.approx(110)


def test_parts_and_overrides():
    r = aidl_lang.compile(source=GOOD, overrides={"width": 6})
    [p] = r.parts
    assert p.name == "plate" and p.kind == "solid" and p.holes == 1 and p.loops == 2
    assert p.bbox == pytest.approx((-76.2, -25.4, 76.2, 25.4))
    assert p.area == pytest.approx(6 * 2 * 25.4 ** 2 - 3.141592653589793 * 6.35 ** 2)


def test_errors_are_diagnostics_not_exceptions(tmp_path):
    r = aidl_lang.compile(source=BAD, path="bad.aidl")
    assert not r.ok
    [d] = r.errors
    assert d.code == "E0103" and d.span.line == 3 and d.fix.replacement == "Circle"
    assert r.diagnostics_json()[0]["span"]["file"] == "bad.aidl"
    with pytest.raises(NotCompiled):
        r.parts
    with pytest.raises(NotCompiled):
        r.to_svg()
    missing = aidl_lang.compile(path=tmp_path / "nope.aidl")
    assert not missing.ok and missing.errors[0].code == "E0004"
    with pytest.raises(TypeError):
        aidl_lang.compile()
    with pytest.raises(ValueError):
        aidl_lang.compile(source=GOOD, budget=0)
    assert aidl_lang.compile(source=GOOD, budget=2).ok


def test_outputs_and_write_safety(tmp_path):
    prog = tmp_path / "p.aidl"
    prog.write_text(GOOD)
    r = aidl_lang.compile(path=prog)
    assert r.to_svg().lstrip().startswith("<?xml") or "<svg" in r.to_svg()
    png = r.to_png(width=200)
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and int.from_bytes(png[16:20], "big") == 200
    out = r.write(tmp_path / "p.dxf")
    doc = ezdxf.read(io.StringIO(out.read_text()))
    [c] = doc.modelspace().query("CIRCLE")
    assert (c.dxf.center.x, c.dxf.center.y, c.dxf.radius) == pytest.approx((25.4, 12.7, 6.35))
    # a symlink is refused, its target untouched; with follow_symlinks written through
    target = tmp_path / "real.svg"
    target.write_text("old")
    link = tmp_path / "link.svg"
    link.symlink_to(target)
    with pytest.raises(WriteError, match="symbolic link"):
        r.write(link)
    assert target.read_text() == "old"
    r.write(link, follow_symlinks=True)
    assert link.is_symlink() and "<svg" in target.read_text()
    # a read-only file is refused unless forced
    ro = tmp_path / "ro.svg"
    ro.write_text("old")
    os.chmod(ro, 0o444)
    with pytest.raises(WriteError, match="read-only"):
        r.write(ro)
    assert ro.read_text() == "old"
    r.write(ro, force=True)
    assert "<svg" in ro.read_text()
    with pytest.raises(WriteError, match="extension"):
        r.write(tmp_path / "p.aidl")
    os.symlink(prog, tmp_path / "same.svg")
    with pytest.raises(WriteError, match="program being compiled"):
        r.write(tmp_path / "same.svg")
    assert prog.read_text() == GOOD
    with pytest.raises(WriteError, match="directory"):
        (tmp_path / "d.svg").mkdir()
        r.write(tmp_path / "d.svg")
    with pytest.raises(WriteError, match="extension"):
        r.write(tmp_path / "p.txt")
    with pytest.raises(ValueError):
        r.encode("bmp")


def _dxf_circles(path):
    doc = ezdxf.readfile(path)
    return sorted((round(c.dxf.center.x, 9), round(c.dxf.center.y, 9), round(c.dxf.radius, 9))
                  for c in doc.modelspace().query("CIRCLE"))


def test_check_values_match_the_dxf(tmp_path):
    """`aidl check --values` prints the corner holes where the DXF writer puts them."""
    out = aidl("check", PLATE, "--values", "plate.corner")
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()[1:]
    centers = {}
    radii = {}
    for ln in lines:
        m = re.fullmatch(r"(kit\.plate\.corner\[(\d)\]\.h)\.(center|radius) = (.*) mm", ln)
        if m:
            nums = [float(v) for v in re.findall(r"-?\d+\.\d+", m.group(4))]
            (centers if m.group(3) == "center" else radii)[m.group(2)] = nums
        else:
            assert re.fullmatch(r"kit\.plate\.corner\[\d\]\.(origin|bbox) = .* mm", ln), ln
    assert sorted(centers) == ["0", "1", "2", "3"]
    assert centers["0"] == [-52.0, -32.0] and radii["0"] == [2.5]
    dxf = tmp_path / "plate.dxf"
    assert aidl("render", PLATE, "-o", dxf).returncode == 0
    circles = _dxf_circles(dxf)
    # the exact values (JSON, full precision) against the DXF's circles, to 1e-6
    js = json.loads(aidl("check", PLATE, "--json", "--values", "plate.corner").stdout)
    assert js["units"] == "mm"
    vals = {v["name"]: v["mm"] for v in js["values"]}
    for i in range(4):
        cx, cy = vals[f"kit.plate.corner[{i}].h.center"]
        r = vals[f"kit.plate.corner[{i}].h.radius"]
        assert any(abs(cx - x) < 1e-6 and abs(cy - y) < 1e-6 and abs(r - rr) < 1e-6
                   for x, y, rr in circles), (i, cx, cy, r)


CORNERS = """solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole corner { c = Circle(center=(0, 0), diameter=6) }
    corners = CornerPattern(corner, body, inset=5)
    Fixed(body)
}
"""

# bottom_left (the original), bottom_right, top_right, top_left
CORNER_CENTRES = [(-25.0, -15.0), (25.0, -15.0), (25.0, 15.0), (-25.0, 15.0)]


def test_values_of_pattern_copies_give_their_geometry():
    """A pattern copy's values are its shapes' too, like any structure's (issue 37: a
    CornerPattern's copies gave only an origin and a box, so three of four hole centres
    could not be read)."""
    r = aidl_lang.compile(source=CORNERS)
    assert r.ok, r.diagnostics
    names = ["plate.corner"] + [f"plate.corners[{k}]" for k in (1, 2, 3)]
    for name, (x, y) in zip(names, CORNER_CENTRES):
        assert r.value(f"{name}.c.center").mm == pytest.approx((x, y), abs=1e-9), name
        assert r.value(f"{name}.c.radius").mm == pytest.approx(3.0, abs=1e-9), name
    assert [v.name for v in r.values_matching(["corners[2]"])] == [
        "plate.corners[2].origin", "plate.corners[2].bbox", "plate.corners[2].c.center",
        "plate.corners[2].c.radius"]


def test_check_values_of_pattern_copies(tmp_path):
    """`aidl check --values` prints every copy's centre and radius, as text and as JSON."""
    f = tmp_path / "corners.aidl"
    f.write_text(CORNERS)
    out = aidl("check", f, "--values", "plate.corner", "plate.corners")
    assert out.returncode == 0, out.stderr
    got = {}
    for ln in out.stdout.splitlines()[1:]:
        m = re.fullmatch(r"plate\.(corners?(?:\[\d\])?)\.c\.center = \((.*), (.*)\) mm", ln)
        if m:
            got[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    assert got == dict(zip(["corner", "corners[1]", "corners[2]", "corners[3]"],
                           CORNER_CENTRES)) | {"corners[0]": CORNER_CENTRES[0]}
    assert "plate.corners[3].c.radius = 3.000 mm" in out.stdout.splitlines()
    js = json.loads(aidl("check", f, "--json", "--values", "corners").stdout)
    vals = {v["name"]: v["mm"] for v in js["values"]}
    for k in (1, 2, 3):
        assert vals[f"plate.corners[{k}].c.center"] == pytest.approx(CORNER_CENTRES[k],
                                                                      abs=1e-9)


def test_check_values_unknown_name_and_errors():
    out = aidl("check", PLATE, "--values", "plate.nothing_here")
    assert out.returncode == 0 and "no value matches" in out.stderr
    bad = aidl("check", ROOT / "tests" / "programs" / "nonexistent.aidl", "--values")
    assert bad.returncode == 1 and "E0004" in bad.stderr


def test_the_facade_holds_only_the_promised_api():
    """Issue 37, "The code": the output-file safety code lives in aidl_lang.output.writers.write and
    the customizer's sliders in aidl_lang.serve.params; the facade re-exports only what
    docs/api.md promises (WriteError, loaded on first use: the output package is heavy)."""
    import aidl_lang
    import aidl_lang.api as api
    from aidl_lang.output.writers import write
    from aidl_lang.serve import params
    for gone in ("stage", "write_atomic", "planted_link", "check_output_path", "Param",
                 "declared_params", "default_span"):
        assert gone not in vars(api), gone
    assert set(api.__all__) == {"compile", "Result", "Value", "PartInfo", "Layout",
                                "NotCompiled", "WriteError", "set_params",
                                "ParamsRefused"} == set(aidl_lang.__all__)
    assert api.WriteError is write.WriteError is aidl_lang.WriteError is WriteError
    assert issubclass(WriteError, OSError)
    assert callable(params.declared_params) and callable(write.check_output_path)


def test_fit_sizes_and_layout_placements_as_data():
    """Issue 73: the assembled fit check as data (`Result.fit`: the W0517/W0518 figures),
    the sizes a maker reads (`Result.sizes`: diameters, corner radii) and where a sheet
    layout put each part (`Layout.placements`, `use`)."""
    short = aidl_lang.compile(source="""thickness 3 mm
assembly kit {
    solid base { r = Rectangle(center=(0, 0), width=40, height=40) }
    solid wall { r = Rectangle(center=(0, 0), width=40, height=20) }
    Place(wall, rotation=(90 deg, 0, 0), position=(0, 0, 13.25))
}""")
    fit = short.fit
    assert fit["checked"] and fit["collisions"] == []
    assert {(f["part"], f["nearest"]) for f in fit["floating"]} >= {("kit.base", "kit.wall")}
    assert all(f["gap"] == pytest.approx(0.25) for f in fit["floating"])
    thick = aidl_lang.compile(source='import "std/joints.aidl"\nthickness 3.5 mm\n'
                                     'assembly kit { box = finger_box(thickness=3 mm) }\n')
    hits = thick.fit["collisions"]
    # the bottom's joints (the walls' extra half millimetre lies outside: test_checks)
    assert len(hits) == 4 and all(h["depth"] == pytest.approx(0.5) for h in hits)
    assert len([d for d in thick.diagnostics if d.code == "W0517"]) == 4
    flat = aidl_lang.compile(source=PLATE_SIZES)
    assert flat.fit == {"checked": False, "collisions": [], "floating": []}
    got = {v.name: v.value for v in flat.sizes()}
    assert got["plate.bore.c.diameter"] == pytest.approx(8)
    assert got["plate.body.corner_radius"] == pytest.approx(3)
    assert got["plate.tab.corner_radius.top_left"] == pytest.approx(2)
    assert got["plate.tab.corner_radius.bottom_right"] == pytest.approx(0)
    assert "plate.bore.c.diameter" not in {v.name for v in flat.values}
    lay = flat.layout((200, 100), 3.0)
    [p] = lay.placements()
    assert p["part"] == "plate" and p["sheet"] == 1
    x0, y0, x1, y1 = p["bbox"]
    assert sorted([x1 - x0, y1 - y0]) == pytest.approx([30, 60])
    assert lay.use() == [pytest.approx(flat.parts[0].area / 20000, abs=1e-4)]


PLATE_SIZES = """units mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=60, height=30, corner_radius=3)
    hole bore { c = Circle(center=(10, 0), radius=4) }
    tab = RoundedRectangle(center=(-20, 0), width=10, height=10, corner_radii=[2, 1, 0, 1])
}
"""
