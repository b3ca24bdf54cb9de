"""What the 3D writers' solids cost, priced before they are built (issue 110): an n x n grid of
3 mm holes each with `Countersink(h, diameter=6 mm)`.  The STL of n = 70 was priced 1.4 M work
units and took 128 s of CPU, past the 90 s backstop; the n = 55 one was written on one machine
and E0304 at `AIDL_CPU_SCALE=3`.  The cones cut and the section's triangulation are now priced
(aidl_lang/output/writers/mesh.py, `solid_seconds`), so the work budget decides: the same answer
and the same work figure at either CPU scale.  Counts only (no clock): about 5 s of CPU."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import aidl_lang


def grid(n: int, sunk: bool = True) -> str:
    """The issue's program: an n x n grid of 3 mm holes at 10 mm, each countersunk 6 mm."""
    return f"""units mm
thickness 4 mm
param n = {n}
solid panel {{
    body = Rectangle(center=(n * 5, n * 5), width=n * 10 + 10, height=n * 10 + 10)
    for i in range(n) {{
        for j in range(n) {{
            hole h {{ c = Circle(center=(i * 10 + 5, j * 10 + 5), diameter=3 mm) }}
            {"Countersink(h, diameter=6 mm)" if sunk else ""}
        }}
    }}
}}
"""


def test_the_cones_and_the_triangulation_are_priced_by_what_they_cut():
    """Each countersink's tool adds its two rings of the hole's chords at
    SECONDS_PER_TOOL_VERTEX a vertex; the section's triangulation grows as vertices x loops
    (4 times the holes: about 16 times the triangulation)."""
    from aidl_lang.output.part.part import Circle, Loop
    from aidl_lang.output.writers import FORMATS, writer_seconds
    from aidl_lang.output.writers import mesh as M
    chords = len(Loop([Circle((0.0, 0.0), 1.5)]).points())
    assert chords > 30                      # a 3 mm hole within 0.005 mm
    per = FORMATS[".stl"].per_vertex
    seen = {}
    for n in (4, 8):
        sunk = aidl_lang.compile(source=grid(n)).output
        plain = aidl_lang.compile(source=grid(n, sunk=False)).output
        [p] = [p for p in plain.parts if p.kind == "solid"]
        v, loops = p.shape.num_vert(), p.shape.num_contour()
        assert loops == n * n + 1 and v == 4 + n * n * chords
        base = M.solid_seconds(plain, per)
        assert abs(base - (per * v + M.TRIANGULATE_PER_VL * v * loops
                           + M.TRIANGULATE_PER_VV * v * v)) < 1e-12
        cones = M.solid_seconds(sunk, per) - base
        assert abs(cones - n * n * 2 * chords * M.SECONDS_PER_TOOL_VERTEX) < 1e-9
        # the same solids in 3MF, at that writer's own rate a vertex
        assert abs(writer_seconds(sunk, ".3mf") - writer_seconds(sunk, ".stl")
                   - (FORMATS[".3mf"].per_vertex - per) * v) < 1e-9
        seen[n] = M.TRIANGULATE_PER_VL * v * loops
    assert seen[8] > 14 * seen[4]


SCRIPT = """
import contextlib, io, json, sys
from aidl_lang.cli.main import main
out = []
for budget in sys.argv[3:]:
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(io.StringIO()):
        rc = main(["render", sys.argv[1], "-o", sys.argv[2] + budget + ".stl", "--json",
                   "--budget", budget])
    got = json.loads(buf.getvalue())
    got.pop("output", None), got.pop("outputs", None)         # the paths (one per scale)
    out.append([rc, got])
print(json.dumps(out))
"""


def test_the_same_answer_and_work_at_either_cpu_scale(tmp_path):
    """`AIDL_CPU_SCALE` multiplies every CPU reading (read once, at import: a process per
    scale).  The grid's STL at the default budget is written with the same work at scale 1 and
    3; at a fiftieth of it the writer is refused before it starts: the same located E0304 (the
    part's line, the work it needs, the `--budget` that covers it) at both, nothing written."""
    import trimesh
    src = tmp_path / "grid.aidl"
    src.write_text(grid(8))
    got = {}
    for scale in ("1", "3"):
        env = {**os.environ, "AIDL_CPU_SCALE": scale,
               "PYTHONPATH": str(Path(aidl_lang.__file__).parent.parent)}
        run = subprocess.run([sys.executable, "-c", SCRIPT, str(src), str(tmp_path / f"s{scale}-"),
                              "1", "0.02"], capture_output=True, text=True, env=env, timeout=300)
        assert run.returncode == 0, run.stderr
        got[scale] = json.loads(run.stdout)
    assert got["1"] == got["3"]
    (rc, ok), (rc_small, refused) = got["1"]
    assert rc == 0 and ok["ok"]
    stl = ok["work"]["stages"]["the STL writer"]
    assert stl > 0.9 * ok["work"]["spent"]          # the cones, priced
    mesh = trimesh.load(tmp_path / "s1-1.stl")
    # every cone cut (without them: 894 mm^3 more); the chords keep 0.2 mm^3 a hole
    assert mesh.is_watertight and abs(mesh.volume - (90 * 90 * 4 - 64 * _sunk_hole())) < 20
    assert rc_small == 1 and not (tmp_path / "s1-0.02.stl").exists()
    [d] = refused["diagnostics"]
    assert d["code"] == "E0304" and "in the STL writer of `panel`" in d["message"]
    assert f"it needs more than {ok['work']['spent']:,} work units" in d["message"]
    from aidl_lang.base.limits import DEFAULT_BUDGET, budget_factor_text
    assert budget_factor_text(ok["work"]["spent"], DEFAULT_BUDGET) == "--budget 0.064"
    assert d["span"]["line"] == 4 and "raise the budget with `--budget 0.064`" in d["hint"]
    from aidl_lang.output.part.part import Circle, Loop
    from aidl_lang.output.writers.mesh import SECONDS_PER_TOOL_VERTEX
    from aidl_lang.base.limits import seconds_as_work
    cones = 64 * 2 * len(Loop([Circle((0.0, 0.0), 1.5)]).points()) * SECONDS_PER_TOOL_VERTEX
    assert d["hint"].endswith(f"; cutting the 64 countersinks and counterbores into the solid "
                              f"needs {int(seconds_as_work(cones)):,} of those units (the SVG, "
                              "DXF and G-code draw their heads without cutting a solid)")


def _sunk_hole() -> float:
    """mm^3 a 3 mm hole with a 6 mm, 90 deg countersink takes from a 4 mm plate: the cone
    1.5 mm deep (a frustum of radii 3 and 1.5) and the bore below it."""
    import math
    cone = math.pi * 1.5 / 3 * (3 * 3 + 3 * 1.5 + 1.5 * 1.5)
    return cone + math.pi * 1.5 ** 2 * 2.5
