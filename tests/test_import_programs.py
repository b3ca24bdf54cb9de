"""Drawings written at test time by real programs from Debian, imported (issue 59).

Each test runs the program headless, writes its drawing into ``tmp_path`` and imports it with
the real importer; the geometry it must give is stated exactly.  A test skips, naming what it
lacks, when the program is missing (``.ci/run`` step 3 installs them: ``freecad``, ``kicad``,
``inkscape``).  Measured on Debian 12: FreeCAD 0.20.2 (``freecadcmd``), KiCad 6.0.11 (its
``pcbnew`` Python module, in the system's Python), Inkscape 1.2.2."""
from __future__ import annotations

import math
import os
import shutil
import subprocess
import textwrap

import pytest

import aidl_lang
from aidl_lang.drawing.write.program import import_drawing
from aidl_lang.drawing.read import read_drawing
from aidl_lang.geometry.shapes.curves import Arc, Circle, Line

EXACT = 1e-9


def _run(cmd, cwd, env=None, timeout=120):
    r = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    assert r.returncode == 0, (cmd, r.stdout[-2000:], r.stderr[-2000:])
    return r


def _ends(segs) -> set:
    return {(round(p[0], 9) + 0.0, round(p[1], 9) + 0.0) for s in segs for p in (s.start, s.end)}


# ------------------------------------------------------------------ FreeCAD
FREECAD_SKETCH = textwrap.dedent('''
    import os, math, FreeCAD as App, Part, Sketcher, importDXF
    V = App.Vector
    doc = App.newDocument("plate")
    sk = doc.addObject("Sketcher::SketchObject", "Plate")
    def arc(cx, cy, r, a0, a1):
        return Part.ArcOfCircle(Part.Circle(V(cx, cy, 0), V(0, 0, 1), r), a0, a1)
    # the outline, 80 x 50, its two right corners rounded (r = 10)
    sk.addGeometry(Part.LineSegment(V(0, 0, 0), V(70, 0, 0)))
    sk.addGeometry(arc(70, 10, 10, -math.pi / 2, 0))
    sk.addGeometry(Part.LineSegment(V(80, 10, 0), V(80, 40, 0)))
    sk.addGeometry(arc(70, 40, 10, 0, math.pi / 2))
    sk.addGeometry(Part.LineSegment(V(70, 50, 0), V(0, 50, 0)))
    sk.addGeometry(Part.LineSegment(V(0, 50, 0), V(0, 0, 0)))
    # a slot: half circles r = 3 about (20, 25) and (40, 25), joined by lines
    sk.addGeometry(arc(20, 25, 3, math.pi / 2, 3 * math.pi / 2))
    sk.addGeometry(Part.LineSegment(V(20, 22, 0), V(40, 22, 0)))
    sk.addGeometry(arc(40, 25, 3, -math.pi / 2, math.pi / 2))
    sk.addGeometry(Part.LineSegment(V(40, 28, 0), V(20, 28, 0)))
    # a hole pattern: three holes r = 2 at x = 55, 62, 69 on y = 25
    for x in (55, 62, 69):
        sk.addGeometry(Part.Circle(V(x, 25, 0), V(0, 0, 1), 2))
    doc.recompute()
    importDXF.export([sk], os.environ["AIDL_OUT"])
    print("FreeCAD", ".".join(App.Version()[:3]))
''')


def test_freecad_sketch_with_arcs_a_slot_and_a_hole_pattern(tmp_path):
    """FreeCAD 0.20 (``freecadcmd``, its Draft DXF exporter ``importDXF.export``): a sketch
    of an 80 x 50 mm plate with two rounded corners (r = 10), a slot (two half circles
    r = 3 about (20, 25) and (40, 25)) and three holes r = 2 on y = 25.  It must import as
    exactly that: the outline's lines and arcs, the slot a hole of two arcs and two lines,
    three circles; the compiled plate's area 80 x 50 - 2 (100 - 25 pi) - (120 + 9 pi)
    - 12 pi mm^2."""
    fc = shutil.which("freecadcmd")
    if fc is None:
        pytest.skip("freecadcmd is not installed (apt-get install -y freecad)")
    (tmp_path / "sketch.py").write_text(FREECAD_SKETCH)
    out = tmp_path / "plate.dxf"
    env = dict(os.environ, AIDL_OUT=str(out), HOME=str(tmp_path), QT_QPA_PLATFORM="offscreen")
    _run([fc, "sketch.py"], tmp_path, env)
    d = read_drawing(out.read_bytes(), "plate.dxf")
    outer, slot = d.outlines
    assert [type(s) for s in outer.segments] in ([Line, Arc, Line, Arc, Line, Line],
                                                 [Line, Line, Arc, Line, Arc, Line],
                                                 [Line, Line, Line, Arc, Line, Arc],
                                                 [Arc, Line, Line, Line, Arc, Line],
                                                 [Line, Arc, Line, Line, Line, Arc],
                                                 [Arc, Line, Arc, Line, Line, Line])
    assert _ends(outer.segments) == {(0, 0), (70, 0), (80, 10), (80, 40), (70, 50), (0, 50)}
    assert sorted((round(s.center[0], 9), round(s.center[1], 9), round(s.radius, 9))
                  for s in outer.segments if isinstance(s, Arc)) == [(70, 10, 10), (70, 40, 10)]
    assert sorted(type(s).__name__ for s in slot.segments) == ["Arc", "Arc", "Line", "Line"]
    assert _ends(slot.segments) == {(20, 22), (40, 22), (40, 28), (20, 28)}
    assert sorted((c.center, c.radius) for c in d.circles) == \
        [((55.0, 25.0), 2.0), ((62.0, 25.0), 2.0), ((69.0, 25.0), 2.0)]
    text, _ = import_drawing(out.read_bytes(), "plate.dxf")
    res = aidl_lang.compile(source=text, path="plate.aidl")
    assert res.ok, [x.message for x in res.diagnostics]
    (part,) = res.output.parts
    want = 80 * 50 - 2 * (100 - 25 * math.pi) - (120 + 9 * math.pi) - 12 * math.pi
    assert abs(part.area - want) < 1e-6, (part.area, want)


