"""``aidl import --infer`` measured as a maker would use it, in two sections.

**Hand-made** (issue 71): the drawings of tests/maker_drawings.py (a NEMA 17 mount, a Raspberry
Pi plate, a flange, a hex fan grille, a slot panel, a front panel with its holes on their own
layer, an LCD panel, a cable comb) are inferred, and each edit a person would make through the
params (a size, a pitch, a count, the body's width) is applied with ``overrides``
(``--set``); the edit did what was meant when the program, rendered, is the drawing of the
design with that number changed (to 1e-6 mm, up to a translation: the inferred plate grows
about its centre where the drawing grows from its corner).  One row per drawing: ``exact``
(the inferred program renders to the drawing itself, 1e-7 mm), ``edits ok/n`` and the failed
edits (``no param``: the program has no param of that name and value; ``wrong``: the edit
moved other things or not those meant).

**Generated** (issue 85, "drawings nobody tuned to"): random maker plates of
tests/gen_drawings.py (features of every kind tied to an edge, a corner or the centre, in mm
and inches, exported through ezdxf or svgwrite with layers, blocks, bulges, transformed
groups), each drawing given random edits of its design (the plate's width or height, a size,
a pitch, a count).  Each edit is made through the inferred program's param whose name and
value match what it changes (of several, each in turn until one does what was meant, as a
person would try them), the program compiled and its DXF (read back by ezdxf) compared
with the edited design's own geometry: every outline and hole by its exact area, centroid,
perimeter and box to 1e-6 mm, up to a translation (the plate's box), and the engraved labels
against the plain import of the edited drawing.  Each edit is ``meant``, ``wrong`` (compiled,
something else), ``no param`` or ``failed`` (the import or the compile failed); the shares
are printed by kind of edit, by kind of feature edited, by format and unit, with the kinds of
feature a wrong edit misplaced.

Run:  .venv/bin/python benchmarks/imports/infer_edits.py [NAME ...] [-v]        (both sections)
      .venv/bin/python benchmarks/imports/infer_edits.py --generated --seed 1 --count 300 [--keep DIR]
      .venv/bin/python benchmarks/imports/infer_edits.py --quick                 (a small generated run)

Exits 1 when a hand-made drawing's inferred program does not compile or is not exact.
"""
from __future__ import annotations

import argparse
import collections
import io
import pathlib
import random
import re
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

import aidl_lang  # noqa: E402
import dxf_compare  # noqa: E402
import ezdxf  # noqa: E402
import gen_drawings as gen  # noqa: E402
import gen_panels  # noqa: E402
import gen_profiles  # noqa: E402
from aidl_lang.drawing.model import DrawingError  # noqa: E402
from aidl_lang.drawing.infer import import_drawing  # noqa: E402
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


# --- the generated set ------------------------------------------------------------------------

EDIT_KINDS = ("body", "size", "pitch", "count")
HINTS = {"hole": ("hole",), "slot": ("slot",), "cutout": ("cut", "window", "opening", "rect"),
         "notch": ("notch",), "row": ("row", "holes", "slots"), "grid": ("grid", "holes"),
         "hexgrid": ("hex", "grid", "grille", "holes"), "boltcircle": ("bolt", "circle"),
         "keyhole": ("key",), "csk": ("countersink", "hole"), "dhole": ("d_hole", "dhole", "flat"), "arcslot": ("arc",),
         "plate": ("plate", "body"), "corners": ("corner",), "comb": ("notch",),
         "board": ("holes",), "flange": ("bolt", "circle"), "oddcorners": ("corner",),
         "gapgrid": ("grid", "holes"), "cadrow": ("row", "holes"),
         "edgepair": ("hole", "slot"), "perforated": ("holes",), "twogroups": ("holes",)}
UNIT_MM = {"mm": 1.0, "cm": 10.0, "in": 25.4, "inch": 25.4, "m": 1000.0}
ANGLES = {"a0"}         # design keys that are angles (degrees): not scaled by the unit


