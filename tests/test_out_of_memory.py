"""Out of memory anywhere in a compile (NumPy, Manifold, the checks, the writers) is the
program's located E0304 in every front end, never "internal error" (issue 58): the CLI (with
its own address-space cap, `--memory`), the Python API, `aidl serve` / `aidl studio`
sessions and workers, MCP, the LSP job and `aidl batch`.  A MemoryError is injected into a
stage (monkeypatch), or a real one comes from a low RLIMIT_AS in a subprocess."""
import json
import os
import resource
import subprocess
import sys

import pytest

from conftest import ROOT

PLATE = ROOT / "examples" / "mounting_plate.aidl"
FAN = ("def fan(n = 3) -> assembly {\n    if n > 0 {\n        s0 = fan(n - 1)\n"
       "        s1 = fan(n - 1)\n    }\n    c = Circle((0, 0), 1)\n}\n"
       "solid top {\n    v = fan(14)\n}\n")


def _boom(*a, **k):
    raise MemoryError("Unable to allocate 4.80 GiB for an array with shape (644913712,)")


def _cli(*args, cwd):
    return subprocess.run([sys.executable, "-m", "aidl_lang.cli", *args], capture_output=True,
                          text=True, timeout=120, cwd=cwd,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})


# ------------------------------------------------------------------ the CLI's own cap
def test_the_cli_caps_its_memory_and_running_out_is_a_located_E0304(tmp_path):
    """A template doubling itself 14 levels deep needs more than 500 MB of address space:
    with `--memory 500M` (and no `ulimit`) `aidl check` says E0304 at the structure, with the
    flag in the hint.  (It fits in 600 MB since the exact recovery keeps no chord arrays of
    its own per circle, h6-loop: at 600 MB it ended with W0509.)"""
    (tmp_path / "fan.aidl").write_text(FAN)
    r = _cli("check", "fan.aidl", "--memory", "500M", "--budget", "8", cwd=tmp_path)
    assert r.returncode == 1, r.stderr
    assert "fan.aidl:8:1: error[E0304]: the program ran out of memory" in r.stderr, r.stderr
    assert "(500 MB)" in r.stderr and "`--memory SIZE`" in r.stderr
    assert "internal error" not in r.stderr and "Traceback" not in r.stderr


