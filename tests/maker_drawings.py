"""Drawings a maker would bring to ``aidl import --infer`` (issue 71), written as a CAD user
exports them: plain ``LINE``/``ARC``/``CIRCLE``/``LWPOLYLINE`` entities in mm, the origin at
the plate's lower-left corner, some with the holes on a layer of their own.  Each drawing is a
function of its design's numbers, so the drawing a person meant after an edit is the same
function with the edited number; :data:`DRAWINGS` lists each with the edits a person would
make through the inferred program's params (a size, a pitch, a count, the body's width).

An edit is ``(label, param name pattern, current value, new value, the function's keyword
for it)``: the inferred program's param whose name matches the pattern (``re.fullmatch``,
any part prefix allowed) and whose value is the current one is set to the new value; the
program rendered must be the drawing of the function with that keyword, up to a translation
(the plate may grow about its centre where the drawing grows from its corner).

Issue 103 (round six) adds drawings that are not perfectly regular, as makers' files are: a
corner plate with one hole drilled larger, a grid with a hole left out, a fan grille of
square-set holes in a round field, a flange's four holes at 45 degrees, two plates side by
side in one file; a motor plate dimensioned from its far edges, perforated plates (a square-set
and a staggered field over the plate but for a margin), two 2 x 2 groups of one hole size, one
CAD rounded, the other with a hole left out.

Used by benchmarks/imports/infer_edits.py (the share of edits that do what was meant) and
tests/test_import_infer_edits.py (the key edits).
"""
from __future__ import annotations

import io
import math

import ezdxf


def _doc():
    doc = ezdxf.new("R2010")
    doc.units = 4
    return doc, doc.modelspace()


def _bytes(doc) -> bytes:
    s = io.StringIO()
    doc.write(s)
    return s.getvalue().encode()


def _rect(m, x0, y0, w, h, layer="0"):
    m.add_lwpolyline([(x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h)], close=True,
                     dxfattribs={"layer": layer})


def _slot(m, cx, cy, length, width, layer="0"):
    """A vertical slot: two lines and two half-circle arcs."""
    r, a = width / 2, (length - width) / 2
    m.add_line((cx - r, cy - a), (cx - r, cy + a), dxfattribs={"layer": layer})
    m.add_line((cx + r, cy - a), (cx + r, cy + a), dxfattribs={"layer": layer})
    m.add_arc((cx, cy + a), r, 0, 180, dxfattribs={"layer": layer})
    m.add_arc((cx, cy - a), r, 180, 360, dxfattribs={"layer": layer})


def nema17(width=60.0, height=60.0, bore=22.0, spacing=31.0, hole=3.4) -> bytes:
    """A NEMA 17 motor mount: the bore on the plate's centre, four M3 holes round it."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    c = (width / 2, height / 2)
    m.add_circle(c, bore / 2)
    for sx in (-1, 1):
        for sy in (-1, 1):
            m.add_circle((c[0] + sx * spacing / 2, c[1] + sy * spacing / 2), hole / 2)
    return _bytes(doc)


def rpi(width=160.0, height=70.0, hole=2.7, pitch_x=58.0, pitch_y=49.0) -> bytes:
    """A Raspberry Pi mount at the left of a longer plate: its four holes 8 mm from the left
    edge, centred on the plate's height (70 mm: 49 + 2 x 10.5, the plate sized round them)."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    for i in range(2):
        for j in range(2):
            m.add_circle((8 + i * pitch_x, height / 2 + (j - 0.5) * pitch_y), hole / 2)
    return _bytes(doc)


def flange(diameter=100.0, bore=40.0, pcd=75.0, count=8, hole=8.0) -> bytes:
    """A round flange: a bore and a bolt circle of ``count`` holes."""
    doc, m = _doc()
    c = (diameter / 2, diameter / 2)
    m.add_circle(c, diameter / 2)
    m.add_circle(c, bore / 2)
    for k in range(count):
        a = 2 * math.pi * k / count
        m.add_circle((c[0] + pcd / 2 * math.cos(a), c[1] + pcd / 2 * math.sin(a)), hole / 2)
    return _bytes(doc)


