"""`aidl check` of real drawings imported from other programs, whose edges crowd one another
(issue 58): time, peak memory and what the shape checks said or left unchecked.

    .venv/bin/python benchmarks/imports/dense_drawings.py                      # the default set
    .venv/bin/python benchmarks/imports/dense_drawings.py FILE.dxf FILE.svg ... --tree /work/old-6ba884a

Each drawing is imported once (``aidl import FILE -o scratch/NAME.aidl``, this tree), then
checked by each tree's ``aidl`` (``TREE/.venv/bin/aidl``) under ``/usr/bin/time -v`` with an
address-space cap (``ulimit -v``, 6 GB: the quadratic grouping of W0519 before issue 58 took
17 GB on the USA map and would take the machine down) and a 120 s timeout: wall seconds, peak
RSS (MB), the exit status, the number of segments (``Line``/``Arc``/``Bezier``/``Circle``
statements) and the count of each diagnostic code (a ``W0521`` note: a family of checks that
stopped).  The default set is ezdxf's sample maps in /work/corpus/ezdxf (not in the
repository): the world (2.9k segments), the US states (4.7k), the USA map (5.5k, 300 KB) and
the US main map (10k).
"""
from __future__ import annotations

import argparse
import collections
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CORPUS = Path("/work/corpus/ezdxf")
DEFAULT = ["examples_edgeminer_4_world.dxf", "examples_edgeminer_5_us_states.dxf",
           "examples_addons_drawing_data_usa.dxf", "examples_edgeminer_3_us_main.dxf"]


def check(tree: Path, program: Path) -> dict:
    """One capped, timed ``aidl check`` of ``program`` with ``tree``'s command."""
    aidl = tree / ".venv" / "bin" / "aidl"
    with tempfile.NamedTemporaryFile(suffix=".time") as t:
        r = subprocess.run(["bash", "-c", f'ulimit -v 6000000; /usr/bin/time -v -o {t.name} '
                                          f'timeout 120 "{aidl}" check "{program}"'],
                           capture_output=True, text=True)
        tv = Path(t.name).read_text()
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", tv)
    secs = (int(wall.group(1) or 0) * 3600 + int(wall.group(2)) * 60 + float(wall.group(3))
            if wall else float("nan"))
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", tv)
    codes = collections.Counter(re.findall(r"(?:error|warning|note)\[(\w\d{4})\]",
                                           r.stdout + r.stderr))
    more = re.findall(r"and (\d+) more of (\w\d{4})", r.stdout + r.stderr)
    for n, c in more:
        codes[c] += int(n)
    return {"s": secs, "mb": int(rss.group(1)) / 1024 if rss else float("nan"),
            "rc": r.returncode, "codes": dict(sorted(codes.items()))}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("files", nargs="*", help="drawings (.dxf/.svg); default: ezdxf's maps")
    ap.add_argument("--tree", action="append", default=[],
                    help="another tree to check with (its .venv); repeat for more")
    a = ap.parse_args()
    files = [Path(f) for f in a.files] or [CORPUS / f for f in DEFAULT]
    trees = [ROOT] + [Path(t).resolve() for t in a.tree]
    with tempfile.TemporaryDirectory() as scratch:
        for f in files:
            out = Path(scratch) / (f.stem + ".aidl")
            subprocess.run([str(ROOT / ".venv" / "bin" / "aidl"), "import", str(f), "-o",
                            str(out)], capture_output=True, text=True)
            if not out.exists():
                print(f"{f.name}: not imported")
                continue
            segs = len(re.findall(r"\b(?:Line|Arc|Bezier|Circle)\(", out.read_text()))
            for tree in trees:
                r = check(tree, out)
                print(f"{f.name} ({segs} segments) [{tree.name}]: {r['s']:.2f} s, "
                      f"{r['mb']:.0f} MB peak, exit {r['rc']}, {r['codes']}")
                sys.stdout.flush()


if __name__ == "__main__":
    main()
