"""`aidl batch`'s inputs and outputs turned against it (issue 37): symbolic links as OUT or as
a planted journal, a FIFO and /dev/zero among the inputs, an OUT that is not a batch result,
a Parquet OUT whose `id` column is not text, and Ctrl-C under the Dask scheduler."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from aidl_lang.batch.command import UsageError, run_batch
from aidl_lang.batch.store import read_jsonl

ROOT = Path(__file__).resolve().parent.parent
GOOD = "solid plate { body = Rectangle(center=(0, 0), width=40, height=20) }\n"


def _aidl(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "aidl_lang.cli", *args], capture_output=True,
                          text=True, cwd=cwd, timeout=120)


def test_a_symlinked_output_is_refused_and_its_target_untouched(tmp_path):
    (tmp_path / "ok.aidl").write_text(GOOD)
    victim = tmp_path / "victim.txt"
    victim.write_text("victim's notes\n")
    (tmp_path / "link.jsonl").symlink_to(victim)
    r = _aidl("batch", "ok.aidl", "-o", "link.jsonl", cwd=tmp_path)
    assert r.returncode == 2, r.stderr
    assert "`link.jsonl` is a symbolic link; refusing to write through it" in r.stderr
    assert "Traceback" not in r.stderr
    assert victim.read_text() == "victim's notes\n"
    assert (tmp_path / "link.jsonl").is_symlink()


def test_a_planted_parquet_journal_is_refused(tmp_path):
    pytest.importorskip("pyarrow")
    (tmp_path / "ok.aidl").write_text(GOOD)
    victim = tmp_path / "victim.txt"
    victim.write_text("victim's notes\n")
    (tmp_path / "out.parquet.journal.jsonl").symlink_to(victim)
    with pytest.raises(UsageError, match="journal.jsonl` is a symbolic link"):
        run_batch([str(tmp_path / "ok.aidl")], tmp_path / "out.parquet")
    assert victim.read_text() == "victim's notes\n"
    assert not (tmp_path / "out.parquet").exists()


def test_a_fifo_and_dev_zero_in_the_input_folder_are_one_E0004_row_each(tmp_path):
    src = tmp_path / "in"
    src.mkdir()
    (src / "a_ok.aidl").write_text(GOOD)
    os.mkfifo(src / "b_pipe.aidl")
    (src / "c_zero.aidl").symlink_to("/dev/zero")
    (src / "d_ok.aidl").write_text(GOOD.replace("40", "30"))
    result = run_batch([str(src)], tmp_path / "rows.jsonl", workers=1)
    rows = {Path(r["id"]).name: r for r in result["rows"]}
    assert rows["a_ok.aidl"]["ok"] and rows["d_ok.aidl"]["ok"]
    for name in ("b_pipe.aidl", "c_zero.aidl"):
        [e] = rows[name]["errors"]
        assert e["code"] == "E0004" and "not a regular file" in e["message"], rows[name]


def test_an_output_that_is_not_a_batch_result_is_refused_before_anything_runs(tmp_path):
    (tmp_path / "ok.aidl").write_text(GOOD)
    notes = tmp_path / "notes.jsonl"
    notes.write_text('{"note": "buy milk"}\n{"note": "call Ann"}\n')
    with pytest.raises(UsageError, match="not a batch result"):
        run_batch([str(tmp_path / "ok.aidl")], notes)
    assert notes.read_text() == '{"note": "buy milk"}\n{"note": "call Ann"}\n'


def test_a_parquet_output_with_an_integer_id_is_refused_before_anything_runs(tmp_path):
    pa = pytest.importorskip("pyarrow")
    import pyarrow.parquet as pq
    (tmp_path / "ok.aidl").write_text(GOOD)
    out = tmp_path / "intid.parquet"
    pq.write_table(pa.table({"id": [1, 2], "x": [0.5, 1.5]}), out)
    ran = []
    with pytest.raises(UsageError, match="not a batch result"):
        run_batch([str(tmp_path / "ok.aidl")], out, on_row=ran.append)
    assert ran == [] and pq.read_table(out).column("id").to_pylist() == [1, 2]
