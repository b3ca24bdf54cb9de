"""The joints between any two panels (std/joints.aidl: tab_and_slot, dovetail, cross_halving,
finger_edge) and the stands and holders built on them (std/stands.aidl), issue 52.

Each generator's demo program (examples/generators/NAME.aidl) goes through the real pipeline:
it compiles without a shape warning, its stated dimensions are re-read from the DXF that
`aidl render -o x.dxf` writes (ezdxf, an independent reader) to 1e-9 mm, the assembled product
(`Place`) passes the fit check (no W0517, W0518) at kerf 0 and 0.15 mm, and material thicker
than the generator's `thickness` collides (W0517)."""
import io
import math
import subprocess
import sys
from pathlib import Path

import ezdxf
import pytest
from shapely.geometry import Polygon as SPolygon

import aidl_lang

ROOT = Path(__file__).resolve().parent.parent
GEN = ROOT / "examples" / "generators"
A = 1e-9


def compile_src(tmp_path, src, name="t.aidl", **kw):
    p = tmp_path / name
    p.write_text(src)
    return aidl_lang.compile(source=src, path=p, **kw)


def demo(name, old=None, new=None):
    src = (GEN / f"{name}.aidl").read_text()
    if old is not None:
        assert old in src, old
        src = src.replace(old, new)
    return src


def codes(r, prefix="W05"):
    return [d.code for d in r.sink.items if d.code.startswith(prefix)]


def loops(r, part):
    """The closed outlines (shapely polygons, lines only) and circles (center, radius) of one
    part in the DXF as ezdxf reads it back."""
    doc = ezdxf.read(io.StringIO(r.to_dxf()))
    polys, circles = [], []
    for e in doc.modelspace():
        if e.dxf.layer != f"CUT-{part}":
            continue
        if e.dxftype() == "LWPOLYLINE":
            pts = list(e.get_points("xyb"))
            assert all(abs(b) < 1e-15 for _, _, b in pts)
            polys.append(SPolygon([(x, y) for x, y, _ in pts]))
        elif e.dxftype() == "CIRCLE":
            circles.append(((e.dxf.center.x, e.dxf.center.y), e.dxf.radius))
    polys.sort(key=lambda p: -p.area)      # the outline first, then the holes
    return polys, circles


def size(poly):
    x0, y0, x1, y1 = poly.bounds
    return x1 - x0, y1 - y0


def xs_at(poly, y):
    """The x of the vertical edges of an outline that cross the height y."""
    cs = list(poly.exterior.coords)
    return sorted(round(p[0], 12) for p, q in zip(cs, cs[1:])
                  if abs(p[0] - q[0]) < 1e-12 and min(p[1], q[1]) < y < max(p[1], q[1]))


@pytest.mark.parametrize("name", ["tab_and_slot", "dovetail", "cross_halving", "finger_edge"])
@pytest.mark.parametrize("kerf", ["", "kerf 0.15 mm\n"])
def test_joint_demo_compiles_clean_and_fits(tmp_path, name, kerf):
    r = compile_src(tmp_path, kerf + demo(name))
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    assert codes(r) == [] and codes(r, "W04") == []


@pytest.mark.parametrize("name", ["tab_and_slot", "cross_halving", "finger_edge"])
def test_joint_material_thicker_than_drawn_collides(tmp_path, name):
    r = compile_src(tmp_path, demo(name, "thickness 3 mm", "thickness 4 mm"))
    ws = [d for d in r.sink.items if d.code == "W0517"]
    assert len(ws) == 1 and ", 1 mm deep," in ws[0].message
    assert codes(r, "W0518") == []


