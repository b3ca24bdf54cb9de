"""A width under the minimum reads under it (issue 113): W0507 and W0519 said "0.50 mm wide,
thinner than 0.5 mm" (two decimals), which the studio's page shows as "0.5 mm wide, thinner
than 0.5 mm" (it drops trailing zeros).  Two holes 10 mm across, their wall a hair under the
0.5 mm minimum, through the real parser, solver and Manifold: the width said, as the compiler
and as the page words it, is a number under the limit.
"""
from __future__ import annotations

import re

import pytest

from aidl_lang import api
from aidl_lang.output.checks.common import below
from aidl_lang.studio.wording import for_page

PLATE = """units mm
solid plate {{
    body = Rectangle(center=(0, 0), width=60, height=30)
    hole a {{ c = Circle(center=(-{x}, 0), radius=5) }}
    hole b {{ c = Circle(center=({x}, 0), radius=5) }}
}}
"""


@pytest.mark.parametrize("x", [5.247, 5.2475, 5.245])
def test_a_wall_under_the_minimum_reads_under_it(x):
    res = api.compile(source=PLATE.format(x=x), path="plate.aidl")
    walls = [d for d in res.diagnostics_json() if d["code"] == "W0507"]
    assert walls, res.diagnostics_json()
    for d in walls:
        for text in (d["message"], for_page(d["message"])):
            m = re.search(r"is ([\d.]+) mm wide, thinner than ([\d.]+) mm", text)
            assert m, text
            assert float(m.group(1)) < float(m.group(2)), text


def test_below_gives_the_decimals_that_read_under_the_limit():
    assert below(0.4996, 0.5) == "0.4996"
    assert below(0.499, 0.5) == "0.499"
    assert below(0.31, 0.5) == "0.31"
    assert below(0.3123, 0.5, 3) == "0.312"
    assert float(below(0.4999999999, 0.5)) < 0.5
