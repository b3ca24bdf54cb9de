"""What Offset and Hull cost (docs/language.md, "Offset, Inset, Shell" and "Hull").

Run:  .venv/bin/python benchmarks/outputs/derived_shapes.py

Compiles (parse, check, solve, booleans, shape checks) a 200-vertex wavy polygon alone and
offset by +2 mm, -2 mm and +2 mm mitered, and 40 circles alone and with their Hull; median of
5 runs after a warm-up, milliseconds on this machine.  The difference to "alone" is the
offset's or hull's own cost: the sweeps of every segment united by Manifold and put back on
the exact curves, or the hull's sampling and exact tangents.
"""
from __future__ import annotations

import math
import pathlib
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.pipeline import compile_source  # noqa: E402


def _prog(body: str) -> str:
    return "solid p {\n" + body + "\n}\n"


def cases() -> dict[str, str]:
    ts = [2 * math.pi * i / 200 for i in range(200)]
    pts = [(30 * (1 + 0.3 * math.cos(7 * t)) * math.cos(t),
            30 * (1 + 0.3 * math.cos(7 * t)) * math.sin(t)) for t in ts]
    poly = "    s = Polygon([" + ", ".join(f"({x:.4f}, {y:.4f})" for x, y in pts) + "])"
    circles = "\n".join(f"    c{i} = Circle(center=({30 * math.cos(i)!r}, {30 * math.sin(i)!r}), "
                        f"radius={1 + i % 5})" for i in range(40))
    return {
        "polygon200 alone": _prog(poly),
        "polygon200 Offset 2": _prog(poly + "\n    o = Offset(s, 2)"),
        "polygon200 Offset -2": _prog(poly + "\n    o = Offset(s, -2)"),
        "polygon200 Offset 2 miter": _prog(poly + '\n    o = Offset(s, 2, join="miter")'),
        "40 circles alone": _prog(circles),
        "Hull of 40 circles": _prog(circles + "\n    h = Hull([" +
                                    ", ".join(f"c{i}" for i in range(40)) + "])"),
    }


def main() -> None:
    for name, src in cases().items():
        compile_source(src, "t.aidl")
        ts = []
        for _ in range(5):
            t0 = time.perf_counter()
            c = compile_source(src, "t.aidl")
            ts.append(time.perf_counter() - t0)
            assert c.ok, [d.message for d in c.sink.items]
        print(f"{name:28s} median {sorted(ts)[2] * 1000:7.1f} ms")


if __name__ == "__main__":
    main()
