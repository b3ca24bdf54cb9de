"""Inputs that gave a Python traceback or "internal error" (issue 70): each is now a located
diagnostic (file, line, column, caret) or simply works, through the real command line."""
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def aidl(*args, cwd=None, stdin=None):
    env = dict(os.environ, AIDL_DEBUG="0")
    return subprocess.run([sys.executable, "-m", "aidl_lang.cli", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd, env=env, input=stdin,
                          timeout=300)


def no_internal(r):
    out = r.stdout + r.stderr
    assert r.returncode != 3 and "internal error" not in out and "Traceback" not in out, out


# ------------------------------------------------------------------ Mirrored about no line
ZERO_AXIS = """solid P {
  axis = Line((0,0), (0,0))
  c = Circle((10,0), 2)
  d = Mirrored(c, axis)
}
"""


@pytest.mark.parametrize("cmd", ["check", "render"])
def test_mirrored_about_a_zero_length_line_is_a_located_E0108(tmp_path, cmd):
    """A line of no length has no direction: the reflection divided by its length (check:
    LinAlgError from the freedom count's SVD; render wrote the file with the copy somewhere)."""
    (tmp_path / "m.aidl").write_text(ZERO_AXIS)
    out = tmp_path / "m.svg"
    r = aidl(cmd, "m.aidl", *(["-o", out] if cmd == "render" else []), cwd=tmp_path)
    no_internal(r)
    assert r.returncode == 1
    assert "m.aidl:4:7: error[E0108]: `P.axis` has zero length" in r.stderr
    assert "no line to mirror about" in r.stderr and "^^^^^^^^^^^^^^^^^" in r.stderr
    assert not out.exists()


def test_mirrored_list_about_a_zero_length_line_is_E0108(compile_text):
    c = compile_text("solid P {\n  a = Circle((10,0), 2)\n  b = Circle((20,0), 2)\n"
                     "  m = Mirrored([a, b], Line((3,4), (3,4)))\n}\n")
    errs = [(d.code, d.span.line, d.span.col) for d in c.sink.items if d.severity == "error"]
    assert errs == [("E0108", 4, 7)]


# ------------------------------------------------------------------ min_wall far below 1 nm
@pytest.mark.parametrize("how", ["program", "cli"])
@pytest.mark.parametrize("value", ["1e-300", "5e-324", "1e-200"])
def test_a_min_wall_whose_square_underflows_is_refused_and_nothing_written(tmp_path, how, value):
    """2 t^2, the least area of a thin wall, underflows to 0 for t below 1e-162 mm: empty
    pieces of what the opening removed were then measured (ValueError: need at least one array
    to concatenate).  A minimum wall is 0 or 0.001 to 1e6 mm (limits.min_wall_problem): the
    statement is a located E0109 naming the range, the option a usage error (exit 2); no file
    is written either way."""
    head = f"min_wall {value} mm\n" if how == "program" else ""
    (tmp_path / "p.aidl").write_text(head + "solid P {\n  r = Rectangle((0,0), 10, 10)\n}\n")
    extra = ["--min-wall", value] if how == "cli" else []
    r = aidl("render", "p.aidl", "-o", "p.dxf", *extra, cwd=tmp_path)
    no_internal(r)
    assert not (tmp_path / "p.dxf").exists()
    assert "from 0.001 to 1e+06 mm, or 0" in r.stderr, r.stderr
    if how == "program":
        assert r.returncode == 1 and "p.aidl:1:10: error[E0109]" in r.stderr, r.stderr
    else:
        assert r.returncode == 2, r.stderr


# ------------------------------------------------------------------ found by the fuzz
@pytest.mark.parametrize("arg,said", [
    ("(0, 0), 30 deg", "argument `radius` of `polar` must be a length, got list"),
    ("3, (1, 1)", "argument `angle` of `polar` must be an angle, got list"),
])
def test_polar_of_a_wrong_kind_is_a_located_E0108_with_its_signature(tmp_path, arg, said):
    """AttributeError: 'NoneType' object has no attribute 'signature' (the hint looked the
    function up among the shapes and constraints)."""
    (tmp_path / "p.aidl").write_text(
        f"solid plate {{\n    c = Circle(center=polar((0, 0), {arg}), radius=3)\n}}\n")
    r = aidl("check", "p.aidl", cwd=tmp_path)
    no_internal(r)
    assert r.returncode == 1
    assert f"p.aidl:2:23: error[E0108]: {said}" in r.stderr, r.stderr
    assert "= hint: polar(center, radius, angle)" in r.stderr
