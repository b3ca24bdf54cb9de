"""A compile's speed side by side with an older tree: the warm compile of a program (all the
shape checks included) and the instructions of a cold ``aidl check`` against those of
``python -c "import numpy"``:

    .venv/bin/python benchmarks/compile/compile_speed.py /work/old-6ba884a
    .venv/bin/python benchmarks/compile/compile_speed.py OLD --file examples/gear.aidl --rounds 15
    .venv/bin/python benchmarks/compile/compile_speed.py OLD --no-callgrind

Each tree runs its own interpreter (``TREE/.venv/bin/python``, an editable install of that
tree, else this interpreter with ``PYTHONPATH=TREE``), one long-lived process per tree that
compiles the program once to warm up and then on request; the requests alternate between the
two processes (new, old, new, old, ...) ``--rounds`` times (default 15), and the best wall
time of each (``time.perf_counter`` around ``compile_source``, the CLI's ``aidl check`` work
without the freedom count) is printed with the ratio new / old: the machine's load changes
both alike.  The shape checks' own time (``check_drawing``, best of the rounds) is printed
beside it.

The cold figures are callgrind instruction counts (``valgrind --tool=callgrind``, one run
each, ``PYTHONHASHSEED=0``, one BLAS thread, bytecode compiled first, run from an empty
folder, ``--budget 100`` so that callgrind's slowness does not end the check with E0304), of
the tree's own ``aidl check FILE`` command (its console script, which ends with ``os._exit``)
and of ``python -c "import numpy"`` with each tree's interpreter, and their ratio (issue 58's
goal: at most 2x).
"""
from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPATH")}
ENV.update(OPENBLAS_NUM_THREADS="1", PYTHONHASHSEED="0")

_WORKER = r'''
import json, sys, time
import aidl_lang.pipeline as P
from aidl_lang.output import checks as C
path = sys.argv[1]
src = open(path, encoding="utf-8").read()
spent = [0.0]
real = P.check_drawing
def timed(*a, **k):
    t = time.perf_counter()
    try:
        return real(*a, **k)
    finally:
        spent[0] = time.perf_counter() - t
P.check_drawing = timed
P.compile_source(src, path)                     # warm: imports, caches, first compile
print("ready", flush=True)
for line in sys.stdin:
    t = time.perf_counter()
    c = P.compile_source(src, path)
    took = time.perf_counter() - t
    print(json.dumps({"s": took, "checks": spent[0], "ok": c.ok,
                      "warnings": sum(d.severity == "warning" for d in c.sink.items)}),
          flush=True)
'''


def python_of(tree: Path) -> tuple[str, dict]:
    """The interpreter of ``tree`` and its environment."""
    env = dict(ENV)
    py = tree / ".venv" / "bin" / "python"
    if py.exists():
        return str(py), env
    env["PYTHONPATH"] = str(tree)
    return sys.executable, env


def warm(trees: list[Path], path: str, rounds: int) -> list[dict]:
    """Best compile and check times of ``path`` in one process per tree, alternating."""
    procs = []
    for tree in trees:
        py, env = python_of(tree)
        p = subprocess.Popen([py, "-c", _WORKER, path], stdin=subprocess.PIPE,
                             stdout=subprocess.PIPE, text=True, env=env, cwd=tree)
        assert p.stdout.readline().strip() == "ready"
        procs.append(p)
    best = [{"s": float("inf"), "checks": float("inf")} for _ in trees]
    try:
        for _ in range(rounds):
            for k, p in enumerate(procs):
                p.stdin.write("go\n")
                p.stdin.flush()
                r = json.loads(p.stdout.readline())
                best[k]["s"] = min(best[k]["s"], r["s"])
                best[k]["checks"] = min(best[k]["checks"], r["checks"])
                best[k]["ok"], best[k]["warnings"] = r["ok"], r["warnings"]
    finally:
        for p in procs:
            p.stdin.close()
            p.wait(timeout=60)
    return best


def callgrind(tree: Path, *args: str) -> float:
    """Instructions (millions) of ``TREE's python ARGS`` under callgrind, from an empty folder."""
    py, env = python_of(tree)
    with tempfile.TemporaryDirectory() as empty:
        r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                            py, *args], capture_output=True, text=True, env=env, cwd=empty)
    m = re.search(r"Collected : (\d+)", r.stderr)
    return int(m.group(1)) / 1e6 if m else float("nan")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("old", help="the older tree (with its own .venv)")
    ap.add_argument("--file", default="examples/telephone.aidl",
                    help="the program, relative to each tree (default examples/telephone.aidl)")
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--no-callgrind", action="store_true")
    a = ap.parse_args()
    trees = [ROOT, Path(a.old).resolve()]
    names = ["new", "old"]
    print(f"{a.file}: new = {ROOT}, old = {trees[1]}")
    best = warm(trees, a.file, a.rounds)
    for name, b in zip(names, best):
        print(f"  warm compile, best of {a.rounds} ({name}): {b['s'] * 1e3:7.1f} ms, of which "
              f"the shape checks {b['checks'] * 1e3:6.1f} ms ({b['warnings']} warnings)")
    print(f"  warm compile new / old: {best[0]['s'] / best[1]['s']:.2f}x "
          f"(checks {best[0]['checks'] / best[1]['checks']:.2f}x)")
    if a.no_callgrind:
        return
    for name, tree in zip(names, trees):
        py, env = python_of(tree)
        subprocess.run([py, "-m", "compileall", "-q", str(tree / "aidl_lang")],
                       stdout=subprocess.DEVNULL, env=env, check=False)
        floor = callgrind(tree, "-c", "import numpy")
        cold = callgrind(tree, str(tree / ".venv" / "bin" / "aidl"), "check", "--budget", "100",
                         str(tree / a.file))
        print(f"  cold `aidl check` ({name}): {cold:7.1f} M instructions, `import numpy` "
              f"{floor:6.1f} M: {cold / floor:.2f}x")


if __name__ == "__main__":
    main()
