"""Gears that turn without running into each other (issue 92: the planetary's W0517).

The gallery's planetary collided at values its sliders allow (planets 5, planet 12, sun 13:
0.00828 mm^3 between planet 1 and the ring): the ring's tips, on the addendum circle
m (ring - 2) / 2, reached below the planet's base circle, where its flank is a radial line and
not the involute (involute interference), and its spaces were only 1 m deep, so a planet's tip
touched their bottoms. Now the ring's spaces are 1.25 m deep (ISO 53), its tips end where the
line of action meets the pinion's base circle (`ring_gear(pinion=)`), and a wheel's tips end
where it meets a small mate's base circle (`spur_gear(mate=)`, given by gear_pair, gear_train
and planetary; the rack of rack_and_pinion likewise).

Laws over the planetary form's slider ranges (settings drawn on the form's grids; the sun's
range and step follow planets and planet as the form states them): no W0517 or W0511; read
back from the DXF (ezdxf): the ring's roots at m (ring + 2.5) / 2, every planet's tip circle
0.25 m inside them (more where the planet's tips are cut back for a small sun), the ring's
tips at least 0.25 m outside the planet's roots; and, turned through a whole pitch (sun, planet
0 and ring about their centres at the gear ratios, the carrier held), no overlap between the
sun, planet 0 and the ring (shapely, < 1e-6 mm^2). Small pinions in gear_pair and under the
rack likewise. In the suite: 2 drawn settings per law plus the reported ones (derandomized),
about 15 s of CPU; AIDL_LAW_EXAMPLES=200 for the long search.
"""
from __future__ import annotations

import io
import math
import os
from pathlib import Path

import ezdxf
import pytest
from ezdxf import path as epath
from hypothesis import HealthCheck, example, given, settings, strategies as st
from shapely import affinity
from shapely.geometry import Point, Polygon

import aidl_lang
from conftest import ROOT

FORM = (ROOT / "aidl_lang" / "studio" / "forms" / "planetary.aidl").read_text()
A20 = math.radians(20)
LAWS = settings(max_examples=int(os.environ.get("AIDL_LAW_EXAMPLES", "2")), deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])


def tip_r(z, mate, m):
    """A gear's tip radius: m (z + 2) / 2, or where the line of action meets the base circle of
    a mate of `mate` teeth (sqrt(rb^2 + (a sin 20)^2)), when that is less."""
    return min(m * (z + 2) / 2, math.hypot(m * z / 2 * math.cos(A20), m * (z + mate) / 2 * math.sin(A20)))


@st.composite
def planetary_settings(draw):
    """A setting of the form's sliders: planets 2-5, planet 12-40, the sun on its grid (from
    max(8, the planets' clearance) in steps of planets, of half an even count, to 48), the
    module 0.5-6 mm in 0.25 mm steps, the axle up to its max."""
    planets = draw(st.integers(2, 5))
    planet = draw(st.integers(12, 40))
    step = planets // (2 - planets % 2)
    s = math.sin(math.pi / planets)
    base = max(8, math.ceil((planet * (1 - s) + 2.5) / s - 1e-9))
    lo = base + (2 * planets - (base + planet) % step) % step
    hi = 48 - (48 + planet) % step
    if lo > hi:                  # 5 planets of 40 teeth: no sun on the slider fits
        planet = 12
        base = max(8, math.ceil((planet * (1 - s) + 2.5) / s - 1e-9))
        lo = base + (2 * planets - (base + planet) % step) % step
        hi = 48 - (48 + planet) % step
    sun = draw(st.sampled_from(range(lo, hi + 1, step)))
    module = 0.5 + 0.25 * draw(st.integers(0, 22))
    top = min(16, module * (min(sun, planet) - 2.5) - 1.1)
    axle = 1 + 0.05 * draw(st.integers(0, max(0, int((top - 1) / 0.05 + 1e-9))))
    return {"planets": planets, "planet": planet, "sun": sun, "module": module, "axle": round(axle, 2)}


def _region(ents, tol=1e-5):
    """The shapely region of one part's outlines: the largest less the ones inside it."""
    polys = []
    for e in ents:
        if e.dxftype() == "CIRCLE":
            c = e.dxf.center
            polys.append(Point(c.x, c.y).buffer(e.dxf.radius, quad_segs=256))
        else:
            polys.append(Polygon([(v.x, v.y) for v in epath.make_path(e).flattening(tol)]))
    polys.sort(key=lambda p: -p.area)
    out = polys[0]
    for h in polys[1:]:
        out = out.difference(h)
    return out