def program_params(text: str) -> list:
    """``[(name, value, unit written or "", mm per unit)]`` of a program's params (a number
    with no unit is in the program's ``units``)."""
    m = re.search(r"^units (\w+)", text, re.M)
    base = UNIT_MM.get(m.group(1), 1.0) if m else 1.0
    out = []
    for p in re.finditer(r"^param (\w+) = (-?[\d.]+(?:e[+-]?\d+)?)[ \t]*(mm|cm|in|inch|m)?\b",
                         text, re.M):
        unit = p.group(3) or ""
        out.append((p.group(1), float(p.group(2)), unit, UNIT_MM[unit] if unit else base))
    return out


def find_params(text: str, design, e) -> list:
    """The params the edit ``e`` may go by, best first: ``[(name, override text)]``.  Each
    one's name matches one of the edit's patterns (the whole name, or a tail after ``_``) and
    its value is the design's value (x the pattern's factor, in the param's unit; a count as
    is); those whose name holds a word of the feature's kind come first, those named for
    another kind of feature (``bolt_circle_d`` for a D-hole of that diameter) last."""
    now = design.value(e)
    found = []
    for name, v, unit, mm in program_params(text):
        tails = [name] if e.whole else [name[k:] for k in range(len(name))
                                        if k == 0 or name[k - 1] == "_"]
        for pat, factor in e.patterns:
            if not any(re.fullmatch(pat, t) for t in tails):
                continue
            if e.kind == "count":
                if v == now:
                    found.append((name, repr(int(e.new))))
                break
            if e.key in ANGLES:             # degrees in any unit of length
                if abs(v - now * factor) <= 1e-7 * max(1.0, abs(now)):
                    found.append((name, f"{e.new * factor!r} deg"))
                break
            want = now * factor * design.u
            if abs(v * mm - want) <= 1e-7 * max(1.0, abs(want)):
                new = e.new * factor * design.u / mm
                found.append((name, f"{new!r} {unit}".strip()))
                break
    return sorted(found, key=lambda f: (not _names(f[0], e.feature_kind),
                                        any(_names(f[0], k) for k in HINTS)))


def find_param(text: str, design, e) -> tuple | None:
    """The best of :func:`find_params`, or ``None``."""
    return (find_params(text, design, e) or [None])[0]


def _names(name: str, kind: str) -> bool:
    """Whether a param's name holds a word of a kind of feature."""
    return any(h in name for h in HINTS.get(kind, ()))


# the layers a program's DXF engraves on: its drawings, and the heads of its countersinks and
# counterbores (issue 102: `Countersink` of a hole, what --infer writes for a mark)
MARKED = ("ENGRAVE", "COUNTERSINK", "COUNTERBORE")


def _engraved(doc, shift) -> list:
    """Each entity of a document's engraved layers (:data:`MARKED`) as a tuple of numbers,
    moved by ``-shift``."""
    out = []
    for x in doc.modelspace():
        if x.dxf.layer not in MARKED:
            continue
        t = x.dxftype()
        if t == "LWPOLYLINE":
            pts = [(p[0], p[1], p[2]) for p in x.get_points("xyb")]
        elif t == "LINE":
            pts = [(x.dxf.start.x, x.dxf.start.y, 0.0), (x.dxf.end.x, x.dxf.end.y, 0.0)]
        elif t in ("ARC", "CIRCLE"):
            pts = [(x.dxf.center.x, x.dxf.center.y, x.dxf.radius)]
            if t == "ARC":
                pts.append((x.dxf.start_angle, x.dxf.end_angle, 0.0))
        else:
            continue
        out.append((t, tuple((a - shift[0], b - shift[1], c) if k == 0 or t != "ARC" else (a, b, c)
                             for k, (a, b, c) in enumerate(pts))))
    return sorted(out, key=lambda e: (e[0], len(e[1]), round(e[1][0][0], 3), round(e[1][0][1], 3)))


def _same_engraved(a: list, b: list, tol: float = 1e-6) -> bool:
    if len(a) != len(b):
        return False
    rest = list(b)
    for x in a:
        for i, y in enumerate(rest):
            if x[0] == y[0] and len(x[1]) == len(y[1]) and all(
                    abs(p - q) <= tol for u, v in zip(x[1], y[1]) for p, q in zip(u, v)):
                rest.pop(i)
                break
        else:
            return False
    return True


