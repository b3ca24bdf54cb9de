"""Run the makers' edits of issue 103's measurement (brief h20-makers) and print the figure.

    cd /work/wt20-makers && .venv/bin/python data/maker_runs/issue103b/run_edits.py [--only NAME] [--png]

For each drawing of makers.py: write it (DXF or SVG), `aidl import --infer` it, and for each
edit find the param a maker picks (its name holds one of the edit's words and its value is the
number drawn; where the program reading showed a maker's pick, it is named in PICK), set the new
value with `aidl set` on a copy, `aidl render` it to DXF, re-read that with ezdxf and compare with
the drawing function's own geometry at the new value (every line, arc and circle, up to a
translation, to 0.01 mm).  Writes work/ (the files) and results.json; prints the table.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import makers  # noqa: E402

ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
AIDL = os.path.join(ROOT, ".venv", "bin", "aidl")
WORK = os.path.join(HERE, "work")
TOL = 0.01

# (drawing, kind, what the maker means, the function's argument, new value,
#  words the param's name holds, the number the drawing shows for it, the param's new value)
EDITS = [
    ("motor_mount", "width", "plate 80 -> 95 mm wide (the motor dimensioned from the right edge)",
     "width", 95, ["width"], 80, 95),
    ("motor_mount", "pitch", "NEMA 17 -> NEMA 14 hole spacing 31 -> 26", "spacing", 26,
     ["pitch", "spacing", "motor"], 31, 26),
    ("motor_mount", "hole size", "motor screw holes 3.4 -> 3 mm", "hole_d", 3.0,
     ["motor", "hole"], 3.4, 3.0),
    ("fan_grille", "hole size", "grille holes 3 -> 3.5 mm", "hole_d", 3.5, ["holes_d", "hole_d"], 3, 3.5),
    ("fan_grille", "pitch", "grille pitch 4.5 -> 5 mm", "pitch", 5, ["pitch"], 4.5, 5),
    ("fan_grille", "size", "grille field 36 -> 40 mm across", "field_d", 40, ["field"], 36, 40),
    ("perforated_plate", "pitch", "hole pitch 10 -> 12 mm", "pitch", 12, ["pitch"], 10, 12),
    ("perforated_plate", "count", "8 -> 6 columns", "cols", 6, ["_n", "cols", "count"], 8, 6),
    ("perforated_plate", "hole size", "holes 5 -> 6 mm", "hole_d", 6, ["_d"], 5, 6),
    ("flange", "count", "4 -> 6 bolt holes (the first stays at 45 deg)", "n", 6, ["_n"], 4, 6),
    ("flange", "pitch", "bolt circle 75 -> 80 mm", "pcd", 80, ["pcd"], 75, 80),
    ("flange", "hole size", "bolt holes 9 -> 11 mm", "hole_d", 11, ["_d"], 9, 11),
    ("bolt_plate", "count", "5 -> 6 bolt holes (the first stays at the top)", "n", 6, ["_n"], 5, 6),
    ("bolt_plate", "width", "plate 100 -> 120 mm wide", "width", 120, ["width"], 100, 120),
    ("bolt_plate", "pitch", "bolt circle 60 -> 70 mm", "pcd", 70, ["pcd"], 60, 70),
    ("cable_comb", "count", "7 -> 6 notches", "n", 6, ["_n"], 7, 6),
    ("cable_comb", "pitch", "notch pitch 18 -> 16 mm", "pitch", 16, ["pitch"], 18, 16),
    ("cable_comb", "size", "notches 8 -> 10 mm wide", "notch_w", 10, ["width"], 8, 10),
    ("bracket_pair", "gap", "gap between the brackets 10 -> 20 mm", "gap", 20, ["gap"], 10, 20),
    ("bracket_pair", "width", "left bracket 60 -> 70 mm wide (the right one moves along)", "w1", 70,
     ["width"], 60, 70),
    ("bracket_pair", "width", "right bracket 60 -> 50 mm wide", "w2", 50, ["width"], 60, 50),
    ("uno_panel", "width", "panel 220 -> 260 mm wide (the board stays by the left edge)", "width", 260,
     ["width"], 220, 260),
    ("uno_panel", "offset", "board 8 -> 18 mm from the left edge (the set's x from the left edge + 10)",
     "board_x", 18, ["_x", "offset"], "+", 10),
    ("uno_panel", "hole size", "board holes 3.2 -> 3 mm", "board_hole_d", 3.0, ["_d"], 3.2, 3.0),
    ("corner_plate", "width", "plate 100 -> 200 mm wide (corner holes stay 10 mm in)", "width", 200,
     ["width"], 100, 200),
    ("corner_plate", "offset", "corner inset 10 -> 8 mm", "inset", 8, ["inset"], 10, 8),
    ("corner_plate", "hole size", "corner holes 4 -> 3.5 mm (the 4.4 mm one stays)", "hole_d", 3.5,
     ["_d"], 4, 3.5),
    ("gap_grid", "width", "plate 150 -> 200 mm wide (the grid stays centred: columns 55, 85, 115, 145)",
     "width", 200, ["width"], 150, 200),
    ("gap_grid", "pitch", "grid pitch 30 -> 25 mm", "pitch", 25, ["pitch"], 30, 25),
    ("gap_grid", "count", "4 -> 5 columns (the gap stays at its turn)", "cols", 5,
     ["_n", "cols"], 4, 5),
    ("slotted_plate", "count", "4 -> 3 slots (the first stays 20 mm in)", "n", 3, ["_n"], 4, 3),
    ("slotted_plate", "pitch", "slot pitch 25 -> 28 mm", "pitch", 28, ["pitch"], 25, 28),
    ("slotted_plate", "size", "slots 20 -> 16 mm long", "slot_len", 16, ["length"], 20, 16),
    ("rounded_plate", "size", "corner radius 8 -> 5 mm", "corner_r", 5, ["radius"], 8, 5),
    ("rounded_plate", "width", "plate 50 -> 60 mm high", "height", 60, ["height"], 50, 60),
    ("rounded_plate", "pitch", "hole pitch 20 -> 24 mm", "pitch", 24, ["pitch"], 20, 24),
    ("cad_row", "pitch", "row pitch 22.5 -> 20 mm (CAD rounding kept)", "pitch", 20, ["pitch"], 22.5, 20),
    ("cad_row", "hole size", "row holes 4 -> 5 mm", "hole_d", 5, ["_d"], 4, 5),
    ("cad_row", "width", "plate 150 -> 170 mm wide", "width", 170, ["width"], 150, 170),
    ("far_edge_bracket", "width", "bracket 100 -> 130 mm wide (holes and slot follow the right edge)",
     "width", 130, ["width"], 100, 130),
    ("far_edge_bracket", "offset", "the two holes 12 -> 15 mm from the right edge",
     "hole_from_right", 15, ["_x", "inset", "offset", "from"], 12, 15),
    ("far_edge_bracket", "size", "slot 22 -> 26 mm long", "slot_len", 26, ["length"], 22, 26),
    ("sensor_panel", "width", "panel 120 -> 150 mm wide (the sensor stays by the right edge)",
     "width", 150, ["width"], 120, 150),
    ("sensor_panel", "offset", "sensor 12 -> 20 mm from the right edge (the set's x from the right edge + 8)",
     "from_right", 20, ["_x", "offset"], "+", 8),
    ("sensor_panel", "hole size", "sensor holes 2.7 -> 3 mm", "hole_d", 3.0, ["_d"], 2.7, 3.0),
    ("hex_vent", "pitch", "vent pitch 8 -> 9 mm", "pitch", 9, ["pitch"], 8, 9),
    ("hex_vent", "hole size", "vent holes 6 -> 5 mm", "hole_d", 5, ["holes_d", "hole_d"], 6, 5),
    ("hex_vent", "size", "vent field 50 -> 56 mm across", "field_d", 56, ["field"], 50, 56),
    ("mirrored_brackets", "width", "the brackets' long leg 50 -> 60 mm (both: mirror images)", "leg_x", 60,
     ["width", "leg"], 50, 60),
    ("mirrored_brackets", "size", "wall 8 -> 6 mm (both)", "wall", 6, ["wall", "thick"], 8, 6),
    ("mirrored_brackets", "gap", "gap between the brackets 10 -> 20 mm", "gap", 20, ["gap"], 10, 20),
    ("pi_panel", "width", "panel 160 -> 190 mm wide (the Pi stays by the right edge)", "width", 190,
     ["width"], 160, 190),
    ("pi_panel", "offset", "the Pi 15 -> 25 mm from the right edge", "from_right", 25,
     ["_x", "offset", "inset"], "+", 10),
    ("pi_panel", "hole size", "the Pi's holes 2.7 -> 3.2 mm (the corner holes stay 2.7)", "hole_d", 3.2,
     ["_d"], 2.7, 3.2),
    ("m3_panel", "width", "panel 150 -> 180 mm wide (the board stays by the right edge)", "width", 180,
     ["width"], 150, 180),
    ("m3_panel", "width", "panel 90 -> 110 mm high (the board stays by the top)", "height", 110,
     ["height"], 90, 110, {"board_dy": 7.1},
     "the spec places a board's set per axis from the centre line when its middle is nearer it than "
     "the edge (here 21.05 mm from the centre line, 23.95 mm from the top): the board stays 7.1 mm "
     "above the centre line"),
    ("m3_panel", "offset", "corner holes 6 -> 8 mm in (the board's holes stay)", "inset", 8,
     ["inset"], 6, 8),
    ("centred_plate", "width", "plate 120 -> 140 mm wide", "width", 140, ["width"], 120, 140),
    ("centred_plate", "offset", "corner holes 6 -> 8 mm from the top and bottom", "inset_y", 8,
     ["inset_y", "inset"], 6, 8),
    ("centred_plate", "size", "window 40 -> 50 mm wide", "window_w", 50, ["window_width", "width"], 40, 50),
    ("stacked_brackets", "gap", "gap between the plates 8 -> 12 mm", "gap", 12, ["gap"], 8, 12),
    ("stacked_brackets", "width", "lower plate 30 -> 35 mm high (the upper one moves up)", "h1", 35,
     ["height"], 30, 35),
    ("stacked_brackets", "width", "upper plate 40 -> 50 mm high", "h2", 50, ["height"], 40, 50),
    ("slotted_motor", "width", "plate 100 -> 120 mm wide (the motor follows the right edge)", "width", 120,
     ["width"], 100, 120),
    ("slotted_motor", "size", "tension slots 8 -> 12 mm long", "slot_len", 12, ["length"], 8, 12),
    ("slotted_motor", "pitch", "motor screw spacing 31 -> 26 mm", "spacing", 26, ["pitch", "spacing"], 31, 26),
    ("far_row", "pitch", "row pitch 15 -> 18 mm (the end hole stays 10 mm from the right edge)", "pitch", 18,
     ["pitch"], 15, 18),
    ("far_row", "width", "plate 140 -> 160 mm wide (the row follows the right edge)", "width", 160,
     ["width"], 140, 160),
    ("far_row", "hole size", "row holes 4 -> 3.5 mm (the 5 mm end hole stays)", "hole_d", 3.5,
     ["_d"], 4, 3.5),
    ("speaker_panel", "pitch", "both grilles' pitch 6 -> 7 mm", "pitch", 7, ["pitch"], 6, 7),
    ("speaker_panel", "hole size", "grille holes 3 -> 2.5 mm (the corner holes stay)", "hole_d", 2.5,
     ["holes_d", "hole_d"], 3, 2.5),
    ("speaker_panel", "offset", "grilles 90 -> 100 mm apart (about the centre)", "spacing", 100,
     ["spacing", "_x", "offset"], 90, 100),
    ("terminal_row", "pitch", "row pitch 12 -> 10 mm (the gap and the pin hole keep their turns)",
     "pitch", 10, ["pitch"], 12, 10),
    ("terminal_row", "count", "8 -> 9 holes (the gap stays at turn 3)", "n", 9, ["_n"], 8, 9),
    ("terminal_row", "hole size", "row holes 3.5 -> 3 mm (the 4 mm pin hole stays)", "hole_d", 3,
     ["_d"], 3.5, 3),
    ("dowel_flange", "count", "6 -> 8 holes (the dowel hole stays on the x axis)", "n", 8, ["_n"], 6, 8),
    ("dowel_flange", "pitch", "bolt circle 66 -> 70 mm", "pcd", 70, ["pcd"], 66, 70),
    ("dowel_flange", "hole size", "bolt holes 5.5 -> 6.6 mm (the dowel hole stays 6)", "hole_d", 6.6,
     ["_d"], 5.5, 6.6),
]

# The drawings' own numbers where they differ from the function's defaults.
DRAWN = {"uno_panel": {"width": 220.0, "board_x": 8.0}, "sensor_panel": {"height": 90.0}}

# Where several params fit an edit's words and number, the one a maker picks on reading the
# program (drawing, function argument) -> param name; filled after reading the programs.
PICK: dict = {
    # the Pi's 2 x 2 grid is `holes` (`corner_holes` are the corners'): a maker picks holes_d
    ("pi_panel", "hole_d"): "holes_d",
    # the Pi's grid is placed `width - 15 + ...`: no param holds its distance from the right edge
    ("pi_panel", "from_right"): None,
    # the two holes are `width - 12`, a number in the text: no param
    ("far_edge_bracket", "hole_from_right"): None,
    # the mirror line is `Line((55, 0), (55, 40))`, numbers in the text: no gap param
    ("mirrored_brackets", "gap"): None,
    # the upper plate is placed at y = 58, a number in the text: no gap param
    ("stacked_brackets", "gap"): None,
    # two grilles alike, each its own pattern with its own params (the spec: "each its own pattern
    # and size params"): a maker changing both grilles sets both
    ("speaker_panel", "pitch"): ["holes_pitch", "holes_2_pitch"],
    ("speaker_panel", "hole_d"): ["holes_d", "holes_2_d"],
    # the grilles are placed at x = 45 and width - 45, numbers in the text: no param
    ("speaker_panel", "spacing"): None,
    # the head says "`l_02` beside `l_01`: placed from its right edge": l_01 is the left bracket
    ("bracket_pair", "w1"): "l_01_width",
    ("bracket_pair", "w2"): "l_02_width",
}


# --------------------------------------------------------------------------- geometry compare

def _curves_of_dxf(path):
    import ezdxf
    doc = ezdxf.readfile(path)
    out = []

    def visit(e):
        t = e.dxftype()
        if t == "LINE":
            out.append(("line", tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]))
        elif t == "ARC":
            out.append(("arc", tuple(e.dxf.center)[:2], e.dxf.radius, e.dxf.start_angle, e.dxf.end_angle))
        elif t == "CIRCLE":
            out.append(("circle", tuple(e.dxf.center)[:2], e.dxf.radius))
        elif t in ("LWPOLYLINE", "POLYLINE", "INSERT"):
            for v in e.virtual_entities():
                visit(v)
        elif t in ("SPLINE", "ELLIPSE"):
            pts = [tuple(p)[:2] for p in e.flattening(0.001)]
            for a, b in zip(pts, pts[1:]):
                out.append(("line", a, b))
    for e in doc.modelspace():
        if e.dxftype() in ("TEXT", "MTEXT", "POINT", "HATCH", "DIMENSION"):
            continue
        visit(e)
    return out


def _samples(prims, step=0.5):
    """Points along every primitive and, for each point, its primitive's index."""
    pts, owner = [], []
    for k, pr in enumerate(prims):
        if pr[0] == "line":
            (x0, y0), (x1, y1) = pr[1], pr[2]
            n = max(2, int(math.hypot(x1 - x0, y1 - y0) / step) + 1)
            t = np.linspace(0, 1, n)
            pts.append(np.c_[x0 + t * (x1 - x0), y0 + t * (y1 - y0)])
        else:
            (cx, cy), r = pr[1], pr[2]
            a0, a1 = (0.0, 360.0) if pr[0] == "circle" else (pr[3], pr[4])
            span = (a1 - a0) % 360 or 360.0
            n = max(16, int(math.radians(span) * r / step) + 1)
            a = np.radians(a0 + np.linspace(0, span, n))
            pts.append(np.c_[cx + r * np.cos(a), cy + r * np.sin(a)])
        owner += [k] * len(pts[-1])
    return np.vstack(pts), np.array(owner)


