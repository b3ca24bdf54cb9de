"""Makers' drawings for issue 103's measurement (brief h20-makers).

Each drawing is a function of its numbers (keyword arguments with the drawn values as defaults)
returning a Part: closed outlines (polylines with bulges, as a CAD program's LWPOLYLINE) and
circles, each on a layer, in mm, with the origin where a maker puts it.  `write_dxf` writes it
as plain LINE/ARC/CIRCLE/LWPOLYLINE (ezdxf); `write_svg` as an svgwrite drawing in a mm viewBox
whose y axis is turned by a group.  Written without reading the inference (aidl_lang/), its
tests or earlier drawings: only docs/import.md.
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
# Each returns a Part; its keyword arguments are the numbers a maker dimensions.


def motor_mount(width=80.0, height=60.0, motor_from_right=30.0, bore_d=22.0, spacing=31.0,
                hole_d=3.4, slot_inset=10.0, slot_len=16.0, slot_w=5.5, slot_spacing=36.0):
    """A NEMA 17 mount: the motor dimensioned from the plate's right (far) edge, two vertical
    mounting slots by the left edge.  Origin at the lower left corner; holes on layer HOLES."""
    p = Part()
    p.poly(rect(0, 0, width, height), "OUTLINE")
    cx, cy = width - motor_from_right, height / 2
    p.circle((cx, cy), bore_d / 2, "HOLES")
    for sx in (-1, 1):
        for sy in (-1, 1):
            p.circle((cx + sx * spacing / 2, cy + sy * spacing / 2), hole_d / 2, "HOLES")
    for sy in (-1, 1):
        p.poly(slot(slot_inset, cy + sy * slot_spacing / 2, slot_len, slot_w, vertical=True), "HOLES")
    return p


def fan_grille(size=50.0, mount_spacing=40.0, mount_d=4.3, hole_d=3.0, pitch=4.5, field_d=36.0,
               corner_r=3.0):
    """A 50 mm fan's grille plate: square-set round holes clipped to a round field, four mounting
    holes at the corners.  Origin at the plate's centre (a maker centres a fan)."""
    p = Part()
    p.poly(rrect(-size / 2, -size / 2, size, size, corner_r))
    for sx in (-1, 1):
        for sy in (-1, 1):
            p.circle((sx * mount_spacing / 2, sy * mount_spacing / 2), mount_d / 2)
    k = int(field_d / pitch) + 1
    for j in range(-k, k + 1):
        for i in range(-k, k + 1):
            x, y = i * pitch, j * pitch
            if math.hypot(x, y) + hole_d / 2 <= field_d / 2 + 1e-7:
                p.circle((x, y), hole_d / 2)
    return p


def perforated_plate(width=120.0, height=80.0, corner_r=5.0, cols=8, rows=5, pitch=10.0,
                     hole_d=5.0):
    """A perforated plate, a grid of holes centred on it; SVG (svgwrite), origin lower left."""
    p = Part(fmt="svg")
    p.poly(rrect(0, 0, width, height, corner_r))
    for j in range(rows):
        for i in range(cols):
            p.circle((width / 2 + (i - (cols - 1) / 2) * pitch,
                      height / 2 + (j - (rows - 1) / 2) * pitch), hole_d / 2)
    return p


def flange(diameter=100.0, bore_d=40.0, pcd=75.0, n=4, hole_d=9.0, angle=45.0):
    """A round flange: four bolt holes at 45 degrees (the drawn angle), a bore.  Origin at the
    centre; outline as ARCs and LINEs exploded (two half arcs)."""
    p = Part(explode=True)
    r = diameter / 2
    p.poly([(r, 0, 1), (-r, 0, 1)])
    p.circle((0, 0), bore_d / 2)
    for i in range(n):
        a = math.radians(angle + i * 360 / n)
        p.circle((pcd / 2 * math.cos(a), pcd / 2 * math.sin(a)), hole_d / 2)
    return p


