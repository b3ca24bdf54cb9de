"""``aidl import --infer --snap TOL`` over a folder of drawings written with Bézier curves
(Boxes.py's examples: every circle and arc a cubic Bézier rounded to 3 decimals; issue 71).

Run:  .venv/bin/python benchmarks/imports/import_snap.py FOLDER [--snap 0.01] [--laser] [--max N] [-v]

For each ``.svg``/``.dxf`` of FOLDER (at most ``--max``), imported with ``--infer`` twice,
without and with ``--snap``: the share of outline and hole pieces recognised (the program's
own ``# recognised: X of Y pieces``), the ``Spline``/``Bezier`` pieces left in the program,
the circles and arcs snapped and the largest deviation (its ``# snapped`` line); both
programs compiled.  Totals per corpus.
"""
from __future__ import annotations

import argparse
import pathlib
import re
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

import aidl_lang  # noqa: E402
from aidl_lang.drawing.infer.infer import import_drawing  # noqa: E402
from aidl_lang.drawing.model import DrawingError  # noqa: E402


def _stats(text: str) -> dict:
    m = re.search(r"# recognised: (\d+) of (\d+) pieces", text)
    s = re.search(r"# snapped .*?: (\d+) Bézier circles and (\d+) Bézier arcs.*?deviation "
                  r"([\d.e-]+) mm", text)
    return {"recog": int(m.group(1)) if m else 0, "pieces": int(m.group(2)) if m else 0,
            "splines": len(re.findall(r"\b(Spline|Bezier|BezierChain|BSpline)\(", text)),
            "circles": int(s.group(1)) if s else 0, "arcs": int(s.group(2)) if s else 0,
            "dev": float(s.group(3)) if s else 0.0}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("folder")
    ap.add_argument("--snap", type=float, default=0.01)
    ap.add_argument("--laser", action="store_true")
    ap.add_argument("--max", type=int, default=1000)
    ap.add_argument("-v", action="store_true")
    args = ap.parse_args(argv)
    files = sorted(p for p in pathlib.Path(args.folder).iterdir()
                   if p.suffix.lower() in (".svg", ".dxf"))[:args.max]
    tot = {k: 0 for k in ("files", "bad", "recog0", "recog1", "pieces0", "pieces1",
                          "splines0", "splines1", "circles", "arcs", "compiled0", "compiled1")}
    worst = 0.0
    t0 = time.process_time()
    for f in files:
        opts = {"roles": "laser"} if args.laser else {}
        try:
            a, _ = import_drawing(f.read_bytes(), f.name, infer=True, **opts)
            b, _ = import_drawing(f.read_bytes(), f.name, infer=True, snap=args.snap, **opts)
        except DrawingError:
            tot["bad"] += 1
            continue
        tot["files"] += 1
        sa, sb = _stats(a), _stats(b)
        ok = [aidl_lang.compile(t, path=ROOT / "x.aidl").ok for t in (a, b)]
        tot["compiled0"] += ok[0]
        tot["compiled1"] += ok[1]
        for k, s in (("0", sa), ("1", sb)):
            tot["recog" + k] += s["recog"]
            tot["pieces" + k] += s["pieces"]
            tot["splines" + k] += s["splines"]
        tot["circles"] += sb["circles"]
        tot["arcs"] += sb["arcs"]
        worst = max(worst, sb["dev"])
        if args.v:
            print(f"{f.name:28s} recognised {sa['recog']:4d}/{sa['pieces']:<4d} -> "
                  f"{sb['recog']:4d}/{sb['pieces']:<4d} splines {sa['splines']:5d} -> "
                  f"{sb['splines']:5d}  snapped {sb['circles']} circles {sb['arcs']} arcs, "
                  f"dev {sb['dev']:.3g} mm  compiled {ok}", flush=True)

    def share(r, p):
        return f"{r}/{p} ({r / p:.1%})" if p else "0/0"
    print(f"{tot['files']} files imported ({tot['bad']} refused): recognised pieces "
          f"{share(tot['recog0'], tot['pieces0'])} -> {share(tot['recog1'], tot['pieces1'])}; "
          f"Bézier statements {tot['splines0']} -> {tot['splines1']}; snapped "
          f"{tot['circles']} circles and {tot['arcs']} arcs, largest deviation {worst:.3g} mm; "
          f"compiled {tot['compiled0']} -> {tot['compiled1']}; "
          f"{time.process_time() - t0:.1f} s CPU")
    return 0


if __name__ == "__main__":
    sys.exit(main())
