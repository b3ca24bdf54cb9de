"""The generators of issue 52: std/enclosures.aidl (board_enclosure) and the mechanisms added
to std/gears.aidl (gear_train, rack_and_pinion, planetary).

Each goes through the real pipeline; its stated dimensions are re-read from the DXF `aidl
render` writes, with ezdxf (an independent reader), to 1e-9 mm; its assembly (`Place`) is
fit-checked at kerf 0 and 0.15 mm (no W0517, no W0518), and material thicker than the
generator's `thickness` collides (W0517).  The demo programs in examples/generators/ compile
without a shape warning.
"""
import math
import subprocess
import sys

import ezdxf
import pytest

from aidl_lang.pipeline import compile_source
from conftest import ROOT

PY = sys.executable
GEN = ROOT / "examples" / "generators"
SHAPE = ("W05",)


_COMPILED: dict = {}


def run(tmp_path, src, name="t.aidl", **kw):
    """``src`` compiled from ``tmp_path / name``; each (text, name, options) once in this
    process (the tests and :func:`dxf_render` ask for the same programs: 46 compiles were 41,
    and each of the 16 renders compiled its program again in an `aidl render`)."""
    key = (src, name, repr(sorted(kw.items())))
    if key not in _COMPILED:
        p = tmp_path / name
        p.write_text(src)
        _COMPILED[key] = (compile_source(src, str(p), **kw), str(p))
    return _COMPILED[key][0]


def codes(c):
    return [d.code for d in c.sink.items]


def clean(c):
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    bad = [(d.code, d.message) for d in c.sink.items if d.code.startswith(SHAPE) or d.code == "W0404"]
    assert bad == []


def dxf_render(tmp_path, src, name="t.aidl", extra=(), cli=False):
    """The DXF `aidl render -o x.dxf` writes, re-read by ezdxf: by the command line itself
    (``cli``, with its ``extra`` arguments), else the API's DXF of the program compiled once
    (:func:`run`), which is that file's text (``Result.encode``, the writer `aidl render`
    calls, at the program's own kerf)."""
    if not cli and not extra:
        import io

        from aidl_lang.api.result import Result
        c = run(tmp_path, src, name)
        return ezdxf.read(io.StringIO(Result(c, _COMPILED[(src, name, "[]")][1], src).to_dxf()))
    p = tmp_path / name
    p.write_text(src)
    out = tmp_path / (p.stem + ".dxf")
    subprocess.run([PY, "-m", "aidl_lang.cli", "render", str(p), "-o", str(out), *extra],
                   check=True, cwd=ROOT, capture_output=True)
    return ezdxf.readfile(str(out))


def bbox(entities):
    from ezdxf import bbox as ebbox
    b = ebbox.extents(entities)
    return b.extmin.x, b.extmin.y, b.extmax.x, b.extmax.y


def by_layer(doc):
    out = {}
    for e in doc.modelspace():
        out.setdefault(e.dxf.layer, []).append(e)
    return out


def fit(tmp_path, src):
    """The fit check's warnings with kerf 0 and with kerf 0.15 mm."""
    got = []
    for kerf in ("", "kerf 0.15 mm\n"):
        c = run(tmp_path, kerf + src)
        assert c.ok, [(d.code, d.message) for d in c.sink.items]
        assert c.drawing.placement
        got.append([d.code for d in c.sink.items if d.code in ("W0517", "W0518")])
    return got


# --- board_enclosure -----------------------------------------------------------------------

ENC = """import "std/enclosures.aidl"
thickness {material} mm
assembly case {{
    box = board_enclosure(width={w} mm, height={h} mm, depth=25 mm, thickness=3 mm,
                          clearance={c} mm, {extra})
}}
"""


def enc(material=3, w=85, h=56, c=2, extra="vent=\"slots\""):
    return ENC.format(material=material, w=w, h=h, c=c, extra=extra)


def test_board_enclosure_demo_is_clean():
    src = (GEN / "board_enclosure.aidl").read_text()
    c = compile_source(src, str(GEN / "board_enclosure.aidl"))
    clean(c)
    assert len(c.drawing.placement) == 6


