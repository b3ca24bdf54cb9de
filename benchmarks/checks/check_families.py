"""`aidl check` on the families of outlines that were quadratic somewhere in the shape checks
(issue 91): CPU seconds of the whole check (a fresh process) and of the shape-check stage
alone, with the warnings they give, here and in an older checkout beside it.

Run:  .venv/bin/python benchmarks/checks/check_families.py [--old /tmp/old] [--scale K] [FAMILY ...]

``--old``: another checkout (``git worktree add /tmp/old main``) run the same way, its
figures printed beside this one's.  ``--scale``: the sizes times K (1: the sizes below).
Families (:data:`FAMILIES`, each ``n -> source``; the generators are the laws' too,
tests/test_checks_scaling.py):

* ``concentric``: n circles about one centre, radius 1 + i mm (one solid)
* ``concentric01``: n circles about one centre, radius 1 + 0.1 i mm (tests/test_reliability)
* ``holes``: a plate with n concentric round holes, one statement's copies (radius 1 + 0.1 i)
* ``nested``: n squares about one centre, side 2 + 2 i mm (one solid)
* ``frames``: n square frames, each a solid with its own square hole, nested in one another
* ``chain``: n 10 x 5 mm rectangles in a row, each touching the next edge to edge
* ``grid``: a plate with n round holes (radius 2 mm, pitch 6 mm)
* ``touching``: n 10 mm squares on a square grid, each touching its neighbours edge to edge
* ``parts``: an assembly of n 10 mm square parts on a grid, touching edge to edge
* ``corners``: n 10 mm squares on a checkerboard (touching at their corners only: W0507)
"""
from __future__ import annotations

import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def concentric(n: int, step: float = 1.0) -> str:
    return "solid s {\n" + "".join(
        f"    c{i} = Circle(center=(0, 0), radius={round(1 + i * step, 1)})\n"
        for i in range(n)) + "}\n"


def holes(n: int) -> str:
    """A plate with n concentric round holes of one statement (radius 1 + 0.1 i mm)."""
    w = 4 + 0.2 * n
    return (f"solid plate {{\n    body = Rectangle(center=(0, 0), width={w}, height={w})\n"
            f"    hole h {{\n        for i in range({n}) {{ c = Circle(center=(0, 0), "
            "radius=1 + 0.1 * i) }\n    }\n}\n")


def nested(n: int) -> str:
    return "solid s {\n" + "".join(
        f"    r{i} = Rectangle(center=(0, 0), width={2 + 2 * i}, height={2 + 2 * i})\n"
        for i in range(n)) + "}\n"


def frames(n: int) -> str:
    return "solid s {\n" + "".join(
        f"    solid f{i} {{\n        r = Rectangle(center=(0, 0), width={4 + 4 * i}, "
        f"height={4 + 4 * i})\n        hole h {{ q = Rectangle(center=(0, 0), width={2 + 4 * i}"
        f", height={2 + 4 * i}) }}\n    }}\n" for i in range(n)) + "}\n"


def chain(n: int) -> str:
    return "solid s {\n" + "".join(
        f"    r{i} = Rectangle(center=({10 * i}, 0), width=10, height=5)\n"
        for i in range(n)) + "}\n"


def grid(n: int, pitch: float = 6.0, r: float = 2.0) -> str:
    cols = math.ceil(math.sqrt(n))
    rows = math.ceil(n / cols)
    w, h = cols * pitch, rows * pitch
    return (f"solid plate {{\n    body = Rectangle(center=({w / 2}, {h / 2}), width={w}, "
            f"height={h})\n    hole holes {{\n        for j in range({rows}) {{\n"
            f"            for i in range({cols}) {{\n                if j * {cols} + i < {n} {{\n"
            f"                    c = Circle(center=(i * {pitch} + {pitch / 2}, j * {pitch} + "
            f"{pitch / 2}), radius={r})\n                }}\n            }}\n        }}\n"
            "    }\n}\n")


def touching(n: int) -> str:
    cols = math.ceil(math.sqrt(n))
    return "solid s {\n" + "".join(
        f"    r{i} = Rectangle(center=({10 * (i % cols)}, {10 * (i // cols)}), width=10, "
        "height=10)\n" for i in range(n)) + "}\n"


