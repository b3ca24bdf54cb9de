"""The `aidl` command line, run as a separate process: exit codes, output files, text and JSON
diagnostics, `explain`, and `--set`."""
import json
import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT

GOOD = """param width = 40
solid s {
    body = Rectangle(center=(0, 0), width=width, height=20)
    hole h { c = Circle(center=(0, 0), radius=5) }
}
"""

BAD = """solid s {
    body = Rectangle(center=(0, 0), width=40, height=20)
    c = Circel(center=(0, 0), radius=5)
}
"""


def aidl(*args, cwd=None, env=None):
    e = dict(os.environ)
    e.pop("AIDL_DEBUG", None)
    e["NO_COLOR"] = "1"
    e.update(env or {})
    return subprocess.run([sys.executable, "-m", "aidl_lang.cli", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd or ROOT, env=e, timeout=120)


def svg_size(text):
    head = text[text.index("<svg"):text.index(">", text.index("<svg"))]
    a = dict(re.findall(r'(\w+)="([^"]*)"', head))
    return float(a["width"].removesuffix("mm")), float(a["height"].removesuffix("mm")), a


@pytest.fixture
def good(tmp_path):
    p = tmp_path / "good.aidl"
    p.write_text(GOOD)
    return p


@pytest.fixture
def bad(tmp_path):
    p = tmp_path / "bad.aidl"
    p.write_text(BAD)
    return p


def test_render_good_file_writes_svg(good):
    r = aidl("render", good)
    assert r.returncode == 0, r.stderr
    out = good.with_suffix(".svg")
    assert out.is_file()
    assert f"wrote {out}" in r.stdout
    text = out.read_text()
    w, h, attrs = svg_size(text)
    assert "viewBox" in attrs
    assert w == pytest.approx(44.0) and h == pytest.approx(24.0)   # 40x20 plus a 5% margin
    assert "<path" in text
    # no temporary files are left beside the output
    assert sorted(p.name for p in good.parent.iterdir()) == ["good.aidl", "good.svg"]


def test_render_with_output_option(good, tmp_path):
    out = tmp_path / "sub.svg"
    r = aidl("render", good, "-o", out)
    assert r.returncode == 0 and out.is_file()
    assert not good.with_suffix(".svg").exists()


def test_check_good_file(good):
    r = aidl("check", good)
    assert r.returncode == 0, r.stderr
    assert "ok" in r.stdout
    assert not good.with_suffix(".svg").exists()       # check writes nothing


def test_bad_file_exit_1_with_location_and_caret(bad):
    r = aidl("render", bad)
    assert r.returncode == 1
    assert not bad.with_suffix(".svg").exists()
    lines = r.stderr.splitlines()
    head = [l for l in lines if "error[E0103]" in l]
    assert head == [f"{bad}:3:9: error[E0103]: unknown function `Circel`"]
    i = lines.index("3 |     c = Circel(center=(0, 0), radius=5)")
    assert lines[i + 1] == "  |         ^^^^^^"
    assert any("did you mean `Circle`?" in l for l in lines)
    assert "aidl: 1 error" in r.stderr
    assert "\x1b[" not in r.stderr                       # no colour when not a terminal


def test_check_bad_file_exit_1(bad):
    r = aidl("check", bad)
    assert r.returncode == 1
    assert re.search(r"bad\.aidl:3:9: error\[E0103\]", r.stderr)


def test_syntax_errors_exit_1_and_all_are_printed(tmp_path):
    p = tmp_path / "syn.aidl"
    p.write_text("solid s {\n    a = 1 +\n    b = (2 3)\n    c = Circle((0, 0), 1\n}\n")
    r = aidl("check", p)
    assert r.returncode == 1
    locs = re.findall(r"syn\.aidl:(\d+):(\d+): error\[(E\d+)\]", r.stderr)
    assert locs[:2] == [("2", "12", "E0001"), ("3", "12", "E0001")]
    assert len(locs) >= 3


@pytest.mark.parametrize("args", [
    [],
    ["render"],
    ["render", "x.aidl", "--bogus"],
    ["frobnicate", "x.aidl"],
    ["render", "x.aidl", "--set", "width"],
    ["explain"],
])
def test_usage_errors_exit_2(args, good):
    args = [good if a == "x.aidl" else a for a in args]
    r = aidl(*args)
    assert r.returncode == 2, (r.stdout, r.stderr)
    assert "Traceback" not in r.stderr
    assert r.stderr.strip()


def test_set_without_equals_writes_nothing(good):
    r = aidl("render", good, "--set", "width")
    assert r.returncode == 2
    assert "NAME=VALUE" in r.stderr
    assert not good.with_suffix(".svg").exists()


def test_missing_input_file(tmp_path):
    r = aidl("render", tmp_path / "nope.aidl")
    assert r.returncode == 1
    assert "error[E0004]" in r.stderr
    assert not (tmp_path / "nope.svg").exists()


def test_json_output_for_errors(bad):
    r = aidl("check", bad, "--json")
    assert r.returncode == 1
    doc = json.loads(r.stdout)
    assert doc["ok"] is False
    (d,) = doc["diagnostics"]
    assert d["code"] == "E0103"
    assert d["severity"] == "error"
    assert d["message"] == "unknown function `Circel`"
    assert d["span"]["line"] == 3 and d["span"]["column"] == 9
    assert d["span"]["end_line"] == 3 and d["span"]["end_column"] == 15
    assert d["span"]["file"].endswith("bad.aidl")
    src = bad.read_text()
    assert src[d["span"]["start"]:d["span"]["end"]] == "Circel"
    assert "Circle" in d["hint"]
    assert d["suggestions"][0] == "Circle"
    assert d["fix"]["replacement"] == "Circle"
    assert "error[E0103]" in d["rendered"] and "^^^^^^" in d["rendered"]


def test_json_output_for_render_success(good, tmp_path):
    out = tmp_path / "o.svg"
    r = aidl("render", good, "--json", "-o", out)
    assert r.returncode == 0
    doc = json.loads(r.stdout)
    assert doc["ok"] is True and doc["diagnostics"] == []
    assert doc["output"] == str(out)
    assert out.is_file()


def test_json_check_reports_the_solve(good):
    r = aidl("check", good, "--json")
    doc = json.loads(r.stdout)
    assert doc["ok"] is True
    assert doc["solve"]["converged"] is True
    assert doc["solve"]["max_residual"] < 1e-6


def test_json_for_a_solver_failure(tmp_path):
    p = tmp_path / "conflict.aidl"
    p.write_text("solid s {\n    c = Circle(center=(0, 0), radius=5)\n    Radius(c, 7)\n}\n")
    r = aidl("check", p, "--json")
    assert r.returncode == 1
    doc = json.loads(r.stdout)
    (d,) = doc["diagnostics"]
    assert d["code"] == "E0401" and d["span"]["line"] == 3
    assert "Radius(c, 7)" in d["hint"]


def test_failing_render_keeps_the_existing_output(good, bad, tmp_path):
    out = tmp_path / "part.svg"
    assert aidl("render", good, "-o", out).returncode == 0
    before = out.read_bytes()
    mtime = out.stat().st_mtime_ns
    r = aidl("render", bad, "-o", out)
    assert r.returncode == 1
    assert out.read_bytes() == before
    assert out.stat().st_mtime_ns == mtime
    # a solver failure does not overwrite either
    conflict = tmp_path / "conflict.aidl"
    conflict.write_text("solid s {\n    c = Circle(center=(0, 0), radius=5)\n    Radius(c, 7)\n}\n")
    assert aidl("render", conflict, "-o", out).returncode == 1
    assert out.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.aidl", "conflict.aidl",
                                                         "good.aidl", "part.svg"]


