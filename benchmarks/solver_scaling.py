"""Solver scaling: AIDL's solver against SolveSpace, and hierarchical against flat.

Run:  .venv/bin/pip install -e ".[bench]"   (SolveSpace's ``slvs`` from PyPI)
      .venv/bin/python benchmarks/solver_scaling.py  [--quick]

Prints one table in four parts:

(a) flat sketch families (``benchmarks/families.py``: a chain of rectangles, points on a ring
    with equal chords, a linkage with lengths and angles) from 10 to 2000 parameters, each
    started 10% off a known solution and checked against it (max point error, mm).  Columns:
    the build (ours: source text to a model; SolveSpace: the sketch made through its API), our
    first solve (building rows, compiling, substituting, Newton), our re-solve from the same
    start with the compiled system cached (what an edit costs), and SolveSpace (``slvs`` from
    PyPI, ``solve_sketch`` only) in the same run, with slvs/ours ratios for each.  planegcs
    needs Python 3.12 and is skipped.
(b) generated hierarchical models with 10 to 500 structures: hierarchical solve against a flat
    solve of the same model, with the log-log growth exponent.
(c) every bundled example: the solve time.
(d) the fixed overhead of a small solve (two points, one distance).

Times are the best of several runs (fewer for slow cases), in milliseconds, on this machine.
"""
from __future__ import annotations

import argparse
import math
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from aidl_lang.pipeline import compile_source  # noqa: E402
from aidl_lang.solver import Solver, run, solve  # noqa: E402
from benchmarks.families import FLAT, hierarchy  # noqa: E402


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


def flat_rows(sizes, have_slvs: bool):
    rows = []
    for name, make in FLAT.items():
        for n in sizes:
            case = make(n, seed=7)
            reps = 5 if n <= 200 else 3
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
            rows.append((name, case.n_params, t_build, b_slvs, t_first, t_again, t_slvs, err,
                         e_slvs, res.converged and res2.converged))
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


def slope(xs, ys) -> float:
    lx, ly = np.log(np.asarray(xs, float)), np.log(np.asarray(ys, float))
    return float(np.polyfit(lx, ly, 1)[0])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes only (a smoke run)")
    args = ap.parse_args()
    try:
        import slvs  # noqa: F401
        have_slvs = True
    except ImportError:
        have_slvs = False
    sizes = [10, 50, 200] if args.quick else [10, 50, 200, 800, 2000]
    print("(a) flat families, started 10% off a known solution"
          + ("" if have_slvs else "  [slvs not installed: pip install slvs]"))
    print("    build: source text to a model (ours: parse + check + interpret) or the sketch "
          "built through the slvs API;\n    1st: a cold solve; re: a warm re-solve from the same "
          "start (compiled system kept); ratios are slvs time / ours (>1: ours faster)")
    print(f"{'family':<11}{'params':>7}{'build':>9}{'slvs bld':>9}{'ratio':>8}{'ours 1st':>10}"
          f"{'ours re':>9}{'slvs':>10}{'1st ratio':>10}{'re ratio':>9}{'err ours':>10}"
          f"{'err slvs':>10}  ok")
    nan = float("nan")
    for name, n, tb, bs, t1, t2, ts, e1, es, okk in flat_rows(sizes, have_slvs):
        def ratio(a, b, w):
            return f"{a / b:{w - 1}.2f}x" if a else " " * (w - 1) + "-"
        print(f"{name:<11}{n:>7}{tb:>9.2f}{(bs or nan):>9.3f}{ratio(bs, tb, 8)}{t1:>10.2f}"
              f"{t2:>9.2f}{(ts or nan):>10.2f}{ratio(ts, t1, 10)}{ratio(ts, t2, 9)}"
              f"{e1:>10.1e}{(es if es is not None else nan):>10.1e}  {okk}")
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


if __name__ == "__main__":
    main()
