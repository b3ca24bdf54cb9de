"""Solver scaling: AIDL's solver against SolveSpace, and hierarchical against flat.

Run:  .venv/bin/pip install -e ".[bench]"   (SolveSpace's ``slvs`` from PyPI)
      python3.12 -m venv .venv312 && .venv312/bin/pip install planegcs   (optional peer)
      .venv/bin/python benchmarks/solver/solver_scaling.py  [--quick] [--no-planegcs]
      .venv/bin/python benchmarks/solver/solver_scaling.py --phases [--repeat N]   (part (e) only)

Prints one table in five parts:

(a) flat sketch families (``benchmarks/solver/families.py``: a chain of rectangles, independent
    rectangles ("islands"), points on a ring with equal chords, a linkage with lengths and
    angles) from 8 to 2000 parameters, each started 10% off a known solution and checked
    against it (max point error, mm).  Columns: the build (ours: source text to a model; the
    peers: the sketch made through their API); the cold solve (ours: building rows,
    compiling, substituting, Newton; ``ref``: :func:`reference_newton`, a 20-line minimum-norm
    Newton with ``splu`` on our rows, its tape compile included; SolveSpace ``slvs`` from
    PyPI and FreeCAD's PlaneGCS ``planegcs`` from PyPI: solve only); the warm re-solve from
    the same start with the compiled system kept (what an edit costs; PlaneGCS keeps its
    sketch, SolveSpace keeps nothing so its cold time stands); ratios peer/ours.  PlaneGCS
    needs Python >= 3.12, so it runs in a subprocess (``benchmarks/solver/peer_planegcs.py``) under
    ``AIDL_PLANEGCS_PYTHON`` or ``.venv312/bin/python``; without it its columns are empty, and
    beyond 800 parameters too (its dense solve takes minutes at 2,000).
(b) generated hierarchical models with 10 to 500 structures: hierarchical solve against a flat
    solve of the same model, with the log-log growth exponent.
(c) every bundled example: the solve time.
(d) the fixed overhead of a small solve (two points, one distance).
(e) where the hierarchical solve of the generated models goes (issue 12 target 3: the
    500-structure model under 300 ms): building the rows (bounding boxes expanded), the one
    compile of the whole model, and the attempts (cutting each attempt's tape, substitution,
    Newton), CPU time (``time.process_time``, median of ``--repeat``), with the tape's size.

Times are the best of several runs (fewer for slow cases), in milliseconds, on this machine.
"""
from __future__ import annotations

import argparse
import math
import os
import pathlib
import sys
import time

# one BLAS thread, as the `aidl` command sets (aidl_lang/cli/__init__.py): threaded OpenBLAS
# spins on the ~100 x 100 dense Newton steps (a 400-unknown warm re-solve: 12 ms, not 0.6 ms)
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.pipeline import compile_source  # noqa: E402
from aidl_lang.solver import Solver, run, solve  # noqa: E402
from aidl_lang.solver.core.tape import Tape  # noqa: E402
from benchmarks.solver.families import FLAT, hierarchy  # noqa: E402


def best_of(fn, reps: int):
    best = math.inf
    out = None
    for _ in range(reps):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best * 1e3, out


def _model(source: str, path: str = "bench.aidl"):
    c = compile_source(source, path, do_solve=False)
    if not c.ok:
        raise SystemExit("benchmark source does not compile: "
                         + "; ".join(d.message for d in c.sink.items[:3]))
    return c.model


def _point_error(model, solution) -> float:
    pts = {g.name: g.points["p"] for g in model.all_geometry() if g.kind == "Point"}
    err = 0.0
    for k, (x, y) in solution.items():
        p = pts[k]
        err = max(err, math.hypot(model.x[p.ix] - x, model.x[p.iy] - y))
    return err


