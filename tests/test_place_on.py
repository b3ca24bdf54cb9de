"""`Place(part, on=other, ...)`: a part placed in another part's frame (issue 111, run ep's
barn-door tracker: two sight vanes on a top board hinged open 5 deg were placed by hand with
`cos` and `sin` and came out 3 mm into the board, W0517; runs dy, eh, dv asked the same).

Through the real parser, solver, Manifold fit check and the 3MF writer re-read by trimesh."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import aidl_lang

ROOT = Path(__file__).resolve().parent.parent
RUN = ROOT / "data" / "model_runs" / "issue111ep" / "run" / "07_barn_door_tracker.first_valid.aidl"


def _codes(r):
    return [d.code for d in r.diagnostics]


def _tracker_on() -> str:
    """Run ep's tracker with its vanes placed on the top board (no trigonometry)."""
    src = RUN.read_text()
    i, j = src.index("    Place(near"), src.index("    Place(knob")
    return src[:i] + (
        "    Place(near, on=top, position=(vane_x, -vane_y + t / 2), rotation=(90 deg, 0, 0))\n"
        "    Place(far, on=top, position=(vane_x, vane_y + t / 2), rotation=(90 deg, 0, 0))\n"
    ) + src[j:]


def test_run_ep_vanes_on_the_hinged_board_fit_their_mortises():
    """As written by the model: W0517 twice (3 mm into the board).  Placed `on=top`: the
    vanes' tenons stand in their mortises of the board opened 5 deg, no collision, and each
    vane's matrix is the board's times its own step in the board's frame."""
    r0 = aidl_lang.compile(source=RUN.read_text(), path=str(RUN))
    assert _codes(r0).count("W0517") == 2
    r = aidl_lang.compile(source=_tracker_on(), path=str(RUN))
    assert r.ok and "W0517" not in _codes(r), [d.message for d in r.diagnostics]
    d = r.output.drawing
    a = math.radians(5)
    # the vane's body corner (-20, 50) of its own frame, z 0 (its bottom face), in the world:
    # turned 90 deg about x in the board's frame, at (20, -27, 6) there (its top face); the board turned
    # -5 deg about y at (0, 0, 6)
    vane = (-20.0, 50.0, 0.0)
    in_top = np.array([20 + vane[0], -27 - vane[2], 6 + vane[1]])
    Ry = np.array([[math.cos(-a), 0, math.sin(-a)], [0, 1, 0], [-math.sin(-a), 0, math.cos(-a)]])
    want = Ry @ in_top + np.array([0, 0, 6.0])
    ox, oy = d.origins["tracker.near"]
    got = d.placement["tracker.near"] @ np.array([ox + vane[0], oy + vane[1], 0.0, 1.0])
    assert np.allclose(got[:3], want, atol=1e-9)


def test_the_part_follows_the_one_it_stands_on():
    """Moving or turning the board moves the vane with it; the flat sheet is unchanged."""
    src = """thickness 3 mm
assembly kit {
    solid board { r = Rectangle(center=(0, 0), width=100, height=60) }
    solid post { r = Rectangle(corner=(-5, 0), opposite=(5, 40)) }
    Place(board, position=BOARD, rotation=TURN)
    Place(post, on=board, position=(30, 10), face="front", up="up")
    RightOf(post, board, gap=10)
}
"""
    def corner(board, turn):
        r = aidl_lang.compile(source=src.replace("BOARD", board).replace("TURN", turn))
        assert r.ok and "W0517" not in _codes(r), [d.message for d in r.diagnostics]
        d = r.output.drawing
        ox, oy = d.origins["kit.post"]
        return (d.placement["kit.post"] @ np.array([ox + 5, oy + 40, 0.0, 1.0]))[:3]
    # flat at (0, 0, 0): the post's (5, 40) corner at x 35, y 10 (its bottom face), z 3 + 40
    assert np.allclose(corner("(0, 0, 0)", "(0, 0, 0)"), (35, 10, 43), atol=1e-9)
    assert np.allclose(corner("(100, 50, 20)", "(0, 0, 0)"), (135, 60, 63), atol=1e-9)
    # the board turned half a turn about z: the post turns with it
    assert np.allclose(corner("(0, 0, 0)", "(0, 0, 180 deg)"), (-35, -10, 43), atol=1e-9)


