"""Front-end speed: cold start, import times, parse throughput, and parse/check/interpret/solve
per KB and per structure.

Run:  .venv/bin/python benchmarks/compile/frontend.py  [--quick] [--repeat N]

Prints four tables (medians over ``--repeat`` runs; the machine is shared, so read medians, not
single runs):

(a) cold start: ``aidl check`` and ``aidl render`` of bundled examples, each a fresh process
    (wall time and CPU time of the child, from ``os.wait4``), and which heavy modules a cold
    ``aidl check`` imports (numpy, scipy, svgwrite, manifold3d).
(b) import time of single modules, each in a fresh interpreter.
(c) parse throughput on a generated program of about 50 KB (``benchmarks/solver/families.py``,
    ``hierarchy``): source text to the typed AST with spans, in MB/s (wall, and CPU: the
    least of the runs, which a loaded machine does not stretch), next to Lark's own LALR
    loop on the same text (``Lark.parse`` with the project's grammar, building a tree).
(d) the stages on generated hierarchical models of 10 to 500 structures: parse, check,
    interpret, solve (hierarchical), in ms, with ms per KB / per structure and the log-log
    growth exponent of each stage.

Children run with bytecode caching on (``PYTHONDONTWRITEBYTECODE`` removed, ``aidl_lang``
compiled first), as an installed package runs.  ``--instructions`` adds, for (a), the
instructions a cold ``aidl check`` executes, counted by ``valgrind --tool=callgrind`` (the same
count whatever else the machine is doing), next to the interpreter's and NumPy's own floor.
``--writers`` prints only (a3): the instructions of a cold ``aidl render`` to SVG and to DXF
side by side, and what importing svgwrite and ezdxf costs.
"""
from __future__ import annotations

import argparse
import math
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")     # as the aidl command (before NumPy loads)

HEAVY = ("numpy", "scipy", "scipy.sparse", "scipy.sparse.linalg", "scipy.linalg", "svgwrite",
         "manifold3d", "lark")


def _median(xs):
    return statistics.median(xs)


CHILD_ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
CHILD_ENV.setdefault("OPENBLAS_NUM_THREADS", "1")


def _compile_bytecode() -> None:
    """Write ``aidl_lang``'s bytecode, as installing the package does."""
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "aidl_lang")],
                   env=CHILD_ENV, stdout=subprocess.DEVNULL, check=False)


def _run_child(argv: list[str]) -> tuple[float, float, int]:
    """Wall seconds, CPU seconds (user + system) and exit status of one child process."""
    t0 = time.perf_counter()
    p = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                         env=CHILD_ENV)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - t0
    p.returncode = os.waitstatus_to_exitcode(status)
    return wall, ru.ru_utime + ru.ru_stime, p.returncode


def _aidl() -> list[str]:
    exe = pathlib.Path(sys.executable).with_name("aidl")
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "aidl_lang.cli"]


def cold_start(repeat: int, all_examples: bool) -> None:
    print("(a) cold start (fresh process each run; median of", repeat, "runs)")
    print(f"{'command':<44}{'wall ms':>9}{'cpu ms':>9}{'min wall':>10}  exit")
    aidl = _aidl()
    cases = [("check telephone.aidl", aidl + ["check", str(ROOT / "examples/telephone.aidl")])]
    names = sorted(p.stem for p in (ROOT / "examples").glob("*.aidl"))
    render = names if all_examples else ["telephone"]
    with tempfile.TemporaryDirectory() as tmp:
        for name in render:
            cases.append((f"render {name}.aidl",
                          aidl + ["render", str(ROOT / f"examples/{name}.aidl"), "-o",
                                  os.path.join(tmp, name + ".svg")]))
        cases.append(("python -c pass (interpreter floor)", [sys.executable, "-c", "pass"]))
        _run_child(cases[0][1])                   # warm the OS file cache and parse-table cache
        for label, argv in cases:
            runs = [_run_child(argv) for _ in range(repeat)]
            walls = [r[0] for r in runs]
            print(f"{label:<44}{_median(walls) * 1e3:>9.0f}{_median([r[1] for r in runs]) * 1e3:>9.0f}"
                  f"{min(walls) * 1e3:>10.0f}  {runs[-1][2]}")
    probe = ("import sys\nfrom aidl_lang.cli.main import main\n"
             "import contextlib, io\n"
             "with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):\n"
             f"    main(['check', {str(ROOT / 'examples/telephone.aidl')!r}])\n"
             f"print(' '.join(m for m in {HEAVY!r} if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         env=CHILD_ENV).stdout
    print("heavy modules imported by `aidl check telephone.aidl`:", out.strip() or "(none)")


def _instructions(argv: list[str]) -> float | None:
    """Millions of instructions one run of ``argv`` executes (callgrind), or None."""
    import re
    import shutil
    if shutil.which("valgrind") is None:
        return None
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *argv],
                       env=CHILD_ENV, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True)
    m = re.search(r"Collected : (\d+)", r.stderr)
    return int(m.group(1)) / 1e6 if m else None


