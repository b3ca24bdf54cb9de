"""Run the makers' edits of issue 114's measurement (brief h23-makers) and print the figure.

    cd /work/wt-makers && PYTHONPATH=/work/wt-makers /work/main/.venv/bin/python \
        data/maker_runs/issue114/run_edits.py [--only NAME] [--png]

(issue103b's runner, copied: only the edits, the drawings' numbers, the picks and the CLI's path
changed.)

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
AIDL = os.environ.get("AIDL", "/work/main/.venv/bin/aidl")     # run with PYTHONPATH=<this tree>
WORK = os.path.join(HERE, "work")
TOL = 0.01

# (drawing, kind, what the maker means, the function's argument, new value,
#  words the param's name holds, the number the drawing shows for it, the param's new value)
EDITS = [
    ("pi_plate", "width", "plate 150 -> 180 mm wide (the Pi stays by the left edge)", "width", 180,
     ["width"], 150, 180),
    ("pi_plate", "offset", "the Pi 20 -> 30 mm from the left edge (moved 10 mm in)", "board_x", 30,
     ["_x", "offset"], "+", 10),
    ("pi_plate", "hole size", "the Pi's holes 2.7 -> 3 mm (the corner holes stay 3.4)", "hole_d", 3.0,
     ["_d"], 2.7, 3.0),
    ("arduino_plate", "width", "plate 240 -> 200 mm long (the Uno stays by the left edge)", "width", 200,
     ["width"], 240, 200),
    ("arduino_plate", "offset", "the Uno 15 -> 25 mm from the left edge (moved 10 mm in)", "board_x", 25,
     ["_x", "offset"], "+", 10),
    ("arduino_plate", "hole size", "the Uno's holes 3.2 -> 3 mm (the corner holes stay 4)", "hole_d", 3.0,
     ["_d"], 3.2, 3.0),
    ("fan_panel", "pitch", "grille pitch 6 -> 7 mm (the field refilled, centred)", "pitch", 7,
     ["pitch"], 6, 7),
    ("fan_panel", "margin", "grille margin 15 -> 20 mm (the field refilled)", "margin", 20,
     ["margin"], 15, 20),
    ("fan_panel", "hole size", "grille holes 4.5 -> 5 mm (the mounting holes stay 4.3)", "hole_d", 5,
     ["_d"], 4.5, 5),
    ("perf_plate", "pitch", "perforation pitch 10 -> 12 mm (the field refilled, margin 12)", "pitch", 12,
     ["pitch"], 10, 12),
    ("perf_plate", "margin", "margin 12 -> 15 mm", "margin", 15, ["margin"], 12, 15),
    ("perf_plate", "width", "plate 200 -> 230 mm wide (the field refilled)", "width", 230,
     ["width"], 200, 230),
    ("checker_plate", "width", "plate 160 -> 220 mm wide (the checkerboard stays one, centred)", "width",
     220, ["width"], 160, 220),
    ("checker_plate", "pitch", "checkerboard pitch 25 -> 22 mm", "pitch", 22, ["pitch"], 25, 22),
    ("checker_plate", "hole size", "the small holes 5 -> 4 mm (the 8 mm ones stay)", "small_d", 4,
     ["_d"], 5, 4),
    ("mixed_lattice", "pitch", "column pitch 18 -> 20 mm (the first column stays 12 mm in)", "pitch_x", 20,
     ["pitch"], 18, 20),
    ("mixed_lattice", "width", "plate 130 -> 150 mm wide (the grid stays by the left edge)", "width", 150,
     ["width"], 130, 150),
    ("mixed_lattice", "hole size", "the 6 mm holes -> 7 mm (the middle row's 4 mm stay)", "hole_d", 7,
     ["_d"], 6, 7),
    ("asym_pair", "width", "strip 140 -> 180 mm long (each hole keeps its own edge)", "width", 180,
     ["width"], 140, 180),
    ("asym_pair", "offset", "the left hole 25 -> 30 mm from the left edge", "left_x", 30,
     ["_x", "hole"], 25, 30),
    ("asym_pair", "hole size", "both holes 6 -> 5 mm", "hole_d", 5, ["_d"], 6, 5),
    ("mirror_slots", "width", "plate 120 -> 150 mm high (each slot stays 12 mm from its edge)", "height",
     150, ["height"], 120, 150),
    ("mirror_slots", "offset", "slots 12 -> 15 mm from the top and bottom", "inset", 15,
     ["inset"], 12, 15),
    ("mirror_slots", "size", "slots 30 -> 36 mm long", "slot_len", 36, ["length"], 30, 36),
    ("bolt_circle_svg", "count", "5 -> 6 bolt holes (the first stays at the top)", "n", 6, ["_n"], 5, 6),
    ("bolt_circle_svg", "pitch", "bolt circle 80 -> 90 mm", "pcd", 90, ["pcd"], 80, 90),
    ("bolt_circle_svg", "hole size", "bolt holes 6.6 -> 5.5 mm", "hole_d", 5.5, ["_d"], 6.6, 5.5),
    ("flange_square", "count", "4 -> 8 bolt holes (the first stays at 45 deg)", "n", 8, ["_n"], 4, 8),
    ("flange_square", "pitch", "bolt circle 80 -> 76 mm", "pcd", 76, ["pcd"], 80, 76),
    ("flange_square", "hole size", "bolt holes 6.6 -> 9 mm", "hole_d", 9, ["_d"], 6.6, 9),
    ("slotted_panel", "count", "5 -> 4 slots (the row stays centred)", "n", 4, ["_n"], 5, 4),
    ("slotted_panel", "size", "slots 6 -> 8 mm wide", "slot_w", 8, ["width"], 6, 8),
    ("slotted_panel", "width", "panel 160 -> 200 mm wide (the slots centred, the holes 8 mm in)", "width",
     200, ["width"], 160, 200),
    ("l_brackets_pair", "gap", "gap between the brackets 15 -> 25 mm", "gap", 25, ["gap"], 15, 25),
    ("l_brackets_pair", "width", "left bracket's foot 50 -> 60 mm (the right one moves along)", "leg1", 60,
     ["width", "leg"], 50, 60),
    ("l_brackets_pair", "width", "right bracket's foot 60 -> 70 mm", "leg2", 70, ["width", "leg"], 60, 70),
    ("mirrored_l", "gap", "gap between the left and the right hand bracket 10 -> 20 mm", "gap", 20,
     ["gap"], 10, 20),
    ("mirrored_l", "width", "the foot 50 -> 60 mm (both: mirror images)", "leg", 60, ["width", "leg"], 50, 60),
    ("mirrored_l", "size", "wall 6 -> 8 mm (both)", "wall", 8, ["wall", "thick"], 6, 8),
    ("stacked_plates", "gap", "gap between the lowest plate and the next 6 -> 12 mm (the upper two move up)",
     "gap1", 12, ["gap"], 6, 12),
    ("stacked_plates", "width", "middle plate 40 -> 50 mm high (the top one moves up)", "h2", 50,
     ["height"], 40, 50),
    ("stacked_plates", "width", "top plate 25 -> 35 mm high", "h3", 35, ["height"], 25, 35),
    ("front_panel", "size", "display window 60 -> 70 mm wide (its left side stays 10 mm in)", "win_w", 70,
     ["width"], 60, 70),
    ("front_panel", "pitch", "knob pitch 30 -> 25 mm (the right knob stays 20 mm from the right edge)",
     "knob_pitch", 25, ["pitch"], 30, 25),
    ("front_panel", "width", "panel 180 -> 210 mm wide (window by the left, knobs by the right)", "width",
     210, ["width"], 180, 210),
    ("cable_comb2", "count", "6 -> 5 notches (centred)", "n", 5, ["_n"], 6, 5),
    ("cable_comb2", "size", "notches 10 -> 12 mm wide", "notch_w", 12, ["width"], 10, 12),
    ("cable_comb2", "size", "notches 15 -> 18 mm deep", "depth", 18, ["depth"], 15, 18),
    ("terminal_strip", "pitch", "terminal pitch 9 -> 10 mm (the first stays 10 mm in)", "pitch", 10,
     ["pitch"], 9, 10),
    ("terminal_strip", "count", "10 -> 8 terminals (the first stays 10 mm in)", "n", 8, ["_n"], 10, 8),
    ("terminal_strip", "width", "strip 130 -> 150 mm long (the row by the left, the mounting hole by the right)",
     "width", 150, ["width"], 130, 150),
    ("lid_svg", "width", "lid 120 -> 140 mm wide (the window centred, the screws in the corners)", "width",
     140, ["width"], 120, 140),
    ("lid_svg", "offset", "screw holes 6 -> 8 mm in", "inset", 8, ["inset"], 6, 8),
    ("lid_svg", "size", "window 40 -> 50 mm wide", "win_w", 50, ["width"], 40, 50),
    ("motor_far", "width", "plate 110 -> 130 mm wide (the motor stays 35 mm from the right edge)", "width",
     130, ["width"], 110, 130),
    ("motor_far", "offset", "the motor 35 -> 40 mm from the right edge", "motor_from_right", 40,
     ["_x", "bore", "motor"], 35, 40),
    ("motor_far", "offset", "mounting holes 15 -> 12 mm from the top and bottom", "mount_inset", 12,
     ["inset"], 15, 12),
    ("sensor_corner", "width", "plate 100 -> 130 mm wide (the sensor follows the right edge)", "width", 130,
     ["width"], 100, 130),
    ("sensor_corner", "width", "plate 80 -> 95 mm high (the sensor follows the top)", "height", 95,
     ["height"], 80, 95),
    ("sensor_corner", "offset", "the sensor 12 -> 20 mm from the right edge (moved 8 mm in)", "from_right",
     20, ["_x", "offset"], "+", 8),
]

# The drawings' own numbers where they differ from the function's defaults (none: each is drawn
# at its defaults).
DRAWN: dict = {}

# Where several params fit an edit's words and number, the one a maker picks on reading the
# program (drawing, function argument) -> param name; filled after reading the programs.
PICK: dict = {
    # the Pi's 2 x 2 grid is placed `center=(20 + i * holes_pitch_x, 15 + ...)`: the 20 is a number
    # in the text, no param (the word match alone would take `holes_pitch_x`, which no maker
    # moving a board sets)
    ("pi_plate", "board_x"): None,
    # the hole is `75 - width / 2 + 25`: the 25 is a number in the text, no `hole1_x`
    ("asym_pair", "left_x"): None,
    # the bore is `bore_c = (width - 35, height / 2)`: the 35 is a number in the text, no param
    ("motor_far", "motor_from_right"): None,
    # the one margin param, `holes_margin = 10  # from the plate's edges to the field's`: the drawn
    # margin is 12 (the head's reading is 10, the roundest that keeps the holes); its meaning is
    # the maker's margin, so a maker wanting a 15 mm margin sets it to 15
    ("perf_plate", "margin"): "holes_margin",
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
    env = dict(os.environ, PYTHONPATH=ROOT)     # the CLI of this tree, not the env's install
    return subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, env=env, **kw)


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