def test_two_numbers_stand_on_the_top_face_of_its_own_thickness():
    """`position=(x, y)` with `on=` is on the part's top face: its own thickness, not the
    file's (a 12 mm base under 3 mm parts)."""
    src = """thickness 3 mm
assembly kit {
    solid base { thickness 12 mm
                 r = Rectangle(center=(0, 0), width=100, height=60) }
    solid puck { r = Circle(center=(0, 0), radius=10) }
    Place(base, position=(0, 0, 0))
    Place(puck, on=base, position=(20, 5))
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok and "W0517" not in _codes(r) and "W0518" not in _codes(r)
    d = r.output.drawing
    ox, oy = d.origins["kit.puck"]
    assert np.allclose(d.placement["kit.puck"] @ np.array([ox, oy, 0.0, 1.0]), (20, 5, 12, 1))


def test_on_a_structure_of_a_part_and_by_a_synonym():
    """`on=top.mortise` is the mortise's frame; `relative_to=` is `on=`."""
    src = """thickness 3 mm
assembly kit {
    solid top {
        r = Rectangle(center=(0, 0), width=100, height=60)
        hole mortise { s = Rectangle(center=(0, 0), width=20, height=3) }
        RightOf(mortise, r, gap=-40)
    }
    solid tab { r = Rectangle(corner=(-10, -3), opposite=(10, 20)) }
    Place(top, position=(0, 0, 0))
    Place(tab, WORD=top.mortise, position=(0, 1.5, 3), face="front", up="up")
}
"""
    for word in ("on", "relative_to"):
        r = aidl_lang.compile(source=src.replace("WORD", word))
        assert r.ok and "W0517" not in _codes(r), [d.message for d in r.diagnostics]
        d = r.output.drawing
        ox, oy = d.origins["kit.tab"]
        # the mortise was moved 20 mm right of (0, 0) by its relation (its left side 40 mm
        # in from the board's right, 50): the tab with it
        mx = d.placement["kit.tab"] @ np.array([ox, oy, 0.0, 1.0])
        assert np.allclose(mx[:3], (20, 1.5, 3), atol=1e-9)


@pytest.mark.parametrize("place, words", [
    ("Place(a, on=a, position=(0, 0, 3))", "`kit.a` is placed on itself"),
    ("Place(a, on=a.inner, position=(0, 0, 3))", "`kit.a` is placed on its own `kit.a.inner`"),
    ("Place(a, on=b, position=(0, 0, 3))\n    Place(b, on=a, position=(0, 0, 3))",
     "`kit.b` is placed on `kit.a`, which is placed on `kit.b`"),
    ("Place(a, on=5, position=(0, 0, 3))", "`on=` of `Place` names a structure, not a number"),
])
def test_errors_of_on(place, words):
    src = f"""thickness 3 mm
assembly kit {{
    solid a {{ r = Rectangle(center=(0, 0), width=10, height=10)
              hole inner {{ c = Circle(center=(0, 0), radius=2) }} }}
    solid b {{ r = Rectangle(center=(40, 0), width=10, height=10) }}
    {place}
}}
"""
    r = aidl_lang.compile(source=src)
    errs = [d for d in r.diagnostics if d.is_error]
    assert len(errs) == 1 and errs[0].code == "E0108" and words in errs[0].message, \
        [(e.code, e.message) for e in errs]
    assert errs[0].hint and errs[0].span.line >= 6


def test_the_3mf_re_read_puts_the_vane_on_the_board():
    """The assembled 3MF, re-read by trimesh: the near vane's lowest point is its tenon's
    tip, through the board's 6 mm (the board's bottom face under it, x 10..30 at 5 deg up),
    its thickness across the mortise's y."""
    import io

    import trimesh
    r = aidl_lang.compile(source=_tracker_on(), path=str(RUN))
    sc = trimesh.load(io.BytesIO(r.encode("3mf", assembled=True)), file_type="3mf")
    pts = {}
    for node in sc.graph.nodes_geometry:
        T, g = sc.graph[node]
        pts[node] = trimesh.transform_points(sc.geometry[g].vertices, T)
    near = next(v for n, v in pts.items() if n.endswith("near"))
    a = math.radians(5)
    # the tenon's tip (its local y -6 .. 0, x -10..10 at the vane's 20) on the board's
    # bottom face, z 6 + x sin(5 deg) in the board's turn: lowest at x 10
    assert near[:, 2].min() == pytest.approx(6 + 10 * math.sin(a), abs=1e-6)
    assert near[:, 1].min() == pytest.approx(-33, abs=1e-6)    # y -vane_y - t / 2