def test_the_default_cap_is_half_the_machine_and_a_normal_render_works_under_it(tmp_path):
    from aidl_lang.base.memory import MIN_CAP, default_cap, machine_memory
    cap = default_cap()
    if cap is None:
        pytest.skip("no /proc/meminfo here")
    assert cap == max(MIN_CAP, machine_memory() // 2)
    code = ("import resource, sys\nfrom aidl_lang.cli.main import main\n"
            "rc = main(sys.argv[1:], cap_memory=True)\n"
            "print(rc, resource.getrlimit(resource.RLIMIT_AS)[0])\n")
    outs = ["-o", "p.svg", "-o", "p.dxf", "-o", "p.gcode", "-o", "p.pdf"]
    for extra, want in (([], cap), (["--memory", "none"], resource.RLIM_INFINITY),
                        (["--memory", "3G"], 3 << 30)):
        r = subprocess.run([sys.executable, "-c", code, "render", str(PLATE), *outs, *extra],
                           capture_output=True, text=True, timeout=120, cwd=tmp_path,
                           env={**os.environ, "PYTHONPATH": str(ROOT)})
        assert r.stdout.split()[-2:] == ["0", str(want)], r.stdout + r.stderr
    # under the smallest default (MIN_CAP) too, the STL/3MF writers included
    r = _cli("render", str(PLATE), "-o", "q.svg", "-o", "q.stl", "-o", "q.3mf",
             "--memory", str(MIN_CAP // (1 << 20)), cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    r = _cli("check", str(PLATE), "--memory", "lots", cwd=tmp_path)
    assert r.returncode == 2 and "`lots` is not a size such as 4G" in r.stderr


# ------------------------------------------------------------------ injected MemoryErrors
def test_cli_render_writer_out_of_memory_is_E0304_and_nothing_written(tmp_path, monkeypatch,
                                                                      capsys):
    from aidl_lang.cli.main import main
    from aidl_lang.output.writers import svg
    good = tmp_path / "p.svg"
    good.write_text("<svg/>")
    monkeypatch.setattr(svg, "write", _boom)
    assert main(["render", str(PLATE), "-o", str(good), "--json"]) == 1
    doc = json.loads(capsys.readouterr().out)
    d = doc["diagnostics"][-1]
    assert d["code"] == "E0304" and "ran out of memory in the SVG writer of `kit." in d["message"]
    assert d["span"]["file"] == str(PLATE) and d["span"]["line"] > 1
    assert good.read_text() == "<svg/>"


def test_cli_check_out_of_memory_after_the_compile_is_E0304(monkeypatch, capsys):
    from aidl_lang import api
    from aidl_lang.cli.main import main
    monkeypatch.setattr(api.Result, "find_redundant", _boom)
    assert main(["check", str(PLATE)]) == 1
    err = capsys.readouterr().err
    assert "error[E0304]: the program ran out of memory while compiling" in err, err
    assert f"{PLATE}:" in err and "internal error" not in err


def test_booleans_and_checks_out_of_memory_in_the_pipeline_and_the_api(monkeypatch):
    import aidl_lang
    from aidl_lang import pipeline
    from aidl_lang.output import OutputError
    from aidl_lang.output.writers import dxf
    monkeypatch.setattr(pipeline, "check_drawing", _boom)
    r = aidl_lang.compile(path=str(PLATE))
    e = [d for d in r.errors if d.code == "E0304"]
    assert e and "in the shape checks" in e[0].message and e[0].span is not None
    monkeypatch.undo()
    r = aidl_lang.compile(path=str(PLATE))
    monkeypatch.setattr(dxf, "write", _boom)
    with pytest.raises(OutputError) as ex:
        r.encode("dxf")
    assert ex.value.budget is not None and ex.value.budget.where is not None
    assert "ran out of memory" in str(ex.value)


def test_api_freedom_and_redundancy_search_out_of_memory(monkeypatch):
    """The API's analyses after the compile: a freedom count that runs out of memory is
    "not counted" with the reason, and the redundancy search's is one located E0304 among
    the result's diagnostics (the MCP `check` tool and the studio call both), never a raw
    MemoryError."""
    import aidl_lang
    from aidl_lang import pipeline
    from aidl_lang.solver.diagnosis import freedom
    r = aidl_lang.compile(path=str(PLATE))
    assert r.ok
    monkeypatch.setattr(freedom, "degrees_of_freedom", _boom)
    doc = r.freedom(detail=True)
    assert doc["dof"] is None and "ran out of memory" in doc["not_counted"], doc
    assert doc["text"].startswith("degrees of freedom not counted (the count ran out of memory")
    monkeypatch.setattr(pipeline, "report_redundancies", _boom)
    found = r.find_redundant()
    assert [d.code for d in found] == ["E0304"], found
    assert "in the redundancy search" in found[0].message and found[0].span is not None
    assert r.not_searched_why == "out of memory" and not r.ok
    assert r.find_redundant() == found               # once per result


def test_serve_session_out_of_memory_is_E0304_not_E0900(monkeypatch, tmp_path):
    from aidl_lang.serve import session as S
    f = tmp_path / "p.aidl"
    f.write_text(PLATE.read_text())
    s = S.Session(f)
    monkeypatch.setattr(S, "after_solve", _boom)
    view = s.load()
    codes = [(d["code"], d["span"]["line"] if d["span"] else None) for d in view["diagnostics"]]
    assert codes and codes[0][0] == "E0304" and codes[0][1] is not None, codes
    assert not any(c == "E0900" for c, _ in codes)


def _studio(request):
    """The studio worker's answer to ``request``, in this process: the handler, then its
    ``idle`` as the worker runs it after each answer (the handler holds off the collector's
    full collections until then: without it, every later test of this process ran without
    one and test_solver_gc's dead models piled up: 27 alive instead of about 10-17)."""
    import gc
    from aidl_lang.studio import compiler
    normal = gc.get_threshold()
    handle = compiler.handler()
    try:
        return handle(request)
    finally:
        handle.idle()
        assert gc.get_threshold() == normal


def _studio_view(tmp_path, source, monkeypatch=None):
    folder = tmp_path / "data" / "0123456789abcdef"
    folder.mkdir(parents=True)
    return _studio(("view", "sid", str(folder), source, {})), folder


def test_studio_out_of_memory_is_a_located_E0304(monkeypatch, tmp_path):
    from aidl_lang.serve import session as S
    monkeypatch.setattr(S, "after_solve", _boom)
    answer, folder = _studio_view(tmp_path, PLATE.read_text())
    d = answer["diagnostics"][0]
    assert d["code"] == "E0304" and d["span"]["file"] == "SESSION/main.aidl", d
    assert "internal error" not in json.dumps(answer)
    from aidl_lang.studio import compiler
    monkeypatch.setattr(compiler, "view", _boom)         # past the session's own handler
    answer = _studio(("view", "sid", str(folder), PLATE.read_text(), {}))
    assert answer["diagnostics"][0]["code"] == "E0304" and answer["retire"] is True
    assert str(tmp_path) not in json.dumps(answer)


def test_studio_answers_never_carry_the_server_folder(tmp_path):
    """A program that errors, warns and imports a file of the session: every string of the
    answer (spans, labels, messages, hints, rendered texts) says SESSION, never the data
    folder (issue 58: `"file": "/tmp/aidl-studio-XXXX/SID/main.aidl"`)."""
    lib = ("def tab(w = 4) -> solid {\n    body = Rectangle(center=(0, 0), width=w, "
           "height=w)\n    x = undefined_name\n}\n")
    folder = tmp_path / "data" / "0123456789abcdef"
    folder.mkdir(parents=True)
    (folder / "lib.aidl").write_text(lib)
    src = ('import "lib.aidl"\nimport "missing.aidl"\nsolid plate {\n'
           '    body = Rectangle(center=(0, 0), width=40, height=20)\n    t = tab(w=2)\n}\n')
    answer = _studio(("view", "sid", str(folder), src, {}))
    text = json.dumps(answer)
    assert answer["diagnostics"], answer
    assert "SESSION/" in text
    assert str(tmp_path) not in text and str(folder) not in text, text[:2000]
    assert os.path.realpath(tmp_path) not in text
    files = {d["span"]["file"] for d in answer["diagnostics"] if d.get("span")}
    assert files <= {"SESSION/main.aidl", "SESSION/lib.aidl", "SESSION/missing.aidl"}, files
    dl = _studio(("download", str(folder), src, {}, "svg", {}))
    assert str(tmp_path) not in json.dumps(dl if isinstance(dl, dict) else {})


def test_mcp_worker_out_of_memory_is_E0304_with_its_line(monkeypatch, tmp_path):
    pytest.importorskip("mcp")
    from aidl_lang.mcp import tools as T
    from aidl_lang.mcp import worker
    monkeypatch.setattr(T, "check", _boom)
    ok, value = worker._handler(str(tmp_path), 1.0)(("check", (PLATE.read_text(), None)))
    assert not ok and str(value).startswith("E0304 line ") and "ran out of memory" in str(value)
    assert "internal error" not in str(value)


def test_lsp_job_out_of_memory_is_the_documents_E0304(monkeypatch):
    from aidl_lang.editor.lsp import job
    answer = job.out_of_memory({"id": 3, "text": FAN, "path": "/x/fan.aidl",
                                "uri": "file:///x/fan.aidl"}, 3)
    d = answer["diagnostics"][0]
    assert answer["id"] == 3 and d["code"] == "E0304" and d["range"]["start"]["line"] == 7
    assert "error" not in answer


def test_batch_row_out_of_memory_is_an_error_row_with_E0304():
    from aidl_lang.batch.child import out_of_memory_row
    row = out_of_memory_row({"id": "fan", "path": "fan.aidl", "source": FAN, "sha256": "",
                             "options": ""})
    assert row["status"] == "error" and row["errors"][0]["code"] == "E0304"
    assert row["errors"][0]["line"] == 8