def bolt_plate(width=100.0, height=100.0, bore_d=30.0, pcd=60.0, n=5, hole_d=6.6, corner_r=6.0):
    """A square plate with a bolt circle of five, the first hole at the top; origin lower left."""
    p = Part()
    p.poly(rrect(0, 0, width, height, corner_r))
    cx, cy = width / 2, height / 2
    p.circle((cx, cy), bore_d / 2)
    for i in range(n):
        a = math.radians(90 + i * 360 / n)
        p.circle((cx + pcd / 2 * math.cos(a), cy + pcd / 2 * math.sin(a)), hole_d / 2)
    return p


def cable_comb(width=150.0, height=40.0, n=7, pitch=18.0, notch_w=8.0, depth=20.0, hole_d=5.0,
               hole_inset=10.0):
    """A cable comb: n square notches in the top side, centred; two mounting holes by the bottom
    edge.  SVG (svgwrite), origin lower left."""
    p = Part(fmt="svg")
    pts = [(0, 0, 0), (width, 0, 0), (width, height, 0)]
    for i in reversed(range(n)):
        x = width / 2 + (i - (n - 1) / 2) * pitch
        pts += [(x + notch_w / 2, height, 0), (x + notch_w / 2, height - depth, 0),
                (x - notch_w / 2, height - depth, 0), (x - notch_w / 2, height, 0)]
    pts.append((0, height, 0))
    p.poly(pts)
    for sx in (-1, 1):
        p.circle((width / 2 + sx * (width / 2 - hole_inset), hole_inset), hole_d / 2)
    return p


def bracket_pair(w1=60.0, w2=60.0, height=40.0, gap=10.0, hole_d=5.0, hole_spacing=30.0,
                 w2_hole_d=8.0):
    """Two brackets drawn side by side in one file (one laser job): the left one with two holes
    on its centre line, the right one with one centre hole.  Origin at the left one's corner."""
    p = Part()
    p.poly(rect(0, 0, w1, height))
    for s in (-1, 1):
        p.circle((w1 / 2 + s * hole_spacing / 2, height / 2), hole_d / 2)
    x2 = w1 + gap
    p.poly(rect(x2, 0, w2, height))
    p.circle((x2 + w2 / 2, height / 2), w2_hole_d / 2)
    return p


UNO = [(14.0, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5)]   # Arduino Uno's holes (mm)


def uno_panel(width=200.0, height=100.0, board_x=10.0, board_y=20.0, board_hole_d=3.2,
              corner_inset=5.0, corner_d=4.2, jack_d=12.0, jack_from_right=25.0):
    """An electronics panel: an Arduino Uno's holes offset (board_x, board_y) from the lower
    left corner, four corner holes, a jack dimensioned from the right edge.  Holes on layer
    Drill, outline on Edge; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height), "Edge")
    for x, y in UNO:
        p.circle((board_x + x, board_y + y), board_hole_d / 2, "Drill")
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, height - corner_inset):
            p.circle((x, y), corner_d / 2, "Drill")
    p.circle((width - jack_from_right, height / 2 + 20), jack_d / 2, "Drill")
    return p


def corner_plate(width=100.0, height=60.0, inset=10.0, hole_d=4.0, odd_d=4.4):
    """Four corner holes, the upper right one drilled 4.4 mm; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            odd = x > width / 2 and y > height / 2
            p.circle((x, y), (odd_d if odd else hole_d) / 2)
    return p


def gap_grid(width=150.0, height=90.0, cols=4, rows=3, pitch=30.0, hole_d=6.0, gap=(2, 1)):
    """A 4 x 3 grid of holes centred on the plate with one hole (column 2, row 1 from the lower
    left, counting from 0) left out; origin lower left; holes on layer HOLES."""
    p = Part()
    p.poly(rect(0, 0, width, height), "PLATE")
    for j in range(rows):
        for i in range(cols):
            if (i, j) == tuple(gap):
                continue
            p.circle((width / 2 + (i - (cols - 1) / 2) * pitch,
                      height / 2 + (j - (rows - 1) / 2) * pitch), hole_d / 2, "HOLES")
    return p


