"""One answer at any load (issue 92): ``aidl check --sweep`` of a panel of 8,000 round holes
whose ``pitch`` ranges 2-6 mm (walls thinner than 0.5 mm below 2.9 mm: holes of 2.4 mm),
run on a quiet machine and again beside two busy loops (``while True: pass``, one a core),
each in a process of its own.  The sweep's budget counts work (interpreter steps, objects,
unknowns, diagnostics), not seconds, so the lines it prints must be the same; prints both
runs' CPU seconds, the sweep's lines and whether they match (exit 1 when they differ).

    PYTHONPATH=$PWD python benchmarks/checks/sweep_load.py [--holes 8000] [--busy 2]
"""
from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def panel(nx: int, ny: int) -> str:
    return f"""param pitch = 4 mm, min = 2 mm, max = 6 mm

solid panel {{
    body = Rectangle(center=(0, 0), width={nx} * pitch + 2 mm, height={ny} * pitch + 2 mm)
    for i in range({nx}) {{
        for j in range({ny}) {{
            hole h {{ c = Circle(center=(({1 - nx} / 2 + i) * pitch, ({1 - ny} / 2 + j) * pitch),
                                diameter=2.4 mm) }}
        }}
    }}
}}
"""


def run(path: str) -> tuple[list[str], float]:
    """The ``sweep:`` and ``W0110`` lines of ``aidl check --sweep path`` and its CPU seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "check", path, "--sweep"],
                       capture_output=True, text=True, env=env, timeout=600)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    lines = [ln for ln in (p.stdout + p.stderr).splitlines()
             if ln.startswith("sweep:") or "W0110" in ln or "= hint" in ln]
    return lines, cpu


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--holes", type=int, default=8000)
    ap.add_argument("--busy", type=int, default=2)
    a = ap.parse_args(argv)
    nx = 100
    ny = max(1, a.holes // nx)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "panel.aidl")
        Path(path).write_text(panel(nx, ny))
        quiet, cpu_q = run(path)
        busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"])
                for _ in range(a.busy)]
        try:
            loaded, cpu_l = run(path)
        finally:
            for p in busy:
                p.kill()
                p.wait()
    same = quiet == loaded
    print(f"{nx * ny} holes: quiet {cpu_q:.1f} s CPU, beside {a.busy} busy loops {cpu_l:.1f} s "
          f"CPU; lines {'identical' if same else 'DIFFER'}")
    for ln in quiet:
        print("    " + ln)
    if not same:
        print("  loaded:")
        for ln in loaded:
            print("    " + ln)
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
