"""E0501: a machine file (G-code, LightBurn, HP-GL) of parts drawn over each other is refused.

Found in issue 84's second fresh-model run: a bird house's walls, each drawn at the origin and
placed in 3D with ``Place``, came out of ``aidl render -o house.gcode`` as one G-code program
cutting seven parts through each other, with no message.  The picture and the SVG may show
parts over each other (an assembly view); a cutter cannot make that.  ``--layout sheet`` lays
them apart and is written.  The law: over generated assemblies of rectangles and circles, the
machine file is refused exactly when shapely finds two parts sharing more than
``STACKED_AREA`` mm^2."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest
import shapely.geometry as sg
from hypothesis import HealthCheck, given, settings, strategies as st

from aidl_lang.output import build, encode
from aidl_lang.output.writers import STACKED_AREA, StackedParts

HOUSE = """assembly house {
    solid front { r = Rectangle(center=(0, 0), width=120, height=110) }
    solid back { r = Rectangle(center=(0, 0), width=120, height=110) }
    Place(front, rotation=(90 deg, 0, 0), position=(0, -60, 0))
    Place(back, rotation=(90 deg, 0, 0), position=(0, 60, 0))
}
"""


def _render(tmp_path, *args):
    r = subprocess.run([sys.executable, "-m", "aidl_lang.cli", "render", *args, "--json"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=300)
    return r.returncode, json.loads(r.stdout)


@pytest.mark.parametrize("suffix, name", [(".gcode", "G-code"), (".lbrn2", "LightBurn"),
                                          (".plt", "HP-GL")])
def test_a_machine_file_of_parts_over_each_other_is_a_located_E0501_and_nothing_is_written(
        tmp_path, suffix, name):
    (tmp_path / "house.aidl").write_text(HOUSE)
    good = tmp_path / f"house{suffix}"
    good.write_text("a good file from before\n")
    rc, doc = _render(tmp_path, "house.aidl", "-o", good.name)
    assert rc == 1 and doc["ok"] is False
    (d,) = [d for d in doc["diagnostics"] if d["code"] == "E0501"]
    assert d["severity"] == "error"
    assert (d["span"]["line"], d["span"]["column"]) == (2, 5)        # the first part
    assert "parts `house.front` and `house.back`" in d["message"]
    assert "13200.0 mm^2 in common" in d["message"]                  # 120 x 110 mm
    assert f"a {name} file" in d["message"] and "--layout sheet" in d["hint"]
    assert good.read_text() == "a good file from before\n"           # never overwritten


def test_the_cutting_layout_of_the_same_parts_is_written_and_the_svg_as_drawn(tmp_path):
    (tmp_path / "house.aidl").write_text(HOUSE)
    rc, _ = _render(tmp_path, "house.aidl", "--layout", "sheet", "-o", "house.gcode")
    assert rc == 0
    pytest.importorskip("gcodeparser")
    from test_gcode import replay
    lit = [m for m in replay((tmp_path / "house.gcode").read_text()) if m.on]
    # both 120 x 110 mm walls cut whole, twice (the built-in laser's passes), apart
    assert sum(m.length for m in lit) == pytest.approx(2 * 2 * 2 * (120 + 110), abs=1e-6)
    span = [max(v) - min(v) for v in zip(*(q for m in lit for q in (m.p, m.q)))]
    assert max(span) >= 2 * 110                       # laid side by side, not on each other
    rc, doc = _render(tmp_path, "house.aidl", "-o", "house.svg")
    assert rc == 0 and not any(d["code"] == "E0501" for d in doc["diagnostics"])


part = st.tuples(st.sampled_from(["Rectangle", "Circle"]), st.integers(-40, 40),
                 st.integers(-40, 40), st.integers(4, 30))


@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])   # one folder: fine
@given(parts=st.lists(part, min_size=2, max_size=4))
def test_law_refused_exactly_when_two_parts_share_area(parts, compile_text):
    lines, polys = [], []
    for k, (kind, x, y, s) in enumerate(parts):
        if kind == "Rectangle":
            lines.append(f"    solid p{k} {{ r = Rectangle(center=({x}, {y}), width={s}, "
                         f"height={s * 0.6}) }}")
            polys.append(sg.box(x - s / 2, y - 0.3 * s, x + s / 2, y + 0.3 * s))
        else:
            lines.append(f"    solid p{k} {{ c = Circle(center=({x}, {y}), radius={s / 2}) }}")
            polys.append(sg.Point(x, y).buffer(s / 2, 256))
    src = "assembly a {\n" + "\n".join(lines) + "\n    AllowOverlap(" + \
        ", ".join(f"p{k}" for k in range(len(parts))) + ")\n}\n"
    res = compile_text(src)
    assert not res.sink.has_errors
    shared = max(polys[i].intersection(polys[j]).area
                 for i in range(len(polys)) for j in range(i + 1, len(polys)))
    if abs(shared - STACKED_AREA) < 0.05:
        return                      # chords and true circles disagree by less than this
    output = build(res.drawing)
    try:
        encode(output, ".gcode")
        refused = False
    except StackedParts as ex:
        refused = True
        assert "lie over each other" in str(ex)
    assert refused == (shared > STACKED_AREA)
