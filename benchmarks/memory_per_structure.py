"""Bytes per structure (issue 26: "~130-140 KiB per structure; halve it"): programs of N
structures, each a solid with one circle (and a variant with a rectangle and a hole), compiled
by the pipeline `aidl check` runs, each N in a fresh process; prints peak traced memory
(tracemalloc), peak resident memory and the slope between the N, and with ``--top`` the
allocation sites of the largest N.

Run:  .venv/bin/python benchmarks/memory_per_structure.py [--top 15] [--sizes 500,2000,5000]
      [--root OTHER_CHECKOUT]

The resident figure is of the traced run (tracemalloc keeps a record per allocation, several
times the program's own memory); `/usr/bin/time -f %M aidl check FILE` gives the untraced one.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

KINDS = {
    "circle": "    for i in range({n}) {{ solid s {{ c = Circle(center=(i * 3, 0), radius=1) }} }}\n",
    "plate": ("    for i in range({n}) {{\n        solid s {{\n"
              "            body = Rectangle(center=(i * 12, 0), width=10, height=6)\n"
              "            hole h {{ c = Circle(center=(i * 12, 0), radius=1) }}\n"
              "        }}\n    }}\n"),
}

CHILD = r'''
import json, resource, sys, tracemalloc
sys.path.insert(0, sys.argv[1])
from aidl_lang.limits import Budget
from aidl_lang.pipeline import compile_source
src = sys.argv[2]
top = int(sys.argv[3])
tracemalloc.start(8 if top else 1)
c = compile_source(src, "m.aidl", budget=Budget(seconds=600))   # tracing is slow
assert c.ok, [d.message for d in c.sink.items]
cur, peak = tracemalloc.get_traced_memory()
stats = []
if top:
    snap = tracemalloc.take_snapshot()
    for s in snap.statistics("lineno")[:top]:
        f = s.traceback[0]
        stats.append([f"{f.filename.split('aidl_lang/')[-1]}:{f.lineno}", s.size])
print(json.dumps({"held": cur, "peak": peak, "stats": stats,
                  "rss": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024}))
'''


def measure(kind: str, n: int, top: int = 0, root: Path = ROOT) -> dict:
    src = "assembly top {\n" + KINDS[kind].format(n=n) + "}\n"
    r = subprocess.run([sys.executable, "-c", CHILD, str(root), src, str(top)],
                       capture_output=True, text=True, timeout=600)
    if r.returncode:
        raise SystemExit(r.stderr[-2000:])
    return json.loads(r.stdout)


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", default="500,2000,5000")
    ap.add_argument("--top", type=int, default=0, help="allocation sites to list (largest N)")
    ap.add_argument("--root", type=Path, default=ROOT,
                    help="the checkout to measure (another commit's tree, for a before/after)")
    a = ap.parse_args()
    sizes = [int(s) for s in a.sizes.split(",")]
    print(f"{a.root}\n{'kind':8} {'N':>6} {'peak traced':>12} {'held after':>11} "
          f"{'peak RSS (traced run)':>22}")
    for kind in KINDS:
        rows = []
        for n in sizes:
            m = measure(kind, n, a.top if n == sizes[-1] else 0, a.root)
            rows.append((n, m))
            print(f"{kind:8} {n:6d} {m['peak'] / 2**20:10.1f} MiB {m['held'] / 2**20:8.1f} MiB "
                  f"{m['rss'] / 2**20:7.0f} MiB")
        (n0, m0), (n1, m1) = rows[0], rows[-1]
        print(f"{kind:8} per structure: {(m1['peak'] - m0['peak']) / (n1 - n0) / 1024:.1f} KiB "
              f"peak traced, {(m1['held'] - m0['held']) / (n1 - n0) / 1024:.1f} KiB held, "
              f"{(m1['rss'] - m0['rss']) / (n1 - n0) / 1024:.1f} KiB RSS")
        for site, size in rows[-1][1]["stats"]:
            print(f"    {size / 2**20:8.1f} MiB  {site}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
