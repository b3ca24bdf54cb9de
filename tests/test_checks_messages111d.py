"""Issue 111's model runs n-s (data/model_runs/issue111{n..s}): messages whose hint was a dead
end, each followed as a model would (the hint's own text pasted into the program)."""
from __future__ import annotations

import re
from pathlib import Path

import aidl_lang

RUNS = Path(__file__).resolve().parent.parent / "data" / "model_runs"


def test_E0408_gives_the_corners_point_where_an_edge_is_an_ellipses():
    """Run s's paddle: `Fillet([handle.top_left, handle.top_right], 8)` where the handle meets
    an Ellipse blade: E0408's hint said "name the two edges that meet there", and naming the
    Ellipse was E0108 (a dead end).  The hint now writes the corner's point; pasted in, the
    program is valid and its two inside corners are rounded (more area than sharp)."""
    src = (RUNS / "issue111s/drafts/06_paddle_blank.attempt1.aidl").read_text()
    r = aidl_lang.compile(source=src)
    errs = [d for d in r.diagnostics if d.code == "E0408"]
    assert len(errs) == 2
    calls = [re.search(r"`(Fillet\(at=[^`]*)`", e.hint).group(1) for e in errs]
    assert calls[0] == "Fillet(at=(-12.5, 101.1049), radius=8 mm)"
    pts = [re.search(r"at=(\([^)]*\))", c).group(1) for c in calls]
    fixed = src.replace("    Fillet([handle.top_left, handle.top_right], 8)",
                        f"    Fillet(at=[{pts[0]}, {pts[1]}], radius=8 mm)")
    assert fixed != src
    r2 = aidl_lang.compile(source=fixed)
    assert r2.ok, [d.message for d in r2.diagnostics if d.is_error]
    sharp = aidl_lang.compile(source=src.replace(
        "    Fillet([handle.top_left, handle.top_right], 8)\n", ""))
    # the handle meets the blade in two inside corners: rounded, they gain material
    assert r2.parts[0].area > sharp.parts[0].area + 10
