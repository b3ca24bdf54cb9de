"""Issue 110's small reliability cases: a param declared twice (E0107), a string's unknown
escape kept and warned (W0114), `aidl set` and `aidl fmt` through a link and never over a
read-only file (the MCP edits refuse both), an MCP path part over 255 bytes a
`bad_argument`, and the router's tool change saying to set Z zero again."""
import contextlib
import io
import os

import pytest

import aidl_lang
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.cli.main import main
from aidl_lang.parser import parse

TWICE = """units mm
param w = 60 mm, min = 10 mm, max = 100 mm
solid plate {
    body = Rectangle(center=(0, 0), width=w, height=20)
}
param w = 80 mm, min = 70 mm, max = 90 mm
"""


def _run(*args) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(list(args))
    return rc, out.getvalue(), err.getvalue()


def test_a_param_declared_twice_is_an_error_at_the_second():
    r = aidl_lang.compile(source=TWICE)
    [e] = r.errors
    assert (e.code, e.span.line, e.span.col) == ("E0107", 6, 7)
    assert "declared twice (first on line 2)" in e.message
    # a param and a top-level constant of one name: the same error, at the later one
    r = aidl_lang.compile(source=TWICE.replace("param w = 80 mm, min = 70 mm, max = 90 mm",
                                               "w = 80 mm"))
    [e] = r.errors
    assert (e.code, e.span.line) == ("E0107", 6) and "is a param (line 2)" in e.message
    # two constants stay what they were: the later is the value
    r = aidl_lang.compile(source=TWICE.replace("param w = 60 mm, min = 10 mm, max = 100 mm",
                                               "w = 40 mm").replace(
        "param w = 80 mm, min = 70 mm, max = 90 mm", "w = 50 mm"))
    assert r.ok, r.errors


def _strings(src: str):
    from aidl_lang import ast as A
    sink = DiagnosticSink()
    prog = parse(src, "s.aidl", sink)
    return [n.value for n in A.walk(prog) if type(n) is A.Str], sink.items


@pytest.mark.parametrize("literal, value, warned", [
    (r'"50\% off"', "50\\% off", [(1, 8, r"`\%`")]),
    (r'"C:\temp\new"', "C:\temp\new", []),            # two escapes, as documented
    (r'"C:\\temp\\new"', "C:\\temp\\new", []),
    (r'"say \"hi\" \'x\'"', "say \"hi\" 'x'", []),
    (r"'a\qb\zc'", "a\\qb\\zc", [(1, 7, r"`\q`"), (1, 10, r"`\z`")]),
])
def test_a_strings_escapes_and_an_unknown_one_kept_and_warned(literal, value, warned):
    vals, diags = _strings(f"x = {literal}\n")
    assert vals == [value]
    assert [(d.span.line, d.span.col, d.message.split(" ")[0]) for d in diags] == warned
    assert all(d.code == "W0114" and d.severity == "warning" for d in diags)


def test_an_engraved_texts_backslash_is_engraved(tmp_path):
    src = 'units mm\ndrawing label {\n    t = Text("50\\% off", position=(0, 0), size=5 mm)\n}\n'
    r = aidl_lang.compile(source=src)
    assert r.ok and [(d.code, d.span.line, d.span.col) for d in _warnings(r)] == \
        [("W0114", 3, 17)]
    # an f-string's unknown escape too
    r = aidl_lang.compile(source=src.replace('Text("', 'Text(f"'))
    assert [(d.code, d.span.col) for d in _warnings(r)] == [("W0114", 18)]


def _warnings(r):
    return [d for d in r.diagnostics if d.severity == "warning"]


PLATE = """units mm
param w = 60 mm, min = 10 mm, max = 100 mm
solid p {
    b = Rectangle(center=(0, 0), width=w, height=20)
}
"""