def grille(width=80.0, height=80.0, hole=5.0, pitch=7.0, corner=3.4, field=(49.0, 42.0)) \
        -> bytes:
    """A fan grille: a hex (staggered) grid of holes filling a vent field of ``field`` (mm)
    centred on the plate (at the defaults 7 rows of 7 and 6 holes; issue 85: a new pitch
    refills the field), a corner hole 5 mm in from each side."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    c = (width / 2, height / 2)
    dy = pitch * math.sqrt(3) / 2
    for j in range(-20, 21):
        off = pitch / 2 if j % 2 else 0.0
        for i in range(-20, 21):
            x, y = i * pitch + off, j * dy
            if abs(x) + hole / 2 <= field[0] / 2 + 1e-9 and abs(y) + hole / 2 <= field[1] / 2 + 1e-9:
                m.add_circle((c[0] + x, c[1] + y), hole / 2)
    for sx in (5, width - 5):
        for sy in (5, height - 5):
            m.add_circle((sx, sy), corner / 2)
    return _bytes(doc)


def slot_panel(width=150.0, height=60.0, count=6, pitch=20.0, length=30.0, slot=6.0) -> bytes:
    """A panel with a row of vertical slots centred on it."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    for k in range(count):
        _slot(m, width / 2 + (k - (count - 1) / 2) * pitch, height / 2, length, slot)
    return _bytes(doc)


def front_panel(width=120.0, height=60.0, pot=7.0, pitch=30.0, corner=3.2) -> bytes:
    """A front panel as panel programs export it: the outline on layer OUTLINE, the holes on
    layer HOLES -- three pot holes in a row centred on the panel, a corner hole in each
    corner."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height, "OUTLINE")
    for k in (-1, 0, 1):
        m.add_circle((width / 2 + k * pitch, height / 2), pot / 2, dxfattribs={"layer": "HOLES"})
    for sx in (5, width - 5):
        for sy in (5, height - 5):
            m.add_circle((sx, sy), corner / 2, dxfattribs={"layer": "HOLES"})
    return _bytes(doc)


def lcd_panel(width=140.0, height=90.0, screw=3.0, spacing_x=75.0, spacing_y=31.0) -> bytes:
    """A panel for a 16x2 LCD: the window (71 x 24) above the centre, its four screws round
    it."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    c = (width / 2, height / 2 + 10)
    _rect(m, c[0] - 35.5, c[1] - 12, 71, 24)
    for sx in (-1, 1):
        for sy in (-1, 1):
            m.add_circle((c[0] + sx * spacing_x / 2, c[1] + sy * spacing_y / 2), screw / 2)
    return _bytes(doc)


def comb(width=120.0, height=30.0, count=7, pitch=15.0, notch=6.0, hole=4.0) -> bytes:
    """A cable comb: ``count`` notches 15 mm deep in its top edge, centred; a mounting hole
    10 mm in from each end."""
    doc, m = _doc()
    pts = [(0, 0), (width, 0), (width, height)]
    xs = [width / 2 + (k - (count - 1) / 2) * pitch for k in range(count)]
    for x in reversed(xs):
        pts += [(x + notch / 2, height), (x + notch / 2, height - 15),
                (x - notch / 2, height - 15), (x - notch / 2, height)]
    pts.append((0, height))
    m.add_lwpolyline(pts, close=True)
    for x in (10, width - 10):
        m.add_circle((x, 7), hole / 2)
    return _bytes(doc)