def test_dovetail_in_the_sheet_plane_collides_only_when_too_tight(tmp_path):
    """A flat dovetail joins two panels of one sheet: thicker material slides in all the
    same, a socket narrower than its tail (clearance < 0) collides."""
    r = compile_src(tmp_path, demo("dovetail", "thickness 3 mm", "thickness 4 mm"))
    assert codes(r) == []
    r = compile_src(tmp_path, demo("dovetail", 'tails=3, cy=30 mm', 'tails=3, clearance=-0.4 mm, cy=30 mm'))
    ws = [d for d in r.sink.items if d.code == "W0517"]
    assert len(ws) == 1 and "`board.lower` and `board.upper`" in ws[0].message


@pytest.mark.parametrize("clearance", [0.0, 0.2])
def test_cross_halving_slot_is_thickness_plus_clearance(tmp_path, clearance):
    r = compile_src(tmp_path, demo("cross_halving").replace(
        "thickness=3 mm,", f"thickness=3 mm, clearance={clearance} mm,"))
    assert r.ok and codes(r) == []
    (a,), _ = loops(r, "cross.a")
    assert size(a) == pytest.approx((80, 40), abs=A)
    xs = [x for x in xs_at(a, 10) if abs(x) < 10]           # the slot's sides, 10 mm down
    assert xs[1] - xs[0] == pytest.approx(3 + clearance, abs=A)
    assert (xs[0] + xs[1]) / 2 == pytest.approx(0, abs=A)
    assert min(y for x, y in a.exterior.coords if abs(x) < 2) == pytest.approx(0, abs=A)  # 20 deep
    (b,), _ = loops(r, "cross.b")
    assert max(y for x, y in b.exterior.coords if abs(x - 90) < 2) == pytest.approx(0, abs=A)


@pytest.mark.parametrize("start,first", [("tab", True), ("gap", False)])
def test_finger_edge_segments_and_start(tmp_path, start, first):
    other = "gap" if start == "tab" else "tab"
    src = demo("finger_edge").replace('start="tab"', "START").replace(
        'start="gap"', f'start="{other}"').replace("START", f'start="{start}"')
    r = compile_src(tmp_path, src)
    assert r.ok
    (base,), _ = loops(r, "corner.base")
    (wall,), _ = loops(r, "corner.wall")
    n, w = 9, 100 / 9                       # the largest odd count of segments >= 10 mm
    # the base's back edge (y 30): material in segment i, halfway into the 3 mm strip
    mat_b = [base.contains(SPolygon([(x, 28.4), (x + 0.1, 28.4), (x + 0.1, 28.6), (x, 28.6)]))
             for x in (-50 + (i + 0.5) * w for i in range(n))]
    mat_w = [wall.contains(SPolygon([(x, 41.4), (x + 0.1, 41.4), (x + 0.1, 41.6), (x, 41.6)]))
             for x in (-50 + (i + 0.5) * w for i in range(n))]
    assert mat_b == [(i % 2 == 0) == first for i in range(n)]
    assert mat_w == [not m for m in mat_b]                    # fingers where the mate has gaps
    sides = [x for x in xs_at(base, 28.5) if -50 < x < 50]
    assert sides == pytest.approx([-50 + k * w for k in range(1, n)], abs=A)
    assert size(base) == pytest.approx((100, 60), abs=A)