def _dist(pts, prims):
    """Distance of each point to the nearest primitive (exact: segments and arcs)."""
    best = np.full(len(pts), np.inf)
    for pr in prims:
        if pr[0] == "line":
            a, b = np.array(pr[1]), np.array(pr[2])
            ab = b - a
            L2 = float(ab @ ab) or 1e-30
            t = np.clip(((pts - a) @ ab) / L2, 0, 1)
            d = np.hypot(*(pts - (a + t[:, None] * ab)).T)
        else:
            c, r = np.array(pr[1]), pr[2]
            v = pts - c
            rad = np.hypot(*v.T)
            d_circle = np.abs(rad - r)
            if pr[0] == "circle":
                d = d_circle
            else:
                a0, a1 = pr[3] % 360, pr[4] % 360
                ang = np.degrees(np.arctan2(v[:, 1], v[:, 0])) % 360
                inside = ((ang - a0) % 360) <= ((a1 - a0) % 360 or 360)
                e0 = c + r * np.array([math.cos(math.radians(a0)), math.sin(math.radians(a0))])
                e1 = c + r * np.array([math.cos(math.radians(a1)), math.sin(math.radians(a1))])
                d_end = np.minimum(np.hypot(*(pts - e0).T), np.hypot(*(pts - e1).T))
                d = np.where(inside, d_circle, d_end)
        best = np.minimum(best, d)
    return best


