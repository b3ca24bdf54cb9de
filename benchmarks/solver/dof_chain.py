"""Issue 37's `aidl check --dof` of 2,500 points, side by side with an older tree:

    .venv/bin/python benchmarks/solver/dof_chain.py [OLD_TREE] [--points 2500] [--rounds 3]

Two programs of N free points: a *chain* (each point a `Distance` from the next: every row
peels, the issue's reproducer) and a *ring* (the chain closed by one more `Distance`: nothing
peels, the redundancy search's worst case).  Each tree runs its own interpreter
(``TREE/.venv/bin/python`` when there is one, else this one with ``PYTHONPATH=TREE``), a fresh
process per run, alternating; printed: the median wall time, CPU (user + system of the child,
``os.wait4``), peak RSS, and the ok line's freedom and the "not counted" lines.  The budget
is the default 15 s of wall time: the run ends near it (the compile's deadline) when the
analysis cannot finish.
"""
from __future__ import annotations

import argparse
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


def programs(n: int) -> dict[str, str]:
    chain = (f"units mm\ndrawing d {{\n    pts = [Point(i * 0.1, 0) for i in range({n})]\n"
             f"    for i in range({n - 1}) {{ Distance(pts[i], pts[i + 1], 0.1) }}\n")
    return {"chain": chain + "}\n",
            "ring": chain + f"    Distance(pts[{n - 1}], pts[0], {round((n - 1) * 0.1, 6)})\n}}\n"}


def interpreter(tree: pathlib.Path) -> tuple[str, dict]:
    py = tree / ".venv" / "bin" / "python"
    if py.exists():
        return str(py), dict(os.environ)
    return sys.executable, dict(os.environ, PYTHONPATH=str(tree))


def run(tree: pathlib.Path, path: str) -> tuple[float, float, float, str]:
    """(wall s, CPU s, peak RSS MB, the lines that say what was counted) of one run."""
    py, env = interpreter(tree)
    t0 = time.monotonic()
    p = subprocess.Popen([py, "-m", "aidl_lang.cli", "check", "--dof", path], cwd=tree,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=env)
    out = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.monotonic() - t0
    said = [ln for ln in out.splitlines() if ": ok (" in ln or "not counted" in ln]
    said = [ln.split("; ", 1)[-1] if ": ok (" in ln else ln for ln in said]
    return wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024, " | ".join(said)[:160]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("old", nargs="?")
    ap.add_argument("--points", type=int, default=2500)
    ap.add_argument("--rounds", type=int, default=3)
    a = ap.parse_args()
    trees = [("new", ROOT)] + ([("old", pathlib.Path(a.old).resolve())] if a.old else [])
    with tempfile.TemporaryDirectory() as d:
        for name, src in programs(a.points).items():
            path = os.path.join(d, f"{name}{a.points}.aidl")
            pathlib.Path(path).write_text(src)
            got: dict = {t: [] for t, _ in trees}
            for _ in range(a.rounds):
                for t, tree in trees:
                    got[t].append(run(tree, path))
            for t, _ in trees:
                rows = got[t]
                print(f"{name:5s} {a.points} {t}: wall {statistics.median(r[0] for r in rows):6.2f} s"
                      f"  CPU {statistics.median(r[1] for r in rows):6.2f} s"
                      f"  RSS {max(r[2] for r in rows):5.0f} MB  {rows[-1][3]}")


if __name__ == "__main__":
    main()
