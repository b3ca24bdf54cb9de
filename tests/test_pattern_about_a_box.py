"""A pattern about a point read from a bounding box (issue 111, run r's utensil crock:
`CircularPattern(drain, 4, box.bottom.bb.center, start_angle=45 deg)` with the original
placed by `polar(box.bottom.bb.center, ...)` ended "internal error: TapeError: cannot compile
BBTerm into a residual", no file, no line).  The copy rules are deferred as a box constraint's
are; the holes land where the pattern says, read back from the part as cut."""
from __future__ import annotations

import pytest

import aidl_lang

SRC = """import "std/joints.aidl"
thickness 3 mm
assembly crock {
    box = finger_box(length=100 mm, depth=100 mm, height=80 mm, thickness=3 mm, finger=10 mm,
                     closed=false)
    hole drain { c = Circle(center=(0, 0), diameter=6) }
    drains = CircularPattern(drain, 4, box.bottom.bb.center, start_angle=45 deg)
    Coincident(drain.c.center, polar(box.bottom.bb.center, 25 mm, ANGLE))
    CutInto(drain, box.bottom)
}
"""


@pytest.mark.parametrize("angle, at", [("0 deg", 45), ("45 deg", 90)])
def test_a_circular_pattern_about_a_panels_box_centre(angle, at):
    r = aidl_lang.compile(source=SRC.replace("ANGLE", angle))
    assert r.ok, [d.message for d in r.diagnostics if d.is_error]
    import math
    vals = {v.name: v.mm for v in r.values}
    cx, cy = vals["crock.box.bottom.bbox"][0:2]
    cx, cy = (cx + vals["crock.box.bottom.bbox"][2]) / 2, (cy + vals["crock.box.bottom.bbox"][3]) / 2
    got = sorted(tuple(round(c, 6) for c in vals[k]) for k in vals
                 if k.startswith("crock.drains[") and k.endswith(".c.center"))
    # the original at `angle` on the 25 mm circle (construction: start_angle turns all),
    # its 4 copies turned by start_angle 45, then every 90
    want = sorted((round(cx + 25 * math.cos(math.radians(at + 90 * k)), 6),
                   round(cy + 25 * math.sin(math.radians(at + 90 * k)), 6)) for k in range(4))
    assert len(got) == 4
    assert [c for p in got for c in p] == pytest.approx([c for p in want for c in p], abs=1e-6)
