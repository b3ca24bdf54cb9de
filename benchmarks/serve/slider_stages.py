"""What each stage after the interpreter costs in a slider move of the gear pair (issue 38):

    .venv/bin/python benchmarks/serve/slider_stages.py                 # CPU, best of 7 per stage
    .venv/bin/python benchmarks/serve/slider_stages.py --callgrind     # + instructions per stage
    .venv/bin/python benchmarks/serve/slider_stages.py --tree OLD      # another tree (its .venv)

A warm process loads ``examples/gear_pair.aidl`` in a :class:`~aidl_lang.serve.session.Session`
and makes one move (``pinion_teeth`` = 13), then times each stage of that move on its own, in
the order a move runs them: ``solver`` (the :class:`~aidl_lang.solver.Solver`'s set-up: the
rows, the pinned geometry and its values; Newton itself is a few ms), ``render`` (the booleans, :func:`render_model`), ``chords`` (the grids of the
booleans' chords and of their segments' exact ends, which the exact outlines match the
result's edges and vertices against, built once per move, on the first ``build``), ``build``
(the exact outlines put back on the curves, :func:`aidl_lang.output.part.part.build`, the chord
grids already built), ``svg`` (the
writer on that output), ``check`` (:func:`check_drawing`, what ``update_checks`` runs
after the picture), ``topology`` (the rest of ``update_checks``: the drawing's
:func:`~aidl_lang.output.checks.topology` for W0510) and ``picture`` (what a move does after
the solve, as one: :func:`~aidl_lang.pipeline.after_solve` with the compile's deadline, as
``Session.set_params`` calls it, then the SVG of its drawing, every arc made afresh).  With ``--callgrind`` each stage also runs three times in a process under
``valgrind --tool=callgrind --instr-atstart=no`` that switches the instrumentation on around
those runs only (``callgrind_control -i``), so the count is the stage's alone, per run:
the machine's load does not change it (a minute or more per stage under valgrind).
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
STAGES = ("solver", "render", "chords", "build", "svg", "check", "topology", "picture")

CHILD = r"""
import os, subprocess, sys, time
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.interp import Interpreter
from aidl_lang.base.limits import DEFAULT_BUDGET
from aidl_lang.output import to_svg
from aidl_lang.output.part.build.booleans import render_model
from aidl_lang.output.checks import check_drawing, topology
from aidl_lang.output.part.part import build
from aidl_lang.base.limits import Deadline
from aidl_lang.pipeline import after_solve
from aidl_lang.serve.session import Session
from aidl_lang.solver import Solver, run
path, stage, runs, mode = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
s = Session(path)
s.load()
s.set_params({"pinion_teeth": "13"})
s.update_checks()
sink = DiagnosticSink()
sink.sources.update(s.sources)
model = Interpreter(sink, {"pinion_teeth": "13"}, budget=DEFAULT_BUDGET.scaled(100)).run(s.program)
run(Solver(model))
drawing = render_model(model)
out = build(drawing, "drive")
fn = {"solver": lambda: Solver(model), "render": lambda: render_model(model),
      "chords": lambda: (setattr(drawing.exact, "_index", None), drawing.exact._chords(),
                         setattr(drawing.exact, "_eg", None), drawing.exact._ends_grid()),
      "build": lambda: build(drawing, "drive"), "svg": lambda: to_svg(out, title="drive"),
      "check": lambda: check_drawing(drawing, DiagnosticSink()),
      "topology": lambda: topology(drawing),
      "picture": lambda: to_svg(after_solve(DiagnosticSink(), model, shape_checks=False,
                                            deadline=Deadline(time.monotonic() + 600,
                                                              DEFAULT_BUDGET.scaled(100))),
                                title="drive")}[stage]
fn()
if mode == "cpu":
    best = min((lambda t: (fn(), time.process_time() - t)[1])(time.process_time())
               for _ in range(runs))
    print(f"{1000 * best:.1f}")
else:
    def ctl(x):
        subprocess.run(["callgrind_control", "-i", x, str(os.getpid())],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    ctl("on")
    for _ in range(runs):
        fn()
    ctl("off")
"""


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--tree", type=Path, default=ROOT, help="the tree to measure (its .venv)")
    ap.add_argument("--callgrind", action="store_true", help="also count instructions")
    ap.add_argument("--only", default=",".join(STAGES), help="comma-separated stages")
    a = ap.parse_args()
    tree = a.tree.resolve()
    py = tree / ".venv" / "bin" / "python"
    python = str(py) if py.exists() else sys.executable
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH",)}
    env.update(OPENBLAS_NUM_THREADS="1", PYTHONHASHSEED="0")
    gear = str(tree / "examples" / "gear_pair.aidl")
    print(f"tree: {tree}")
    for stage in a.only.split(","):
        r = subprocess.run([python, "-c", CHILD, gear, stage, "7", "cpu"], capture_output=True,
                           text=True, env=env, cwd=str(tree))
        line = f"{stage:<8} {r.stdout.strip() or r.stderr.strip()[-200:]} ms CPU (best of 7)"
        if a.callgrind:
            g = subprocess.run(["valgrind", "--tool=callgrind", "--instr-atstart=no",
                                "--callgrind-out-file=/dev/null", python, "-c", CHILD, gear,
                                stage, "3", "callgrind"], capture_output=True, text=True,
                               env=env, cwd=str(tree))
            m = re.search(r"Collected : (\d+)", g.stderr)
            line += f", {int(m.group(1)) / 3e6:.1f} M instructions" if m else ", no count"
        print(line, flush=True)


if __name__ == "__main__":
    main()
