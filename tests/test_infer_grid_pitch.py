"""A square grid's one pitch and a column's own (`_Part.grid`, issue 85): the grid's pitch was
carried from the x loop to the y loop in a name set only inside the loop (pyflakes: an
undefined name on the path where the x count is 1; `one` needs both counts above 1, so the
path is not taken, and the name is now set before the loop).  Drawn with ezdxf, the output
DXF read back with ezdxf."""
from __future__ import annotations

import io

import ezdxf
import pytest

import aidl_lang
from aidl_lang.drawing.infer import import_drawing


def _plate(path, centres) -> bytes:
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (100, 0), (100, 80), (0, 80)], close=True)
    for c in centres:
        m.add_circle(c, 1.5)
    doc.saveas(path)
    return path.read_bytes()


def _holes(text, tmp_path, overrides) -> list:
    res = aidl_lang.compile(text, path=tmp_path / "p.aidl", overrides=overrides)
    assert res.ok, [str(d) for d in res.errors]
    doc = ezdxf.read(io.StringIO(res.to_dxf()))
    return sorted((round(e.dxf.center.x, 9), round(e.dxf.center.y, 9))
                  for e in doc.modelspace() if e.dxftype() == "CIRCLE")


@pytest.mark.parametrize("nx,ny", [(3, 3), (4, 2), (1, 4), (4, 1)])
def test_grid_pitch_moves_every_hole(tmp_path, nx, ny):
    x0, y0 = 20.0, 15.0
    cs = [(x0 + 10 * i, y0 + 10 * j) for i in range(nx) for j in range(ny)]
    text, _ = import_drawing(_plate(tmp_path / "g.dxf", cs), "g.dxf", infer=True)
    pitch = [ln.split()[1] for ln in text.splitlines()
             if ln.startswith("param") and "pitch" in ln]
    assert len(pitch) == 1, text            # one pitch: a square grid, a row, a column
    assert _holes(text, tmp_path, {}) == sorted(cs)
    got = _holes(text, tmp_path, {pitch[0]: "12 mm"})
    xs, ys = sorted({x for x, _ in got}), sorted({y for _, y in got})
    assert len(got) == nx * ny and len(xs) == nx and len(ys) == ny, got
    for v in (xs, ys):
        assert all(abs(b - a - 12) <= 1e-9 for a, b in zip(v, v[1:])), got
