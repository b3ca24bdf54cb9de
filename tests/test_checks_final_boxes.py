"""Issue 84, alignment on a shape's final outline: a relation that reads the box of a
structure with a ``Fillet`` or ``Chamfer`` reads it before the rounding (which acts on the
finished outline); where the final outline does not reach the side read, W0405 gives both
sides and the difference (docs/codes.md W0405).  Final outlines are read back exactly
(``Result.parts``: lines and arcs), the differences checked against the corner geometry: a
90-degree corner pointing along an axis, filleted by ``r``, ends ``r * (sqrt(2) - 1)`` in."""
from __future__ import annotations

import math
import re

import pytest
from hypothesis import given, settings, strategies as st

import aidl_lang

X = """solid board {{ b = Rectangle(center=(0, 0), width=90, height=90) }}
solid x0 {{
    a = Rectangle(center=(10, 10), width=24, height=4, rotation={rot} deg)
    c = Rectangle(center=(10, 10), width=24, height=4, rotation={rot} deg + 90 deg)
    {op}
}}
{align}
"""


def _compile(rot=45, op="Fillet(radius=1.5)", align="AlignLeft(x0, board)"):
    r = aidl_lang.compile(X.format(rot=rot, op=op, align=align))
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    return r


def _w0405(r) -> list:
    return [d for d in r.diagnostics if d.code == "W0405"]


def _part(r, name):
    return next(p for p in r.parts if p.name == name).bbox


def test_align_left_on_a_filleted_x_says_how_far_in_its_outline_ends():
    r = _compile()
    (w,) = _w0405(r)
    assert w.span.line == 7 and "AlignLeft(x0, board)" in w.message
    assert "its left is at -45.000 mm, the final outline's at -44.379 mm (0.621 mm in)" \
        in w.message
    assert "x0.bb.left + 0.62132 mm ==" in w.hint
    # the exact outline: the X's left tip is r (sqrt 2 - 1) in from the board's edge
    assert _part(r, "model.x0")[0] == pytest.approx(-45 + 1.5 * (math.sqrt(2) - 1), abs=1e-9)


def test_the_hints_equation_puts_the_outline_on_the_edge_and_is_not_warned():
    r = _compile(align="x0.bb.left + 1.5 mm * (sqrt(2) - 1) == board.bb.left\n"
                       "AlignCenterY(x0, board)")
    assert not _w0405(r)
    assert _part(r, "model.x0")[0] == pytest.approx(-45, abs=1e-9)


def test_a_rounded_corner_off_the_side_read_is_not_warned():
    # an upright cross: its left side is a straight edge, the fillets are off it
    r = _compile(rot=0)
    assert not _w0405(r)
    assert _part(r, "model.x0")[0] == pytest.approx(-45, abs=1e-9)


@settings(max_examples=12, deadline=None)
@given(r=st.integers(1, 19).map(lambda k: k / 10), side=st.sampled_from(
    [("AlignLeft", 0, 1), ("AlignRight", 2, -1), ("AlignTop", 3, -1),
     ("AlignBottom", 1, 1)]), op=st.sampled_from(["Fillet(radius={r})",
                                                    "Chamfer(distance={r})"]))
def test_law_the_warned_difference_is_the_outlines(r, side, op):
    """For a fillet radius or chamfer leg ``r`` on the 45-degree X aligned on any side of the
    board: W0405 gives the difference the exact final outline has (a fillet
    ``r (sqrt 2 - 1)``, a chamfer of legs ``r`` on a 90-degree tip ``r / sqrt 2``), and the
    outline ends that far in from the board's side."""
    name, k, inward = side
    res = _compile(op=op.format(r=r), align=f"{name}(x0, board)")
    (w,) = _w0405(res)
    want = r * (math.sqrt(2) - 1) if op.startswith("Fillet") else r / math.sqrt(2)
    got = float(re.search(r"\(([0-9.]+) mm in\)", w.message).group(1))
    assert got == pytest.approx(want, abs=5e-4)
    edge = (-45, -45, 45, 45)[k]
    assert _part(res, "model.x0")[k] == pytest.approx(edge + inward * want, abs=1e-9)


