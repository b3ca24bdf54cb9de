"""The standard library's generators as a maker uses them (issue 52): every demo program in
examples/generators/ compiles clean, its parts nest on a cutting sheet (`--layout sheet`),
each once, inside the sheet, none on another (the sheet's DXF re-read with ezdxf), and the
gallery shows it flat and assembled.  Each generator's own dimensions and fit are tested in
tests/test_boxes.py, tests/test_stands.py and tests/test_mechanisms.py."""
import io
import math

import pytest

import aidl_lang

from conftest import ROOT

DEMOS = sorted((ROOT / "examples" / "generators").glob("*.aidl"))


def test_there_are_the_generators_of_issue_52():
    names = {p.stem for p in DEMOS}
    assert len(names) >= 15
    assert {"lid_box", "sliding_lid_box", "divider_tray", "board_enclosure", "gear_train",
            "planetary", "tablet_stand", "wall_shelf", "dovetail"} <= names


@pytest.mark.parametrize("path", DEMOS, ids=lambda p: p.stem)
def test_a_demo_compiles_clean_and_its_generator_is_in_the_docs_and_the_prompt(path):
    """The demo says what it is and compiles with no message at all; `aidl docs NAME` finds
    the generator in its stdlib module and `aidl prompt` has its line (the model is a user)."""
    from aidl_lang.llm.prompt import system_prompt
    from aidl_lang.library.reference import lookup_text
    name, src = path.stem, path.read_text()
    assert src.startswith("# ") and f"{name}(" in src
    r = aidl_lang.compile(source=src, path=path)
    assert r.ok and [d.code for d in r.sink.items] == [], [d.message for d in r.sink.items]
    text, found = lookup_text(name)
    assert found and text.startswith(f"{name} (") and "template, std/" in text.splitlines()[0]
    assert any(ln.startswith(f"- {name}(") for ln in system_prompt().splitlines())


@pytest.mark.parametrize("path", DEMOS, ids=lambda p: p.stem)
def test_a_demo_nests_on_a_cutting_sheet(path):
    import ezdxf
    import manifold3d as mf
    r = aidl_lang.compile(path=str(path))
    assert r.ok and not [d for d in r.diagnostics if d.code.startswith("W05")], \
        [(d.code, d.message) for d in r.diagnostics]
    solids = [p for p in r.parts if p.kind == "solid"]
    lay = r.layout(sheet=(600.0, 400.0), gap=3.0)
    assert lay.parts == len(solids) and lay.sheets >= 1
    for data in lay.encode("dxf"):
        doc = ezdxf.read(io.StringIO(data.decode()))
        # each part's outer loops on its own layer: the sheet's pieces, re-read
        pieces = {}
        for e in doc.modelspace():
            if not e.dxf.layer.startswith("CUT"):
                continue
            pts = _points(e)
            if pts:
                pieces.setdefault(e.dxf.layer, []).append(pts)
        assert len(pieces) == len(solids) if lay.sheets == 1 else pieces
        shapes = {}
        for layer, loops in pieces.items():
            xs = [x for lp in loops for x, _ in lp]
            ys = [y for lp in loops for _, y in lp]
            assert min(xs) >= -1e-6 and min(ys) >= -1e-6, layer
            assert max(xs) <= 600 + 1e-6 and max(ys) <= 400 + 1e-6, layer
            shapes[layer] = mf.CrossSection(loops, mf.FillRule.EvenOdd)
        names = sorted(shapes)
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                # the parts keep the gap: their intersection is empty (a chord's sliver at most)
                assert (shapes[a] ^ shapes[b]).area() < 1e-6, (path.stem, a, b)


def _points(e) -> list:
    """A closed DXF entity (CIRCLE, closed LWPOLYLINE with bulges) as a polygon within
    0.01 mm; [] for anything else."""
    if e.dxftype() == "CIRCLE":
        (cx, cy, _), r = e.dxf.center, e.dxf.radius
        n = max(16, int(math.pi / math.acos(max(-1.0, 1 - 0.01 / r))) + 1)
        return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n))
                for k in range(n)]
    if e.dxftype() == "LWPOLYLINE" and e.closed:
        from ezdxf.path import make_path
        return [(v.x, v.y) for v in make_path(e).flattening(0.01)]
    return []


def test_the_gallery_shows_every_generator_flat_and_assembled():
    text = (ROOT / "docs" / "gallery.md").read_text()
    for p in DEMOS:
        assert f"(images/gen-{p.stem}.png)" in text and f"(images/gen-{p.stem}-3d.png)" in text
        assert (ROOT / "docs" / "images" / f"gen-{p.stem}-3d.png").exists()
    rows = (ROOT / "docs" / "generators.md").read_text()
    for p in DEMOS:
        assert f"`{p.stem}`" in rows, p.stem
