"""Law 1, the machine makes what was drawn (issue 109; benchmarks/laws/law_machine.py).

The issue's cases as real programs through the parser, solver, booleans and G-code writer, the
G-code re-read by ``gcodeparser`` and swept with the bit (shapely):

* a 60 x 40 mm plate with a 20 x 10 mm hole 1.2 mm from its edge, T-bones: before, the bit ran
  1.59 mm into that wall at both corners and the plate came out in two pieces with only "4
  inside corners relieved"; now those two corners are cut as dogbones (0.735 mm of wall left),
  W0527 at the hole says so, and the plate is one piece;
* the same with a 0.4 mm wall (``min_wall 0.3 mm``) and dogbones: those two corners are not
  relieved (W0527), the note counts 2;
* a 10 degree wedge-shaped hole: its dogbone took 27.7 mm^2 (3.5 bit discs, 1.45 mm into the
  edges), its T-bone 32.5 mm^2: not relieved, W0527 with those figures;
* the law itself sees the old defects: with every relief cut as asked (the old plan) it reports
  the two pieces and the 3.5-disc relief;
* the law over a fixed sample of the repository's programs, router (dogbone, T-bone) and laser.
"""
from __future__ import annotations

import contextlib
import io

import pytest

pytest.importorskip("gcodeparser")
pytest.importorskip("shapely")

from benchmarks.laws import law_machine as law  # noqa: E402

from conftest import ROOT  # noqa: E402

PLATE = """units mm
thickness 3 mm
{wall}solid plate {{
    body = Rectangle(bottom_left=(0, 0), width=60, height=40)
    hole window {{ w = Rectangle(bottom_left=({x}, 15), width=20, height=10) }}
}}
"""
THIN_TBONE = PLATE.format(wall="", x=38.8)                    # 1.2 mm from the edge
THIN_DOGBONE = PLATE.format(wall="min_wall 0.3 mm\n", x=39.6)  # 0.4 mm, min_wall 0.3 mm
WEDGE = """units mm
thickness 3 mm
solid plate {
    body = Rectangle(bottom_left=(0, 0), width=60, height=40)
    hole wedge { w = Polygon(points=[(10, 20), (50, 16.500504), (50, 23.499496)]) }
}
"""
ROUTER = [("router dogbone", {"kind": "router"})]
TBONE = [("router tbone", {"kind": "router", "relief": "tbone"})]


def _render(tmp_path, src: str, relief: str) -> tuple[int, str, str]:
    """``aidl render`` of ``src`` to router G-code with ``relief``: exit code, what it said,
    the G-code."""
    from aidl_lang.cli.main import main
    f = tmp_path / "t.aidl"
    f.write_text(src)
    prof = tmp_path / "r.toml"
    prof.write_text(f'kind = "router"\nrelief = "{relief}"\n')
    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        rc = main(["render", str(f), "-o", str(tmp_path / "t.nc"), "--machine", str(prof)])
    return rc, err.getvalue() + out.getvalue(), (tmp_path / "t.nc").read_text()


def test_thin_wall_tbone_plate_stays_one_piece_and_says_which_corners(tmp_path):
    assert law.check_program(THIN_TBONE, "t.aidl", machines=law.MACHINES) == []
    rc, said, text = _render(tmp_path, THIN_TBONE, "tbone")
    assert rc == 0
    assert said.count("warning[W0527]") == 1
    assert ":5:5: warning[W0527]: the router's 3.175 mm bit does not cut the T-bone relief at " \
        "2 inside corners of part `plate`, (58.8, 25), (58.8, 15): at (58.8, 25) a T-bone " \
        "would cut through the 1.2 mm of material between the corner and the part's outer " \
        "edge, 0.387 mm past it" in said
    assert "each cut as a dogbone instead" in said
    assert "4 inside corners of 1 part relieved (tbone, 2 of them as dogbones where a T-bone " \
        "does not fit)" in said
    # the G-code replayed: 4 reliefs, two T-bones on the long edges' line and two dogbones
    moves = law.replay(text, "router")
    loops, opens, spikes = law.runs(moves, law.THICKNESS, True)
    assert len(spikes) == 4 and not opens
    tips = sorted((round(q[0], 4), round(q[1], 4)) for _, q in spikes)
    r = 3.175 / 2
    d = r / 2 ** 0.5
    assert tips == sorted([(38.8, round(15 + r, 4)), (38.8, round(25 - r, 4)),
                           (round(58.8 - d, 4), round(15 + d, 4)),
                           (round(58.8 - d, 4), round(25 - d, 4))])
    # the wall the dogbones leave: 1.2 mm less the disc's reach past the corner, r (1 - 0.707)
    assert 60 - max(q[0] for _, q in spikes) - r == pytest.approx(1.2 - r + d, abs=1e-9)


def test_thin_wall_dogbone_plate_is_not_relieved_there(tmp_path):
    assert law.check_program(THIN_DOGBONE, "t.aidl", machines=law.MACHINES) == []
    rc, said, text = _render(tmp_path, THIN_DOGBONE, "dogbone")
    assert rc == 0 and said.count("warning[W0527]") == 1
    assert ":6:5: warning[W0527]: the router's 3.175 mm bit does not cut the dogbone relief " \
        "at 2 inside corners of part `plate`, (59.6, 25), (59.6, 15): at (59.6, 25) a " \
        "dogbone would cut through the 0.4 mm of material between the corner and the part's " \
        "outer edge, 0.065 mm past it" in said
    assert "not relieved: the material stays up to 0.658 mm from the drawn corner" in said
    assert "2 inside corners of 1 part relieved (dogbone)" in said
    assert "; warning: the router's 3.175 mm bit does not cut the dogbone relief" in text
    _, _, spikes = law.runs(law.replay(text, "router"), law.THICKNESS, True)
    assert sorted(round(q[0], 4) for _, q in spikes) == [40.7225, 40.7225]