@pytest.mark.parametrize("w,h,c", [(85, 56, 2), (60, 40, 1.5), (100, 70, 0)])
def test_board_enclosure_floor_holes_and_ports_from_the_dxf(tmp_path, w, h, c):
    t = 3
    src = enc(w=w, h=h, c=c, extra='holes=[[4, 5], [30, 5], [4, 30]], hole_d=3.4 mm, standoff=6 mm, '
              'ports=[["front", 20, 10, 4], ["left", 15, 9, 3.5], ["back", 25, 8, 5], ["right", 18, 12, 6]]')
    clean(run(tmp_path, src))
    doc = dxf_render(tmp_path, src, cli=True)         # `aidl render` itself, once a size
    layers = by_layer(doc)
    bottom = [e for k, v in layers.items() if k.endswith("bottom") for e in v]
    x0, y0, x1, y1 = bbox(bottom)
    # the floor: the board plus clearance and a wall each side, outside
    L, D = w + 2 * c + 2 * t, h + 2 * c + 2 * t
    assert (x1 - x0, y1 - y0) == pytest.approx((L, D), abs=1e-9)
    holes = sorted((round(e.dxf.center.x - x0 - t - c, 9), round(e.dxf.center.y - y0 - t - c, 9),
                    e.dxf.radius) for e in bottom if e.dxftype() == "CIRCLE")
    assert [v for hx, hy, _ in holes for v in (hx, hy)] == pytest.approx([4, 5, 4, 30, 30, 5], abs=1e-9)
    assert all(abs(r - 1.7) < 1e-9 for *_, r in holes)
    # the ports: each a rectangle (4 lines or a closed polyline) in its wall
    deck = t + 6 + 1.6          # floor, standoff, board: the port's bottom edge above z = 0

    def openings(part):
        ents = [e for k, v in layers.items() if k.endswith(part) for e in v]
        outer = bbox(ents)
        inner = [e for e in ents if e.dxftype() == "LWPOLYLINE" and len(list(e.get_points())) == 4]
        return outer, [bbox([e]) for e in inner]

    (fx0, fy0, fx1, fy1), (port,) = openings("front")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((10, 4), abs=1e-9)
    assert (port[0] + port[2]) / 2 - fx0 - t - c == pytest.approx(20, abs=1e-9)
    assert port[1] - fy0 == pytest.approx(deck, abs=1e-9)
    (bx0, by0, bx1, by1), (port,) = openings("back")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((8, 5), abs=1e-9)
    assert (port[0] + port[2]) / 2 - bx0 - t - c == pytest.approx(25, abs=1e-9)
    # left wall: its right edge (net) is the floor's edge; z runs leftward
    (lx0, ly0, lx1, ly1), (port,) = openings("left")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((3.5, 9), abs=1e-9)
    assert lx1 - port[2] == pytest.approx(deck, abs=1e-9)
    assert (port[1] + port[3]) / 2 - ly0 - t - c == pytest.approx(15, abs=1e-9)
    (rx0, ry0, rx1, ry1), (port,) = openings("right")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((6, 12), abs=1e-9)
    assert port[0] - rx0 == pytest.approx(deck, abs=1e-9)
    assert (port[1] + port[3]) / 2 - ry0 - t - c == pytest.approx(18, abs=1e-9)
    # the walls stand depth + 2 t tall
    assert fy1 - fy0 == pytest.approx(25 + 2 * t, abs=1e-9)


def test_board_enclosure_vents(tmp_path):
    for vent, kind, n in (("slots", "LWPOLYLINE", 12), ("hex", "CIRCLE", None)):
        src = enc(extra=f'vent="{vent}"')
        clean(run(tmp_path, src))
        layers = by_layer(dxf_render(tmp_path, src))
        lid = [e for k, v in layers.items() if k.endswith("lid") for e in v]
        x0, y0, x1, y1 = bbox(lid)
        cuts = [e for e in lid if e.dxftype() == kind and bbox([e])[2] - bbox([e])[0] < 70]
        if vent == "slots":
            # (85 - 10) // 6 = 12 slots, 3 mm wide, 56 - 10 = 46 mm long, 6 mm apart
            assert len(cuts) == n
            for e in cuts:
                a, b, c, d = bbox([e])
                assert (c - a, d - b) == pytest.approx((3, 46), abs=1e-9)
        else:
            assert all(abs(e.dxf.radius - 2) < 1e-9 for e in cuts) and len(cuts) > 50
            xs = sorted({round(e.dxf.center.x, 6) for e in cuts})
            assert xs[1] - xs[0] == pytest.approx(3, abs=1e-6)   # rows shifted half a pitch
        # every vent inside the board's area less 5 mm
        for e in cuts:
            a, b, c, d = bbox([e])
            assert a >= (x0 + x1) / 2 - 85 / 2 + 5 - 1e-9 and c <= (x0 + x1) / 2 + 85 / 2 - 5 + 1e-9


