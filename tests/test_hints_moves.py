"""Issue 84, every hint safe: W0508 (two holes overlap) and W0507 (the wall between two holes
thinner than ``min_wall``) say "move hole `B` D mm further from hole `A`".  D was measured on
the chords of the circles (0.005 mm inside them each) and rounded to the nearest 0.01 mm,
so the move as written could leave 0.49 mm of a 0.5 mm minimum (W0507 again: 8 of 30
generated overlaps before).  The law: two round holes of random radii at a random angle,
overlapping or 0.05 to 0.45 mm apart; the hole the hint names moved D mm along the line of
centres, away from the other: no warning left, the wall at least the minimum (and at
most 0.03 mm more), each hole the same circle in its own opening."""
from __future__ import annotations

import math
import re

import pytest
from hypothesis import given, settings, strategies as st

import aidl_lang

PLATE = """solid plate {{
    body = Rectangle(center=(0, 0), width=80, height=60)
    hole a {{ c = Circle(center=({ax}, {ay}), radius={ra}) }}
    hole b {{ c = Circle(center=({bx}, {by}), radius={rb}) }}
}}
"""
MOVE = re.compile(r"move hole `plate\.(\w+)` ([0-9.]+) mm further from hole `plate\.(\w+)`")


def _compile(a, b, ra, rb):
    r = aidl_lang.compile(PLATE.format(ax=round(a[0], 6), ay=round(a[1], 6), bx=round(b[0], 6),
                                       by=round(b[1], 6), ra=ra, rb=rb))
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    return r


def _warnings(r) -> list:
    return [d for d in r.diagnostics if d.severity == "warning"]


@settings(max_examples=16, deadline=None)
@given(ra=st.sampled_from([2, 3, 4.5]), rb=st.sampled_from([2, 3.3, 5]),
       angle=st.floats(0, 2 * math.pi), gap=st.one_of(st.floats(-2.5, -0.05),
                                                       st.floats(0.05, 0.45)))
def test_law_moving_a_hole_as_the_hint_says_clears_it(ra, rb, angle, gap):
    a = (-5.0, 0.0)
    u = (math.cos(angle), math.sin(angle))
    b = (a[0] + (ra + rb + gap) * u[0], a[1] + (ra + rb + gap) * u[1])
    r = _compile(a, b, ra, rb)
    (w,) = [d for d in _warnings(r) if d.code in ("W0507", "W0508")]
    assert w.code == ("W0508" if gap < 0 else "W0507")
    who, dist, other = MOVE.search(w.hint).groups()
    assert {who, other} == {"a", "b"}
    d = float(dist)
    if who == "b":
        b = (b[0] + d * u[0], b[1] + d * u[1])
    else:
        a = (a[0] - d * u[0], a[1] - d * u[1])
    fixed = _compile(a, b, ra, rb)
    assert _warnings(fixed) == [], (w.hint, [x.message for x in _warnings(fixed)])
    # the material left between the two holes (mm, a geometric web, not a time): at least
    # the 0.5 mm minimum, and the move not more than 0.03 mm beyond it
    web_mm = math.hypot(b[0] - a[0], b[1] - a[1]) - ra - rb
    assert 0.5 <= web_mm <= 0.5 + 0.03
    # each hole the same circle, now its own opening: the plate less two whole discs
    (part,) = fixed.parts
    assert part.holes == 2
    assert part.area == pytest.approx(80 * 60 - math.pi * (ra * ra + rb * rb), abs=0.05)
