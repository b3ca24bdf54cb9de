"""The live preview's slider, end to end: the time from a customizer message sent over the
WebSocket to the picture's frame received, through the real ``aidl serve`` (uvicorn,
Starlette, the warm session) and a real client (``websockets``).

    python benchmarks/serve/slider_ws.py [OLD_TREE ...] [--file examples/gear_pair.aidl]
                                   [--param pinion_teeth --values 13,14] [--moves 20]
                                   [--rest 0.6] [--rounds 2]

Each tree (this checkout first, then every OLD_TREE, e.g. a ``git archive`` of an older
commit) serves the file in its own process (``PYTHONPATH=TREE``, run from a temporary
directory, bytecode compiled first); the trees take turns for ``--rounds`` rounds.  A round
waits for the first picture, makes two moves that are not counted, then ``--moves`` moves: each
sends ``{"type": "set", "id": k, "values": {param: value}}`` and waits for the frame answering
``id`` k (the picture; the shape checks follow it ``CHECKS_DELAY`` later, after the slider
rests).  After each picture the client rests ``--rest`` seconds, so every move starts at a quiet
moment, as a user lets go of a slider and looks.  Prints, per tree, the median, the 90th
percentile and the worst move in milliseconds (wall clock: what the user waits), the median
of the server's CPU time during a move (all its threads: robust on a loaded machine, where the
wall clock is not) and the server's CPU per move, the rests included (the shape checks and the
idle-time collection).

Issue 38's target: the ``gear_pair`` slider at most 150 ms in the server at a quiet moment.
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
from benchmarks.serve.serve_latency import serving  # noqa: E402  (the server's start and stop)

ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPATH")}


def cpu_of(pid: int) -> float:
    """The process's time on a CPU so far in seconds, all its threads (Linux
    ``/proc/PID/task/*/schedstat``, nanoseconds; a thread that ended meanwhile is not
    counted, so read it around spans in which the server's threads live on)."""
    total = 0
    for task in Path(f"/proc/{pid}/task").iterdir():
        try:
            total += int((task / "schedstat").read_text().split()[0])
        except (FileNotFoundError, ProcessLookupError):
            pass
    return total / 1e9


def one_round(tree: Path, file: Path, param: str, values: list[str], moves: int,
              rest: float) -> tuple[list[float], list[float], float]:
    """Serve ``file`` from ``tree`` and make the moves: (wall ms of each move, the server's
    CPU ms during each move, the server's CPU ms per move with the rests)."""
    from websockets.sync.client import connect
    env = dict(ENV, PYTHONPATH=str(tree))
    with tempfile.TemporaryDirectory() as cwd, \
            serving([sys.executable, "-m", "aidl_lang.cli"], file, Path(cwd), env,
                    timeout=300) as (url, proc):
        walls, cpus = [], []
        with connect(url.replace("http://", "ws://") + "ws", max_size=None,
                     open_timeout=120) as ws:
            first = json.loads(ws.recv(timeout=300))
            if first.get("type") != "view":
                raise SystemExit(f"{tree}: the first frame is not a view: {first}")
            time.sleep(rest)
            cpu0 = None
            for k in range(moves + 2):
                if k == 2:
                    cpu0 = cpu_of(proc.pid)
                value = values[k % len(values)]
                t, c = time.perf_counter(), cpu_of(proc.pid)
                ws.send(json.dumps({"type": "set", "id": k, "values": {param: value}}))
                while True:
                    msg = json.loads(ws.recv(timeout=300))
                    if msg.get("type") == "view" and msg.get("id") == k:
                        break
                    if msg.get("type") == "error":
                        raise SystemExit(f"{tree}: {msg}")
                wall = time.perf_counter() - t
                cpu_move = cpu_of(proc.pid) - c
                if not msg.get("ok", True) or msg.get("svg") is None:
                    raise SystemExit(f"{tree}: the move to {param}={value} failed: "
                                     f"{str(msg.get('diagnostics'))[:400]}")
                if k >= 2:
                    walls.append(wall * 1000)
                    cpus.append(cpu_move * 1000)
                time.sleep(rest)
            # the CPU of the moves, their checks included (they run during the rests)
            cpu = (cpu_of(proc.pid) - cpu0) * 1000 / moves
        return walls, cpus, cpu


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("trees", nargs="*", type=Path, help="older trees to compare with")
    ap.add_argument("--file", type=Path, default=ROOT / "examples" / "gear_pair.aidl")
    ap.add_argument("--param", default="pinion_teeth")
    ap.add_argument("--values", default="13,14", help="the values the moves take in turn")
    ap.add_argument("--moves", type=int, default=20)
    ap.add_argument("--rest", type=float, default=0.6, help="seconds between moves")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--verbose", action="store_true", help="print every move")
    a = ap.parse_args()
    trees = [ROOT] + [t.resolve() for t in a.trees]
    for t in trees:
        subprocess.run([sys.executable, "-m", "compileall", "-q", str(t / "aidl_lang")],
                       env=ENV, check=True, stdout=subprocess.DEVNULL)
    file = a.file.resolve()
    values = [v.strip() for v in a.values.split(",")]
    print(f"{file.name}: {a.moves} moves of {a.param} over {values}, {a.rest} s apart, "
          f"{a.rounds} rounds; wall ms from the message sent to the picture received")
    print(f"{'tree':40} {'median':>8} {'p90':>8} {'worst':>8} {'CPU in':>8} {'CPU all':>8}")
    print(f"{'':40} {'':>8} {'':>8} {'':>8} {'median':>8} {'per move':>8}")
    for r in range(a.rounds):
        for t in trees:
            walls, cpus, cpu = one_round(t, file, a.param, values, a.moves, a.rest)
            q = statistics.quantiles(walls, n=10, method="inclusive")
            if a.verbose:
                print("   wall", " ".join(f"{w:.0f}" for w in walls))
                print("   CPU ", " ".join(f"{w:.0f}" for w in cpus))
            print(f"{str(t)[-40:]:40} {statistics.median(walls):8.1f} {q[-1]:8.1f} "
                  f"{max(walls):8.1f} {statistics.median(cpus):8.1f} {cpu:8.1f}", flush=True)


if __name__ == "__main__":
    main()
