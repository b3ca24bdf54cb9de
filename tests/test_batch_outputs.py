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
