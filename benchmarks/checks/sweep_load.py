"""One answer at any load (issue 92): ``aidl check --sweep`` of a panel of 8,000 round holes
whose ``pitch`` ranges 2-6 mm (walls thinner than 0.5 mm below 2.9 mm: holes of 2.4 mm),
run on a quiet machine and again beside two busy loops (``while True: pass``, one a core),
each in a process of its own.  The sweep's budget counts work (interpreter steps, objects,
unknowns, diagnostics, what the booleans and the fit check walk), not seconds, so the lines
it prints must be the same; prints both runs' CPU seconds, the sweep's lines, their sha256
and whether they match (exit 1 when they differ).  ``--entry ID`` sweeps a gallery design
instead (``generator/tool_holder``); ``--studio`` asks what the studio's sliders hatch
(:func:`aidl_lang.studio.hatching.sweep_ranges`: the scan and the sweep's combinations in
one budget, the request's JSON compared whole).

    PYTHONPATH=$PWD python benchmarks/checks/sweep_load.py [--holes 8000] [--busy 2]
    PYTHONPATH=$PWD python benchmarks/checks/sweep_load.py --entry generator/board_enclosure --studio

h18-work (load 6-12 on 2 cores from the other sessions; "quiet": no busy loop of ours), the
lines' sha256 quiet / busy: tool_holder ``--sweep`` 83a14b9e2172f1f8 / the same (8.7 / 9.1 s
CPU, 58 points, 42 not judged), ``--studio`` df775639a18982c8 / the same (8.2 / 8.6 s, 68
points); board_enclosure ``--sweep`` baa73fffd6fb616c / the same (5.8 / 6.8 s, 29 points, 3
not judged), ``--studio`` 3b0907d8338eacf6 / the same (6.7 / 6.7 s, 32 points); the 8,000-hole
panel 65de46dffdc31785 / the same (11.7 / 13.4 s: its 2 mm end, 31,000 overlaps, spends the
budget alone; below 4 mm not judged).
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

STUDIO = """import json, sys
from aidl_lang.studio.hatching import sweep_ranges
path = sys.argv[1]
got = sweep_ranges(os.path.dirname(path), open(path).read())
print(json.dumps(got, sort_keys=True))
"""


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


def run(path: str, studio: bool = False) -> tuple[list[str], float]:
    """The ``sweep:`` and ``W0110`` lines of ``aidl check --sweep path`` (``studio``: the
    studio's hatching JSON, one line) and its CPU seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    cmd = ([sys.executable, "-c", "import os\n" + STUDIO, path] if studio else
           [sys.executable, "-m", "aidl_lang.cli", "check", path, "--sweep"])
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=900)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    if studio:
        return [p.stdout.strip() or p.stderr.strip()[-300:]], cpu
    lines = [ln for ln in (p.stdout + p.stderr).splitlines()
             if ln.startswith("sweep:") or "W0110" in ln or "= hint" in ln]
    return lines, cpu


def digest(lines: list[str]) -> str:
    return hashlib.sha256("\n".join(lines).encode()).hexdigest()[:16]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--holes", type=int, default=8000)
    ap.add_argument("--busy", type=int, default=2)
    ap.add_argument("--entry", help="a gallery id (generator/tool_holder) instead of the panel")
    ap.add_argument("--studio", action="store_true",
                    help="the studio's hatching request instead of aidl check --sweep")
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "main.aidl")
        if a.entry:
            from aidl_lang.studio import gallery
            what = a.entry
            Path(path).write_text(next(e.source for e in gallery.entries() if e.id == a.entry))
        else:
            nx = 100
            ny = max(1, a.holes // nx)
            what = f"{nx * ny} holes"
            Path(path).write_text(panel(nx, ny))
        quiet, cpu_q = run(path, a.studio)
        busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"])
                for _ in range(a.busy)]
        try:
            loaded, cpu_l = run(path, a.studio)
        finally:
            for p in busy:
                p.kill()
                p.wait()
    same = quiet == loaded
    print(f"{what}{' (studio)' if a.studio else ''}: quiet {cpu_q:.1f} s CPU, beside {a.busy} "
          f"busy loops {cpu_l:.1f} s CPU; lines {'identical' if same else 'DIFFER'} "
          f"(sha256 {digest(quiet)}, {digest(loaded)})")
    for ln in quiet:
        print("    " + (ln if not a.studio else _short(ln)))
    if not same:
        print("  loaded:")
        for ln in loaded:
            print("    " + (ln if not a.studio else _short(ln)))
    return 0 if same else 1


def _short(line: str) -> str:
    """The studio's answer in brief: points, work, skipped, summary."""
    try:
        got = json.loads(line)
    except ValueError:
        return line
    return (f"points {got.get('points')}, work {got.get('work')}, skipped "
            f"{got.get('skipped')}: {got.get('summary')}")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
