"""Makers' drawings for issue 114's second measurement (brief h24-makers).

Each drawing is a function of its numbers (keyword arguments with the drawn values as defaults)
returning a Part: closed outlines (polylines with bulges, as a CAD program's LWPOLYLINE) and
circles, each on a layer, in mm, with the origin where a maker puts it.  `write_dxf` writes it
as plain LINE/ARC/CIRCLE/LWPOLYLINE (ezdxf); `write_svg` as an svgwrite drawing in a mm viewBox
whose y axis is turned by a group, numbers to 6 decimals.  Written without reading the
inference (aidl_lang/), its tests or earlier drawings: only docs/import.md and issue 114's list
(the Part, the writers and the format of a drawing function are issue114's makers.py's, which
were issue103b's, reused; none of their drawings is).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

# --------------------------------------------------------------------------- geometry


@dataclass
class Part:
    # each item: ("poly", layer, [(x, y, bulge), ...]) closed, or ("circle", layer, (cx, cy), r)
    items: list = field(default_factory=list)
    fmt: str = "dxf"            # "dxf" or "svg"
    explode: bool = False       # DXF: write outlines as LINE/ARC instead of LWPOLYLINE

    def poly(self, pts, layer="0"):
        self.items.append(("poly", layer, list(pts)))

    def circle(self, c, r, layer="0"):
        self.items.append(("circle", layer, (float(c[0]), float(c[1])), float(r)))

    def move(self, dx, dy):
        out = []
        for it in self.items:
            if it[0] == "poly":
                out.append(("poly", it[1], [(x + dx, y + dy, b) for x, y, b in it[2]]))
            else:
                out.append(("circle", it[1], (it[2][0] + dx, it[2][1] + dy), it[3]))
        self.items = out
        return self


Q = math.tan(math.radians(90) / 4)       # bulge of a quarter arc, counter-clockwise


def rect(x0, y0, w, h):
    return [(x0, y0, 0), (x0 + w, y0, 0), (x0 + w, y0 + h, 0), (x0, y0 + h, 0)]


def rrect(x0, y0, w, h, r):
    """A rounded rectangle, counter-clockwise, each corner a quarter arc (bulge on the arc's start)."""
    if r <= 0:
        return rect(x0, y0, w, h)
    return [(x0 + r, y0, 0), (x0 + w - r, y0, Q), (x0 + w, y0 + r, 0), (x0 + w, y0 + h - r, Q),
            (x0 + w - r, y0 + h, 0), (x0 + r, y0 + h, Q), (x0, y0 + h - r, 0), (x0, y0 + r, Q)]


def slot(cx, cy, length, width, vertical=False):
    """A slot, `length` end to end, its end caps two half circles (bulge 1)."""
    a, r = (length - width) / 2, width / 2
    if not vertical:
        return [(cx - a, cy - r, 0), (cx + a, cy - r, 1), (cx + a, cy + r, 0), (cx - a, cy + r, 1)]
    return [(cx + r, cy - a, 0), (cx + r, cy + a, 1), (cx - r, cy + a, 0), (cx - r, cy - a, 1)]



# --------------------------------------------------------------------------- the drawings
# Each returns a Part; its keyword arguments are the numbers a maker dimensions.  Written from
# issue 114's list and docs/import.md alone, before any of them was imported (brief h24-makers);
# none is a drawing of issue114's or issue103b's runs.


def _fit(field, d, pitch):
    """How many holes of diameter d on a pitch lie whole in a field `field` long."""
    return int(math.floor((field - d) / pitch + 1e-9)) + 1


MEGA = [(13.97, 2.54), (15.24, 50.8), (66.04, 7.62), (66.04, 35.56), (90.17, 50.8), (96.52, 2.54)]
# an Arduino Mega 2560's six holes from its board origin (datasheet, 0.55 in = 13.97 mm, ...)


def mega_plate(width=200.0, height=90.0, board_x=20.0, board_y=12.0, hole_d=3.2, corner_inset=6.0,
               corner_d=4.0):
    """A base plate for an Arduino Mega: the board's origin board_x from the left edge and
    board_y from the bottom, its six M3 holes; four corner holes.  Outline on `OUTLINE`, every
    hole on `HOLES`."""
    p = Part()
    p.poly(rect(0, 0, width, height), "OUTLINE")
    for x, y in MEGA:
        p.circle((board_x + x, board_y + y), hole_d / 2, "HOLES")
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, height - corner_inset):
            p.circle((x, y), corner_d / 2, "HOLES")
    return p