def _moved(pr, t):
    if pr[0] == "line":
        return ("line", (pr[1][0] + t[0], pr[1][1] + t[1]), (pr[2][0] + t[0], pr[2][1] + t[1]))
    return (pr[0], (pr[1][0] + t[0], pr[1][1] + t[1])) + tuple(pr[2:])


def _bbox(pts):
    return pts.min(axis=0), pts.max(axis=0)


def _describe(pr):
    if pr[0] == "circle":
        return f"hole d{2 * pr[2]:g} at ({pr[1][0]:.2f}, {pr[1][1]:.2f})"
    if pr[0] == "arc":
        return f"arc r{pr[2]:g} about ({pr[1][0]:.2f}, {pr[1][1]:.2f})"
    return f"line ({pr[1][0]:.2f}, {pr[1][1]:.2f})-({pr[2][0]:.2f}, {pr[2][1]:.2f})"


def compare(truth, got):
    """(max deviation in mm after the best translation, what is off: a list of words)."""
    tp, towner = _samples(truth)
    gp, gowner = _samples(got)
    (tmin, tmax), (gmin, gmax) = _bbox(tp), _bbox(gp)
    cands = [tmin - gmin, tmax - gmax, (tmin + tmax - gmin - gmax) / 2, np.zeros(2)]
    best = None
    for t in cands:
        g2 = [_moved(p, t) for p in got]
        d1 = _dist(tp, g2)
        d2 = _dist(gp + t, truth)
        err = max(d1.max(), d2.max())
        if best is None or err < best[0]:
            best = (err, t, d1, d2)
    err, t, d1, d2 = best
    if err > TOL:   # described as a maker lays the two on one another: by their lower left corners
        t = cands[0]
        g2 = [_moved(p, t) for p in got]
        d1, d2 = _dist(tp, g2), _dist(gp + t, truth)
        err = max(d1.max(), d2.max())
    off = []
    if err > TOL:
        per = {}
        for k, d in zip(towner, d1):
            per[k] = max(per.get(k, 0), d)
        bad = sorted(((d, k) for k, d in per.items() if d > TOL), reverse=True)
        for d, k in bad[:4]:
            off.append(f"{_describe(truth[k])} off {d:.2f} mm")
        if len(bad) > 4:
            off.append(f"... {len(bad)} of {len(truth)} pieces of the drawing off")
        gper = {}
        for k, d in zip(gowner, d2):
            gper[k] = max(gper.get(k, 0), d)
        extra = sorted(((d, k) for k, d in gper.items() if d > TOL), reverse=True)
        if extra:
            off.append(f"{len(extra)} pieces of the program's not in the drawing, the farthest "
                       f"{_describe(_moved(got[extra[0][1]], t))} ({extra[0][0]:.2f} mm)")
    return float(err), off, [float(x) for x in t]


