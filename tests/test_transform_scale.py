"""Scale, move and flip a whole structure (issue 95): `Scaled`, `Translated` (copies, as
`Mirrored`), `Scale`, `Translate` (`Move`) and `Flip` (in place).

The laws of tests/test_transform_laws.py, for the new operations: every closed kind scaled
about a point (factors below and above 1) and moved is exactly the original's exact outline
mapped by shapely.affinity; every template there (a filleted plate with a hole, fillets at
chosen corners, an outline of lines, an arc and a spline, the stdlib spur gear) scaled as a
structure is its final part scaled, fillets included.  The issue's case: a bicycle plaque
made 30 % smaller by one `Scale(plaque, 0.7)`, its SVG read back with svgelements: every
path's box and length 0.7 times the unscaled plaque's.  (~6 s CPU.)"""
from __future__ import annotations

import math

import pytest
import svgelements
from hypothesis import given, strategies as st

import aidl_lang
from test_transform_laws import (LAWS, SHAPES, TEMPLATES, _compile, _loops, _parts, _program,
                                 _region, _same, _strokes, _same_curve, TEXT)
from shapely import affinity
from shapely.geometry import Point

SCALABLE = sorted(k for k in SHAPES if k != "Drawing2D")


def _scaling(k, cx, cy):
    return [k, 0, 0, k, cx - k * cx, cy - k * cy]


@pytest.mark.parametrize("kind", SCALABLE)
@LAWS
@given(k=st.sampled_from([0.7, 1.6, 0.25]), c=st.sampled_from([(0, 0), (12, 5), (-20, 31)]),
       by=st.sampled_from([(25, 0), (-7, 18)]))
def test_scaled_and_translated_copies_are_the_mapped_original(kind, k, c, by):
    ops = (f"    m = Scaled(s, {k}, center=({c[0]}, {c[1]}))\n"
           f"    t = Translated(s, by=({by[0]}, {by[1]}))\n")
    L = _loops(_compile(_program(SHAPES[kind], ops)), ["s", "m", "t"])
    _same(L["m"], _region(L["s"], _scaling(k, *c), k), f"{kind} scaled {k} about {c}")
    _same(L["t"], _region(L["s"], [1, 0, 0, 1, *by]), f"{kind} moved by {by}")


@LAWS
@given(k=st.sampled_from([0.5, 2.0]))
def test_scaled_text_is_every_stroke_scaled(k):
    r = _compile(f"units mm\ndrawing d {{\n    {TEXT}\n    m = Scaled(s, {k}, center=(3, -4))\n}}\n")
    orig, got = _strokes(r, "d.s"), _strokes(r, "d.m")
    assert len(orig) >= 7 and len(got) == len(orig)
    for g, o in zip(got, orig):
        ref = [affinity.affine_transform(Point(p), _scaling(k, 3, -4)).coords[0] for p in o]
        _same_curve(g, ref, False, f"Text scaled {k}")


@pytest.mark.parametrize("what", sorted(TEMPLATES))
def test_a_scaled_structure_is_its_part_scaled(what):
    """A template instance scaled as a structure: its final part (booleans, fillets and
    chamfers after them, their radii scaled too) is the original part scaled."""
    defs, call = TEMPLATES[what]
    src = (f'units mm\nimport "std/gears.aidl" as gears\n{defs}assembly kit {{\n'
           f"    a = {call}\n    b = Scaled(a, 0.6, center=(-40, 25))\n}}\n")
    P = _parts(_compile(src))
    _same(P["kit.b"], _region(P["kit.a"], _scaling(0.6, -40, 25), 0.6), f"{what} scaled")


PLAQUE = """units mm
solid plaque {
    body = RoundedRectangle(center=(0, 0), width=140, height=80, corner_radius=10)
    hole back_wheel { c = Circle(center=(-38, -12), radius=20) }
    hole front_wheel { c = Circle(center=(38, -12), radius=20) }
    hole mount { m = Slot(center=(0, 30), length=30, width=6) }
    drawing frame {
        a = Line(start=(-38, -12), end=(-5, 14))
        b = Line(start=(-5, 14), end=(30, 14))
        c = Line(start=(30, 14), end=(38, -12))
        d = Line(start=(-5, 14), end=(2, -12))
        e = Line(start=(2, -12), end=(38, -12))
        name = Text("RIDE", position=(0, -32), size=7)
    }
    Fixed(body.center)
    Fillet(radius=2)
}
"""


