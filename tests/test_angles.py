"""`pi` and `tau` are radians where they meet an angle (issue 84, "Angles silently wrong").

A bare number next to an angle is degrees (docs/language.md 5.4), and `pi` and `tau` were bare
numbers: in a door sign, `cos(theta + k * (tau - 2 * theta) / n)` with `theta = atan2(...)`
read `tau` as 6.28 deg, and the moon came out 24.7 x 39.4 mm with its horns the wrong way
instead of 33 x 44 mm, with no word said.  Now `pi`, `tau` and what arithmetic makes of them
(`2 * pi / n`, `pi * module / pitch_r`) count radians: next to an angle, or given for one,
`pi` is 180 deg; in plain arithmetic it is 3.14159 as before.

The laws compile generated expressions with the real compiler: each trig expression gives
the value of the same program with `pi` written `(180 deg)` and `tau` `(360 deg)`, and the
angle-sum identity holds for every number of radians added to an angle.
"""
from __future__ import annotations

import functools
import math

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

import aidl_lang
from exact_geometry import L, read_dxf

# a crescent: the outer circle's arc from one horn round the back to the other, then the
# inner circle's arc back; the horns where the two circles cross, found with atan2
MOON = """
R = 22              # outer radius: the moon is 44 mm tall
hx = 11             # the horns' x: the moon is 22 + 11 = 33 mm wide
hy = sqrt(R * R - hx * hx)
cx = 16             # the inner circle's center
r = sqrt((hx - cx) * (hx - cx) + hy * hy)
theta = atan2(hy, hx)           # a horn, seen from the outer center
phi = atan2(hy, hx - cx)        # the same horn, seen from the inner center
n = 24
solid moon {
    outer = [(R * cos(theta + k * (TURN - 2 * theta) / n),
              R * sin(theta + k * (TURN - 2 * theta) / n)) for k in range(n + 1)]
    inner = [(cx + r * cos(TURN - phi - k * (TURN - 2 * phi) / n),
              r * sin(TURN - phi - k * (TURN - 2 * phi) / n)) for k in range(1, n)]
    body = Polygon(outer + inner)
}
"""


def _moon_truth(n: int = 24) -> list[tuple[float, float]]:
    """The crescent's outline computed here, in radians, as the sign's maker meant it."""
    R, hx, cx = 22.0, 11.0, 16.0
    hy = math.sqrt(R * R - hx * hx)
    r = math.hypot(hx - cx, hy)
    th, ph = math.atan2(hy, hx), math.atan2(hy, hx - cx)
    tau = 2 * math.pi
    out = [(R * math.cos(th + k * (tau - 2 * th) / n), R * math.sin(th + k * (tau - 2 * th) / n))
           for k in range(n + 1)]
    inner = [(cx + r * math.cos(tau - ph - k * (tau - 2 * ph) / n),
              r * math.sin(tau - ph - k * (tau - 2 * ph) / n)) for k in range(1, n)]
    return out + inner


@pytest.mark.parametrize("turn", ["tau", "2 * pi", "360 deg", "tau * 1 rad"])
def test_door_sign_moon_is_33_by_44_mm(turn, tmp_path):
    """The door sign's crescent, re-read from its DXF with ezdxf: 33 x 44 mm, its back on
    the left (x from -22 to 11), the outline the maker computed (shapely: no area between
    them).  Before, `tau` was 6.28 deg there: 24.7 x 39.4 mm, from x = 11 to 35.7, the horns
    the wrong way, with no diagnostic."""
    from shapely.geometry import Polygon
    r = aidl_lang.compile(source=MOON.replace("TURN", turn))
    assert r.ok and not r.diagnostics, [d.message for d in r.diagnostics]
    out = r.write(tmp_path / "moon.dxf")
    segs = [s for ent in read_dxf(out) for s in ent.segments]
    assert segs and all(isinstance(s, L) for s in segs)
    xs = [p[0] for s in segs for p in (s.start, s.end)]
    ys = [p[1] for s in segs for p in (s.start, s.end)]
    assert min(xs) == pytest.approx(-22, abs=1e-9) and max(xs) == pytest.approx(11, abs=1e-9)
    assert min(ys) == pytest.approx(-22, abs=1e-9) and max(ys) == pytest.approx(22, abs=1e-9)
    got = Polygon([s.start for s in segs])
    truth = Polygon(_moon_truth())
    assert got.is_valid and got.area == pytest.approx(truth.area, rel=1e-9)
    assert got.symmetric_difference(truth).area < 1e-6


