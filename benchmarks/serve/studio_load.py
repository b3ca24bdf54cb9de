"""Load test of ``aidl studio``: simulated people editing and downloading, driven by Locust.

    python benchmarks/serve/studio_load.py --users 50 --minutes 3
    python benchmarks/serve/studio_load.py --users 200 --minutes 1

Starts ``aidl studio --port 0`` (``--processes``, ``--compilers``; the per-client rate limit
raised, since every simulated user comes from 127.0.0.1), then runs Locust headless against it
(``locust -f benchmarks/serve/studio_locust.py``).  Each simulated user opens a session, picks a design
from the gallery and then, every 2-6 s (a person moving a slider, reading the picture), sends a
changed value (``POST /api/view``); one action in ten is a download (DXF of the cutting sheet,
or the 3D GLB).  It prints the preview latency (p50/p95/worst, ms), the answers by status
(``503`` is the studio's "busy" answer, shown on the page; any other non-200 is an error), and
the compile workers' memory at the start and the end (``GET /api/stats``).  Needs the ``bench``
extra (``pip install -e ".[bench]"``).
"""
from __future__ import annotations

import argparse
import csv
import json
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT_ = HERE.parents[1]
sys.path.insert(0, str(ROOT_))

from benchmarks.serve.studio_server import studio  # noqa: E402


def stats(url: str) -> dict:
    with urllib.request.urlopen(url + "api/stats", timeout=30) as r:
        return json.loads(r.read())


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--users", type=int, default=50)
    ap.add_argument("--minutes", type=float, default=3.0)
    ap.add_argument("--processes", type=int, default=1)
    ap.add_argument("--compilers", type=int, default=2)
    ap.add_argument("--spawn-rate", type=float, default=5.0)
    args = ap.parse_args()
    with studio("--processes", str(args.processes), "--compilers", str(args.compilers),
                "--rate", "1000000/minute") as (url, _proc):
        with tempfile.TemporaryDirectory() as tmp:
            prefix = Path(tmp) / "load"
            t0 = time.monotonic()
            run = subprocess.Popen(
                [sys.executable, "-m", "locust", "-f", str(HERE / "studio_locust.py"),
                 "--headless", "-u", str(args.users), "-r", str(args.spawn_rate),
                 "-t", f"{int(args.minutes * 60)}s", "--host", url.rstrip("/"),
                 "--csv", str(prefix), "--only-summary", "--loglevel", "WARNING"],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            memory = []             # (s, [MB per worker]) every 30 s: growth shows here
            while run.poll() is None:
                time.sleep(1)
                if time.monotonic() - t0 >= 30 * (len(memory) + 1):
                    memory.append((round(time.monotonic() - t0),
                                   [round(w["rss"] / 2**20) for w in stats(url)["workers"]]))
            _, err = run.communicate()
            seconds = time.monotonic() - t0
            after = stats(url)
            rows = list(csv.DictReader(open(f"{prefix}_stats.csv")))
            failures = list(csv.DictReader(open(f"{prefix}_failures.csv")))
    print(f"{args.users} users, {args.minutes:g} min ({seconds:.0f} s), "
          f"{args.processes} process x {args.compilers} compilers")
    print(f"{'request':<28}{'count':>7}{'fail':>6}{'p50 ms':>9}{'p95 ms':>9}{'max ms':>9}")
    for r in rows:
        print(f"{r['Name'][:27]:<28}{r['Request Count']:>7}{r['Failure Count']:>6}"
              f"{r['50%']:>9}{r['95%']:>9}{float(r['Max Response Time']):>9.0f}")
    for f in failures:
        print(f"failure: {f['Method']} {f['Name']}: {f['Error'][:160]} x{f['Occurrences']}")
    print("server:", json.dumps({k: after[k] for k in ("compiles", "busy", "limited",
                                                       "timeouts")}))
    print("worker memory MB every 30 s: " + "  ".join(f"{t}s {m}" for t, m in memory)
          + f"  end {[round(w['rss'] / 2**20) for w in after['workers']]}; "
          f"restarts {[w['restarts'] for w in after['workers']]}")
    if run.returncode not in (0, 1):
        print(err[-2000:], file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
