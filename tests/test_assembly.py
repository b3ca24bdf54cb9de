"""The assembled product (docs/language.md "Placing parts in 3D", docs/outputs.md "The assembled
product"): `Place` and its located errors, the placed solids re-read from 3MF, GLB and STEP by
trimesh and OCP (one named solid per part, vertices on the design's numbers), `aidl render
--assembled` and its picture.  The fit check's warnings (W0517, W0518) are in test_checks.py."""
import io
import math
import subprocess
import sys

import numpy as np
import pytest

from conftest import ROOT

BOX = """import "std/joints.aidl"
thickness 3 mm
assembly kit { box = finger_box(length=120 mm, depth=80 mm, height=50 mm, thickness=3 mm) }
"""
PANELS = ("kit.box.bottom", "kit.box.front", "kit.box.back", "kit.box.left", "kit.box.right",
          "kit.box.lid")
# each panel's box in the assembled product: the box stands on z = 0, centred on x = y = 0
BOXES = {"kit.box.bottom": (-60, -40, 0, 60, 40, 3), "kit.box.front": (-60, -40, 0, 60, -37, 50),
         "kit.box.back": (-60, 37, 0, 60, 40, 50), "kit.box.left": (-60, -40, 0, -57, 40, 50),
         "kit.box.right": (57, -40, 0, 60, 40, 50), "kit.box.lid": (-60, -40, 47, 60, 40, 50)}


def _fingers(length: float) -> list[float]:
    """The finger breakpoints along an edge of outer ``length`` centred on 0 (std/joints.aidl:
    the largest odd count of segments at least 10 mm wide between the 3 mm corners)."""
    run = length - 6
    q = math.floor(run / 10)
    n = q if q % 2 else q - 1
    return [-length / 2, length / 2] + [-run / 2 + k * run / n for k in range(n + 1)]


@pytest.fixture(scope="module")
def box():
    import aidl_lang
    r = aidl_lang.compile(BOX, str(ROOT / "box.aidl"))
    assert r.ok
    return r


def _on(values, allowed, tol=1e-9):
    allowed = np.asarray(sorted(allowed), dtype=float)
    d = np.abs(np.asarray(values)[:, None] - allowed[None, :]).min(axis=1)
    return float(d.max())


def _check_box(named: dict, tol: float):
    """named: part -> (n, 3) placed vertices; each on its panel's planes and fingers."""
    assert sorted(named) == sorted(PANELS)
    for name, v in named.items():
        x0, y0, z0, x1, y1, z1 = BOXES[name]
        assert np.allclose(v.min(axis=0), (x0, y0, z0), atol=tol, rtol=0), name
        assert np.allclose(v.max(axis=0), (x1, y1, z1), atol=tol, rtol=0), name
    # the design's numbers: the front's faces at y = -40 and -37, its fingers along x at the
    # breakpoints of a 120 mm edge, along z at those of a 50 mm edge (0..50)
    front = named["kit.box.front"]
    assert _on(front[:, 1], (-40, -37)) <= tol
    assert _on(front[:, 0], _fingers(120)) <= tol
    assert _on(front[:, 2], [z + 25 for z in _fingers(50)]) <= tol
    left = named["kit.box.left"]
    assert _on(left[:, 0], (-60, -57)) <= tol
    assert _on(left[:, 1], _fingers(80)) <= tol


def test_place_errors_are_located(compile_text):
    cases = [
        ("Place(a.r, position=(0, 0, 1))", "E0108", "places a structure", "a.r,"),
        ("Place(a, position=(0, 1))", "E0108", "three lengths", "(0, 1)"),
        ("Place(a, rotation=(1 mm, 0, 0))", "E0109", "three angles", "(1 mm, 0, 0)"),
        ("Place(a, position=(a.r.width, 0, 0))", "E0109", "known before solving", "(a.r.width"),
        ("Place(a)\n    Place(a, position=(0, 0, 3))", "E0108", "already placed, on line 4",
         "Place(a, position"),
        ("Place(a, position=(2e9, 0, 0))", "E0305", "beyond the model extent", "(2e9"),
    ]
    for stmt, code, words, at in cases:
        src = ("assembly kit {\n    solid a { r = Rectangle(center=(0, 0), width=20, height=10) }\n"
               "    solid b { c = Circle(center=(40, 0), radius=5) }\n    " + stmt + "\n}\n")
        c = compile_text(src)
        (d,) = [d for d in c.sink.items if d.severity == "error"]
        assert d.code == code and words in d.message, (stmt, d.message)
        line = src.splitlines()[d.span.line - 1]
        assert line[d.span.col - 1:].startswith(at), (stmt, line, d.span)
    c = compile_text("""assembly kit {
    solid a { r = Rectangle(center=(0, 0), width=20, height=10)
        solid inner { c = Circle(center=(0, 0), radius=2) } }
    Place(a.inner, position=(0, 0, 1))
}""")
    (d,) = [d for d in c.sink.items if d.severity == "error"]
    assert d.code == "E0108" and "`kit.a.inner` is not a part: it is merged into solid `kit.a`" \
        in d.message and d.span.line == 4
    c = compile_text("""assembly kit {
    assembly a { solid p { r = Rectangle(center=(0, 0), width=20, height=10) } }
    assembly b { solid q { c = Circle(center=(40, 0), radius=5) } }
    Place(b.q, position=(0, 0, 1))
}""")
    assert c.ok and c.drawing.placement["kit.b.q"][2, 3] == 1


