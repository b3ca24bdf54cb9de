"""A sweep's combination bound is one it judged on both sides (issue 110).

`check --sweep` said "`w` below 41.5 with `n` above 7: W0507" (the place where the line from
the written values to the failing point turned clean), yet w = 44 with n = 8 failed too.  Each
param of a combination is now bisected alone, the others held at the failing values, and its
bound is said only when the point at it was judged clean, one past it failing, and no point the
sweep judged on that line says otherwise (aidl_lang/params/sweep.py, `_Sweep._bounds`).

The reproduction: a plate `w` wide with `n` slots 3 mm wide at `w / n`: the wall at the plate's
edge is `w / (2 n) - 1.5` mm, thinner than 0.5 mm below w = 4 n (40 mm at n = 10), so the edge
of the failing region is a slanted line that no box "w below X with n above Y" follows.  The
law: every combination sentence's claim holds at every point the sweep judged and at points
checked here by a plain compile (and on a plate's hole at `off` of radius `r`).  Cost:
about 6 s of CPU (a few sweeps and compiles)."""
from __future__ import annotations

import pytest

import aidl_lang
from aidl_lang.params.sweep import sweep
from test_studio_sweep import SLID  # noqa: E402

SLOTS = """units mm
param w = 60 mm, min = 20 mm, max = 100 mm
param n = 4, min = 1, max = 10, step = 1

solid plate {{
    body = Rectangle(center=(0, 0), width=w, height=30)
    for i in range(n) {{
        hole s {{ r = Rectangle(center=(-w / 2 + (i + 0.5) * w / n, 0), width={slot}, height=20) }}
    }}
}}
"""


def _fails(source: str, values: dict, units: dict) -> bool:
    """A plain compile at ``values`` has a problem the written values do not (the sweep's own
    rule): an error, a warning on a line the written compile has none of that code, or a
    part whose topology changes (a hole breaking through the outline; a count's openings
    aside)."""
    from aidl_lang.output.checks.changes import topology, topology_changes

    def said(r):
        return {(d.code, d.span.line if d.span else None) for d in r.diagnostics
                if d.severity != "info" and d.code not in ("W0510", "W0521")}
    written = aidl_lang.compile(source=source, path="p.aidl")
    ov = {n: f"{x:g} {units.get(n, '')}".strip() for n, x in values.items()}
    r = aidl_lang.compile(source=source, path="p.aidl", overrides=ov)
    if not r.ok or said(r) - said(written):
        return True
    base, now = topology(written.compiled.drawing), topology(r.compiled.drawing)
    return any(w for part, t in now.items() if part in base
               for w in topology_changes(base[part], t)
               if not (" opening" in w and "instead of" in w))


def _claims(rep):
    """Each combination's bounds as (finding, param, clean value, failing value, side)."""
    for f in rep.findings:
        if len(f.clean) > 1:
            for n, (clean, failing, side) in f.bounds.items():
                yield f, n, clean, failing, side


def _holds_at_the_points_judged(rep, written: dict) -> None:
    """No point the sweep judged on a bound's line contradicts it: clean from the written
    value to the bound, failing past it up to the finding's value."""
    for f, n, clean, failing, side in _claims(rep):
        up = side == "above"
        assert (failing > clean) == up and (f.values[n] > written[n]) == up
        line = {k: v for k, v in f.values.items() if k != n}
        on = 0
        for key, codes in rep.seen.items():
            pt = dict(key)
            if any(pt[k] != v for k, v in line.items()) or \
                    any(pt[k] != written[k] for k in pt if k not in f.values):
                continue
            x, on = pt[n], on + 1
            if min(written[n], clean) <= x <= max(written[n], clean):
                assert not codes, (n, x, codes, rep.combinations())
            elif min(clean, f.values[n]) <= x <= max(clean, f.values[n]):
                assert codes, (n, x, rep.combinations())
        assert on >= 3          # the written value, the bound, a failing value at least


