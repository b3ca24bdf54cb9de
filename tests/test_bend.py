"""`Bend` (issue 72, living hinges bent in 3D): a part cut flat is shown bent in the assembled
product. The flex box (examples/generators/flex_box.aidl, std/boxes.aidl) bends its wall 90 deg
over each of its four living hinges: its assembled 3MF, re-read by trimesh, has the wall wrapped
round the base's rounded corners (watertight, on the base's outline, no volume shared with the
base, the lid or the lips: Manifold's booleans), as has the studio's view GLB; the fit check
warns of nothing. Before, the wall stood flat along the back and ran 118 mm past each side.
A small part bent once lands on the numbers of the bend's arithmetic; misuses are located."""
import io
import math
from pathlib import Path

import manifold3d as mf
import numpy as np
import pytest
import trimesh

import aidl_lang

ROOT = Path(__file__).resolve().parent.parent
# examples/generators/flex_box.aidl: 120 x 80 x 50 mm outside, corner radius 20, 3 mm sheet
L, W, H, R, T = 120.0, 80.0, 50.0, 20.0, 3.0
RUN = 2 * (L - 2 * R) + 2 * (W - 2 * R) + 2 * math.pi * (R - T / 2)   # the wall's flat length


def _bodies(scene) -> dict:
    """Node name -> its mesh moved into place (as a 3MF or GLB reader shows it)."""
    out = {}
    for node in scene.graph.nodes_geometry:
        M, geom = scene.graph[node]
        m = scene.geometry[geom].copy()
        m.apply_transform(M)
        out[node] = m
    return out


def _manifold(m):
    return mf.Manifold(mf.Mesh(vert_properties=np.asarray(m.vertices, dtype=np.float32),
                               tri_verts=np.asarray(m.faces, dtype=np.uint32)))


@pytest.fixture(scope="module")
def flex():
    r = aidl_lang.compile(path=str(ROOT / "examples" / "generators" / "flex_box.aidl"))
    assert r.ok, [d.message for d in r.errors]
    return r


@pytest.fixture(scope="module")
def flex_3mf(flex):
    data = flex.encode("3mf", assembled=True)
    return _bodies(trimesh.load(io.BytesIO(data), file_type="3mf"))      # trimesh merges vertices


def test_the_flex_box_3mf_has_its_wall_bent_round_the_corners(flex_3mf):
    panel = flex_3mf["round_box.box.wall"]       # the hinge panel's mesh (mm)
    others = {n: m for n, m in flex_3mf.items() if n != "round_box.box.wall"}
    assert set(others) == {f"round_box.box.{n}" for n in ("base", "lid", "lip[0]", "lip[1]")}
    for name, m in flex_3mf.items():
        assert m.is_watertight and m.is_volume, name
    # a ring (its two ends meet mid-front and are welded): a closed surface of genus 1
    assert panel.euler_number == 0
    # on the base's outline, between the base and the lid (before: x -178.1 .. 178.1, y 37 .. 40)
    assert panel.bounds.ravel() == pytest.approx([-L / 2, -W / 2, T, L / 2, W / 2, H - T], abs=1e-6)
    # at the corners every vertex lies between the inside radius and the outside one
    v = panel.vertices
    for sx in (-1, 1):
        for sy in (-1, 1):
            cx, cy = sx * (L / 2 - R), sy * (W / 2 - R)
            at = (sx * v[:, 0] > L / 2 - R + 1e-9) & (sy * v[:, 1] > W / 2 - R + 1e-9)
            d = np.hypot(v[at, 0] - cx, v[at, 1] - cy)
            assert at.sum() > 500
            assert d.min() == pytest.approx(R - T, abs=1e-6) and d.max() == pytest.approx(R, abs=1e-6)
    # the strip's volume (mm^3) kept: a chord leaves its arc by at most 0.005 mm, a segment of
    # at most 2/3 of that times its length, over both faces' arcs (radii 20 and 17), 44 mm high
    chord_loss_mm3 = 2 / 3 * 0.005 * (H - 2 * T) * 2 * math.pi * (R + R - T)
    assert abs(panel.volume - RUN * (H - 2 * T) * T) < chord_loss_mm3
    # no volume shared with any other panel (Manifold's 3D booleans on the meshes re-read)
    shell = _manifold(panel)
    for name, m in others.items():
        assert (shell ^ _manifold(m)).volume() < 1e-3, name


def test_the_fit_check_uses_the_bent_wall(flex):
    # bent, the wall touches the base, the lid and nothing else: no W0517, no W0518
    assert [d.code for d in flex.sink.items] == []
    assert flex.fit["checked"] and flex.fit["collisions"] == [] and flex.fit["floating"] == []


def test_the_studio_view_shows_the_wall_bent(flex):
    from aidl_lang.output.writers.glb import to_view_glb
    got = _bodies(trimesh.load(io.BytesIO(to_view_glb(flex.output)), file_type="glb"))
    assert got["round_box.box.wall"].bounds.ravel() == pytest.approx(
        [-L / 2, -W / 2, T, L / 2, W / 2, H - T], abs=1e-6)