# --------------------------------------------------------------------------- aidl

def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, **kw)


PARAM = re.compile(r"^[ \t]*param[ \t]+(\w+)[ \t]*=[ \t]*(-?[0-9.]+(?:e-?\d+)?)[ \t]*([a-z]*)", re.M)


def params(text):
    return [(m.group(1), float(m.group(2)), m.group(3)) for m in PARAM.finditer(text)]


def import_drawing(name):
    d = os.path.join(WORK, name)
    os.makedirs(d, exist_ok=True)
    kw = DRAWN.get(name, {})
    part = makers.DRAWINGS[name](**kw)
    src = makers.write(part, os.path.join(d, name))
    prog = os.path.join(d, name + ".aidl")
    r = run([AIDL, "import", "--infer", src, "-o", prog])
    ok = r.returncode == 0
    c = run([AIDL, "check", prog]) if ok else None
    rt = None
    if ok:      # the program unedited renders the drawing (the comparison's own check)
        out = os.path.join(d, name + "_unedited.dxf")
        rr = run([AIDL, "render", prog, "-o", out])
        if rr.returncode == 0:
            rt = round(compare(makers.primitives(part), _curves_of_dxf(out))[0], 6)
    return {"name": name, "source": os.path.relpath(src, HERE), "ok": ok,
            "import_err": (r.stderr or r.stdout)[-2000:] if not ok else "",
            "check": (c.stdout + c.stderr).strip()[-300:] if c else "", "roundtrip_mm": rt}


