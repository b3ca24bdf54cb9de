"""Cutting-layout speed: 50 parts of five shapes (plates, discs, L brackets, slotted bars,
gear-like stars) laid out on 600 x 400 mm sheets with spyrrow (docs/outputs.md, "Cutting an
assembly"), and the kerf offset of every part.

Run:  .venv/bin/python benchmarks/outputs/layout.py [--parts N] [--seconds S]

Prints the compile time (for scale), the kerf offset, the nesting plan (``plan``: outlines,
spyrrow, the sheets) and the placing of the exact segments, in milliseconds (best of 3), with
the number of sheets and the sheet area used.  ``--seconds`` gives the packer time to improve
its first packing (default 0, what ``aidl render --layout sheet`` does by default).
"""
from __future__ import annotations

import argparse
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.output import build  # noqa: E402
from aidl_lang.output.fabrication.layout import compensate, place, plan  # noqa: E402
from aidl_lang.pipeline import compile_source  # noqa: E402

SHAPES = [
    "body = RoundedRectangle(center=({x}, {y}), width=60, height=40, corner_radius=5)\n"
    "hole h {{ c = Circle(center=({x}, {y}), radius=8) }}",
    "body = Circle(center=({x}, {y}), radius=22)\n"
    "hole h {{ c = Circle(center=({x}, {y}), radius=5) }}",
    "body = Polygon(points=[({x}, {y}), ({x} + 50, {y}), ({x} + 50, {y} + 12), "
    "({x} + 12, {y} + 12), ({x} + 12, {y} + 40), ({x}, {y} + 40)])",
    "body = Slot(start=({x}, {y}), end=({x} + 70, {y}), width=14)\n"
    "hole h {{ s = Slot(start=({x} + 15, {y}), end=({x} + 55, {y}), width=5) }}",
    "body = RegularPolygon(center=({x}, {y}), radius=25, sides=7)",
]


def source(n: int) -> str:
    rows = []
    for i in range(n):
        x, y = (i % 10) * 90, (i // 10) * 90
        rows.append(f"    solid p{i} {{\n        " +
                    SHAPES[i % len(SHAPES)].format(x=x, y=y).replace("\n", "\n        ") +
                    "\n    }")
    return "units mm\nassembly parts {\n" + "\n".join(rows) + "\n}\n"


def best(f, k=3):
    out, t = None, float("inf")
    for _ in range(k):
        t0 = time.perf_counter()
        out = f()
        t = min(t, time.perf_counter() - t0)
    return out, t * 1e3


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--parts", type=int, default=50)
    ap.add_argument("--seconds", type=int, default=0)
    a = ap.parse_args()
    src = source(a.parts)
    t0 = time.perf_counter()
    res = compile_source(src, "bench.aidl")
    assert res.ok, [d.message for d in res.sink.items]
    out = build(res.drawing, "parts")
    t_compile = (time.perf_counter() - t0) * 1e3
    cut, t_kerf = best(lambda: compensate(out, 0.15))
    sheet = (600.0, 400.0)
    where, t_plan = best(lambda: plan(cut, sheet, 3.0, (0.0, 90.0), a.seconds),
                         1 if a.seconds else 3)
    (sheets, _), t_place = best(lambda: place(cut, where, sheet))
    used = sum(p.area for s in sheets for p in s.parts) / (len(sheets) * sheet[0] * sheet[1])
    print(f"{a.parts} parts: compile {t_compile:.0f} ms, kerf {t_kerf:.1f} ms, "
          f"plan {t_plan:.0f} ms (spyrrow, {a.seconds} s to improve), place {t_place:.1f} ms; "
          f"{len(sheets)} sheet(s) of 600 x 400 mm, {used:.0%} of the sheet area used")


if __name__ == "__main__":
    main()
