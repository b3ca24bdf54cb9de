"""`aidl import --snap TOL` (issue 71): Bézier circles and arcs, as Boxes.py writes them
(cubic Béziers with 3-decimal numbers), taken as true circles and arcs within TOL, near-equal
radii made one, and the header saying what was snapped and the largest deviation.  A drawing
made here, through the CLI's entry (in process), the program compiled and its DXF re-read with ezdxf; the
deviation measured against the file's own Béziers."""
from __future__ import annotations

import argparse
import math
import re

import ezdxf
import pytest

import aidl_lang

K = 0.5522847498          # the quarter circle's Bézier handle


def _r3(v: float) -> str:
    return f"{round(v, 3):g}"


def _quarter(cx, cy, r, a0):
    a1 = a0 + math.pi / 2
    p0 = (cx + r * math.cos(a0), cy + r * math.sin(a0))
    p3 = (cx + r * math.cos(a1), cy + r * math.sin(a1))
    c1 = (p0[0] - K * r * math.sin(a0), p0[1] + K * r * math.cos(a0))
    c2 = (p3[0] + K * r * math.sin(a1), p3[1] - K * r * math.cos(a1))
    return [tuple(float(_r3(v)) for v in p) for p in (p0, c1, c2, p3)]


def _d(beziers, start=None, lines=()) -> str:
    return " ".join(f"C {_r3(b[1][0])} {_r3(b[1][1])} {_r3(b[2][0])} {_r3(b[2][1])} "
                    f"{_r3(b[3][0])} {_r3(b[3][1])}" for b in beziers)


HOLES = [(8.1234 + 83.7 * i, 7.77 + 44.5 * j) for i in (0, 1) for j in (0, 1)]
BEZ: list = []            # every Bézier of the file (SVG units = mm, y down)


def _svg() -> str:
    BEZ.clear()
    paths = []
    # the plate: 100 x 60, corners r 2.5 as quarter Béziers
    r, segs = 2.5, []
    d = f"M {_r3(r)} 0 H {_r3(100 - r)} "
    for (cx, cy), a0, after in (((100 - r, r), -math.pi / 2, f"V {_r3(60 - r)}"),
                                ((100 - r, 60 - r), 0, f"H {_r3(r)}"),
                                ((r, 60 - r), math.pi / 2, f"V {_r3(r)}"),
                                ((r, r), math.pi, "Z")):
        q = _quarter(cx, cy, r, a0)
        BEZ.append(q)
        d += _d([q]) + " " + after + " "
    paths.append(d)
    for cx, cy, rr in [(x, y, 1.6) for x, y in HOLES] + [(50, 30, 11)]:
        qs = [_quarter(cx, cy, rr, k * math.pi / 2) for k in range(4)]
        BEZ.extend(qs)
        paths.append(f"M {_r3(qs[0][0][0])} {_r3(qs[0][0][1])} " + _d(qs) + " Z")
    # an ellipse 3 x 2.6 of Béziers: no circle within 0.01 mm, stays Béziers
    e = [[(x * 1.5 / 1.3 + 50 - 1.5 * 50 / 1.3, y) for x, y in q]
         for q in (_quarter(50, 50, 1.3, k * math.pi / 2) for k in range(4))]
    paths.append(f"M {_r3(e[0][0][0])} {_r3(e[0][0][1])} " + _d(e) + " Z")
    body = "".join(f'  <path d="{p}" fill="none" stroke="black"/>\n' for p in paths)
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="60mm" '
            'viewBox="0 0 100 60">\n' + body + "</svg>\n")


