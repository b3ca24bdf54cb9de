"""The whole ``aidl check`` of some files, in this tree and in older trees, side by side in one
run (issue 48: a gear pair under a ``Below`` took 99-190 s).

Each tree runs in its own process (``PYTHONPATH=TREE``); each file is checked in-process
through the CLI's ``main(["check", FILE])`` (the compile, W0401's search, the freedom count and
what slides), CPU seconds, best of ``--repeat`` after one warm-up run, and the process's peak
RSS.  A file that takes longer than ``--timeout`` seconds is reported as ``> T s``.

Run:  .venv/bin/python benchmarks/compile/check_trees.py [--timeout 60] [--repeat 3] TREE ... -- FILE ...
      (TREE: a checkout or ``git archive`` of the project; ``.`` is this one)
"""
from __future__ import annotations

import argparse
import json
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]

CHILD = r"""
import contextlib, io, json, resource, sys, time
from aidl_lang.cli.main import main
path, repeat = sys.argv[1], int(sys.argv[2])
best, unknowns = 1e9, None
for k in range(repeat + 1):
    out = io.StringIO()
    t0 = time.process_time()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        try:
            main(["check", path])
        except SystemExit:
            pass
    if k:
        best = min(best, time.process_time() - t0)
    line = out.getvalue().splitlines()[-1] if out.getvalue() else ""
print(json.dumps({"cpu": best, "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                  "line": line}))
"""


def run(tree: str, path: str, repeat: int, timeout: float) -> str:
    path = str(pathlib.Path(path).resolve())
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(tree).resolve()))
    try:
        p = subprocess.run([sys.executable, "-c", CHILD, path, str(repeat)], env=env, cwd=tree,
                           capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return f"> {timeout:g} s"
    try:
        doc = json.loads(p.stdout.strip().splitlines()[-1])
    except (IndexError, ValueError):
        return "failed: " + (p.stderr.strip().splitlines() or ["?"])[-1][:60]
    unknowns = doc["line"].split(" unknowns")[0].rsplit(" ", 1)[-1] if " unknowns" in doc["line"] \
        else "?"
    return f"{1e3 * doc['cpu']:8.0f} ms {doc['rss_mb']:6.0f} MB  {unknowns:>5s} unknowns"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("rest", nargs="+", help="TREE ... -- FILE ...")
    a = ap.parse_args()
    if "--" in a.rest:
        k = a.rest.index("--")
        trees, files = a.rest[:k], a.rest[k + 1:]
    else:
        trees, files = a.rest, [str(ROOT / "tests/programs/gear_pair_plate_below.aidl"),
                                str(ROOT / "examples/gear_pair.aidl"),
                                str(ROOT / "examples/telephone.aidl")]
    for f in files:
        print(pathlib.Path(f).name)
        for t in trees:
            print(f"  {t:28s} {run(t, f, a.repeat, a.timeout)}", flush=True)


if __name__ == "__main__":
    main()
