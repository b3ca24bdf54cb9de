"""Where the solver puts things, before and after a solver change: a regression guard.

Compiles every example (``examples/**/*.aidl``), every figure program (``docs/figures``),
every ```aidl block of ``docs/*.md``, every test program (``tests/programs``), every model-run
program (``data/model_runs``) and every standard-library template called with its defaults,
and records per program: whether it compiled, its diagnostic codes, each part's box and area
(``aidl_lang.api.Result.parts``) and every named solved value (``Result.values``: points,
lengths, boxes).  Two records are compared with a tolerance (1e-6 mm).

Usage (issue 73: parts stay, features move)::

    PYTHONPATH=/work/main python benchmarks/solver/compare_placement.py record main.json
    PYTHONPATH=.          python benchmarks/solver/compare_placement.py record branch.json
    python benchmarks/solver/compare_placement.py diff main.json branch.json

``record`` runs from the checkout it is given by ``PYTHONPATH`` but reads the programs of
this checkout (``--root``), so both records compile the same texts.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOL = 1e-6


def programs(root: str) -> list[tuple[str, str, str]]:
    """``[(name, path to resolve imports from, source[, overrides])]`` of every program
    named above (an example once more per ``--set`` of its ``# Try:`` line)."""
    out = []
    for sub in ("examples", "docs/figures", "tests/programs", "data/model_runs"):
        base = os.path.join(root, sub)
        for d, _, files in sorted(os.walk(base)):
            if "hostile" in d.split(os.sep):
                continue
            for f in sorted(files):
                if f.endswith(".aidl"):
                    p = os.path.join(d, f)
                    with open(p, encoding="utf-8") as fh:
                        text = fh.read()
                    out.append((os.path.relpath(p, root), p, text))
                    # each "# Try: --set k=v" of an example, one at a time
                    for m in re.finditer(r"--set\s+(\w+)=(\S+)", "\n".join(
                            ln for ln in text.splitlines() if ln.startswith("# Try:"))):
                        out.append((f"{os.path.relpath(p, root)}@{m.group(1)}={m.group(2)}",
                                    p, text, {m.group(1): m.group(2).strip("'")}))
    docs = os.path.join(root, "docs")
    for f in sorted(os.listdir(docs)):
        if not f.endswith(".md"):
            continue
        with open(os.path.join(docs, f), encoding="utf-8") as fh:
            text = fh.read()
        for k, m in enumerate(re.finditer(r"```aidl\n(.*?)```", text, re.S)):
            out.append((f"docs/{f}#{k}", os.path.join(docs, f"_block{k}.aidl"), m.group(1)))
    std = os.path.join(root, "stdlib")
    for f in sorted(os.listdir(std)):
        if not f.endswith(".aidl"):
            continue
        with open(os.path.join(std, f), encoding="utf-8") as fh:
            text = fh.read()
        for m in re.finditer(r"^def (\w+)\((.*?)\)\s*->\s*(\w+)", text, re.M | re.S):
            name, kind = m.group(1), m.group(3)
            if kind == "hole":
                body = (f"solid s {{\n    body = Rectangle(center=(0, 0), width=300, "
                        f"height=300)\n    h = {name}()\n}}\n")
            else:
                body = f"assembly kit {{\n    t = {name}()\n}}\n"
            out.append((f"std/{f}:{name}", os.path.join(root, "_std.aidl"),
                        f'import "std/{f}"\n\nthickness 3 mm\n\n{body}'))
    return out


def record(root: str) -> dict:
    from aidl_lang import api
    rec = {}
    for name, path, source, *over in programs(root):
        t0 = time.process_time()
        try:
            r = api.compile(source, path=path, overrides=over[0] if over else None)
            entry = {"ok": r.ok, "codes": sorted(d.code for d in r.diagnostics)}
            sr = r.compiled.solve
            if sr is not None:         # the solve's work: Newton steps, attempts, tapes
                entry["work"] = [sr.iterations, sr.attempts, sr.solver.compiles]
            if r.ok:
                entry["parts"] = {p.name: [list(p.bbox), p.area, p.holes] for p in r.parts}
                entry["values"] = {v.name: v.mm for v in r.values}
        except Exception as e:          # noqa: BLE001 - recorded, compared as text
            entry = {"ok": False, "raised": f"{type(e).__name__}: {e}"}
        entry["cpu"] = time.process_time() - t0
        rec[name] = entry
        print(f"{entry['cpu']:7.2f} s  {name}", file=sys.stderr, flush=True)
    return rec


def _num_diff(a, b) -> float:
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return abs(a - b)
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return max((_num_diff(u, v) for u, v in zip(a, b)), default=0.0)
    return math.inf if a != b else 0.0


def diff(a: dict, b: dict) -> list[str]:
    """Every difference between two records, one line each."""
    lines = []
    for name in sorted(set(a) | set(b)):
        x, y = a.get(name), b.get(name)
        if x is None or y is None:
            lines.append(f"{name}: only in {'second' if x is None else 'first'}")
            continue
        if x.get("ok") != y.get("ok") or x.get("codes") != y.get("codes") or \
                x.get("raised") != y.get("raised"):
            lines.append(f"{name}: ok {x.get('ok')} -> {y.get('ok')}, codes "
                         f"{x.get('codes')} -> {y.get('codes')} {y.get('raised', '')}")
        for key in ("parts", "values"):
            px, py = x.get(key) or {}, y.get(key) or {}
            for k in sorted(set(px) | set(py)):
                d = _num_diff(px.get(k), py.get(k))
                if d > TOL:
                    lines.append(f"{name}: {key[:-1]} {k}: {px.get(k)} -> {py.get(k)}")
    return lines


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("record")
    r.add_argument("out")
    r.add_argument("--root", default=HERE)
    d = sub.add_parser("diff")
    d.add_argument("first")
    d.add_argument("second")
    args = ap.parse_args(argv)
    if args.cmd == "record":
        with open(args.out, "w", encoding="utf-8") as fh:
            json.dump(record(args.root), fh, indent=0)
        return 0
    with open(args.first, encoding="utf-8") as f1, open(args.second, encoding="utf-8") as f2:
        lines = diff(json.load(f1), json.load(f2))
    print("\n".join(lines) if lines else "no differences")
    with open(args.first, encoding="utf-8") as f1, open(args.second, encoding="utf-8") as f2:
        a, b = json.load(f1), json.load(f2)
    both = [k for k in a if k in b and a[k].get("work") and b[k].get("work")]
    tot = [[sum(r[k]["work"][i] for k in both) for i in range(3)] for r in (a, b)]
    print(f"solver work over {len(both)} programs (Newton steps, attempts, tapes): "
          f"{tot[0]} -> {tot[1]}", file=sys.stderr)
    for k in both:
        if a[k]["work"] != b[k]["work"]:
            print(f"  {k}: {a[k]['work']} -> {b[k]['work']}", file=sys.stderr)
    print(f"{len(lines)} differences", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