def pick_param(name, arg, words, drawn, prog_text):
    ps = params(prog_text)
    if (name, arg) in PICK:
        p = PICK[(name, arg)]
        if p is None:
            return None, [], "no param holds it (the program read: the number is in the text)"
        return p, [p], "named on reading the program"
    if drawn == "+":            # a move: the one param of that name, whatever its value
        fits = [p for p, v, u in ps if any(w in p for w in words)]
        if len(fits) == 1:
            return fits[0], fits, "name (a move by a difference)"
        return None, fits, ("several params fit" if fits else "no param of that name")
    by_value = [p for p, v, u in ps if abs(v - drawn) <= 1e-6]
    fits = [p for p in by_value if any(w in p for w in words)]
    if len(fits) == 1:
        return fits[0], fits, "name and value"
    if len(fits) > 1:
        return None, fits, "several params fit"
    return None, [], ("no param of that name and value" + (
        f" (of that value only: {', '.join(by_value)})" if by_value else ""))


def do_edit(k, e):
    name, kind, meant, arg, new, words, drawn, new_param = e[:8]
    spec_kw, spec_note = (e[8], e[9]) if len(e) > 8 else (None, "")
    d = os.path.join(WORK, name)
    prog = os.path.join(d, name + ".aidl")
    res = {"k": k, "drawing": name, "kind": kind, "meant": meant}
    if not os.path.exists(prog):
        res.update(verdict="impossible", why="the import failed")
        return res
    text = open(prog).read()
    p, cands, how = pick_param(name, arg, words, drawn, text)
    res["candidates"] = cands
    if p is None:
        res.update(verdict="impossible" if not cands or how.startswith("no") else "ambiguous",
                   why=f"{how}: {', '.join(cands) or 'none'}")
        return res
    if drawn == "+":
        old = dict((q, v) for q, v, u in params(text))[p]
        new_param = round(old + new_param, 9)
    ps = p if isinstance(p, list) else [p]
    res["param"] = ", ".join(f"{q} = {new_param:g}" for q in ps)
    ed = os.path.join(d, f"edit{k:02d}_{ps[0]}.aidl")
    shutil.copy(prog, ed)
    s = run([AIDL, "set", ed] + [f"{q}={new_param}" for q in ps])
    out = os.path.join(d, f"edit{k:02d}_{ps[0]}.dxf")
    r = run([AIDL, "render", ed, "-o", out])
    if r.returncode != 0:
        res.update(verdict="wrong", why="set/render failed: " + (s.stdout + s.stderr + r.stderr)[-300:])
        return res
    kw = dict(DRAWN.get(name, {}))
    kw[arg] = new
    got = _curves_of_dxf(out)
    if spec_kw:     # the spec reads this edit another way than the maker's own dimension
        merr, moff, _ = compare(makers.primitives(makers.DRAWINGS[name](**kw)), got)
        res["maker_reading"] = f"{merr:.2f} mm off the maker's own dimensioning; " + "; ".join(moff[:2])
        res["spec_note"] = spec_note
        kw.update(spec_kw)
    truth = makers.primitives(makers.DRAWINGS[name](**kw))
    err, off, t = compare(truth, got)
    res["deviation_mm"] = round(err, 4)
    res["translation"] = [round(x, 4) for x in t]
    # the comparison's own check: the edited program must differ from the unedited drawing
    res["off_unedited_mm"] = round(compare(makers.primitives(makers.DRAWINGS[name](**DRAWN.get(name, {}))),
                                           got)[0], 4)
    if err <= TOL:
        res.update(verdict="meant", why="")
    else:
        res.update(verdict="wrong", why=f"{err:.2f} mm off; " + "; ".join(off))
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only")
    ap.add_argument("--png", action="store_true", help="render every edited program to PNG too")
    ap.add_argument("--jobs", type=int, default=3)
    a = ap.parse_args()
    names = [n for n in makers.DRAWINGS if not a.only or n == a.only]
    edits = [(k, e) for k, e in enumerate(EDITS, 1) if e[0] in names]
    with ThreadPoolExecutor(a.jobs) as ex:
        imports = list(ex.map(import_drawing, names))
        results = list(ex.map(lambda ke: do_edit(*ke), edits))
    if a.png:
        for r in results:
            if "param" in r:
                p = r["param"].split(" = ")[0]
                ed = os.path.join(WORK, r["drawing"], f"edit{r['k']:02d}_{p}.aidl")
                run([AIDL, "render", ed, "-o", ed[:-5] + ".png"])
    by_kind = {}
    for r in results:
        m, n = by_kind.get(r["kind"], (0, 0))
        by_kind[r["kind"]] = (m + (r["verdict"] == "meant"), n + 1)
    meant = sum(r["verdict"] == "meant" for r in results)
    for i in imports:
        print(f"import {i['name']:17s} ok={i['ok']} unedited render off the drawing by "
              f"{i['roundtrip_mm']} mm; check: {i['check'][-60:]}")
    for r in results:
        print(f"{r['k']:2d} {r['drawing']:17s} {r['kind']:9s} {r['verdict']:10s} "
              f"{r.get('param', '-'):28s} {r['why'][:160]}"
              + (f" [unedited {r['off_unedited_mm']}]" if "off_unedited_mm" in r else "")
              + (f" [spec's reading; maker's: {r['maker_reading'][:60]}]" if "maker_reading" in r else ""))
    print(f"\n{meant} of {len(results)} edits do what was meant")
    for kind, (m, n) in sorted(by_kind.items()):
        print(f"  {kind}: {m} of {n}")
    if not a.only:
        with open(os.path.join(HERE, "table.md"), "w") as f:
            f.write(f"**{meant} of {len(results)} edits do what was meant** "
                    f"({len(imports)} drawings; by kind: "
                    + ", ".join(f"{kd} {m} of {n}" for kd, (m, n) in sorted(by_kind.items())) + ")\n\n")
            f.write("| # | drawing | kind | edit (what the maker means) | param set | verdict | how far off, what moved |\n")
            f.write("|---|---|---|---|---|---|---|\n")
            for r in results:
                why = r["why"]
                if "spec_note" in r:
                    why = (why + " " if why else "") + f"judged by the spec: {r['spec_note']} (the maker's own dimension: {r['maker_reading']})"
                f.write(f"| {r['k']} | {r['drawing']} | {r['kind']} | {r['meant']} | "
                        f"{r.get('param', '-')} | {r['verdict']} | {why.replace('|', '/')} |\n")
        with open(os.path.join(HERE, "results.json"), "w") as f:
            json.dump({"imports": imports, "edits": results, "meant": meant, "total": len(results),
                       "by_kind": by_kind}, f, indent=1)


if __name__ == "__main__":
    main()
