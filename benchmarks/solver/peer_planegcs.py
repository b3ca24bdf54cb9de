"""FreeCAD's PlaneGCS (``planegcs`` from PyPI, Python >= 3.12) on the benchmark sketches.

Run by ``benchmarks/solver/solver_scaling.py`` in a subprocess under the Python named by
``AIDL_PLANEGCS_PYTHON`` (default ``.venv312/bin/python`` in the repository, made with
``python3.12 -m venv .venv312 && .venv312/bin/pip install planegcs``).  Reads a JSON list of
sketches (:attr:`benchmarks.solver.families.Case.spec` plus ``solution`` and ``reps``) on stdin and
writes one JSON result per sketch: build, cold solve and warm re-solve times (ms, best of
``reps``) and the max point error against the known solution (mm).

The warm re-solve keeps the sketch (PlaneGCS keeps its system) and only puts the points back
at their starting values, as our re-solve keeps the compiled system.
"""
from __future__ import annotations

import json
import math
import sys
import time


def build(spec):
    import planegcs
    sk = planegcs.Sketch()
    P = {k: sk.add_point(x, y) for k, (x, y) in spec["points"].items()}
    for k in spec["fixed"]:
        x, y = spec["points"][k]
        sk.fix_point(P[k], x, y)
    lines, circles = {}, {}

    def line(a, b):
        key = (a, b)
        if key not in lines:
            lines[key] = sk.add_line(P[a], P[b])
        return lines[key]
    for c in spec["constraints"]:
        kind = c[0]
        if kind == "horizontal":
            sk.horizontal(line(c[1], c[2]))
        elif kind == "vertical":
            sk.vertical(line(c[1], c[2]))
        elif kind == "distance":
            sk.set_p2p_distance(P[c[1]], P[c[2]], c[3])
        elif kind == "coincident":
            sk.coincident(P[c[1]], P[c[2]])
        elif kind == "on_circle":
            key = tuple(c[2:5])
            if key not in circles:
                ctr = sk.add_point(c[2], c[3])
                sk.fix_point(ctr, c[2], c[3])
                circles[key] = sk.add_circle(ctr, sk.add_fixed_param(c[4]))
            sk.point_on_circle(P[c[1]], circles[key])
        elif kind == "equal_length":
            sk.equal_length(line(c[1], c[2]), line(c[3], c[4]))
        elif kind == "angle":
            sk.set_l2l_angle(line(c[1], c[2]), line(c[3], c[4]), c[5])
        else:
            raise ValueError(f"unknown constraint {kind}")
    return sk, P


def measure(case):
    import planegcs
    ok_status = {planegcs.SolveStatus.Success, planegcs.SolveStatus.Converged}
    spec, reps = case["spec"], case["reps"]
    t_build = t_cold = t_warm = math.inf
    for _ in range(reps):
        t0 = time.perf_counter()
        sk, P = build(spec)
        t1 = time.perf_counter()
        st = sk.solve()
        t2 = time.perf_counter()
        t_build, t_cold = min(t_build, t1 - t0), min(t_cold, t2 - t1)
    ok = st in ok_status
    err = max(math.hypot(sk.get_point(P[k])[0] - x, sk.get_point(P[k])[1] - y)
              for k, (x, y) in case["solution"].items())
    ids = {k: sk.get_point_param_ids(P[k]) for k in spec["points"]}
    for _ in range(reps):
        for k, (x, y) in spec["points"].items():
            sk.set_param(ids[k][0], x)
            sk.set_param(ids[k][1], y)
        t0 = time.perf_counter()
        st = sk.solve()
        t_warm = min(t_warm, time.perf_counter() - t0)
    ok = ok and st in ok_status
    return {"build": t_build * 1e3, "cold": t_cold * 1e3, "warm": t_warm * 1e3,
            "err": err, "ok": ok}


def main() -> None:
    cases = json.load(sys.stdin)
    out = []
    for c in cases:
        try:
            out.append(measure(c))
        except Exception as e:          # a sketch PlaneGCS cannot build: say so in the table
            out.append({"error": f"{type(e).__name__}: {e}"})
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
