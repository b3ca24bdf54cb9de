"""A compile's figures side by side with an older tree (issue 38; paired runs, CPU time and callgrind):

    .venv/bin/python benchmarks/compile/compare_trees.py /work/old-75922ec           # every figure
    .venv/bin/python benchmarks/compile/compare_trees.py OLD --only plate400,telephone --rounds 7
    .venv/bin/python benchmarks/compile/compare_trees.py OLD --big                   # + 10,000 structures

Each tree runs its own interpreter: ``TREE/.venv/bin/python`` when there is one (an editable
install of that tree), else this interpreter with ``PYTHONPATH=TREE``.  Runs alternate between
the two trees (new, old, new, old, ...), each a fresh process, from a scratch folder; CPU is
the child's user + system time (``os.wait4``), memory its peak RSS; the median of
``--rounds`` is printed.  Instructions are counted by ``valgrind --tool=callgrind`` (one run
each, ``PYTHONHASHSEED=0``; the machine's load does not change them; ``--no-callgrind`` skips
them).  Bytecode is compiled first and kept, as an installed package runs.  The cold checks
run with ``--budget 100``: under callgrind the default 15 s of wall time runs out (E0304) and
the count would stop early; the budget does not change the work of a check that fits.

The figures (issue 38):

* ``numpy``: ``python -c "import numpy"``, the floor the cold checks are compared with;
* ``plate400``: cold ``aidl check`` of a plate with one hole structure of 400 circles;
* ``telephone``: cold ``aidl check examples/telephone.aidl``;
* ``structures1000`` (and ``structures10000`` with ``--big``): ``aidl check`` of an assembly
  of N solids (a Rectangle with a round hole each), CPU, peak RSS and the freedom count;
* ``slider``: in one process, ``compile_source`` of ``examples/gear_pair.aidl`` plain and with
  ``--set``-style overrides (a slider move; what the CLI pays), and the server's move (the
  defaults' topology kept, :class:`aidl_lang.serve.session.Session` when the tree has it;
  a tree without it says so, and its move is the override compile); plus the solve's unknowns
  and equations and, unless ``--no-callgrind``, the instructions of one server move (a
  process with three moves less one with one, halved; budget 100).  A tree that cannot
  compile the gear pair (75922ec has no ``std/gears.aidl``) prints the first diagnostic;
  ``slider-gear`` is the same figure for ``examples/gear.aidl`` (each tree's own copy), which
  every tree since 75922ec reads;
* ``holes900`` / ``holes5000``: :func:`check_drawing` of a plate with N hole structures on a
  6 mm grid (``benchmarks/checks/checks_scaling.py``), CPU in one process after the compile;
* ``diagnose1000``: in one process after the compile of the 1,000 plates, the CPU of the
  first freedom count (``degrees_of_freedom(floating=False)``, as ``aidl check`` makes it),
  the redundancy search without a time bound and the sliding analysis; one line per round;
* ``flood``: ``aidl check`` of 3,000 calls of an unknown function (3,000 E0103): CPU and the
  number of lines printed;
* ``nest``: ``aidl render --layout sheet`` of ``examples/laser_box.aidl`` to SVG.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
from benchmarks.checks.checks_scaling import plate  # noqa: E402

ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPATH")}
ENV.update(OPENBLAS_NUM_THREADS="1", PYTHONHASHSEED="0")


def one_hole_plate(n: int, pitch: float = 6.0, r: float = 2.0) -> str:
    """A plate with one hole structure holding ``n`` circles on a square grid."""
    cols = math.ceil(math.sqrt(n))
    rows = math.ceil(n / cols)
    w, h = cols * pitch, rows * pitch
    return f"""solid plate {{
    body = Rectangle(center=({w / 2}, {h / 2}), width={w}, height={h})
    hole holes {{
        for i in range({n}) {{
            c = Circle(center=((i % {cols}) * {pitch} + {pitch / 2}, (i // {cols}) * {pitch} + {pitch / 2}), radius={r})
        }}
    }}
}}
"""


def structures(n: int) -> str:
    """An assembly of ``n`` solids, each a Rectangle with a round hole."""
    return ("assembly a {\n  for i in range(%d) {\n    solid s {\n"
            "      r = Rectangle(center=(i * 12, 0), width=10, height=6)\n"
            "      hole h { c = Circle(center=(i * 12, 0), radius=1.5) }\n    }\n  }\n}\n" % n)


def flood(n: int = 3000) -> str:
    return "solid s {\n  c = Circle(center=(0, 0), radius=5)\n" + "".join(
        f"  x{i} = Bogus(1)\n" for i in range(n)) + "}\n"


SLIDER = r"""
import json, sys, time
from aidl_lang.pipeline import compile_source
path, name = sys.argv[1], sys.argv[2]
src = open(path).read()
ov = {name: "14"}
out = {}
c = compile_source(src, path)                              # imports, caches
if not c.ok:                                               # a tree that cannot read the program
    d = c.sink.items[0]
    out["error"] = f"{getattr(d, 'code', '')} {d.message}"[:100]
    print(json.dumps(out))
    sys.exit(0)
def cpu(fn, k=3):
    best = 1e9
    for _ in range(k):
        t = time.process_time(); r = fn(); best = min(best, time.process_time() - t)
    return best, r
plain, c = cpu(lambda: compile_source(src, path))
over, _ = cpu(lambda: compile_source(src, path, overrides=ov))
out.update({"plain_ms": 1000 * plain, "override_ms": 1000 * over,
            "unknowns": getattr(c.solve, "n_unknowns", None),
            "equations": getattr(c.solve, "n_equations", None)})
try:
    from aidl_lang.serve.session import Session
except ImportError as ex:     # an older tree without the session API: the override compile is its move
    out["server_ms"] = None
    out["server_error"] = "no session API (aidl_lang.serve.session): its move is the override compile"
else:
    s = Session(path)
    s.load()
    k = [0]
    def move():          # a slider move: the picture, then its checks (W0510 included)
        k[0] += 1
        v = s.set_params({name: str(13 + k[0] % 2)})
        s.update_checks()
        return v
    move()
    out["server_ms"] = 1000 * cpu(move)[0]
print(json.dumps(out))
"""

DIAGNOSE = r"""
import json, sys, time
from aidl_lang.base.limits import DEFAULT_BUDGET
from aidl_lang.pipeline import compile_source
import scipy.sparse                      # imported by the check anyway: not counted below
c = compile_source(open(sys.argv[1]).read(), "s1000.aidl", budget=DEFAULT_BUDGET.scaled(100))
assert c.ok, [d.message for d in c.sink.items]
from aidl_lang.solver.diagnosis import diagnose as D
try:                                     # split out of diagnose.py (issue 63)
    from aidl_lang.solver.diagnosis import freedom as F, redundancy as R, sliding as S
except ImportError:                      # an older tree: all in diagnose.py
    F = R = S = D
def cpu(fn):
    t = time.process_time(); fn(); return 1000 * (time.process_time() - t)
out = {"dof_ms": cpu(lambda: F.degrees_of_freedom(c.solve.solver, floating=False))}
out["redundancy_ms"] = cpu(lambda: R.redundancies(c.solve.solver))
if hasattr(S, "sliding"):
    out["sliding_ms"] = cpu(lambda: S.sliding(c.solve.solver))
print(json.dumps(out))
"""

HOLES = r"""
import json, sys, time
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.output.checks import check_drawing
from aidl_lang.base.limits import DEFAULT_BUDGET
from aidl_lang.pipeline import compile_source
c = compile_source(open(sys.argv[1]).read(), "grid.aidl", min_wall=0,
                   budget=DEFAULT_BUDGET.scaled(100))      # no E0304 on a loaded machine
assert c.ok, [d.message for d in c.sink.items]
t = time.process_time()
sink = DiagnosticSink()
check_drawing(c.drawing, sink)
print(json.dumps({"checks_ms": 1000 * (time.process_time() - t), "warnings": len(sink.items)}))
"""


class Tree:
    def __init__(self, path: Path):
        self.path = path.resolve()
        venv = self.path / ".venv" / "bin" / "python"
        self.python = str(venv) if venv.exists() else sys.executable
        self.env = dict(ENV)
        if not venv.exists():
            self.env["PYTHONPATH"] = str(self.path)
        subprocess.run([self.python, "-m", "compileall", "-q", str(self.path / "aidl_lang")],
                       env=self.env, stdout=subprocess.DEVNULL, check=False)

    def aidl(self, *args: str) -> list[str]:
        return [self.python, "-m", "aidl_lang.cli", *args]


def run(argv: list[str], env: dict, cwd: str) -> dict:
    """One child: its CPU seconds, peak RSS (MiB), exit status and stdout."""
    with tempfile.TemporaryFile("w+") as out:
        p = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT, env=env, cwd=cwd, text=True)
        _, status, ru = os.wait4(p.pid, 0)
        out.seek(0)
        text = out.read()
    return {"cpu": ru.ru_utime + ru.ru_stime, "rss": ru.ru_maxrss / 1024,
            "exit": os.waitstatus_to_exitcode(status), "out": text}


def instructions(argv: list[str], env: dict, cwd: str) -> float:
    """Instructions (millions) of one run under callgrind."""
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *argv],
                       capture_output=True, text=True, env=env, cwd=cwd)
    m = re.search(r"Collected : (\d+)", r.stderr)
    return int(m.group(1)) / 1e6 if m else float("nan")


MOVES = r"""
import sys
from aidl_lang.pipeline import compile_source
path, moves = sys.argv[1], int(sys.argv[2])
try:
    from aidl_lang.serve.session import Session
except ImportError:          # no session API: a move is the override compile
    src = open(path).read()
    for k in range(moves):
        compile_source(src, path, overrides={"pinion_teeth": str(13 + k % 2)})
else:
    import aidl_lang.serve.session as S
    from aidl_lang.base.limits import DEFAULT_BUDGET
    if hasattr(S, "Interpreter"):    # a budget of 100: no deadline cuts a move short under callgrind
        _I = S.Interpreter
        S.Interpreter = lambda *a, **k: _I(*a, budget=DEFAULT_BUDGET.scaled(100), **k)
    s = Session(path)
    s.load()
    for k in range(moves):
        s.set_params({"pinion_teeth": str(13 + k % 2)})
        s.update_checks()
"""


def _move_instructions(t, path: str, cwd: str) -> float:
    """Instructions (millions) of one slider move: a process with three moves less one with
    one, halved (imports, the load and the first move cancel)."""
    one = instructions([t.python, "-c", MOVES, path, "1"], t.env, cwd)
    three = instructions([t.python, "-c", MOVES, path, "3"], t.env, cwd)
    return (three - one) / 2


def paired(trees, make, rounds, cwd):
    """``rounds`` alternating runs of ``make(tree)`` in each tree: per tree a list of runs."""
    res = {t: [] for t in trees}
    for _ in range(rounds):
        for t in trees:
            res[t].append(run(make(t), t.env, cwd))
    return res


def med(runs, key):
    return statistics.median(r[key] for r in runs)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("old", type=Path, help="the older tree (a checkout of e.g. 75922ec)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--only", default="", help="comma-separated figure names")
    ap.add_argument("--no-callgrind", action="store_true")
    ap.add_argument("--big", action="store_true", help="also 10,000 structures (minutes, GiB)")
    a = ap.parse_args()
    new, old = Tree(ROOT), Tree(a.old)
    trees = (new, old)
    only = set(a.only.split(",")) if a.only else None
    want = lambda name: only is None or name in only  # noqa: E731
    tmp = tempfile.mkdtemp(prefix="compare-trees-")
    files = {"plate400": one_hole_plate(400), "s1000": structures(1000),
             "s10000": structures(10000), "flood": flood(), "holes900": plate(900),
             "holes5000": plate(5000)}
    for k, v in files.items():
        Path(tmp, f"{k}.aidl").write_text(v)
    tel = str(ROOT / "examples" / "telephone.aidl")
    gear = str(ROOT / "examples" / "gear_pair.aidl")
    box = str(ROOT / "examples" / "laser_box.aidl")
    print(f"new: {new.path}\nold: {old.path}\nmedian of {a.rounds} paired runs; "
          "instructions: one callgrind run (M)\n")
    row = "{:<16}{:<5}{:>9}{:>9}{:>10}{:>16}  {}"
    print(row.format("figure", "tree", "cpu ms", "rss MiB", "instr M", "x numpy", "note"))
    floor = {}

    def cold(name, argv_of, note_of=lambda r: ""):
        runs = paired(trees, argv_of, a.rounds, tmp)
        for t, tag in ((new, "new"), (old, "old")):
            ir = float("nan") if a.no_callgrind else instructions(argv_of(t), t.env, tmp)
            cpu = 1000 * med(runs[t], "cpu")
            if name == "numpy":
                floor[t] = (cpu, ir)
            x = ""
            if t in floor and name != "numpy":
                x = f"{cpu / floor[t][0]:.2f}c"
                if not math.isnan(ir):
                    x = f"{ir / floor[t][1]:.2f}i {x}"
            print(row.format(name, tag, f"{cpu:.0f}", f"{med(runs[t], 'rss'):.0f}",
                             f"{ir:.1f}", x, note_of(runs[t][-1])), flush=True)

    last = lambda r: (r["out"].strip().splitlines() or [""])[-1][:70]  # noqa: E731
    if want("numpy") or want("plate400") or want("telephone"):
        cold("numpy", lambda t: [t.python, "-c", "import numpy"])
    if want("plate400"):
        cold("plate400", lambda t: t.aidl("check", "--budget", "100", f"{tmp}/plate400.aidl"), last)
    if want("telephone"):
        cold("telephone", lambda t: t.aidl("check", "--budget", "100", tel), last)
    for n in (1000, 10000):
        if want(f"structures{n}") and (n == 1000 or a.big):
            a_rounds, a.rounds = a.rounds, (a.rounds if n == 1000 else 1)
            nc, a.no_callgrind = a.no_callgrind, True
            cold(f"structures{n}", lambda t: t.aidl("check", "--budget", "100", f"{tmp}/s{n}.aidl"),
                 last)
            a.rounds, a.no_callgrind = a_rounds, nc
    if want("diagnose1000"):
        for _ in range(a.rounds):
            for t, tag in ((new, "new"), (old, "old")):
                r = run([t.python, "-c", DIAGNOSE, f"{tmp}/s1000.aidl"], t.env, tmp)
                try:
                    note = ", ".join(f"{k[:-3]} {v:.0f} ms" for k, v in
                                     json.loads(r["out"].strip().splitlines()[-1]).items())
                except (ValueError, IndexError):
                    note = r["out"].strip()[-70:]
                print(row.format("diagnose1000", tag, "", "", "", "", note), flush=True)
    if want("flood"):
        nc, a.no_callgrind = a.no_callgrind, True
        cold("flood", lambda t: t.aidl("check", f"{tmp}/flood.aidl"),
             lambda r: f"{len(r['out'].splitlines())} lines; {last(r)}")
        a.no_callgrind = nc
    if want("nest"):
        nc, a.no_callgrind = a.no_callgrind, True
        cold("nest", lambda t: t.aidl("render", box, "--layout", "sheet", "-o", f"{tmp}/sheet-{id(t)}.svg"),
             last)
        a.no_callgrind = nc
    if want("slider"):
        # the gear pair (std/gears.aidl), and the older example every tree has (examples/gear.aidl,
        # each tree's own copy) so that a tree which cannot read the gear pair still compares
        progs = [("slider", lambda t: gear), ("slider-gear", lambda t: str(t.path / "examples" / "gear.aidl"))]
        for fig, prog in progs:
            for t, tag in ((new, "new"), (old, "old")):
                argv = [t.python, "-c", SLIDER, prog(t), "pinion_teeth"]
                r = run(argv, t.env, tmp)
                try:
                    j = json.loads(r["out"].strip().splitlines()[-1])
                except (ValueError, IndexError):
                    print(f"{fig:<16}{tag:<5} failed: {r['out'][-300:]}")
                    continue
                if "error" in j:
                    print(f"{fig:<16}{tag:<5} cannot compile {Path(prog(t)).name}: {j['error']}")
                    continue
                if j["server_ms"] is None:
                    srv = f"- ({j['server_error']})"
                else:
                    srv = f"{j['server_ms']:.0f} ms"
                ins = ""
                if not a.no_callgrind:     # per move: (three moves - one move) / 2, as docs/dev/performance.md
                    ins = f"; {_move_instructions(t, prog(t), tmp):.0f} M instructions per move"
                print(f"{fig:<16}{tag:<5} plain {j['plain_ms']:.0f} ms, override "
                      f"{j['override_ms']:.0f} ms ({j['override_ms'] / j['plain_ms']:.2f}x), "
                      f"server move {srv} (CPU, best of 3); {j['unknowns']} unknowns, "
                      f"{j['equations']} equations{ins}", flush=True)
    for n in (900, 5000):
        if want(f"holes{n}"):
            for t, tag in ((new, "new"), (old, "old")):
                r = run([t.python, "-c", HOLES, f"{tmp}/holes{n}.aidl"], t.env, tmp)
                try:
                    j = json.loads(r["out"].strip().splitlines()[-1])
                except (ValueError, IndexError):
                    print(f"holes{n} {tag}: {r['out'][-300:]}")
                    continue
                print(f"holes{n:<11}{tag:<5} check_drawing {j['checks_ms']:.0f} ms CPU, "
                      f"{j['warnings']} warnings", flush=True)


if __name__ == "__main__":
    main()
