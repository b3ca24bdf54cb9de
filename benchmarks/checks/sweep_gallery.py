"""The default ``aidl check --sweep`` (each param's ends and middle, then its seeded Latin
hypercube of combinations) over every gallery entry with ranged params; prints each entry's
points, CPU seconds and findings (issue 84).  Not in the suite (minutes of CPU); the suite's
small pass is tests/test_sweep_gallery.py and tests/test_sweep_gallery_late.py
(test_every_gallery_entry_is_clean_across_its_declared_ranges).

    PYTHONPATH=$PWD python benchmarks/checks/sweep_gallery.py [--points N] [--seed S] [ID ...]

h14-lhs (34 ranged entries, 8 points, seed 0): before, 7 findings in 84 s CPU (finger 3.1 mm
on 6.5 mm sheet colliding in finger_box, lid_box, drawer; screw=7 in mounting_plate and
wall_shelf; divider_tray's assert over locals; sliding_lid_box's pull at 10 mm sheet); after,
0 findings in 78 s.  The suite's 3 combinations (seed 0) find two more, left in
tests/test_sweep_gallery.py's LEFT (flex_box's web, spur_gear's pointed teeth).

h17-sweep (40 entries, 8 points, every pair, load 18-20 on 2 cores): 137 s CPU, each entry within
the 15 s guard (tool_holder 15.0 s: the guard cut it at 88 of 100 points, 510,289 units, its
CPU a unit ~29 us, above the calibration); planetary 27 points and 32 not judged (730,534
units), ring_gear 2 not judged; 19 findings, all on params without a declared range but
planetary's (planet=13, sun=9: W0517).  ``--related`` runs the suite's plan.

h18-work (the work counting the booleans' and the fit check's vertices, parts and booleans;
600,000 units; 8 points, every pair, niced at load 5-7): 98 s CPU, 18 findings (planetary's
not reached: 15 points, 44 not judged); every entry at 8.9 s or less (ring_gear 8.9,
gear_pair 8.0, tool_holder 7.6, rack_and_pinion 7.4, gear_train 7.3), none near the 15 s
guard; 7 entries with planned points not judged (tool_holder 43, divider_tray 42, planetary
44, ring_gear 9, rack_and_pinion 8, gear_pair 6, board_enclosure 3).

``--units N`` measures the work's calibration instead (aidl_lang/params/sweep_plan.py): each
entry's default sweep to N work units, the CPU a unit of its points (its first compile, the
written values', left out), then the least, median and largest over the entries (and any
``--file`` given: the 8,000-hole panel of sweep_load.py).  h18-work (N = 40,000, load 8-10 on
2 cores): 2.0 / 7.3 / 12.5 us a unit over the 48 entries and the panel (tool_holder 12.5,
flex_box 12.4, the panel at 2 mm 4.6; before the booleans' and the fit check's counts:
1.5 / 8.8 / 30.5, board_enclosure 30).
"""
from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path


def ranged(entry) -> bool:
    return any(p["declared"] and p["min"] is not None and p["max"] is not None
               and p["kind"] in ("length", "angle", "number", "integer") for p in entry.params)


def main(argv=None) -> int:
    from aidl_lang.studio import gallery
    from aidl_lang.params.sweep import LHS_POINTS, SEED, sweep
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ids", nargs="*", help="entry ids (default: every ranged entry)")
    ap.add_argument("--points", type=int, default=LHS_POINTS, help="Latin hypercube size")
    ap.add_argument("--seed", type=int, default=SEED)
    ap.add_argument("--budget", type=float, default=None, help="budget factor per sweep")
    ap.add_argument("--related", action="store_true",
                    help="the suite's plan: a count at its ends only with the params related "
                         "to it (sweep(pairs='related')); default every pair")
    ap.add_argument("--units", type=int, default=0,
                    help="the CPU a work unit of each entry's sweep to this many units")
    ap.add_argument("--file", action="append", default=[], help="a program to measure too")
    a = ap.parse_args(argv)
    if a.units:
        return units(a.units, a.ids, a.file)
    todo = [e for e in gallery.entries() if ranged(e) and (not a.ids or e.id in a.ids)]
    total, found = 0.0, 0
    with tempfile.TemporaryDirectory() as d:
        for e in todo:
            rep = sweep(e.source, str(Path(d) / "main.aidl"), budget=a.budget,
                        points=a.points, seed=a.seed, pairs="related" if a.related else True)
            total += rep.seconds
            found += len(rep.findings)
            print(f"{e.id}: {rep.points} points, {rep.work:,} work units, {rep.seconds:.1f} s, "
                  f"{len(rep.findings)} finding(s)" + (f", {rep.skipped} skipped"
                                                      if rep.skipped else ""), flush=True)
            for f in rep.findings:
                print(f"    {f.diagnostic.message}\n      {f.diagnostic.hint}", flush=True)
            if not rep.ok:
                print("    not compiled:", "; ".join(x.message for x in rep.errors[:2]))
    print(f"{len(todo)} entries, {found} finding(s), {total:.0f} s CPU")
    return 1 if found else 0


def units(n: int, ids, files) -> int:
    """Each entry's (and each file's) default sweep to ``n`` work units: the CPU seconds of
    its compiles but the first over the units they counted, printed with the band."""
    import statistics
    import time
    from aidl_lang.params import sweep as S
    from aidl_lang.studio import gallery
    spent: dict = {}
    cur = [None, True]
    compile_ = S._Sweep._compile

    def timed(self, ov):
        t = time.process_time()
        got = compile_(self, ov)
        if not cur[1]:
            c = spent.setdefault(cur[0], [0.0, 0, 0])
            c[0] += time.process_time() - t
            c[1] += got.cost
            c[2] += 1
        cur[1] = False
        return got
    S._Sweep._compile = timed
    todo = [(f, Path(f).read_text()) for f in files] + [
        (e.id, e.source) for e in gallery.entries() if not ids or e.id in ids]
    with tempfile.TemporaryDirectory() as d:
        for name, source in todo:
            cur[:] = [name, True]
            S.sweep(source, str(Path(d) / "main.aidl"), work=n)
    S._Sweep._compile = compile_
    rate = {k: c / u * 1e6 for k, (c, u, _) in spent.items() if u}
    for k in sorted(rate, key=rate.get):
        print(f"{rate[k]:6.1f} us a unit  {spent[k][2]:3d} compiles  {spent[k][0]:6.2f} s  {k}")
    v = sorted(rate.values())
    print(f"{len(v)} programs: min {v[0]:.1f}, median {statistics.median(v):.1f}, "
          f"max {v[-1]:.1f} us a unit")
    return 0


if __name__ == "__main__":
    sys.exit(main())