def reference_newton(exprs, n_params: int, x: np.ndarray, cols: np.ndarray,
                     tol: float = 1e-10, max_iter: int = 50):
    """The 20-line reference: plain minimum-norm Newton, ``dx = -J^T (J J^T)^-1 F`` through
    ``splu``, on our compiled tape of every row (no substitution, no damping, no hierarchy).
    Returns ``(x, converged, steps)``."""
    import scipy.sparse as sp
    from scipy.sparse.linalg import splu
    tape = Tape(exprs, n_params)
    x = x.copy()
    for it in range(max_iter):
        F = tape.evaluate(x)
        if float(np.max(np.abs(F))) <= tol:
            return x, True, it
        J = tape.jacobian(x, cols)
        G = (J @ J.T + 1e-12 * sp.identity(J.shape[0], format="csr")).tocsc()
        x[cols] -= J.T @ splu(G).solve(F)
    return x, False, max_iter


PGCS_MAX = 800      # PlaneGCS is timed up to this many parameters


def planegcs_python() -> str | None:
    """The Python that runs ``benchmarks/solver/peer_planegcs.py`` (``AIDL_PLANEGCS_PYTHON``, else
    the repository's ``.venv312``), or None when it has no ``planegcs``."""
    import subprocess
    py = os.environ.get("AIDL_PLANEGCS_PYTHON") or str(ROOT / ".venv312/bin/python")
    try:
        ok = subprocess.run([py, "-c", "import planegcs"], capture_output=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return py if ok.returncode == 0 else None


def planegcs_times(py: str | None, cases: list) -> list:
    """PlaneGCS's build, cold and warm times for ``cases`` ((Case, reps)), in one subprocess."""
    import json
    import subprocess
    if py is None:
        return [None] * len(cases)
    # PlaneGCS factorises densely (its solve grows ~n^3: 2,000 parameters take minutes), so
    # it is run up to PGCS_MAX parameters, once per case above 200
    todo = [i for i, (c, _) in enumerate(cases) if c.n_params <= PGCS_MAX]
    data = [{"spec": cases[i][0].spec, "solution": cases[i][0].solution,
             "reps": cases[i][1] if cases[i][0].n_params <= 200 else 1} for i in todo]
    try:
        out = subprocess.run([py, str(ROOT / "benchmarks/solver/peer_planegcs.py")],
                             input=json.dumps(data), capture_output=True, text=True, timeout=900)
    except subprocess.TimeoutExpired:
        print("planegcs peer: out of time (900 s)")
        return [None] * len(cases)
    if out.returncode != 0:
        print("planegcs peer failed:", out.stderr.strip().splitlines()[-1:])
        return [None] * len(cases)
    res = [None] * len(cases)
    for i, r in zip(todo, json.loads(out.stdout)):
        res[i] = r if "error" not in r else None
    return res


def flat_rows(sizes, have_slvs: bool, pgcs: str | None = None):
    rows = []
    cases = []
    for name, make in FLAT.items():
        for n in sizes:
            case = make(n, seed=7)
            reps = 5 if n <= 200 else 3
            cases.append((case, reps))
            t_build, base = best_of(lambda: _model(case.source), 1 if n > 200 else 3)
            x0 = list(base.x)

            def first():
                base.x = list(x0)
                s = Solver(base)
                return s, run(s)
            t_first, (solver, res) = best_of(first, reps)
            err = _point_error(base, case.solution)

            def again():
                solver.x[:solver.n_model] = x0
                return run(solver)
            t_again, res2 = best_of(again, reps)
            # the reference, from the same start on the same rows (built outside the timing)
            xr = solver.x.copy()
            xr[:solver.n_model] = x0
            xr[solver.n_model:] = 0.0
            cols = np.flatnonzero(solver.free)
            t_ref, (_, ref_ok, _) = best_of(
                lambda: reference_newton(solver.rows.exprs, solver.rows.n_params, xr, cols), reps)
            t_slvs = e_slvs = b_slvs = None
            if have_slvs:
                b_slvs, _ = best_of(case.slvs, reps if n <= 800 else 1)
                runner = {}

                def slvs_solve():
                    go, read = case.slvs()
                    runner["read"] = read
                    t0 = time.perf_counter()
                    ok = go()
                    runner["t"] = time.perf_counter() - t0
                    return ok
                ts = math.inf
                for _ in range(reps if n <= 800 else 1):
                    slvs_solve()
                    ts = min(ts, runner["t"])
                t_slvs = ts * 1e3
                read = runner["read"]
                e_slvs = max(math.hypot(*(np.subtract(read(k), v)))
                             for k, v in case.solution.items())
            rows.append([name, case.n_params, t_build, b_slvs, t_first, t_again, t_slvs, err,
                         e_slvs, res.converged and res2.converged, t_ref if ref_ok else None])
    for row, pg in zip(rows, planegcs_times(pgcs, cases)):
        row.append(pg)
    return rows


def hierarchy_rows(sizes):
    rows = []
    for n in sizes:
        case = hierarchy(n, seed=3)
        t_compile, _ = best_of(lambda: _model(case.source), 1)
        model = _model(case.source)
        x0 = list(model.x)
        out = {}
        for flat in (False, True):
            def go():
                model.x = list(x0)
                return solve(model, flat=flat, diagnose=False)
            t, res = best_of(go, 3 if n <= 200 else 2)
            out[flat] = (t, res)
        rows.append((n, len(model.structures), model and len(x0), t_compile, out[False][0],
                     out[True][0], out[False][1].converged, out[True][1].converged,
                     out[False][1].attempts))
    return rows


def hierarchy_phases(sizes, repeat: int) -> None:
    """Part (e): CPU ms of each phase of ``solve(model)`` (the same calls, timed apart)."""
    print(f"\n(e) phases of the hierarchical solve (CPU ms, median of {repeat}; "
          "rows: build_rows, compile: Solver.whole, attempts: cuts + substitution + Newton)")
    print(f"{'structures':>10}{'rows':>7}{'nodes':>8}{'leaves':>8}{'minmax':>8}{'attempts':>9}"
          f"{'rows':>9}{'compile':>9}{'attempts':>9}{'total':>9}  ok")
    for n in sizes:
        model = _model(hierarchy(n, seed=3).source)
        x0 = list(model.x)
        runs = []
        for _ in range(repeat):
            model.x = list(x0)
            t0 = time.process_time()
            s = Solver(model)
            t1 = time.process_time()
            whole = s.whole
            t2 = time.process_time()
            res = run(s, diagnose=False)
            t3 = time.process_time()
            runs.append((t1 - t0, t2 - t1, t3 - t2, t3 - t0))
        med = [sorted(col)[len(col) // 2] * 1e3 for col in zip(*runs)]
        print(f"{len(model.structures):>10}{whole.n_rows:>7}{whole.n_nodes:>8}"
              f"{len(whole.leaf_node):>8}{whole.n_choices:>8}{res.attempts:>9}"
              + "".join(f"{v:>9.1f}" for v in med) + f"  {res.converged}")


def slope(xs, ys) -> float:
    lx, ly = np.log(np.asarray(xs, float)), np.log(np.asarray(ys, float))
    return float(np.polyfit(lx, ly, 1)[0])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes only (a smoke run)")
    ap.add_argument("--no-planegcs", action="store_true", help="skip the PlaneGCS peer")
    ap.add_argument("--phases", action="store_true",
                    help="only part (e): the phases of the hierarchical solve")
    ap.add_argument("--repeat", type=int, default=5, help="runs per model in part (e)")
    args = ap.parse_args()
    phase_sizes = [10, 50] if args.quick else [10, 50, 200, 500]
    if args.phases:
        hierarchy_phases(phase_sizes, args.repeat)
        return
    try:
        import slvs  # noqa: F401
        have_slvs = True
    except ImportError:
        have_slvs = False
    sizes = [10, 50, 80, 200] if args.quick else [10, 50, 80, 200, 400, 800, 2000]
    pgcs = None if args.no_planegcs else planegcs_python()
    print("(a) flat families, started 10% off a known solution"
          + ("" if have_slvs else "  [slvs not installed: pip install slvs]")
          + ("" if pgcs else "  [planegcs not found: see benchmarks/solver/peer_planegcs.py]"))
    print("    build: source text to a model (ours: parse + check + interpret; peers: the sketch "
          "through their API)\n    cold: first solve (ours: rows, compile, substitution, Newton; "
          "ref: the 20-line numpy/splu Newton incl. its tape compile; slvs, pgcs: solve only)\n"
          "    warm: re-solve from the same start with the system kept (slvs keeps nothing: its "
          "cold time)\n    x/ours ratios: >1 means ours is faster; ms, best of several runs")
    print(f"{'family':<11}{'params':>7}{'build':>8}{'slvs':>7}{'pgcs':>7} |{'cold':>8}{'ref':>8}"
          f"{'slvs':>8}{'pgcs':>8} |{'warm':>8}{'pgcs':>8} |{'ref/':>6}{'slvs/':>6}{'slvs/':>6}"
          f"{'pgcs/':>6}{'pgcs/':>6} |{'err':>8}{'slvs':>8}{'pgcs':>8}  ok")
    print(f"{'':<11}{'':>7}{'':>8}{'':>7}{'':>7} |{'':>8}{'':>8}{'':>8}{'':>8} |{'':>8}{'':>8} |"
          f"{'cold':>6}{'cold':>6}{'warm':>6}{'cold':>6}{'warm':>6} |")
    nan = float("nan")

    def r(a, b):
        return f"{a / b:>6.2f}" if a and b else f"{'-':>6}"
    for (name, n, tb, bs, t1, t2, ts, e1, es, okk, tr, pg) in flat_rows(sizes, have_slvs, pgcs):
        pg = pg or {}
        print(f"{name:<11}{n:>7}{tb:>8.1f}{(bs or nan):>7.2f}{pg.get('build', nan):>7.2f} |"
              f"{t1:>8.2f}{(tr or nan):>8.2f}{(ts or nan):>8.2f}{pg.get('cold', nan):>8.2f} |"
              f"{t2:>8.2f}{pg.get('warm', nan):>8.2f} |{r(tr, t1)}{r(ts, t1)}{r(ts, t2)}"
              f"{r(pg.get('cold'), t1)}{r(pg.get('warm'), t2)} |{e1:>8.0e}"
              f"{(es if es is not None else nan):>8.0e}{pg.get('err', nan):>8.0e}"
              f"  {okk and pg.get('ok', True)}")
    hs = [10, 50] if args.quick else [10, 50, 200, 500]
    print("\n(b) generated hierarchical models (solve only; parse+interpret shown apart)")
    print(f"{'structures':>10}{'params':>8}{'interp':>9}{'hier':>9}{'flat':>9}{'attempts':>10}  ok")
    hr = hierarchy_rows(hs)
    for n, ns, npar, tc, th, tf, okh, okf, att in hr:
        print(f"{ns:>10}{npar:>8}{tc:>9.1f}{th:>9.1f}{tf:>9.1f}{att:>10}  {okh and okf}")
    if len(hr) > 1:
        print(f"growth exponent (log-log fit, time vs structures): hierarchical "
              f"{slope([r[1] for r in hr], [r[4] for r in hr]):.2f}, flat "
              f"{slope([r[1] for r in hr], [r[5] for r in hr]):.2f}")
    print("\n(c) bundled examples (solve only)")
    for path in sorted((ROOT / "examples").glob("*.aidl")):
        model = _model(path.read_text(), str(path))
        x0 = list(model.x)

        def go():
            model.x = list(x0)
            return solve(model)
        t, res = best_of(go, 5)
        print(f"{path.stem:<16}{t:>8.2f} ms  {len(x0):>5} params  converged={res.converged}")
    print("\n(d) fixed overhead of a small solve (2 points, Fixed + Distance, 3 Newton steps)")
    model = _model("solid s {\n a = Point(0, 0)\n b = Point(3, 4.5)\n Fixed(a)\n"
                   " Distance(a, b, 6)\n}\n")
    x0 = list(model.x)

    def small():
        model.x = list(x0)
        return solve(model)
    t, res = best_of(small, 50)
    print(f"small solve {t:.3f} ms ({res.iterations} Newton steps, converged={res.converged})")
    hierarchy_phases(phase_sizes, args.repeat)


if __name__ == "__main__":
    main()