def test_set_changes_the_result(good, tmp_path):
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    assert aidl("render", good, "-o", a).returncode == 0
    r = aidl("render", good, "-o", b, "--set", "width=100")
    assert r.returncode == 0, r.stderr
    wa, ha, _ = svg_size(a.read_text())
    wb, hb, _ = svg_size(b.read_text())
    assert wa == pytest.approx(44.0)
    assert wb == pytest.approx(110.0)            # 100 wide plus a 5% margin
    assert ha == pytest.approx(24.0) and hb == pytest.approx(30.0)


def test_set_with_units_and_several_params(tmp_path):
    p = tmp_path / "two.aidl"
    p.write_text("param w = 10\nparam h = 10\nsolid s { r = Rectangle(center=(0, 0), width=w, height=h) }\n")
    out = tmp_path / "two.svg"
    r = aidl("render", p, "-o", out, "--set", "w=5cm", "--set", "h = 1 in")
    assert r.returncode == 0, r.stderr
    w, h, _ = svg_size(out.read_text())
    assert w == pytest.approx(50 * 1.1) and h == pytest.approx(25.4 + 0.1 * 50)


def test_set_unknown_param_is_E0113(good):
    r = aidl("check", good, "--set", "widht=3")
    assert r.returncode == 1
    assert "error[E0113]" in r.stderr
    assert "width" in r.stderr


