"""A standard-library call with a bare number (or a value of the wrong kind) for a length
parameter: the message, if any, is at the user's call, never inside std/*.aidl (issue 73).

A parameter whose default carries a unit (``thickness=3 mm``) is a length: a bare number given
to it is in the caller's file unit (the bare-number rule, docs/language.md 5.4), so that it does
not stay bare inside the library (``floor(run / finger)`` was a length^-1: E0109 and E0101 at
std/joints.aidl:39-42). A value of another kind is E0109 at the argument, with the fix.
Real programs through the real pipeline; DXF re-read by ezdxf.
"""
import io
import json
import subprocess
import sys

import ezdxf
import pytest

import aidl_lang


def _compile(tmp_path, src: str, name: str = "u.aidl"):
    p = tmp_path / name
    p.write_text(src)
    return aidl_lang.compile(source=src, path=p), str(p)


def _outline(result) -> list:
    """Every LWPOLYLINE's points, rounded to 1e-9 mm, sorted: the drawing as a comparable value."""
    doc = ezdxf.read(io.StringIO(result.to_dxf()))
    polys = [tuple((round(x, 9), round(y, 9)) for x, y in e.get_points("xy"))
             for e in doc.modelspace().query("LWPOLYLINE")]
    return sorted(polys)


def test_bare_lengths_to_finger_panel_are_the_callers_lengths(tmp_path):
    bare, _ = _compile(tmp_path, 'import "std/joints.aidl"\n\n'
                       'p = finger_panel(width=100, height=80, thickness=3)\n')
    unit, _ = _compile(tmp_path, 'import "std/joints.aidl"\n\n'
                       'p = finger_panel(width=100 mm, height=80 mm, thickness=3 mm)\n')
    assert bare.ok, [(d.code, d.message, d.span.file) for d in bare.diagnostics]
    assert not [d for d in bare.diagnostics if "std" in str(d.span.file if d.span else "")]
    got = _outline(bare)
    assert got and got == _outline(unit)
    xs = [x for poly in got for x, _ in poly]
    assert max(xs) - min(xs) == pytest.approx(100, abs=1e-9)


def test_bare_length_in_an_inch_file_is_inches(tmp_path):
    """Before: the bare 2 stayed bare into std/joints.aidl (a mm file), a 2 mm finger."""
    bare, _ = _compile(tmp_path, 'units in\nimport "std/joints.aidl"\n\n'
                       'p = finger_panel(width=4, height=3, thickness=0.125, finger=1)\n')
    unit, _ = _compile(tmp_path, 'units in\nimport "std/joints.aidl"\n\n'
                       'p = finger_panel(width=4 in, height=3 in, thickness=0.125 in, finger=1 in)\n')
    assert bare.ok and unit.ok
    assert _outline(bare) == _outline(unit)


@pytest.mark.parametrize("call", [
    'spur_gear(teeth=12, module=2)',
    'finger_edge(length=60, thickness=3)',
    'text_on_arc(text="AB", radius=30)',
    'dovetail(length=60, depth=10, angle=10)',
])
def test_bare_numbers_to_stdlib_templates_raise_nothing_in_the_library(tmp_path, call):
    mod = {"spur": "gears", "text": "plates"}.get(call[:4], "joints")
    r, path = _compile(tmp_path, f'import "std/{mod}.aidl"\n\nx = {call}\n')
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    assert [(d.code, str(d.span.file)) for d in r.diagnostics if d.span and str(d.span.file) != path] == []


def test_wrong_kind_is_e0109_at_the_users_argument(tmp_path):
    src = 'import "std/joints.aidl"\n\nbox = finger_box(length=100, depth=80, thickness=3 deg)\n'
    p = tmp_path / "x.aidl"
    p.write_text(src)
    out = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", "--json", str(p)],
                         capture_output=True, text=True, timeout=300)
    data = json.loads(out.stdout)
    assert not data["ok"]
    (d,) = data["diagnostics"]
    assert d["code"] == "E0109"
    assert d["span"]["file"] == str(p)
    col = src.splitlines()[2].index("3 deg") + 1
    assert (d["span"]["line"], d["span"]["column"], d["span"]["end_column"]) == (3, col, col + 5)
    assert "`thickness` of `finger_box` is a length like its default `3 mm`, got an angle" \
        in d["message"]
    assert "thickness=3 mm" in d["hint"]
    assert "^^^^^" in d["rendered"]