# issue 84 item: Offset (a miter join's tips reach past the grown box, an inset's outline
# stays inside it) as well as Fillet and Chamfer, over generated shapes, operations and sides
SHAPES = {
    "x": "a = Rectangle(center=(10, 10), width=24, height=4, rotation={rot} deg)\n"
         "    c = Rectangle(center=(10, 10), width=24, height=4, rotation={rot} deg + 90 deg)",
    "star": "s = Star(center=(10, 10), points=5, outer_radius=20, inner_radius=8, "
            "rotation={rot} deg)",
    "rect": "s = Rectangle(center=(10, 10), width=24, height=14, rotation={rot} deg)",
}
OPS = {
    "fillet": ("", "Fillet(radius={r})"), "chamfer": ("", "Chamfer(distance={r})"),
    "offset": ("o = Offset(s, {r})", ""), "miter": ('o = Offset(s, {r}, join="miter")', ""),
    "inset": ("o = Inset(s, {r})", ""),
}
SIDE = {"AlignLeft": (0, "left"), "AlignRight": (2, "right"), "AlignBottom": (1, "bottom"),
        "AlignTop": (3, "top")}
LAW = """solid board {{ b = Rectangle(center=(0, 0), width=90, height=90) }}
solid x0 {{
    {shape}
    {made}
    {finish}
}}
{align}
"""


def _outlines(r) -> dict:
    return {p.name: tuple(p.bbox) for p in r.parts}


@settings(max_examples=24, deadline=None)
@given(shape=st.sampled_from(sorted(SHAPES)), op=st.sampled_from(sorted(OPS)),
       kind=st.sampled_from(sorted(SIDE)), rot=st.integers(0, 89),
       r=st.integers(5, 25).map(lambda k: k / 10))
def test_law_aligned_on_the_final_outline_or_warned_and_the_fix_puts_it_there(
        shape, op, kind, rot, r):
    """Random shape, random Fillet/Chamfer/Offset/miter Offset/Inset, random Align* kind:
    either the aligned sides of the final outlines coincide to 1e-6 mm, or W0405 is given;
    its hint's equation, written for the Align, removes it, puts the final outline on the
    board's side to 1e-6 mm and leaves the board and the part's extent along the other axis
    as they were."""
    if shape == "x" and op in ("offset", "miter", "inset"):
        shape = "rect"                      # an Offset takes one shape
    made, fin = OPS[op]
    src = LAW.format(shape=SHAPES[shape].format(rot=rot), made=made.format(r=r),
                     finish=fin.format(r=r), align=f"{kind}(x0, board)")
    res = aidl_lang.compile(src)
    assert res.ok, [f"{d.code} {d.message}" for d in res.errors]
    k, side = SIDE[kind]
    before = _outlines(res)
    board = before["model.board"]
    ws = _w0405(res)
    if abs(before["model.x0"][k] - board[k]) <= 1e-6:
        assert not ws
        return
    (w,) = ws
    eq = re.search(r"`(x0\.bb\.\w+ [+-] [0-9.]+ mm) == \.\.\.`", w.hint).group(1)
    fixed = aidl_lang.compile(src.replace(f"{kind}(x0, board)", f"{eq} == board.bb.{side}"))
    assert fixed.ok and not _w0405(fixed)
    after = _outlines(fixed)
    assert after["model.x0"][k] == pytest.approx(board[k], abs=1e-6)
    assert after["model.board"] == pytest.approx(board, abs=1e-9)
    o = (k + 1) % 2                       # the other axis: its extent as it was
    assert after["model.x0"][o] - before["model.x0"][o] == pytest.approx(0, abs=1e-6)
    w_b = before["model.x0"][k + 2 - 2 * (k // 2)] - before["model.x0"][k]
    assert after["model.x0"][k + 2 - 2 * (k // 2)] - after["model.x0"][k] == \
        pytest.approx(w_b, abs=1e-6)
