"""A bare number given to a param from outside its file is in the param's own unit (issue
105): `aidl set x.aidl w=40` on `param w = 60 mm, min = 20 mm, max = 200 mm` writes `40 mm`
and the file compiles; MCP `set_params` the same; `--set angle=20` on a degree param is 20
deg; the studio's session (the `--set` texts) alike.  Real programs through the real
compiler; the values read back from the solved model."""
import math
import os
import subprocess
import sys

import pytest

import aidl_lang
from aidl_lang.api import set_params
from conftest import ROOT

PLATE = """param w = 60 mm, min = 20 mm, max = 200 mm   # the width
param tilt = 30 deg, min = 0 deg, max = 90 deg
param h = 40 mm
param n = 3
solid plate {
    body = Rectangle(center=(0, 0), width=w, height=h)
    hole slot { c = Circle(center=(n, 0), radius=2) }
}
drawing mark { l = Line(start=(0, 0), end=(20 * cos(tilt), 20 * sin(tilt))) }
"""


def _mm(result, name):
    return result.value(name).mm


def test_set_params_writes_the_params_unit_and_the_file_compiles():
    text, res = set_params(PLATE, {"w": 40, "tilt": "20", "h": 25.5, "n": 4})
    assert text.splitlines()[:4] == [
        "param w = 40 mm, min = 20 mm, max = 200 mm   # the width",
        "param tilt = 20 deg, min = 0 deg, max = 90 deg",
        "param h = 25.5 mm",
        "param n = 4"]                              # a plain number keeps no unit
    assert res.ok, res.diagnostics
    assert _mm(res, "plate.body.width") == pytest.approx(40.0, abs=1e-9)
    assert _mm(res, "plate.body.height") == pytest.approx(25.5, abs=1e-9)
    end = res.value("mark.l.end").mm
    assert end[0] == pytest.approx(20 * math.cos(math.radians(20)), abs=1e-9)
    assert end[1] == pytest.approx(20 * math.sin(math.radians(20)), abs=1e-9)
    again = aidl_lang.compile(source=text)
    assert again.ok and not again.errors


def test_a_bare_number_is_the_params_own_unit_not_the_files():
    """In a file of `units in`, `w=40` on `param w = 60 mm` is 40 mm (was 40 in: 1016 mm,
    past its range); a param written as a bare number stays one (the file's units where a
    length is taken)."""
    src = "units in\n" + PLATE.replace("param h = 40 mm", "param h = 1.5")
    text, res = set_params(src, {"w": 40, "h": 2})
    assert "param w = 40 mm, min = 20 mm" in text and "param h = 2\n" in text
    assert res.ok, res.diagnostics
    assert _mm(res, "plate.body.width") == pytest.approx(40.0, abs=1e-9)
    assert _mm(res, "plate.body.height") == pytest.approx(50.8, abs=1e-9)
    for ov, want in (({"w": "40"}, 40.0), ({"w": 0.5 * 100}, 50.0), ({"w": "2 in"}, 50.8)):
        r = aidl_lang.compile(source=src, overrides=ov)
        assert r.ok, (ov, r.diagnostics)
        assert _mm(r, "plate.body.width") == pytest.approx(want, abs=1e-9), ov


def test_an_angle_param_takes_a_bare_number_in_its_unit():
    """`--set tilt=20` on a degree param is 20 deg (was an error about its `min`); on a
    param written in radians it is radians."""
    r = aidl_lang.compile(source=PLATE, overrides={"tilt": "20"})
    assert r.ok, r.diagnostics
    assert r.value("tilt").mm == pytest.approx(math.radians(20), abs=1e-12)
    rad = PLATE.replace("param tilt = 30 deg, min = 0 deg, max = 90 deg", "param tilt = 0.5 rad")
    r = aidl_lang.compile(source=rad, overrides={"tilt": "1"})
    assert r.ok and r.value("tilt").mm == pytest.approx(1.0, abs=1e-12)
    far = aidl_lang.compile(source=PLATE, overrides={"tilt": "120"})
    [e] = far.errors
    assert e.code == "E0124" and "120 deg is outside the range 0 deg .. 90 deg" in e.message


def test_an_expression_of_bare_numbers_is_written_with_the_unit():
    text, res = set_params(PLATE, {"w": "2 * 20", "h": "-(-30)"})
    assert "param w = (2 * 20) * 1 mm, min" in text and "param h = (-(-30)) * 1 mm" in text
    assert res.ok and _mm(res, "plate.body.width") == pytest.approx(40.0, abs=1e-9)
    # a value that names another param or has its own unit stays as given
    text, res = set_params(PLATE, {"h": "w / 2", "w": "5 cm"})
    assert "param h = w / 2" in text and "param w = 5 cm," in text
    assert res.ok and _mm(res, "plate.body.height") == pytest.approx(25.0, abs=1e-9)


def test_a_bare_number_past_the_range_is_refused_before_anything_is_written():
    from aidl_lang.api import ParamsRefused
    with pytest.raises(ParamsRefused) as e:
        set_params(PLATE, {"w": 400})
    assert "400 mm is outside the range 20 mm .. 200 mm" in str(e.value)


def test_aidl_set_on_the_command_line(tmp_path):
    f = tmp_path / "x.aidl"
    f.write_text(PLATE)
    env = dict(os.environ, NO_COLOR="1")
    r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "set", str(f), "w=40",
                        "tilt=20"], capture_output=True, text=True, cwd=ROOT, env=env,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    assert f.read_text().startswith("param w = 40 mm, min = 20 mm, max = 200 mm   # the width\n"
                                    "param tilt = 20 deg, min = 0 deg")
    r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(f), "--set",
                        "tilt=25"], capture_output=True, text=True, cwd=ROOT, env=env,
                       timeout=120)
    assert r.returncode == 0 and "error" not in r.stderr, r.stderr


def test_mcp_set_params_writes_the_unit(tmp_path):
    from aidl_lang.mcp.tools import Workspace, set_params as tool
    (tmp_path / "x.aidl").write_text(PLATE)
    doc = tool(Workspace(tmp_path), "x.aidl", {"w": 40})
    assert doc["ok"], doc
    assert (tmp_path / "x.aidl").read_text().startswith("param w = 40 mm, min = 20 mm")
    assert doc["parts"][0]["bbox"][2] - doc["parts"][0]["bbox"][0] == pytest.approx(40.0)


def test_the_studio_session_reads_a_bare_number_in_the_params_unit(tmp_path):
    from aidl_lang.serve.session import Session
    f = tmp_path / "x.aidl"
    f.write_text(PLATE)
    s = Session(str(f))
    s.load()
    s.set_params({"w": "40", "tilt": "20"})
    vals = {p.name: p.value for p in s.params}
    assert vals["w"] == pytest.approx(40.0) and vals["tilt"] == pytest.approx(20.0)
