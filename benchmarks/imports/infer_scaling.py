"""``aidl import --infer`` of perforated panels (issue 83): CPU seconds against the holes, and
against the plain import of the same file, before and after in one run.

Run:  .venv/bin/python benchmarks/imports/infer_scaling.py [--sizes N ...] [--tree PATH] [--timeout S]

The panel: a plate (a closed LWPOLYLINE) with round holes of r 3 mm on a 10 mm pitch (the
issue's): 2,000 = 50 x 40, 5,000 = 100 x 50, 20,000 = 141 x 141 (19,881), 50,000 = 250 x 200;
the 50,000-hole panel is past the 50,000 geometry objects of a program, so it runs with
``--budget 2`` (as in the issue), the others with the default budget (15 s).

Each command (``aidl import --infer FILE -o out.aidl``, and ``aidl import`` without it) runs
in a fresh process (``python -m aidl_lang.cli``, the tree on ``PYTHONPATH``); its CPU (user +
system, ``os.wait4``: start-up and imports included) is the figure, as
``/usr/bin/time -f "%U+%S s"`` gives it (``benchmarks/checks/perforated.py``'s ``run``).
``status``: ``ok``, the first error code printed (``E0304``: past the budget, or refused
before the work from the counts), or ``timeout``
(``--timeout`` seconds of wall time, default 300).  ``--tree PATH`` runs the same commands on
another checkout too (e.g. the tree before the change, from ``git archive``), its rows beside
this tree's.  The machine is shared: read CPU seconds, never wall time.  Nothing is asserted
here; the counts that must stay linear are held by ``tests/test_import_infer_scaling.py``.
"""
from __future__ import annotations

import argparse
import os
import pathlib
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from benchmarks.checks.perforated import run, write_dxf  # noqa: E402
SIZES = {2000: (50, 40), 5000: (100, 50), 20000: (141, 141), 50000: (250, 200)}


def write_panel(path, nx: int, ny: int, pitch: float = 10.0, r: float = 3.0) -> None:
    """A DXF (R2010, mm) of an ``nx`` x ``ny`` grid of holes of radius ``r`` in a plate."""
    W, H = nx * pitch, ny * pitch
    write_dxf(path, [(0, 0), (W, 0), (W, H), (0, H)],
              [(pitch / 2 + i * pitch, pitch / 2 + j * pitch, r)
               for j in range(ny) for i in range(nx)])


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sizes", type=int, nargs="*", default=list(SIZES), choices=list(SIZES))
    ap.add_argument("--tree", type=pathlib.Path, help="another checkout to run beside this one")
    ap.add_argument("--timeout", type=float, default=300.0)
    a = ap.parse_args(argv)
    trees = [("this", ROOT)] + ([("tree", a.tree.resolve())] if a.tree else [])
    print(f"{'holes':>7} {'tree':5} {'infer s':>8} {'status':8} {'plain s':>8} {'status':8}")
    with tempfile.TemporaryDirectory() as tmp:
        for n in a.sizes:
            nx, ny = SIZES[n]
            f = pathlib.Path(tmp) / f"panel{n}.dxf"
            write_panel(f, nx, ny)
            budget = ["--budget", "2"] if nx * ny > 50_000 - 4 else []
            for label, tree in trees:
                base = [sys.executable, "-m", "aidl_lang.cli", "import", str(f), *budget]
                env = dict(os.environ, PYTHONPATH=str(tree))
                ti, _, si, _ = run(base + ["--infer", "-o", "infer.aidl"], env, tmp, a.timeout)
                tp, _, sp, _ = run(base + ["-o", "plain.aidl"], env, tmp, a.timeout)
                print(f"{nx * ny:>7} {label:5} {ti:8.2f} {si:8} {tp:8.2f} {sp:8}", flush=True)


if __name__ == "__main__":
    main()
