"""Issue 85, "recognise what makers draw": a double-D hole, a keyway (a bore with a key slot)
and a skewed vent row (slots at an angle, in a row; in an SVG their half circles are path arcs
split at the quadrants) come back from `aidl import --infer` with the size params a person
keeps (``ddhole_d``, ``ddhole_flat`` across the flats; ``keyway_d``, ``keyway_w``,
``keyway_depth`` past the bore; the slots' length), the program exactly the drawing,
compiling clean and fully constrained, and each param, edited, gives the drawing of the
edited design (the generator's, tests/gen_drawings.py, drawn again and compared loop by loop
to 1e-6 mm by benchmarks/imports/infer_edits.py's independent reader)."""
from __future__ import annotations

import math
import random
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import aidl_lang
import gen_drawings as gen
from aidl_lang.drawing.infer import import_drawing
from aidl_lang.drawing.infer.holes.bores import double_d, keyway
from aidl_lang.drawing.infer.shapes import merged
from aidl_lang.geometry.shapes.curves import Arc, Line
from benchmarks.imports import infer_edits as bench

FEATURES = {
    "ddhole": {"kind": "ddhole", "ax": ("L", 20), "ay": ("B", 15), "d": 10, "af": 7,
               "angle": 0},
    "ddhole90": {"kind": "ddhole", "ax": ("R", 25), "ay": ("C", 0.0), "d": 12, "af": 8,
                 "angle": 90},
    "keyway": {"kind": "keyway", "ax": ("L", 25), "ay": ("C", 0.0), "d": 16, "kw": 4,
               "depth": 2, "angle": 90},
    "keyway30": {"kind": "keyway", "ax": ("R", 20), "ay": ("T", 20), "d": 12, "kw": 3,
                 "depth": 1.5, "angle": 210},
    "ventrow": {"kind": "ventrow", "ax": ("C", 0.0), "ay": ("T", 15), "dir": "x", "n": 4,
                "p": 12, "w": 4, "length": 16, "angle": 45},
}
CASES = [  # (feature, format, design key, new value, the param's name)
    ("ddhole", "dxf", "d", 12, "ddhole_d"),
    ("ddhole", "svg", "af", 6, "ddhole_flat"),
    ("ddhole90", "dxf", "af", 9, "ddhole_flat"),
    ("keyway", "dxf", "d", 18, "keyway_d"),
    ("keyway", "svg", "kw", 5, "keyway_w"),
    ("keyway30", "dxf", "depth", 2.5, "keyway_depth"),
    ("ventrow", "svg", "length", 20, r"\w+_length"),
    ("ventrow", "dxf", "length", 12, r"\w+_length"),
]


def _design(name: str, fmt: str) -> gen.Design:
    d = gen.Design("mm", 120, 80, ("square", 0.0), (0.0, 0.0), [dict(FEATURES[name])])
    d.style = {"format": fmt, "layers": None, "blocks": True, "bulges": fmt == "dxf",
               "insunits": True}
    assert d.valid()
    return d


@pytest.mark.parametrize("name,fmt,key,new,param", CASES,
                         ids=[f"{c[0]}-{c[1]}-{c[2]}" for c in CASES])
def test_a_bore_or_vent_row_comes_back_with_its_size_params(tmp_path, name, fmt, key, new,
                                                           param):
    d = _design(name, fmt)
    suffix, data = gen.export(d)
    text, _ = import_drawing(data, "m" + suffix, infer=True)
    found = re.search(rf"^param ({param}) = ([0-9.]+) mm(,.*)?$", text, re.M)
    assert found, text
    res = aidl_lang.compile(text, path=tmp_path / "m.aidl")
    warned = [x for x in res.diagnostics if x.severity == "warning"]
    assert res.ok and not warned and res.freedom()["dof"] == 0, (text, [str(x) for x in warned])
    assert bench.compare(d, bench.output_of(text, tmp_path / "b.aidl"), tmp_path) == [], text
    e = next(e for e in d.edits() if e.feature == 0 and e.key == key)
    want = d.edited(e, new)
    assert want.valid()
    got = bench.output_of(text, tmp_path / "e.aidl", {found.group(1): f"{new} mm"})
    assert not isinstance(got, str), got
    assert bench.compare(want, got, tmp_path) == [], text
    assert bench.compare(d, got, tmp_path) != []          # the edit changed the drawing


def _pieces(loop, turn: int, flip: bool) -> list:
    """The generator's loop as the inference's curves, its pieces started at ``turn`` and
    run backwards when ``flip``, arcs split at their middles (as readers split them)."""
    out = []
    for g in loop:
        if g[0] == "L":
            out.append(Line(g[1], g[2]))
        else:
            _, c, r, a, sw = g
            out += [Arc(c, r, a, sw / 2), Arc(c, r, a + sw / 2, sw / 2)]
    out = out[turn % len(out):] + out[:turn % len(out)]
    if flip:
        out = [Line(s.end, s.start) if isinstance(s, Line) else
               Arc(s.center, s.radius, s.start_angle + s.sweep, -s.sweep) for s in reversed(out)]
    return merged(out)


