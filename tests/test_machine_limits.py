"""Machine profiles cannot ask for a job without end (issue 58): every number that multiplies
the work (passes, a router's depth per pass, tabs, lead-in, speeds, ...) has a range
(aidl_lang/output/fabrication/machine.py RANGES / OP_RANGES, docs/machines.md "Ranges"); past it the
profile is one error line naming the key and the range, and nothing is written.  A router
whose thickness / depth_per_pass is past MAX_DEPTH_PASSES, or a job past MAX_JOB_MOVES
moves, is refused by the writer, naming what to change."""
import os
import re
import subprocess
import sys

import pytest

from aidl_lang.output import build, for_cutting
from aidl_lang.output.fabrication.machine import (MAX_DEPTH_PASSES, OP_RANGES, RANGES, MachineError,
                                      from_dict, load)
from aidl_lang.output.part.part import OutputError
from aidl_lang.output.writers import gcode, hpgl
from aidl_lang.pipeline import compile_source

from conftest import ROOT

PLATE = ROOT / "examples" / "mounting_plate.aidl"


def _beyond(low, high, whole):
    """A value just below ``low`` and one just above ``high``."""
    if whole:
        return [low - 1, high + 1]
    return [low - max(1e-6, abs(low) * 1e-3), high * 1.001]


@pytest.mark.parametrize("key", sorted(RANGES))
def test_every_profile_number_is_refused_past_each_end_of_its_range(key):
    low, high, unit = RANGES[key]
    whole = key == "tabs"
    for v in (low, high):                       # each end is allowed
        m = from_dict({key: int(v) if whole else float(v)}, "m.toml")
        assert getattr(m, key) == pytest.approx(v)
    for v in _beyond(low, high, whole):
        with pytest.raises(MachineError) as e:
            from_dict({key: v}, "m.toml")
        said = str(e.value)
        assert f"`{key}` must be" in said and f"from {low:g} to {high:g}" in said, said
        assert "m.toml" in said and "\n" not in said


@pytest.mark.parametrize("key", sorted(OP_RANGES))
def test_every_operation_number_is_refused_past_each_end_of_its_range(key):
    low, high, unit = OP_RANGES[key]
    whole = key == "passes"
    for kind in ("laser", "router"):
        for v in (low, high):
            m = from_dict({"kind": kind, "cut_outer": {key: int(v) if whole else float(v)}})
            assert getattr(m.operation("cut_outer"), key) == pytest.approx(v)
        for v in _beyond(low, high, whole):
            with pytest.raises(MachineError) as e:
                from_dict({"kind": kind, "cut_outer": {key: v}})
            said = str(e.value)
            assert f"`cut_outer.{key}` must be" in said and f"from {low:g} to {high:g}" in said


def test_an_inch_profile_is_checked_in_mm_and_says_its_range_in_inches():
    m = from_dict({"units": "inch", "kind": "router", "cut_outer": {"depth_per_pass": 0.0625}})
    assert m.operation("cut_outer").depth_per_pass == pytest.approx(1.5875)
    with pytest.raises(MachineError) as e:      # 0.0001 in = 0.00254 mm: below 0.01 mm
        from_dict({"units": "inch", "kind": "router", "cut_outer": {"depth_per_pass": 0.0001}})
    assert "from 0.01 to 100 mm (0.000394 to 3.94 in)" in str(e.value)
    for bad in (float("nan"), float("inf"), True, "1"):
        with pytest.raises(MachineError):
            from_dict({"cut_outer": {"speed": bad}})


def _render(tmp_path, profile: str, *extra, out="p.gcode"):
    prof = tmp_path / "r.toml"
    prof.write_text(profile)
    # a memory cap of its own, so that a regression cannot take the machine down
    return subprocess.run([sys.executable, "-m", "aidl_lang.cli", "render", str(PLATE),
                           "-o", str(tmp_path / out), "--machine", str(prof), *extra],
                          capture_output=True, text=True, timeout=120, cwd=tmp_path,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})


@pytest.mark.parametrize("depth", ["1e-12", "1e-6"])
def test_a_router_depth_per_pass_of_nothing_is_one_profile_error_and_nothing_written(
        tmp_path, depth):
    """The issue's two cases: 1e-12 answered `internal error: MemoryError`, 1e-6 ran past
    120 s and 1.9 GB writing millions of passes.  The good file already there stays."""
    good = tmp_path / "p.gcode"
    good.write_bytes(b"; a good job\nM2\n")
    before = good.stat().st_mtime_ns
    r = _render(tmp_path, f'kind = "router"\n[cut_outer]\ndepth_per_pass = {depth}\n')
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "`cut_outer.depth_per_pass` must be a number from 0.01 to " \
        "100 mm" in lines[0] and "r.toml" in lines[0], r.stderr
    assert "internal error" not in r.stderr and "Traceback" not in r.stderr
    assert good.read_bytes() == b"; a good job\nM2\n" and good.stat().st_mtime_ns == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.gcode", "r.toml"]