def _values(src: str, *names: str) -> list[float]:
    r = aidl_lang.compile(source=src + '\nsolid s { b = Rectangle(center=(0, 0), width=10, height=10) }\n')
    assert r.ok, [d.message for d in r.diagnostics]
    return [r.value(n).value for n in names]


def test_pi_is_180_deg_next_to_an_angle_and_a_number_elsewhere():
    """Where `pi` meets an angle it is pi radians; in plain arithmetic (a length, `sin`) it
    is the number 3.14159 as before."""
    src = """
module = 2 mm
pitch_r = 20 mm
a = 30 deg + pi / 2
b = 10 deg - tau / 8
c = 10 deg + pi * module / pitch_r
d = 10 deg + max(pi / 2, tau / 8)
e = 10 deg - pi * pi / pi
f = 10 deg + pi / pi
g = 10 deg + 2 * (pi + 1) / 2
h = 10 deg + round(pi / 4, 3)
i = 10 deg + sqrt(pi * pi)
c3 = cos(3 * pi)
circ = 2 * pi * 10 mm
num = pi / 2
s6 = sin(pi / 6)
"""
    r = aidl_lang.compile(source=src + "solid s { b = Rectangle(center=(0, 0), width=1, height=1) }")
    assert r.ok and not r.diagnostics
    v = {n: r.value(n).value for n in ("a", "b", "c", "d", "e", "f", "g", "h", "i", "c3", "circ",
                                         "num", "s6")}
    assert v["a"] == pytest.approx(120) and v["b"] == pytest.approx(-35)
    assert v["c"] == pytest.approx(10 + 18)            # pi * 2 / 20 rad = 18 deg
    assert v["d"] == pytest.approx(100)
    assert v["e"] == pytest.approx(-170)               # pi * pi / pi: radians again
    assert v["f"] == pytest.approx(11)                 # pi / pi: the plain number 1, degrees
    assert v["g"] == pytest.approx(10 + math.degrees(math.pi + 1))   # 1 next to pi: radians
    assert v["h"] == pytest.approx(10 + math.degrees(0.785)) and v["i"] == pytest.approx(190)
    assert v["c3"] == pytest.approx(-1)                # and no W0107: 3 pi is meant as radians
    assert v["circ"] == pytest.approx(20 * math.pi) and v["num"] == pytest.approx(math.pi / 2)
    assert v["s6"] == pytest.approx(0.5)
    assert r.value("circ").unit == "mm" and r.value("num").unit == ""


