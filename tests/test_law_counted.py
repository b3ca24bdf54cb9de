"""Law 5 (issue 109): one thing is counted once.  The issue's plate, `Countersink([a, b, a.c,
a], diameter=9 mm)` with `Counterbore(a, ...)` and `Countersink(b, diameter=12 mm)`, was
accepted without a word: `aidl parts` said 4 countersinks (and a counterbore, and another
countersink) for a two-hole plate, the DXF engraved hole a's head three times, the router
plunged it again and again.  Now a hole named twice, or sunk again with the same head, is one
countersink, and sunk again with another head it is E0108 at the second call naming the first's
line; the law (`benchmarks/laws/law_counted.py`: `aidl parts --json`, the DXF by ezdxf, the
router's G-code by gcodeparser) over fixed programs, and the numbers that show it bites."""
from __future__ import annotations

import io

import pytest

import aidl_lang

pytest.importorskip("gcodeparser")

from benchmarks.laws import law_counted as law  # noqa: E402
from test_law_outputs import Entry, _run  # noqa: E402

HEAD = """units mm
thickness 6 mm
solid plate {
    body = Rectangle(center=(0, 0), width=60, height=40)
    hole a { c = Circle(center=(-15, 0), diameter=4.5) }
    hole b { c = Circle(center=(15, 0), diameter=4.5) }
"""
ISSUE = HEAD + """    Countersink([a, b, a.c, a], diameter=9 mm)
    Counterbore(a, diameter=8, depth=2)
    Countersink(b, diameter=12 mm)
}
"""
LISTED = HEAD + "    Countersink([a, b, a.c, a], diameter=9 mm)\n}\n"
AGAIN = HEAD + """    Countersink([a, b], diameter=9 mm)
    Countersink(a.c, diameter=9 mm, angle=90 deg)
    Counterbore(b, diameter=8 mm, depth=2 mm)
}
"""


def test_the_issue_plate_is_two_errors_naming_the_first_call(tmp_path):
    """The counterbore on a (line 8) and the 12 mm countersink on b (line 9): E0108 each, at
    the hole named, saying what sinks it already and on which line."""
    f = tmp_path / "plate.aidl"
    f.write_text(ISSUE)
    rc, _, err = _run("check", str(f))
    assert rc == 1
    assert (f"{f}:8:17: error[E0108]: `Counterbore` sinks hole `plate.a.c` a second time: "
            "`Countersink(diameter=9 mm, angle=90 deg)` sinks it already (line 7); a hole "
            "takes one countersink or counterbore") in err
    assert (f"{f}:9:17: error[E0108]: `Countersink` sinks hole `plate.b.c` a second time: "
            "`Countersink(diameter=9 mm, angle=90 deg)` sinks it already (line 7)") in err
    assert err.count("error[") == 2


@pytest.mark.parametrize("src", [LISTED, AGAIN.replace(
    "    Counterbore(b, diameter=8 mm, depth=2 mm)\n", "")], ids=["listed", "again"])
def test_a_hole_sunk_twice_alike_is_one_countersink_everywhere(tmp_path, src):
    """Hole a named three times in one list, or once more by a second call with the same head:
    `aidl parts` says 2 countersinks, the DXF's COUNTERSINK layer has 2 circles, the router
    plunges the V-bit once at each hole; no warning."""
    f = tmp_path / "plate.aidl"
    f.write_text(src)
    rc, out, err = _run("parts", str(f))
    assert rc == 0 and err == ""
    assert "plate: 2 countersinks, 4.5 mm holes, 9 mm heads at 90 deg, 2.25 mm deep" in out
    r = aidl_lang.compile(source=src, path=str(f))
    assert sorted(law.dxf_sink_circles(r.encode("dxf"))) == [(-15.0, 0.0), (15.0, 0.0)]
    text = r.encode("gcode", kerf=0, machine="router").decode()
    assert law.sink_plunges(text) == {(-15.0, 0.0): 1, (15.0, 0.0): 1}
    assert text.split("\nM0\n")[1].count("G1 Z-4.5") == 2     # after the tool change
    assert law.check(Entry("plate.aidl", src, str(f))) == []


def test_another_head_on_a_sunk_hole_is_E0108():
    r = aidl_lang.compile(source=AGAIN)
    (d,) = [d for d in r.diagnostics if d.severity == "error"]
    assert d.code == "E0108" and d.span.line == 9
    assert "`Counterbore` sinks hole `plate.b.c` a second time" in d.message
    r = aidl_lang.compile(source=AGAIN.replace("angle=90 deg", "angle=82 deg"))
    assert [(d.code, d.span.line) for d in r.diagnostics if d.severity == "error"] == [
        ("E0108", 8), ("E0108", 9)]