def test_board_enclosure_fits_and_catches_thick_material(tmp_path):
    assert fit(tmp_path, enc()) == [[], []]
    c = run(tmp_path, enc(material=4))
    assert "W0517" in codes(c)


def test_board_enclosure_bad_side_is_named(tmp_path):
    c = run(tmp_path, enc(extra='ports=[["top", 10, 5, 5]]'))
    assert not c.ok and any("side" in d.message for d in c.sink.items if d.code == "E0405")


def test_board_enclosure_docs_name_its_ports_and_vents():
    from aidl_lang.library.reference import lookup_text
    d, found = lookup_text("board_enclosure")
    assert found and "ports" in d and "vent" in d


# --- gears: gear_train, rack_and_pinion, planetary --------------------------------------------

def part(layers, name):
    return [e for k, v in layers.items() if k.endswith("." + name) for e in v]


def circles(ents):
    return [(e.dxf.center.x, e.dxf.center.y, e.dxf.radius) for e in ents if e.dxftype() == "CIRCLE"]


def meshing_clean(c):
    """Compiled without an error, a shape warning (W0511: teeth running into each other in the
    flat view) or a collision (W0517) or loose part (W0518) in the assembly."""
    clean(c)
    assert c.drawing.placement


TRAIN = """import "std/gears.aidl"
thickness {material} mm
assembly drive {{ train = gear_train(teeth={teeth}, module={m} mm, axle=4 mm{extra}) }}
"""


def test_gear_train_demo_is_clean():
    src = (GEN / "gear_train.aidl").read_text()
    meshing_clean(compile_source(src, str(GEN / "gear_train.aidl")))


@pytest.mark.parametrize("teeth,m", [([12, 36, 12, 30], 2), ([15, 20], 1.5), ([13, 17, 24, 11, 40], 1),
                                     ([12, 12, 12], 3)])
def test_gear_train_axles_at_the_exact_centre_distances(tmp_path, teeth, m):
    src = TRAIN.format(material=3, teeth=teeth, m=m, extra="")
    meshing_clean(run(tmp_path, src))
    layers = by_layer(dxf_render(tmp_path, src))
    holes = sorted(circles(part(layers, "plate")))
    assert len(holes) == len(teeth)
    for (xa, ya, ra), (xb, yb, rb), za, zb in zip(holes, holes[1:], teeth, teeth[1:]):
        assert math.hypot(xb - xa, yb - ya) == pytest.approx(m * (za + zb) / 2, abs=1e-9)
        assert yb == pytest.approx(ya, abs=1e-9) and ra == pytest.approx(2, abs=1e-12)
    # each gear bored for its axle, on the axle's x (flat: the gears lie above the plate)
    for i, (x, y, r) in enumerate(holes):
        (bx, by, br), = circles(part(layers, f"gear[{i}]"))
        assert bx == pytest.approx(x, abs=1e-9) and br == pytest.approx(2, abs=1e-12)


def test_gear_train_fit_and_thick_material(tmp_path):
    src = TRAIN.format(material=3, teeth=[12, 36, 12, 30], m=2, extra="")
    assert fit(tmp_path, src) == [[], []]
    assert "W0517" in codes(run(tmp_path, TRAIN.format(material=4, teeth=[12, 36, 12, 30], m=2, extra="")))


def tight(c):
    """The W0517 volumes (mm^3) of a mesh without backlash: the flanks touch, and the arcs that
    stand for the involute (within 0.0003 mm of it) overlap by a few thousandths."""
    return [float(d.message.split("share ")[1].split(" mm^3")[0]) for d in c.sink.items
            if d.code == "W0517"]