@pytest.mark.parametrize("relief,area,times,deep", [("dogbone", "27.7", "3.5", "1.45"),
                                                    ("tbone", "32.5", "4.1", "3.15")])
def test_acute_corner_is_not_relieved_and_says_what_it_would_take(tmp_path, relief, area,
                                                                    times, deep):
    rc, said, text = _render(tmp_path, WEDGE, relief)
    assert rc == 0 and said.count("warning[W0527]") == 1
    name = "T-bone" if relief == "tbone" else "dogbone"
    a = "a T-bone" if relief == "tbone" else "a dogbone"
    assert f":5:5: warning[W0527]: the router's 3.175 mm bit does not cut the {name} relief " \
        "at 1 inside corner of part `plate`, (10, 20): an acute corner (10 deg, sharper than " \
        f"60): {a} would take {area} mm^2 beside it, {times} times the bit's disc, {deep} mm " \
        "deep into its edges; not relieved" in said
    _, _, spikes = law.runs(law.replay(text, "router"), law.THICKNESS, True)
    assert len(spikes) == 2                  # the two 85 degree corners only
    assert law.check_program(WEDGE, "w.aidl", machines=TBONE + ROUTER) == []


def test_the_law_sees_the_old_reliefs(monkeypatch):
    """With every relief cut as asked (the plan before issue 109), the law reports the plate
    in two pieces and the wedge's relief of 3.5 bit discs: it would fail the old code."""
    from aidl_lang.output.fabrication import reliefs
    from aidl_lang.output.fabrication.reliefs import Planned, inside_corners

    def old(part, radius, style, wall=0.5, corners=None):
        cs = inside_corners(part, radius) if corners is None else corners
        return [] if style == "none" else [Planned(c, style, style, "") for c in cs]

    monkeypatch.setattr(reliefs, "plan", old)
    said = law.check_program(THIN_TBONE, "t.aidl", machines=TBONE, name="t")
    assert said == ["t [router tbone]: part `plate` comes out in 2 pieces, drawn as 1"]
    said = law.check_program(THIN_DOGBONE, "d.aidl", machines=ROUTER, name="d")
    assert said == ["d [router dogbone]: part `plate` comes out in 2 pieces, drawn as 1"]
    said = law.check_program(WEDGE, "w.aidl", machines=ROUTER, name="w")
    assert len(said) == 1 and "takes 27.72 mm^2 (3.5 of the tool's disc), reaching 16.6 mm " \
        "from its tip" in said[0]


# A fixed sample of the repository's programs with parts (the runner covers them all): finger
# joints relieved by the hundred, a box, holes and slots; router and laser.
SAMPLE = ["examples/generators/drawer.aidl", "examples/laser_box.aidl",
          "examples/logo_plate.aidl", "examples/key.aidl", "examples/pcb_enclosure.aidl",
          "tests/programs/gear_pair_plate_below.aidl"]


@pytest.mark.parametrize("rel", SAMPLE)
def test_the_law_holds_over_a_sample_of_the_programs(rel):
    f = ROOT / rel
    said = law.check_program(f.read_text(), str(f), name=rel)
    assert said == []


def test_law_interface():
    class Entry:
        name, path, overrides, kind = "w", "w.aidl", {}, "tests"
        source = WEDGE
    assert law.applies(Entry) and law.check(Entry) == []
    Entry.source = "solid p { body = Circle(center=(0, 0), radius=-1) }"
    assert law.check(Entry) == []           # does not compile: not applicable
    assert law.NAME and law.TOLERANCE


@pytest.mark.parametrize("rel,part,at,deep", [
    ("examples/violin.aidl", "violin", "(-40.39, 33.19)", "0.175"),
    ("tests/programs/picture/rounded_corner_nick.aidl", "bracket", "(18.41, 13.65)", "1.59"),
    ("tests/programs/model_run73/phone_side.aidl", "side", "(60.09, 0)", "0.175")])
def test_a_slot_narrower_than_the_bit_is_refused(tmp_path, rel, part, at, deep):
    """Found by the law: the violin's 3 mm f-hole stems, a nick between a rounded corner and
    an arm, a 3 mm slot, each narrower than the 3.175 mm bit: every segment's offset is
    sound, the loop's is not, and the bit took 48.9, 33.5 and 2.1 mm^2 of the part (the nick
    left the bracket in two pieces) with no word.  Now the writer refuses the job as it does
    a tooth gap narrower than the bit (exit 1, nothing written)."""
    from aidl_lang.cli.main import main
    err = io.StringIO()
    out = tmp_path / "v.nc"
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        rc = main(["render", str(ROOT / rel), "-o", str(out), "--machine", "router"])
    assert rc == 1 and not out.exists()
    assert f"aidl: error: the router's tool (3.175 mm across) does not fit part `{part}`: a " \
        f"slot or notch near {at} is narrower than the cut: the offset path comes {deep} mm " \
        "into the material there; use a smaller tool" in err.getvalue()
    # a 2.9 mm bit fits the 3 mm features: the law holds
    f = ROOT / rel
    assert law.check_program(f.read_text(), str(f), machines=[
        ("router 3 mm", {"kind": "router", "tool_diameter": 2.9})]) == []
