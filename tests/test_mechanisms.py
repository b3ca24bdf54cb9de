"""The generators of issue 52: std/enclosures.aidl (board_enclosure) and the mechanisms added
to std/gears.aidl (gear_train, rack_and_pinion, planetary).

Each goes through the real pipeline; its stated dimensions are re-read from the DXF `aidl
render` writes, with ezdxf (an independent reader), to 1e-9 mm; its assembly (`Place`) is
fit-checked at kerf 0 and 0.15 mm (no W0517, no W0518), and material thicker than the
generator's `thickness` collides (W0517).  The demo programs in examples/generators/ compile
without a shape warning.
"""
import io
import math
import subprocess
import sys

import ezdxf
import pytest

from aidl_lang.pipeline import compile_source
from conftest import ROOT

PY = sys.executable
GEN = ROOT / "examples" / "generators"
SHAPE = ("W05",)


def run(tmp_path, src, name="t.aidl", **kw):
    p = tmp_path / name
    p.write_text(src)
    return compile_source(src, str(p), **kw)


def codes(c):
    return [d.code for d in c.sink.items]


def clean(c):
    assert c.ok, [(d.code, d.message) for d in c.sink.items]
    bad = [(d.code, d.message) for d in c.sink.items if d.code.startswith(SHAPE) or d.code == "W0404"]
    assert bad == []


def dxf_render(tmp_path, src, name="t.aidl", extra=()):
    """The DXF `aidl render -o x.dxf` writes, re-read by ezdxf."""
    p = tmp_path / name
    p.write_text(src)
    out = tmp_path / (p.stem + ".dxf")
    subprocess.run([PY, "-m", "aidl_lang.cli", "render", str(p), "-o", str(out), *extra],
                   check=True, cwd=ROOT, capture_output=True)
    return ezdxf.readfile(str(out))


def bbox(entities):
    from ezdxf import bbox as ebbox
    b = ebbox.extents(entities)
    return b.extmin.x, b.extmin.y, b.extmax.x, b.extmax.y


def by_layer(doc):
    out = {}
    for e in doc.modelspace():
        out.setdefault(e.dxf.layer, []).append(e)
    return out


def fit(tmp_path, src):
    """The fit check's warnings with kerf 0 and with kerf 0.15 mm."""
    got = []
    for kerf in ("", "kerf 0.15 mm\n"):
        c = run(tmp_path, kerf + src)
        assert c.ok, [(d.code, d.message) for d in c.sink.items]
        assert c.drawing.placement
        got.append([d.code for d in c.sink.items if d.code in ("W0517", "W0518")])
    return got


def docs_and_prompt(name):
    d = subprocess.run([PY, "-m", "aidl_lang.cli", "docs", name], check=True, cwd=ROOT,
                       capture_output=True, text=True).stdout
    p = subprocess.run([PY, "-m", "aidl_lang.cli", "prompt"], check=True, cwd=ROOT,
                       capture_output=True, text=True).stdout
    assert f"def {name}(" in d or f"{name}(" in d
    assert any(line.lstrip("- `").startswith(name + "(") or f"`{name}(" in line
               for line in p.splitlines())
    return d


# --- board_enclosure -----------------------------------------------------------------------

ENC = """import "std/enclosures.aidl"
thickness {material} mm
assembly case {{
    box = board_enclosure(width={w} mm, height={h} mm, depth=25 mm, thickness=3 mm,
                          clearance={c} mm, {extra})
}}
"""


def enc(material=3, w=85, h=56, c=2, extra="vent=\"slots\""):
    return ENC.format(material=material, w=w, h=h, c=c, extra=extra)


def test_board_enclosure_demo_is_clean():
    src = (GEN / "board_enclosure.aidl").read_text()
    c = compile_source(src, str(GEN / "board_enclosure.aidl"))
    clean(c)
    assert len(c.drawing.placement) == 6


