"""Issue 73's model run (data/model_runs/issue73/: 24 requests written from `aidl prompt` alone):
the defects it found, each as the .aidl text that exposed it (tests/programs/model_run73/),
through the real pipeline (``compile_source``), the hint followed as a model would.

* a construction helper (a bolt square `Concentric` with the plate) moved the plate: the NEMA 17
  plate written at (30, 30) came out at (15, 15); now the helper goes to the plate;
* W0508 between copies of an unnamed pattern offered `AllowOverlap(ring[0]_pattern[3])`, which
  is not a name a program can write (E0001 when applied); and a named pattern in a loop, which
  the better hint asks for, was E0108 ("already has a child named `rings[1]`");
* W0504 for a part cut in two by its own hole named the shape twice and offered only "make the
  pieces overlap ... or make the structure an `assembly`" (a part shipped in two pieces);
* W0404 on two holes tied to each other: both hints followed gave W0401 (redundant)."""
from __future__ import annotations

import pytest

from conftest import ROOT

PROGRAMS = ROOT / "tests" / "programs" / "model_run73"
EXACT = 1e-9


def _compile(src: str, tmp_path, name: str = "p.aidl"):
    from aidl_lang.pipeline import compile_source
    p = tmp_path / name
    p.write_text(src)
    return compile_source(src, str(p))


def _warnings(c, code=None):
    return [d for d in c.sink.items if d.severity == "warning" and (code is None or d.code == code)]


def _errors(c):
    return [(d.code, d.message) for d in c.sink.items if d.severity == "error"]


def _read(name: str) -> str:
    return (PROGRAMS / name).read_text()


def test_a_construction_helper_goes_to_the_plate_not_the_plate_to_it(tmp_path):
    import aidl_lang
    r = aidl_lang.compile(path=str(PROGRAMS / "nema17.aidl"))
    assert r.ok, [d.message for d in r.errors]
    v = {x.name: x.mm for x in r.values}
    # before: the plate met its construction square halfway, at (15, 15)
    assert v["mount.body.center"] == pytest.approx((30, 30), abs=EXACT)
    assert v["mount.square.center"] == pytest.approx((30, 30), abs=EXACT)
    assert v["mount.bore.c.center"] == pytest.approx((30, 30), abs=EXACT)
    holes = sorted(tuple(round(c, 9) for c in v[k]) for k in
                   ("mount.m3.c.center", "mount.m3_pattern[1].c.center",
                    "mount.m3_pattern[2].c.center", "mount.m3_pattern[3].c.center"))
    assert holes == [(14.5, 14.5), (14.5, 45.5), (45.5, 14.5), (45.5, 45.5)]
    (part,) = r.parts
    assert part.bbox == pytest.approx((0, 0, 60, 60), abs=EXACT)


@pytest.fixture(scope="module")
def grille(tmp_path_factory):
    return _compile(_read("grille_unnamed.aidl"), tmp_path_factory.mktemp("grille"))


def test_W0508_between_unnamed_pattern_copies_asks_to_name_the_pattern(grille):
    ws = _warnings(grille, "W0508")
    assert len(ws) == 8
    for w in ws:
        assert "_pattern[" not in w.hint.split("if one opening is meant")[1]
        assert "name the pattern statement that copies them (`NAME = ` before it) and write " \
               "`AllowOverlap(NAME)` after it" in w.hint
        assert w.fix is None                # was `AllowOverlap(ring, ring[0]_pattern[3])`: E0001


def test_following_it_names_the_pattern_in_the_loop_and_silences_every_W0508(grille, tmp_path):
    src = _read("grille_unnamed.aidl").replace(
        "        CircularPattern(ring, 4, body.center)\n",
        "        rings = CircularPattern(ring, 4, body.center)\n        AllowOverlap(rings)\n")
    src = src.replace("\n}\n", "\n    assert len(rings) == 2 and len(rings[1]) == 4, \"a list per iteration\"\n}\n")
    c = _compile(src, tmp_path)
    assert not _errors(c)                 # was E0108: `grille` already has a child `rings[1]`
    assert not _warnings(c, "W0508") and not _warnings(c, "W0523")
    names = sorted(s.path for s in c.model.structures if s.kind == "hole")
    assert names == ["grille.ring[0]", "grille.ring[1]"] + [
        f"grille.rings[{i}][{k}]" for i in range(2) for k in (1, 2, 3)]
    # the same cut: accepting the opening changed no part
    (a,), (b,) = grille.drawing.parts, c.drawing.parts
    assert (a.shape - b.shape).area() + (b.shape - a.shape).area() < 1e-9