def test_explain_prints_the_text():
    r = aidl("explain", "E0202")
    assert r.returncode == 0
    assert r.stdout.startswith("E0202: constraint outside its structure's subtree")
    assert "common parent" in r.stdout
    assert "CenterInside(dial, base)" in r.stdout
    lower = aidl("explain", "e0101")
    assert lower.returncode == 0 and lower.stdout.startswith("E0101: unknown name")


def test_explain_unknown_code_exit_2():
    r = aidl("explain", "E9999")
    assert r.returncode == 2
    assert "E0202" in r.stderr


def test_every_code_can_be_explained():
    from aidl_lang.cli import main
    from aidl_lang.base.codes import CODES
    import contextlib
    import io
    for code in CODES:
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            assert main(["explain", code]) == 0
        assert buf.getvalue().startswith(code + ": ")


def test_output_to_a_missing_directory_is_an_error_not_a_crash(good, tmp_path):
    r = aidl("render", good, "-o", tmp_path / "no" / "such" / "dir" / "x.svg")
    assert r.returncode == 1
    assert "cannot write" in r.stderr
    assert "internal error" not in r.stderr


def test_example_renders_from_the_command_line(tmp_path):
    src = ROOT / "examples" / "mounting_plate.aidl"
    out = tmp_path / "plate.svg"
    r = aidl("render", src, "-o", out, "--set", "washers=2")
    assert r.returncode == 0, r.stderr
    ids = re.findall(r'id="(part-[^"]*)"', out.read_text())
    assert ids == ["part-kit_plate", "part-kit_w_0_", "part-kit_w_1_"]


def test_closed_stdout_is_not_an_internal_error():
    rfd, wfd = os.pipe()
    os.close(rfd)
    try:
        r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "explain", "E0202"],
                           stdout=wfd, stderr=subprocess.PIPE, text=True, cwd=ROOT, timeout=60)
    finally:
        os.close(wfd)
    assert "internal error" not in r.stderr
    assert r.returncode != 3


def test_parser_for_one_subcommand_parses_as_the_full_parser():
    """`aidl CMD ...` builds only CMD's arguments (cold start); the result is the same as with
    every subcommand's, and SUBCOMMANDS names every subcommand the full parser has."""
    from aidl_lang.cli.arguments import SUBCOMMANDS, _parser
    full = _parser()
    choices = next(a for a in full._actions if a.dest == "cmd").choices
    assert sorted(SUBCOMMANDS) == sorted(choices)
    samples = [["render", "a.aidl", "-o", "a.svg", "-o", "a.dxf", "--set", "w=3mm", "--dpi", "200"],
               ["check", "a.aidl", "--json", "--dof", "--budget", "2"],
               ["check", "a.aidl", "--values", "plate.bore", "--json"], ["explain", "E0202"],
               ["docs", "SpurGear"], ["docs"], ["import", "b.dxf", "-o", "b.aidl", "--units", "in", "--layer", "Edge.Cuts"],
               ["parts", "a.aidl", "--json", "--set", "w=3mm"],
               ["fmt", "--check", "a.aidl", "b.aidl"], ["set", "a.aidl", "w=3mm", "--json"],
               ["lsp", "--stdio", "--clientProcessId=7"],
               ["serve", "a.aidl", "--port", "0"],
               ["studio", "--host", "0.0.0.0", "--port", "0", "--processes", "2", "--compilers", "3",
                "--rate", "60/minute", "--memory", "800", "--recycle", "50", "--budget", "2"],
               ["mcp", "--root", "parts", "--budget", "2"],
               ["prompt", "--words"], ["prompt", "--examples", "3"],
               ["batch", "d", "x.jsonl", "-o", "o.parquet", "--render", "svg", "--out-dir", "r",
                "--workers", "2", "--scheduler", "local", "--set", "w=3", "--timeout", "5"],
               ["generate", "a wrench", "-o", "w.aidl", "--rounds", "2"], ["eval", "p.txt"]]
    assert {s[0] for s in samples} == set(SUBCOMMANDS)
    for argv in samples:
        assert vars(_parser(argv[0]).parse_args(argv)) == vars(full.parse_args(argv)), argv