def instruction_counts() -> None:
    print("\n(a2) instructions of one cold run (callgrind, millions; independent of load)")
    cases = [("python -c pass", [sys.executable, "-c", "pass"]),
             ("python -c 'import numpy'", [sys.executable, "-c", "import numpy"]),
             ("aidl check telephone.aidl",
              [sys.executable, "-m", "aidl_lang.cli", "check", str(ROOT / "examples/telephone.aidl")])]
    for label, argv in cases:
        n = _instructions(argv)
        print(f"  {label:<32}" + (f"{n:>10.1f}" if n is not None else "   (no valgrind)"))


def writer_costs(examples: list[str]) -> None:
    """(a3) a cold ``aidl render`` to SVG against the same render to DXF: callgrind
    instructions of each (one run: the count does not depend on load) and their ratio, next to
    the cost of importing each writer's library on top of NumPy (docs/outputs.md, "Speed")."""
    print("\n(a3) cold render, SVG against DXF (callgrind, millions of instructions)")
    print(f"{'example':<20}{'svg':>10}{'dxf':>10}{'dxf/svg':>9}")
    aidl = [sys.executable, "-m", "aidl_lang.cli"]
    with tempfile.TemporaryDirectory() as tmp:
        for name in examples:
            src = str(ROOT / f"examples/{name}.aidl")
            n = {ext: _instructions(aidl + ["render", src, "-o", os.path.join(tmp, name + ext)])
                 for ext in (".svg", ".dxf")}
            if None in n.values():
                print(f"{name:<20}   (no valgrind)")
                return
            print(f"{name:<20}{n['.svg']:>10.0f}{n['.dxf']:>10.0f}{n['.dxf'] / n['.svg']:>9.2f}")
    floor = _instructions([sys.executable, "-c", "import numpy"])
    for lib in ("svgwrite", "ezdxf"):
        n = _instructions([sys.executable, "-c", f"import numpy, {lib}"])
        print(f"  import {lib} (over numpy){n - floor:>12.0f}")


def import_times(repeat: int) -> None:
    print("\n(b) import time in a fresh interpreter (ms, median of", repeat, "runs)")
    mods = ["lark", "numpy", "scipy.sparse", "scipy.sparse.linalg", "svgwrite", "manifold3d",
            "aidl_lang.parser", "aidl_lang.pipeline", "aidl_lang.cli.main"]
    for m in mods:
        code = (f"import time; t = time.perf_counter(); import {m}; "
                "print(time.perf_counter() - t)")
        ts = []
        for _ in range(repeat):
            r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                               env=CHILD_ENV)
            if r.returncode:
                break
            ts.append(float(r.stdout))
        print(f"  {m:<24}" + (f"{_median(ts) * 1e3:>8.1f}" if ts else "     n/a"))


def _timed(fn, repeat: int):
    ts, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        ts.append(time.perf_counter() - t0)
    return _median(ts), out


def _cpu(fn) -> float:
    """The CPU seconds of one call of ``fn`` (the machine's load does not stretch them)."""
    t0 = time.process_time()
    fn()
    return time.process_time() - t0


