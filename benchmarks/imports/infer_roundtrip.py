"""``aidl import --infer`` of every example's DXF, rendered again: the same geometry to 1e-7 mm
and the same texts (issue 71, "Done when").

Run:  .venv/bin/python benchmarks/imports/infer_roundtrip.py [NAME ...] [--generators] [-v]

Each ``examples/*.aidl`` (with ``--generators`` also ``examples/generators/*.aidl``; or the
NAMEs given, file stems) is compiled and written to DXF; that DXF is imported with ``--infer``
(:func:`aidl_lang.drawing.infer.import_drawing`, what the CLI calls), the program compiled by
the real compiler and written to DXF again, and the two DXFs compared by an independent reader
(``tests/dxf_compare.py``: ezdxf alone, curve by curve, to 1e-7 mm).  Texts: the strings of
the example's ``Text`` shapes (its compiled model) against those of the inferred program's
(a multiset; a text left as strokes is missing).  One row per file:

* ``curves``: curves in the first DXF; ``off``: curves of either DXF with no partner within
  1e-7 mm (0 when exact); ``texts``: texts found again / texts in the example; ``missing``:
  the texts not found as ``Text``.

Exits 1 when an inferred program fails to compile or any curve is off (a missing text is
listed, not a failure: text the importer cannot recognise is kept as its exact strokes).
"""
from __future__ import annotations

import argparse
import collections
import pathlib
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

import aidl_lang  # noqa: E402
import dxf_compare  # noqa: E402
from aidl_lang.drawing.infer.infer import import_drawing  # noqa: E402

TOL = 1e-7


def texts(res) -> collections.Counter:
    """The strings of the compiled program's ``Text`` shapes."""
    return collections.Counter(g.data["text"] for g in res.compiled.model.all_geometry()
                               if g.kind == "Text")


def one(src: pathlib.Path, tmp: pathlib.Path) -> dict:
    res = aidl_lang.compile(path=src)
    row = {"name": src.stem, "ok": False, "curves": 0, "off": None, "want": 0, "got": 0,
           "missing": [], "why": ""}
    if not res.ok:
        row["why"] = "example does not compile"
        return row
    first = tmp / f"{src.stem}.dxf"
    first.write_text(res.to_dxf())
    t0 = time.process_time()
    text, _ = import_drawing(first.read_bytes(), first.name, infer=True)
    row["cpu"] = time.process_time() - t0
    again = aidl_lang.compile(text, path=tmp / f"{src.stem}_infer.aidl")
    if not again.ok:
        row["why"] = "; ".join(str(d) for d in again.errors)[:200]
        return row
    second = tmp / f"{src.stem}_back.dxf"
    second.write_text(again.to_dxf())
    dxf_compare.TOL = TOL
    a, b = dxf_compare.curves(first), dxf_compare.curves(second)
    left, extra = dxf_compare.unmatched(a, b)
    want, got = texts(res), texts(again)
    row.update(ok=True, curves=len(a), off=len(left) + len(extra),
               want=sum(want.values()), got=sum((want & got).values()),
               missing=sorted((want - got).elements()), left=left[:3], extra=extra[:3])
    return row


def main(argv=None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("names", nargs="*")
    ap.add_argument("--generators", action="store_true")
    ap.add_argument("-v", action="store_true")
    args = ap.parse_args(argv)
    files = sorted((ROOT / "examples").glob("*.aidl"))
    if args.generators:
        files += sorted((ROOT / "examples" / "generators").glob("*.aidl"))
    if args.names:
        files = [f for f in files if f.stem in args.names]
    rows = []
    with tempfile.TemporaryDirectory() as d:
        for f in files:
            r = one(f, pathlib.Path(d))
            rows.append(r)
            miss = ", ".join(repr(t) for t in r["missing"][:6])
            more = f" +{len(r['missing']) - 6}" if len(r["missing"]) > 6 else ""
            print(f"{r['name']:18s} curves {r['curves']:5d}  off {r['off'] if r['ok'] else '-':>4}"
                  f"  texts {r['got']:3d}/{r['want']:<3d} {miss}{more} {r['why']}", flush=True)
            if args.v and r["ok"] and r["off"]:
                print("   first only:", r["left"], "\n   inferred only:", r["extra"])
    exact = sum(1 for r in rows if r["ok"] and r["off"] == 0)
    want = sum(r["want"] for r in rows)
    got = sum(r["got"] for r in rows)
    with_text = [r for r in rows if r["want"]]
    print(f"{len(rows)} files: {exact} exact to {TOL:g} mm, "
          f"{sum(1 for r in rows if not r['ok'])} not compiled; texts {got}/{want} found again "
          f"({sum(1 for r in with_text if r['got'] == r['want'])} of {len(with_text)} files with "
          f"text have all); infer CPU {sum(r.get('cpu', 0) for r in rows):.1f} s")
    return 0 if exact == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
