"""A perforated panel (an outline and thousands of circles, issue 74) read and ordered into
Drawing2D's loops with the same work per hole at 2,000 and at 19,900 holes: counts, not
wall time.

- the DXF reader takes a plain CIRCLE in one step (``dxf.WORK["plain_circles"]``);
- :func:`~aidl_lang.geometry.shapes.drawing2d.local_parts` tests each hole's probe against the
  polygons whose box holds it, as arrays: one probe test per hole (the outline), no circle's
  polygon sampled (``drawing2d.WORK``).  Before, every loop was masked against the boxes of
  all the others (n^2 comparisons: 2.2 s of the 19,000-hole panel) and every circle sampled;
- the construction Circles of ``d.circles`` are made when the program names them: a panel
  nothing refers to hole by hole has 2 unknowns (its origin), not 2 + 2 per hole.
"""
from __future__ import annotations

from pathlib import Path

import ezdxf
import pytest

import aidl_lang
from aidl_lang.drawing.read import dxf as dxf_reader
from aidl_lang.drawing.read import read_drawing
from aidl_lang.geometry.shapes import drawing2d

PITCH, R = 10.0, 2.0


def panel_dxf(path: Path, nx: int, ny: int) -> None:
    """An R2010 DXF in mm: a closed LWPOLYLINE outline and nx * ny CIRCLEs of radius R."""
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    w, h = nx * PITCH, ny * PITCH
    msp.add_lwpolyline([(0, 0), (w, 0), (w, h), (0, h)], close=True)
    for i in range(nx):
        for j in range(ny):
            msp.add_circle((PITCH / 2 + i * PITCH, PITCH / 2 + j * PITCH), R)
    doc.saveas(path)


def panel_svg(path: Path, nx: int, ny: int) -> None:
    """An SVG in mm: a <rect> outline and nx * ny <circle>s of radius R."""
    w, h = nx * PITCH, ny * PITCH
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:g}mm" height="{h:g}mm" '
           f'viewBox="0 0 {w:g} {h:g}">',
           f'<rect x="0" y="0" width="{w:g}" height="{h:g}" fill="none" stroke="black"/>']
    out += [f'<circle cx="{PITCH / 2 + i * PITCH:g}" cy="{PITCH / 2 + j * PITCH:g}" r="{R:g}" '
            'fill="none" stroke="black"/>' for i in range(nx) for j in range(ny)]
    path.write_text("\n".join(out + ["</svg>"]))


def _work(path: Path):
    """What reading and ordering the panel at ``path`` did: the reader's and local_parts'
    counts, and the loops (holes clockwise)."""
    for w in (dxf_reader.WORK, drawing2d.WORK):
        for k in w:
            w[k] = 0
    d = read_drawing(path.read_bytes(), path.name)
    loops, _paths, circles, outlines = drawing2d.local_parts(d, 0.0)
    return dict(dxf_reader.WORK), dict(drawing2d.WORK), loops, circles, outlines


@pytest.mark.parametrize("ext", ["dxf", "svg"])
def test_reading_and_nesting_a_panel_are_linear_in_its_holes(tmp_path, ext):
    """500 and 5,000 holes (ten times as many): each hole read in one step (DXF) and tested
    once, against the outline; no circle sampled; every hole clockwise inside the
    counter-clockwise outline (the 50,000-hole panel is read in test_import_limits.py)."""
    per_hole = []
    for nx, ny in ((10, 50), (50, 100)):
        n = nx * ny
        p = tmp_path / f"panel{n}.{ext}"
        (panel_dxf if ext == "dxf" else panel_svg)(p, nx, ny)
        read, work, loops, circles, outlines = _work(p)
        assert len(circles) == n and len(outlines) == 1 and len(loops) == n + 1
        assert loops[0].area == pytest.approx(nx * ny * PITCH ** 2)        # outline: ccw
        assert all(len(lp.segments) == 1 and not lp.segments[0].ccw for lp in loops[1:])
        assert work["loops"] == n + 1
        assert work["polygons"] == 1, work        # the outline only: no circle sampled
        per_hole.append((work["pairs"] / n, read["plain_circles"] / n))
    assert per_hole[0] == per_hole[1] == (1.0, 1.0 if ext == "dxf" else 0.0), per_hole


