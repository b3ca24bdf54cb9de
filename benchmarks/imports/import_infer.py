"""``aidl import --infer`` over every example: how close the inferred program comes to the
hand-written one (issue 60).

Run:  .venv/bin/python benchmarks/imports/import_infer.py [NAME ...] [-v]
      .venv/bin/python benchmarks/imports/import_infer.py --corpus tests/data/ezdxf [--max-bytes N]

Each example (``examples/*.aidl``, or the NAMEs given) is compiled and rendered to DXF, then
imported twice from that DXF: as pieces (``aidl import``) and as a design (``aidl import
--infer``); both programs are compiled by the real compiler and the inferred one rendered back
and compared with the first DXF (tests/dxf_compare.py, ezdxf alone, to 1e-6 mm).  One row per
example:

* ``hand``, ``pieces``, ``infer``: program lines (not blank, not comments) of the hand-written
  example, of the plain import and of the inferred one; ``ratio``: infer / hand (goal <= 1.5);
* ``recog``: the share of the outline and hole pieces that went into recognised shapes (the
  inferred program's own header, ``# recognised: X of Y pieces``);
* ``dof``: degrees of freedom left (``Result.freedom()``) of the plain and the inferred
  program;
* ``exact``: the inferred program renders to the same curves (1e-6 mm);
* ``ms``: the inferred import's time;
* ``edits``: the edit test: each size param of a repeated feature (a ``param`` ending
  ``_d``, ``_width``, ``_height``, ``_length``, ``_radius`` used inside a ``for``) is set
  10 % larger (``--set``); ``ok/n`` counts those whose change moved
  exactly the feature's instances (count x pieces per instance curves changed, nothing else).

``--corpus FOLDER``: every ``.dxf``/``.dxf.gz`` of the folder (at most ``--max-bytes``,
default 300 000, unzipped) imported both ways; both programs compiled and rendered, the two
DXFs compared (1e-6 mm): files, exact, program lines of each, import seconds.

Exits 1 when an inferred program fails to compile or is not exact.
"""
from __future__ import annotations

import argparse
import pathlib
import re
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

import aidl_lang  # noqa: E402
import dxf_compare  # noqa: E402
from aidl_lang.drawing.infer.infer import import_drawing  # noqa: E402

PIECES = {"Circle": 1, "Slot": 4, "Rectangle": 4, "RoundedRectangle": 8, "Sector": 3}


def code_lines(text: str) -> int:
    return sum(1 for ln in text.splitlines() if ln.strip() and not ln.strip().startswith("#"))


def differ(a, b) -> tuple[list, list]:
    dxf_compare.TOL = 1e-6
    return dxf_compare.unmatched(dxf_compare.curves(a), dxf_compare.curves(b))


def feature_params(text: str) -> list[tuple[str, int, int]]:
    """``(param, instances, pieces each)`` for each param that sizes or spaces the shapes of
    one loop: the loops around the statement that uses it (``range(n)``: n, ``[-1, 1]``: 2)."""
    params = [p for p in re.findall(r"^param (\w+) =", text, re.M)
              if re.search(r"_(d|width|height|length|radius)$", p)]
    out = []
    lines = text.splitlines()
    for p in params:
        uses = [i for i, ln in enumerate(lines) if re.search(rf"\b{p}\b", ln)
                and not ln.startswith("param")]
        shape_uses = [i for i in uses if re.search(r"= (\w+)\(", lines[i])]
        if len(shape_uses) != 1:
            continue
        i = shape_uses[0]
        kind = re.search(r"= (\w+)\(", lines[i]).group(1)
        if kind not in PIECES or not lines[i].lstrip().startswith("hole"):
            continue
        depth = len(lines[i]) - len(lines[i].lstrip())
        n = 1
        for j in range(i - 1, -1, -1):
            d = len(lines[j]) - len(lines[j].lstrip())
            if d < depth and lines[j].lstrip().startswith("for "):
                n *= loop_count(text, lines[j])
                depth = d
            elif d < depth:
                depth = d
        if n > 1:
            out.append((p, n, PIECES[kind]))
    return out


def loop_count(text: str, line: str) -> int:
    """How many times a ``for`` line runs: ``range(4)``, ``range(holes_n)`` (a count param,
    ``range(holes_cols - j % 2)`` by its first row), or a list's items (``[-1, 1]``, a list
    of points)."""
    m = re.search(r"range\((\w+)", line)
    if m:
        w = m.group(1)
        return int(w) if w.isdigit() else int(value_of(text, w))
    items = re.search(r"\[(.*)\]", line).group(1)
    return items.count("(") or len(items.split(","))


def value_of(text: str, p: str) -> float:
    return float(re.search(rf"^param {p} = ([-\d.e]+)", text, re.M).group(1))