def test_aidl_set_and_fmt_edit_through_a_link_and_refuse_a_read_only_file(tmp_path):
    real = tmp_path / "real.aidl"
    real.write_text(PLATE)
    link = tmp_path / "link.aidl"
    link.symlink_to("real.aidl")
    rc, out, err = _run("set", str(link), "w=33")
    assert rc == 0, err
    assert link.is_symlink() and os.readlink(link) == "real.aidl"
    assert "param w = 33 mm, min = 10 mm" in real.read_text()

    ro = tmp_path / "ro.aidl"
    ro.write_text(PLATE)
    ro.chmod(0o444)
    rc, out, err = _run("set", str(ro), "w=30")
    assert rc == 1 and "is read-only (mode 0444); refusing to edit it" in err
    assert ro.read_text() == PLATE
    messy = tmp_path / "messy.aidl"
    messy.write_text(PLATE.replace("width=w, height=20", "width=w,height=20"))
    messy.chmod(0o444)
    rc, out, err = _run("fmt", str(messy))
    assert rc == 1 and "is read-only" in err and "width=w,height=20" in messy.read_text()


def test_mcp_refuses_a_long_name_and_a_read_only_program(tmp_path):
    from aidl_lang.mcp import tools
    (tmp_path / "ro.aidl").write_text(PLATE)
    (tmp_path / "ro.aidl").chmod(0o444)
    ws = tools.Workspace(tmp_path)
    long = "a" * 300 + ".aidl"
    for fn, kw, arg in ((tools.check, dict(path=long), "path"),
                        (tools.set_params, dict(path=long, values={"w": "30 mm"}), "path"),
                        (tools.write_program, dict(path="d/" + long, text="units mm\n"), "path"),
                        (tools.render, dict(path="ro.aidl", output=long[:-5] + ".svg"),
                         "output")):
        with pytest.raises(tools.Refused) as ex:
            fn(ws, **kw)
        assert ex.value.code == "bad_argument" and "at most 255" in str(ex.value), fn
        assert f"in `{arg}`" in str(ex.value)
    for fn, kw in ((tools.set_params, dict(values={"w": "30 mm"})),
                   (tools.write_program, dict(text="units mm\n"))):
        with pytest.raises(tools.Refused) as ex:
            fn(ws, path="ro.aidl", **kw)
        assert "read-only (mode 0444)" in str(ex.value), fn
    assert (tmp_path / "ro.aidl").read_text() == PLATE


def test_the_routers_tool_change_says_to_set_z_zero(tmp_path):
    src = """units mm
thickness 6 mm
solid plate {
    body = Rectangle(center=(0, 0), width=40, height=30)
    hole h { c = Circle(center=(0, 0), diameter=4.5 mm) }
    Countersink(h, diameter=9 mm)
}
"""
    f = tmp_path / "p.aidl"
    f.write_text(src)
    rc, out, err = _run("render", str(f), "-o", str(tmp_path / "p.nc"), "--machine", "router")
    assert rc == 0, err
    text = (tmp_path / "p.nc").read_text()
    assert "; tool change: a 90 deg V-bit for the 1 countersink: put it in, set Z zero on " \
        "the material's top with it, then resume\nM0\n" in text