def test_placement_in_the_file_unit_and_nested_assemblies_compose(compile_text):
    """A bare number is in the file's unit; an assembly's placement carries its parts."""
    from aidl_lang.output import build
    c = compile_text("""units cm
thickness 2 mm
assembly kit {
    assembly pair {
        solid a { r = Rectangle(center=(1, 1), width=2, height=2) }
        Place(a, rotation=(0, 0, 90 deg), position=(0, 0, 1))
    }
    Place(pair, position=(10, 0, 0))
}""")
    assert c.ok
    M = c.drawing.placement["kit.pair.a"]
    # a's corner (20, 20) mm on the sheet: turned about z to (-20, 20), up 10 mm, over 100 mm
    assert np.allclose(M @ [20, 20, 0, 1], [80, 20, 10, 1], atol=1e-12, rtol=0)
    assert np.allclose(M @ [0, 0, 2, 1], [100, 0, 12, 1], atol=1e-12, rtol=0)
    out = build(c.drawing)
    from aidl_lang.output.fabrication.assembly import solids
    ((name, m),) = solids(out)
    assert name == "kit.pair.a" and np.allclose(m.bounding_box(), (80, 0, 10, 100, 20, 12),
                                                atol=1e-9, rtol=0)


def test_3mf_one_named_object_per_panel_on_the_design_numbers(box):
    import trimesh
    data = box.encode("3mf", assembled=True)
    sc = trimesh.load(io.BytesIO(data), file_type="3mf")
    named = {}
    for node in sc.graph.nodes_geometry:
        T, g = sc.graph[node]
        named[node] = trimesh.transform_points(sc.geometry[g].vertices, T)
    _check_box(named, 1e-9)
    # without --assembled: the net as on the sheet, every panel from z 0 to 3
    flat = trimesh.load(io.BytesIO(box.encode("3mf")), file_type="3mf")
    assert all(np.isclose(g.bounds[1][2], 3.0) for g in flat.geometry.values())


def test_glb_named_nodes_in_the_flat_views_colours(box):
    import trimesh
    from aidl_lang.output.part.part import PALETTE
    sc = trimesh.load(io.BytesIO(box.encode("glb", assembled=True)), file_type="glb")
    named = {}
    for node in sc.graph.nodes_geometry:
        T, g = sc.graph[node]
        named[node] = trimesh.transform_points(sc.geometry[g].vertices, T)
        colour = sc.geometry[g].visual.vertex_colors[0][:3]
        k = PANELS.index(node)
        assert "#%02x%02x%02x" % tuple(int(c) for c in colour) == PALETTE[k]
    _check_box(named, 2e-5)            # glTF stores float32