def _parts(result) -> dict:
    out: dict = {}
    for e in ezdxf.read(io.StringIO(result.to_dxf())).modelspace():
        out.setdefault(e.dxf.layer.split(".")[-1], []).append(e)
    return out


def _centre(ents):
    """The centre of a gear (its bore) or the ring (its plate's circle)."""
    c = max((e for e in ents if e.dxftype() == "CIRCLE"), key=lambda e: e.dxf.radius).dxf.center
    return c.x, c.y


def _radii(ents, c):
    (outline,) = [e for e in ents if e.dxftype() == "LWPOLYLINE"]
    return [math.dist(p, c) for p in outline.get_points("xy")]


def _turned_overlap(a, ca, wa, b, cb, wb, pitch_a, steps=8):
    """The largest overlap (mm^2) of regions a and b turned about their centres by wa and wb
    degrees per degree of a, through one pitch of a (`pitch_a` degrees)."""
    worst = 0.0
    for i in range(steps):
        t = pitch_a * i / steps
        worst = max(worst, affinity.rotate(a, wa * t, origin=ca).intersection(
            affinity.rotate(b, wb * t, origin=cb)).area)
    return worst


@LAWS
@given(planetary_settings())
@example({"planets": 5, "planet": 12, "sun": 13, "module": 2.0, "axle": 4.0})  # 0.00828 mm^3 once
@example({"planets": 2, "planet": 13, "sun": 9, "module": 2.0, "axle": 4.0})   # 0.0033 mm^3 once
@example({"planets": 2, "planet": 40, "sun": 8, "module": 6.0, "axle": 4.0})   # sun: 0.0793 mm^3
def test_the_planetary_turns_clear_at_every_slider_setting(tmp_path, s):
    m, sun, planet = s["module"], s["sun"], s["planet"]
    ring = sun + 2 * planet
    over = {k: (f"{v} mm" if k in ("module", "axle") else str(v)) for k, v in s.items()}
    r = aidl_lang.compile(source=FORM, path=tmp_path / "planetary.aidl", overrides=over)
    assert r.ok and [d.code for d in r.diagnostics if d.code in ("W0511", "W0517")] == [], \
        (s, [(d.code, d.message) for d in r.diagnostics])
    parts = _parts(r)
    o = _centre(parts["ring_gear"])
    inner = min((e for e in parts["ring_gear"] if e.dxftype() == "LWPOLYLINE"),
                key=lambda e: max(math.dist(p, o) for p in e.get_points("xy")))
    ring_r = [math.dist(p, o) for p in inner.get_points("xy")]
    root, tips = max(ring_r), min(ring_r)
    assert root == pytest.approx(m * (ring + 2.5) / 2, abs=1e-6)          # 1.25 m deep
    a = m * (sun + planet) / 2
    # the ring's tips: where the line of action meets the planet's base circle, or the
    # addendum circle when that lies further out
    assert tips == pytest.approx(max(m * (ring - 2) / 2, math.hypot(
        m * ring / 2 * math.cos(A20), m * (ring - planet) / 2 * math.sin(A20))), abs=1e-9)
    for k in range(s["planets"]):
        ents = parts[f"planet_gear[{k}]"]
        c = _centre(ents)
        d = math.dist(c, o)
        assert d == pytest.approx(a, abs=1e-9)
        pr = _radii(ents, c)
        tip = max(pr)
        assert tip == pytest.approx(tip_r(planet, sun, m), abs=1e-9)
        # radial clearance, the planet's tip circle to the ring's roots: 0.25 m (it was 0),
        # more by what a small sun cut from the planet's tips
        clear = root - (d + tip)
        assert clear == pytest.approx(0.25 * m + (m * (planet + 2) / 2 - tip), abs=1e-6)
        assert clear >= 0.25 * m - 1e-6
        # the ring's tips clear the planet's roots by 0.25 m or more
        assert tips - (d + min(pr)) >= 0.25 * m - 1e-6
    # turned through a sun pitch, the carrier held: the sun by t, planet 0 by -t sun / planet,
    # the ring by -t sun / ring (one planet pitch each)
    sun_e, p0 = parts["sun_gear"], parts["planet_gear[0]"]
    sun_reg = Polygon([(v.x, v.y) for v in epath.make_path(
        next(e for e in sun_e if e.dxftype() == "LWPOLYLINE")).flattening(1e-5)])
    p0_reg = Polygon([(v.x, v.y) for v in epath.make_path(
        next(e for e in p0 if e.dxftype() == "LWPOLYLINE")).flattening(1e-5)])
    ring_reg = Point(o).buffer(root + m, quad_segs=256).difference(
        Polygon([(v.x, v.y) for v in epath.make_path(inner).flattening(1e-5)]))
    cs, c0 = _centre(sun_e), _centre(p0)
    assert _turned_overlap(sun_reg, cs, 1, p0_reg, c0, -sun / planet, 360 / sun) < 1e-6
    assert _turned_overlap(ring_reg, o, -sun / ring, p0_reg, c0, -sun / planet, 360 / sun) < 1e-6


