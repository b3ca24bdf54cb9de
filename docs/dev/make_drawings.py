"""Writes the drawings the examples import, into ``examples/parts/`` (run it again after
changing it; it lives here, not beside them, because ``examples/`` ships inside the wheel as
data and a ``.py`` there would ship as a module):

* ``pcb_board.dxf``: a small board in KiCad's convention: its outline on layer ``Edge.Cuts``
  as LINE and ARC entities (rounded corners of 3 mm), four M3 mounting holes as CIRCLEs
  (3.2 mm) on ``Edge.Cuts``, and a reference text on ``F.SilkS`` (not imported);
  millimetres (``$INSUNITS`` = 4).  Used by ``examples/pcb_enclosure.aidl``.
* ``logo.svg``: a leaf logo, 24 mm wide (``width="24mm"`` over a 240-unit ``viewBox``):
  cubic Béziers, a circular arc and a circle.  Used by ``examples/logo_plate.aidl``.

Copies go to ``stdlib/drawings/`` (``Drawing2D("std/drawings/...")``) for the docs and ``aidl docs``.
``python docs/dev/make_drawings.py``
"""
from __future__ import annotations

import shutil
from pathlib import Path

import ezdxf

ROOT = Path(__file__).resolve().parent.parent.parent
HERE = ROOT / "examples" / "parts"
DOCS = ROOT / "stdlib" / "drawings"

W, H, R = 64.0, 42.0, 3.0            # board size and corner radius, mm
HOLES = [(3.5, 3.5), (W - 3.5, 3.5), (W - 3.5, H - 3.5), (3.5, H - 3.5)]


def board(path: Path) -> None:
    doc = ezdxf.new("R2010", setup=False)
    doc.units = ezdxf.units.MM
    doc.layers.add("Edge.Cuts", color=2)
    doc.layers.add("F.SilkS", color=7)
    msp = doc.modelspace()
    cut = {"layer": "Edge.Cuts"}
    msp.add_line((R, 0), (W - R, 0), dxfattribs=cut)
    msp.add_line((W, R), (W, H - R), dxfattribs=cut)
    msp.add_line((W - R, H), (R, H), dxfattribs=cut)
    msp.add_line((0, H - R), (0, R), dxfattribs=cut)
    for (cx, cy), a in (((W - R, R), 270), ((W - R, H - R), 0), ((R, H - R), 90), ((R, R), 180)):
        msp.add_arc((cx, cy), R, a, a + 90, dxfattribs=cut)
    for x, y in HOLES:
        msp.add_circle((x, y), 1.6, dxfattribs=cut)
    msp.add_text("SENSOR-BOARD rev A", height=1.5, dxfattribs={"layer": "F.SilkS"}).set_placement((8, 20))
    doc.saveas(path)


LOGO = """<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="24mm" height="24mm" viewBox="0 0 240 240">
  <g id="logo">
    <path id="leaf" d="M 120 20 C 190 60 210 150 120 220 C 30 150 50 60 120 20 Z"
          fill="none" stroke="#2e7d32" stroke-width="4"/>
    <path id="vein" d="M 120 60 L 120 200 M 120 110 A 40 40 0 0 1 160 150
                       M 120 110 A 40 40 0 0 0 80 150" fill="none" stroke="#2e7d32"/>
    <circle id="dot" cx="120" cy="85" r="10" fill="none" stroke="#2e7d32"/>
  </g>
</svg>
"""


def main() -> None:
    board(HERE / "pcb_board.dxf")
    (HERE / "logo.svg").write_text(LOGO)
    DOCS.mkdir(parents=True, exist_ok=True)
    for n in ("pcb_board.dxf", "logo.svg"):
        shutil.copyfile(HERE / n, DOCS / n)


if __name__ == "__main__":
    main()