# ------------------------------------------------------------------ KiCad
KICAD_BOARD = textwrap.dedent('''
    import sys, pcbnew
    out = sys.argv[1]
    b = pcbnew.BOARD()
    def P(x, y):
        return pcbnew.wxPoint(pcbnew.FromMM(x), pcbnew.FromMM(y))
    def shape(kind):
        s = pcbnew.PCB_SHAPE(b)
        s.SetShape(kind)
        s.SetLayer(pcbnew.Edge_Cuts)
        s.SetWidth(pcbnew.FromMM(0.1))
        b.Add(s)
        return s
    corners = [(0, 0), (60, 0), (60, 40), (0, 40)]
    for p, q in zip(corners, corners[1:] + corners[:1]):
        s = shape(pcbnew.SHAPE_T_SEGMENT)
        s.SetStart(P(*p))
        s.SetEnd(P(*q))
    for cx, cy in [(4, 4), (56, 4), (56, 36), (4, 36)]:      # M3 mounting holes, r = 1.6
        c = shape(pcbnew.SHAPE_T_CIRCLE)
        c.SetCenter(P(cx, cy))
        c.SetEnd(P(cx + 1.6, cy))
    pcbnew.SaveBoard(out + "/board.kicad_pcb", b)
    b = pcbnew.LoadBoard(out + "/board.kicad_pcb")
    pc = pcbnew.PLOT_CONTROLLER(b)
    po = pc.GetPlotOptions()
    po.SetOutputDirectory(out)
    po.SetDXFPlotUnits(pcbnew.DXF_UNITS_MILLIMETERS)
    po.SetDXFPlotPolygonMode(False)
    po.SetAutoScale(False)
    po.SetScale(1)
    po.SetMirror(False)
    pc.SetLayer(pcbnew.Edge_Cuts)
    pc.OpenPlotfile("Edge_Cuts", pcbnew.PLOT_FORMAT_DXF, "board outline")
    pc.PlotLayer()
    pc.ClosePlot()
    print("KiCad", pcbnew.Version())
''')


def _system_python_with_pcbnew():
    for py in ("/usr/bin/python3", shutil.which("python3")):
        if py and os.path.exists(py):
            r = subprocess.run([py, "-c", "import pcbnew"], capture_output=True, timeout=60)
            if r.returncode == 0:
                return py
    return None


def test_kicad_board_outline_and_mounting_holes_plotted_from_edge_cuts(tmp_path):
    """KiCad 6 (its ``pcbnew`` Python module, run in the system's Python): a 60 x 40 mm board
    outline and four M3 mounting holes (r = 1.6 at 4 mm from each corner) drawn on Edge.Cuts,
    plotted to DXF in mm (``PLOT_CONTROLLER``, DXF, not polygon mode).  KiCad's y axis points
    down and its plot turns it up: the outline must import as the rectangle (0, 0) to
    (60, -40) and four circles r = 1.6 at (4, -4), (56, -4), (56, -36), (4, -36), exactly;
    the compiled board's area 2400 - 4 x 2.56 pi mm^2."""
    py = _system_python_with_pcbnew()
    if py is None:
        pytest.skip("KiCad's pcbnew module is not installed (apt-get install -y kicad)")
    (tmp_path / "board.py").write_text(KICAD_BOARD)
    _run([py, "board.py", str(tmp_path)], tmp_path, dict(os.environ, HOME=str(tmp_path)))
    (dxf,) = tmp_path.glob("*Edge_Cuts*.dxf")
    data = dxf.read_bytes()
    d = read_drawing(data, "board.dxf")
    (outer,) = d.outlines
    assert all(isinstance(s, Line) for s in outer.segments) and len(outer.segments) == 4
    assert _ends(outer.segments) == {(0, 0), (60, 0), (60, -40), (0, -40)}
    assert sorted((c.center, c.radius) for c in d.circles) == \
        sorted([((4.0, -4.0), 1.6), ((56.0, -4.0), 1.6), ((56.0, -36.0), 1.6),
                ((4.0, -36.0), 1.6)])
    text, _ = import_drawing(data, "board.dxf")
    res = aidl_lang.compile(source=text, path="board.aidl")
    assert res.ok, [x.message for x in res.diagnostics]
    (part,) = res.output.parts
    assert abs(part.area - (2400 - 4 * 2.56 * math.pi)) < 1e-6


