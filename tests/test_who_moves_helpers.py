"""Issue 111: of a child and a helper (construction geometry) related, the first-named moves.

A model's cat bookend placed its tail's tab with `Midpoint(tab.bottom.midpoint, axis)`, the
axis a construction line of the cat; the solve moved the tab 4.6 mm and the axis the rest of
the way, so the tail, drawn at literal coordinates beside the axis, was left behind.  The
prompt says the first-named moves to the second: the tab moves, the axis stays where written
(tree._held_helpers).  A helper also placed on the part moves to it as before (issue 73: a
bolt square on its plate).
"""
from __future__ import annotations

import pytest

import aidl_lang

CAT = """units mm
solid cat {{
    body = Rectangle(center=(0, 0), width=60, height=40)
    axis = Line((20, 20), (20, 60), construction=true)
    tail = Polygon([(18, 18), (24, 18), (26, 55), (20, 58)])
    solid tab {{
        r = Rectangle(center=(8, 45), width=10, height=20)
    }}
    {relation}
{extra}}}
"""


def _values(src: str) -> dict:
    r = aidl_lang.compile(src)
    assert r.ok, [d.message for d in r.errors]
    return {v.name: v.mm for v in r.values}


@pytest.mark.parametrize("relation", [
    "Midpoint(tab.r.bottom.midpoint, axis)",
    "tab.r.bottom.midpoint == axis.midpoint",
    "Coincident(tab.r.bottom.midpoint, axis.midpoint)",
])
def test_the_tab_moves_to_the_axis_the_axis_stays(relation):
    v = _values(CAT.format(relation=relation, extra=""))
    assert v["cat.axis.start"] == pytest.approx((20, 20), abs=1e-9)     # as written
    assert v["cat.axis.end"] == pytest.approx((20, 60), abs=1e-9)
    assert v["cat.tail.p0"] == pytest.approx((18, 18), abs=1e-9)
    # the tab's bottom on the axis's midpoint: moved the whole 12 mm, 5 mm (the axis
    # moved 12 mm and 5 mm before, the tab not at all)
    assert v["cat.tab.r.center"] == pytest.approx((20, 50), abs=1e-9)