def slotted_plate(width=140.0, height=50.0, n=4, pitch=25.0, first_x=20.0, slot_len=20.0,
                  slot_w=6.0, hole_d=5.0):
    """A row of vertical slots, its first slot 20 mm in from the left edge (an end member within
    1.5 pitches of its edge), and a hole by the right edge; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for i in range(n):
        p.poly(slot(first_x + i * pitch, height / 2, slot_len, slot_w, vertical=True))
    p.circle((width - 12, height / 2), hole_d / 2)
    return p


def rounded_plate(width=90.0, height=50.0, corner_r=8.0, n=3, pitch=20.0, hole_d=6.0):
    """A rounded plate drawn about its centre (origin at the centre), a row of three holes on its
    centre line.  SVG (svgwrite)."""
    p = Part(fmt="svg")
    p.poly(rrect(-width / 2, -height / 2, width, height, corner_r))
    for i in range(n):
        p.circle(((i - (n - 1) / 2) * pitch, 0), hole_d / 2)
    return p


CAD_OFF = [0.0, 0.02, -0.03, 0.01, 0.04, -0.02]   # each hole's CAD rounding off its node (x)


def cad_row(width=150.0, height=40.0, n=6, pitch=22.5, hole_d=4.0, corner_d=3.0, inset=6.0):
    """A row of six holes centred on the plate whose x a CAD program rounded 0.01-0.04 mm off the
    pitch, four small corner holes; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for i in range(n):
        x = width / 2 + (i - (n - 1) / 2) * pitch + CAD_OFF[i % len(CAD_OFF)]
        p.circle((round(x, 4), height / 2), hole_d / 2)
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            p.circle((x, y), corner_d / 2)
    return p


def far_edge_bracket(width=100.0, height=50.0, hole_from_right=12.0, hole_spacing=26.0,
                     hole_d=5.5, slot_from_right=40.0, slot_len=22.0, slot_w=6.0, left_hole_d=8.0):
    """A bracket dimensioned from its right (far) edge: two holes 12 mm in and a horizontal slot
    40 mm in (its centre); a single larger hole by the left edge; origin lower left.  Exploded
    to LINE/ARC as some CAD exports are."""
    p = Part(explode=True)
    p.poly(rect(0, 0, width, height))
    for s in (-1, 1):
        p.circle((width - hole_from_right, height / 2 + s * hole_spacing / 2), hole_d / 2)
    p.poly(slot(width - slot_from_right, height / 2, slot_len, slot_w))
    p.circle((15, height / 2), left_hole_d / 2)
    return p


SENSOR = [(0.0, 0.0), (22.5, 0.0), (11.0, 17.0)]   # a sensor board's three holes


def sensor_panel(width=120.0, height=70.0, from_right=12.0, from_top=10.0, hole_d=2.7,
                 window_w=40.0, window_h=20.0, window_r=2.0):
    """A sensor board's three holes placed from the upper right corner (its nearest hole
    `from_right` from the right edge, `from_top` below the top of that hole set), and a display
    window on the left half; origin lower left; holes on layer HOLES."""
    p = Part()
    p.poly(rect(0, 0, width, height), "OUTLINE")
    # the set's right-most hole is SENSOR[1]; its top-most SENSOR[2]
    x0 = width - from_right - SENSOR[1][0]
    y0 = height - from_top - SENSOR[2][1]
    for x, y in SENSOR:
        p.circle((x0 + x, y0 + y), hole_d / 2, "HOLES")
    p.poly(rrect(15, height / 2 - window_h / 2, window_w, window_h, window_r), "HOLES")
    return p


