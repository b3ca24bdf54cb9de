"""Large inputs (issue 26's reproducers), timed through ``aidl check`` (a fresh process each):

    python benchmarks/checks/large_inputs.py                  # this checkout
    PYTHONPATH=/path/to/other/checkout python benchmarks/checks/large_inputs.py   # another one (before)

1 000 concentric circles in one solid; 5 000 separate circles in one 250 kB file; a
LinearPattern of 5 000 and 10 000 overlapping circles (a diagonal chain); 5 000 lines in
shuffled order closing one polygon; an import diamond of 16 levels (33 files).  Each run is
cut at ``--timeout`` seconds (default 300)."""
from __future__ import annotations

import argparse
import math
import os
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def cases(d: Path) -> dict[str, Path]:
    out = {}

    def put(name, text):
        p = d / f"{name}.aidl"
        p.write_text(text)
        out[name] = p
    put("concentric-1000", "solid s {\n" + "".join(
        f"  c{i} = Circle(center=(0, 0), radius={1 + i * 0.1:.1f})\n" for i in range(1000)) + "}\n")
    put("separate-5000", "solid s {\n" + "".join(
        f"  c{i} = Circle(center=({(i % 70) * 3}, {(i // 70) * 3}), radius=1)\n"
        for i in range(5000)) + "}\n")
    for n in (5000, 10000):
        put(f"pattern-{n}", f"solid s {{\n  c = Circle(center=(0, 0), radius=1)\n"
                            f"  p = LinearPattern(c, {n}, (-1, 1))\n}}\n")
    n = 5000
    pts = [(round(100 * math.cos(2 * math.pi * i / n), 9), round(100 * math.sin(2 * math.pi * i / n), 9))
           for i in range(n)]
    order = list(range(n))
    random.Random(1).shuffle(order)
    put("lines-5000", "solid s {\n" + "".join(
        f"  l{i} = Line(({pts[i][0]}, {pts[i][1]}), ({pts[(i + 1) % n][0]}, {pts[(i + 1) % n][1]}))\n"
        for i in order) + "}\n")
    dd = d / "diamond"
    dd.mkdir()
    (dd / "bottom.aidl").write_text("def base() -> solid {\n  c = Circle(center=(0, 0), radius=1)\n}\n")
    for k in range(15, -1, -1):
        for s in "ab":
            imps = 'import "bottom.aidl"\n' if k == 15 else \
                f'import "d{k + 1}a.aidl"\nimport "d{k + 1}b.aidl"\n'
            (dd / f"d{k}{s}.aidl").write_text(
                imps + f"def t{k}{s}() -> solid {{\n  c = Circle(center=(0, 0), radius=1)\n}}\n")
    (dd / "main.aidl").write_text('import "d0a.aidl"\nimport "d0b.aidl"\n'
                                  "solid p { c = Circle(center=(0, 0), radius=5) }\n")
    out["diamond-16"] = dd / "main.aidl"
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--only", default="", help="comma-separated case names")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for name, path in cases(Path(tmp)).items():
            if args.only and name not in args.only.split(","):
                continue
            t0 = time.perf_counter()
            try:
                r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", str(path)],
                                   capture_output=True, text=True, timeout=args.timeout,
                                   env=dict(os.environ))
                tail = (r.stdout.strip().splitlines() or r.stderr.strip().splitlines() or [""])[-1]
                what = f"exit {r.returncode}: {tail[:90]}"
            except subprocess.TimeoutExpired:
                what = f"cut at {args.timeout:g} s"
            print(f"{name:16} {time.perf_counter() - t0:7.2f} s  {what}", flush=True)


if __name__ == "__main__":
    main()
