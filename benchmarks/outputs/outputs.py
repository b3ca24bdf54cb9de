"""Output speed: the booleans, the arc recovery and each writer, on the largest bundled example
and on a generated 500-part assembly (docs/outputs.md, "Speed").

Run:  .venv/bin/python benchmarks/outputs/outputs.py

Prints one table: for each model, the time of the solve (for scale), the booleans and the shape
checks (``render_model`` + ``check_drawing``), the exact output model (``build``: arc recovery),
and each writer (``encode`` to .svg, .dxf, .png, .stl, .3mf, .step) with the output's size.  Times are
the best of 3 runs (one for STEP), in milliseconds, on this machine.
"""
from __future__ import annotations

import math
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.base.diagnostics import DiagnosticSink  # noqa: E402
from aidl_lang.output import Options, build, encode, render_model  # noqa: E402
from aidl_lang.output.checks import check_drawing  # noqa: E402
from aidl_lang.output.part.part import MissingDependency  # noqa: E402
from aidl_lang.pipeline import compile_source  # noqa: E402


def generated(n: int = 500) -> str:
    """An assembly of ``n`` plates in rows of 20, each a rounded rectangle with a bore and a
    slot: every part has lines, corner arcs and circles."""
    rows = math.ceil(n / 20)
    return f"""assembly sheet {{
    for i in range({rows}) {{
        for j in range(20) {{
            solid plate {{
                body = RoundedRectangle(center=(j * 30, i * 30), width=24, height=24, corner_radius=3)
                hole bore {{ c = Circle(center=(j * 30 - 4, i * 30), radius=4) }}
                hole slot {{ s = Slot(center=(j * 30 + 6, i * 30), length=10, width=3, rotation=90 deg) }}
            }}
        }}
    }}
}}
"""


def best_of(fn, reps: int = 3):
    best, out = math.inf, None
    for _ in range(reps):
        t = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t)
    return best * 1000, out


def row(name: str, src: str, path: str) -> None:
    t_compile, c = best_of(lambda: compile_source(src, path), 1)
    assert c.ok, [d.message for d in c.sink.items]
    t_bool, d = best_of(lambda: render_model(c.model))
    t_check, _ = best_of(lambda: check_drawing(d, DiagnosticSink()))
    t_build, o = best_of(lambda: build(d, c.model.root.name))
    segs = sum(len(lp.segments) for p in o.parts for lp in p.loops)
    cells = [name, f"{len(o.parts)}", f"{segs}", f"{t_compile:.0f}", f"{t_bool:.0f}",
             f"{t_check:.0f}", f"{t_build:.0f}"]
    for ext in (".svg", ".dxf", ".png", ".stl", ".3mf", ".step"):
        try:
            t, data = best_of(lambda: encode(o, ext, Options()), 1 if ext == ".step" else 3)
        except MissingDependency:
            cells.append("n/a (extra not installed)")
            continue
        cells.append(f"{t:.0f} ({len(data) // 1024} KiB)")
    print("| " + " | ".join(cells) + " |")


def main() -> None:
    heads = ["model", "parts", "segments", "compile (incl. booleans, checks)", "booleans",
             "checks", "arc recovery", "svg", "dxf", "png", "stl", "3mf", "step"]
    print("| " + " | ".join(heads) + " |")
    print("|" + "---|" * len(heads))
    examples = sorted((ROOT / "examples").glob("*.aidl"))
    sizes = []
    for p in examples:
        c = compile_source(p.read_text(), str(p))
        o = build(c.drawing)
        sizes.append((sum(len(lp.segments) for q in o.parts for lp in q.loops) +
                      sum(len(s.segments) for s in o.engrave), p))
    largest = max(sizes)[1]
    row(largest.stem, largest.read_text(), str(largest))
    row("generated 500 parts", generated(500), "generated.aidl")


if __name__ == "__main__":
    main()
