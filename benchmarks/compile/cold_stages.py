"""Where a cold ``aidl check`` spends its instructions, stage by stage (callgrind):

    .venv/bin/python benchmarks/compile/cold_stages.py                       # examples/telephone.aidl
    .venv/bin/python benchmarks/compile/cold_stages.py examples/gear.aidl
    .venv/bin/python benchmarks/compile/cold_stages.py --families          # + each family of checks
    .venv/bin/python benchmarks/compile/cold_stages.py --tree /tmp/old     # another tree beside it

Each stage is one fresh process under ``valgrind --tool=callgrind`` that runs the check up to
that stage and ends with ``os._exit`` (no interpreter teardown, as the ``aidl`` command ends);
a stage's cost is the difference from the one before.  The stages: Python with NumPy,
Manifold and the standard-library modules a check imports; the check's own modules; the
parse; the name check; the interpretation; the solve; the extent, assertion and branch checks
and the booleans (``after_solve`` without the shape checks); the shape checks; and the whole
``aidl check`` command (the freedom count, the redundancy search, the argument parsing and
the printing).  ``PYTHONHASHSEED=0``, one BLAS thread, bytecode compiled first, run from an
empty folder, as ``benchmarks/compile/compare_trees.py``; the counts repeat to 0.1 M.  The issue-38 note in
docs/dev/performance.md quotes them.

``--families`` adds the shape checks family by family (:data:`aidl_lang.output.checks.FAMILIES`):
the stage run with that one family only, less the stage run with none (what every family
shares, W0524 and the notes, is in "none"); ``--tree DIR`` runs the same stages with
``PYTHONPATH=DIR`` (this interpreter, DIR's sources, its bytecode compiled first) in a
column beside this tree's (issue 95: the counts of two trees side by side in one run).
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

STAGES = ["python, numpy, manifold3d, stdlib", "aidl_lang modules", "parse", "name check",
          "interpret", "solve", "extent, branches, booleans", "shape checks",
          "freedom count, redundancy, CLI"]

_RUN = r'''
import os, sys, time, warnings
S, F = int(sys.argv[1]), sys.argv[2]
if S == 0:
    import numpy, manifold3d, argparse, json, dataclasses, threading, gettext, copy, zlib
    os._exit(0)
import aidl_lang.cli.main, aidl_lang.api, aidl_lang.pipeline, aidl_lang.solver.diagnosis.diagnose
import aidl_lang.solver.diagnosis.freedom, aidl_lang.solver.diagnosis.redundancy, aidl_lang.solver.diagnosis.sliding
import aidl_lang.output.checks
if S == 8:
    from aidl_lang.cli.main import main
    main(["check", "--budget", "100", F])
    sys.stdout.flush()
    os._exit(0)
import numpy as np
from aidl_lang.pipeline import parse, check, Interpreter, solve, after_solve, DiagnosticSink
ONLY = os.environ.get("AIDL_ONLY_FAMILY")
if ONLY is not None:                     # --families: run one family of shape checks (or none)
    import aidl_lang.output.checks as C
    every = C._Shares.run
    C._Shares.run = lambda self, family, part, fn: (every(self, family, part, fn)
                                                    if family == ONLY else None)
from aidl_lang.base.limits import DEFAULT_BUDGET
sys.setrecursionlimit(20000)
sink = DiagnosticSink()
if S >= 2:
    prog = parse(open(F, encoding="utf-8").read(), F, sink)
if S >= 3:
    check(prog, sink)
if S >= 4:
    b = DEFAULT_BUDGET.scaled(100)
    model = Interpreter(sink, None, b, time.monotonic() + b.seconds).run(prog)
if S >= 5:
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        solve(model, deadline=time.monotonic() + 100)
if S >= 6:
    after_solve(sink, model, shape_checks=S >= 7)
os._exit(0)
'''


ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPATH")}
ENV.update(OPENBLAS_NUM_THREADS="1", PYTHONHASHSEED="0")


def callgrind(*args: str, tree: str | None = None, family: str | None = None) -> float:
    """Instructions (millions) of ``python ARGS`` under callgrind, run from an empty folder
    (``python -c`` searches the current folder first: a crowded one costs millions);
    ``tree``: with ``PYTHONPATH=tree``; ``family``: only that family of shape checks runs."""
    env = dict(ENV, **({"PYTHONPATH": tree} if tree else {}),
               **({"AIDL_ONLY_FAMILY": family} if family is not None else {}))
    with tempfile.TemporaryDirectory() as empty:
        r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                            sys.executable, *args], capture_output=True, text=True, env=env,
                           cwd=empty)
    m = re.search(r"Collected : (\d+)", r.stderr)
    return int(m.group(1)) / 1e6 if m else float("nan")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file", nargs="?", default=str(ROOT / "examples" / "telephone.aidl"))
    ap.add_argument("--tree", help="another tree, measured beside this one (PYTHONPATH=TREE)")
    ap.add_argument("--families", action="store_true",
                    help="also the shape checks family by family")
    args = ap.parse_args()
    path = str(Path(args.file).resolve())
    trees = [None] + ([str(Path(args.tree).resolve())] if args.tree else [])
    for t in trees:
        subprocess.run([sys.executable, "-m", "compileall", "-q", str(Path(t or ROOT) / "aidl_lang")],
                       stdout=subprocess.DEVNULL, env=ENV, check=False)
    floor = callgrind("-c", "import numpy")
    print(f"{path}\n`python -c \"import numpy\"`: {floor:.1f} M\n")
    names = ["this tree"] + ([args.tree] if args.tree else [])
    print(f"{'stage':<36}" + "".join(f"{'instr M':>10}{'total M':>10}{'x numpy':>9}"
                                     for _ in trees) + "   (" + ", ".join(names) + ")")
    before = [0.0] * len(trees)
    for i, name in enumerate(STAGES):
        row = f"{name:<36}"
        for k, t in enumerate(trees):
            total = callgrind("-c", _RUN, str(i), path, tree=t)
            row += f"{total - before[k]:>10.1f}{total:>10.1f}{total / floor:>9.2f}"
            before[k] = total
        print(row, flush=True)
    if args.families:
        from aidl_lang.output.checks import FAMILIES
        print("\nthe shape checks by family (instructions M over the stage with none of them)")
        none = [callgrind("-c", _RUN, "7", path, tree=t, family="") for t in trees]
        print(f"{'none (W0524, notes)':<36}" + "".join(f"{n:>10.1f}" for n in none))
        for fam in FAMILIES:
            got = [callgrind("-c", _RUN, "7", path, tree=t, family=fam) for t in trees]
            print(f"{fam:<36}" + "".join(f"{g - n:>10.1f}" for g, n in zip(got, none)), flush=True)


if __name__ == "__main__":
    main()