PAIR = """import "std/gears.aidl"
assembly drive {{
    pair = gear_pair(teeth1={z1}, teeth2={z2}, module={m} mm, bore1=1 mm, bore2=1 mm, backlash=0.05 mm)
}}
"""


@LAWS
@given(z1=st.integers(8, 16), z2=st.integers(20, 120), m=st.sampled_from([0.5, 1.0, 2.0, 3.0]))
@example(z1=8, z2=120, m=3.0)         # 0.028 mm^2 turned, before the wheel's tips were cut back
def test_a_small_pinion_turns_clear_of_its_wheel(tmp_path, z1, z2, m):
    """gear_pair's slider ranges (examples/gear_pair.aidl: pinion 8-40, wheel 20-120, module
    0.5-3 mm) below 17 teeth: the wheel's tips at tip_r, and no overlap through a pitch."""
    r = aidl_lang.compile(source=PAIR.format(z1=z1, z2=z2, m=m), path=tmp_path / "pair.aidl")
    assert r.ok and not [d for d in r.diagnostics if d.code in ("W0511", "W0517")]
    parts = _parts(r)
    regs, cs = [], []
    for g, z, mate in (("gear1", z1, z2), ("gear2", z2, z1)):
        c = _centre(parts[g])
        assert max(_radii(parts[g], c)) == pytest.approx(tip_r(z, mate, m), abs=1e-9)
        regs.append(_region([e for e in parts[g] if e.dxftype() == "LWPOLYLINE"]))
        cs.append(c)
    assert _turned_overlap(regs[0], cs[0], 1, regs[1], cs[1], -z1 / z2, 360 / z1) < 1e-6


RACK = """import "std/gears.aidl"
thickness 3 mm
assembly slide {{ drive = rack_and_pinion(teeth={z}, module={m} mm, rack_teeth={n}) }}
"""


@pytest.mark.parametrize("z,m,n", [(11, 6, 8), (13, 2, 9)])
def test_the_rack_runs_clear_of_a_small_pinion(tmp_path, z, m, n):
    """The fewest teeth rack_and_pinion's form allows, at its largest module (0.042 mm^2
    turned, before the rack's tips ended r sin^2 20 over the pitch line): the pinion rolled
    along the rack through a pitch (turned by t, moved by r t) meets no rack tooth."""
    r = aidl_lang.compile(source=RACK.format(z=z, m=m, n=n), path=tmp_path / "rack.aidl")
    assert r.ok and not [d for d in r.diagnostics if d.code in ("W0511", "W0517")]
    parts = _parts(r)
    rack = _region(parts["rack"])
    c = _centre(parts["pinion"])
    pinion = _region([e for e in parts["pinion"] if e.dxftype() == "LWPOLYLINE"])
    top = max(p[1] for p in next(e for e in parts["rack"] if e.dxftype() == "LWPOLYLINE").get_points("xy"))
    assert c[1] - top == pytest.approx(m * z / 2 - min(m, m * z / 2 * math.sin(A20) ** 2), abs=1e-9)
    rad = m * z / 2
    worst = 0.0
    for i in range(8):
        t = 360 / z * i / 8
        moved = affinity.translate(affinity.rotate(pinion, t, origin=c), -rad * math.radians(t), 0)
        worst = max(worst, moved.intersection(rack).area)
    assert worst < 1e-6
