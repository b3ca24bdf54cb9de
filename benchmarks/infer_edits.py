"""``aidl import --infer`` measured as a maker would use it (issue 71): the drawings of
tests/maker_drawings.py (a NEMA 17 mount, a Raspberry Pi plate, a flange, a hex fan grille, a
slot panel, a front panel with its holes on their own layer, an LCD panel, a cable comb) are
inferred, and each edit a person would make through the params (a size, a pitch, a count, the
body's width) is applied with ``overrides`` (``--set``); the edit did what was meant when the
program, rendered, is the drawing of the design with that number changed (to 1e-6 mm, up to a
translation: the inferred plate grows about its centre where the drawing grows from its
corner).

Run:  .venv/bin/python benchmarks/infer_edits.py [NAME ...] [-v]

One row per drawing: ``exact`` (the inferred program renders to the drawing itself, 1e-7 mm),
``edits ok/n`` and the failed edits (``no param``: the program has no param of that name and
value; ``wrong``: the edit moved other things or not those meant).  The last line is the
share over all edits.  Exits 1 when an inferred program does not compile or is not exact.
"""
from __future__ import annotations

import argparse
import pathlib
import re
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

import aidl_lang  # noqa: E402
import dxf_compare  # noqa: E402
from aidl_lang.drawing.infer.infer import import_drawing  # noqa: E402
from maker_drawings import DRAWINGS  # noqa: E402


def _curves(path) -> list:
    """The DXF's curves moved so that their bounding box starts at (0, 0)."""
    cs = dxf_compare.curves(path)
    pts = [p for c in cs for p in c[1]]
    ext = [c for c in cs if c[0] in ("C", "A")]
    xs = [p[0] for p in pts] + [c[1][0][0] - c[2][0] for c in ext]
    ys = [p[1] for p in pts] + [c[1][0][1] - c[2][0] for c in ext]
    x0, y0 = min(xs), min(ys)
    return [(c[0], tuple((p[0] - x0, p[1] - y0) for p in c[1]), c[2]) for c in cs]


def same(a, b, tol: float) -> bool:
    dxf_compare.TOL = tol
    left, extra = dxf_compare.unmatched(_curves(a), _curves(b))
    return not left and not extra


def params(text: str) -> dict:
    return {m.group(1): float(m.group(2)) for m in
            re.finditer(r"^param (\w+) = (-?[\d.e+-]+)", text, re.M)}


def find(text: str, pattern: str, value: float) -> str | None:
    for name, v in params(text).items():
        if abs(v - value) <= 1e-9 and any(re.fullmatch(pattern, name[k:])
                                           for k in range(len(name))
                                           if k == 0 or name[k - 1] == "_"):
            return name
    return None


def run_one(name: str, tmp: pathlib.Path, verbose: bool = False) -> tuple[bool, int, int, list]:
    """``(exact, edits ok, edits, [failed edit labels])`` of one drawing."""
    fn, edits = DRAWINGS[name]
    src = tmp / f"{name}.dxf"
    src.write_bytes(fn())
    text, _ = import_drawing(src.read_bytes(), src.name, infer=True)
    if verbose:
        print(text)
    res = aidl_lang.compile(text, path=tmp / f"{name}.aidl")
    if not res.ok:
        return False, 0, len(edits), ["does not compile: " + str(res.errors[0])]
    back = tmp / f"{name}_back.dxf"
    back.write_text(res.to_dxf())
    exact = same(src, back, 1e-7)
    ok, failed = 0, []
    for label, pattern, now, new, kw in edits:
        p = find(text, pattern, now)
        if p is None:
            failed.append(f"{label} (no param)")
            continue
        r = aidl_lang.compile(text, path=tmp / f"{name}_e.aidl", overrides={p: repr(new)})
        if not r.ok:
            failed.append(f"{label} ({p}: {r.errors[0]})")
            continue
        out = tmp / f"{name}_{kw}.dxf"
        out.write_text(r.to_dxf())
        want = tmp / f"{name}_{kw}_want.dxf"
        want.write_bytes(fn(**{kw: new}))
        if same(want, out, 1e-6):
            ok += 1
        else:
            failed.append(f"{label} ({p}: wrong)")
    return exact, ok, len(edits), failed


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="drawings (default: all)")
    ap.add_argument("-v", action="store_true", help="print each inferred program")
    a = ap.parse_args(argv)
    names = a.names or list(DRAWINGS)
    total = good = 0
    bad = False
    with tempfile.TemporaryDirectory() as d:
        print(f"{'drawing':<12} {'exact':<6} {'edits':<6} failed")
        for n in names:
            exact, ok, k, failed = run_one(n, pathlib.Path(d), a.v)
            total += k
            good += ok
            bad |= not exact
            print(f"{n:<12} {'yes' if exact else 'NO':<6} {ok}/{k:<4} {'; '.join(failed)}")
    print(f"edits that did what was meant: {good} of {total} ({100 * good / max(total, 1):.0f} %)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