@pytest.mark.parametrize("clearance", [0.0, 0.2])
def test_tab_and_slot_tabs_slots_screw_and_nut(tmp_path, clearance):
    r = compile_src(tmp_path, demo("tab_and_slot").replace(
        'part="slot",', f'part="slot", clearance={clearance} mm,'))
    assert r.ok and codes(r) == []
    base, holes = loops(r, "joint.base")
    assert size(base[0]) == pytest.approx((80, 60), abs=A)
    slots = sorted(base[1:], key=lambda p: p.bounds[0])
    assert [v for s in slots for v in size(s)] == pytest.approx([10 + clearance, 3 + clearance] * 2, abs=A)
    assert [s.centroid.x for s in slots] == pytest.approx([-15, 15], abs=A)
    assert [s.centroid.y for s in slots] == pytest.approx([0, 0], abs=A)
    ((hx, hy), hr), = holes
    assert (hx, hy, 2 * hr) == pytest.approx((0, 0, 3.4), abs=A)          # M3 medium, ISO 273
    (wall,), _ = loops(r, "joint.wall")
    assert size(wall) == pytest.approx((60, 40), abs=A)
    assert xs_at(wall, 41.5) == pytest.approx([-20, -10, 10, 20], abs=A)   # two 10 mm tabs, 3 long
    assert xs_at(wall, 45) == pytest.approx([-30, -1.7, 1.7, 30], abs=A)   # the screw's slot: 3.4
    assert xs_at(wall, 49) == pytest.approx([-30, -2.8, 2.8, 30], abs=A)   # the nut: 5.5 + 0.1
    ys = [y for x, y in wall.exterior.coords if abs(abs(x) - 2.8) < A]
    assert (min(ys), max(ys)) == pytest.approx((49 - 1.25, 49 + 1.25), abs=A)  # 2.4 + 0.1 at 6 mm
    assert max(y for x, y in wall.exterior.coords if abs(x) < 2) == pytest.approx(55, abs=A)  # 12 mm


@pytest.mark.parametrize("clearance", [0.0, 0.2])
def test_dovetail_tails_and_sockets(tmp_path, clearance):
    r = compile_src(tmp_path, demo("dovetail").replace(
        'part="socket",', f'part="socket", clearance={clearance} mm,'))
    assert r.ok and codes(r) == []
    (lower,), _ = loops(r, "board.lower")
    (upper,), _ = loops(r, "board.upper")
    assert size(lower) == pytest.approx((90, 50), abs=A)
    assert size(upper) == pytest.approx((90, 40), abs=A)
    p, d, k = 30, 10, math.tan(math.radians(10))
    # the tails: p/2 - 2 (d/2) tan(angle) wide on the line y 15, p/2 + d tan(angle) at the tips
    tails = {(round(x, 9), round(y, 9)) for x, y in lower.exterior.coords}
    for i in range(3):
        m = -45 + (i + 0.5) * p
        for s in (-1, 1):
            assert (round(m + s * (p / 4 - d / 2 * k), 9), 15.0) in tails
            assert (round(m + s * (p / 4 + d / 2 * k), 9), 25.0) in tails
    # the sockets' flank corners at 1e-9: on the line y 30 and at the tips y 40
    corners = {(round(x, 9), round(y, 9)) for x, y in upper.exterior.coords}
    for i in range(3):
        m = -45 + (i + 0.5) * p
        for s in (-1, 1):
            assert (round(m + s * (p / 4 - d / 2 * k + clearance / 2), 9), 30.0) in corners
            assert (round(m + s * (p / 4 + d / 2 * k + clearance / 2), 9), 40.0) in corners


@pytest.mark.parametrize("src,msg", [
    ('solid p { b = Rectangle(center=(0, 0), width=60, height=40)\n j = tab_and_slot(part="tabs") }', "part is"),
    ('solid p { b = Rectangle(center=(0, 0), width=60, height=40)\n j = tab_and_slot(tabs=1) }', "at least 2 tabs"),
    ('solid p { b = Rectangle(center=(0, 0), width=60, height=40)\n j = finger_edge(start="finger") }', "start is"),
    ('solid p { b = Rectangle(center=(0, 0), width=60, height=40)\n j = dovetail(angle=60 deg) }', "too steep"),
])
def test_joint_arguments_are_checked(tmp_path, src, msg):
    r = compile_src(tmp_path, 'import "std/joints.aidl"\n' + src + "\n")
    assert [e.code for e in r.errors] == ["E0405"] and msg in r.errors[0].message


@pytest.mark.parametrize("name", ["tab_and_slot", "dovetail", "cross_halving", "finger_edge"])
def test_joint_docs_and_prompt(name):
    from aidl_lang.reference import stdlib_lines
    out = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "docs", name], cwd=ROOT,
                         capture_output=True, text=True)
    assert out.returncode == 0 and f"{name}(" in out.stdout
    assert f"- {name}(" in stdlib_lines()
