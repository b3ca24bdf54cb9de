"""Makers' drawings for issue 114's measurement (brief h23-makers).

Each drawing is a function of its numbers (keyword arguments with the drawn values as defaults)
returning a Part: closed outlines (polylines with bulges, as a CAD program's LWPOLYLINE) and
circles, each on a layer, in mm, with the origin where a maker puts it.  `write_dxf` writes it
as plain LINE/ARC/CIRCLE/LWPOLYLINE (ezdxf); `write_svg` as an svgwrite drawing in a mm viewBox
whose y axis is turned by a group.  Written without reading the inference (aidl_lang/), its
tests or earlier drawings: only docs/import.md and issue 114's list (the Part, the writers and
the format of a drawing function are issue103b's makers.py's, reused; its drawings are not).
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
# --------------------------------------------------------------------------- the drawings
# Each returns a Part; its keyword arguments are the numbers a maker dimensions.  Written from
# issue 114's list and docs/import.md alone, before any of them was imported (brief h23-makers).


def _fit(field, d, pitch):
    """How many holes of diameter d on a pitch lie whole in a field `field` long."""
    return int(math.floor((field - d) / pitch + 1e-9)) + 1


PI = [(0.0, 0.0), (58.0, 0.0), (0.0, 49.0), (58.0, 49.0)]      # a Raspberry Pi's four holes


def pi_plate(width=150.0, height=100.0, board_x=20.0, board_y=15.0, hole_d=2.7, corner_inset=5.0,
             corner_d=3.4):
    """A base plate for a Raspberry Pi: the Pi's four M2.5 holes, the lower left one board_x from
    the left edge and board_y from the bottom; four corner holes.  Holes on layer HOLES."""
    p = Part()
    p.poly(rect(0, 0, width, height), "OUTLINE")
    for x, y in PI:
        p.circle((board_x + x, board_y + y), hole_d / 2, "HOLES")
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, height - corner_inset):
            p.circle((x, y), corner_d / 2, "HOLES")
    return p


UNO = [(14.0, 2.5), (15.3, 50.7), (66.1, 7.6), (66.1, 35.5)]   # an Arduino Uno's holes (datasheet)


def arduino_plate(width=240.0, height=100.0, board_x=15.0, board_y=10.0, hole_d=3.2, corner_r=4.0,
                  corner_inset=6.0, corner_d=4.0):
    """A long mounting plate with an Arduino Uno at its left end (board origin board_x, board_y
    from the lower left corner), rounded corners, four corner holes; exploded to LINE/ARC."""
    p = Part(explode=True)
    p.poly(rrect(0, 0, width, height, corner_r))
    for x, y in UNO:
        p.circle((board_x + x, board_y + y), hole_d / 2)
    for x in (corner_inset, width - corner_inset):
        for y in (corner_inset, height - corner_inset):
            p.circle((x, y), corner_d / 2)
    return p


def fan_panel(size=120.0, mount_inset=7.5, mount_d=4.3, margin=15.0, pitch=6.0, hole_d=4.5):
    """A 120 mm fan's panel: four mounting holes 105 mm apart and a square-set field of holes
    filling the panel less a margin (as many as lie whole in it, centred)."""
    p = Part()
    p.poly(rect(0, 0, size, size))
    for x in (mount_inset, size - mount_inset):
        for y in (mount_inset, size - mount_inset):
            p.circle((x, y), mount_d / 2)
    n = _fit(size - 2 * margin, hole_d, pitch)
    for i in range(n):
        for j in range(n):
            p.circle((size / 2 + (i - (n - 1) / 2) * pitch, size / 2 + (j - (n - 1) / 2) * pitch),
                     hole_d / 2)
    return p


def perf_plate(width=200.0, height=150.0, margin=12.0, pitch=10.0, hole_d=5.0, corner_r=5.0):
    """A perforated plate: round holes on a square pitch over the plate less a 12 mm margin, as
    many as lie whole in it, centred; rounded corners; exploded to LINE/ARC."""
    p = Part(explode=True)
    p.poly(rrect(0, 0, width, height, corner_r))
    nx, ny = _fit(width - 2 * margin, hole_d, pitch), _fit(height - 2 * margin, hole_d, pitch)
    for i in range(nx):
        for j in range(ny):
            p.circle((width / 2 + (i - (nx - 1) / 2) * pitch, height / 2 + (j - (ny - 1) / 2) * pitch),
                     hole_d / 2)
    return p


def checker_plate(width=160.0, height=110.0, cols=5, rows=4, pitch=25.0, hole_d=8.0, small_d=5.0):
    """A 5 x 4 checkerboard of 8 mm and 5 mm holes on a 25 mm pitch, centred; the lower left
    hole 8 mm.  Holes on layer HOLES."""
    p = Part()
    p.poly(rect(0, 0, width, height), "PLATE")
    for i in range(cols):
        for j in range(rows):
            d = hole_d if (i + j) % 2 == 0 else small_d
            p.circle((width / 2 + (i - (cols - 1) / 2) * pitch, height / 2 + (j - (rows - 1) / 2) * pitch),
                     d / 2, "HOLES")
    return p


def mixed_lattice(width=130.0, height=70.0, cols=5, rows=3, first_x=12.0, pitch_x=18.0, pitch_y=15.0,
                  hole_d=6.0, small_d=4.0):
    """A 5 x 3 grid, its middle row 4 mm holes, the others 6 mm; the first column 12 mm from the
    left edge, the rows centred on the height; an SVG."""
    p = Part(fmt="svg")
    p.poly(rect(0, 0, width, height))
    for i in range(cols):
        for j in range(rows):
            d = small_d if j == (rows - 1) // 2 else hole_d
            p.circle((first_x + i * pitch_x, height / 2 + (j - (rows - 1) / 2) * pitch_y), d / 2)
    return p


def asym_pair(width=140.0, height=40.0, left_x=25.0, right_from_right=25.03, hole_d=6.0):
    """A strip with two holes on its centre line: one 25 mm from the left edge, the other 25.03
    from the right (drawn apart, not mirrored); an SVG."""
    p = Part(fmt="svg")
    p.poly(rect(0, 0, width, height))
    p.circle((left_x, height / 2), hole_d / 2)
    p.circle((width - right_from_right, height / 2), hole_d / 2)
    return p


def mirror_slots(width=90.0, height=120.0, inset=12.0, slot_len=30.0, slot_w=8.0, hole_d=20.0):
    """A plate with two mounting slots, one 12 mm from the bottom, one 12 mm from the top, both
    centred across, and a centre hole."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for y in (inset, height - inset):
        p.poly(slot(width / 2, y, slot_len, slot_w))
    p.circle((width / 2, height / 2), hole_d / 2)
    return p