def _svg(tmp_path, src, name):
    p = tmp_path / f"{name}.aidl"
    p.write_text(src)
    out = tmp_path / f"{name}.svg"
    from aidl_lang.cli.main import main
    assert main(["render", str(p), "-o", str(out)]) == 0
    shapes = [e for e in svgelements.SVG.parse(str(out)).elements()
              if isinstance(e, svgelements.Shape) and not isinstance(e, svgelements.Rect)]
    return [(e.bbox(), svgelements.Path(e).length()) for e in shapes
            if e.bbox() is not None]


def test_the_issue_s_bicycle_plaque_made_30_percent_smaller_by_one_scale(tmp_path):
    """One `Scale(plaque, 0.7)` (was: ~30 numbers multiplied by hand): the SVG, read back,
    holds the same paths, each box and length 0.7 times the unscaled plaque's; the plaque's
    sizes read 0.7 times (98 x 56 mm, its wheels 28 mm across), and statements after the
    Scale reach the scaled plaque by its name."""
    before = _svg(tmp_path, PLAQUE, "before")
    after = _svg(tmp_path, PLAQUE + "Scale(plaque, 0.7)\nassert plaque.bb.width == 98 mm\n",
                 "after")
    assert len(after) == len(before) >= 10
    for (b0, l0), (b1, l1) in zip(sorted(before), sorted(after)):
        assert [v * 0.7 for v in b0] == pytest.approx(list(b1), abs=1e-3)
        assert l1 == pytest.approx(0.7 * l0, rel=1e-4)
    r = aidl_lang.compile(source=PLAQUE + "Scale(plaque, 0.7)\n")
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    [part] = r.output.parts
    x0, x1, y0, y1 = _box(part)
    assert (round(x1 - x0, 9), round(y1 - y0, 9)) == (98, 56)
    v = {x.name: x.value for x in r.values}
    assert v["plaque.body.width"] == pytest.approx(98) and v["plaque.back_wheel.c.radius"] == \
        pytest.approx(14)


def _box(part):
    """(x0, x1, y0, y1) of a part's exact outline."""
    from aidl_lang.api import exact_bbox
    x0, y0, x1, y1 = exact_bbox([seg for lp in part.loops for seg in lp.segments])
    return x0, x1, y0, y1


