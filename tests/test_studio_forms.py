"""aidl studio's forms offer only values that compile (issue 62, "Forms that cannot fail").

A generator's program states how its arguments depend on each other as ranges over other
params (``param depth = 70 mm, min = rows * (hole + 4 mm) + ...``, examples/generators/), or
the gallery derives them from the generator's asserts over its arguments
(:func:`aidl_lang.studio.gallery.assert_relations`); the studio's compile worker moves a
value that left such a range back into it (:func:`aidl_lang.studio.compiler.settle`).
Every slider extreme of every gallery entry then compiles: one process, one warm
:class:`~aidl_lang.serve.session.Session` per entry, each extreme interpreted, solved and
cut by the booleans (no picture, no warnings: the view adds those).
"""
from __future__ import annotations

from collections import OrderedDict

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from aidl_lang.studio import compiler, gallery
from benchmarks.checks.slider_extremes import NUMERIC, extremes

# the generators whose numeric params all declare their ranges and whose slider extremes
# compile without a move (the full run: benchmarks/checks/slider_extremes.py, 392 extremes
# of 48 entries, 24.5 s CPU): tests/test_sweep_gallery*.py sweep those of its sample at their
# declared ends (:func:`_left_to_the_sweep`)
LEFT_TO_THE_SWEEP = {"generator/ring_gear", "generator/drawer", "generator/rack_and_pinion",
                     "generator/divider_tray", "generator/spur_gear", "generator/finger_box",
                     "generator/wall_shelf", "generator/lid_box"}


# the extremes that compile only with another value moved: each entry's param named here
MOVED = {"generator/tool_holder": "rows", "generator/planetary": "planet",
         "generator/flex_box": "thickness", "generator/rounded_tab": "width",
         "generator/board_enclosure": "standoff"}
STRIDE = 4      # every 4th of the other entries, in the gallery's order, from the first


def _left_to_the_sweep() -> set:
    """The entries of LEFT_TO_THE_SWEEP that tests/test_sweep_gallery*.py sweep (its sample)."""
    from test_sweep_gallery import _ranged
    return LEFT_TO_THE_SWEEP & {p.values[0].id for p in _ranged()}


def _sample() -> list:
    """``(entry, names)``: every STRIDE-th entry of the gallery but those left to the sweep
    and MOVED, all its params (``names`` None), and the first entry with a kind of slider
    (NUMERIC) those lack; then each MOVED entry with its one param.  A fixed subset, the same
    on every run (all 452 extremes of 49 entries: 29.8 s of CPU; this: about 5 s); every
    gallery slider end compiles in the law corpus (benchmarks/laws/law_compiles.py) and in
    benchmarks/checks/slider_extremes.py."""
    left = _left_to_the_sweep()
    rest = [e for e in gallery.entries() if e.id not in left and e.id not in MOVED]
    chosen = rest[::STRIDE]
    for kind in NUMERIC:
        if not any(p["kind"] == kind for e in chosen for p in e.params):
            chosen += [e for e in rest if any(p["kind"] == kind for p in e.params)][:1]
    return [(e, None) for e in chosen] + [(gallery.entry(i), {name}) for i, name in MOVED.items()]


def test_every_slider_extreme_of_every_gallery_entry_compiles(tmp_path):
    """Each slider extreme of a fixed sample of the entries (:func:`_sample`) compiles,
    settled where it needs another value moved; those left to the sweep are swept at their
    declared ends by tests/test_sweep_gallery*.py."""
    left = _left_to_the_sweep()
    assert left
    for e in gallery.entries():
        if e.id in left:
            assert all(p["declared"] for p in e.params if p["kind"] in NUMERIC), e.id
    sample = _sample()
    # the sample holds examples and generators, and every kind of numeric slider
    assert {e.id.split("/")[0] for e, names in sample if names is None} == {"example",
                                                                           "generator"}
    assert {p["kind"] for e, names in sample if names is None for p in e.params} >= \
        {p["kind"] for e in gallery.entries() for p in e.params} & set(NUMERIC)
    failed, moved, count = [], [], 0
    for e, names in sample:
        n, f, m = extremes(e, str(tmp_path / "main.aidl"), names)
        count, failed, moved = count + n, failed + f, moved + m
    assert not failed, failed
    assert count >= 80
    # the dependencies did their work: these extremes compile only with another value moved
    where = {(m[0], m[1], m[2]) for m in moved}
    assert {("generator/tool_holder", "rows", "max"), ("generator/planetary", "planet", "max"),
            ("generator/flex_box", "thickness", "max"), ("generator/rounded_tab", "width", "max"),
            ("generator/board_enclosure", "standoff", "max")} <= where, sorted(where)