def test_the_law_bites():
    """The numbers of the defect as the law reads them: a countersink plunged three times at
    one place, and a head circle drawn twice on the DXF's layer."""
    text = "\n".join(["G21 G90", "M0", "M3 S18000"] + [
        "G0 X-15 Y0", "G1 F300", "G1 Z-4.5", "G0 Z5"] * 3 + ["G0 X15 Y0", "G1 Z-4.5", "G0 Z5"])
    assert law.sink_plunges(text) == {(-15.0, 0.0): 3, (15.0, 0.0): 1}
    import ezdxf
    doc = ezdxf.new()
    for _ in range(2):
        doc.modelspace().add_circle((-15, 0), 4.5, dxfattribs={"layer": "COUNTERSINK"})
    buf = io.StringIO()
    doc.write(buf)
    assert law.dxf_repeats(buf.getvalue().encode()) == [
        "DXF: a CIRCLE on layer COUNTERSINK is drawn more than once"]


@pytest.mark.parametrize("name", ["mounting_plate", "laser_box"])
def test_the_law_holds_on_examples(name):
    from pathlib import Path
    p = Path(__file__).resolve().parent.parent / "examples" / f"{name}.aidl"
    assert law.check(Entry(f"examples/{name}.aidl", p.read_text(), str(p))) == []


TWICE = """units mm
solid plate {
    body = Rectangle(center=(0, 60), width=80, height=40)
}
drawing marks {
    a = Line(start=(-30, 0), end=(-10, 0))
    b = Line(start=(-10, 0), end=(-30, 0))
    c = Line(start=(0, 0), end=(20, 0))
    d = Line(start=(10, 0), end=(30, 0))
    r = Circle(center=(0, 10), radius=3)
    s = Circle(center=(0, 10), radius=3)
    t = Arc(center=(-20, -10), radius=5, start_angle=0 deg, end_angle=180 deg)
    u = Arc(center=(-20, -10), radius=5, start_angle=90 deg, end_angle=270 deg)
}
"""


def test_an_engraving_drawn_twice_is_engraved_once(tmp_path):
    """A line drawn twice (either way round), two lines over half their length, a circle and
    two arcs of one circle overlapping by a quarter turn (the Bezier heart's handles in
    docs/language.md drew (0, 10)-(0, 15) twice and the DXF engraved it twice): the DXF's
    ENGRAVE layer holds each place once (ezdxf: 20 + 30 mm of lines, one circle, arcs over
    270 degrees), the SVG as much (svgelements' path lengths), and the law holds."""
    import math
    import ezdxf
    import svgelements
    r = aidl_lang.compile(source=TWICE)
    assert r.ok and not [d for d in r.diagnostics if d.severity != "note"], r.diagnostics
    doc = ezdxf.read(io.StringIO(r.encode("dxf").decode()))
    eng = [e for e in doc.modelspace() if e.dxf.layer == "ENGRAVE"]
    lines = sum(math.dist(e.dxf.start, e.dxf.end) for e in eng if e.dxftype() == "LINE")
    lines += sum(sum(math.dist(p, q) for p, q in zip(pts, pts[1:])) for pts in
                 (list(e.get_points("xy")) for e in eng if e.dxftype() == "LWPOLYLINE"))
    assert lines == pytest.approx(50.0, abs=1e-9)
    assert len([e for e in eng if e.dxftype() == "CIRCLE"]) == 1
    arcs = sum((e.dxf.end_angle - e.dxf.start_angle) % 360 for e in eng if e.dxftype() == "ARC")
    assert arcs == pytest.approx(270.0, abs=1e-6)
    from xml.etree import ElementTree
    ns = "{http://www.w3.org/2000/svg}"
    (g,) = [g for g in ElementTree.fromstring(r.encode("svg")).iter(f"{ns}g")
            if g.get("id") == "engrave"]
    drawn = sum(svgelements.Path(e.get("d")).length() if e.tag == f"{ns}path" else
                2 * math.pi * float(e.get("r")) for e in g)
    assert drawn == pytest.approx(50.0 + 2 * math.pi * 3 + 1.5 * math.pi * 5, abs=1e-3)
    f = tmp_path / "twice.aidl"
    f.write_text(TWICE)
    assert law.check(Entry("twice.aidl", TWICE, str(f))) == []