def esp32_carrier(width=120.0, height=70.0, corner_r=5.0, from_right=15.0, spacing_x=46.0,
                  spacing_y=23.5, hole_d=3.0, mount_x=10.0, mount_inset=12.0, mount_d=5.0):
    """A carrier for an ESP32 dev board (four M2.5 holes, 46 x 23.5 mm), its right holes
    from_right from the right edge, centred on the height; two mounting holes by the left edge,
    mount_inset from the bottom and from the top.  Rounded corners; exploded to LINE/ARC."""
    p = Part(explode=True)
    p.poly(rrect(0, 0, width, height, corner_r))
    x1 = width - from_right
    for x in (x1 - spacing_x, x1):
        for y in (height / 2 - spacing_y / 2, height / 2 + spacing_y / 2):
            p.circle((x, y), hole_d / 2)
    for y in (mount_inset, height - mount_inset):
        p.circle((mount_x, y), mount_d / 2)
    return p


SENSOR3 = [(0.0, 0.0), (16.5, 0.0), (8.25, 18.0)]     # a sensor board's three holes


def sensor_strip(width=120.0, height=35.0, sensor_x=10.0, sensor_y=6.0, sensor_d=2.5,
                 hole_from_right=10.0, hole_d=5.0):
    """A strip with a small sensor board by its left end (its lower left hole sensor_x from the
    left edge) and one 5 mm hole hole_from_right from the right edge on the centre line; an SVG
    (6-decimal numbers)."""
    p = Part(fmt="svg")
    p.poly(rect(0, 0, width, height))
    for x, y in SENSOR3:
        p.circle((sensor_x + x, sensor_y + y), sensor_d / 2)
    p.circle((width - hole_from_right, height / 2), hole_d / 2)
    return p


def speaker_grille(width=160.0, height=120.0, margin=15.0, pitch=7.0, hole_d=4.0, mount_inset=6.0,
                   mount_d=4.5):
    """A speaker grille panel: 4 mm holes on a square 7 mm pitch filling the panel less a 15 mm
    margin (as many as lie whole in it, centred), four mounting holes in the corners.  Outline
    on `PANEL`, holes on `HOLES`."""
    p = Part()
    p.poly(rect(0, 0, width, height), "PANEL")
    nx, ny = _fit(width - 2 * margin, hole_d, pitch), _fit(height - 2 * margin, hole_d, pitch)
    for i in range(nx):
        for j in range(ny):
            p.circle((width / 2 + (i - (nx - 1) / 2) * pitch, height / 2 + (j - (ny - 1) / 2) * pitch),
                     hole_d / 2, "HOLES")
    for x in (mount_inset, width - mount_inset):
        for y in (mount_inset, height - mount_inset):
            p.circle((x, y), mount_d / 2, "HOLES")
    return p


def vent_plate(width=240.0, height=140.0, corner_r=4.0, margin=15.0, pitch=10.0, hole_d=6.0):
    """A perforated vent plate: 6 mm holes on a square 10 mm pitch over the plate less a 15 mm
    margin (as many as lie whole in it, centred); rounded corners; exploded to LINE/ARC."""
    p = Part(explode=True)
    p.poly(rrect(0, 0, width, height, corner_r))
    nx, ny = _fit(width - 2 * margin, hole_d, pitch), _fit(height - 2 * margin, hole_d, pitch)
    for i in range(nx):
        for j in range(ny):
            p.circle((width / 2 + (i - (nx - 1) / 2) * pitch, height / 2 + (j - (ny - 1) / 2) * pitch),
                     hole_d / 2)
    return p


