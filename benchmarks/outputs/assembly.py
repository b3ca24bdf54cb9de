"""The time to assemble and check a product (issue 40): a 6-panel finger box (std/joints.aidl's
``finger_box``, placed by itself) and a 40-part egg-crate divider (20 slats each way,
cross-halved at their 400 crossings, each slat placed with ``Place``):

    python benchmarks/outputs/assembly.py                 # both models, 3 runs each, medians
    python benchmarks/outputs/assembly.py --runs 5 --slats 10

Printed per model: the compile without the fit check (parse, solve, booleans, the 2D checks),
the fit check alone (:func:`aidl_lang.output.fabrication.assembly.fit`: the placed solids, every pair
whose boxes meet intersected with Manifold), the assembled 3MF and GLB writers, and the
warnings found (none for both: the box's fingers and the crate's slots fit).  Wall-clock
seconds on a shared machine: compare side by side, not across days.
"""
from __future__ import annotations

import argparse
import statistics
import time

BOX = """import "std/joints.aidl"
thickness 3 mm
assembly kit { box = finger_box(length=120 mm, depth=80 mm, height=50 mm, thickness=3 mm) }
"""


def egg_crate(n: int = 20, pitch: float = 20.0, t: float = 3.0, h: float = 30.0) -> str:
    """An egg-crate divider of ``n`` slats each way (2n parts), ``pitch`` mm apart, ``t`` mm
    material, ``h`` mm high: the x slats slotted from the top, the y slats from the bottom,
    each slot ``t`` wide and ``h / 2`` deep, laid out in rows on the sheet and placed."""
    length = (n + 1) * pitch
    xs = [(k - (n - 1) / 2) * pitch for k in range(n)]
    out = [f"thickness {t} mm", "assembly crate {"]
    for i in range(n):                      # along x, slots from the top
        row = 40 * i
        slots = "\n".join(f"            s{k} = Rectangle(center=({x}, {row + h * 0.75 + 1}), "
                          f"width={t}, height={h / 2 + 2})" for k, x in enumerate(xs))
        out.append(f"    solid xs{i} {{\n        b = Rectangle(center=(0, {row + h / 2}), "
                   f"width={length}, height={h})\n        Fixed(b)\n        hole cuts {{\n"
                   f"{slots}\n        }}\n        Fixed(cuts)\n    }}")
        out.append(f"    Place(xs{i}, rotation=(90 deg, 0, 0), position=(0, {xs[i] + t / 2}, "
                   f"{-row}))")
    for j in range(n):                      # along y, slots from the bottom
        row = 40 * (n + j)
        slots = "\n".join(f"            s{k} = Rectangle(center=({x}, {row + h / 4 - 1}), "
                          f"width={t}, height={h / 2 + 2})" for k, x in enumerate(xs))
        out.append(f"    solid ys{j} {{\n        b = Rectangle(center=(0, {row + h / 2}), "
                   f"width={length}, height={h})\n        Fixed(b)\n        hole cuts {{\n"
                   f"{slots}\n        }}\n        Fixed(cuts)\n    }}")
        out.append(f"    Place(ys{j}, rotation=(90 deg, 0, 90 deg), position=({xs[j] - t / 2}, "
                   f"0, {-row}))")
    out.append("}")
    return "\n".join(out) + "\n"


def measure(name: str, src: str, runs: int) -> None:
    import aidl_lang
    from aidl_lang.output import Options, build, encode
    from aidl_lang.output.fabrication.assembly import extrude, fit, normals_of
    from aidl_lang.output import checks
    t_compile, t_fit, t_3mf, t_glb = [], [], [], []
    saved = checks._check_fit
    for _ in range(runs):
        checks._check_fit = lambda *a, **k: None          # the compile without the fit check
        try:
            t0 = time.perf_counter()
            r = aidl_lang.compile(src, f"/tmp/{name}.aidl", budget=100)
            t_compile.append(time.perf_counter() - t0)
        finally:
            checks._check_fit = saved
        assert r.ok, [str(d) for d in r.diagnostics]
        d = r.output.drawing
        t0 = time.perf_counter()
        parts = [(p.name, p.kind, p.shape, d.thickness.get(p.name)) for p in d.parts]
        hits, gaps = fit(extrude(parts, d.placement), normals=normals_of(d.placement))
        t_fit.append(time.perf_counter() - t0)
        out = build(d)
        t0 = time.perf_counter()
        encode(out, ".3mf", Options(assembled=True))
        t_3mf.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        encode(out, ".glb", Options(assembled=True))
        t_glb.append(time.perf_counter() - t0)
    med = statistics.median
    print(f"{name}: {len(d.placement)} parts; compile {med(t_compile):.3f} s, fit check "
          f"{med(t_fit):.3f} s, assembled 3MF {med(t_3mf):.3f} s, GLB {med(t_glb):.3f} s; "
          f"{len(hits)} collisions, {len(gaps)} gaps (median of {runs})")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--slats", type=int, default=20, help="slats each way (2 x this parts)")
    a = ap.parse_args()
    measure("finger_box", BOX, a.runs)
    measure(f"egg_crate_{2 * a.slats}", egg_crate(a.slats), a.runs)


if __name__ == "__main__":
    main()
