"""A bolt circle's start angle as a person reads it, kept when the count changes (issue 85;
issue 103 by the spec, docs/import.md "What an edit means": a new count keeps the first hole
where it is): a hole on the x axis, else one at the top, else the first hole's drawn angle.
Where two readings draw the same holes the x axis wins, then the top: 4 or 8 holes with one
at the top have one on the x axis; 6 holes half a pitch off it have one at the top.  (Issue
85 read holes half a pitch off the x axis as straddling it, so four at 45 deg became six at
30 deg: the first hole moved.)  Drawn with ezdxf, the output DXF read back with ezdxf."""
from __future__ import annotations

import io
import math

import ezdxf
import pytest

import aidl_lang
from aidl_lang.drawing.infer import import_drawing

C, R = (50.0, 50.0), 30.0


def _flange(path, n: int, a0: float) -> bytes:
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (100, 0), (100, 100), (0, 100)], close=True)
    for k in range(n):
        a = a0 + 2 * math.pi * k / n
        m.add_circle((C[0] + R * math.cos(a), C[1] + R * math.sin(a)), 2.0)
    doc.saveas(path)
    return path.read_bytes()


@pytest.mark.parametrize("n,start,reading", [
    (4, "axis", "axis"), (4, "top", "axis"), (4, "between", "drawn"),
    (8, "top", "axis"), (6, "top", "top"), (6, "between", "top"),
    (6, "axis", "axis"), (5, "top", "top"), (5, "between", "drawn"), (3, "between", "drawn")])
def test_bolt_circle_count_keeps_its_start(tmp_path, n, start, reading):
    first = {"axis": 0.0, "between": math.pi / n, "top": math.pi / 2}
    text, _ = import_drawing(_flange(tmp_path / "f.dxf", n, first[start]), "f.dxf", infer=True)
    cnt = [ln.split()[1] for ln in text.splitlines()
           if ln.startswith("param") and ln.split()[1].endswith("_n")]
    assert len(cnt) == 1, text
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl", overrides={cnt[0]: str(n + 1)})
    assert res.ok, [str(d) for d in res.errors]
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    got = sorted((round(e.dxf.center.x, 6), round(e.dxf.center.y, 6))
                 for e in doc.modelspace() if e.dxftype() == "CIRCLE")
    m = n + 1
    a0 = {"axis": 0.0, "drawn": first[start], "top": math.pi / 2}[reading]
    want = sorted((round(C[0] + R * math.cos(a0 + 2 * math.pi * k / m), 6),
                   round(C[1] + R * math.sin(a0 + 2 * math.pi * k / m), 6)) for k in range(m))
    assert len(got) == m and all(math.dist(p, q) <= 1e-6 for p, q in zip(got, want)), (got, want)


def test_two_rings_and_a_lone_hole_of_one_size_are_each_their_own(tmp_path):
    """Two bolt circles of one hole size about the plate's centre (5 on a 60 mm circle, 8 on
    a 32 mm one) and a lone hole of that size: no one pattern, and too far apart to split by
    neighbours, they were one list of 14 centres (no pitch circle, no count to edit).  Now
    split by their distance from the centre: two bolt circles, each its own `_pcd` and `_n`,
    and the lone hole."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (100, 0), (100, 100), (0, 100)], close=True)
    for n, rr in ((5, 30.0), (8, 16.0)):
        for k in range(n):
            a = 2 * math.pi * k / n
            m.add_circle((C[0] + rr * math.cos(a), C[1] + rr * math.sin(a)), 2.5)
    m.add_circle((C[0], C[1] + 40), 2.5)
    doc.saveas(tmp_path / "r.dxf")
    text, _ = import_drawing((tmp_path / "r.dxf").read_bytes(), "r.dxf", infer=True)
    pcd = {float(ln.split()[3]): ln.split()[1] for ln in text.splitlines()
           if ln.startswith("param") and ln.split()[1].endswith("_pcd")}
    assert sorted(pcd) == [32.0, 60.0], text
    cnt = {ln.split()[1] for ln in text.splitlines()
           if ln.startswith("param") and ln.split()[1].endswith("_n")}
    assert len(cnt) == 2, text
    outer_n = pcd[60.0][:-len("pcd")] + "n"
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl",
                            overrides={pcd[60.0]: "70 mm", outer_n: "6"})
    assert res.ok, [str(d) for d in res.errors]
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    got = [(e.dxf.center.x, e.dxf.center.y) for e in doc.modelspace() if e.dxftype() == "CIRCLE"]
    dist = sorted(round(math.dist(p, C), 6) for p in got)
    assert dist == [16.0] * 8 + [35.0] * 6 + [40.0], dist
