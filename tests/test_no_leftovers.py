"""The session-end check of tests/conftest.py: a pytest run whose test leaves a child process
running (here `sleep`, started and not stopped) ends with a non-zero status, naming the process
and the test after which it was first seen; the same run that stops its child passes."""
import os
import re
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(),
                                reason="the check reads /proc (Linux)")

LEAKY = """import subprocess

def test_starts_a_child():
    subprocess.Popen(["sleep", "60"])
"""
TIDY = """import subprocess

def test_starts_and_stops_a_child():
    p = subprocess.Popen(["sleep", "60"])
    p.terminate()
    p.wait()
"""


def _run(tmp_path: Path, body: str, *args: str) -> subprocess.CompletedProcess:
    shutil.copy(ROOT / "tests" / "conftest.py", tmp_path / "conftest.py")
    (tmp_path / "test_it.py").write_text(body)
    env = {**os.environ, "AIDL_TEST_LEFT_GRACE": "0.5",
           "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1"}          # a plain pytest starts in 0.3 s
    return subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                           *args, "test_it.py"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120, env=env)


# the suite runs on pytest-xdist workers (``-n auto``, pyproject.toml): there a worker checks
# its own children and hands what it found to the controller, which names it and fails
XDIST = ("-p", "xdist.plugin", "-n", "1")


@pytest.mark.parametrize("args", [(), XDIST], ids=["in-process", "xdist-worker"])
def test_a_child_left_running_fails_the_run_and_is_named(tmp_path, args):
    r = _run(tmp_path, LEAKY, *args)
    pids = [int(p) for p in re.findall(r"pid (\d+) \(sleep 60\)", r.stdout)]
    try:
        assert r.returncode == 1, r.stdout + r.stderr
        assert "1 passed" in r.stdout and "processes left running" in r.stdout, r.stdout
        assert len(pids) == 1, r.stdout
        assert "first seen after test_it.py::test_starts_a_child" in r.stdout, r.stdout
    finally:                       # the orphan is ours now (the subreaper): stop it
        for p in pids:
            try:
                os.kill(p, signal.SIGKILL)
                os.waitpid(p, 0)
            except (ProcessLookupError, ChildProcessError):
                pass


@pytest.mark.parametrize("args", [(), XDIST], ids=["in-process", "xdist-worker"])
def test_a_run_that_stops_its_children_passes(tmp_path, args):
    r = _run(tmp_path, TIDY, *args)
    assert r.returncode == 0 and "processes left running" not in r.stdout, r.stdout + r.stderr