def mixed_grid(width=120.0, height=100.0, cols=4, rows=4, pitch=20.0, hole_d=5.0, inner_d=8.0,
               corner_inset=6.0, corner_d=3.5):
    """A 4 x 4 grid on a 20 mm pitch, centred, its inner 2 x 2 holes 8 mm and the ring round
    them 5 mm; four 3.5 mm corner holes.  Holes on `HOLES`, the plate on `PLATE`."""
    p = Part()
    p.poly(rect(0, 0, width, height), "PLATE")
    for i in range(cols):
        for j in range(rows):
            inner = 0 < i < cols - 1 and 0 < j < rows - 1
            p.circle((width / 2 + (i - (cols - 1) / 2) * pitch, height / 2 + (j - (rows - 1) / 2) * pitch),
                     (inner_d if inner else hole_d) / 2, "HOLES")
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, height - corner_inset):
            p.circle((x, y), corner_d / 2, "HOLES")
    return p


def checker_strip(width=150.0, height=50.0, cols=6, rows=2, first_x=12.0, pitch=15.0, hole_d=6.0,
                  small_d=4.0):
    """A 6 x 2 checkerboard of 6 mm and 4 mm holes on a 15 mm pitch, its first column 12 mm from
    the left edge, the rows centred on the height, the lower left hole 6 mm; an SVG."""
    p = Part(fmt="svg")
    p.poly(rect(0, 0, width, height))
    for i in range(cols):
        for j in range(rows):
            d = hole_d if (i + j) % 2 == 0 else small_d
            p.circle((first_x + i * pitch, height / 2 + (j - (rows - 1) / 2) * pitch), d / 2)
    return p


def edge_holes(width=150.0, height=80.0, big_x=22.0, big_d=10.0, small_from_right=18.0,
               small_from_top=15.0, small_d=6.0):
    """A plate with two single holes: a 10 mm one big_x from the left edge on the centre line,
    a 6 mm one 18 mm from the right edge and 15 mm from the top.  Holes on `HOLES`."""
    p = Part()
    p.poly(rect(0, 0, width, height), "OUTLINE")
    p.circle((big_x, height / 2), big_d / 2, "HOLES")
    p.circle((width - small_from_right, height - small_from_top), small_d / 2, "HOLES")
    return p


def post_strip(width=30.0, height=160.0, low_y=15.0, top_from_top=20.0, hole_d=5.0):
    """An upright strip with two 5 mm holes on its vertical centre line, one 15 mm from the
    bottom, the other 20 mm from the top (not mirrored)."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    p.circle((width / 2, low_y), hole_d / 2)
    p.circle((width / 2, height - top_from_top), hole_d / 2)
    return p


def terminal_block(width=110.0, height=30.0, n=10, pitch=7.5, first_x=10.0, row_y=18.0, hole_d=3.0,
                   mount_from_right=8.0, mount_y=8.0, mount_d=4.5):
    """A connector strip: ten 3 mm terminal holes on a 7.5 mm pitch, the first 10 mm from the
    left edge, 18 mm up; a 4.5 mm mounting hole 8 mm from the right edge, 8 mm up."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for i in range(n):
        p.circle((first_x + i * pitch, row_y), hole_d / 2)
    p.circle((width - mount_from_right, mount_y), mount_d / 2)
    return p


def pipe_flange(diameter=150.0, bore_d=60.0, pcd=115.0, n=8, hole_d=14.0, angle=22.5):
    """A round pipe flange: eight 14 mm holes on a 115 mm circle, the first at 22.5 deg (half a
    pitch off the axes), a 60 mm bore; origin at the centre; exploded to LINE/ARC."""
    p = Part(explode=True)
    r = diameter / 2
    p.poly([(r, 0, 1), (-r, 0, 1)])
    p.circle((0, 0), bore_d / 2)
    for i in range(n):
        a = math.radians(angle + i * 360 / n)
        p.circle((pcd / 2 * math.cos(a), pcd / 2 * math.sin(a)), hole_d / 2)
    return p