def parse_throughput(repeat: int) -> None:
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang import parser as P
    from aidl_lang.parsing import lexing as LX, tables as T
    from aidl_lang.parser import mask_comments, parse
    from benchmarks.solver.families import hierarchy
    src = hierarchy(140, seed=3).source
    kb = len(src.encode()) / 1e3
    # Lark alone, building its own tree with positions (what the parser did before issue 12)
    from lark import Lark
    lp = Lark(P.GRAMMAR.read_text(), postlex=LX._PostLex(), propagate_positions=True,
              **T._LARK_OPTIONS)
    parse(src, "gen.aidl", DiagnosticSink())      # build the parser outside the timing
    t_ast, prog = _timed(lambda: parse(src, "gen.aidl", DiagnosticSink()), repeat)
    cpu_ast = min(_cpu(lambda: parse(src, "gen.aidl", DiagnosticSink())) for _ in range(repeat))
    masked = mask_comments(src)
    t_raw, _ = _timed(lambda: lp.parse(masked, start="start"), repeat)
    print(f"\n(c) parse throughput on a generated {kb:.1f} KB program "
          f"({len(prog.stmts)} top-level statement(s); median of {repeat})")
    print(f"  source -> typed AST with spans  {t_ast * 1e3:8.1f} ms  {kb / 1e3 / t_ast:6.2f} MB/s"
          f"  {t_ast * 1e3 / kb:6.2f} ms/KB")
    print(f"  the same, CPU (least of {repeat})   {cpu_ast * 1e3:8.1f} ms  {kb / 1e3 / cpu_ast:6.2f} MB/s"
          "  (what a quiet machine's wall time is)")
    print(f"  Lark.parse to a Tree, positions {t_raw * 1e3:8.1f} ms  {kb / 1e3 / t_raw:6.2f} MB/s")


def _slope(xs, ys) -> float:
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-9)) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return (sum((a - mx) * (b - my) for a, b in zip(lx, ly))
            / sum((a - mx) ** 2 for a in lx))


def stages(sizes, repeat: int) -> None:
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.interp import Interpreter
    from aidl_lang.parser import parse
    from aidl_lang.solver import solve
    from aidl_lang.typecheck import check
    from benchmarks.solver.families import hierarchy
    print(f"\n(d) stages on generated hierarchical models (ms, median of {repeat})")
    print(f"{'structs':>8}{'KB':>7}{'parse':>9}{'check':>9}{'interp':>9}{'build':>9}"
          f"{'solve':>9}{'ms/KB':>8}{'ms/struct':>10}  ok")
    rows = []
    for n in sizes:
        src = hierarchy(n, seed=3).source
        kb = len(src.encode()) / 1e3
        t_parse, prog = _timed(lambda: parse(src, "gen.aidl", DiagnosticSink()), repeat)
        t_check, _ = _timed(lambda: check(prog, DiagnosticSink()), repeat)

        def interp():
            sink = DiagnosticSink()
            return Interpreter(sink).run(prog), sink
        t_interp, (model, sink) = _timed(interp, repeat)
        assert not sink.has_errors, [d.message for d in sink.items[:3]]
        x0 = list(model.x)

        def go():
            model.x = list(x0)
            return solve(model, diagnose=False)
        t_solve, res = _timed(go, repeat)
        ns = len(model.structures)
        build = t_parse + t_check + t_interp
        rows.append((ns, kb, t_parse, t_check, t_interp, build, t_solve))
        print(f"{ns:>8}{kb:>7.1f}{t_parse * 1e3:>9.1f}{t_check * 1e3:>9.1f}{t_interp * 1e3:>9.1f}"
              f"{build * 1e3:>9.1f}{t_solve * 1e3:>9.1f}{build * 1e3 / kb:>8.2f}"
              f"{build * 1e3 / ns:>10.2f}  {res.converged}")
    if len(rows) > 1:
        xs = [r[0] for r in rows]
        print("growth exponent (log-log, time vs structures): "
              + ", ".join(f"{name} {_slope(xs, [r[i] for r in rows]):.2f}"
                          for i, name in ((2, "parse"), (3, "check"), (4, "interp"),
                                          (5, "build"), (6, "solve"))))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repeats and sizes (a smoke run)")
    ap.add_argument("--repeat", type=int, default=None, help="runs per measurement")
    ap.add_argument("--all-examples", action="store_true",
                    help="cold-render every bundled example, not only the telephone")
    ap.add_argument("--instructions", action="store_true",
                    help="also count a cold check's instructions with valgrind (slow: ~30 s)")
    ap.add_argument("--writers", action="store_true",
                    help="only (a3): a cold render to SVG against DXF, instructions by valgrind")
    args = ap.parse_args()
    rep = args.repeat or (3 if args.quick else 11)
    _compile_bytecode()
    if args.writers:
        writer_costs(["mounting_plate", "telephone"])
        return
    cold_start(rep, args.all_examples)
    if args.instructions:
        instruction_counts()
    import_times(max(3, rep // 2))
    parse_throughput(rep)
    stages([10, 50] if args.quick else [10, 50, 200, 500], max(3, rep // 3))


if __name__ == "__main__":
    main()