def hex_vent(width=100.0, height=70.0, pitch=8.0, hole_d=6.0, field_d=50.0, corner_inset=6.0,
             corner_d=3.5):
    """A hex-set vent of round holes clipped to a round field at the plate's centre, four corner
    holes; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    cx, cy = width / 2, height / 2
    dy = pitch * math.sqrt(3) / 2
    k = int(field_d / dy) + 1
    for j in range(-k, k + 1):
        for i in range(-k - 1, k + 2):
            x = (i + (0.5 if j % 2 else 0.0)) * pitch
            y = j * dy
            if math.hypot(x, y) + hole_d / 2 <= field_d / 2 + 1e-7:
                p.circle((cx + x, cy + y), hole_d / 2)
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, height - corner_inset):
            p.circle((x, y), corner_d / 2)
    return p


def mirrored_brackets(leg_x=50.0, leg_y=40.0, wall=8.0, hole_d=5.0, gap=10.0):
    """A left and a right L bracket, each the other's mirror image, drawn side by side (one laser
    job), a hole midway along each leg; origin at the left one's outer corner."""
    p = Part()
    left = [(0, 0), (leg_x, 0), (leg_x, wall), (wall, wall), (wall, leg_y), (0, leg_y)]
    holes = [((wall + leg_x) / 2, wall / 2), (wall / 2, (wall + leg_y) / 2)]
    m = 2 * leg_x + gap                       # x -> m - x mirrors about the line between them
    p.poly([(x, y, 0) for x, y in left])
    p.poly([(m - x, y, 0) for x, y in reversed(left)])
    for x, y in holes:
        p.circle((x, y), hole_d / 2)
        p.circle((m - x, y), hole_d / 2)
    return p

PI = [(0.0, 0.0), (58.0, 0.0), (0.0, 49.0), (58.0, 49.0)]   # a Raspberry Pi's holes about (3.5, 3.5)


def pi_panel(width=160.0, height=100.0, from_right=15.0, from_top=12.0, hole_d=2.7, corner_inset=4.0,
             corner_d=2.7, switch_d=7.0):
    """A Raspberry Pi's 58 x 49 mm hole square placed from the upper right corner (its right
    column `from_right` from the right edge, its top row `from_top` below the top), four corner
    holes of the same M2.5 size, a switch hole by the left edge; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    x0, y0 = width - from_right - 58.0, height - from_top - 49.0
    for x, y in PI:
        p.circle((x0 + x, y0 + y), hole_d / 2)
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, height - corner_inset):
            p.circle((x, y), corner_d / 2)
    p.circle((25, height / 2), switch_d / 2)
    return p


BOARD4 = [(0.0, 0.0), (40.6, 2.5), (38.1, 27.9), (2.5, 25.4)]   # a sensor board's four holes


def m3_panel(width=150.0, height=90.0, from_right=14.0, from_top=10.0, hole_d=3.2, inset=6.0,
             board_dy=None):
    """A board's four M3 holes in no pattern placed from the upper right corner, four M3 corner
    holes (one size for all: makers use M3 everywhere); origin lower left."""
    p = Part()
    p.poly(rrect(0, 0, width, height, 3.0))
    x0 = width - from_right - 40.6
    y0 = height - from_top - 27.9
    if board_dy is not None:        # the spec's reading: the board's lowest hole from the centre line
        y0 = height / 2 + board_dy
    for x, y in BOARD4:
        p.circle((x0 + x, y0 + y), hole_d / 2)
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            p.circle((x, y), hole_d / 2)
    return p


def centred_plate(width=120.0, height=70.0, corner_r=4.0, inset_x=8.0, inset_y=6.0, hole_d=3.5,
                  window_w=40.0, window_h=25.0):
    """A plate drawn about its centre (origin at the centre): corner holes 8 mm in from the sides
    and 6 mm from the top and bottom, a rectangular window in the middle."""
    p = Part()
    p.poly(rrect(-width / 2, -height / 2, width, height, corner_r))
    for sx in (-1, 1):
        for sy in (-1, 1):
            p.circle((sx * (width / 2 - inset_x), sy * (height / 2 - inset_y)), hole_d / 2)
    p.poly(rect(-window_w / 2, -window_h / 2, window_w, window_h))
    return p


def stacked_brackets(width=80.0, h1=30.0, h2=40.0, gap=8.0, hole_d=5.0, hole_spacing=60.0,
                     slot_len=30.0, slot_w=6.0):
    """Two plates drawn one above the other (one laser job): the lower one with two holes, the
    upper one with a centred slot; origin at the lower one's corner."""
    p = Part()
    p.poly(rect(0, 0, width, h1))
    for s in (-1, 1):
        p.circle((width / 2 + s * hole_spacing / 2, h1 / 2), hole_d / 2)
    y2 = h1 + gap
    p.poly(rect(0, y2, width, h2))
    p.poly(slot(width / 2, y2 + h2 / 2, slot_len, slot_w))
    return p


