"""How far std/gears.aidl's circular arcs lie from the true involute (docs/stdlib.md, "Gears").

For each module and tooth count, compiles ``spur_gear`` through the real pipeline, reads the
DXF back with ezdxf and measures, on 60 points of every flank arc, the normal distance to the
involute of that flank: ``r_b * |theta +- inv(acos(r_b / rho)) - (axis +- half)|`` (the
involute's normal is tangent to the base circle, so a turn of d radians moves it r_b * d).
Also reports the arcs per flank and the compile time.

    .venv/bin/python benchmarks/outputs/involute_deviation.py
"""
import io
import math
import sys
import tempfile
import time
from pathlib import Path

import ezdxf
from ezdxf.math import bulge_to_arc

import aidl_lang


def deviation(module: float, z: int, alpha_deg: float = 20.0):
    src = (f'import "std/gears.aidl"\nsolid g {{ w = spur_gear(teeth={z}, module={module} mm, '
           f'pressure_angle={alpha_deg} deg) }}\n')
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "g.aidl"
        p.write_text(src)
        t = time.perf_counter()
        r = aidl_lang.compile(source=src, path=p)
        dxf = r.to_dxf()
        secs = time.perf_counter() - t
    assert r.ok, [e.message for e in r.errors]
    doc = ezdxf.read(io.StringIO(dxf))
    (poly,) = [e for e in doc.modelspace() if e.dxftype() == "LWPOLYLINE"]
    alpha = math.radians(alpha_deg)
    rb = module * z / 2 * math.cos(alpha)
    half = math.pi / (2 * z) + math.tan(alpha) - alpha
    pts = list(poly.get_points("xyb"))
    worst, flank_arcs = 0.0, 0
    for i, (x, y, b) in enumerate(pts):
        if abs(b) < 1e-15:
            continue
        x2, y2, _ = pts[(i + 1) % len(pts)]
        c, a0, a1, rad = bulge_to_arc((x, y), (x2, y2), b)
        if math.hypot(c.x, c.y) < 1e-9:
            continue                      # tip and root arcs are centred on the gear
        flank_arcs += 1
        if a1 < a0:
            a1 += 2 * math.pi
        for k in range(61):
            a = a0 + (a1 - a0) * k / 60
            px, py = c.x + rad * math.cos(a), c.y + rad * math.sin(a)
            rho = math.hypot(px, py)
            if rho <= rb:
                continue
            th = math.atan2(py, px)
            iv = math.tan(math.acos(rb / rho)) - math.acos(rb / rho)
            worst = max(worst, rb * min(abs(math.remainder(th + s * iv - (2 * math.pi * j / z + s * half),
                                                           2 * math.pi)) for j in range(z) for s in (1, -1)))
    return worst, flank_arcs // (2 * z), secs


def main():
    print("| module | teeth | arcs per flank | max deviation (mm) | compile + DXF (s) |")
    print("|---|---|---|---|---|")
    for m in (0.5, 1, 2, 3, 5, 10):
        for z in (12, 90):
            dev, n, secs = deviation(m, z)
            print(f"| {m:g} | {z} | {n} | {dev:.1e} | {secs:.2f} |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
