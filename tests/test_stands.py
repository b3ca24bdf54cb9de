"""The joints between any two panels (std/joints.aidl: tab_and_slot, dovetail, cross_halving,
finger_edge) and the stands and holders built on them (std/stands.aidl), issue 52.

Each generator's demo program (examples/generators/NAME.aidl) goes through the real pipeline:
it compiles without a shape warning, its stated dimensions are re-read from the DXF that
`aidl render -o x.dxf` writes (ezdxf, an independent reader) to 1e-9 mm, the assembled product
(`Place`) passes the fit check (no W0517, W0518) at kerf 0 and 0.15 mm, and material thicker
than the generator's `thickness` collides (W0517)."""
import io
import math
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
    ('solid p { b = Rectangle(center=(0, 0), width=60, height=40)\n j = tab_and_slot(tabs=0) }', "at least 1 tab"),
    ('solid p { b = Rectangle(center=(0, 0), width=60, height=40)\n j = finger_edge(start="finger") }', "start is"),
    ('solid p { b = Rectangle(center=(0, 0), width=60, height=40)\n j = dovetail(angle=60 deg) }', "too steep"),
])
def test_joint_arguments_are_checked(tmp_path, src, msg):
    r = compile_src(tmp_path, 'import "std/joints.aidl"\n' + src + "\n")
    assert [e.code for e in r.errors] == ["E0405"] and msg in r.errors[0].message


# ---------------------------------------------------------------------------------------------
# Stands and holders (std/stands.aidl)

STANDS = {"tablet_stand": 3, "laptop_stand": 4, "tool_holder": 6, "wall_shelf": 4}   # parts


@pytest.mark.parametrize("name", list(STANDS))
@pytest.mark.parametrize("kerf", ["", "kerf 0.15 mm\n"])
def test_stand_compiles_clean_places_every_part_and_fits(tmp_path, name, kerf):
    r = compile_src(tmp_path, kerf + demo(name))
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    assert codes(r) == [] and codes(r, "W04") == []        # no shape warning, no W0517/W0518
    assert len(r.compiled.drawing.placement) == STANDS[name] == len(r.parts)


@pytest.mark.parametrize("name,joints", [("tablet_stand", 2), ("laptop_stand", 4),
                                         ("tool_holder", 10), ("wall_shelf", 4)])
def test_stand_material_thicker_than_drawn_collides(tmp_path, name, joints):
    r = compile_src(tmp_path, demo(name, "thickness 3 mm", "thickness 4 mm"))
    ws = [d for d in r.sink.items if d.code == "W0517"]
    assert len(ws) >= joints and all(", 1 mm deep," in w.message for w in ws)


def slot_width(poly, y, near):
    """The width of the slot crossing height y next to x = near (its two sides)."""
    xs = [x for x in xs_at(poly, y) if abs(x - near) < 5]
    assert len(xs) == 2, xs
    return xs[1] - xs[0], (xs[0] + xs[1]) / 2


@pytest.mark.parametrize("clearance", [0.0, 0.25])
def test_tablet_stand_dimensions(tmp_path, clearance):
    r = compile_src(tmp_path, demo("tablet_stand", "thickness=3 mm)", f"thickness=3 mm, clearance={clearance} mm)"))
    assert r.ok and codes(r) == []
    H, a = 130, math.radians(70)
    D = (H - 6) / math.tan(a) + 60
    for i in range(2):
        (s,), _ = loops(r, f"stand.s.support[{i}]")
        assert size(s) == pytest.approx((D, H), abs=A)
        ox = (2 * i - 1) * (D + 5) / 2
        w, c = slot_width(s, 10, ox)                 # from the bottom edge, 20 deep
        assert (w, c) == pytest.approx((3 + clearance, ox), abs=A)
        assert max(y for x, y in s.exterior.coords if abs(x - ox) < 2) == pytest.approx(20, abs=A)
        ys = sorted({round(y, 9) for x, y in s.exterior.coords if abs(x - (ox + D / 2)) < A})
        assert ys == pytest.approx([0, 18], abs=A)   # the front: the 6 mm ledge + the 12 mm lip
    (f,), _ = loops(r, "stand.s.foot")
    assert size(f) == pytest.approx((140, 40), abs=A)
    for sx in (-55, 55):
        assert slot_width(f, -15, sx) == pytest.approx((3 + clearance, sx), abs=A)


