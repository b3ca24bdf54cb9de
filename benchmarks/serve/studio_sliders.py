"""A slider move on every gallery entry, to its flat view (issue 72, "Speed"):

    .venv/bin/python benchmarks/serve/studio_sliders.py                 # every entry
    .venv/bin/python benchmarks/serve/studio_sliders.py --only planetary --runs 3
    .venv/bin/python benchmarks/serve/studio_sliders.py --tree /work/main     # that tree's code too

For each entry of :func:`aidl_lang.studio.gallery.entries` one warm session is opened
through the studio's own path, the compile worker's handler
(:func:`aidl_lang.studio.compiler.handler`: ``("view", ...)`` requests, as ``/api/view``
sends them, answered by the worker's warm ``Session``; after each answer the handler's
``idle``, when it has one, runs untimed, as the worker runs it after sending the answer),
on the entry's defaults; then each slider (a param
with ``min``/``max``) is moved to its minimum and to its maximum, one move at a time from the
defaults, and the time of that ``view`` call (the answer carries the SVG) is taken: CPU
seconds of this process (the main figure: the machine is shared) and wall seconds.  Printed:
per entry the number of moves, the median and the slowest move (CPU and wall), and whether
every move answered ``ok`` with an SVG; then the slowest entries overall.  Bounds are the
form's (:func:`~aidl_lang.studio.gallery.param_rows`); an integer param moves to whole ends.
``--tree DIR``: the same run again with ``DIR``'s ``aidl_lang`` (another checkout), printed
after this tree's.
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(os.environ.get("AIDL_BENCH_TREE") or Path(__file__).resolve().parents[2])
sys.path.insert(0, str(ROOT))


def _value(row: dict, v) -> str:
    if row["kind"] == "integer":
        v = int(round(v))
    unit = row.get("unit") or ""
    return f"{v} {unit}".strip()


def moves(entry) -> list[dict]:
    """One dict {name: value} per slider end of ``entry`` (the other params at defaults)."""
    out = []
    for row in entry.params:
        if row["kind"] in ("bool", "string") or row.get("min") is None or row.get("max") is None:
            continue
        for end in (row["min"], row["max"]):
            if end != row["default"]:
                out.append({row["name"]: _value(row, end)})
    return out


def bench(entry, handle, runs: int = 1) -> dict:
    idle = getattr(handle, "idle", lambda: None)

    def view(folder, values):
        doc = handle(("view", "s-" + entry.id, folder, entry.source, values))
        return doc
    with tempfile.TemporaryDirectory() as folder:
        view(folder, {})                                        # warm: the defaults
        idle()
        cpu, wall, bad = [], [], 0
        for mv in moves(entry):
            for _ in range(runs):
                view(folder, {})                                # back to the defaults
                idle()
                c0, w0 = time.process_time(), time.perf_counter()
                doc = view(folder, mv)
                cpu.append(time.process_time() - c0)
                wall.append(time.perf_counter() - w0)
                idle()                                          # after the answer is sent
                bad += not (doc.get("ok") and doc.get("svg"))
    return {"id": entry.id, "moves": len(cpu), "cpu": cpu, "wall": wall, "bad": bad}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default="", help="entries whose id contains this")
    ap.add_argument("--runs", type=int, default=1, help="times each move is made")
    ap.add_argument("--tree", default="", help="another checkout to run the same on, after")
    a = ap.parse_args(argv)
    from aidl_lang.studio.compiler import handler
    from aidl_lang.studio.gallery import entries
    handle = handler()
    print(f"tree: {ROOT}")
    rows = []
    print(f"{'entry':40s} {'moves':>5s} {'cpu med':>8s} {'cpu max':>8s} "
          f"{'wall med':>8s} {'wall max':>8s} {'not ok':>6s}")
    for e in entries():
        if a.only not in e.id:
            continue
        r = bench(e, handle, a.runs)
        rows.append(r)
        if not r["cpu"]:
            print(f"{e.id:40s} {0:5d}  (no sliders)")
            continue
        print(f"{e.id:40s} {r['moves']:5d} {statistics.median(r['cpu']):8.3f} "
              f"{max(r['cpu']):8.3f} {statistics.median(r['wall']):8.3f} "
              f"{max(r['wall']):8.3f} {r['bad']:6d}", flush=True)
    rows = [r for r in rows if r["cpu"]]
    rows.sort(key=lambda r: -statistics.median(r["cpu"]))
    print("\nslowest (median CPU s per move):")
    for r in rows[:5]:
        print(f"  {r['id']:40s} {statistics.median(r['cpu']):.3f}")
    if a.tree:
        sys.stdout.flush()
        again = [sys.executable, __file__, "--only", a.only, "--runs", str(a.runs)]
        return subprocess.call(again, env=dict(os.environ, AIDL_BENCH_TREE=a.tree))
    return 0


if __name__ == "__main__":
    sys.exit(main())