@pytest.fixture(scope="module")
def sessions():
    return OrderedDict()


def test_a_value_follows_the_range_that_depends_on_another(sessions, tmp_path):
    """12 rows of 16 mm holes, 4 mm apart, need a box 12 x 20 + 2 x 3 + 0.5 mm deep: the
    form's depth (70 mm) moves there and the design compiles, instead of an E0405."""
    e = gallery.entry("generator/tool_holder")
    folder = str(tmp_path)
    assert compiler.view(sessions, "t", folder, e.source, {})["ok"]       # the form opens
    view = compiler.view(sessions, "t", folder, e.source, {"rows": "12"})
    assert view["ok"], view["diagnostics"]
    assert view["clamped"] == {"depth": pytest.approx(246.5)}
    depth = next(p for p in view["params"] if p["name"] == "depth")
    assert (depth["value"], depth["min"]) == (pytest.approx(246.5), pytest.approx(246.5))
    # without the move, the generator's own assert fails: the range is what makes it compile
    from aidl_lang import api
    bare = api.compile(source=e.source.replace("min = rows * (hole + 4 mm)", "min = 1 mm * rows"),
                       overrides={"rows": "12"})
    assert not bare.ok and {d.code for d in bare.errors} == {"E0405"}


def test_the_sun_steps_onto_a_count_where_the_planets_sit_evenly(sessions, tmp_path):
    e = gallery.entry("generator/planetary")
    assert compiler.view(sessions, "p", str(tmp_path), e.source, {})["ok"]
    view = compiler.view(sessions, "p", str(tmp_path), e.source, {"planet": "14"})
    assert view["ok"], view["diagnostics"]
    # 2 x (sun + planet) divides by 3 planets: the sun moves from 12 to 13 (10, 13, 16, ...)
    assert view["clamped"] == {"sun": 13}
    sun = next(p for p in view["params"] if p["name"] == "sun")
    assert (sun["min"], sun["step"], sun["max"]) == (10, 3, 46)
    assert "ring=sun + 2 * planet" in e.source.replace("\n", " ").replace("  ", "")


def test_a_failure_no_range_explains_is_left_as_the_visitor_made_it(sessions, tmp_path):
    """A value the ranges do not cover (a typed name of a missing generator) is not moved:
    the error is the visitor's, with their values."""
    e = gallery.entry("generator/tool_holder")
    src = e.source.replace("tool_holder(", "tool_holdr(", 1)
    compiler.view(sessions, "x", str(tmp_path), src, {})
    view = compiler.view(sessions, "x", str(tmp_path), src, {"rows": "3"})
    assert not view["ok"] and "clamped" not in view


def test_the_gallery_derives_a_range_from_an_assert_over_arguments():
    # std/shapes.aidl: `assert length > (width + hole_d) / 2 + 0.5 mm` -> length's min follows
    # width and hole_d, a step above
    src = gallery.entry("generator/rounded_tab").source
    assert ("param length = 20 mm, min=max(5 mm, (width + hole_d) / 2 + 0.5 mm + 0.2 mm), "
            "max=80 mm") in src
    assert src.index("param width") < src.index("param hole_d") < src.index("param length")
    rel = gallery.assert_relations(gallery.renderable_generators()["rounded_tab"])
    assert rel == {"length": {"min": [("(width + hole_d) / 2 + 0.5 mm", True)], "max": []},
                   "hole_d": {"min": [], "max": [("width - 1 mm", True)]}}
    # `assert hole_d < width - 1 mm` (the eye's 0.5 mm wall, issue 84's sweep)
    assert "param hole_d = 6 mm, min=1.5 mm, max=min(24 mm, width - 1 mm - 0.05 mm)" in src