# ------------------------------------------------------------------ Inkscape
INKSCAPE_SVG = '''<svg xmlns="http://www.w3.org/2000/svg"
     xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     width="100mm" height="60mm" viewBox="0 0 100 60">
  <g inkscape:groupmode="layer" id="layer1" inkscape:label="Cut">
    <path id="outline" d="M 10 10 H 90 V 50 H 10 Z" fill="none" stroke="#000000"/>
    <path id="slit" d="M 30 20 V 40" fill="none" stroke="#000000"/>
  </g>
  <g inkscape:groupmode="layer" id="layer2" inkscape:label="Engrave">
    <text id="label" x="50" y="30" font-size="5" font-family="sans-serif"
          fill="#000000">AIDL 59</text>
  </g>
</svg>
'''


def test_inkscape_dxf_r14_of_a_panel_with_a_slit_and_text(tmp_path):
    """Inkscape 1.2 (``--export-extension=org.ekips.output.dxf_outlines``, its "Desktop
    Cutting Plotter (AutoCAD DXF R14)" output): an 80 x 40 mm panel (10..90 x 10..50) with
    a 20 mm slit at x = 30 on layer ``Cut`` and the text "AIDL 59" on layer ``Engrave``.
    The R14 exporter writes no TEXT entity (text is left out), so the text is first turned
    into paths by Inkscape (``--export-text-to-path``).  Imported with ``--cut Cut
    --engrave Engrave``: the panel (Inkscape turns the y axis over: y' = 60 - y, which
    leaves the panel where it was) with the slit as a through-cut, ``cut cuts``, from
    (30, 40) to (30, 20), one line; the letters engraved, their outlines standing on the
    baseline y = 30 from x = 50 (to its overshoot: the font is the machine's sans-serif)."""
    ink = shutil.which("inkscape")
    if ink is None:
        pytest.skip("inkscape is not installed (apt-get install -y inkscape)")
    (tmp_path / "panel.svg").write_text(INKSCAPE_SVG)
    env = dict(os.environ, HOME=str(tmp_path), XDG_CONFIG_HOME=str(tmp_path / "cfg"))
    _run([ink, "panel.svg", "--export-text-to-path", "--export-type=svg", "-o", "paths.svg"],
         tmp_path, env)
    _run([ink, "paths.svg", "--export-type=dxf",
          "--export-extension=org.ekips.output.dxf_outlines", "-o", "panel.dxf"], tmp_path, env)
    data = (tmp_path / "panel.dxf").read_bytes()
    assert b"AC1014" in data                           # R14
    d = read_drawing(data, "panel.dxf", layer="Cut", cut="Cut")
    (outer,) = d.outlines
    assert _ends(outer.segments) == {(10, 10), (90, 10), (90, 50), (10, 50)}
    (slit,) = d.paths
    assert [type(s) for s in slit.segments] == [Line] and _ends(slit.segments) == \
        {(30, 20), (30, 40)}
    text, notes = import_drawing(data, "panel.dxf", cut="Cut", engrave="Engrave")
    cut = text.split("cut cuts {", 1)[1].split("}", 1)[0]
    assert [ln.strip() for ln in cut.strip().splitlines()] == [
        "p1_0 = Line(start=(30, 40), end=(30, 20))", "for x in [p1_0.start, p1_0.end] { Fixed(x)"]
    letters = read_drawing(data, "panel.dxf", layer="Engrave")
    x0, y0, x1, y1 = letters.box()
    # on the baseline (round letters and digits dip below it by their overshoot, ~1.5 %)
    assert abs(y0 - 30) < 0.15 and 50 <= x0 < 51 and 60 < x1 < 80 and 32 < y1 < 35, \
        letters.box()
    res = aidl_lang.compile(source=text, path="panel.aidl")
    assert res.ok, [x.message for x in res.diagnostics]
