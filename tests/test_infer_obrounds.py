"""An obround is one Slot however it is drawn (issue 85, "obrounds of any angle"): two lines
and two half circles (:func:`~aidl_lang.drawing.infer.shapes._as_slot`), or a rounded
rectangle whose corner radius is half its height, its caps as quarter arcs
(:func:`~aidl_lang.drawing.infer.shapes._as_rrect`).  Both readers claim such a loop, so they
must agree: the same length, width, centre and turn (in (-90, 90] degrees: a slot turned
half a turn is the same slot), at every angle."""
from __future__ import annotations

import math

from hypothesis import given, settings, strategies as st

from aidl_lang.drawing.infer.shapes import _as_rrect, _as_slot, recognise, rrect_pieces
from aidl_lang.geometry.shapes.curves import Arc, Line


def _obround(c, length, width, rot) -> list:
    """An obround as two lines and two half circles, counter-clockwise."""
    r, span = width / 2, length - width
    u = (math.cos(rot), math.sin(rot))
    p = (c[0] - u[0] * span / 2, c[1] - u[1] * span / 2)
    q = (c[0] + u[0] * span / 2, c[1] + u[1] * span / 2)
    n = (-u[1] * r, u[0] * r)
    return [Line((p[0] - n[0], p[1] - n[1]), (q[0] - n[0], q[1] - n[1])),
            Arc(q, r, rot - math.pi / 2, math.pi),
            Line((q[0] + n[0], q[1] + n[1]), (p[0] + n[0], p[1] + n[1])),
            Arc(p, r, rot + math.pi / 2, math.pi)]


def _turn(a: float) -> float:
    """``a`` (radians) as a slot's turn, in (-pi/2, pi/2]."""
    a = math.remainder(a, math.pi)
    return a + math.pi if a <= -math.pi / 2 + 1e-12 else a


def _check(sh, c, length, width, rot):
    assert sh is not None and sh.kind == "Slot", sh
    assert abs(sh.args["length"] - length) <= 1e-9 and abs(sh.args["width"] - width) <= 1e-9
    assert math.dist(sh.center, c) <= 1e-9
    d = abs(sh.args["rotation"] - _turn(rot))
    assert min(d, math.pi - d) <= 1e-9 and -math.pi / 2 < sh.args["rotation"] <= math.pi / 2 + 1e-12, \
        (math.degrees(sh.args["rotation"]), math.degrees(rot))


@settings(max_examples=150, deadline=None)
@given(st.floats(-50, 50), st.floats(-50, 50), st.floats(2, 20), st.floats(0.5, 30),
       st.integers(-360, 360), st.floats(0, 1))
def test_obround_is_one_slot_however_drawn(x, y, width, extra, deg, frac):
    length = width + extra
    rot = math.radians(deg + frac * 0.9)
    c = (x, y)
    segs = _obround(c, length, width, rot)
    _check(_as_slot(segs), c, length, width, rot)
    _check(recognise(segs), c, length, width, rot)
    # the same outline as a rounded rectangle of radius half its height (caps as quarter arcs)
    rr = rrect_pieces(c, length, width, rot, [width / 2] * 4)
    _check(_as_rrect(rr), c, length, width, rot)
    _check(_as_slot(rr), c, length, width, rot)
    _check(recognise(rr), c, length, width, rot)
    # and a rounded rectangle stood on its end (its height the longer side)
    rr = rrect_pieces(c, width, length, rot - math.pi / 2, [width / 2] * 4)
    _check(_as_rrect(rr), c, length, width, rot)
    _check(recognise(rr), c, length, width, rot)