def bolt_circle_svg(diameter=110.0, bore_d=40.0, pcd=80.0, n=5, hole_d=6.6):
    """A round flange of five bolt holes, the first at the top; origin at the centre; an SVG."""
    p = Part(fmt="svg")
    r = diameter / 2
    p.poly([(r, 0, 1), (-r, 0, 1)])
    p.circle((0, 0), bore_d / 2)
    for i in range(n):
        a = math.radians(90 + i * 360 / n)
        p.circle((pcd / 2 * math.cos(a), pcd / 2 * math.sin(a)), hole_d / 2)
    return p


def flange_square(width=100.0, corner_r=10.0, bore_d=50.0, pcd=80.0, n=4, hole_d=6.6, angle=45.0):
    """A square flange, origin at its centre, rounded corners, a bore and four holes on a bolt
    circle at 45 degrees; exploded to LINE/ARC."""
    p = Part(explode=True)
    p.poly(rrect(-width / 2, -width / 2, width, width, corner_r))
    p.circle((0, 0), bore_d / 2)
    for i in range(n):
        a = math.radians(angle + i * 360 / n)
        p.circle((pcd / 2 * math.cos(a), pcd / 2 * math.sin(a)), hole_d / 2)
    return p


def slotted_panel(width=160.0, height=60.0, n=5, pitch=24.0, slot_len=30.0, slot_w=6.0,
                  mount_x=8.0, mount_d=5.0):
    """A panel with a row of five upright slots centred on it and two mounting holes 8 mm from
    the left and right edges on the centre line.  Slots and holes on layer HOLES."""
    p = Part()
    p.poly(rect(0, 0, width, height), "PANEL")
    for i in range(n):
        p.poly(slot(width / 2 + (i - (n - 1) / 2) * pitch, height / 2, slot_len, slot_w, vertical=True),
               "HOLES")
    for x in (mount_x, width - mount_x):
        p.circle((x, height / 2), mount_d / 2, "HOLES")
    return p