def bearing_plate(width=90.0, bore_d=28.0, pcd=48.0, n=3, hole_d=5.5, angle=90.0, corner_inset=7.0,
                  corner_d=4.5):
    """A square plate for a 3-bolt bearing: a 28 mm bore in the middle, three 5.5 mm holes on a
    48 mm circle, the first at the top, four 4.5 mm corner holes 7 mm in; an SVG (the bolt
    holes' centres to 6 decimals, as the exporter rounds them)."""
    p = Part(fmt="svg")
    p.poly(rect(0, 0, width, width))
    c = width / 2
    p.circle((c, c), bore_d / 2)
    for i in range(n):
        a = math.radians(angle + i * 360 / n)
        p.circle((c + pcd / 2 * math.cos(a), c + pcd / 2 * math.sin(a)), hole_d / 2)
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, width - corner_inset):
            p.circle((x, y), corner_d / 2)
    return p


def vent_slots(width=180.0, height=80.0, n=7, pitch=12.0, slot_len=40.0, slot_w=5.0, mount_x=8.0,
               mount_d=4.0):
    """A panel with seven upright cooling slots, 40 x 5 mm on a 12 mm pitch, centred; two 4 mm
    mounting holes on the centre line, 8 mm from the left and the right edges."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for i in range(n):
        p.poly(slot(width / 2 + (i - (n - 1) / 2) * pitch, height / 2, slot_len, slot_w, vertical=True))
    for x in (mount_x, width - mount_x):
        p.circle((x, height / 2), mount_d / 2)
    return p


def spacer_pair(w1=40.0, w2=50.0, height=30.0, gap=12.0, hole1_d=6.0, hole2_d=8.0):
    """Two spacer plates side by side on one layer, their bottoms in line, gap apart: the left
    one 40 x 30 with a 6 mm hole in its middle, the right one 50 x 30 with an 8 mm hole."""
    p = Part()
    p.poly(rect(0, 0, w1, height))
    p.circle((w1 / 2, height / 2), hole1_d / 2)
    x2 = w1 + gap
    p.poly(rect(x2, 0, w2, height))
    p.circle((x2 + w2 / 2, height / 2), hole2_d / 2)
    return p


def t_bracket(width=100.0, height=60.0, stem=20.0, wall=15.0, hole_in=12.0, hole_d=5.0):
    """An upright T bracket: a bar `wall` thick across the top, a stem `stem` wide centred under
    it; a 5 mm hole in the bar 12 mm from each end, midway through the bar; exploded to LINE."""
    p = Part(explode=True)
    a, b, t = (width - stem) / 2, (width + stem) / 2, height - wall
    p.poly([(a, 0, 0), (b, 0, 0), (b, t, 0), (width, t, 0), (width, height, 0), (0, height, 0),
            (0, t, 0), (a, t, 0)])
    for x in (hole_in, width - hole_in):
        p.circle((x, height - wall / 2), hole_d / 2)
    return p


def stacked_strips(w1=150.0, h1=20.0, w2=120.0, h2=30.0, gap=8.0, hole_in=10.0, hole_d=5.0,
                   big_d=10.0):
    """Two strips stacked, their left ends in line, gap apart: the lower 150 x 20 with a 5 mm
    hole 10 mm from each end, the upper 120 x 30 with a 10 mm hole in its middle."""
    p = Part()
    p.poly(rect(0, 0, w1, h1))
    for x in (hole_in, w1 - hole_in):
        p.circle((x, h1 / 2), hole_d / 2)
    y2 = h1 + gap
    p.poly(rect(0, y2, w2, h2))
    p.circle((w2 / 2, y2 + h2 / 2), big_d / 2)
    return p


def jack_panel(width=200.0, height=80.0, corner_r=3.0, inset=5.0, corner_d=3.2, n=4, pitch=20.0,
               jack_y=25.0, jack_d=6.0, win_x=12.0, win_top=12.0, win_w=60.0, win_h=25.0,
               sw_from_right=15.0, sw_w=12.0, sw_h=20.0):
    """A front panel: four 3.2 mm corner holes 5 mm in, a row of four 6 mm jacks on a 20 mm
    pitch centred across, 25 mm up; a display window 60 x 25 whose left side is 12 mm from the
    left edge and top 12 mm below the top; a switch cut-out 12 x 20 whose right side is 15 mm
    from the right edge, centred on the height.  Rounded corners; an SVG (6-decimal numbers)."""
    p = Part(fmt="svg")
    p.poly(rrect(0, 0, width, height, corner_r))
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            p.circle((x, y), corner_d / 2)
    for i in range(n):
        p.circle((width / 2 + (i - (n - 1) / 2) * pitch, jack_y), jack_d / 2)
    p.poly(rect(win_x, height - win_top - win_h, win_w, win_h))
    p.poly(rect(width - sw_from_right - sw_w, height / 2 - sw_h / 2, sw_w, sw_h))
    return p


def v_comb(width=160.0, height=40.0, n=8, pitch=16.0, notch_w=8.0, depth=12.0, mount_x=10.0,
           mount_y=10.0, mount_d=4.5):
    """A cable comb with eight V notches in its top side (8 mm wide at the top, 12 mm deep) on a
    16 mm pitch, centred; two 4.5 mm mounting holes 10 mm from the ends, 10 mm up; exploded to
    LINE."""
    p = Part(explode=True)
    pts = [(0, 0, 0), (width, 0, 0), (width, height, 0)]
    for i in reversed(range(n)):
        cx = width / 2 + (i - (n - 1) / 2) * pitch
        pts += [(cx + notch_w / 2, height, 0), (cx, height - depth, 0), (cx - notch_w / 2, height, 0)]
    pts.append((0, height, 0))
    p.poly(pts)
    for x in (mount_x, width - mount_x):
        p.circle((x, mount_y), mount_d / 2)
    return p


def din_plate(width=150.0, height=60.0, slot_inset=12.0, slot_len=16.0, slot_w=5.5, n=5, pitch=25.0,
              row_y=20.0, hole_d=4.0):
    """A plate with two mounting slots lying along its length on the centre line, each centred
    12 mm from its end (mirrored), and a row of five 4 mm holes on a 25 mm pitch centred across,
    20 mm up."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for x in (slot_inset, width - slot_inset):
        p.poly(slot(x, height / 2, slot_len, slot_w))
    for i in range(n):
        p.circle((width / 2 + (i - (n - 1) / 2) * pitch, row_y), hole_d / 2)
    return p


