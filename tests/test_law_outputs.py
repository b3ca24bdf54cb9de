"""Law 2 (issue 109): every output is the same part.  The issue's case, a 200 mm countersink on
the 4.5 mm holes of an 80 x 50 plate, which wrote an STL, 3MF and GLB of 0 triangles (exit 0)
beside an SVG and DXF of the whole plate and a router G-code of cones: now E0503 at the call in
every format, through the real command line and the studio's download, nothing written (a good
file left as it was); a head through the part at a `--thickness` given to `aidl render` the
same; the router's countersink as wide at the top as the drawings' head where its V-bit would
go past the part (it was clamped: a 6 mm cone for a 9 mm head in 3 mm plywood); and the law
(`benchmarks/laws/law_outputs.py`: each format re-read by svgelements, ezdxf, pdfplumber,
gcodeparser, trimesh) over fixed programs, with the numbers that show it bites."""
from __future__ import annotations

import contextlib
import io
import math
from dataclasses import dataclass, field
from pathlib import Path

import pytest

import aidl_lang
from aidl_lang.cli.main import main

pytest.importorskip("gcodeparser")

from benchmarks.laws import law_outputs as law  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent

from test_checks_sinks import BORED, PLATE  # noqa: E402  (PLATE: four 4.5 mm holes, 9 mm heads, 6 mm)

BIG = PLATE.replace("diameter=9 mm)", "diameter=200 mm)")
GOOD = PLATE
THIN = GOOD.replace("thickness 6 mm", "thickness 3 mm")      # the V-bit goes 4.5 mm deep
BAR = """units mm
thickness 6 mm
solid bar {
    body = Rectangle(center=(0, 0), width=80, height=20)
    hole a { c = Circle(center=(-20, 0), diameter=4.5 mm) }
    hole b { c = Circle(center=(0, 0), diameter=4.5 mm) }
    hole e { c = Circle(center=(20, 0), diameter=4.5 mm) }
    Countersink([a, b, e], diameter=24 mm)
}
"""


@dataclass(frozen=True)
class Entry:
    """A corpus entry as `benchmarks/laws/corpus.py` gives it (the fields the law reads)."""
    name: str
    source: str
    path: str
    overrides: dict = field(default_factory=dict)
    kind: str = "tests"


def _run(*args) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(list(args))
    return rc, out.getvalue(), err.getvalue()


def test_the_200_mm_countersink_is_E0503_in_every_format_and_nothing_is_written(tmp_path):
    """The issue's plate: one `aidl render` of STL, 3MF, GLB, SVG and DXF exits 1 with E0503
    at the `Countersink` call (line 7, column 5), writes none of them, and leaves the STL a
    good compile wrote there before as it was; `aidl check` says the same."""
    f = tmp_path / "plate.aidl"
    f.write_text(GOOD)
    stl = tmp_path / "plate.stl"
    assert _run("render", str(f), "-o", str(stl))[0] == 0
    before = stl.read_bytes()
    assert len(before) > 84                     # a good plate: triangles
    f.write_text(BIG)
    outs = [tmp_path / f"plate.{x}" for x in ("stl", "3mf", "glb", "svg", "dxf")]
    args = [a for o in outs for a in ("-o", str(o))]
    rc, out, err = _run("render", str(f), *args)
    assert rc == 1 and "wrote" not in out
    assert f"{f}:7:5: error[E0503]: the countersinks of part `plate` leave nothing of it: " \
        "the 200 mm head on `plate.holes.c` (4.5 mm hole) goes through the 6 mm part, its " \
        "90 deg cone 188 mm wide at its bottom face" in err
    assert stl.read_bytes() == before
    assert [o.exists() for o in outs[1:]] == [False] * 4
    rc, _, err = _run("check", str(f))
    assert rc == 1 and "error[E0503]" in err


@pytest.mark.parametrize("fmt", ["svg", "gcode"])
def test_each_format_alone_refuses_it_too(tmp_path, fmt):
    f = tmp_path / "plate.aidl"
    f.write_text(BIG)
    o = tmp_path / f"plate.{fmt}"
    extra = ["--machine", "router"] if fmt == "gcode" else []
    rc, _, err = _run("render", str(f), "-o", str(o), *extra)
    assert rc == 1 and "error[E0503]" in err and not o.exists()


def test_the_studio_download_refuses_it(tmp_path):
    """The studio's STL download (and its assembled STL, `closed_stl`) compile through the
    same pipeline: an error with E0503, no file."""
    pytest.importorskip("starlette")
    from aidl_lang.studio.compiler import download
    for settings in ({}, {"assembled": True}):
        got = download(str(tmp_path), BIG, {}, "stl", settings)
        assert isinstance(got, dict), settings
        assert [d["code"] for d in got["diagnostics"]] == ["E0503"]
    data, name, _ = download(str(tmp_path), GOOD, {}, "stl", {})
    assert name.endswith(".stl") and len(data) > 84