def _ell(x0, leg, height, wall, flip=False):
    """An L profile: its outer corner at (x0, 0) (the far right one when flipped), a foot `leg`
    long along x and an upright `height` tall, both `wall` thick."""
    if not flip:
        return [(x0, 0, 0), (x0 + leg, 0, 0), (x0 + leg, wall, 0), (x0 + wall, wall, 0),
                (x0 + wall, height, 0), (x0, height, 0)]
    return [(x0 - leg, 0, 0), (x0, 0, 0), (x0, height, 0), (x0 - wall, height, 0),
            (x0 - wall, wall, 0), (x0 - leg, wall, 0)]


def l_brackets_pair(leg1=50.0, leg2=60.0, height=40.0, wall=8.0, gap=15.0):
    """Two L brackets side by side in one laser file, the second 60 mm long, 15 mm apart; exploded
    to LINE/ARC."""
    p = Part(explode=True)
    p.poly(_ell(0, leg1, height, wall))
    p.poly(_ell(leg1 + gap, leg2, height, wall))
    return p


def mirrored_l(leg=50.0, height=40.0, wall=6.0, gap=10.0):
    """An L bracket and its mirror image (the left and the right hand one), 10 mm apart."""
    p = Part()
    p.poly(_ell(0, leg, height, wall))
    p.poly(_ell(2 * leg + gap, leg, height, wall, flip=True))
    return p


def stacked_plates(w1=100.0, h1=30.0, w2=90.0, h2=40.0, w3=70.0, h3=25.0, gap1=6.0, gap2=10.0,
                   d1=8.0, d2=6.0, d3=5.0):
    """Three plates stacked one above the other (a nesting for the laser), their left edges in
    line, each a hole at its centre; origin at the lowest one's lower left corner."""
    p = Part()
    y = 0.0
    for w, h, d, g in ((w1, h1, d1, gap1), (w2, h2, d2, gap2), (w3, h3, d3, 0.0)):
        p.poly(rect(0, y, w, h))
        p.circle((w / 2, y + h / 2), d / 2)
        y += h + g
    return p


def front_panel(width=180.0, height=90.0, corner_r=3.0, inset=5.0, corner_d=3.2, win_x=10.0,
                win_top=15.0, win_w=60.0, win_h=30.0, knob_from_right=20.0, knob_pitch=30.0,
                knob_n=3, knob_y=25.0, knob_d=7.0):
    """A front panel: four corner holes, a display window 10 mm from the left edge and 15 mm from
    the top, three knob holes in a row, the last 20 mm from the right edge.  Holes on HOLES."""
    p = Part()
    p.poly(rrect(0, 0, width, height, corner_r), "PANEL")
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            p.circle((x, y), corner_d / 2, "HOLES")
    p.poly(rect(win_x, height - win_top - win_h, win_w, win_h), "HOLES")
    for i in range(knob_n):
        p.circle((width - knob_from_right - i * knob_pitch, knob_y), knob_d / 2, "HOLES")
    return p