@pytest.mark.step
def test_step_one_named_solid_per_panel_on_the_design_numbers(box):
    pytest.importorskip("OCP")
    import tempfile
    from OCP.OCP.collections import Sequence_TDF_Label
    from OCP.STEPCAFControl import STEPCAFControl_Reader
    from OCP.TCollection import TCollection_ExtendedString
    from OCP.TDataStd import TDataStd_Name
    from OCP.TDocStd import TDocStd_Document
    from OCP.TopAbs import TopAbs_SOLID, TopAbs_VERTEX
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    from OCP.BRep import BRep_Tool
    from OCP.XCAFDoc import XCAFDoc_DocumentTool
    with tempfile.NamedTemporaryFile(suffix=".step") as f:
        f.write(box.encode("step", assembled=True))
        f.flush()
        rd = STEPCAFControl_Reader()
        rd.SetNameMode(True)
        rd.ReadFile(f.name)
        doc = TDocStd_Document(TCollection_ExtendedString("XmlOcaf"))
        rd.Transfer(doc)
    st = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    seq = Sequence_TDF_Label()
    st.GetFreeShapes(seq)
    named = {}
    for i in range(1, seq.Length() + 1):
        lab = seq.Value(i)
        nm = TDataStd_Name()
        assert lab.FindAttribute(TDataStd_Name.GetID_s(), nm)
        shape = st.GetShape_s(lab)
        n_solids, ex = 0, TopExp_Explorer(shape, TopAbs_SOLID)
        while ex.More():
            n_solids += 1
            ex.Next()
        assert n_solids == 1
        pts, ex = [], TopExp_Explorer(shape, TopAbs_VERTEX)
        while ex.More():
            p = BRep_Tool.Pnt_s(TopoDS.Vertex(ex.Current()))
            pts.append((p.X(), p.Y(), p.Z()))
            ex.Next()
        named[nm.Get().ToExtString()] = np.array(pts)
    _check_box(named, 1e-9)


def test_phone_stand_foot_is_the_sheet_turned_a_quarter(compile_text):
    """Every vertex of the placed foot is its sheet vertex (x, y, z) at (z - 1.5, x - 100, y)."""
    import trimesh
    from aidl_lang.output import Options, build, encode
    src = (ROOT / "examples" / "phone_stand.aidl").read_text()
    c = compile_text(src)
    out = build(c.drawing)
    flat = trimesh.load(io.BytesIO(encode(out, ".3mf")), file_type="3mf")
    placed = trimesh.load(io.BytesIO(encode(out, ".3mf", Options(assembled=True))),
                          file_type="3mf")

    def verts(sc, name):
        T, g = sc.graph[name]
        return trimesh.transform_points(sc.geometry[g].vertices, T)
    v = verts(flat, "stand.foot")
    want = np.column_stack([v[:, 2] - 1.5, v[:, 0] - 100, v[:, 1]])
    assert np.abs(verts(placed, "stand.foot") - want).max() <= 1e-9
    assert verts(placed, "stand.foot")[:, 0].min() == -1.5


def test_render_assembled_cli(tmp_path):
    prog = tmp_path / "box.aidl"
    prog.write_text(BOX)
    aidl = [sys.executable, "-m", "aidl_lang.cli"]
    r = subprocess.run(aidl + ["render", str(prog), "--assembled", "-o", str(tmp_path / "b.svg")],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and "--assembled writes STL, 3MF, STEP, GLB or PNG" in r.stderr
    r = subprocess.run(aidl + ["render", str(prog), "--assembled", "--layout", "sheet", "-o",
                               str(tmp_path / "b.stl")], capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and "do not go together" in r.stderr
    r = subprocess.run(aidl + ["render", str(prog), "--assembled", "-o", str(tmp_path / "b.stl"),
                               "-o", str(tmp_path / "b.png"), "--png-width", "300"],
                       capture_output=True, text=True, timeout=180)
    assert r.returncode == 0, r.stderr
    import trimesh
    m = trimesh.load(tmp_path / "b.stl")
    assert np.allclose(m.bounds, [(-60, -40, 0), (60, 40, 50)], atol=1e-5)
    from PIL import Image
    im = np.asarray(Image.open(tmp_path / "b.png").convert("RGB")).astype(int)
    assert im.shape[1] == 300
    red = (im[:, :, 0] > 200) & (im[:, :, 1] < 60) & (im[:, :, 2] < 60)
    assert red.sum() == 0              # no collision drawn


def test_assembled_png_draws_a_collision_in_red(compile_text):
    from PIL import Image
    from aidl_lang.output import Options, build, encode
    # the example's range stops at the sheet (3 mm): opened to 1 mm to show the collision
    src = (ROOT / "examples" / "phone_stand.aidl").read_text().replace("min = 3 mm, max = 6 mm", "min = 1 mm, max = 6 mm")
    for slot, reds in (("3mm", False), ("2.5mm", True)):
        c = compile_text(src, overrides={"slot": slot})
        png = encode(build(c.drawing), ".png", Options(assembled=True, width=240))
        im = np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)
        red = (im[:, :, 0] > 200) & (im[:, :, 1] < 60) & (im[:, :, 2] < 60)
        assert (red.sum() > 20) == reds, slot
        # the support in the first colour of the flat view's palette, shaded
        blue = (im[:, :, 2] > im[:, :, 0] + 40)
        assert blue.sum() > 1000