def output_of(text: str, path, overrides=None):
    """``(cut loop signatures, ezdxf document)`` of a program, or the first error's text."""
    res = aidl_lang.compile(text, path=path, overrides=overrides)
    if not res.ok:
        return str(res.errors[0])
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    segs, texts = [], []
    for x in doc.modelspace():
        if x.dxf.layer not in MARKED:
            gen._dxf_segments(x, segs, texts)
    loops, _ = gen.chain([s for _, s in segs])
    return [gen.signature(lp) for lp in loops], doc


def compare(design, got, tmp: pathlib.Path) -> list:
    """The kinds of feature of ``design`` its program's output ``got`` misplaced (``[]``:
    exact): the plate as ``plate``, a loop of no feature as ``extra``, labels as ``label``."""
    sigs, doc = got
    owners = design.loops()
    want, _ = gen.normalised([gen.signature(lp) for _, lp in owners])
    have, shift = gen.normalised(sigs)
    left, rest = gen.match(want, have)
    bad = [("plate" if owners[i][0] < 0 else design.features[owners[i][0]]["kind"])
           for i in sorted({i for i in left})]
    bad = sorted(set(bad)) + (["extra"] if rest and not left else [])
    if design.labels() or design.marks():
        suffix, data = gen.export(design)
        (tmp / ("truth" + suffix)).write_bytes(data)
        plain, _ = import_drawing(data, "truth" + suffix)
        ref = output_of(plain, tmp / "truth.aidl")
        if isinstance(ref, str):
            raise RuntimeError("the plain import of a generated drawing fails: " + ref)
        _, tshift = gen.normalised(ref[0])
        if not _same_engraved(_engraved(doc, shift), _engraved(ref[1], tshift)):
            bad.append("label" if design.labels() else "csk")
    return bad


def _pick_edits(rng, design, k: int) -> list:
    """Up to ``k`` edits of ``design``, the kinds taken in turn (body, size, pitch, count)."""
    by = collections.defaultdict(list)
    for e in design.edits():
        by[e.kind].append(e)
    for v in by.values():
        rng.shuffle(v)
    out = []
    kinds = [x for x in EDIT_KINDS if by[x]]
    rng.shuffle(kinds)
    while len(out) < k and any(by.values()):
        for kind in kinds:
            if by[kind] and len(out) < k:
                out.append(by[kind].pop())
    return out


def run_drawing(design, tmp: pathlib.Path, rng, k: int = 5) -> dict:
    """One generated drawing: imported with ``--infer``, checked against its design, then up
    to ``k`` random edits made through the program's params.  Returns ``{"exact", "error",
    "program", "edits": [(Edit, outcome, detail)]}``."""
    suffix, data = gen.export(design)
    src = tmp / ("d" + suffix)
    src.write_bytes(data)
    out = {"exact": False, "error": "", "program": "", "edits": [], "file": src, "data": data}
    edits = []
    for e in _pick_edits(rng, design, k):
        d2 = gen.random_edit(rng, design, e)
        if d2 is not None:
            edits.append((e, d2))
    try:
        text, _ = import_drawing(data, src.name, infer=True)
    except DrawingError as exc:
        out["error"] = f"import: {exc}"
        out["edits"] = [(e, "failed", out["error"]) for e, _ in edits]
        return out
    out["program"] = text
    base = output_of(text, tmp / "d.aidl")
    if isinstance(base, str):
        out["error"] = f"compile: {base}"
        out["edits"] = [(e, "failed", out["error"]) for e, _ in edits]
        return out
    out["exact"] = not compare(design, base, tmp)
    for e, d2 in edits:
        tries = []
        for p in find_params(text, design, e):       # a person tries each that fits
            got = output_of(text, tmp / "e.aidl", {p[0]: p[1]})
            if isinstance(got, str):
                tries.append((e, "failed", f"{p[0]}={p[1]}: {got}"))
                continue
            bad = compare(d2, got, tmp)
            tries.append((e, "wrong" if bad else "meant",
                          f"{p[0]}={p[1]}" + (f": misplaced {', '.join(bad)}" if bad else "")))
            if not bad:
                break
        out["edits"].append(tries[-1] if tries and tries[-1][1] == "meant" else
                            tries[0] if tries else (e, "no param", ""))
    return out


