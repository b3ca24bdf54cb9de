"""The main file is read the way imports are (issue 37): a regular file only, opened
non-blocking (a FIFO never hangs), at most the import size limit, refused before it is
read whole or lexed, with a located E0004."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import time

import pytest

from aidl_lang.library.sources import MAX_IMPORT_BYTES

pytestmark = pytest.mark.timing


def _check(path, cwd):
    """``aidl check --json PATH``: ``(result, the child's CPU seconds)`` (a file read whole
    or lexed would spend them; the wall clock of a loaded machine is no measure).  A FIFO
    that blocked would hang: the timeout is the guard."""
    from cpu_clock import child_cpu
    with child_cpu() as cpu:
        r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", "--json", str(path)],
                           capture_output=True, text=True, cwd=cwd, timeout=120)
    return r, cpu()


@pytest.mark.parametrize("kind", ["dev-zero", "fifo", "huge"])
def test_a_main_file_that_is_not_a_small_regular_file_is_a_located_E0004(tmp_path, kind):
    f = tmp_path / "main.aidl"
    if kind == "dev-zero":
        f.symlink_to("/dev/zero")
        why = "is not a regular file"
    elif kind == "fifo":
        os.mkfifo(f)
        why = "is not a regular file"
    else:                                  # one 60 MB string literal
        with open(f, "w") as fh:
            fh.write('solid s { t = "')
            fh.write("x" * 60_000_000)
            fh.write('" }\n')
        why = f"is larger than {MAX_IMPORT_BYTES} bytes"
    r, seconds = _check("main.aidl", tmp_path)
    assert r.returncode == 1, r.stderr
    doc = json.loads(r.stdout)
    [d] = doc["diagnostics"]
    assert d["code"] == "E0004" and why in d["message"], d
    assert d["span"]["file"] == "main.aidl" and d["span"]["line"] == 1
    assert "MemoryError" not in r.stdout + r.stderr and "Traceback" not in r.stderr
    assert seconds < 20


def test_mcp_refuses_a_huge_file_by_path_quickly(tmp_path):
    from aidl_lang.mcp import tools as T
    with open(tmp_path / "big.aidl", "w") as fh:
        fh.write('solid s { t = "' + "x" * 60_000_000 + '" }\n')
    os.mkfifo(tmp_path / "pipe.aidl")
    ws = T.Workspace(tmp_path)
    t0 = time.process_time()                 # CPU seconds (a blocked FIFO would hang)
    with pytest.raises(T.Refused, match="larger than"):
        T.check(ws, path="big.aidl")
    with pytest.raises(T.Refused, match="not a regular file|not a file"):
        T.check(ws, path="pipe.aidl")
    assert time.process_time() - t0 < 5


def test_the_api_reads_the_main_file_like_an_import(tmp_path):
    import aidl_lang
    f = tmp_path / "z.aidl"
    f.symlink_to("/dev/zero")
    r = aidl_lang.compile(path=f)
    [d] = r.diagnostics
    assert d.code == "E0004" and "not a regular file" in d.message and d.span.line == 1
    (tmp_path / "ok.aidl").write_text("\ufeffsolid s { c = Circle((0, 0), 1) }\n")
    assert aidl_lang.compile(path=tmp_path / "ok.aidl").ok
