"""Profiles (issue 93, round five): an L, T, U or Z bracket or a stepped plate drawn as lines
at right angles, sharp or filleted, is a polygon of params: "longer leg" or "thicker" is one
param, and an edit does what the spec says (docs/import.md, "What an edit means": a profile
keeps its walls' thickness).  The truths are tests/gen_profiles.py's designs drawn again with
the edited number and compared by exact loop signatures (the benchmark's `compare`).  Cost:
a hand-made L (3 compiles) and a law over 8 generated profiles of 2 edits each (~24
compiles), about 6 s CPU."""
from __future__ import annotations

import io
import random

import ezdxf
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import aidl_lang
import gen_profiles as gp
from aidl_lang.drawing.infer import import_drawing
from benchmarks.imports import infer_edits as bench


def _l_bracket(leg: float, wall: float, r: float):
    """An equal-leg L bracket's design, a hole in the middle of each leg."""
    d = gp.ProfileDesign("mm", "l_bracket", {"a": leg, "b": leg, "t": wall, "u": wall,
                                             "ri": r, "ro": 0.0},
                         (False, False, False), (0.0, 0.0), {("a", "b"), ("t", "u")}, 4.0)
    d.style = {"format": "dxf", "bulges": True, "insunits": True}
    return d


def test_an_equal_l_bracket_is_one_leg_and_one_wall(tmp_path):
    """An equal-leg L, 40 mm legs, 8 mm walls, a 3 mm inside fillet and a hole in the middle
    of each leg: `leg`, `wall` and `fillet` params; leg 50 and wall 10 each give the L drawn
    so (the holes stay in the middle of their legs)."""
    d = _l_bracket(40, 8, 3)
    suffix, data = bench.gen.export(d)
    text, _ = import_drawing(data, "l" + suffix, infer=True)
    for line in ("param leg = 40 mm", "param wall = 8 mm", "param fillet = 3 mm",
                 "body = Polygon([(0, 0), (leg, 0), (leg, wall), (wall, wall), (wall, leg), "
                 "(0, leg)])", "Fillet(at=[(wall, wall)], radius=fillet)"):
        assert line in text, text
    assert not bench.compare(d, bench.output_of(text, tmp_path / "a.aidl"), tmp_path)
    for key, name, new in (("a", "leg", 50.0), ("t", "wall", 10.0)):
        e = next(e for e in d.edits() if e.key == key)
        want = d.edited(e, new)
        got = bench.output_of(text, tmp_path / "b.aidl", {name: repr(new)})
        assert not isinstance(got, str), got
        assert not bench.compare(want, got, tmp_path), (key, text)


def test_a_u_with_a_narrow_opening_stays_a_plate_with_a_notch():
    """A U whose opening is narrower than half its width reads as a plate with a notch (the
    spec: a notch's width and depth); wider, as a U of walls."""
    for t, notch in ((10.0, True), (30.0, False)):
        doc = ezdxf.new("R2010")
        doc.units = 4
        W, H = 100.0, 60.0
        doc.modelspace().add_lwpolyline([(0, 0), (W, 0), (W, H), (W - t, H), (W - t, 20),
                                         (t, 20), (t, H), (0, H)], close=True)
        s = io.StringIO()
        doc.write(s)
        text, _ = import_drawing(s.getvalue().encode(), "u.dxf", infer=True)
        assert ("notch" in text) is (t == 30.0) and ("param wall = 10 mm" in text) is notch, text
        assert aidl_lang.compile(text).ok


@settings(max_examples=8, deadline=None)
@given(seed=st.integers(0, 10 ** 6), kind=st.sampled_from(gp.PROFILE_KINDS))
def test_profile_edits_do_what_the_spec_means(seed, kind, tmp_path_factory):
    """Law: a generated profile of each kind (turned, mirrored, in mm or inches, DXF or SVG,
    fillets or none) is inferred exactly, and two of its edits (a leg or a size, a wall, a
    step, a fillet) made through the param of that name and value give the design drawn
    with that number changed."""
    tmp = tmp_path_factory.mktemp("p")
    rng = random.Random(seed)
    d = gp.random_profile(rng, kind)
    r = bench.run_drawing(d, tmp, rng, 2)
    assert r["exact"] and not r["error"], (d.describe(), r["program"])
    bad = [(e.label, o, dt) for e, o, dt in r["edits"] if o != "meant"]
    assert not bad, (d.describe(), bad, r["program"])


@pytest.mark.parametrize("kind", gp.PROFILE_KINDS)
def test_the_generator_draws_each_kind_read_back_by_ezdxf(kind):
    """Each kind's drawing, read back by ezdxf alone, is its design's loops exactly."""
    d = gp.random_profile(random.Random(3), kind)
    d.style = dict(d.style, format="dxf")
    layers, _ = bench.gen.read_dxf(bench.gen.to_dxf(d), d.u)
    got = [lp for loops in layers.values() for lp in loops]
    want = [lp for _, lp in d.loops()]
    left, rest = bench.gen.match(
        *(bench.gen.normalised([bench.gen.signature(lp) for lp in x])[0] for x in (want, got)))
    assert not left and not rest