def designs(seed: int, kinds: tuple = gen.KINDS):
    """Random designs from ``seed``, forever: each of ``kinds`` in turn is in the next (the
    others drawn from ``kinds``; the default, :data:`gen.KINDS`, draws what it always drew)."""
    rng = random.Random(seed)
    i = 0
    plates = tuple(k for k in kinds if k in gen.ALL_KINDS) or gen.KINDS
    while True:
        k = kinds[i % len(kinds)]
        if k in gen_profiles.PROFILE_KINDS:     # a profile is its own part
            d = gen_profiles.random_profile(rng, k)
        elif k in gen_panels.PANEL_KINDS:       # a panel: features of its own kinds
            d = gen_panels.random_panel(rng, k)
        else:
            d = gen.random_design(rng, [k], pool=plates)
            d.kind = k
        yield d, rng
        i += 1


OUTCOMES = ("meant", "wrong", "no param", "failed")


def _table(title: str, rows: dict) -> None:
    print(f"{title:<12} {'edits':>5} " + " ".join(f"{o:>8}" for o in OUTCOMES) + "   meant %")
    for key in sorted(rows, key=lambda k: (-sum(rows[k].values()), k)):
        c = rows[key]
        n = sum(c.values())
        print(f"{key:<12} {n:>5} " + " ".join(f"{c[o]:>8}" for o in OUTCOMES)
              + f"   {100 * c['meant'] / max(n, 1):6.1f}")


def run_generated(seed: int, count: int, per: int = 5, keep: pathlib.Path | None = None,
                  verbose: bool = False, kinds: tuple = gen.KINDS) -> dict:
    """At least ``count`` edits of generated drawings from ``seed``: prints the tables and
    returns ``{"edits": [(drawing index, Edit, outcome, detail)], "drawings", "exact",
    "errors"}``."""
    t0 = time.perf_counter()
    rows = {k: collections.defaultdict(collections.Counter) for k in
            ("kind", "drawing", "feature", "format", "misplaced")}
    res = {"edits": [], "drawings": 0, "exact": 0, "errors": []}
    with tempfile.TemporaryDirectory() as d:
        tmp = pathlib.Path(d)
        for n, (design, rng) in enumerate(designs(seed, kinds)):
            if len(res["edits"]) >= count:
                break
            r = run_drawing(design, tmp, rng, per)
            res["drawings"] += 1
            res["exact"] += r["exact"]
            if r["error"]:
                res["errors"].append((n, r["error"]))
            fmt = f"{design.style['format']} {design.units}"
            for e, outcome, detail in r["edits"]:
                res["edits"].append((n, e, outcome, detail))
                rows["kind"][e.kind][outcome] += 1
                rows["feature"][e.feature_kind][outcome] += 1
                rows["drawing"][design.kind][outcome] += 1
                rows["format"][fmt][outcome] += 1
                if outcome == "wrong":
                    for k in detail.split("misplaced ")[-1].split(", "):
                        rows["misplaced"][k]["wrong"] += 1
                if verbose and outcome != "meant":
                    print(f"#{n} {e.label} {design.value(e)} -> {e.new}: {outcome} {detail}")
            if keep and any(o != "meant" for _, o, _ in r["edits"]):
                keep.mkdir(parents=True, exist_ok=True)
                (keep / f"g{n}{r['file'].suffix}").write_bytes(r["data"])
                (keep / f"g{n}.aidl").write_text(r["program"] or r["error"])
                (keep / f"g{n}.txt").write_text(design.describe() + "\n" + "\n".join(
                    f"{e.label} {design.value(e)} -> {e.new}: {o} {dt}" for e, o, dt in r["edits"]))
    n = len(res["edits"])
    good = sum(o == "meant" for _, _, o, _ in res["edits"])
    print(f"generated: seed {seed}, {res['drawings']} drawings, {res['exact']} inferred exactly, "
          f"{len(res['errors'])} failed to import or compile, {n} edits "
          f"({time.perf_counter() - t0:.0f} s)")
    _table("edit kind", rows["kind"])
    _table("drawing", rows["drawing"])
    _table("feature", rows["feature"])
    _table("format", rows["format"])
    print("features a wrong edit misplaced: " + ", ".join(
        f"{k} {c['wrong']}" for k, c in sorted(rows["misplaced"].items(),
                                               key=lambda kv: -kv[1]["wrong"])))
    print(f"generated edits that did what was meant: {good} of {n} ({100 * good / max(n, 1):.1f} %)")
    return res