def cable_comb2(width=150.0, height=40.0, n=6, pitch=20.0, notch_w=10.0, depth=15.0, mount_x=10.0,
                mount_y=10.0, mount_d=4.5):
    """A cable comb: six round-bottomed notches in the top edge, centred, and two mounting holes;
    exploded to LINE/ARC."""
    p = Part(explode=True)
    pts = [(0, 0, 0), (width, 0, 0), (width, height, 0)]
    r = notch_w / 2
    for i in reversed(range(n)):
        cx = width / 2 + (i - (n - 1) / 2) * pitch
        pts += [(cx + r, height, 0), (cx + r, height - depth + r, -1), (cx - r, height - depth + r, 0),
                (cx - r, height, 0)]
    pts.append((0, height, 0))
    p.poly(pts)
    for x in (mount_x, width - mount_x):
        p.circle((x, mount_y), mount_d / 2)
    return p


def terminal_strip(width=130.0, height=25.0, n=10, pitch=9.0, first_x=10.0, hole_d=3.5,
                   mount_from_right=12.0, mount_d=5.0):
    """A terminal strip: ten holes on a 9 mm pitch, the first 10 mm from the left edge, on the
    centre line, and a mounting hole 12 mm from the right edge.  Holes on layer HOLES."""
    p = Part()
    p.poly(rect(0, 0, width, height), "STRIP")
    for i in range(n):
        p.circle((first_x + i * pitch, height / 2), hole_d / 2, "HOLES")
    p.circle((width - mount_from_right, height / 2), mount_d / 2, "HOLES")
    return p


def lid_svg(width=120.0, height=80.0, corner_r=6.0, inset=6.0, hole_d=3.4, win_w=40.0, win_h=20.0):
    """An enclosure lid: rounded corners, four corner screw holes, a centred window; an SVG."""
    p = Part(fmt="svg")
    p.poly(rrect(0, 0, width, height, corner_r))
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            p.circle((x, y), hole_d / 2)
    p.poly(rect(width / 2 - win_w / 2, height / 2 - win_h / 2, win_w, win_h))
    return p


def motor_far(width=110.0, height=70.0, motor_from_right=35.0, bore_d=22.0, spacing=31.0,
              screw_d=3.4, mount_x=10.0, mount_inset=15.0, mount_d=5.0):
    """A NEMA 17 plate: the motor 35 mm from the right edge on the centre line (its bore and four
    screw holes), two mounting holes 10 mm from the left edge, 15 mm from the top and bottom."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    cx, cy = width - motor_from_right, height / 2
    p.circle((cx, cy), bore_d / 2)
    for sx in (-1, 1):
        for sy in (-1, 1):
            p.circle((cx + sx * spacing / 2, cy + sy * spacing / 2), screw_d / 2)
    for y in (mount_inset, height - mount_inset):
        p.circle((mount_x, y), mount_d / 2)
    return p


SENSOR = [(0.0, 0.0), (20.3, 0.0), (8.0, 15.2)]     # a sensor board's holes, from its upper right one


def sensor_corner(width=100.0, height=80.0, from_right=12.0, from_top=10.0, hole_d=2.5, inset=5.0,
                  corner_d=4.0):
    """A plate with a sensor board by its upper right corner (its upper right hole 12 mm from the
    right edge, 10 mm from the top, the others to its left and below) and four corner holes."""
    p = Part()
    p.poly(rect(0, 0, width, height))
    for dx, dy in SENSOR:
        p.circle((width - from_right - dx, height - from_top - dy), hole_d / 2)
    for x in (inset, width - inset):
        for y in (inset, height - inset):
            p.circle((x, y), corner_d / 2)
    return p


DRAWINGS = {f.__name__: f for f in [
    pi_plate, arduino_plate, fan_panel, perf_plate, checker_plate, mixed_lattice, asym_pair,
    mirror_slots, bolt_circle_svg, flange_square, slotted_panel, l_brackets_pair, mirrored_l,
    stacked_plates, front_panel, cable_comb2, terminal_strip, lid_svg, motor_far, sensor_corner]}


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