def test_a_thickness_given_to_the_writers_is_judged_the_same(tmp_path):
    """Three 24 mm heads on a 20 mm bar: at the program's 6 mm they leave it whole (W0529 and
    written); at `--thickness 1mm` their cones are 22 mm wide at the bottom face and cut the
    bar into 6 pieces: E0503 at line 8, nothing written, the SVG neither."""
    f = tmp_path / "bar.aidl"
    f.write_text(BAR)
    rc, out, err = _run("render", str(f), "-o", str(tmp_path / "a.stl"))
    assert rc == 0 and "warning[W0529]" in err
    outs = [tmp_path / "b.stl", tmp_path / "b.svg"]
    rc, out, err = _run("render", str(f), "-o", str(outs[0]), "-o", str(outs[1]),
                        "--thickness", "1mm")
    assert rc == 1 and not any(o.exists() for o in outs)
    assert f"{f}:8:5: error[E0503]: the countersinks of part `bar` cut it into 6 pieces " \
        "(it is drawn in 1)" in err
    r = aidl_lang.compile(source=BAR.replace("thickness 6 mm", "thickness 1 mm"))
    assert [d.code for d in r.diagnostics if d.severity == "error"] == ["E0503"]


def test_the_router_sinks_a_countersink_as_wide_as_its_head_in_thin_stock():
    """A 9 mm head on a 4.5 mm hole in 3 mm stock: the 90 deg V-bit would go 4.5 mm deep, past
    the part; it was plunged to 3 mm, a 6 mm cone beside the drawings' 9 mm head.  Now its tip
    runs round a 3 mm circle at 3 mm deep: 2 (1.5 + 3) = 9 mm at the top, as the SVG's head
    (gcodeparser), and the mesh's volume is the plate's less four 2.25 mm deep cones."""
    r = aidl_lang.compile(source=THIN)
    assert r.ok
    text = r.encode("gcode", kerf=0, machine="router").decode()
    made = law.router_heads(text, 90.0, 3.175 / 2)
    drawn = law.svg_heads(r.encode("svg", kerf=0, style="laser"))
    assert sorted(made) == sorted(drawn) == sorted([(-30.0, -15.0), (30.0, -15.0),
                                                    (-30.0, 15.0), (30.0, 15.0)])
    assert all(made[p] == pytest.approx(9.0, abs=1e-9) and drawn[p] == 9.0 for p in made)
    assert law.compare(r) == []
    (s,) = law.expected(r.output)["solids"]
    cone = math.pi * 2.25 / 3 * (4.5 ** 2 + 4.5 * 2.25 + 2.25 ** 2) - math.pi * 2.25 ** 3
    assert law.sink_volume(s["heads"][0]) == pytest.approx(cone, rel=1e-12)


def test_the_law_bites():
    """An STL of 0 triangles, a mesh without its cones, and a loop moved 1e-5 mm in the DXF
    are each a violation."""
    r = aidl_lang.compile(source=GOOD)
    want = law.expected(r.output)
    import trimesh
    assert law.same_solid("stl", want, trimesh.Trimesh().export(file_type="stl")) == [
        "stl: 0 triangles for 1 solid parts"]
    plain = aidl_lang.compile(source=GOOD.replace("    Countersink(corners, diameter=9 mm)\n",
                                                  ""))
    (v,) = law.same_solid("stl", want, plain.encode("stl"))
    assert v.startswith("stl: volume 23619.4 mm³") and "less the heads is 23427.4 mm³" in v
    dxf = r.encode("dxf", kerf=0).decode().replace("\n2.25\n", "\n2.25001\n", 1)
    (v,) = law.same_loops("dxf", want, law.dxf_loops(dxf.encode()), law.TOL_2D)
    assert v.startswith("dxf: a loop's box is 1e-05 mm from the exact outline's")


@pytest.mark.parametrize("name", ["examples/mounting_plate", "examples/bracket",
                                  "examples/guitar_body", "examples/coat_hanger",
                                  "data/model_runs/issue105e/run/10_switch_plate"])
def test_the_law_holds_on_examples(name):
    """A fixed sample of examples/: lines and arcs (a plate, a bracket), splines (a guitar
    body), a part with a hole in its outline (a coat hanger); and a model's light-switch plate
    with two 7 mm countersinks, whose STL and 3MF read back as 97 torn bodies (the cones' tool
    met the holes' walls ring on ring 1e-10 mm apart): one watertight body now."""
    p = ROOT / f"{name}.aidl"
    assert law.check(Entry(f"{name}.aidl", p.read_text(), str(p))) == []


@pytest.mark.parametrize("src", [GOOD, BORED, BAR], ids=["countersinks", "counterbores",
                                                         "through"])
def test_the_law_holds_on_sunk_plates(tmp_path, src):
    f = tmp_path / "p.aidl"
    f.write_text(src)
    assert law.check(Entry("p.aidl", src, str(f))) == []


def test_a_program_that_does_not_compile_is_not_applicable(tmp_path):
    with pytest.raises(law.NotApplicable, match="E0503"):
        law.check(Entry("big.aidl", BIG, str(tmp_path / "big.aidl")))
