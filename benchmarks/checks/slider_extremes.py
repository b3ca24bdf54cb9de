"""Every slider extreme of every gallery entry, compiled as the studio's compile worker does
(one warm :class:`~aidl_lang.serve.session.Session` per entry, no picture, no warnings) and,
when it fails, settled by :func:`aidl_lang.studio.compiler.settle` (issue 62, "Forms that
cannot fail"); prints each entry's extremes, CPU seconds, failures and the values moved.
The suite runs a sample (tests/test_studio_forms.py::
test_every_slider_extreme_of_every_gallery_entry_compiles: a fixed stride of the entries and
the params whose extremes compile only with another value moved); this runs them all, as
the law corpus does (benchmarks/laws/law_compiles.py: every gallery slider end).

    PYTHONPATH=$PWD python benchmarks/checks/slider_extremes.py [ID ...]

2026-11-27 (h16-suite): 48 entries, 392 extremes, 0 failing, 20 moved, 24.5 s CPU.
2026-11-28 (h24-suite): 49 entries, 452 extremes, 0 failing, 29 moved, 29.8 s CPU.
"""
from __future__ import annotations

import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

NUMERIC = ("length", "angle", "number")


def _text(p: dict, x: float) -> str:
    return f"{x:.12g} {p['unit']}".strip()


def lean(session):
    """``values -> {"ok", "params"}``: the session's compile without the SVG and warnings."""
    def run(values: dict) -> dict:
        res = session._compile(values, drawing=True, shape_checks=False)
        params = [p.to_json() for p in session._params(res.fctx, values)] \
            if res.fctx is not None else []
        return {"ok": res.ok, "params": params}
    return run


def extremes(entry, path: str, names=None) -> tuple[int, list, list]:
    """``(count, failed, moved)`` of ``entry``'s slider extremes (of the params in ``names``
    only, when given): ``failed`` holds
    ``(id, param, "min"|"max", value)`` of those that do not compile even settled, ``moved``
    ``(id, param, end, {param: value})`` of those that compile only with another value moved.
    Raises AssertionError when the entry does not open or settle moves the slider itself."""
    from aidl_lang.serve.session import Session
    from aidl_lang.studio import compiler
    s = Session(path)
    doc = s.load(entry.source)
    assert doc["ok"], entry.id
    run = lean(s)
    count, failed, moved = 0, [], []
    for p in doc["params"]:
        if p["kind"] not in NUMERIC or (names is not None and p["name"] not in names):
            continue
        # the slider's ends: its max is the last of its steps from its min
        top = p["min"] + math.floor((p["max"] - p["min"]) / p["step"] + 1e-9) * p["step"]
        for end, x in (("min", p["min"]), ("max", top)):
            count += 1
            values = {p["name"]: _text(p, x)}
            got = run(values)
            if not got["ok"]:
                got, clamped = compiler.settle(run, values, got)
                assert p["name"] not in clamped, (entry.id, p["name"], end)   # the slider stays
                if clamped:
                    moved.append((entry.id, p["name"], end, clamped))
            if not got["ok"]:
                failed.append((entry.id, p["name"], end, p[end]))
    return count, failed, moved


def main(argv=None) -> int:
    from aidl_lang.studio import gallery
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ids", nargs="*", help="entry ids (default: every entry)")
    a = ap.parse_args(argv)
    todo = [e for e in gallery.entries() if not a.ids or e.id in a.ids]
    total, failed, moved, cpu = 0, [], [], 0.0
    with tempfile.TemporaryDirectory() as d:
        for e in todo:
            t = time.process_time()
            n, f, m = extremes(e, str(Path(d) / "main.aidl"))
            dt = time.process_time() - t
            total, cpu = total + n, cpu + dt
            failed += f
            moved += m
            print(f"{e.id:32s} {n:3d} extremes {dt:6.2f} s CPU  {len(f)} failing  {len(m)} moved")
    print(f"{len(todo)} entries, {total} extremes, {len(failed)} failing, {len(moved)} moved, "
          f"{cpu:.1f} s CPU")
    for f in failed:
        print("failing:", f)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