def _output(src_path=PLATE):
    res = compile_source(src_path.read_text(), str(src_path))
    assert res.ok
    return for_cutting(build(res.drawing, res.model.root.name), None)


def test_a_router_past_its_passes_is_refused_naming_the_part_and_the_key():
    out = _output()
    m = from_dict({"kind": "router", "cut_outer": {"depth_per_pass": 0.01}})
    j = gcode.job(out, m, thickness=MAX_DEPTH_PASSES * 0.01)         # at the limit: written
    assert j.text.count("G1 Z-10") >= 1
    with pytest.raises(OutputError) as e:
        gcode.job(out, m, thickness=(MAX_DEPTH_PASSES + 1) * 0.01)
    said = str(e.value)
    assert "cut_outer.depth_per_pass" in said and f"{MAX_DEPTH_PASSES + 1:,} passes" in said
    assert re.search(r"part `kit\.(plate|w\[\d\])` \(10\.01 mm thick\)", said), said


def test_a_job_past_its_moves_is_refused_before_anything_is_written(monkeypatch):
    """Passes x segments bound the program's size (MAX_JOB_MOVES): the mounting plate at 100
    passes is some 8 000 G-code lines, refused when the bound is below that."""
    out = _output()
    m = from_dict({"kind": "laser", "cut_inner": {"passes": 100}, "cut_outer": {"passes": 100}})
    n = len(gcode.job(out, m).text.splitlines())
    assert 5_000 < n < 20_000
    p = from_dict({"kind": "plotter", "cut_inner": {"passes": 100}, "cut_outer": {"passes": 100}})
    opts = type("O", (), {"machine": p})()
    assert hpgl.to_hpgl(out, opts).count("VS") >= 1           # within the bound: written
    import aidl_lang.output.fabrication.machine as M
    monkeypatch.setattr(M, "MAX_JOB_MOVES", n // 2)
    monkeypatch.setattr(gcode, "MAX_JOB_MOVES", n // 2)
    with pytest.raises(OutputError) as e:
        gcode.job(out, m)
    assert f"more than {n // 2:,} G-code lines" in str(e.value) and "`passes`" in str(e.value)
    monkeypatch.setattr(M, "MAX_JOB_MOVES", 100)     # 100 passes of more than one segment
    with pytest.raises(OutputError) as e:
        hpgl.to_hpgl(out, opts)
    assert "HPGL segments" in str(e.value)


def test_the_cli_keeps_the_good_file_when_the_writer_refuses(tmp_path):
    good = tmp_path / "p.gcode"
    good.write_bytes(b"; a good job\nM2\n")
    r = _render(tmp_path, 'kind = "router"\n[cut_outer]\ndepth_per_pass = 0.01\n',
                "--thickness", "20mm")
    assert r.returncode == 1 and "2,000 passes of 0.01 mm" in r.stderr, r.stderr
    assert "internal error" not in r.stderr
    assert good.read_bytes() == b"; a good job\nM2\n"


def test_a_profile_file_out_of_range_names_the_file(tmp_path):
    f = tmp_path / "m.toml"
    f.write_text("travel_speed = 0\n")          # was accepted; the estimate divided by it
    with pytest.raises(MachineError) as e:
        load(f)
    assert str(f) in str(e.value) and "`travel_speed` must be a number from 1 to 100000 " \
        "mm/min, not 0" in str(e.value)


@pytest.mark.parametrize("profile,said", [
    ("tabs = " + "9" * 400, "`tabs` must be a whole number from 0 to 16, not an integer of "
                            "400 digits"),
    ("[cut_outer]\npasses = -" + "9" * 400, "`cut_outer.passes` must be a whole number from 1 "
                                            "to 100, not an integer of 400 digits"),
    ("kerf = " + "9" * 400, "`kerf` must be a number from 0 to 10 mm, not an integer of 400 "
                            "digits"),
    ("kerf = 0.1\ntabs = " + "9" * 5000, "`tabs` on line 2 is a number of more than 4300 "
                                         "digits"),
])
def test_a_profile_integer_of_hundreds_of_digits_is_one_error_naming_the_key(tmp_path, profile,
                                                                             said):
    """400 digits: OverflowError converting it to a float (an internal error); 5,000: Python
    refuses to read it (ValueError from tomllib).  Now one line naming the key and its range,
    and nothing written."""
    r = _render(tmp_path, profile + "\n")
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and said in lines[0] and "r.toml" in lines[0], r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.toml"]
    with pytest.raises(MachineError) as e:            # a dict (the API, the studio) alike
        from_dict({"tabs": -10 ** 5000})
    assert "`tabs` must be a whole number from 0 to 16, not an integer of more than 4000 " \
        "digits" in str(e.value)