def run_handmade(names: list, verbose: bool) -> bool:
    """The hand-made section; ``True`` when every drawing's program is exact."""
    total = good = 0
    bad = False
    with tempfile.TemporaryDirectory() as d:
        print(f"{'drawing':<12} {'exact':<6} {'edits':<6} failed")
        for n in names:
            exact, ok, k, failed = run_one(n, pathlib.Path(d), verbose)
            total += k
            good += ok
            bad |= not exact
            print(f"{n:<12} {'yes' if exact else 'NO':<6} {ok}/{k:<4} {'; '.join(failed)}")
    print(f"hand-made edits that did what was meant: {good} of {total} "
          f"({100 * good / max(total, 1):.0f} %)")
    return not bad


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="hand-made drawings (default: all)")
    ap.add_argument("-v", action="store_true", help="print each inferred hand-made program, "
                    "each generated edit that did not do what was meant")
    ap.add_argument("--generated", action="store_true", help="the generated set only")
    ap.add_argument("--handmade", action="store_true", help="the hand-made set only")
    ap.add_argument("--seed", type=int, default=1, help="the generated set's seed (1)")
    ap.add_argument("--count", type=int, default=300, help="generated edits, at least (300)")
    ap.add_argument("--per", type=int, default=5, help="edits per generated drawing (5)")
    ap.add_argument("--quick", action="store_true", help="a small generated run (24 edits)")
    ap.add_argument("--keep", type=pathlib.Path, help="write each generated drawing with an "
                    "edit not meant, its program and its edits, into this folder")
    ap.add_argument("--kinds", default="", help="the generated features' kinds: `new` (the "
                    "kinds drawn only when asked: double-D holes, keyways, skewed vent rows, countersunk holes), "
                    "`round5` (issue 93's: corner holes and slots, combs, board hole sets, "
                    "flanges at a drawn angle), `profiles` (L, T, U, Z brackets, stepped "
                    "plates), `panels` (front panels of rows and windows, grilles), `issue93` "
                    "(round5, profiles and panels), `irregular` (issue 103's: four corner "
                    "holes one of them larger, a grid with a hole left out, a row a CAD "
                    "program rounded), `round6` (issue 103, continued: two holes or slots "
                    "mirrored about a centre line each by its own edge, a perforated plate, two "
                    "2 x 2 groups of one size, one CAD rounded, one with a hole left out), "
                    "`round7` (issue 114: a lattice of holes of two sizes, a checkerboard or "
                    "mixed; a single hole by its edges; two holes in line by their own edges, "
                    "not mirrored), "
                    "`all`, or names joined by commas (default: the first set, as always)")
    a = ap.parse_args(argv)
    every = gen.ALL_KINDS + gen_profiles.PROFILE_KINDS + gen_panels.PANEL_KINDS
    kinds = {"": gen.KINDS, "new": gen.NEW_KINDS, "round5": gen.ROUND5_KINDS,
             "profiles": gen_profiles.PROFILE_KINDS, "panels": gen_panels.PANEL_KINDS,
             "issue93": gen.ROUND5_KINDS + gen_profiles.PROFILE_KINDS + gen_panels.PANEL_KINDS,
             "irregular": gen.IRREGULAR_KINDS, "round6": gen.ROUND6_KINDS,
             "round7": gen.ROUND7_KINDS, "all": every}.get(
        a.kinds, tuple(a.kinds.split(",")))
    if not set(kinds) <= set(every):
        ap.error(f"--kinds: not a kind: {', '.join(sorted(set(kinds) - set(every)))}")
    ok = True
    if not a.generated and not a.quick:
        ok = run_handmade(a.names or list(DRAWINGS), a.v)
    if not a.handmade and not a.names:
        run_generated(a.seed, 24 if a.quick else a.count, a.per, a.keep, a.v, kinds)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
