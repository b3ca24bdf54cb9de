"""How the geometry checks on the final shape scale with the number of holes
(docs/outputs.md, "Checks").

Run:  .venv/bin/python benchmarks/checks/checks_scaling.py [N ...]

Compiles a generated plate with N round holes on a square grid (default N = 100, 400, 900;
radius 2 mm) and times ``check_drawing`` on its booleans' result, best of 3 runs, in
milliseconds on this machine, with two of its stages apart: the holes (W0501-W0503, each
hole against its neighbourhood) and the webs and merges (W0507 measured, W0508), and the
number of warnings.  Two grids: pitch 6 mm (2 mm walls, nothing to warn about) and pitch
4.3 mm (0.3 mm webs: a W0507 for every two neighbours, the warning path at its busiest).
"""
from __future__ import annotations

import math
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.base.diagnostics import DiagnosticSink  # noqa: E402
from aidl_lang.output import checks as C  # noqa: E402
from aidl_lang.pipeline import compile_source  # noqa: E402


def plate(n: int, pitch: float = 6.0, r: float = 2.0) -> str:
    """A plate with ``n`` holes of radius ``r`` on a grid of ``pitch`` (mm)."""
    cols = math.ceil(math.sqrt(n))
    rows = math.ceil(n / cols)
    w, h = cols * pitch, rows * pitch
    return f"""solid plate {{
    body = Rectangle(center=({w / 2}, {h / 2}), width={w}, height={h})
    for i in range({n}) {{
        hole h {{ c = Circle(center=((i % {cols}) * {pitch} + {pitch / 2}, (i // {cols}) * {pitch} + {pitch / 2}), radius={r}) }}
    }}
}}
"""


def best(fn, runs: int = 3) -> float:
    t = math.inf
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        t = min(t, time.perf_counter() - t0)
    return 1000 * t


def main(sizes) -> None:
    print(f"{'pitch':>5} {'holes':>6} {'holes ms':>9} {'webs ms':>8} {'check_drawing ms':>17} "
          f"{'warnings':>9}")
    for pitch in (6.0, 4.3):
        for n in sizes:
            c = compile_source(plate(n, pitch), f"grid{n}.aidl", min_wall=0)
            assert c.ok and c.drawing is not None, [d.message for d in c.sink.items]
            d = c.drawing
            roots = C._part_roots(d)
            part, shape = next(iter(roots.items()))
            loops = {part: [p for p in shape.to_polygons()]}

            def holes():            # as check_drawing runs them: one owner area per part
                near = C._Near(roots, loops, d.cuts)
                owner_areas: dict = {}
                for cut in d.cuts:
                    C._check_hole(d, cut, roots, DiagnosticSink(), near.local, owner_areas)

            def webs():
                a = C._analyse(d, part, shape, d.cuts, C.MIN_WALL)
                C._report_openings(a, part, C.MIN_WALL, DiagnosticSink())
            sink = DiagnosticSink()
            ms = best(lambda: C.check_drawing(d, DiagnosticSink()))
            C.check_drawing(d, sink)
            print(f"{pitch:>5} {n:>6} {best(holes):>9.1f} {best(webs):>8.1f} {ms:>17.1f} "
                  f"{len(sink.items):>9}")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [100, 400, 900])
