"""`aidl batch` throughput against a shell loop of `aidl check` over the same files
(docs/batch.md, "What it costs").

Run:  .venv/bin/python benchmarks/agents/batch.py [--files 100] [--no-dask]

The files: the bundled examples (12) and generated plates (a rounded plate with a row of holes
and a slot, sizes and counts varied) up to ``--files``.  Prints programs per second for

- the shell loop: ``for f in FILES; do aidl check "$f"; done`` (one cold process per program);
- ``aidl batch`` on the local pool with 1 and 2 workers (``run_batch``, JSONL output, timed
  from the call to the last row written: worker start-up included);
- ``aidl batch --scheduler local``: a 2-worker ``dask.distributed.LocalCluster`` (its start
  and stop included), unless ``--no-dask``;

each with its CPU time per program (load-independent on a shared machine, where wall-time
ratios swing with the other jobs), its rate over the whole wall time (start-up included) and its steady rate (from the
first row of each worker to the last: what a long batch runs at), their speed-ups over the
shell loop, and the time 10,000 such programs would take (start-up + 10,000 at the steady
rate).
A batch row does more than ``aidl check`` (it also builds the exact output model for the part,
hole and area counts).
"""
from __future__ import annotations

import argparse
import os
import resource
import pathlib
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.batch.command import run_batch  # noqa: E402


def plate(i: int) -> str:
    w, n = 40 + i % 37, 2 + i % 6
    return f"""units mm
param width = {w} mm
param holes = {n}

solid plate {{
    body = RoundedRectangle(center=(0, 0), width=width, height=30, corner_radius=3)
    for k in range(holes) {{
        hole bore {{
            c = Circle(center=(-width / 2 + (k + 1) * width / (holes + 1), 6), radius=2)
        }}
    }}
    hole slot {{
        s = Slot(center=(0, -7), length=width / 2, width=4)
    }}
}}
"""


def corpus(folder: pathlib.Path, n: int) -> list[str]:
    files = sorted(str(p) for p in (ROOT / "examples").glob("*.aidl"))[:n]
    for i in range(n - len(files)):
        p = folder / f"plate_{i:03d}.aidl"
        p.write_text(plate(i))
        files.append(str(p))
    return files


def cpu() -> float:
    """CPU seconds (user + system) of this process and of its children that ended."""
    return sum(getattr(resource.getrusage(who), f) for who in
               (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN) for f in ("ru_utime", "ru_stime"))


def shell_loop(files: list[str]) -> tuple[float, float, float]:
    aidl = pathlib.Path(sys.executable).with_name("aidl")
    script = 'for f in "$@"; do "$AIDL" check "$f" >/dev/null 2>&1; done'
    c0, t0 = cpu(), time.perf_counter()
    subprocess.run(["bash", "-c", script, "loop", *files], check=False,
                   env=dict(os.environ, AIDL=str(aidl)))
    took = time.perf_counter() - t0
    return took, len(files) / took, cpu() - c0


def batch(files: list[str], out: pathlib.Path, workers: int,
          **kw) -> tuple[float, float, float | None]:
    """(wall time, steady rate, CPU seconds): the steady rate is the one between the first row
    of each worker and the last row, which leaves out the start-up (worker processes, a
    cluster); the CPU time counts this process and its workers (not a Dask cluster's, whose
    processes are not this one's children: None)."""
    stamps = []
    c0, t0 = cpu(), time.perf_counter()
    result = run_batch(files, out, workers=workers,
                       on_row=lambda row: stamps.append(time.perf_counter()), **kw)
    took = time.perf_counter() - t0
    bad = [r["id"] for r in result["rows"] if not r["ok"]]
    assert not bad, f"programs that failed: {bad[:5]}"
    steady = (len(stamps) - workers) / (stamps[-1] - stamps[workers - 1])
    return took, steady, None if "scheduler" in kw else cpu() - c0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--files", type=int, default=100)
    ap.add_argument("--no-dask", action="store_true")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        files = corpus(tmp, args.files)
        n = len(files)
        runs = [("shell loop of `aidl check`", *shell_loop(files))]
        runs.append(("aidl batch, 1 local worker", *batch(files, tmp / "w1.jsonl", 1)))
        runs.append(("aidl batch, 2 local workers", *batch(files, tmp / "w2.jsonl", 2)))
        if not args.no_dask:
            runs.append(("aidl batch, 2-worker LocalCluster",
                         *batch(files, tmp / "dask.jsonl", 2, scheduler="local")))
    print(f"{n} programs ({min(12, n)} examples, {max(0, n - 12)} generated plates); "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    print(f"{'':36} {'wall s':>7} {'prog/s':>7} {'x loop':>7} {'steady/s':>9} {'x loop':>7} "
          f"{'CPU ms/prog':>12} {'x loop':>7} {'10,000 programs':>16}")
    loop_rate, loop_cpu = runs[0][2], runs[0][3]
    for name, took, steady, used in runs:
        rate = n / took
        startup = max(0.0, took - n / steady)
        per10k = startup + 10_000 / steady
        cpu_txt = (f"{used / n * 1000:12.1f} {loop_cpu / used:6.1f}x" if used
                   else f"{'-':>12} {'-':>7}")
        print(f"{name:36} {took:7.2f} {rate:7.1f} {rate / loop_rate:6.1f}x {steady:9.1f} "
              f"{steady / loop_rate:6.1f}x {cpu_txt} {per10k / 60:12.1f} min")


if __name__ == "__main__":
    main()