def nema23_plate(width=150.0, height=90.0, motor_x=45.0, bore_d=38.1, spacing=47.14, hole_d=5.0,
                 mount_from_right=12.0, mount_inset=12.0, mount_d=6.0):
    """A NEMA 23 motor plate: the motor's centre 45 mm from the left edge on the centre line, its
    38.1 mm boss bore and four 5 mm screw holes 47.14 mm apart round it; two 6 mm mounting holes
    12 mm from the right edge, 12 mm from the bottom and from the top.  Holes on `HOLES`."""
    p = Part()
    p.poly(rect(0, 0, width, height), "OUTLINE")
    cy = height / 2
    p.circle((motor_x, cy), bore_d / 2, "HOLES")
    for sx in (-1, 1):
        for sy in (-1, 1):
            p.circle((motor_x + sx * spacing / 2, cy + sy * spacing / 2), hole_d / 2, "HOLES")
    for y in (mount_inset, height - mount_inset):
        p.circle((width - mount_from_right, y), mount_d / 2, "HOLES")
    return p


DRAWINGS = {f.__name__: f for f in [
    mega_plate, esp32_carrier, sensor_strip, speaker_grille, vent_plate, mixed_grid, checker_strip,
    edge_holes, post_strip, terminal_block, pipe_flange, bearing_plate, vent_slots, spacer_pair,
    t_bracket, stacked_strips, jack_panel, v_comb, din_plate, nema23_plate]}


# --------------------------------------------------------------------------- writers


def _arc_of(p, q, b):
    """Centre, radius, start and end angles (degrees, counter-clockwise) of the bulge arc p -> q."""
    theta = 4 * math.atan(b)
    dx, dy = q[0] - p[0], q[1] - p[1]
    chord = math.hypot(dx, dy)
    r = chord / (2 * math.sin(abs(theta) / 2))
    mx, my = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
    h = r * math.cos(theta / 2)          # signed distance from the chord to the centre
    nx, ny = -dy / chord, dx / chord
    s = 1 if b > 0 else -1
    cx, cy = mx + s * nx * h, my + s * ny * h
    if b < 0:
        p, q = q, p
    a0 = math.degrees(math.atan2(p[1] - cy, p[0] - cx))
    a1 = math.degrees(math.atan2(q[1] - cy, q[0] - cx))
    return (cx, cy), r, a0, a1


