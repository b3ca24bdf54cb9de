"""Load test of the studio as deployed: Locust through Debian's nginx to two studio processes
sharing one Redis, one of them killed mid-run (issue 62).

    python benchmarks/serve/studio_nginx_load.py --users 50 --minutes 5

Starts ``redis-server``, two ``aidl studio`` processes by the image's entry script
(``deploy/studio/entrypoint.sh``; ``--compilers`` each, the per-client rate raised, since every
simulated user comes from 127.0.0.1) and nginx with docs/studio.md's configuration
(benchmarks/serve/studio_cluster.py), then runs Locust headless against nginx
(benchmarks/serve/studio_nginx_locust.py: the person of studio_locust.py, who also uploads a drawing
and checks it is still there).  Halfway (``--kill-at``) one studio process and its compile
workers are killed (SIGKILL).  Prints per request: count, failures, p50/p95/max (ms); the busy
answers (503, retried by nginx on the other process, then by the page); uploads lost; and each
process's memory (the server and its compile workers, MB) every 30 s.  Needs the ``bench``
extra (Locust), the ``studio`` extra (redis), and Debian's redis-server and nginx.
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT_ = HERE.parents[1]
sys.path.insert(0, str(ROOT_))

from benchmarks.serve.studio_cluster import (free_port, get, nginx, redis_server,  # noqa: E402
                                       studio_processes)


def rss_mb(pid: int) -> int:
    try:
        with open(f"/proc/{pid}/statm") as f:
            return round(int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20)
    except OSError:
        return 0


def memory(procs, ports) -> list:
    """Per studio process: ``[server MB, [worker MB, ...]]`` (None once killed)."""
    out = []
    for proc, port in zip(procs, ports):
        if proc.poll() is not None:
            out.append(None)
            continue
        try:
            stats = json.loads(get(f"http://127.0.0.1:{port}/api/stats", 10)[1])
            out.append([rss_mb(proc.pid), [round(w["rss"] / 2**20) for w in stats["workers"]]])
        except (OSError, ValueError):
            out.append([rss_mb(proc.pid), []])
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--users", type=int, default=50)
    ap.add_argument("--minutes", type=float, default=5.0)
    ap.add_argument("--compilers", type=int, default=1, help="compile workers per process")
    ap.add_argument("--kill-at", type=float, default=0.5,
                    help="fraction of the run after which one studio process is killed")
    ap.add_argument("--spawn-rate", type=float, default=5.0)
    args = ap.parse_args()
    ports = [free_port(), free_port()]
    env = {"AIDL_STUDIO_COMPILERS": str(args.compilers), "AIDL_STUDIO_RATE": "1000000/minute"}
    with redis_server() as (url, _redis), \
            studio_processes(ports, {**env, "AIDL_STUDIO_STORE": url}) as procs, \
            nginx(free_port(), ports) as front, \
            tempfile.TemporaryDirectory() as tmp:
        prefix = Path(tmp) / "load"
        out = Path(tmp) / "counts.json"
        seconds = int(args.minutes * 60)
        t0 = time.monotonic()
        run = subprocess.Popen(
            [sys.executable, "-m", "locust", "-f", str(HERE / "studio_nginx_locust.py"),
             "--headless", "-u", str(args.users), "-r", str(args.spawn_rate),
             "-t", f"{seconds}s", "--host", front.rstrip("/"), "--csv", str(prefix),
             "--only-summary", "--loglevel", "WARNING"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
            env={**os.environ, "AIDL_LOAD_OUT": str(out)})
        samples, killed = [], None
        while run.poll() is None:
            time.sleep(1)
            now = time.monotonic() - t0
            if killed is None and now >= args.kill_at * seconds:
                samples.append((round(now), memory(procs, ports)))
                os.killpg(procs[0].pid, signal.SIGKILL)
                procs[0].wait()
                killed = round(now)
            if now >= 30 * (len(samples) + 1):
                samples.append((round(now), memory(procs, ports)))
        _, err = run.communicate()
        took = time.monotonic() - t0
        rows = list(csv.DictReader(open(f"{prefix}_stats.csv")))
        failures = list(csv.DictReader(open(f"{prefix}_failures.csv")))
        counts = json.loads(out.read_text()) if out.exists() else {}
        end = memory(procs, ports)
    print(f"{args.users} users, {args.minutes:g} min ({took:.0f} s) through nginx to 2 studio "
          f"processes x {args.compilers} compilers, one Redis; process 1 killed at {killed} s")
    print(f"{'request':<28}{'count':>7}{'fail':>6}{'p50 ms':>9}{'p95 ms':>9}{'max ms':>9}")
    for r in rows:
        print(f"{r['Name'][:27]:<28}{r['Request Count']:>7}{r['Failure Count']:>6}"
              f"{r['50%']:>9}{r['95%']:>9}{float(r['Max Response Time']):>9.0f}")
    for f in failures:
        print(f"failure: {f['Method']} {f['Name']}: {f['Error'][:160]} x{f['Occurrences']}")
    print(f"busy answers (503): {counts.get('busy')}; uploads lost: {counts.get('lost')}")
    print("memory MB [server, [workers]] per process:")
    for t, m in samples + [("end", end)]:
        print(f"  {t}s: {m}" if t != "end" else f"  end: {m}")
    if run.returncode not in (0, 1):
        print(err[-2000:], file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