def _tab_values(w: float, fd: float, fl: float) -> dict:
    """The rounded tab's form at width ``w``, its hole and length at fractions ``fd``, ``fl``
    of the ranges that follow it (as the form declares them)."""
    d = 1.5 + fd * (min(24.0, w - 1.05) - 1.5)
    lo = max(5.0, (w + d) / 2 + 0.7)
    return {"width": f"{w!r} mm", "hole_d": f"{d!r} mm", "length": f"{lo + fl * (80 - lo)!r} mm"}


@settings(max_examples=12, deadline=None)
@given(w=st.floats(5, 80), fd=st.floats(0, 1), fl=st.floats(0, 1))
@example(w=50.0, fd=0.2, fl=0.0)            # width 50, length 23.35: a half disc on 0.85 mm
@example(w=80.0, fd=1.0, fl=0.0)            # every bound at once
@example(w=5.0, fd=1.0, fl=0.0)
def test_law_the_rounded_tab_is_clean_at_every_slider_setting(w, fd, fl):
    """Issue 92: width above 44.8 mm with length above 27.2 mm left a ledge (W0520, width 51.8,
    length 29.2: the stem poked 0.23 mm past the round end's circle, which reached 20 mm below
    the base at width 50, length 30).  The round end is now a half disc on the stem (a
    RoundedRectangle), the length's range follows the width and the eye: no diagnostic at any
    setting inside the form's ranges (15 compiles, about 0.5 s of CPU; 308 random settings
    outside the suite: none)."""
    import aidl_lang
    src = gallery.entry("generator/rounded_tab").source
    r = aidl_lang.compile(source=src, path="main.aidl", overrides=_tab_values(w, fd, fl))
    assert r.ok and [g.code for g in r.diagnostics if g.severity != "info"] == [], \
        [(g.code, g.message) for g in r.diagnostics]


def test_the_rounded_tab_is_flat_at_its_base_in_the_dxf(tmp_path):
    """Width 50, length 30: the outline ezdxf reads spans y 0-30 and x -25-25 (before: the
    round end's circle reached y = -20, a disc with two nubs), the eye centred 5 mm up."""
    import ezdxf
    from ezdxf import bbox
    import aidl_lang
    src = gallery.entry("generator/rounded_tab").source
    r = aidl_lang.compile(source=src, path=str(tmp_path / "main.aidl"),
                          overrides={"width": "50 mm", "length": "30 mm"})
    assert r.ok
    out = tmp_path / "tab.dxf"
    r.write(str(out))
    doc = ezdxf.readfile(out)
    box = bbox.extents(doc.modelspace())
    assert (box.extmin.x, box.extmin.y, box.extmax.x) == pytest.approx((-25, 0, 25), abs=1e-9)
    assert box.extmax.y == pytest.approx(30, abs=1e-9)
    [eye] = doc.modelspace().query("CIRCLE")
    assert (eye.dxf.center.x, eye.dxf.center.y, eye.dxf.radius) == pytest.approx((0, 5, 3))


@pytest.mark.parametrize("name", sorted(p.stem for p in gallery.FORMS.glob("*.aidl")))
def test_a_form_draws_what_its_example_draws(name, tmp_path):
    """A form (aidl_lang/studio/forms/) is its examples/generators file with params: at its
    defaults, the same parts of the same outlines."""
    from aidl_lang import api
    from aidl_lang.library.sources import EXAMPLES
    e = gallery.entry(f"generator/{name}")
    assert e.source == (gallery.FORMS / f"{name}.aidl").read_text()
    mine = api.compile(source=e.source, path=str(tmp_path / "main.aidl"))
    file = api.compile(path=str(EXAMPLES / "generators" / f"{name}.aidl"))
    assert mine.ok and file.ok
    assert mine.to_svg(kerf=0) == file.to_svg(kerf=0)


def test_a_session_new_to_a_worker_draws_the_page_s_values(tmp_path):
    """The tab's compile may land on a worker that has no session for it yet (the other one
    drew its last picture): the page's values are drawn, not the program's defaults."""
    e = gallery.entry("generator/tool_holder")
    view = compiler.view(OrderedDict(), "new", str(tmp_path), e.source, {"rows": "3"})
    assert view["ok"] and view["values"] == {"rows": "3"}
    assert next(p for p in view["params"] if p["name"] == "rows")["value"] == 3