@pytest.mark.parametrize("w,h,c", [(85, 56, 2), (60, 40, 1.5), (100, 70, 0)])
def test_board_enclosure_floor_holes_and_ports_from_the_dxf(tmp_path, w, h, c):
    t = 3
    src = enc(w=w, h=h, c=c, extra='holes=[[4, 5], [30, 5], [4, 30]], hole_d=3.4 mm, standoff=6 mm, '
              'ports=[["front", 20, 10, 4], ["left", 15, 9, 3.5], ["back", 25, 8, 5], ["right", 18, 12, 6]]')
    clean(run(tmp_path, src))
    doc = dxf_render(tmp_path, src)
    layers = by_layer(doc)
    bottom = [e for k, v in layers.items() if k.endswith("bottom") for e in v]
    x0, y0, x1, y1 = bbox(bottom)
    # the floor: the board plus clearance and a wall each side, outside
    L, D = w + 2 * c + 2 * t, h + 2 * c + 2 * t
    assert (x1 - x0, y1 - y0) == pytest.approx((L, D), abs=1e-9)
    holes = sorted((round(e.dxf.center.x - x0 - t - c, 9), round(e.dxf.center.y - y0 - t - c, 9),
                    e.dxf.radius) for e in bottom if e.dxftype() == "CIRCLE")
    assert [v for hx, hy, _ in holes for v in (hx, hy)] == pytest.approx([4, 5, 4, 30, 30, 5], abs=1e-9)
    assert all(abs(r - 1.7) < 1e-9 for *_, r in holes)
    # the ports: each a rectangle (4 lines or a closed polyline) in its wall
    deck = t + 6 + 1.6          # floor, standoff, board: the port's bottom edge above z = 0

    def openings(part):
        ents = [e for k, v in layers.items() if k.endswith(part) for e in v]
        outer = bbox(ents)
        inner = [e for e in ents if e.dxftype() == "LWPOLYLINE" and len(list(e.get_points())) == 4]
        return outer, [bbox([e]) for e in inner]

    (fx0, fy0, fx1, fy1), (port,) = openings("front")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((10, 4), abs=1e-9)
    assert (port[0] + port[2]) / 2 - fx0 - t - c == pytest.approx(20, abs=1e-9)
    assert port[1] - fy0 == pytest.approx(deck, abs=1e-9)
    (bx0, by0, bx1, by1), (port,) = openings("back")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((8, 5), abs=1e-9)
    assert (port[0] + port[2]) / 2 - bx0 - t - c == pytest.approx(25, abs=1e-9)
    # left wall: its right edge (net) is the floor's edge; z runs leftward
    (lx0, ly0, lx1, ly1), (port,) = openings("left")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((3.5, 9), abs=1e-9)
    assert lx1 - port[2] == pytest.approx(deck, abs=1e-9)
    assert (port[1] + port[3]) / 2 - ly0 - t - c == pytest.approx(15, abs=1e-9)
    (rx0, ry0, rx1, ry1), (port,) = openings("right")
    assert (port[2] - port[0], port[3] - port[1]) == pytest.approx((6, 12), abs=1e-9)
    assert port[0] - rx0 == pytest.approx(deck, abs=1e-9)
    assert (port[1] + port[3]) / 2 - ry0 - t - c == pytest.approx(18, abs=1e-9)
    # the walls stand depth + 2 t tall
    assert fy1 - fy0 == pytest.approx(25 + 2 * t, abs=1e-9)


def test_board_enclosure_vents(tmp_path):
    for vent, kind, n in (("slots", "LWPOLYLINE", 12), ("hex", "CIRCLE", None)):
        src = enc(extra=f'vent="{vent}"')
        clean(run(tmp_path, src))
        layers = by_layer(dxf_render(tmp_path, src))
        lid = [e for k, v in layers.items() if k.endswith("lid") for e in v]
        x0, y0, x1, y1 = bbox(lid)
        cuts = [e for e in lid if e.dxftype() == kind and bbox([e])[2] - bbox([e])[0] < 70]
        if vent == "slots":
            # (85 - 10) // 6 = 12 slots, 3 mm wide, 56 - 10 = 46 mm long, 6 mm apart
            assert len(cuts) == n
            for e in cuts:
                a, b, c, d = bbox([e])
                assert (c - a, d - b) == pytest.approx((3, 46), abs=1e-9)
        else:
            assert all(abs(e.dxf.radius - 2) < 1e-9 for e in cuts) and len(cuts) > 50
            xs = sorted({round(e.dxf.center.x, 6) for e in cuts})
            assert xs[1] - xs[0] == pytest.approx(3, abs=1e-6)   # rows shifted half a pitch
        # every vent inside the board's area less 5 mm
        for e in cuts:
            a, b, c, d = bbox([e])
            assert a >= (x0 + x1) / 2 - 85 / 2 + 5 - 1e-9 and c <= (x0 + x1) / 2 + 85 / 2 - 5 + 1e-9


def test_board_enclosure_fits_and_catches_thick_material(tmp_path):
    assert fit(tmp_path, enc()) == [[], []]
    c = run(tmp_path, enc(material=4))
    assert "W0517" in codes(c)


def test_board_enclosure_bad_side_is_named(tmp_path):
    c = run(tmp_path, enc(extra='ports=[["top", 10, 5, 5]]'))
    assert not c.ok and any("side" in d.message for d in c.sink.items if d.code == "E0405")


def test_board_enclosure_docs_and_prompt():
    d = docs_and_prompt("board_enclosure")
    assert "ports" in d and "vent" in d