def slotted_motor(width=100.0, height=70.0, motor_from_right=35.0, bore_d=22.0, spacing=31.0,
                  slot_len=8.0, slot_w=3.4, hole_d=5.0, hole_spacing=50.0, hole_x=10.0):
    """A belt-tension motor plate: four horizontal slots for the motor's screws round its bore,
    the motor dimensioned from the right edge; two mounting holes by the left edge."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    cx, cy = width - motor_from_right, height / 2
    p.circle((cx, cy), bore_d / 2)
    for sx in (-1, 1):
        for sy in (-1, 1):
            p.poly(slot(cx + sx * spacing / 2, cy + sy * spacing / 2, slot_len, slot_w))
    for s in (-1, 1):
        p.circle((hole_x, cy + s * hole_spacing / 2), hole_d / 2)
    return p


def far_row(width=140.0, height=40.0, n=5, pitch=15.0, end_from_right=10.0, hole_d=4.0, odd_d=5.0,
            left_hole_d=8.0):
    """A row of five holes whose right-most one sits 10 mm from the right edge and was drilled
    5 mm (the others 4 mm), a single larger hole by the left edge; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for i in range(n):
        x = width - end_from_right - i * pitch
        p.circle((x, height / 2), (odd_d if i == 0 else hole_d) / 2)
    p.circle((15, height / 2), left_hole_d / 2)
    return p


def speaker_panel(width=180.0, height=80.0, spacing=90.0, n=5, pitch=6.0, hole_d=3.0, corner_d=3.4,
                  inset=5.0):
    """Two speaker grilles alike, 5 x 5 holes each, their centres `spacing` apart about the
    panel's centre, and four corner holes; origin lower left."""
    p = Part()
    p.poly(rrect(0, 0, width, height, 4.0))
    for s in (-1, 1):
        cx = width / 2 + s * spacing / 2
        for j in range(n):
            for i in range(n):
                p.circle((cx + (i - (n - 1) / 2) * pitch, height / 2 + (j - (n - 1) / 2) * pitch),
                         hole_d / 2)
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            p.circle((x, y), corner_d / 2)
    return p


def terminal_row(width=120.0, height=30.0, n=8, pitch=12.0, hole_d=3.5, gap=3, odd=0, odd_d=4.0):
    """A row of 8 holes centred on a strip, the fourth (turn 3) left out for a cable, the first
    (turn 0) drilled 4 mm for a locating pin; origin lower left."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for i in range(n):
        if i == gap:
            continue
        p.circle((width / 2 + (i - (n - 1) / 2) * pitch, height / 2), (odd_d if i == odd else hole_d) / 2)
    return p


def dowel_flange(diameter=90.0, bore_d=30.0, pcd=66.0, n=6, hole_d=5.5, dowel_d=6.0):
    """A round flange with six holes on a circle from the x axis, the first a 6 mm dowel hole,
    the others 5.5 mm; origin at the centre (an SVG)."""
    p = Part(fmt="svg")
    r = diameter / 2
    p.poly([(r, 0, 1), (-r, 0, 1)])
    p.circle((0, 0), bore_d / 2)
    for i in range(n):
        a = math.radians(i * 360 / n)
        p.circle((pcd / 2 * math.cos(a), pcd / 2 * math.sin(a)), (dowel_d if i == 0 else hole_d) / 2)
    return p


DRAWINGS = {f.__name__: f for f in [
    motor_mount, fan_grille, perforated_plate, flange, bolt_plate, cable_comb, bracket_pair,
    uno_panel, corner_plate, gap_grid, slotted_plate, rounded_plate, cad_row, far_edge_bracket,
    sensor_panel, hex_vent, mirrored_brackets, pi_panel, m3_panel, centred_plate,
    stacked_brackets, slotted_motor, far_row, speaker_panel, terminal_row, dowel_flange]}


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