def test_pi_given_for_an_angle():
    """`rotation=pi / 4` is 45 deg (a square turned to a diamond 14.14 mm across), not
    0.785 deg; a template's angle parameter, a constraint and a comparison read it alike."""
    src = """
def spoke(turn=10 deg) -> solid {
    b = Rectangle(center=(0, 0), width=10, height=10, rotation=turn)
}
assert pi / 4 < 50 deg and pi / 4 > 40 deg, "pi / 4 is 45 deg"
solid a { b = Rectangle(center=(0, 0), width=10, height=10, rotation=pi / 4) }
c = spoke(turn=pi / 4)
drawing d {
    l = Line(start=(0, 40), end=(10, 41))
    l.angle == tau / 8
    a = l.angle
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [d.message for d in r.diagnostics]
    half = 5 * math.sqrt(2)
    boxes = {p.name: p.bbox for p in r.parts}
    for box in (boxes["model.a"], boxes["model.c"]):
        assert box[2] - box[0] == pytest.approx(2 * half, abs=1e-6)
    assert r.value("d.a").value == pytest.approx(45, abs=1e-6)


# ------------------------------------------------------------------ laws
_ANGLE_LEAVES = st.one_of(st.integers(-180, 180).map(lambda n: f"{n} deg"),
                          st.sampled_from(["th", "atan2(1, 2)", "atan2(-3, 1)"]))
_BARE_LEAVES = st.integers(1, 9).map(str)


@functools.cache
def _expr(kind: str, depth: int, mixed: bool):
    """Programs text of a trigonometric argument of ``kind``: "angle", "bare" (plain
    numbers) or "rad" (built from pi and tau); ``mixed``: "rad" may also add a plain number
    (`tau - 3`, radians by the rule; the substitution law leaves those out).  Made once for
    each (kind, depth, mixed): the laws draw it inside a ``flatmap``, and building the tree
    of strategies again at every draw was most of their time (3.1 s of CPU for 40 examples;
    the same draws now)."""
    if depth == 0:
        return {"angle": _ANGLE_LEAVES, "bare": _BARE_LEAVES,
                "rad": st.sampled_from(["pi", "tau"])}[kind]
    sub = lambda k: _expr(k, depth - 1, mixed)   # noqa: E731
    pm = st.sampled_from(["+", "-"])

    def bin_(a, op, b):
        return st.tuples(a, op, b).map(lambda t: f"({t[0]} {t[1]} {t[2]})")
    if kind == "angle":
        forms = [bin_(sub("angle"), pm, sub("angle")), bin_(sub("angle"), pm, sub("bare")),
                 bin_(sub("bare"), pm, sub("angle")), bin_(sub("angle"), pm, sub("rad")),
                 bin_(sub("rad"), pm, sub("angle")), bin_(sub("angle"), st.just("*"), sub("bare")),
                 bin_(sub("bare"), st.just("*"), sub("angle")),
                 bin_(sub("angle"), st.just("/"), _BARE_LEAVES)]
    elif kind == "bare":
        forms = [bin_(sub("bare"), st.sampled_from(["+", "-", "*"]), sub("bare")),
                 bin_(sub("bare"), st.just("/"), _BARE_LEAVES)]
    else:
        forms = [bin_(sub("rad"), st.just("*"), sub("bare")), bin_(sub("bare"), st.just("*"), sub("rad")),
                 bin_(sub("rad"), st.just("/"), _BARE_LEAVES), bin_(sub("rad"), pm, sub("rad")),
                 sub("rad").map(lambda x: f"(-{x})")]
        if mixed:
            forms += [bin_(sub("rad"), pm, sub("bare")), bin_(sub("bare"), pm, sub("rad"))]
    return st.one_of(_expr(kind, 0, mixed), *forms)


def _compile_values(exprs: list[str], fns=("sin", "cos", "tan")):
    lines = ["th = atan2(3, 4)"]
    for i, x in enumerate(exprs):
        lines += [f"{f}{i} = {f}({x})" for f in fns] + [f"c{i} = cos({x})"]
    r = aidl_lang.compile(source="\n".join(lines)
                          + "\nsolid s { b = Rectangle(center=(0, 0), width=10, height=10) }\n")
    assert r.ok, [d.message for d in r.diagnostics]
    vals = [{f: r.value(f"{f}{i}").value for f in fns + ("c",)} for i in range(len(exprs))]
    return vals, sorted(d.code for d in r.diagnostics)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.sampled_from(["angle", "bare", "rad"]).flatmap(
    lambda k: st.integers(0, 3).flatmap(lambda d: _expr(k, d, False))), min_size=1, max_size=6))
def test_law_pi_means_180_deg_where_it_meets_an_angle(exprs):
    """Every sin/cos/tan of a tree of + - * / over angles in deg, atan2 results, plain
    numbers, pi and tau gives the value of the same program with `pi` written `(180 deg)`
    and `tau` `(360 deg)`; neither gives a warning but W0107 (sin of an all-plain number
    past a whole turn), the same on both.  Before issue 84, `30 deg + pi` was 33.14 deg."""
    got, codes = _compile_values(exprs)
    sub = [x.replace("tau", "(360 deg)").replace("pi", "(180 deg)") for x in exprs]
    want, codes_sub = _compile_values(sub)
    assert codes == codes_sub and set(codes) <= {"W0107"}
    for x, g, w in zip(exprs, got, want):
        for f in ("sin", "cos"):
            assert g[f] == pytest.approx(w[f], abs=1e-9), (x, f)
        if abs(w["c"]) > 1e-3:
            assert g["tan"] == pytest.approx(w["tan"], rel=1e-6, abs=1e-9), x


# 10 examples (40 before): issue 84's defect (pi next to an angle read as 3.14 deg, every
# angle_scale giving deg) fails it in 10 of 10 seeds at 3 examples already
@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_ANGLE_LEAVES, st.integers(0, 3).flatmap(lambda d: _expr("rad", d, True)))
def test_law_radians_added_to_an_angle_are_radians(theta, x):
    """For every number made from pi and tau (plain numbers added to it included, and
    `pi * module / pitch_r`), `cos(theta + x)` is `cos(theta) cos(x) - sin(theta) sin(x)`
    and likewise `sin`: `x` is read in radians next to an angle as it is in `sin(x)`."""
    x2 = f"({x} * module / pitch_r)"
    src = "\n".join(["th = atan2(3, 4)", "module = 2 mm", "pitch_r = 2 mm"] + [
        f"cs{i} = cos({theta} + {v})\nsn{i} = sin({theta} + {v})\nca{i} = cos({theta})\n"
        f"sa{i} = sin({theta})\ncx{i} = cos({v})\nsx{i} = sin({v})" for i, v in enumerate((x, x2))])
    names = [f"{p}{i}" for i in range(2) for p in ("cs", "sn", "ca", "sa", "cx", "sx")]
    v = dict(zip(names, _values(src, *names)))
    for i in range(2):
        assert v[f"cs{i}"] == pytest.approx(v[f"ca{i}"] * v[f"cx{i}"] - v[f"sa{i}"] * v[f"sx{i}"], abs=1e-9)
        assert v[f"sn{i}"] == pytest.approx(v[f"sa{i}"] * v[f"cx{i}"] + v[f"ca{i}"] * v[f"sx{i}"], abs=1e-9)


# ------------------------------------------------------------------ the corpus
def test_no_program_of_the_corpus_changes(monkeypatch):
    """Every program of the examples, the standard library, tests/programs, the benchmarks and
    the model-written runs under data/ that names `pi` or `tau` or imports a file: none of
    them reads a number made from pi as an angle, so each gives the same value under the
    rule as before it (the rule changes only programs that mixed pi with angles, which were
    wrong: 3.14 deg).  Read during interpretation, where the rule acts."""
    from pathlib import Path
    import re

    import aidl_lang.geometry.core.values as values
    import aidl_lang.interpreter.calls as calls
    import aidl_lang.interpreter.statements as statements
    from aidl_lang.pipeline import compile_source
    root = Path(__file__).resolve().parents[1]
    met = []

    def counting(q, deg, _real=values.angle_scale):
        k = _real(q, deg)
        if k == 1.0:
            met.append(q.const())
        return k
    for m in (values, calls, statements):
        monkeypatch.setattr(m, "angle_scale", counting)
    files = [p for d in ("examples", "aidl_lang/examples", "stdlib", "tests/programs", "data",
                         "benchmarks") for p in sorted((root / d).rglob("*.aidl"))]
    chosen = [p for p in files if re.search(r"\b(pi|PI|tau)\b|^import", p.read_text(), re.M)]
    assert len(files) > 200 and len(chosen) > 50
    # each program once: aidl_lang/examples is a link to examples/, and the model runs under
    # data/ hold the same text in several folders (a text that imports only the standard
    # library means the same wherever it is): 90 compiles were 61
    once = {}
    for p in chosen:
        text = p.read_text()
        local = re.search(r'^\s*import\s+"(?!std/)', text, re.M)
        once.setdefault(p.resolve() if local else text, p)
    chosen = list(once.values())
    # an angle times a ratio of lengths keeps its radian (run fk's squirrel baffle, `360 deg
    # * RB / L`, read as 5.058 deg before: wrong, a 5 deg sliver cut for a 290 deg pattern);
    # its radians are met where it meets an angle, as the rule means
    wrong_before = {"03_squirrel_baffle.first_valid.aidl"}
    for p in chosen:
        compile_source(p.read_text(), str(p), do_solve=False)
        if p.name in wrong_before:
            assert met, p
            met.clear()
        assert not met, (p, met)
    # and the door sign does meet it
    compile_source(MOON.replace("TURN", "tau"), "moon.aidl", do_solve=False)
    assert met
