"""Text cut as a stencil in one `Text` (issue 95): `Text("HELLO", ..., stencil=true)` in a
hole cuts the letters as openings, their islands (the counters of O, A, B, ...) held by
bridges.  Through the real pipeline; the SVG read back with svgelements.  The law, over
generated strings of the font's letters, digits and signs: the sheet stays one piece (no
island falls out), every opening lies inside the letters' strokes, and the bridges take a
little of them.  (~4 s CPU.)"""
import string

import pytest
import svgelements
from hypothesis import example, given, settings, strategies as st
from shapely.geometry import Polygon
from shapely.ops import unary_union

import aidl_lang
from aidl_lang.geometry.shapes.tessellate import CHORD_TOL

SRC = """solid stencil {{
    body = Rectangle(center=(0, 0), width={w}, height=80)
    hole letters {{ t = Text("{text}", position=(0, 0), size=30, valign="middle", stencil=true{extra}) }}
}}
"""


def _compile(text, extra="", w=None):
    r = aidl_lang.compile(source=SRC.format(text=text, extra=extra, w=w or 40 + 30 * len(text)))
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    return r


def _polys(part):
    outer = [lp for lp in part.loops if lp.area > 0]
    holes = [lp for lp in part.loops if lp.area < 0]
    return outer, [Polygon(lp.points()) for lp in holes]


def test_hello_is_cut_as_a_stencil_in_one_text(tmp_path):
    """The issue's HELLO: one sheet with six openings (H, E, L, L and the O in two halves,
    bridged top and bottom), read back from the SVG: 7 closed outlines, the O's halves
    mirror images of each other."""
    p = tmp_path / "hello.aidl"
    p.write_text(SRC.format(text="HELLO", extra="", w=200))
    from aidl_lang.cli.main import main
    assert main(["render", str(p), "-o", str(tmp_path / "hello.svg")]) == 0
    svg = svgelements.SVG.parse(str(tmp_path / "hello.svg"))
    subpaths = [sp for e in svg.elements() if isinstance(e, svgelements.Path)
                for sp in e.as_subpaths()]
    assert len(subpaths) == 7
    r = _compile("HELLO", w=200)
    [part] = r.output.parts
    outer, holes = _polys(part)
    assert len(outer) == 1 and len(holes) == 6
    o1, o2 = sorted(holes, key=lambda h: h.centroid.x)[-2:]
    assert o1.area == pytest.approx(o2.area, rel=1e-3)
    assert o1.bounds[2] < o2.bounds[0]                    # a bridge between the halves
    assert o2.bounds[0] - o1.bounds[2] == pytest.approx(3.0, abs=1e-6)   # size / 10


LETTERS = string.ascii_letters + string.digits + "&@%$#?!"


@settings(max_examples=6, deadline=None)
@given(text=st.text(alphabet=LETTERS, min_size=1, max_size=6))
@example(text="$")          # drawn at --hypothesis-seed=2 (issue 109): kept on every run
def test_law_the_sheet_stays_one_piece(text):
    r = _compile(text)
    parts = r.output.parts
    assert len(parts) == 1
    outer, holes = _polys(parts[0])
    assert len(outer) == 1                                # no island left in any opening
    plain = _compile(text, extra=", bridge=0.001")       # (a hair: the letters themselves)
    _, letters = _polys(plain.output.parts[0])
    whole = unary_union(letters)
    cut = unary_union(holes)
    # (chords: a letter's curves and a stencil's pieces of them, split at a bridge, are each
    # sampled within CHORD_TOL of the curve, at different points: one's vertices stand up to
    # that far outside the other's chords.  Within 0.002 mm, "$" at --hypothesis-seed=2 stood
    # 0.0044 mm^2 out, 0.003 mm high slivers along its bar's round ends; issue 109)
    assert cut.difference(whole.buffer(CHORD_TOL + 0.001)).area < 1e-3
    # (no counter: no bridge.  The bridges' share was bound at a quarter of the letters:
    # "$" at --hypothesis-seed=2, issue 109, gives 36 %, right: its two bars stand 0.72 mm
    # apart, one long counter between them, and the 3 mm band through it runs down both
    # bars' inner edges, the stencil's usual bridge between a dollar's bars)
    assert -1e-6 < whole.area - cut.area < 0.4 * whole.area


@pytest.mark.parametrize("call,code,said", [
    ('Text("HI", position=(0, 0), size=10, stencil=true, bridge=6)', "E0108", "narrower"),
    ('Text("HI", position=(0, 0), size=10)', "E0120", "stencil=true"),
])
def test_stencil_mistakes_are_said_at_the_call(call, code, said):
    r = aidl_lang.compile(source="solid s {\n    body = Rectangle(center=(0, 0), width=60, "
                          f"height=30)\n    hole h {{ t = {call} }}\n}}\n")
    [e] = r.errors
    assert e.code == code and said in (e.message + (e.hint or "")) and e.span.line == 3