def arduino(width=100.0, height=70.0, hole=3.2) -> bytes:
    """An Arduino Uno plate: the board's four holes where the board puts them (no pattern),
    the board centred on the plate."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    ox, oy = width / 2 - 68.58 / 2, height / 2 - 53.34 / 2
    for x, y in ((13.97, 2.54), (15.24, 50.8), (66.04, 7.62), (66.04, 35.56)):
        m.add_circle((ox + x, oy + y), hole / 2)
    return _bytes(doc)


def brackets(leg=40.0, width=15.0, hole=4.0, gap=10.0) -> bytes:
    """A mirrored pair of L-brackets (one drawn, the other its mirror image about x = 0),
    a hole in each leg."""
    doc, m = _doc()
    for s in (1, -1):
        x0 = s * gap / 2
        pts = [(x0, 0), (x0 + s * leg, 0), (x0 + s * leg, width), (x0 + s * width, width),
               (x0 + s * width, leg), (x0, leg)]
        m.add_lwpolyline(pts if s > 0 else pts[::-1], close=True)
        m.add_circle((x0 + s * (leg + width) / 2, width / 2), hole / 2)
        m.add_circle((x0 + s * width / 2, (leg + width) / 2), hole / 2)
    return _bytes(doc)


# name: (function, [(label, param pattern, current value, new value, keyword)])
def corner_plate(width=160.0, height=100.0, inset=10.0, hole=4.0, odd=4.4) -> bytes:
    """Four corner holes, the top right one drilled larger (issue 103: a clearance hole)."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            big = x > width / 2 and y > height / 2
            m.add_circle((x, y), (odd if big else hole) / 2)
    return _bytes(doc)


def gapped_grid(width=160.0, height=100.0, pitch=30.0, cols=4, rows=3, hole=5.0,
                gap=(2, 1)) -> bytes:
    """A grid of holes centred on the plate with one left out (issue 103), the gap at its
    column and row from the lower left."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    for i in range(cols):
        for j in range(rows):
            if (i, j) != gap:
                m.add_circle((width / 2 + (i - (cols - 1) / 2) * pitch,
                              height / 2 + (j - (rows - 1) / 2) * pitch), hole / 2)
    return _bytes(doc)


def fan_grille(width=80.0, height=80.0, pitch=6.0, hole=4.0, field=60.0, corner=3.4) -> bytes:
    """A fan grille of square-set round holes clipped to a round field on the plate's centre
    (issue 103), four mounting holes 4 mm in from the corners."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    k = int(field / pitch) + 1
    for i in range(-k, k + 1):
        for j in range(-k, k + 1):
            if math.hypot(i * pitch, j * pitch) + hole / 2 <= field / 2 + 1e-9:
                m.add_circle((width / 2 + i * pitch, height / 2 + j * pitch), hole / 2)
    for x in (4, width - 4):
        for y in (4, height - 4):
            m.add_circle((x, y), corner / 2)
    return _bytes(doc)


def flange45(width=80.0, height=80.0, count=4, pcd=50.0, hole=5.5, angle=45.0) -> bytes:
    """A square flange: a bore and ``count`` holes on a circle, the first at 45 degrees."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    c = (width / 2, height / 2)
    m.add_circle(c, 10)
    for k in range(count):
        a = math.radians(angle) + 2 * math.pi * k / count
        m.add_circle((c[0] + pcd / 2 * math.cos(a), c[1] + pcd / 2 * math.sin(a)), hole / 2)
    return _bytes(doc)


def two_plates(first=60.0, second=50.0, gap=10.0, height=40.0) -> bytes:
    """Two plates side by side in one file (issue 103): four corner holes in the first, a
    bore in the middle of the second."""
    doc, m = _doc()
    _rect(m, 0, 0, first, height)
    _rect(m, first + gap, 0, second, height)
    for x in (5, first - 5):
        for y in (5, height - 5):
            m.add_circle((x, y), 1.6)
    m.add_circle((first + gap + second / 2, height / 2), 4)
    return _bytes(doc)


def checkerboard(width=120.0, height=80.0, big=6.0, small=5.0, px=30.0, py=25.0) -> bytes:
    """A 4 x 3 checkerboard of ``big`` and ``small`` holes on a ``px`` / ``py`` pitch, centred
    on the plate (issue 114: it was two staggered grids, one from each edge)."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    for i in range(4):
        for j in range(3):
            m.add_circle((width / 2 + (i - 1.5) * px, height / 2 + (j - 1) * py),
                         (big if (i + j) % 2 == 0 else small) / 2)
    return _bytes(doc)