def test_nested_circles_are_ordered_by_their_depth(tmp_path):
    """Circles in circles (a washer in a hole in a washer ...), and two overlapping ones:
    depth by the even-odd rule, as before, through the grid of boxes."""
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    msp.add_lwpolyline([(-50, -50), (50, -50), (50, 50), (-50, 50)], close=True)
    for r in (30, 20, 10, 5):
        msp.add_circle((0, 0), r)
    for i in range(200):                                       # small holes, depth 1
        msp.add_circle((-45 + (i % 20) * 0.5, -45 + (i // 20) * 0.5), 0.2)
    msp.add_circle((40, 40), 3)
    msp.add_circle((41, 40), 3)                                # overlaps: its probe is inside
    doc.saveas(tmp_path / "n.dxf")
    d = read_drawing((tmp_path / "n.dxf").read_bytes(), "n.dxf")
    loops, _p, circles, _o = drawing2d.local_parts(d, 0.0)
    ccw = {(c.center, c.radius): lp.segments[0].ccw for lp in loops[1:]
           for c in lp.segments}
    assert [ccw[((0.0, 0.0), float(r))] for r in (30, 20, 10, 5)] == [False, True, False, True]
    assert ccw[((-45.0, -45.0), 0.2)] is False
    # (43, 40), the probe of the one at (40, 40), is inside the other: depth 2, outer;
    # (44, 40), the other's, is 4 mm from (40, 40): depth 1, a hole
    assert ccw[((40.0, 40.0), 3.0)] is True
    assert ccw[((41.0, 40.0), 3.0)] is False


def _unknowns(res) -> int:
    """The unknowns of the solve (those Newton solved and those settled directly), as `aidl
    check` counts them."""
    s = res.compiled.solve
    return s.n_unknowns + s.n_settled


PROGRAM = 'solid p {{\n    d = Drawing2D("panel.dxf")\n{extra}}}\n'


def test_a_panel_nothing_names_hole_by_hole_has_no_unknown_per_hole(tmp_path):
    """The 200-hole panel as a Drawing2D: 2 unknowns (its origin; before: 402, a point per
    hole), its 200 holes cut; naming `d.circles` makes them, and a constraint on one places
    the drawing to 1e-9 mm."""
    panel_dxf(tmp_path / "panel.dxf", 10, 20)
    src = PROGRAM.format(extra="")
    res = aidl_lang.compile(src, path=tmp_path / "main.aidl")
    assert res.ok, [str(d) for d in res.diagnostics]
    assert _unknowns(res) == 2
    out = tmp_path / "out.dxf"
    out.write_text(res.to_dxf())
    cs = [c for c in ezdxf.readfile(out).modelspace().query("CIRCLE")]
    assert len(cs) == 200 and all(abs(c.dxf.radius - R) < 1e-9 for c in cs)
    src = PROGRAM.format(extra="    q = Point((100 mm, 50 mm))\n"
                               "    Fixed(q)\n"
                               "    Coincident(d.circles[0].center, q.p)\n")
    res = aidl_lang.compile(src, path=tmp_path / "main.aidl")
    assert res.ok, [str(d) for d in res.diagnostics]
    assert _unknowns(res) == 2 + 2 + 2 * 200       # + the point, + a centre per hole
    out.write_text(res.to_dxf())
    cs = sorted((c.dxf.center.x, c.dxf.center.y) for c in
                ezdxf.readfile(out).modelspace().query("CIRCLE"))
    # circles[0] is the file's first by (-r, x, y): (5, 5), now at (100, 50)
    assert abs(cs[0][0] - 100) < 1e-9 and abs(cs[0][1] - 50) < 1e-9, cs[:2]