def _turn(a: float, b: float, period: float) -> float:
    return abs((a - b + period / 2) % period - period / 2)


@settings(max_examples=60, deadline=None)
@given(x=st.floats(-200, 200), y=st.floats(-200, 200), d=st.floats(2, 60),
       ratio=st.floats(0.15, 0.9), ang=st.floats(-360, 360), turn=st.integers(0, 9),
       flip=st.booleans())
def test_bores_are_recognised_with_their_known_sizes(x, y, d, ratio, ang, turn, flip):
    """Law: a double-D and a keyway of any size, place, direction, starting piece and
    sense, their arcs split, give back their centre, diameter, across-flats / key width and
    depth and direction; neither is taken for the other, nor a D-hole or a slot for either."""
    a = math.radians(ang)
    got = double_d(_pieces(gen.ddhole_loop((x, y), d, d * ratio, a), turn, flip))
    assert got is not None and keyway(_pieces(gen.ddhole_loop((x, y), d, d * ratio, a),
                                              turn, flip)) is None
    c, dd, af, g = got
    assert math.dist(c, (x, y)) < 1e-7 and abs(dd - d) < 1e-7 and abs(af - d * ratio) < 1e-7
    assert _turn(g, a, math.pi) < 1e-7 and -math.pi / 2 < g <= math.pi / 2 + 1e-9
    kw, depth = d * ratio * 0.8, d * ratio / 3
    loop = _pieces(gen.keyway_loop((x, y), d, kw, depth, a), turn, flip)
    got = keyway(loop)
    assert got is not None and double_d(loop) is None
    c, dd, w, k, g = got
    assert math.dist(c, (x, y)) < 1e-7 and abs(dd - d) < 1e-7 and abs(w - kw) < 1e-7
    assert abs(k - depth) < 1e-7 and _turn(g, a, 2 * math.pi) < 1e-7
    for other in (gen.dhole_loop((x, y), d, d * ratio / 2, a),
                  gen.slot_loop((x, y), d * (1 + ratio), d * ratio, a)):
        assert double_d(_pieces(other, turn, flip)) is None
        assert keyway(_pieces(other, turn, flip)) is None


@settings(max_examples=12, deadline=None)
@given(seed=st.integers(0, 10 ** 6), kind=st.sampled_from(gen.NEW_KINDS))
def test_generated_new_kinds_read_back_and_infer_exactly(tmp_path_factory, seed, kind):
    """Law: a generated design with a double-D, a keyway or a skewed vent row (and others of
    every kind), exported as DXF or SVG, read back by ezdxf / svgelements alone, has exactly
    the design's loops; its inferred program draws it exactly."""
    d = gen.random_design(random.Random(seed), [kind], pool=gen.ALL_KINDS)
    assert any(f["kind"] == kind for f in d.features)
    want = gen.normalised([gen.signature(lp) for _, lp in d.loops()])[0]
    layers, _ = gen.read_dxf(gen.to_dxf(d), d.u)
    got = gen.normalised([gen.signature(lp) for ly, ls in layers.items() if ly != "CSK"
                          for lp in ls])[0]     # (countersink marks: not loops of the part)
    assert gen.match(want, got) == ([], [])
    loops, _ = gen.read_svg(gen.to_svg(d))
    got = gen.normalised([gen.signature(lp) for lp in loops])[0]
    assert gen.match(want, got) == ([], [])
    tmp = tmp_path_factory.mktemp("g")
    r = bench.run_drawing(d, tmp, random.Random(seed), k=0)
    assert r["exact"] and not r["error"], (d.describe(), r["program"], r["error"])


def test_each_size_of_a_kind_has_its_own_numbered_params(tmp_path):
    """Three double-D holes of three sizes: ``ddhole_d``, ``ddhole_2_d``, ``ddhole_3_d`` (not
    ``ddhole_2_2_d``: the holes' names are not the params'), each editing its own hole."""
    feats = [{"kind": "ddhole", "ax": ("L", 15 + 30 * k), "ay": ("C", 0.0), "d": 10 + 2 * k,
              "af": 7 + k, "angle": 0} for k in range(3)]
    d = gen.Design("mm", 120, 60, ("square", 0.0), (0.0, 0.0), feats)
    d.style = {"format": "dxf", "layers": None, "blocks": False, "bulges": True,
               "insunits": True}
    assert d.valid()
    text, _ = import_drawing(gen.to_dxf(d), "m.dxf", infer=True)
    names = re.findall(r"^param (ddhole\w*_d) = ([0-9.]+) mm$", text, re.M)
    assert sorted(n for n, _ in names) == ["ddhole_2_d", "ddhole_3_d", "ddhole_d"], text
    e = next(e for e in d.edits() if e.feature == 1 and e.key == "d")
    got = bench.output_of(text, tmp_path / "e.aidl", {dict((v, n) for n, v in names)["12"]:
                                                      "13 mm"})
    assert bench.compare(d.edited(e, 13), got, tmp_path) == [], text