def test_gear_train_phases_mesh_every_parity(tmp_path):
    """A gear turned half a pitch wrong runs its teeth into its neighbour's (W0511 flat, W0517
    assembled, square millimetres): every parity of the counts is tried, with the default
    backlash (nothing touches) and without (the flanks touch, < 0.01 mm^3)."""
    for teeth in ([12, 36, 12, 30], [13, 17, 24, 11], [11, 20, 15, 16, 9]):
        c = run(tmp_path, TRAIN.format(material=3, teeth=teeth, m=2, extra=""))
        assert c.ok and [d for d in codes(c) if d in ("W0511", "W0517", "W0518")] == [], teeth
        c = run(tmp_path, TRAIN.format(material=3, teeth=teeth, m=2, extra=", backlash=0 mm"))
        assert "W0511" not in codes(c) and all(v < 0.01 for v in tight(c)), teeth


RACK = """import "std/gears.aidl"
thickness {material} mm
assembly slide {{ drive = rack_and_pinion(teeth={z}, module={m} mm, rack_teeth={n}{extra}) }}
"""


def test_rack_and_pinion_demo_is_clean():
    src = (GEN / "rack_and_pinion.aidl").read_text()
    meshing_clean(compile_source(src, str(GEN / "rack_and_pinion.aidl")))