def test_a_sweep_starts_no_point_its_work_left_cannot_pay():
    """Issue 110: a 20,000-hole panel's sweep spent 11 s of CPU on points it started and
    abandoned, then said "0 points ... out of budget".  A point the work left cannot pay is
    not started, and the answer says what one point needs."""
    from aidl_lang.params.sweep import sweep
    base = sweep(PLATE, "p.aidl", points=0)
    assert base.ok and base.points >= 3 and base.point_work > 0 and not base.short
    need = base.point_work
    rep = sweep(PLATE, "p.aidl", points=0, work=need // 2)
    # nothing compiled: only the declarations read (the ranges a point is moved into)
    assert rep.points == 0 and rep.work < need / 50 and rep.short == need // 2 - rep.work
    assert rep.point_work == need
    assert f"one point needs about {need:,} work units" in rep.text()
    assert f"{rep.short:,} were left, so no more was started" in rep.text()
    # room for two points: two judged, nothing begun past them
    rep = sweep(PLATE, "p.aidl", points=0, work=int(2.5 * need))
    assert 1 <= rep.points <= 2 and rep.work <= int(2.5 * need) and rep.short


def _sunk_grid(n: int, sunk: bool = True) -> str:
    return f"""units mm
thickness 4 mm
solid panel {{
    body = Rectangle(center=({n * 5}, {n * 5}), width={n * 10 + 10}, height={n * 10 + 10})
    for i in range({n}) {{
        for j in range({n}) {{
            hole h {{ c = Circle(center=(i * 10 + 5, j * 10 + 5), diameter=3 mm) }}
            {"Countersink(h, diameter=6 mm)" if sunk else ""}
        }}
    }}
    hole edge {{ c = Circle(center=(2, -3), diameter=3 mm) }}
    Countersink(edge, diameter=9 mm)
}}
"""


def test_each_countersink_is_judged_against_the_material_near_it(monkeypatch):
    """Issue 110: W0528 subtracted the whole part from each head's disc (3,025 sunk holes:
    31.7 s of CPU against 1.98 s unsunk).  Each head now meets only the loops near it: the
    loops one head is measured against do not grow with the panel, and the warnings are
    the same (the head off the edge, and no other)."""
    from aidl_lang.output.checks.holes import sinks as S
    met: list = []
    around = S._Near.around

    def counted(self, center, r):
        got = around(self, center, r)
        met.append(len(got.to_polygons()))
        return got
    monkeypatch.setattr(S._Near, "around", counted)
    most = {}
    for n in (8, 16):
        met.clear()
        r = aidl_lang.compile(source=_sunk_grid(n))
        w = [d for d in r.diagnostics if d.code == "W0528"]
        assert len(w) == 1 and "countersink of `panel.edge.c` at (2, -3)" in w[0].message
        assert len(met) == n * n + 1
        most[n] = max(met)
    assert most[16] == most[8] <= 12          # its hole, its neighbours', the outline


def test_the_wall_guards_message_says_what_it_measured(monkeypatch):
    """Issue 110: the wall guard said "this machine gave the compile less than 10% of a
    core" after 56.8 s of CPU in 150 s (38 %).  It now says the CPU the compile got since
    it started and that share, measured (the clocks stand in for a busy machine)."""
    import time
    from aidl_lang.base import limits
    clock = {"cpu": 100.0, "wall": 1000.0}
    monkeypatch.setattr(time, "process_time", lambda: clock["cpu"])
    monkeypatch.setattr(time, "monotonic", lambda: clock["wall"])
    start = limits.started()
    clock["cpu"] += 56.8
    clock["wall"] += 150.5
    text = limits.wall_text(15.0, start)
    assert text == ("more than 150 s of wall time (10 x its 15 s budget), in which the compile "
                    "got 56.8 s of CPU (38% of a core: the machine is busy, or a stage waited)")
    d = limits.Deadline(limits.now() + 1e9)
    clock["wall"] += 200.0
    with pytest.raises(limits.OutOfBudget) as ex:
        d.backstop("booleans")
    assert "in which the compile got 0 s of CPU (0% of a core" in str(ex.value)


def test_a_constructors_point_may_read_a_box_side():
    """`Rectangle(center=(c.center.x, c.bb.bottom), ...)` was an internal error ("TapeError:
    cannot compile BBTerm into a residual"): a constructor's equations that read a box are
    deferred as a box relation's are, for every constructor."""
    src = """units mm
solid p {
    c = Circle(center=(0, 0), radius=5)
    r = Rectangle(center=(c.center.x, c.bb.bottom), width=10, height=2)
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [d.message for d in r.errors]
    got = {v.name: v.mm for v in r.values}
    assert got["p.r.center"] == pytest.approx((0.0, -5.0), abs=1e-9)