def test_only_the_given_subcommand_is_built_and_usage_is_unchanged(capsys):
    """`aidl check ...` builds only the check parser; the top-level usage line still lists
    every subcommand, as when all are built."""
    mod = sys.modules["aidl_lang.cli.arguments"]
    full, one = mod._parser(None), mod._parser("check")
    assert full.format_usage() == one.format_usage()
    sub = [a for a in one._actions if a.dest == "cmd"][0]
    assert list(sub.choices) == ["check"]
    assert list([a for a in full._actions if a.dest == "cmd"][0].choices) == list(mod.SUBCOMMANDS)
    for name in mod.SUBCOMMANDS:
        a = [x for x in mod._parser(name)._actions if x.dest == "cmd"][0].choices[name]
        b = [x for x in full._actions if x.dest == "cmd"][0].choices[name]
        assert a.format_help() == b.format_help()


def test_values_before_the_file_does_not_swallow_it(good):
    """`aidl check --values FILE` (issue 35): `--values` takes any number of names, and used to
    take the program's name too ("the following arguments are required: file")."""
    alone = aidl("check", "--values", good)
    assert alone.returncode == 0, alone.stderr
    assert "s.h.c.radius = 5.000 mm" in alone.stdout and "s.body.width = 40.000 mm" in alone.stdout
    named = aidl("check", "--values", "s.h", good)
    assert named.returncode == 0, named.stderr
    assert "s.h.c.radius = 5.000 mm" in named.stdout and "s.body" not in named.stdout
    after = aidl("check", good, "--values", "s.h.c", "s.body.width", "--json")
    got = {v["name"] for v in json.loads(after.stdout)["values"]}
    assert "s.h.c.radius" in got and "s.body.width" in got and "s.body.height" not in got
    none = aidl("check", "--values")
    assert none.returncode == 2 and "required: file" in none.stderr


def test_aidl_set_rewrites_param_values_and_checks(tmp_path, capsys):
    """`aidl set FILE NAME=VALUE ...` (issue 86): only each value's text changes, then the
    file is checked; a value outside its declared range is E0124 at the range, the file left
    as it was; an unknown name says the nearest."""
    from aidl_lang.cli.main import main as aidl
    text = ("units mm\n# a plate\nparam width = 40 mm, min=20 mm, max=80 mm   # the width\n"
            "param holes = 4\n\nsolid plate {\n"
            "    body = Rectangle(center=(0, 0), width=width, height=20)\n}\n")
    f = tmp_path / "p.aidl"
    f.write_text(text)
    assert aidl(["set", str(f), "width=50 mm", "holes=6"]) == 0
    assert f.read_text() == text.replace("= 40 mm,", "= 50 mm,").replace("= 4\n", "= 6\n")
    assert f"{f}: ok" in capsys.readouterr().out
    for arg, said in (("width=500 mm", "error[E0124]: `width=500 mm`: 500 mm is outside"),
                      ("widht=5", "no param `widht`; did you mean `width`?")):
        assert aidl(["set", str(f), arg]) == 1
        assert said in capsys.readouterr().err
        assert "= 50 mm," in f.read_text()
