"""Issue 85, anchoring as the drawing means it: `aidl import --infer` writes a plate's body
so that its width and height params grow it from the point its drawing is drawn from (a
corner at the origin: that corner; the centre at the origin: the centre), and places every
feature (a round hole, a cut-out no primitive makes, a bore with a key) from the body's
reference nearest it (its left or right edge, its centre; ties go to the centre), so that a
new width or height keeps each feature where the drawing ties it.

The law: a generated plate with generated features, drawn with ezdxf; its inferred program
compiled with a new width and height (``overrides``, as ``--set``) and written to DXF is the
drawing of the same design at the new size, exactly (1e-6 mm, no translation allowed), for
every feature kind and both origins."""
from __future__ import annotations

import math
import sys

import ezdxf
import pytest
from hypothesis import HealthCheck, given, reject, settings
from hypothesis import strategies as st

import aidl_lang
from aidl_lang.drawing.infer import import_drawing
from conftest import ROOT

sys.path.insert(0, str(ROOT / "tests"))
import dxf_compare  # noqa: E402


def _ref(v: float, size: float) -> tuple[int, float]:
    """The reference a coordinate is tied to: (-1 the low edge, 0 the centre, 1 the high
    edge, the offset from it); the nearest, ties to the centre, then the low edge."""
    side = min((0, -1, 1), key=lambda k: (round(abs(v - size / 2 - k * size / 2), 9), k != 0))
    return side, v - (size / 2 + side * size / 2)


def _moved(v: float, size: float, new: float) -> float:
    side, d = _ref(v, size)
    return new / 2 + side * new / 2 + d


ROW = (3, 9.0)          # a row of 3 holes 9 mm apart along x, its x the first hole's


def _moved_row(x: float, size: float, new: float) -> float:
    """A row's first x at the new size: centred when its middle is on the centre line, else
    kept by its end member nearer an edge (issue 85: "a row symmetric about the centre:
    centred"; never by its first member)."""
    n, pitch = ROW
    lo, hi = x, x + (n - 1) * pitch
    if abs((lo + hi) / 2 - size / 2) <= 1e-9:
        return _moved((lo + hi) / 2, size, new) - (hi - lo) / 2
    return lo if lo <= size - hi else new - (size - hi) - (hi - lo)


