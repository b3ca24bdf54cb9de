"""Run the makers' edits of issue 114's second measurement (brief h24-makers) and print the figure.

    cd /work/wt-makers && PYTHONPATH=/work/wt-makers /work/main/.venv/bin/python \
        data/maker_runs/issue114b/run_edits.py [--only NAME] [--png] [--jobs 2]

(issue114's runner, copied: only the edits, the picks and this docstring changed.)

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
    ("mega_plate", "width", "plate 200 -> 240 mm wide (the Mega stays by the left edge)", "width", 240,
     ["width"], 200, 240),
    ("mega_plate", "offset", "the Mega 12 -> 20 mm from the bottom (moved 8 mm up)", "board_y", 20,
     ["_y", "offset"], "+", 8),
    ("mega_plate", "hole size", "the Mega's holes 3.2 -> 3.5 mm (the corner holes stay 4)", "hole_d", 3.5,
     ["_d"], 3.2, 3.5),
    ("esp32_carrier", "width", "carrier 120 -> 140 mm wide (the board follows the right edge, the "
     "mounting holes the left)", "width", 140, ["width"], 120, 140),
    ("esp32_carrier", "offset", "the board 15 -> 25 mm from the right edge (moved 10 mm in)", "from_right",
     25, ["_x", "offset"], "+", 10),
    ("esp32_carrier", "offset", "mounting holes 12 -> 15 mm from the bottom and the top", "mount_inset", 15,
     ["inset"], 12, 15),
    ("sensor_strip", "width", "strip 120 -> 150 mm long (the sensor by the left end, the hole by the right)",
     "width", 150, ["width"], 120, 150),
    ("sensor_strip", "offset", "the sensor 10 -> 16 mm from the left edge (moved 6 mm in)", "sensor_x", 16,
     ["_x", "offset"], "+", 6),
    ("sensor_strip", "offset", "the 5 mm hole 10 -> 14 mm from the right edge", "hole_from_right", 14,
     ["_x"], 10, 14),
    ("speaker_grille", "pitch", "grille pitch 7 -> 8 mm (the field refilled inside the 15 mm margin)",
     "pitch", 8, ["pitch"], 7, 8),
    ("speaker_grille", "margin", "grille margin 15 -> 20 mm (the field refilled)", "margin", 20,
     ["margin"], 15, 20),
    ("speaker_grille", "width", "panel 160 -> 200 mm wide (the field refilled, the mounting holes in the "
     "corners)", "width", 200, ["width"], 160, 200),
    ("vent_plate", "pitch", "perforation pitch 10 -> 12 mm (the field refilled, margin 15)", "pitch", 12,
     ["pitch"], 10, 12),
    ("vent_plate", "margin", "margin 15 -> 20 mm (the field refilled)", "margin", 20, ["margin"], 15, 20),
    ("vent_plate", "hole size", "perforation holes 6 -> 5 mm (the field refilled)", "hole_d", 5,
     ["_d"], 6, 5),
    ("mixed_grid", "width", "plate 120 -> 150 mm wide (the grid stays one, centred)", "width", 150,
     ["width"], 120, 150),
    ("mixed_grid", "pitch", "grid pitch 20 -> 22 mm (about its centre)", "pitch", 22, ["pitch"], 20, 22),
    ("mixed_grid", "hole size", "the inner four holes 8 -> 10 mm (the ring's 5 mm stay)", "inner_d", 10,
     ["_d"], 8, 10),
    ("checker_strip", "count", "6 -> 8 columns (the first stays 12 mm in, the checkerboard carries on)",
     "cols", 8, ["_n", "cols"], 6, 8),
    ("checker_strip", "pitch", "pitch 15 -> 16 mm (the first column stays 12 mm in)", "pitch", 16,
     ["pitch"], 15, 16),
    ("checker_strip", "width", "strip 150 -> 180 mm long (the lattice stays by the left edge)", "width", 180,
     ["width"], 150, 180),
    ("edge_holes", "offset", "the 10 mm hole 22 -> 30 mm from the left edge", "big_x", 30, ["_x"], 22, 30),
    ("edge_holes", "width", "plate 150 -> 180 mm wide (each hole keeps its own edge)", "width", 180,
     ["width"], 150, 180),
    ("edge_holes", "offset", "the 6 mm hole 15 -> 20 mm from the top", "small_from_top", 20, ["_y"], 15, 20),
    ("post_strip", "width", "strip 160 -> 200 mm long (each hole keeps its own end)", "height", 200,
     ["height"], 160, 200),
    ("post_strip", "offset", "the lower hole 15 -> 20 mm from the bottom", "low_y", 20, ["_y"], 15, 20),
    ("post_strip", "hole size", "both holes 5 -> 6 mm", "hole_d", 6, ["_d"], 5, 6),
    ("terminal_block", "pitch", "terminal pitch 7.5 -> 7 mm (the first stays 10 mm in)", "pitch", 7,
     ["pitch"], 7.5, 7),
    ("terminal_block", "count", "10 -> 11 terminals (the first stays 10 mm in)", "n", 11, ["_n"], 10, 11),
    ("terminal_block", "offset", "the mounting hole 8 -> 12 mm from the right edge", "mount_from_right", 12,
     ["_x"], 8, 12),
    ("pipe_flange", "count", "8 -> 4 bolt holes (the first stays at 22.5 deg)", "n", 4, ["_n"], 8, 4),
    ("pipe_flange", "pitch", "bolt circle 115 -> 120 mm", "pcd", 120, ["pcd"], 115, 120),
    ("pipe_flange", "hole size", "bolt holes 14 -> 18 mm", "hole_d", 18, ["_d"], 14, 18),
    ("bearing_plate", "pitch", "bolt circle 48 -> 52 mm", "pcd", 52, ["pcd"], 48, 52),
    ("bearing_plate", "count", "3 -> 4 bolt holes (the first stays at the top)", "n", 4, ["_n"], 3, 4),
    ("bearing_plate", "offset", "corner holes 7 -> 9 mm in", "corner_inset", 9, ["inset"], 7, 9),
    ("vent_slots", "count", "7 -> 9 slots (centred)", "n", 9, ["_n"], 7, 9),
    ("vent_slots", "pitch", "slot pitch 12 -> 14 mm (centred)", "pitch", 14, ["pitch"], 12, 14),
    ("vent_slots", "size", "slots 40 -> 30 mm long", "slot_len", 30, ["length"], 40, 30),
    ("spacer_pair", "gap", "gap between the spacers 12 -> 20 mm", "gap", 20, ["gap"], 12, 20),
    ("spacer_pair", "width", "left spacer 40 -> 50 mm wide (the right one moves along)", "w1", 50,
     ["width"], 40, 50),
    ("spacer_pair", "hole size", "the right spacer's hole 8 -> 10 mm", "hole2_d", 10, ["_d"], 8, 10),
    ("t_bracket", "size", "stem 20 -> 26 mm wide (centred under the bar)", "stem", 26, ["stem", "width"],
     20, 26),
    ("t_bracket", "width", "bracket 60 -> 75 mm high (the bar stays 15 mm thick)", "height", 75,
     ["height"], 60, 75),
    ("t_bracket", "size", "bar 15 -> 12 mm thick (the holes stay midway through it)", "wall", 12,
     ["wall", "thick"], 15, 12),
    ("stacked_strips", "gap", "gap between the strips 8 -> 15 mm (the upper moves up)", "gap", 15,
     ["gap"], 8, 15),
    ("stacked_strips", "width", "lower strip 20 -> 25 mm high (the upper moves up)", "h1", 25,
     ["height"], 20, 25),
    ("stacked_strips", "hole size", "the upper strip's hole 10 -> 12 mm", "big_d", 12, ["_d"], 10, 12),
    ("jack_panel", "width", "panel 200 -> 240 mm wide (window by the left, jacks centred, switch by the "
     "right)", "width", 240, ["width"], 200, 240),
    ("jack_panel", "pitch", "jack pitch 20 -> 25 mm (centred)", "pitch", 25, ["pitch"], 20, 25),
    ("jack_panel", "size", "window 60 -> 50 mm wide (its left side stays 12 mm in)", "win_w", 50,
     ["width"], 60, 50),
    ("v_comb", "count", "8 -> 6 notches (centred)", "n", 6, ["_n"], 8, 6),
    ("v_comb", "size", "notches 12 -> 15 mm deep", "depth", 15, ["depth"], 12, 15),
    ("v_comb", "pitch", "notch pitch 16 -> 18 mm (centred)", "pitch", 18, ["pitch"], 16, 18),
    ("din_plate", "width", "plate 150 -> 180 mm wide (each slot 12 mm from its end, the row centred)",
     "width", 180, ["width"], 150, 180),
    ("din_plate", "offset", "slots 12 -> 15 mm from the ends", "slot_inset", 15, ["inset"], 12, 15),
    ("din_plate", "pitch", "hole pitch 25 -> 22 mm (centred)", "pitch", 22, ["pitch"], 25, 22),
    ("nema23_plate", "width", "plate 150 -> 170 mm wide (the motor stays 45 mm from the left edge)",
     "width", 170, ["width"], 150, 170),
    ("nema23_plate", "offset", "the motor 45 -> 55 mm from the left edge", "motor_x", 55, ["_x"], 45, 55),
    ("nema23_plate", "hole size", "motor screw holes 5 -> 5.5 mm", "hole_d", 5.5, ["_d"], 5, 5.5),
]

# The drawings' own numbers where they differ from the function's defaults (none: each is drawn
# at its defaults).
DRAWN: dict = {}

# Where several params fit an edit's words and number, the one a maker picks on reading the
# program (drawing, function argument) -> param name (or a list, set to one value); filled after
# reading the programs, before any edit was run.
PICK: dict = {
    # the Mega's six holes are "one set, from the centre": `width / 2 - 13.96 + c.x`,
    # `height / 2 + 2.56 + c.y`; no param holds their height (the word rule finds none either)
    ("mega_plate", "board_y"): None,
    # `holes_2_x = 15  # its end member, from the right edge`: the board's grid; the word rule
    # also takes `holes_2_pitch_x`, which no maker moving a board sets
    ("esp32_carrier", "from_right"): "holes_2_x",
    # `holes_x = 10  # the set's hole nearest the corner, from the left edge` is the sensor;
    # `hole1_x = 10  # its centre, from the right edge` the 5 mm hole (both 10, both `_x`)
    ("sensor_strip", "sensor_x"): "holes_x",
    ("sensor_strip", "hole_from_right"): "hole1_x",
    # `v_notches_n = 8` (the word `_n` is in `v_notches_width = 8` too)
    ("v_comb", "n"): "v_notches_n",
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