def test_W0504_names_the_hole_that_cuts_the_part_apart_and_following_it_joins_it(tmp_path):
    src = _read("phone_side.aidl")
    c = _compile(src, tmp_path)
    (w,) = _warnings(c, "W0504")
    assert "(hole `side.slot` cuts `side.base` apart)" in w.message
    assert w.hint.startswith("move, shorten or shrink that hole so that material joins")
    # the hint followed: the slot shortened to 3 mm, from the top of the strip down
    fixed = src.replace("center=(60, 3), width=3, height=6", "center=(60, 4.5), width=3, height=3")
    c2 = _compile(fixed, tmp_path, "fixed.aidl")
    assert not _warnings(c2)
    (before,), (after,) = c.drawing.parts, c2.drawing.parts
    assert len(before.shape.to_polygons()) == 2 and len(after.shape.to_polygons()) == 1
    assert after.shape.area() - before.shape.area() == pytest.approx(3 * 3, abs=1e-9)


def _check(src: str):
    """What `aidl check` reports: the compile's warnings and the redundancy and sliding
    searches' (W0401, W0404), through the public API; and the solved values."""
    import aidl_lang
    r = aidl_lang.compile(src)
    assert r.ok, [d.message for d in r.errors]
    r.find_redundant(seconds=None)
    return [d for d in r.diagnostics if d.severity == "warning"], \
        {x.name: x.mm for x in r.values}


def test_holes_tied_to_each_other_stay_where_written_and_no_W0404():
    """The two screws are tied to each other in y (`VerticalDistance(bottom, top, 60.3)`) and
    to nothing else: the first-named is placed on the second, which nothing moves, so both
    are where the model wrote them and nothing slides (issue 111: W0404 warned each, though
    the design is exactly as meant); the ok line says "placed on it (harmless)".  Both tied
    to the part with `.bb.center ==` as well repeats the distance: W0401."""
    src = _read("switch_plate.aidl")
    ws, v = _check(src)
    assert ws == []
    assert v["plate.top_screw.c.center"] == pytest.approx((0, 30.15), abs=EXACT)
    assert v["plate.bottom_screw.c.center"] == pytest.approx((0, -30.15), abs=EXACT)
    import aidl_lang
    assert "hole `plate.top_screw` free but stays where written on its part; hole `plate.bottom_screw` " \
        "placed on it (harmless)" in aidl_lang.compile(src).freedom()["text"]
    both = src.replace("60.3)\n", "60.3)\n    top_screw.bb.center == (0, 30.15)\n"
                                   "    bottom_screw.bb.center == (0, -30.15)\n")
    assert [w.code for w in _check(both)[0]] == ["W0401"]


def test_a_reused_pattern_name_is_told_to_take_its_own_name(tmp_path):
    src = """solid p {
    body = Rectangle(center=(0, 0), width=60, height=30)
    hole a { c = Circle(center=(-10, 0), radius=2) }
    hole b { c = Circle(center=(-10, 8), radius=2) }
    x = LinearPattern(a, 2, (10, 0))
    x = LinearPattern(b, 2, (10, 0))
}
"""
    c = _compile(src, tmp_path)
    ((code, msg),) = _errors(c)
    # was "name the copy: `copy = ...`" to a copy that was named
    assert code == "E0108" and msg.endswith("give these copies a name of their own (`x_2 = ...`)")
    (d,) = [d for d in c.sink.items if d.severity == "error"]
    assert (d.span.line, d.span.col) == (6, 9)
    c2 = _compile(src.replace("    x = LinearPattern(b", "    x_2 = LinearPattern(b"), tmp_path, "q.aidl")
    assert not _errors(c2) and c2.drawing.parts[0].shape.area() == pytest.approx(
        60 * 30 - 4 * 3.141592653589793 * 4, rel=1e-3)
