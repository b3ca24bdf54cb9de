"""Issue 111: W0505's `Inside(...)` names the shape the engraving is drawn over.

A model's cat bookend had a whisker on its head run off the outline; W0505's hint proposed
`Inside(face.w2, haunch, margin=0.5 mm)`: the part's largest shape, the hips, so following it
dragged the whisker 40 mm across the body.  The hint now names the shape of the part (or of a
solid within it, as written in the part: `head.skull`) whose face holds most of the mark, the
nearest among equals; followed, the whisker stays on the head.  Law 4, *a hint keeps the
design* (benchmarks/laws/law_hints.py), holds on the program.
"""
from __future__ import annotations

from types import SimpleNamespace

import pytest

import aidl_lang
from benchmarks.laws import law_hints

CAT = """units mm
solid cat {{
    haunch = Ellipse(center=(0, 0), rx=45, ry=30)
    {head}
    drawing face {{
        w1 = Line((58, 30), (72, 32))
        w2 = Line((58, 27), (74, 24))
        eye = Circle(center=(46, 40), radius=2)
    }}
{fix}}}
"""
CHILD = "solid head {\n        skull = Circle(center=(45, 30), radius=18)\n    }"
OWN = "skull = Circle(center=(45, 30), radius=18)"


def _w0505(src: str) -> dict:
    r = aidl_lang.compile(src)
    assert r.ok, [d.message for d in r.errors]
    return {d.message.split("`")[1]: d.hint for d in r.diagnostics if d.code == "W0505"}


@pytest.mark.parametrize("head, name", [(CHILD, "head.skull"), (OWN, "skull")])
def test_the_whiskers_hint_names_the_head_not_the_hips(head, name):
    hints = _w0505(CAT.format(head=head, fix=""))
    assert set(hints) == {"cat.face.w1", "cat.face.w2"}
    for mark, hint in hints.items():
        short = mark.removeprefix("cat.")
        assert f"`Inside({short}, {name}, margin=0.5 mm)` in `cat`" in hint, hint
        assert "haunch" not in hint


def test_the_hint_followed_keeps_the_whisker_on_the_head():
    src = CAT.format(head=CHILD, fix="    Inside(face.w2, head.skull, margin=0.5 mm)\n")
    r = aidl_lang.compile(src)
    assert r.ok, [d.message for d in r.errors]
    vals = {v.name: v.mm for v in r.values}
    x0, y0 = vals["cat.face.w2.start"]
    x1, y1 = vals["cat.face.w2.end"]
    # inside the skull's box (27..63, 12..48) with the margin, where `haunch` would have put
    # it inside (-45..45, -30..30): its right end was at 74 mm, now 62.5
    assert 27.5 - 1e-6 <= min(x0, x1) and max(x0, x1) <= 62.5 + 1e-6
    assert max(x0, x1) == pytest.approx(62.5, abs=1e-6)
    assert 12.5 - 1e-6 <= min(y0, y1) and max(y0, y1) <= 47.5 + 1e-6


def test_law_hints_holds_on_the_cat():
    src = CAT.format(head=CHILD, fix="")
    entry = SimpleNamespace(name="cat.aidl", path="cat.aidl", overrides={}, source=src)
    assert law_hints.check(entry) == []