def primitives(part):
    """The part as ('line', p, q), ('arc', c, r, a0, a1), ('circle', c, r)."""
    out = []
    for it in part.items:
        if it[0] == "circle":
            out.append(("circle", it[2], it[3]))
            continue
        pts = it[2]
        for k, (x, y, b) in enumerate(pts):
            nx, ny, _ = pts[(k + 1) % len(pts)]
            if b == 0:
                out.append(("line", (x, y), (nx, ny)))
            else:
                out.append(("arc",) + _arc_of((x, y), (nx, ny), b))
    return out


def write_dxf(part, path):
    import ezdxf
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    layers = {it[1] for it in part.items}
    for name in layers:
        if name not in doc.layers:
            doc.layers.add(name)
    for it in part.items:
        attr = {"layer": it[1]}
        if it[0] == "circle":
            msp.add_circle(it[2], it[3], dxfattribs=attr)
        elif part.explode:
            pts = it[2]
            for k, (x, y, b) in enumerate(pts):
                nx, ny, _ = pts[(k + 1) % len(pts)]
                if b == 0:
                    msp.add_line((x, y), (nx, ny), dxfattribs=attr)
                else:
                    c, r, a0, a1 = _arc_of((x, y), (nx, ny), b)
                    msp.add_arc(c, r, a0, a1, dxfattribs=attr)
        else:
            msp.add_lwpolyline([(x, y, 0, 0, b) for x, y, b in it[2]], format="xyseb",
                               close=True, dxfattribs=attr)
    doc.saveas(path)


def write_svg(part, path):
    import svgwrite
    xs, ys = [], []
    for pr in primitives(part):
        if pr[0] == "circle":
            xs += [pr[1][0] - pr[2], pr[1][0] + pr[2]]
            ys += [pr[1][1] - pr[2], pr[1][1] + pr[2]]
        elif pr[0] == "line":
            xs += [pr[1][0], pr[2][0]]
            ys += [pr[1][1], pr[2][1]]
        else:
            xs += [pr[1][0] - pr[2], pr[1][0] + pr[2]]
            ys += [pr[1][1] - pr[2], pr[1][1] + pr[2]]
    x0, x1, y0, y1 = min(xs) - 5, max(xs) + 5, min(ys) - 5, max(ys) + 5
    w, h = x1 - x0, y1 - y0
    dwg = svgwrite.Drawing(path, size=(f"{w:g}mm", f"{h:g}mm"), viewBox=f"{x0:g} {-y1:g} {w:g} {h:g}")
    g = dwg.g(transform="scale(1,-1)", fill="none", stroke="black", stroke_width=0.1)
    for it in part.items:
        if it[0] == "circle":
            g.add(dwg.circle(center=(round(it[2][0], 6), round(it[2][1], 6)), r=it[3]))
            continue
        pts = it[2]
        d = [f"M {pts[0][0]:.6f} {pts[0][1]:.6f}"]
        for k, (x, y, b) in enumerate(pts):
            nx, ny, _ = pts[(k + 1) % len(pts)]
            if b == 0:
                d.append(f"L {nx:.6f} {ny:.6f}")
            else:
                c, r, a0, a1 = _arc_of((x, y), (nx, ny), b)
                theta = 4 * math.atan(b)
                large = 1 if abs(theta) > math.pi else 0
                sweep = 1 if b > 0 else 0
                d.append(f"A {r:.6f} {r:.6f} 0 {large} {sweep} {nx:.6f} {ny:.6f}")
        d.append("Z")
        g.add(dwg.path(d=" ".join(d)))
    dwg.add(g)
    dwg.save()


def write(part, stem):
    """Write the part as its maker exports it; the path written."""
    if part.fmt == "svg":
        write_svg(part, stem + ".svg")
        return stem + ".svg"
    write_dxf(part, stem + ".dxf")
    return stem + ".dxf"