def test_a_lip_at_zero_clearance_touches_the_bent_wall_without_a_collision():
    """The inside face's chords fall on those of the lip's concentric corner arcs (the same
    count of chords over the quarter): touching, no W0517 (0.171 mm^3 each lip with the
    planes spaced by the sagitta bound alone)."""
    r = aidl_lang.compile(source='import "std/boxes.aidl"\nthickness 3 mm\n'
                                 'assembly kit { b = flex_box(clearance=0 mm) }\n')
    assert r.ok and [d.code for d in r.sink.items] == []
    assert r.fit["checked"] and r.fit["collisions"] == []


BENT = """thickness 3 mm
assembly kit {
    solid base { r = Rectangle(center=(0, 0), width=60, height=40) }
    solid wall { r = Rectangle(center=(10, 60), width=80, height=30) }
    Place(wall, rotation=(90 deg, 0, 180 deg), position=(0, -20, -42))
    BEND
}
"""


def test_one_bend_lands_on_its_arithmetic(tmp_path):
    """The docs' example (docs/language.md, "Bending a part"): the wall stands on the base's
    front edge and turns inward 90 deg at x = 20 round an inside radius of 2 mm: its zone is
    pi / 2 * (2 + 1.5) wide; after it the wall runs on along +y with its outside face at the
    axis less 5 mm."""
    r = aidl_lang.compile(source=BENT.replace("BEND", "Bend(wall, at=20, angle=90 deg, radius=2)"))
    assert r.ok and [d.code for d in r.sink.items] == []
    v = _bodies(trimesh.load(io.BytesIO(r.encode("3mf", assembled=True)),
                             file_type="3mf"))["kit.wall"].vertices
    w = math.pi / 2 * 3.5
    xs = 20 - w / 2                          # the zone's start on the sheet: world x = -xs
    assert v[:, 0].min() == pytest.approx(-xs - 5, abs=1e-9)
    assert v[:, 1].max() == pytest.approx(-20 + 5 + (50 - (20 + w / 2)), abs=1e-9)
    assert v[:, 0].max() == pytest.approx(30, abs=1e-9)
    assert v[:, 2].max() == pytest.approx(33, abs=1e-9)


@pytest.mark.parametrize("other, place, volume", [
    # a 4 x 4 mm block 10 mm up where the wall turns inward: the leg (x -22.25..-19.25, 3 mm
    # thick) runs through it, 3 x 4 x 3 = 36 mm^3 (unbent, the wall touched nothing there)
    ("post { r = Rectangle(center=(-20.75, 0), width=4, height=4) }",
     "Place(post, position=(0, 0, 10))", 36.0),
    # a panel standing parallel 10 mm behind the wall's unbent start, where the leg turns in:
    # 3 x 3 x 10 = 90 mm^3 (the fit check's 2D shortcut for parallel plates took the bent wall
    # for its flat sheet: "touches no other part", W0518)
    ("panel { r = Rectangle(center=(20.75, 60), width=6, height=10) }",
     "Place(panel, rotation=(90 deg, 0, 180 deg), position=(0, -10, -42))", 90.0),
], ids=["block", "parallel-panel"])
def test_the_fit_check_meets_a_part_where_the_bent_leg_goes(other, place, volume):
    src = BENT.replace("BEND", f"Bend(wall, at=20, angle=90 deg, radius=2)\n"
                               f"    solid {other}\n    {place}")
    r = aidl_lang.compile(source=src)
    # the panel is drawn on the wall on the flat sheet, and both are placed: cut through each
    # other there (W0511, issue 111's round thirteen)
    assert [d.code for d in r.sink.items] == (["W0511", "W0517"] if "panel" in other
                                              else ["W0517"])
    (hit,) = r.fit["collisions"]
    assert {hit["a"], hit["b"]} == {"kit.wall", "kit." + other.split()[0]}
    assert hit["volume"] == pytest.approx(volume, abs=1e-6)


def test_bends_whose_zones_overlap_are_refused_at_the_second():
    """Each bend takes pi / 2 * (2 + 1.5) = 5.498 mm of the sheet: two 4 mm apart overlap."""
    src = BENT.replace("BEND", "Bend(wall, at=20, angle=90 deg, radius=2)\n"
                               "    Bend(wall, at=24, angle=90 deg, radius=2)")
    r = aidl_lang.compile(source=src)
    (e,) = r.errors
    assert e.code == "E0108" and "5.498 and 5.498 mm" in e.message and "4 mm apart" in e.message
    assert (e.span.line, e.span.col) == (7, 5) and "at least 5.498 mm apart" in e.hint


@pytest.mark.parametrize("bend, code, at, says", [
    ("Bend(base.r, at=20, angle=90 deg)", "E0108", "base.r", "bends a structure"),
    ("Bend(wall, at=20, angle=0 deg, radius=2)", "E0108", "0 deg", "at most 360 deg"),
    ("Bend(wall, at=20, angle=90 deg, radius=-1)", "E0108", "-1", "inside radius is 0 or more"),
    ("Bend(wall, at=wall.r.center.x, angle=90 deg)", "E0109", "wall.r.center.x",
     "known before solving"),
])
def test_a_misused_bend_is_located(bend, code, at, says):
    r = aidl_lang.compile(source=BENT.replace("BEND", bend))
    (e,) = [d for d in r.errors]
    assert e.code == code and says in e.message
    # at the argument at fault: line 6, its column (1-based, after 4 spaces of indent)
    assert (e.span.line, e.span.col) == (6, 4 + bend.index(at) + 1)
