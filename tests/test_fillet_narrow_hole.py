"""W0410 (the fresh models' run data/model_runs/issue105b, request 8): a `Fillet(4)` written
beside a bracket's plate rounds every corner of the final outline, the 4.2 mm tab slot's too,
whose ends then come out round (2.1 mm: half its width) and no square tab fits.  A note names
the hole, its width and what fitted; its hint, followed, rounds the plate alone and the check
is clean; a hole wide enough for the radius, or a Fillet with `at`, says nothing."""
from __future__ import annotations

import pytest

import aidl_lang

BRACKET = """units mm
solid bracket {
    plate = Rectangle(center=(0, 0), width=100, height=60)
    %s
    hole tab {
        s = Rectangle(center=(10, -20), width=40, height=%s)
    }
}
"""


def _check(fillet: str, slot: float = 4.2):
    return aidl_lang.compile(source=BRACKET % (fillet, slot), path="bracket.aidl")


def test_a_whole_outline_fillet_that_rounds_a_slots_ends_is_a_note_and_its_hint_is_clean():
    res = _check("Fillet(4)")
    assert res.ok
    [d] = [d for d in res.diagnostics if d.code == "W0410"]
    assert d.severity == "note" and d.span.line == 4
    assert "the hole at (10, -20) mm, 4.2 mm across: only 2.1 mm fits" in d.message
    assert "`Fillet(plate, 4)`" in d.hint
    fixed = _check("Fillet(plate, 4)")
    assert fixed.ok and not fixed.diagnostics, [x.message for x in fixed.diagnostics]
    slot = next(p for p in fixed.parts)
    # the plate's corners rounded, the slot's square: the part's area is the plate's less
    # its four corners' (4 - pi) r^2 and less the whole 40 x 4.2 slot
    assert slot.area == pytest.approx(100 * 60 - (4 - 3.141592653589793) * 16 - 40 * 4.2,
                                      abs=1e-6)


@pytest.mark.parametrize("fillet, slot", [("Fillet(4)", 9.0), ("Fillet(plate, 4)", 4.2),
                                          ("Fillet([plate.top, plate.right], 4)", 4.2)])
def test_no_note_where_the_hole_takes_the_radius_or_the_corners_are_named(fillet, slot):
    res = _check(fillet, slot)
    assert res.ok and not [d for d in res.diagnostics if d.code == "W0410"]


WINDER = """units mm
solid winder {
    left = Rectangle(center=(-18, 0), width=14, height=70)
    right = Rectangle(center=(18, 0), width=14, height=70)
    bar = Rectangle(center=(0, 0), width=22, height=22)
    hole slit {
        s = Rectangle(center=(-18, 30), width=%s, height=10)
    }
    AlignTop(slit, left)
    %s
}
"""


def test_a_whole_outline_fillet_that_rounds_a_narrow_notchs_bottom_is_a_note():
    """The fresh models' cable winder (data/model_runs/issue105c, request 15): a 3 mm slit
    cut from the top edge under `Fillet(4)` comes out with a round bottom and a flared mouth,
    silently; now the note W0410 names the notch, and its hint (the part's shapes named)
    leaves the slit square, with W0406 saying what the mouth's corners got."""
    res = aidl_lang.compile(source=WINDER % (3, "Fillet(4)"), path="winder.aidl")
    [d] = [d for d in res.diagnostics if d.code == "W0410"]
    assert d.severity == "note"
    assert "the notch whose bottom is at (-18, 25) mm, 3 mm across: only 1.5 mm fits" \
        in d.message
    assert "`Fillet([left, right, bar], 4)`" in d.hint
    fixed = aidl_lang.compile(source=WINDER % (3, "Fillet([left, right, bar], 4)"),
                              path="winder.aidl")
    codes = sorted(x.code for x in fixed.diagnostics)
    assert codes == ["W0406"], [x.message for x in fixed.diagnostics]
    wide = aidl_lang.compile(source=WINDER % (9, "Fillet(4)"), path="winder.aidl")
    assert not [x for x in wide.diagnostics if x.code == "W0410"]      # 9 mm takes r 4