def two_holes(width=120.0, height=60.0, left=30.0, right=29.98, hole=4.0) -> bytes:
    """Two holes in line, ``left`` from the left edge and ``right`` from the right one (issue
    114: at x = 30 and 90.02 they were a row of two from its right end)."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    for x in (left, width - right):
        m.add_circle((x, height / 2), hole / 2)
    return _bytes(doc)


def edge_hole(width=100.0, height=70.0, x=15.0, hole=8.0) -> bytes:
    """A plate with one hole ``x`` from its left edge, 20 mm below its top (issue 114: "move
    it 10 mm further in" found no param)."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    m.add_circle((x, height - 20), hole / 2)
    return _bytes(doc)


def three_plates(first=40.0, second=30.0, third=50.0, gap=10.0, gap2=10.0) -> bytes:
    """Three plates in a row, each with a hole in its middle, drawn largest first (issue 114:
    the first written had no gap param)."""
    doc, m = _doc()
    x = {"b": first + gap}
    x["c"] = x["b"] + second + gap2
    for x0, w in ((x["c"], third), (0.0, first), (x["b"], second)):
        _rect(m, x0, 0, w, 40)
        m.add_circle((x0 + w / 2, 20), 3)
    return _bytes(doc)


def _rounded(m, w, h, r):
    """A plate's outline as one polyline with rounded corners (bulges of a quarter turn)."""
    b = math.tan(math.pi / 8)
    m.add_lwpolyline([(r, 0, 0), (w - r, 0, b), (w, r, 0), (w, h - r, b), (w - r, h, 0),
                      (r, h, b), (0, h - r, 0), (0, r, b)], format="xyb", close=True)


def motor_plate(width=160.0, height=100.0, spacing=31.0, hole=3.4, slot_length=14.0,
                edge_in=12.0, motor_in=40.0) -> bytes:
    """A motor mount plate dimensioned from its far edges (issue 103): the outline a polyline
    with 5 mm rounded corners; a NEMA 17's 22 mm bore ``motor_in`` from the right and the top
    edges, its four holes round it; two holes of the motor holes' size 10 mm in from the
    right edge, ``edge_in`` from the top and bottom; two vertical mounting slots (two lines, two
    arcs) 12 mm from the left edge, 20 mm from the top and bottom."""
    doc, m = _doc()
    _rounded(m, width, height, 5.0)
    for y in (20.0, height - 20.0):
        _slot(m, 12.0, y, slot_length, 5.5)
    c = (width - motor_in, height - motor_in)
    m.add_circle(c, 11.0)
    for sx in (-1, 1):
        for sy in (-1, 1):
            m.add_circle((c[0] + sx * spacing / 2, c[1] + sy * spacing / 2), hole / 2)
    for y in (edge_in, height - edge_in):
        m.add_circle((width - 10.0, y), hole / 2)
    return _bytes(doc)


def perforated(width=200.0, height=150.0, hole=5.0, pitch=10.0, margin=15.0) -> bytes:
    """A perforated plate (issue 103): a square-set field of holes over the plate but for a
    ``margin`` all round, as a maker fills it: as many holes each way as lie whole in the
    field, centred in it (17 x 12 at the defaults)."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    nx = math.floor((width - 2 * margin - hole) / pitch + 1e-9) + 1
    ny = math.floor((height - 2 * margin - hole) / pitch + 1e-9) + 1
    for i in range(nx):
        for j in range(ny):
            m.add_circle((width / 2 + (i - (nx - 1) / 2) * pitch,
                          height / 2 + (j - (ny - 1) / 2) * pitch), hole / 2)
    return _bytes(doc)


def perforated_hex(width=200.0, height=150.0, hole=5.0, pitch=10.0, margin=15.0) -> bytes:
    """A perforated plate with a staggered (hex, 60 degree) field: the lattice about the
    plate's centre (a hole on it, alternate rows half a pitch over), every hole lying whole
    in the plate less a ``margin`` all round."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    dy = pitch * math.sqrt(3) / 2
    k = int(max(width, height) / pitch) + 1
    for j in range(-k, k + 1):
        for i in range(-k, k + 1):
            x, y = (i + (j % 2) / 2) * pitch, j * dy
            if abs(x) + hole / 2 <= width / 2 - margin + 1e-9 and \
                    abs(y) + hole / 2 <= height / 2 - margin + 1e-9:
                m.add_circle((width / 2 + x, height / 2 + y), hole / 2)
    return _bytes(doc)


def two_groups(width=200.0, height=100.0, pitch=30.0, hole=4.0, inset=20.0) -> bytes:
    """Two 2 x 2 groups of one hole size (issue 103), each ``inset`` from its end of the
    plate and centred on its height: the left one with a hole CAD rounded 0.03 mm off its
    node, the right one with its top right hole left out."""
    doc, m = _doc()
    _rect(m, 0, 0, width, height)
    for i in range(2):
        for j in range(2):
            x = inset + i * pitch + (0.03 if (i, j) == (1, 0) else 0.0)
            m.add_circle((x, height / 2 + (j - 0.5) * pitch), hole / 2)
            if (i, j) != (1, 1):
                m.add_circle((width - inset - pitch + i * pitch,
                              height / 2 + (j - 0.5) * pitch), hole / 2)
    return _bytes(doc)


DRAWINGS = {
    "nema17": (nema17, [
        ("plate width", r"width", 60, 70, "width"),
        ("motor hole spacing", r"motor_holes_(pitch|spacing)", 31, 26, "spacing"),
        ("motor hole size", r"motor_holes_d", 3.4, 3.5, "hole"),
        ("bore size", r"bore_d", 22, 24, "bore"),
    ]),
    "rpi": (rpi, [
        ("plate width", r"width", 160, 180, "width"),
        ("hole size", r"holes_d", 2.7, 2.5, "hole"),
        ("pitch x", r"holes_pitch_x", 58, 60, "pitch_x"),
        ("pitch y", r"holes_pitch_y", 49, 45, "pitch_y"),
    ]),
    "flange": (flange, [
        ("body diameter", r"diameter", 100, 110, "diameter"),
        ("bolt count", r"bolt_circle_n", 8, 6, "count"),
        ("pitch circle", r"bolt_circle_pcd", 75, 80, "pcd"),
        ("hole size", r"bolt_circle_d", 8, 9, "hole"),
        ("bore size", r"bore_d", 40, 42, "bore"),
    ]),
    "grille": (grille, [
        ("plate width", r"width", 80, 90, "width"),
        ("grille pitch", r"\w*pitch\w*", 7, 8, "pitch"),
        ("grille hole size", r"holes_d", 5, 4, "hole"),
        ("corner hole size", r"corner_hole_d", 3.4, 3, "corner"),
    ]),
    "slot_panel": (slot_panel, [
        ("panel width", r"width", 150, 170, "width"),
        ("slot pitch", r"slots_pitch", 20, 22, "pitch"),
        ("slot count", r"slots_n", 6, 5, "count"),
        ("slot length", r"slots_length", 30, 32, "length"),
    ]),
    "front_panel": (front_panel, [
        ("panel width", r"width", 120, 140, "width"),
        ("pot pitch", r"holes_pitch", 30, 25, "pitch"),
        ("pot size", r"holes_d", 7, 9.5, "pot"),
        ("corner hole size", r"corner_hole_d", 3.2, 3.5, "corner"),
    ]),
    "lcd_panel": (lcd_panel, [
        ("panel width", r"width", 140, 160, "width"),
        ("screw spacing x", r"screw_holes_pitch_x", 75, 80, "spacing_x"),
        ("screw spacing y", r"screw_holes_pitch_y", 31, 33, "spacing_y"),
        ("screw size", r"screw_holes_d", 3, 3.4, "screw"),
    ]),
    "comb": (comb, [
        ("notch pitch", r"notches_pitch", 15, 14, "pitch"),
        ("notch count", r"notches_n", 7, 6, "count"),
        ("mounting hole size", r"holes_d", 4, 5, "hole"),
        ("comb width", r"width", 120, 140, "width"),
    ]),
    "arduino": (arduino, [
        ("plate width", r"width", 100, 120, "width"),
        ("hole size", r"holes?_d", 3.2, 3.4, "hole"),
    ]),
    "brackets": (brackets, [
        ("hole size", r"holes?_d", 4, 5, "hole"),
        ("leg length", r"\w*leg\w*", 40, 50, "leg"),
    ]),
    "corner_plate": (corner_plate, [
        ("plate width", r"width", 160, 200, "width"),
        ("corner inset", r"corner_inset", 10, 12, "inset"),
        ("corner hole size", r"corner_hole_d", 4, 3.5, "hole"),
        ("odd hole size", r"\w*odd_d", 4.4, 5, "odd"),
    ]),
    "gapped_grid": (gapped_grid, [
        ("plate width", r"width", 160, 200, "width"),
        ("grid pitch", r"holes_pitch", 30, 25, "pitch"),
        ("grid columns", r"holes_cols", 4, 5, "cols"),
        ("hole size", r"holes_d", 5, 6, "hole"),
    ]),
    "fan_grille": (fan_grille, [
        ("field size", r"holes_field_d", 60, 50, "field"),
        ("grille pitch", r"holes_pitch", 6, 7, "pitch"),
        ("grille hole size", r"holes_d", 4, 3.5, "hole"),
        ("plate width", r"width", 80, 90, "width"),
    ]),
    "flange45": (flange45, [
        ("bolt count", r"\w*_n", 4, 6, "count"),
        ("pitch circle", r"\w*_pcd", 50, 56, "pcd"),
        ("first hole's angle", r"\w*_angle", 45, 30, "angle"),
    ]),
    "motor_plate": (motor_plate, [
        ("plate width", r"width", 160, 190, "width"),
        ("plate height", r"height", 100, 120, "height"),
        ("motor hole spacing", r"motor_holes_(pitch|spacing)", 31, 26, "spacing"),
        ("slot length", r"slots_length", 14, 18, "slot_length"),
        ("edge holes' inset", r"holes_inset", 12, 15, "edge_in"),
    ]),
    "perforated": (perforated, [
        ("hole pitch", r"holes_pitch", 10, 15, "pitch"),
        ("hole pitch (finer)", r"holes_pitch", 10, 8, "pitch"),
        ("hole size", r"holes_d", 5, 4, "hole"),
        ("plate width", r"width", 200, 230, "width"),
        ("margin", r"holes_margin", 15, 20, "margin"),
    ]),
    "perforated_hex": (perforated_hex, [
        ("hole pitch", r"holes_pitch", 10, 15, "pitch"),
        ("hole size", r"holes_d", 5, 6, "hole"),
        ("plate height", r"height", 150, 170, "height"),
        ("margin", r"holes_margin", 15, 12, "margin"),
    ]),
    "two_groups": (two_groups, [
        ("plate width", r"width", 200, 240, "width"),
        ("plate height", r"height", 100, 120, "height"),
    ]),
    "checkerboard": (checkerboard, [
        ("plate width", r"width", 120, 200, "width"),
        ("column pitch", r"holes_pitch_x", 30, 25, "px"),
        ("large holes", r"holes_d", 6, 6.5, "big"),
        ("small holes", r"holes_small_d", 5, 4, "small"),
    ]),
    "two_holes": (two_holes, [
        ("plate width", r"width", 120, 200, "width"),
        ("hole size", r"holes_d", 4, 5, "hole"),
    ]),
    "edge_hole": (edge_hole, [
        ("hole's distance from the left edge", r"hole1_x", 15, 25, "x"),
        ("plate height", r"height", 70, 90, "height"),
    ]),
    "three_plates": (three_plates, [
        ("first plate's width", r"l_02_width", 40, 50, "first"),
        ("first gap", r"l_03_gap", 10, 15, "gap"),
        ("second gap", r"l_01_gap", 10, 5, "gap2"),
    ]),
    "two_plates": (two_plates, [
        ("first plate's width", r"l_01_width", 60, 80, "first"),
        ("second plate's width", r"l_02_width", 50, 70, "second"),
        ("gap", r"l_02_gap", 10, 5, "gap"),
    ]),
}