def parts(n: int) -> str:
    """An assembly of n 10 mm square parts on a square grid, touching edge to edge."""
    cols = math.ceil(math.sqrt(n))
    return (f"assembly kit {{\n    for i in range({n}) {{\n        solid p {{ r = Rectangle("
            f"center=(10 * (i % {cols}), 10 * (i // {cols})), width=10, height=10) }}\n"
            "    }\n}\n")


def corners(n: int) -> str:
    cols = math.ceil(math.sqrt(2 * n))
    cells = [(i, j) for j in range(cols) for i in range(cols) if (i + j) % 2 == 0][:n]
    return "solid s {\n    min_wall 0.5\n" + "".join(
        f"    r{k} = Rectangle(center=({10 * i}, {10 * j}), width=10, height=10)\n"
        for k, (i, j) in enumerate(cells)) + "}\n"


FAMILIES = {
    "concentric": (concentric, 1000),
    "concentric01": (lambda n: concentric(n, 0.1), 1000),
    "holes": (holes, 1000),
    "nested": (nested, 1000),
    "frames": (frames, 300),
    "chain": (chain, 2000),
    "grid": (grid, 20000),
    "touching": (touching, 2500),
    "corners": (corners, 400),
    "parts": (parts, 2500),
}

# run in the checkout under test (``sys.path[0]``): the shape checks timed alone, then the
# whole `aidl check` in-process (the CPU of a fresh process is the outer figure)
_STAGE = r"""
import json, sys, time
sys.path.insert(0, sys.argv[1])
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.base.limits import DEFAULT_BUDGET, Deadline, now
from aidl_lang.output import checks
from aidl_lang.pipeline import _compile, run_deep
src = open(sys.argv[2]).read()
c = run_deep(lambda: _compile(DiagnosticSink(), src, "f.aidl", None, True,
                              budget=DEFAULT_BUDGET.scaled(20), shape_checks=False))
sink = DiagnosticSink()
t0 = time.process_time()
run_deep(lambda: checks.check_drawing(c.drawing, sink, None,
                                      Deadline(now() + 60, DEFAULT_BUDGET.scaled(4))))
cpu = time.process_time() - t0
codes = sorted(d.code for d in sink.items)
print(json.dumps({"stage": cpu, "codes": {k: codes.count(k) for k in set(codes)}}))
"""


def measure(tree: Path, path: Path) -> dict:
    """The check stage's CPU and warnings, and the whole `aidl check`'s CPU (a process)."""
    out = subprocess.run([sys.executable, "-c", _STAGE, str(tree), str(path)],
                         capture_output=True, text=True, cwd=tree)
    res = json.loads(out.stdout.strip().splitlines()[-1]) if out.returncode == 0 else \
        {"stage": float("nan"), "codes": {"crash": out.stderr[-300:]}}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run([sys.executable, "-c", "import sys; sys.path.insert(0, sys.argv[1]); "
                          "from aidl_lang.cli.main import main; sys.exit(main(sys.argv[2:]))",
                          str(tree), "check", str(path)], capture_output=True, text=True,
                         cwd=tree)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    res["check"] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    res["rc"] = run.returncode
    res["E0304"] = "E0304" in run.stdout + run.stderr
    return res


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("families", nargs="*", default=list(FAMILIES))
    ap.add_argument("--old", type=Path, help="an older checkout to run beside this one")
    ap.add_argument("--scale", type=float, default=1.0)
    a = ap.parse_args()
    trees = [("new", ROOT)] + ([("old", a.old.resolve())] if a.old else [])
    print(f"{'family':>13} {'n':>6} " + " ".join(
        f"{t + ' check s':>12} {t + ' stage s':>12}" for t, _ in trees) + "  warnings")
    with tempfile.TemporaryDirectory() as d:
        for name in a.families:
            make, n = FAMILIES[name]
            n = max(1, int(n * a.scale))
            p = Path(d) / f"{name}{n}.aidl"
            p.write_text(make(n))
            rows = [measure(tree, p) for _, tree in trees]
            cells = " ".join(f"{r['check']:>12.2f} {r['stage']:>12.2f}" for r in rows)
            said = " | ".join(",".join(f"{k}x{v}" for k, v in sorted(r["codes"].items()))
                              + (" E0304!" if r["E0304"] else "")
                              + (f" rc={r['rc']}" if r["rc"] else "") for r in rows)
            print(f"{name:>13} {n:>6} {cells}  {said}", flush=True)


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    main()