@pytest.fixture(scope="module")
def snapped(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("snap")
    (tmp / "plate.svg").write_text(_svg())
    from aidl_lang.cli.main import main       # the CLI's own entry, in process
    assert main(["import", "--infer", "--snap", "0.01mm", str(tmp / "plate.svg"), "-o",
                 str(tmp / "plate.aidl")]) == 0
    text = (tmp / "plate.aidl").read_text()
    res = aidl_lang.compile(text, path=tmp / "plate.aidl")
    assert res.ok, [str(d) for d in res.errors] + [text]
    (tmp / "plate.dxf").write_text(res.to_dxf())
    return text, ezdxf.readfile(str(tmp / "plate.dxf"))


def test_bezier_circles_and_corners_come_back_as_true_ones(snapped):
    """The four 3-decimal Bézier holes of r 1.6 are one hole size (`holes_d = 3.2`), the
    bore 22 across, the plate a RoundedRectangle of corner radius 2.5; the header says what
    was snapped and the largest deviation; the ellipse (0.2 mm off round) stays Béziers."""
    text, _ = snapped
    assert re.search(r"# snapped \(--snap 0\.01 mm\): 5 Bézier circles and 4 Bézier arcs "
                     r"taken as true ones, 2 groups of near-equal radii made one; largest "
                     r"deviation 0\.00\d+ mm", text), text
    assert "param holes_d = 3.2 mm" in text and "param bore_d = 22 mm" in text, text
    assert "param corner_radius = 2.5 mm" in text and "RoundedRectangle(" in text, text
    assert text.count("Bezier(") + text.count("Spline(") >= 1        # the ellipse


def test_snapped_curves_lie_within_the_tolerance_of_the_files_beziers(snapped):
    """Read back with ezdxf: four circles of r 1.6 and one of r 11 (exact numbers), the
    corner arcs r 2.5; every point of every snapped Bézier of the file (64 a span) within
    0.01 mm of the curve that replaced it (y flipped: SVG y down)."""
    _, doc = snapped
    circles = [(tuple(e.dxf.center)[:2], e.dxf.radius) for e in doc.modelspace()
               if e.dxftype() == "CIRCLE"]
    assert sorted(round(r, 12) for _, r in circles) == [1.6] * 4 + [11.0]
    arcs = [e for e in doc.modelspace().query("ARC")] + \
        [v for e in doc.modelspace().query("LWPOLYLINE") for v in e.virtual_entities()
         if v.dxftype() == "ARC"]
    assert sorted(round(a.dxf.radius, 12) for a in arcs) == [2.5] * 4
    curves = [(c, r) for c, r in circles] + [(tuple(a.dxf.center)[:2], a.dxf.radius)
                                             for a in arcs]
    worst = 0.0
    for b in BEZ:
        pts = []
        for i in range(65):
            t = i / 64
            s = 1 - t
            x = s ** 3 * b[0][0] + 3 * s * s * t * b[1][0] + 3 * s * t * t * b[2][0] + t ** 3 * b[3][0]
            y = s ** 3 * b[0][1] + 3 * s * s * t * b[1][1] + 3 * s * t * t * b[2][1] + t ** 3 * b[3][1]
            pts.append((x, -y))
        worst = max(worst, min(max(abs(math.dist(p, c) - r) for p in pts) for c, r in curves))
    assert 1e-4 < worst <= 0.01, worst


def test_without_snap_the_beziers_stay_exact_and_a_bad_tolerance_is_refused(tmp_path, capsys):
    """No `--snap`: no Bézier is a circle (exact curves only, as before); `--snap 0` and
    `--snap 1ft` are refused with what to write (the CLI's own parser, in process)."""
    from aidl_lang.cli.main import main
    from aidl_lang.drawing.infer import import_drawing
    text, _ = import_drawing(_svg().encode(), "plate.svg", infer=True)
    assert "Circle(" not in text and "# snapped" not in text
    (tmp_path / "p.svg").write_text(_svg())
    with pytest.raises(SystemExit) as ex:
        main(["import", "--snap", "1ft", str(tmp_path / "p.svg")])
    assert ex.value.code == 2
    assert "`1ft` is no length: write it as 0.01mm" in capsys.readouterr().err
    from aidl_lang.cli.arguments import _snap_tolerance
    with pytest.raises(argparse.ArgumentTypeError, match="more than 0 and at most 10 mm"):
        _snap_tolerance("0")
    assert _snap_tolerance("0.001in") == pytest.approx(0.0254)
