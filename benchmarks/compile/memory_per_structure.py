"""Memory per structure (issue 26, item 5): peak traced bytes and peak RSS of a compile and an
SVG render of N structures, each in a fresh process:

    python benchmarks/compile/memory_per_structure.py                 # N = 500, 1000, 2000, 5000
    python benchmarks/compile/memory_per_structure.py --n 500 2000 --top 15
    PYTHONPATH=/path/to/other/checkout python benchmarks/compile/memory_per_structure.py   # before

Two programs: ``circle`` (``for i in range(N) { solid s { c = Circle(...) } }`` inside an
assembly) and ``plate`` (a Rectangle with a circular hole per structure).  Each is compiled
through :func:`aidl_lang.api.compile` (what ``aidl check`` and ``aidl render`` run) and
rendered with ``Result.to_svg()``.  Printed: peak ``tracemalloc`` bytes, peak RSS
(``resource.getrusage``, includes the interpreter and imported modules), and bytes per
structure as the slope of the peak between consecutive N.  With ``--top K`` the K largest
allocation sites (by line) still held at the end of each N = 2000 run follow.  The
compile is given ``budget=100`` so that a busy machine does not end it in E0304."""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

PROGRAMS = {
    "circle": ("assembly a {{\n  for i in range({n}) {{\n"
               "    solid s {{ c = Circle(center=(i * 3, 0), radius=1) }}\n  }}\n}}\n"),
    "plate": ("assembly a {{\n  for i in range({n}) {{\n"
              "    solid s {{\n      r = Rectangle(center=(i * 12, 0), width=10, height=6)\n"
              "      hole h {{ c = Circle(center=(i * 12, 0), radius=1.5) }}\n    }}\n  }}\n}}\n"),
}

CHILD = r"""
import json, resource, sys, tracemalloc
src, top = sys.argv[1], int(sys.argv[2])
import aidl_lang.api as api
api.compile("solid s { c = Circle(center=(0, 0), radius=1) }\n").to_svg()   # imports, caches
tracemalloc.start(1)
r = api.compile(src, path="<bench>", budget=100)   # no E0304 on a busy machine
assert r.ok, [d.message for d in r.errors]
svg = r.to_svg()
cur, peak = tracemalloc.get_traced_memory()
snap = tracemalloc.take_snapshot() if top else None
tracemalloc.stop()
sites = []
if snap is not None:
    for st in snap.statistics("lineno")[:top]:
        f = st.traceback[0]
        sites.append([f"{f.filename.split('site-packages/')[-1].split('aidl_lang/')[-1]}:{f.lineno}", st.size, st.count])
print(json.dumps({"peak": peak, "held": cur, "svg": len(svg), "sites": sites,
                  "rss": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024}))
"""


def run(kind: str, n: int, top: int = 0) -> dict:
    """One compile + SVG render of ``PROGRAMS[kind]`` with ``n`` structures in a fresh
    process: ``{"peak", "held", "rss", "svg", "sites"}`` (bytes)."""
    # a fixed hash seed: set iteration order moves when the cyclic collector runs, which
    # moves the traced peak by several MiB from one run to the next
    out = subprocess.run([sys.executable, "-c", CHILD, PROGRAMS[kind].format(n=n), str(top)],
                         capture_output=True, text=True, check=True,
                         env={**os.environ, "PYTHONHASHSEED": "0"},
                         cwd=tempfile.gettempdir())   # not this folder: PYTHONPATH decides
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[500, 1000, 2000, 5000])
    ap.add_argument("--kinds", nargs="+", default=list(PROGRAMS))
    ap.add_argument("--top", type=int, default=12, help="allocation sites shown (N=2000)")
    a = ap.parse_args()
    MiB = 1024 * 1024
    for kind in a.kinds:
        print(f"{kind}:  {'N':>6} {'peak traced':>12} {'held':>9} {'peak RSS':>9} {'per structure':>14}")
        prev = None
        sites = None
        for n in a.n:
            r = run(kind, n, a.top if n == 2000 else 0)
            if r["sites"]:
                sites = r["sites"]
            slope = "" if prev is None else f"{(r['peak'] - prev[1]) / (n - prev[0]) / 1024:9.1f} KiB"
            print(f"{'':8}{n:6} {r['peak'] / MiB:9.1f} MiB {r['held'] / MiB:5.1f} MiB "
                  f"{r['rss'] / MiB:5.0f} MiB {slope:>14}")
            prev = (n, r["peak"])
        if sites:
            print(f"  top allocation sites held at the end of the N=2000 {kind} run:")
            for where, size, count in sites:
                print(f"    {size / 1024:9.0f} KiB {count:8} blocks  {where}")


if __name__ == "__main__":
    main()