def one(example: pathlib.Path, tmp: pathlib.Path, verbose: bool) -> dict:
    res = aidl_lang.compile(path=example)
    first = tmp / f"{example.stem}.dxf"
    first.write_text(res.to_dxf())
    data = first.read_bytes()
    plain, _ = import_drawing(data, first.name)
    t0 = time.perf_counter()
    text, _ = import_drawing(data, first.name, infer=True)
    ms = (time.perf_counter() - t0) * 1000
    row = {"name": example.stem, "hand": code_lines(example.read_text()),
           "pieces": code_lines(plain), "infer": code_lines(text), "ms": ms}
    m = re.search(r"# recognised: (\d+) of (\d+) pieces", text)
    row["recog"] = int(m.group(1)) / int(m.group(2)) if m and int(m.group(2)) else 1.0
    p_res = aidl_lang.compile(plain, path=tmp / f"{example.stem}_plain.aidl")
    again = aidl_lang.compile(text, path=tmp / f"{example.stem}_infer.aidl")
    row["dof_plain"] = p_res.freedom()["dof"] if p_res.ok else None
    row["ok"] = again.ok
    if not again.ok:
        row.update(dof=None, exact=False, edits=(0, 0))
        if verbose:
            print(example.stem, [str(d) for d in again.errors][:3])
        return row
    row["dof"] = again.freedom()["dof"]
    second = tmp / f"{example.stem}_back.dxf"
    second.write_text(again.to_dxf())
    left, extra = differ(first, second)
    row["exact"] = not left and not extra
    good = 0
    feats = feature_params(text)
    for p, n, k in feats:
        v = value_of(text, p)
        r = aidl_lang.compile(text, path=tmp / "edit.aidl", overrides={p: repr(v * 1.1)})
        if not r.ok:
            if verbose:
                print(f"  {example.stem}: --set {p}: {[str(d) for d in r.errors][:1]}")
            continue
        out = tmp / "edit.dxf"
        out.write_text(r.to_dxf())
        left, extra = differ(first, out)
        if len(left) == len(extra) == n * k:
            good += 1
        elif verbose:
            print(f"  {example.stem}: --set {p}: {len(left)} curves changed, {n} x {k} wanted")
    row["edits"] = (good, len(feats))
    return row


def corpus(folder: pathlib.Path, max_bytes: int, verbose: bool) -> int:
    import gzip
    from aidl_lang.drawing.model import DrawingError
    n = exact = compiled = la = lb = 0
    secs = 0.0
    bad = []
    with tempfile.TemporaryDirectory() as d:
        tmp = pathlib.Path(d)
        for p in sorted(folder.iterdir()):
            if not re.search(r"\.dxf(\.gz)?$", p.name, re.I):
                continue
            data, name = p.read_bytes(), p.name
            if name.endswith(".gz"):
                data, name = gzip.decompress(data), name[:-3]
            if len(data) > max_bytes:
                continue
            try:
                a, _ = import_drawing(data, name)
                t0 = time.perf_counter()
                b, _ = import_drawing(data, name, infer=True)
                secs += time.perf_counter() - t0
            except DrawingError:
                continue
            n += 1
            ra = aidl_lang.compile(a, path=tmp / "a.aidl")
            rb = aidl_lang.compile(b, path=tmp / "b.aidl")
            if not (ra.ok and rb.ok):
                bad.append((name, "not compiled"))
                continue
            compiled += 1
            (tmp / "a.dxf").write_text(ra.to_dxf())
            (tmp / "b.dxf").write_text(rb.to_dxf())
            left, extra = differ(tmp / "a.dxf", tmp / "b.dxf")
            if left or extra:
                bad.append((name, f"{len(left)} curves differ"))
            else:
                exact += 1
            la += code_lines(a)
            lb += code_lines(b)
    for name, why in bad if verbose else []:
        print(f"  {name}: {why}")
    print(f"{folder}: {n} drawings imported, {compiled} compiled both ways, {exact} inferred "
          f"programs render as the plain import's (1e-6 mm); program lines {la} -> {lb} "
          f"({lb / max(la, 1):.0%}); inferring took {secs:.2f} s in all")
    return 0 if exact == compiled else 1


def main(argv=None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("names", nargs="*")
    ap.add_argument("-v", action="store_true")
    ap.add_argument("--corpus", default=None)
    ap.add_argument("--max-bytes", type=int, default=300_000)
    args = ap.parse_args(argv)
    if args.corpus:
        return corpus(pathlib.Path(args.corpus), args.max_bytes, args.v)
    exs = sorted((ROOT / "examples").glob("*.aidl"))
    if args.names:
        exs = [e for e in exs if e.stem in args.names]
    rows = []
    with tempfile.TemporaryDirectory() as d:
        for ex in exs:
            rows.append(one(ex, pathlib.Path(d), args.v))
    print(f"{'example':16s} {'hand':>5s} {'pieces':>6s} {'infer':>5s} {'ratio':>5s} "
          f"{'recog':>6s} {'dof':>11s} {'exact':>5s} {'ms':>6s} {'edits':>5s}")
    for r in rows:
        dof = f"{r['dof_plain']}->{r['dof']}"
        print(f"{r['name']:16s} {r['hand']:5d} {r['pieces']:6d} {r['infer']:5d} "
              f"{r['infer'] / r['hand']:5.2f} {r['recog']:6.0%} {dof:>11s} "
              f"{'yes' if r['exact'] else 'NO':>5s} {r['ms']:6.0f} "
              f"{r['edits'][0]}/{r['edits'][1]:<3d}")
    n = len(rows)
    within = sum(1 for r in rows if r["infer"] <= 1.5 * r["hand"])
    edits = [sum(r["edits"][i] for r in rows) for i in (0, 1)]
    print(f"{n} examples: {within} within 1.5x the hand-written length "
          f"(median ratio {sorted(r['infer'] / r['hand'] for r in rows)[n // 2]:.2f}), "
          f"{sum(r['recog'] for r in rows) / n:.0%} of pieces recognised on average, "
          f"{sum(1 for r in rows if r['dof'] == 0)} with no degree of freedom left, "
          f"{sum(1 for r in rows if r['exact'])} exact, edits {edits[0]}/{edits[1]}, "
          f"import {sum(r['ms'] for r in rows) / 1000:.2f} s in all")
    return 0 if all(r["ok"] and r["exact"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