@pytest.mark.parametrize("z,m,n", [(16, 2, 12), (12, 1.5, 9), (20, 1, 15)])
def test_rack_pitch_and_pinion_distance_from_the_dxf(tmp_path, z, m, n):
    src = RACK.format(material=3, z=z, m=m, n=n, extra=", backlash=0.1 mm")
    meshing_clean(run(tmp_path, src))
    layers = by_layer(dxf_render(tmp_path, src))
    (rack,) = part(layers, "rack")
    pts = list(rack.get_points("xy"))
    top = max(y for _, y in pts)
    tips = sorted((a[0] + b[0]) / 2 for a, b in zip(pts, pts[1:] + pts[:1])
                  if abs(a[1] - top) < 1e-9 and abs(b[1] - top) < 1e-9)
    assert len(tips) == n
    assert all(b - a == pytest.approx(math.pi * m, abs=1e-9) for a, b in zip(tips, tips[1:]))
    # a tooth's flanks: at the pitch line pi m / 2 - backlash wide; the tips ha over it, a
    # module or, for a pinion under 18 teeth, r sin^2(20 deg) (where the line of action meets
    # its base circle: 16 teeth of 2 mm, 1.871 mm)
    ta = math.tan(math.radians(20))
    ha = min(m, m * z / 2 * math.sin(math.radians(20)) ** 2)
    tip_w = [abs(b[0] - a[0]) for a, b in zip(pts, pts[1:] + pts[:1])
             if abs(a[1] - top) < 1e-9 and abs(b[1] - top) < 1e-9]
    assert all(w + 2 * ha * ta == pytest.approx(math.pi * m / 2 - 0.1, abs=1e-9) for w in tip_w)
    bar = min(y for _, y in pts) + 8       # the bar's top (its default height 8 mm): the roots
    assert top - bar == pytest.approx(1.25 * m + ha, abs=1e-9)
    # the pinion's centre (its bore) m z / 2 above the pitch line, over the rack's middle
    # tooth (of an even count, the one half a pitch right of the middle)
    (px, py, _), = circles(part(layers, "pinion"))
    assert py - (top - ha) == pytest.approx(m * z / 2, abs=1e-9)
    assert px == pytest.approx(tips[n // 2], abs=1e-9)


def test_rack_and_pinion_fit_and_thick_material(tmp_path):
    assert fit(tmp_path, RACK.format(material=3, z=16, m=2, n=12, extra="")) == [[], []]
    assert "W0517" in codes(run(tmp_path, RACK.format(material=4, z=16, m=2, n=12, extra="")))
    for z, n in ((16, 12), (15, 11), (13, 8)):
        c = run(tmp_path, RACK.format(material=3, z=z, m=2, n=n, extra=""))
        assert c.ok and [d for d in codes(c) if d in ("W0511", "W0517", "W0518")] == [], (z, n)
        c = run(tmp_path, RACK.format(material=3, z=z, m=2, n=n, extra=", backlash=0 mm"))
        assert "W0511" not in codes(c) and all(v < 0.01 for v in tight(c)), (z, n)
    # the fewest teeth the form allows, at its largest module, on an even rack: the pinion's gap
    # over a tooth (a tooth down into the middle gap shared 0.127 mm^3, W0517)
    for extra in ("", ", backlash=0 mm"):
        c = run(tmp_path, RACK.format(material=3, z=11, m=6, n=8, extra=extra))
        assert c.ok and [d for d in codes(c) if d in ("W0511", "W0517", "W0518")] == [], extra


PLAN = """import "std/gears.aidl"
thickness {material} mm
assembly reducer {{ set = planetary(sun={s}, planet={p}, ring={r}, planets={n}, module={m} mm{extra}) }}
"""


def test_planetary_demo_is_clean():
    src = (GEN / "planetary.aidl").read_text()
    meshing_clean(compile_source(src, str(GEN / "planetary.aidl")))


@pytest.mark.parametrize("s,p,r,n,m", [(12, 18, 48, 3, 2), (12, 12, 36, 4, 1.5), (18, 15, 48, 3, 1),
                                       (20, 10, 40, 5, 1)])
def test_planetary_centre_distances_and_ring_from_the_dxf(tmp_path, s, p, r, n, m):
    src = PLAN.format(material=3, s=s, p=p, r=r, n=n, m=m, extra="")
    meshing_clean(run(tmp_path, src))
    layers = by_layer(dxf_render(tmp_path, src))
    (sx, sy, _), = circles(part(layers, "sun_gear"))
    planets = [circles(part(layers, f"planet_gear[{k}]"))[0] for k in range(n)]
    a = m * (s + p) / 2
    for k, (x, y, _) in enumerate(planets):
        assert math.hypot(x - sx, y - sy) == pytest.approx(a, abs=1e-9)
        assert math.atan2(y - sy, x - sx) % (2 * math.pi) == pytest.approx(
            (2 * math.pi * k / n) % (2 * math.pi), abs=1e-9)
    # the carrier's axle holes: the same distances about its centre hole
    body, *holes = sorted(circles(part(layers, "carrier")), key=lambda h: -h[2])
    cx, cy = body[0], body[1]
    assert sorted(round(math.hypot(x - cx, y - cy), 9) for x, y, _ in holes) == pytest.approx(
        [0] + [a] * n, abs=1e-9)
    # the ring: internal teeth whose tips lie on the circle m (ring - 2) / 2 about the sun's
    # axis, or further out where the line of action meets the planets' base circles
    # (sqrt(rb^2 + (a sin 20)^2), a = m (ring - planet) / 2: 46.26 mm for 48/18 of 2 mm), and
    # roots 1.25 m past the pitch circle
    ring = part(layers, "ring_gear")
    inner = min((e for e in ring if e.dxftype() == "LWPOLYLINE"), key=lambda e: bbox([e])[2] - bbox([e])[0])
    radii = [math.hypot(x - sx, y - sy) for x, y in inner.get_points("xy")]
    a20 = math.radians(20)
    tips = max(m * (r - 2) / 2, math.hypot(m * r / 2 * math.cos(a20), m * (r - p) / 2 * math.sin(a20)))
    assert min(radii) == pytest.approx(tips, abs=1e-9)
    assert max(radii) == pytest.approx(m * (r + 2.5) / 2, abs=1e-6)


def test_planetary_fit_and_thick_material(tmp_path):
    assert fit(tmp_path, PLAN.format(material=3, s=12, p=18, r=48, n=3, m=2, extra="")) == [[], []]
    assert "W0517" in codes(run(tmp_path, PLAN.format(material=4, s=12, p=18, r=48, n=3, m=2, extra="")))
    c = run(tmp_path, PLAN.format(material=3, s=12, p=12, r=36, n=4, m=2, extra=", backlash=0 mm"))
    assert "W0511" not in codes(c) and all(v < 0.01 for v in tight(c))


def test_planetary_tooth_count_rules_name_the_count_to_use(tmp_path):
    c = run(tmp_path, PLAN.format(material=3, s=12, p=18, r=50, n=3, m=2, extra=""))
    (e,) = [d for d in c.sink.items if d.code == "E0405"]
    assert "ring = sun + 2 * planet" in e.message and "50 == 48" in e.message
    # 13 + 2 * 18 = 49; (49 + 13) / 3 is not whole: sun 12 (ring 48) is the nearest that is
    c = run(tmp_path, PLAN.format(material=3, s=13, p=18, r=49, n=3, m=2, extra=""))
    (e,) = [d for d in c.sink.items if d.code == "E0405"]
    assert "divide by planets" in e.message and "13 == 12" in e.message