def test_translate_and_flip_in_place_keep_the_name(tmp_path):
    """`Translate(plaque, (200, 10))` moves the part (its name kept, the original
    construction as `plaque_original`); `Move` is its synonym; `Flip` mirrors a shape in
    place about a line."""
    r = aidl_lang.compile(source=PLAQUE + "Move(plaque, (200, 10))\n")
    assert r.ok
    v = {x.name: x.value for x in r.values}
    assert v["plaque.body.center"] == pytest.approx((200, 10))
    assert v["plaque_original.body.center"] == pytest.approx((0, 0))
    [part] = r.output.parts
    assert part.name.endswith("plaque") and _box(part)[0] == pytest.approx(200 - 70)
    src = ("units mm\nsolid p {\n    body = Polygon(points=[(0, 0), (30, 0), (30, 12), (12, 20)])\n"
           "    axis = Line(start=(0, -10), end=(0, 30), construction=true)\n    Fixed(axis)\n"
           "    Fixed(body.points[0])\n    Flip(body, about=axis)\n}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok
    [part] = r.output.parts
    assert _box(part) == pytest.approx((-30, 0, 0, 20))
    v = {x.name: x.value for x in r.values}
    assert v["p.body.p1"] == pytest.approx((-30, 0)) and v["p.body_original.p1"] == pytest.approx((30, 0))


@pytest.mark.parametrize("call,said", [
    ("Scale(plaque, 0)", "a factor more than 0"),
    ("Scale(plaque, -0.5)", "a factor more than 0"),
])
def test_a_factor_that_is_no_scale_is_refused_at_the_call(call, said):
    r = aidl_lang.compile(source=PLAQUE + call + "\n")
    [e] = r.errors
    assert e.code == "E0108" and said in e.message and e.span.line == PLAQUE.count("\n") + 1


def test_scale_twice_in_place_is_refused():
    r = aidl_lang.compile(source=PLAQUE + "Scale(plaque, 0.7)\nScale(plaque, 0.5)\n")
    [e] = r.errors
    assert "changed in place already" in e.message


@pytest.mark.parametrize("syn,canon,args", [
    ("Move", "Translate", "(20, 5)"), ("Shift", "Translate", "(20, 5)"),
    ("Moved", "Translated", "by=(20, 5)"), ("Resize", "Scale", "0.5, center=(3, 4)"),
    ("Resized", "Scaled", "0.5, center=(3, 4)")])
def test_a_synonym_is_its_transform(syn, canon, args):
    """Each synonym gives the canonical operation's parts, point for point."""
    def parts(name):
        r = aidl_lang.compile(source=PLAQUE + f"x = {name}(plaque, {args})\n")
        assert r.ok, [(d.code, d.message) for d in r.diagnostics]
        return sorted((p.name, _box(p)) for p in r.output.parts)
    want = parts(canon)
    assert parts(syn) == want and len(want) >= 1


# ---------------------------------------------------------------- issue 105: Scale in place
STAR_ON_TREE = """units mm
{kind} card {{
    solid tree {{
        body = Triangle(center=(0, 0), base=60, height=80)
    }}
    solid star {{
        s = Star(center=(10, 60), points=5, outer_radius=8, inner_radius=4)
    }}
    At(star.s.center, tree.body.center, dy={dy})
    Scale(star, {k})
}}
"""


def _star_tips(r, name="card.star.s"):
    v = {x.name: x.mm for x in r.values}
    c = v[f"{name}.center"]
    return c, [math.dist(v[f"{name}.p{i}"], c) for i in range(0, 10, 2)]


@pytest.mark.parametrize("kind", ["assembly", "solid"])
def test_the_issues_star_scaled_after_its_at_keeps_the_centre_the_at_gave_it(kind):
    """`Scale(star, 1.5)` after `At(star.s.center, tree.body.center, dy=45)`: the scaled star
    is the one placed, its centre at (0, 45) and its tips 12 mm out (before: scaled about
    the origin, the `At` held the hidden original and the star's centre was at (0, 67.5),
    off the tree: W0504 in a solid, whose hint added a second placement)."""
    r = aidl_lang.compile(source=STAR_ON_TREE.format(kind=kind, dy=45, k=1.5))
    assert r.ok and "W0504" not in [d.code for d in r.diagnostics]
    c, tips = _star_tips(r)
    assert c == pytest.approx((0, 45), abs=1e-9)
    assert tips == pytest.approx([12] * 5, abs=1e-9)
    drawn = {p.name for p in r.output.parts}
    assert not any("star_original" in n for n in drawn)


def test_a_scaled_star_that_falls_off_says_to_change_its_placement_not_add_one():
    r = aidl_lang.compile(source=STAR_ON_TREE.format(kind="solid", dy=52, k=0.5))
    [w] = [d for d in r.diagnostics if d.code == "W0504"]
    assert "`card.star` is scaled in place (`Scale`, factor 0.5) about its own centre" in w.hint
    assert "not by adding a second placement" in w.hint and "Above(" not in w.hint
    assert _star_tips(r)[0] == pytest.approx((0, 52), abs=1e-9)


def test_scale_keeps_a_things_own_centre_and_scaled_keeps_the_origin():
    """Nothing places them: `Scale` of a shape and of a structure (its box: the ring and a
    hole poking out of it) keeps the box's centre where it is written; `Scaled` without
    `center=` scales about the origin (issue 95's default)."""
    src = """units mm
assembly a {
    solid ring {
        o = Circle(center=(40, 10), radius=10)
        hole h { c = Circle(center=(50, 10), radius=4) }
    }
    solid dot { d = Circle(center=(-30, 5), radius=2) }
    solid far { f = Rectangle(center=(20, -40), width=10, height=6) }
    Scale(ring, 2)
    Scale(dot.d, 3)
    twice = Scaled(far, 2)
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]
    v = {x.name: x.mm for x in r.values}
    # the ring's box: x from 30 to 54 (the hole pokes 4 mm out), y from 0 to 20: centre (42, 10)
    assert v["a.ring.o.center"] == pytest.approx((42 + 2 * (40 - 42), 10), abs=1e-9)
    assert v["a.ring.h.c.center"] == pytest.approx((42 + 2 * (50 - 42), 10), abs=1e-9)
    assert v["a.ring.o.radius"] == pytest.approx(20, abs=1e-9)
    assert v["a.dot.d.center"] == pytest.approx((-30, 5), abs=1e-9)
    assert v["a.dot.d.radius"] == pytest.approx(6, abs=1e-9)
    assert v["a.twice.f.center"] == pytest.approx((40, -80), abs=1e-9)


def test_what_places_it_carries_to_the_scaled_copy_and_its_size_stays_the_originals():
    """Written before the `Scale`, outside the thing: `plate.bb.left == 5` places it (its
    residual changes when the plate moves), so it holds on the scaled plate; `plate.bb.width
    == 20` sizes it, so it stays on the original and the drawn plate is 2 x 20 mm wide."""
    src = """units mm
assembly a {
    solid plate { r = Rectangle(corner=(0, 0), opposite=(10, 8)) }
    plate.bb.width == 20
    plate.bb.left == 5
    Scale(plate, 2)
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]
    [part] = [p for p in r.output.parts if p.name == "a.plate"]
    x0, x1, y0, y1 = _box(part)
    assert (x0, x1 - x0) == pytest.approx((5, 40), abs=1e-9)
    assert y1 - y0 == pytest.approx(16, abs=1e-9)


def test_a_shape_scaled_in_place_is_placed_on_its_reference():
    """`Scale(ear, 1.5)` after `At(ear.center, head.center, dx=-3, dy=6)` (the ear written 1
    mm off): the scaled ear goes to its place on the head; the head and body stay."""
    src = """units mm
solid cat {
    body = Ellipse(center=(0, 0), rx=20, ry=15)
    head = Circle(center=(15, 12), radius=8)
    ear = Circle(center=(12, 19), radius=3)
    At(head.center, body.center, dx=15, dy=12)
    At(ear.center, head.center, dx=-3, dy=6)
    Scale(ear, 1.5)
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok
    v = {x.name: x.mm for x in r.values}
    assert v["cat.ear.center"] == pytest.approx((12, 18), abs=1e-9)
    assert v["cat.ear.radius"] == pytest.approx(4.5, abs=1e-9)
    assert v["cat.head.center"] == pytest.approx((15, 12), abs=1e-9)
    assert v["cat.body.center"] == pytest.approx((0, 0), abs=1e-9)


def _law_kinds():
    from test_who_moves import KINDS
    from aidl_lang import registry
    return sorted(k for k in KINDS if registry.lookup(k).category != "operation")


@pytest.mark.parametrize("kind", _law_kinds())
@LAWS
@given(data=st.data())
def test_law_a_relation_written_before_scale_is_one_written_after_it(kind, data):
    """Every relating constraint of the registry (tests/test_who_moves.py's kinds, less the
    operations): a part, a feature (a hole, a child solid) related to it, then `Scale(h, k)`
    -- the scaled feature ends exactly where the same relation written after the `Scale`
    (naming the scaled one) puts it: the relation carries to the scaled copy."""
    from test_who_moves import programs
    src, *_ = data.draw(programs(kind).filter(lambda c: "LinearPattern" not in c[0]))
    k = data.draw(st.sampled_from([0.5, 1.5]))
    rel = src.splitlines()[-2]
    assert rel.startswith("    ") and "h" in rel
    before = src.replace(rel, f"{rel}\n    Scale(h, {k})")
    after = src.replace(rel, f"    Scale(h, {k})\n{rel}")

    def feature(text):
        r = aidl_lang.compile(source=text)
        assert r.ok, (text, [(d.code, d.message) for d in r.errors])
        return {x.name: x.mm for x in r.values if x.name.startswith("plate.h.")
                and x.name.endswith((".center", ".radius"))}
    got, want = feature(before), feature(after)
    assert got.keys() == want.keys() and len(got) >= 2
    for name, v in want.items():
        assert got[name] == pytest.approx(v, abs=1e-9), (name, before)