@pytest.mark.parametrize("clearance", [0.0, 0.25])
def test_laptop_stand_dimensions(tmp_path, clearance):
    r = compile_src(tmp_path, demo("laptop_stand", "thickness=3 mm)", f"thickness=3 mm, clearance={clearance} mm)"))
    assert r.ok and codes(r) == []
    D, h = 220, 30
    back = h + D * math.tan(math.radians(15))
    for i in range(2):
        (s,), _ = loops(r, f"stand.s.side[{i}]")
        assert size(s) == pytest.approx((D, back), abs=A)
        ox = (2 * i - 1) * (D + 5) / 2
        ys = sorted({round(y, 9) for x, y in s.exterior.coords if abs(x - (ox + D / 2)) < A})
        assert ys == pytest.approx([0, h + 10], abs=A)      # the front with its 10 mm lip
        for k in (-1, 1):
            assert slot_width(s, 5, ox + k * (D / 2 - 30)) == pytest.approx((3 + clearance, ox + k * (D / 2 - 30)), abs=A)
    for k in range(2):
        (b,), _ = loops(r, f"stand.s.bar[{k}]")
        assert size(b) == pytest.approx((260, h), abs=A)
        top = b.bounds[3]
        assert slot_width(b, top - 5, -110) == pytest.approx((3 + clearance, -110), abs=A)


@pytest.mark.parametrize("outside", [True, False])
def test_tool_holder_outside_and_inside_sizes_and_holes(tmp_path, outside):
    r = compile_src(tmp_path, demo("tool_holder", "hole=16 mm)", f"hole=16 mm, outside={str(outside).lower()})"))
    assert r.ok and codes(r) == []
    L, D, H = (100, 70, 90) if outside else (106, 76, 96)     # inside + 2 x 3 mm
    sizes = {"bottom": (L, D), "top": (L, D), "front": (L, H), "back": (L, H), "left": (H, D), "right": (H, D)}
    for name, wh in sizes.items():
        polys, _ = loops(r, f"desk.pens.{name}")
        assert size(polys[0]) == pytest.approx(wh, abs=A), name
    (top,), holes = loops(r, "desk.pens.top")
    assert len(holes) == 6 and all(rad == pytest.approx(8, abs=A) for _, rad in holes)
    (cx, cy), (x0, y0, x1, y1) = top.centroid.coords[0], top.bounds
    px, py = (L - 6) / 3, (D - 6) / 2                         # spread over the plate inside the joints
    want = sorted(((x0 + x1) / 2 + (c - 1) * px, (y0 + y1) / 2 + (k - 0.5) * py) for k in range(2) for c in range(3))
    got = sorted(c for c, _ in holes)
    assert [v for p in got for v in p] == pytest.approx([v for p in want for v in p], abs=A)


def test_tool_holder_checks_that_the_holes_fit(tmp_path):
    r = compile_src(tmp_path, demo("tool_holder", "hole=16 mm", "hole=30 mm"))
    assert [e.code for e in r.errors] == ["E0405"] and "4 mm apart" in r.errors[0].message


@pytest.mark.parametrize("clearance", [0.0, 0.25])
def test_wall_shelf_dimensions(tmp_path, clearance):
    r = compile_src(tmp_path, demo("wall_shelf", "screw=4)", f"screw=4, clearance={clearance} mm)"))
    assert r.ok and codes(r) == []
    back, holes = loops(r, "shelf.s.back")
    assert size(back[0]) == pytest.approx((300, 150), abs=A)
    slots = sorted(back[1:], key=lambda p: (p.bounds[0], p.bounds[1]))
    assert len(slots) == 4
    assert [v for s in slots for v in size(s)] == pytest.approx([3 + clearance, 20 + clearance] * 4, abs=A)
    assert sorted(round(s.centroid.x, 9) for s in slots) == pytest.approx([-110, -110, 110, 110], abs=A)
    assert sorted(round(s.centroid.y, 9) for s in slots) == pytest.approx([-37.5, -37.5, 37.5, 37.5], abs=A)
    assert [round(2 * rad, 9) for _, rad in holes] == [4.5, 4.5]          # M4 medium, ISO 273
    assert sorted((x, y) for (x, y), _ in holes) == [pytest.approx((-55, 60), abs=A), pytest.approx((55, 60), abs=A)]
    (shelf,), _ = loops(r, "shelf.s.shelf")
    assert size(shelf) == pytest.approx((300, 120), abs=A)
    top = shelf.bounds[3]
    for sx in (-110, 110):
        assert slot_width(shelf, top - 30, sx) == pytest.approx((3 + clearance, sx), abs=A)
        assert min(y for x, y in shelf.exterior.coords if abs(x - sx) < 2) == pytest.approx(top - 60, abs=A)
    for i in range(2):
        (b,), _ = loops(r, f"shelf.s.bracket[{i}]")
        # depth + the tabs through the plate; 150 tall at its back edge, where the shoulder below
        # the lower tab cuts the pointed foot back by the thickness (the diagonal falls 100 in 123)
        assert size(b) == pytest.approx((123, 150 - 3 * 100 / 123), abs=A)