def test_the_issues_combination_is_said_by_bounds_judged_on_both_sides():
    src = SLOTS.format(slot=3)
    rep = sweep(src, "slots.aidl")
    written = {"w": 60.0, "n": 4.0}
    [f] = [f for f in rep.findings if len(f.clean) > 1]
    assert f.values == {"w": 20.0, "n": 10.0}
    w_clean, w_failing, _ = f.bounds["w"]
    n_clean, n_failing, _ = f.bounds["n"]
    # at n = 10 the edge wall breaks below w = 40 mm; at w = 20 mm above n = 4 (wall 0.5)
    assert 40.0 <= w_clean <= 40.0 + 0.8 and w_failing < w_clean
    assert (n_clean, n_failing) == (4.0, 5.0)
    [line] = rep.combinations()
    assert line == (f"`w` below {w_clean:g} mm with `n` = 10; `n` above 4 with `w` = 20 mm: "
                    f"{f.code}"), line
    assert f"sweep: combination: {line}" in rep.text()
    [js] = [g for g in rep.to_json()["findings"] if len(g["clean"]) > 1]
    assert js["bounds"]["n"] == {"clean": 4.0, "failing": 5.0, "side": "above"}
    # the issue's point: with n = 10, w = 34 mm (above the old diagonal bound) fails, and the
    # bound said puts it on the failing side
    assert _fails(src, {"w": 34.0, "n": 10.0}, rep.units) and 34.0 < w_clean
    _holds_at_the_points_judged(rep, written)


# test_studio_sweep's hole of radius `r` at `off` in a 60 x 40 mm plate (off to 25 mm, r to
# 18 mm): each alone is clean, together the wall to the right edge (30 - off - r) is thinner
# than 0.5 mm: a slanted line again, both reals
DISC = (SLID.replace("height=20", "height=40").replace("max=40 mm", "max=25 mm")
        .replace("max=5 mm", "max=18 mm"))


@pytest.mark.parametrize("src, written", [(SLOTS.format(slot=3), {"w": 60.0, "n": 4.0}),
                                          (SLOTS.format(slot=4), {"w": 60.0, "n": 4.0}),
                                          (DISC, {"off": 10.0, "r": 3.0})])
def test_law_each_bound_holds_where_the_sweep_judged_and_where_checked_here(src, written):
    """Every bound of every combination: the sweep's judged points agree, and a plain compile
    is clean at the bound and fails at the failing value judged and half-way from it to the
    finding's value (a slanted wall: one side each)."""
    rep = sweep(src, "p.aidl", points=4)
    claims = list(_claims(rep))
    assert claims, rep.text()
    _holds_at_the_points_judged(rep, written)
    for f, n, clean, failing, side in claims[:2]:
        at = dict(f.values)
        assert not _fails(src, {**at, n: clean}, rep.units), (n, clean)
        assert _fails(src, {**at, n: failing}, rep.units), (n, failing)
        mid = (failing + f.values[n]) / 2
        mid = float(round(mid)) if not rep.units[n] else mid        # a count
        assert _fails(src, {**at, n: mid}, rep.units), (n, mid)


def test_the_studios_sweep_says_bounds_judged_on_both_sides_too():
    """The studio's request (the scan of each slider alone, then the sweep's combinations,
    one budget): its combinations' bounds are bisected at the failing values, never read off
    the scan's values (which hold the other sliders where they are written)."""
    from aidl_lang.params.sweep_scan import scan_and_sweep
    _, rep = scan_and_sweep(DISC, "p.aidl")
    claims = list(_claims(rep))
    assert {n for _, n, *_ in claims} == {"off", "r"}, rep.combinations()
    _holds_at_the_points_judged(rep, {"off": 10.0, "r": 3.0})
    for f, n, clean, failing, side in claims:
        # the wall to the right edge: 30 - off - r >= 0.5 mm exactly where it is clean
        other = f.values["r" if n == "off" else "off"]
        edge = 30 - 0.5 - other
        assert failing > edge >= clean - 1e-9, (n, clean, failing, edge)


def test_a_combination_without_a_bound_judged_says_its_values_only():
    """A budget that ends before the bounds are bisected: the sentence gives the failing
    values and says no bound was judged on both sides, never the line's guess."""
    src = SLOTS.format(slot=3)
    full = sweep(src, "slots.aidl")
    [f] = [f for f in full.findings if len(f.clean) > 1]
    for work in range(full.work // 3, full.work, max(1, full.work // 12)):
        rep = sweep(src, "slots.aidl", work=work)
        combos = [g for g in rep.findings if len(g.clean) > 1]
        if combos and not combos[0].bounds:
            [line] = rep.combinations()
            assert line == f"`w` = 20 mm with `n` = 10 (no bound judged on both sides): {f.code}"
            return
    pytest.fail("no budget left a combination without bounds")