def draw(path, W: float, H: float, centred: bool, features: list) -> None:
    """A W x H plate (its lower-left corner at the origin, or its centre there) with
    ``features`` ``(kind, x, y)`` placed from its lower-left corner."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    ox, oy = (-W / 2, -H / 2) if centred else (0.0, 0.0)
    m.add_lwpolyline([(ox, oy), (ox + W, oy), (ox + W, oy + H), (ox, oy + H)], close=True)
    for kind, x, y in features:
        cx, cy = ox + x, oy + y
        if kind == "circle":
            m.add_circle((cx, cy), 2.5)
        elif kind == "row":
            for k in range(ROW[0]):
                m.add_circle((cx + k * ROW[1], cy), 1.5)
        elif kind == "dhole":           # a circle of radius 4 with a flat 3 mm right of centre
            a = math.degrees(math.acos(3 / 4))
            s = 4 * math.sin(math.radians(a))
            m.add_arc((cx, cy), 4, a, 360 - a)
            m.add_line((cx + 3, cy - s), (cx + 3, cy + s))
        elif kind == "keyhole":         # a bore of radius 4 with a 3 mm key down to -9 mm
            a = math.asin(1.5 / 4)
            c = 4 * math.cos(a)
            m.add_arc((cx, cy), 4, math.degrees(-math.pi / 2 + a), math.degrees(-math.pi / 2 - a) + 360)
            m.add_lwpolyline([(cx + 1.5, cy - c), (cx + 1.5, cy - 9), (cx - 1.5, cy - 9),
                              (cx - 1.5, cy - c)])
    doc.saveas(path)


FEATURE = st.tuples(st.sampled_from(["circle", "dhole", "keyhole", "row"]),
                    st.floats(0.1, 0.9), st.floats(0.15, 0.85))


def _spread(features: list, W: float, H: float) -> list:
    """Features at those fractions of a third of the plate's width each (the k-th feature
    in the k-th third), kept 12 mm from the edges: none touches another or the edge."""
    third = W / 4
    return [(kind, round(k * third + 12 + fx * (third - 24), 1) if third > 26 else
             round(12 + fx * (W - 24 - (18 if kind == "row" else 0)), 1),
             round(12 + fy * (H - 24), 1))
            for k, (kind, fx, fy) in enumerate(features)]


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(W=st.integers(60, 160), H=st.integers(50, 120), dW=st.integers(-20, 40),
       dH=st.integers(-15, 30), centred=st.booleans(),
       features=st.lists(FEATURE, min_size=1, max_size=3, unique_by=lambda f: f[0]))
def test_law_a_new_plate_size_keeps_every_feature_where_the_drawing_ties_it(
        tmp_path, W, H, dW, dH, centred, features):
    placed = _spread(features, W, H)     # one of each kind (alike ones are a pattern)
    if any(math.hypot(a[1] - b[1], a[2] - b[2]) < 12 + 18 * ("row" in (a[0], b[0]))
           for a in placed for b in placed if a is not b):
        reject()
    src = tmp_path / "p.dxf"
    draw(src, W, H, centred, placed)
    text, _ = import_drawing(src.read_bytes(), "p.dxf", infer=True)
    W2, H2 = W + dW, H + dH
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl",
                            overrides={"width": f"{W2} mm", "height": f"{H2} mm"})
    assert res.ok, (text, [str(d) for d in res.errors])
    got = tmp_path / "got.dxf"
    got.write_text(res.to_dxf())
    want = tmp_path / "want.dxf"
    # the truth: each feature as far from its reference as drawn, the plate grown from its
    # origin (a corner at (0, 0), or its centre)
    draw(want, W2, H2, centred, [(k, (_moved_row if k == "row" else _moved)(x, W, W2),
                                  _moved(y, H, H2)) for k, x, y in placed])
    dxf_compare.TOL = 1e-6
    left, extra = dxf_compare.unmatched(dxf_compare.curves(want), dxf_compare.curves(got))
    assert not left and not extra, (text, left[:3], extra[:3])


def test_a_plate_drawn_from_its_corner_grows_from_it(tmp_path):
    """The body of a plate whose lower-left corner is at the origin is written from it
    (``center=(width / 2, height / 2)``); a keyhole 20 mm from the right edge stays 20 mm
    from it at 150 mm (it stayed at x = 100 before: 50 mm from the edge)."""
    src = tmp_path / "k.dxf"
    draw(src, 120, 60, False, [("keyhole", 100, 40), ("dhole", 15, 15)])
    text, _ = import_drawing(src.read_bytes(), "k.dxf", infer=True)
    assert "body = Rectangle(center=(width / 2, height / 2), width=width, height=height)" \
        in text, text
    assert "h = Circle(center=(width - 20, height / 2 + 10), radius=4)" in text, text
    res = aidl_lang.compile(text, path=tmp_path / "k.aidl", overrides={"width": "150 mm"})
    assert res.ok and res.freedom()["dof"] == 0
    (part,) = res.parts
    assert part.bbox == pytest.approx((0, 0, 150, 60), abs=1e-9)



def test_a_row_by_the_right_edge_keeps_its_right_hole_when_its_pitch_changes(tmp_path):
    """Three holes 9 mm apart, the last 10 mm from the right edge of a 120 mm plate: the row
    is written from that hole (``width - 10 + (i - (holes_n - 1)) * holes_pitch``), so a
    pitch of 12 keeps it 10 mm from the edge and moves the others (before: from the first
    hole, the last one ended 16 mm from the edge)."""
    src = tmp_path / "r.dxf"
    draw(src, 120, 60, False, [("row", 92, 30)])
    text, _ = import_drawing(src.read_bytes(), "r.dxf", infer=True)
    assert "width - 10 + (i - (holes_n - 1)) * holes_pitch" in text, text
    res = aidl_lang.compile(text, path=tmp_path / "r.aidl", overrides={"holes_pitch": "12 mm",
                                                                       "width": "140 mm"})
    assert res.ok
    got = tmp_path / "got.dxf"
    got.write_text(res.to_dxf())
    circles = sorted(c[1][0][0] for c in dxf_compare.curves(got) if c[0] == "C")
    assert circles == pytest.approx([106, 118, 130], abs=1e-9)


def test_labels_on_their_own_layer_move_with_the_hole_they_name(tmp_path):
    """A plate on OUTLINE, a hole 15 mm from its right edge and its label "PWR" 8 mm above it
    on LABELS (a drawing of its own beside the part): at 150 mm wide the label is still
    8 mm above the hole (it stayed at x = 105 before)."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (120, 0), (120, 60), (0, 60)], close=True,
                     dxfattribs={"layer": "OUTLINE"})
    m.add_circle((105, 20), 3, dxfattribs={"layer": "OUTLINE"})
    m.add_text("PWR", height=3, dxfattribs={"layer": "LABELS", "insert": (105, 28)})
    doc.saveas(tmp_path / "l.dxf")
    text, _ = import_drawing((tmp_path / "l.dxf").read_bytes(), "l.dxf", infer=True)
    assert 'Text("PWR", position=(width - 15, height / 2 - 2)' in text, text
    res = aidl_lang.compile(text, path=tmp_path / "l.aidl", overrides={"width": "150 mm"})
    assert res.ok
