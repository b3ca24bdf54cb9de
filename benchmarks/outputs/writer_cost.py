"""What each output writer costs (issue 26: the writers inside the budget), and how far
:func:`aidl_lang.output.writers.writer_seconds` — the estimate `aidl render` uses to refuse a
writer sure to end past the deadline — is above it:

    python benchmarks/outputs/writer_cost.py                  # N = 500, 2000; every format
    python benchmarks/outputs/writer_cost.py --n 1000 --formats .svg,.dxf

Two programs per N: ``parts`` (an assembly of N one-circle parts: the per-part cost) and
``holes`` (one plate with about N round holes: the per-segment cost).  Each is compiled once
(``budget=100``, so a busy machine does not end it), its exact output built, and each format
encoded once in this process; printed: the writer's wall time, seconds per item (part, loop
or segment) or per vertex (STL, 3MF), and ``estimate / measured`` (the constants in
``aidl_lang/output/writers/__init__.py``, each Format's per_item or per_vertex, are these
figures rounded up about twice, so the ratio stays above 1 on a busy machine; SVG's and DXF's
are a quiet machine's CPU per item, so their ratio is about 1 on a quiet machine and under it
on a busy one: they are refused only when sure to end past the deadline).  A format whose library is missing is skipped; STEP is slow (about 2 ms a loop), so
it runs on the N = 500 programs only unless named with ``--formats``."""
from __future__ import annotations

import argparse
import time

PROGRAMS = {
    "parts": ("assembly top {{\n  for i in range({n}) {{\n"
              "    solid p {{ c = Circle(center=(i * 30, 0), radius=5) }}\n  }}\n}}\n"),
    "holes": ("solid plate {{\n  body = Rectangle(center=(0, 0), width={w}, height={w})\n"
              "  for i in range({k}) {{ for j in range({k}) {{\n"
              "    hole h {{ c = Circle(center=({o} + i * 30, {o} + j * 30), radius=5) }}\n"
              "  }} }}\n}}\n"),
}
FORMATS = (".svg", ".dxf", ".png", ".stl", ".3mf", ".step")


def source(kind: str, n: int) -> str:
    k = max(1, round(n ** 0.5))
    return PROGRAMS[kind].format(n=n, k=k, w=k * 30 + 40, o=-k * 15 + 15)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[500, 2000])
    ap.add_argument("--formats", default=None, help="comma-separated suffixes (default: all)")
    args = ap.parse_args()
    from aidl_lang.base.limits import DEFAULT_BUDGET
    from aidl_lang.output import MissingDependency, Options, OutputError, build, encode
    from aidl_lang.output.writers import FORMATS, writer_seconds
    from aidl_lang.pipeline import compile_source
    print(f"{'program':>12} {'format':>6} {'items':>7} {'vertices':>9} {'seconds':>8} "
          f"{'us/unit':>8} {'estimate/measured':>18}")
    for n in args.n:
        for kind in PROGRAMS:
            c = compile_source(source(kind, n), f"{kind}.aidl", budget=DEFAULT_BUDGET.scaled(100))
            assert c.ok, [d.message for d in c.sink.items]
            out = build(c.drawing, kind)
            items = sum(1 + len(p.loops) + sum(len(lp.segments) for lp in p.loops)
                        for p in out.parts)
            verts = sum(p.shape.num_vert() for p in c.drawing.parts)
            formats = (args.formats.split(",") if args.formats else
                       [f for f in FORMATS if f != ".step" or n <= 500])
            for suffix in formats:
                t0 = time.perf_counter()
                try:
                    encode(out, suffix, Options())
                except (MissingDependency, OutputError) as e:
                    print(f"{kind + str(n):>12} {suffix:>6}  skipped: {str(e)[:60]}")
                    continue
                dt = time.perf_counter() - t0
                unit = verts if FORMATS[suffix].per_vertex else items
                print(f"{kind + str(n):>12} {suffix:>6} {items:>7} {verts:>9} {dt:>8.3f} "
                      f"{dt / unit * 1e6:>8.1f} {writer_seconds(out, suffix) / dt:>18.2f}",
                      flush=True)


if __name__ == "__main__":
    main()
