"""Perforated sheets (issue 74): our `aidl check` and `aidl render -o .dxf` of a panel with
thousands of round holes against the libraries' floor, timed in the same run.

Run:  .venv/bin/python benchmarks/checks/perforated.py [--quick] [--tree PATH] [--sizes N ...]
                                                [--only GROUPS] [--budget K]

The panel: ``n`` holes of radius 2 mm on a 10 mm pitch in a rectangle (2,000 = 50 x 40,
20,000 = 200 x 100, 50,000 = 250 x 200; ``--sizes 19000``: issue 74's 1,000 x 1,900 mm panel of
100 x 190 holes), written three ways:

* ``dxf``: a DXF (R2010, ``$INSUNITS`` 4 = mm; a closed LWPOLYLINE outline and one CIRCLE per
  hole) read by ``solid p { d = Drawing2D("panel.dxf") }``;
* ``svg``: an SVG (width/height in mm; a ``<rect>`` outline and one ``<circle>`` per hole)
  read the same way;
* ``loop``: the AIDL program with two nested ``for`` loops of ``hole h { c = Circle(...) }``.

For each, ``aidl check FILE`` and ``aidl render FILE -o out.dxf`` run each in a fresh process
(``python -m aidl_lang.cli``, the tree on ``PYTHONPATH``); the child's CPU time (user +
system) and peak RSS come from ``os.wait4``, so the figures are those of that process alone,
start-up and imports included.  The status column is ``ok``, the first error code the
command printed (``E0304``: past the 15 s wall-time budget, ``--budget K`` scales it;
``E0130``: a drawing of more shapes than ``Drawing2D`` reads), or the exit status.  A
command that ends in ``E0304`` runs again with ``--budget 20`` (``--rerun K``; 0: not) on a
row of its own: the wall-time budget of a loaded machine ends a compile long before 15 s of
CPU, and the second row gives the CPU the whole command takes (every figure of the budget is
scaled, as ``--budget`` does).

The floor (the ``floor`` column, one per case, also a fresh process, CPU the same way):
``ezdxf.readfile`` of the case's DXF, ONE Manifold ``CrossSection`` boolean (the outline minus
every circle, each a polygon of as many chords as our booleans cut it into:
``aidl_lang.geometry.shapes.tessellate.segments_for``, sagitta <= ``CHORD_TOL`` 0.005 mm; the
circles built as one ``CrossSection``, then one difference, its polygons read out) and an
ezdxf write of the outline and the circles.  ``ratio`` is ours / floor; the goal of issue 74
is <= 2 for the 20,000-hole panel, and the 50,000-hole panel within the default budget.

OpenSCAD (issue 110): for the ``loop`` panel, ``openscad -o out.dxf panel.scad`` of the same
panel (``difference()`` of the ``square`` and a ``circle(r=2, $fn=32)`` per hole, in the same
nested loops; ``--openscad PATH``, default ``/usr/bin/openscad`` or the one on PATH; the row
says it is skipped when there is none), timed the same way, its ratio to the floor in the
``ratio`` column; a last line per panel gives ours / floor and ours / OpenSCAD for the render.
Issue 110's case, the 1,000 x 1,900 mm panel of 19,000 holes as a loop, in one go:
``--only panel --sizes 19000 --formats loop`` (goal: the render within 2 x the floor).

Other groups (``--only``; all by default):

* ``panel``: the three panels above at each size (``--sizes``; ``--quick``: 2,000 only);
* ``collinear``: 5,000 circles 1 mm apart on one line in one plate (6 mm high), as holes of
  r 0.4 mm (apart: 0.2 mm walls) and of r 0.6 mm (overlapping: one long opening); an AIDL loop,
  the floor as above from the same circles in a DXF (goal: within 2 s);
* ``sheet``: ``aidl render --layout sheet -o sheet.svg`` of an assembly of 1,000 solid parts
  (``sheet1000``: a 10 x 6 mm plate with a 1.5 mm hole, each a copy moved by the loop;
  ``sheet1000-mixed``: five small shapes in turn, plate, disc, L bracket, slotted bar,
  heptagon), with the spyrrow nesting of the ``layout`` extra (goal: within 10 s); no floor.

``--tree PATH`` runs every command (the floor once) on another checkout too (its ``aidl_lang``
first on ``PYTHONPATH``, e.g. ``/work/main`` for the tree before), its rows beside this
tree's, so before and after are one run on one machine state.  Each command is also bounded
by ``--timeout`` seconds of wall time (default 600; ``timeout`` in the status column).

The machine is shared: read CPU seconds, never wall time.  Nothing here is asserted; the
counts that must stay linear are held by ``tests/test_perforated_scaling.py``.
"""
from __future__ import annotations

import argparse
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
CHORD_TOL = 0.005          # aidl_lang.geometry.shapes.tessellate.CHORD_TOL (the floor's chords)

SIZES = {2000: (50, 40), 19000: (100, 190), 20000: (200, 100), 50000: (250, 200)}
DEFAULT_SIZES = [2000, 20000, 50000]


# ------------------------------------------------------------------ the cases
def grid(nx: int, ny: int, pitch: float = 10.0):
    """The panel's size (W, H, mm) and its hole centres (row by row, mm)."""
    W, H = nx * pitch, ny * pitch
    return W, H, [(-W / 2 + pitch / 2 + i * pitch, -H / 2 + pitch / 2 + j * pitch)
                  for i in range(nx) for j in range(ny)]


def panel_aidl(nx: int, ny: int, pitch: float = 10.0, r: float = 2.0) -> str:
    """The panel as an AIDL program: a Rectangle and two nested loops of round holes."""
    W, H = nx * pitch, ny * pitch
    return f"""solid panel {{
  body = Rectangle(center=(0, 0), width={W} mm, height={H} mm)
  for i in range({nx}) {{
    for j in range({ny}) {{
      hole h {{ c = Circle(center=({-W / 2 + pitch / 2} mm + i * {pitch} mm, {-H / 2 + pitch / 2} mm + j * {pitch} mm), radius={r} mm) }}
    }}
  }}
}}
"""


def write_dxf(path, outline, circles) -> None:
    """A DXF (R2010, mm) of a closed LWPOLYLINE ``outline`` and CIRCLEs ``(x, y, r)``."""
    import ezdxf
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    msp.add_lwpolyline(outline, close=True)
    for x, y, r in circles:
        msp.add_circle((x, y), r)
    doc.saveas(path)


def write_svg(path, W: float, H: float, circles) -> None:
    """An SVG (mm page, y down) of a ``<rect>`` outline and ``<circle>`` elements."""
    rows = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}mm" height="{H}mm" '
            f'viewBox="0 0 {W} {H}">',
            f'<rect x="0" y="0" width="{W}" height="{H}" fill="none" stroke="black"/>']
    rows += [f'<circle cx="{x + W / 2:g}" cy="{H / 2 - y:g}" r="{r:g}" fill="none" '
             'stroke="black"/>' for x, y, r in circles]
    pathlib.Path(path).write_text("\n".join(rows + ["</svg>\n"]))


def panel_scad(nx: int, ny: int, pitch: float = 10.0, r: float = 2.0, fn: int = 32) -> str:
    """The panel of :func:`panel_aidl` as an OpenSCAD program (2D, mm; circles of ``fn``
    sides)."""
    W, H = nx * pitch, ny * pitch
    return (f"difference() {{\n  square([{W}, {H}], center=true);\n"
            f"  for (i = [0:{nx - 1}]) for (j = [0:{ny - 1}])\n"
            f"    translate([{-W / 2 + pitch / 2} + i * {pitch}, {-H / 2 + pitch / 2} + j * {pitch}])"
            f" circle(r={r}, $fn={fn});\n}}\n")


def reader(name: str) -> str:
    return f'solid p {{\n  d = Drawing2D("{name}")\n}}\n'


def collinear_aidl(n: int, r: float) -> str:
    """``n`` holes of radius ``r`` 1 mm apart on one line in a plate 6 mm high."""
    return f"""solid plate {{
  body = Rectangle(bottom_left=(-2 mm, -3 mm), width={n + 3} mm, height=6 mm)
  for i in range({n}) {{
    hole h {{ c = Circle(center=(i * 1 mm, 0 mm), radius={r} mm) }}
  }}
}}
"""


SHEET_SHAPES = [
    "body = Rectangle(center=({x}, {y}), width=10, height=6)\n"
    "hole h {{ c = Circle(center=({x}, {y}), radius=1.5) }}",
    "body = Circle(center=({x}, {y}), radius=5)\n"
    "hole h {{ c = Circle(center=({x}, {y}), radius=1.2) }}",
    "body = Polygon(points=[({x}, {y}), ({x} + 12, {y}), ({x} + 12, {y} + 3), "
    "({x} + 3, {y} + 3), ({x} + 3, {y} + 10), ({x}, {y} + 10)])",
    "body = Slot(start=({x}, {y}), end=({x} + 14, {y}), width=4)\n"
    "hole h {{ s = Slot(start=({x} + 3, {y}), end=({x} + 11, {y}), width=1.5) }}",
    "body = RegularPolygon(center=({x}, {y}), radius=5, sides=7)",
]


def sheet_aidl(n: int) -> str:
    """An assembly of ``n`` copies of one small plate with a hole (a loop of solids)."""
    return ("units mm\nassembly a {\n  for i in range(%d) {\n    solid s {\n"
            "      r = Rectangle(center=(i * 12, 0), width=10, height=6)\n"
            "      hole h { c = Circle(center=(i * 12, 0), radius=1.5) }\n    }\n  }\n}\n" % n)


def sheet_mixed_aidl(n: int) -> str:
    """An assembly of ``n`` small parts of five shapes in turn, each written out."""
    rows = []
    for i in range(n):
        x, y = (i % 40) * 20, (i // 40) * 20
        rows.append(f"  solid p{i} {{\n    " +
                    SHEET_SHAPES[i % len(SHEET_SHAPES)].format(x=x, y=y).replace("\n", "\n    ")
                    + "\n  }")
    return "units mm\nassembly parts {\n" + "\n".join(rows) + "\n}\n"


# ------------------------------------------------------------------ running
FLOOR = r"""
import math, sys, ezdxf, manifold3d as mf
src, dst, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
def chords(r):
    if r <= tol:
        return 8
    return max(3, min(20000, math.ceil(2 * math.pi / (2 * math.acos(1 - tol / r)))))
doc = ezdxf.readfile(src)
msp = doc.modelspace()
outline = [tuple(p[:2]) for p in msp.query("LWPOLYLINE")[0].get_points("xy")]
circles = [(e.dxf.center.x, e.dxf.center.y, e.dxf.radius) for e in msp.query("CIRCLE")]
polys = []
for x, y, r in circles:
    n = chords(r)
    polys.append([(x + r * math.cos(2 * math.pi * k / n), y + r * math.sin(2 * math.pi * k / n))
                  for k in range(n)])
part = mf.CrossSection([outline]) - mf.CrossSection(polys, mf.FillRule.NonZero)
loops = part.to_polygons()
out = ezdxf.new("R2010")
out.header["$INSUNITS"] = 4
m = out.modelspace()
m.add_lwpolyline(outline, close=True)
for x, y, r in circles:
    m.add_circle((x, y), r)
out.saveas(dst)
print(len(loops))
"""


def run(cmd: list[str], env: dict, cwd: str, timeout: float):
    """Run ``cmd``; (CPU s of the child, peak RSS MB, status, output)."""
    t0 = time.monotonic()
    p = subprocess.Popen(cmd, env=env, cwd=cwd, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT)
    import threading
    buf = []
    th = threading.Thread(target=lambda: buf.append(p.stdout.read()), daemon=True)
    th.start()
    timed_out = False
    while True:
        pid, status, ru = os.wait4(p.pid, os.WNOHANG)
        if pid:
            break
        if time.monotonic() - t0 > timeout:
            p.kill()
            timed_out = True
        time.sleep(0.05)
    p.returncode = os.waitstatus_to_exitcode(status)
    th.join()
    text = (buf[0] if buf else b"").decode(errors="replace")
    cpu = ru.ru_utime + ru.ru_stime
    mb = ru.ru_maxrss / 1024
    if timed_out:
        st = "timeout"
    else:
        codes = re.findall(r"\b([EW]0\d{3})\b", text)
        err = [c for c in codes if c.startswith("E")]
        st = err[0] if err else ("ok" if p.returncode == 0 else f"exit {p.returncode}")
        stage = re.search(r"budget in (the [a-z ]+?) of", text)
        if st == "E0304" and stage:
            st += f" ({stage.group(1)})"
    return cpu, mb, st, text


class Tree:
    def __init__(self, path: pathlib.Path, label: str):
        self.path, self.label = path, label
        self.env = dict(os.environ, PYTHONPATH=str(path), OPENBLAS_NUM_THREADS="1")

    def aidl(self, *args) -> list[str]:
        return [sys.executable, "-m", "aidl_lang.cli", *args]

    def where(self) -> str:
        # run outside any checkout: the current folder comes first on sys.path (the tree
        # before showed as this one when run from this one's root)
        return subprocess.run([sys.executable, "-c", "import aidl_lang; print(aidl_lang.__file__)"],
                              env=self.env, capture_output=True, text=True,
                              cwd=tempfile.gettempdir()).stdout.strip()


def floor(dxf: str, work: str, timeout: float):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    return run([sys.executable, "-c", FLOOR, dxf, os.path.join(work, "floor-out.dxf"),
                str(CHORD_TOL)], env, work, timeout)


def header() -> None:
    print(f"{'case':46} {'tree':6} {'ours s':>8} {'floor s':>8} {'ratio':>6} {'MB':>7}  status",
          flush=True)


def row(case: str, tree: str, cpu: float, fl: float | None, mb: float, st: str) -> None:
    fs = f"{fl:8.2f}" if fl else f"{'-':>8}"
    ratio = f"{cpu / fl:6.1f}" if fl else f"{'-':>6}"
    print(f"{case:46} {tree:6} {cpu:8.2f} {fs} {ratio} {mb:7.0f}  {st}", flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="the 2,000-hole panel only")
    ap.add_argument("--tree", type=pathlib.Path, help="another checkout, timed beside this one")
    ap.add_argument("--sizes", type=int, nargs="*", help="numbers of holes (default 2000 "
                    "20000 50000; any n: a grid of about n holes)")
    ap.add_argument("--only", default="panel,collinear,sheet",
                    help="groups: panel, collinear, sheet (comma-separated)")
    ap.add_argument("--formats", default="dxf,svg,loop")
    ap.add_argument("--budget", type=float, default=None, help="--budget K for every command")
    ap.add_argument("--rerun", type=float, default=20.0,
                    help="a command that ends in E0304 runs again with --budget K (default "
                    "20; 0: not), for its CPU time on a loaded machine")
    ap.add_argument("--timeout", type=float, default=600.0)
    ap.add_argument("--openscad", default=None, help="the openscad program timed beside the "
                    "loop panel (default /usr/bin/openscad, else the one on PATH; '' : none)")
    a = ap.parse_args()
    import shutil
    scad = a.openscad if a.openscad is not None else (
        "/usr/bin/openscad" if os.path.exists("/usr/bin/openscad") else shutil.which("openscad"))
    groups = set(a.only.split(","))
    if a.quick:
        groups &= {"panel"}
        a.sizes = [2000]
    sizes = a.sizes or DEFAULT_SIZES
    trees = [Tree(ROOT, "this")] + ([Tree(a.tree.resolve(), "other")] if a.tree else [])
    for t in trees:
        print(f"# {t.label}: {t.where()}")
    extra = ["--budget", f"{a.budget:g}"] if a.budget else []
    work = tempfile.mkdtemp(prefix="aidl-perforated-")
    print(f"# CPU seconds of each fresh process (user + system), peak RSS; files in {work}")
    header()

    def commands(case: str, fname: str, fl: float | None, render=True) -> dict:
        """Each tree's check and render rows; ``{tree label: render CPU s}`` (ok only)."""
        took = {}
        for t in trees:
            todo = [("check", t.aidl("check", fname, *extra))]
            if render:
                todo.append(("render", t.aidl("render", fname, "-o", f"out-{t.label}.dxf",
                                             *extra)))
            for what, cmd in todo:
                cpu, mb, st, _ = run(cmd, t.env, work, a.timeout)
                row(f"{case} {what}", t.label, cpu, fl, mb, st)
                if st.startswith("E0304") and a.rerun and not a.budget:
                    cpu, mb, st, _ = run(cmd + ["--budget", f"{a.rerun:g}"], t.env, work,
                                         a.timeout)
                    row(f"{case} {what} --budget {a.rerun:g}", t.label, cpu, fl, mb, st)
                if what == "render" and st == "ok":
                    took[t.label] = cpu
        return took

    def openscad(case: str, nx: int, ny: int, fl: float | None) -> float | None:
        """The OpenSCAD row of the loop panel: its render's CPU s, or None."""
        if not scad:
            print(f"{case} openscad: skipped, no openscad (install it, or give --openscad "
                  "PATH)", flush=True)
            return None
        name = f"panel{nx * ny}.scad"
        pathlib.Path(work, name).write_text(panel_scad(nx, ny))
        cpu, mb, st, text = run([scad, "-o", f"scad{nx * ny}.dxf", name],
                                dict(os.environ), work, a.timeout)
        row(f"{case} openscad 32-gon render", "scad", cpu, fl, mb,
            st if st != "ok" else "ok")
        return cpu if st == "ok" else None

    if "panel" in groups:
        for n in sizes:
            nx, ny = SIZES.get(n) or (max(1, round(math.sqrt(n * 1.25))),
                                      max(1, round(n / round(math.sqrt(n * 1.25)))))
            W, H, centres = grid(nx, ny)
            circles = [(x, y, 2.0) for x, y in centres]
            outline = [(-W / 2, -H / 2), (W / 2, -H / 2), (W / 2, H / 2), (-W / 2, H / 2)]
            dxf = os.path.join(work, f"panel{n}.dxf")
            write_dxf(dxf, outline, circles)
            fcpu, fmb, fst, ftext = floor(dxf, work, a.timeout)
            row(f"{nx * ny} holes floor", "-", fcpu, None, fmb,
                f"{fst}, {ftext.strip()} loops" if fst == "ok" else fst)
            fl = fcpu if fst == "ok" else None
            for fmt in a.formats.split(","):
                if fmt == "dxf":
                    name = f"panel{n}-dxf.aidl"
                    pathlib.Path(work, name).write_text(reader(f"panel{n}.dxf"))
                elif fmt == "svg":
                    write_svg(os.path.join(work, f"panel{n}.svg"), W, H, circles)
                    name = f"panel{n}-svg.aidl"
                    pathlib.Path(work, name).write_text(reader(f"panel{n}.svg"))
                else:
                    name = f"panel{n}-loop.aidl"
                    pathlib.Path(work, name).write_text(panel_aidl(nx, ny))
                took = commands(f"{nx * ny} holes {fmt}", name, fl)
                if fmt == "loop":
                    sc = openscad(f"{nx * ny} holes", nx, ny, fl)
                    for label, cpu in took.items():
                        said = [f"{cpu / fl:.2f} x the floor" if fl else "no floor",
                                f"{cpu / sc:.2f} x OpenSCAD" if sc else "no OpenSCAD"]
                        print(f"# {nx * ny} holes loop render, {label}: {cpu:.2f} s CPU, "
                              + ", ".join(said), flush=True)
    if "collinear" in groups:
        for r, label in ((0.4, "apart r 0.4"), (0.6, "overlapping r 0.6")):
            n = 5000
            circles = [(float(i), 0.0, r) for i in range(n)]
            outline = [(-2.0, -3.0), (n + 1.0, -3.0), (n + 1.0, 3.0), (-2.0, 3.0)]
            dxf = os.path.join(work, f"collinear{r}.dxf")
            write_dxf(dxf, outline, circles)
            fcpu, fmb, fst, ftext = floor(dxf, work, a.timeout)
            row(f"{n} collinear {label} floor", "-", fcpu, None, fmb,
                f"{fst}, {ftext.strip()} loops" if fst == "ok" else fst)
            name = f"collinear{r}.aidl"
            pathlib.Path(work, name).write_text(collinear_aidl(n, r))
            commands(f"{n} collinear {label}", name, fcpu if fst == "ok" else None)
    if "sheet" in groups:
        for label, src in (("sheet1000", sheet_aidl(1000)),
                           ("sheet1000-mixed", sheet_mixed_aidl(1000))):
            name = f"{label}.aidl"
            pathlib.Path(work, name).write_text(src)
            for t in trees:
                cmd = t.aidl("render", name, "--layout", "sheet", "-o", f"{label}-{t.label}.svg",
                             *extra)
                for more in ([], ["--budget", f"{a.rerun:g}"]):
                    cpu, mb, st, text = run(cmd + more, t.env, work, a.timeout)
                    m = re.search(r"laid out (\d+) parts on (\d+) sheet", text)
                    row(f"{label} --layout sheet" + (" --budget %g" % a.rerun if more else ""),
                        t.label, cpu, None, mb,
                        st + (f", {m.group(1)} parts on {m.group(2)} sheet(s)" if m else ""))
                    if not st.startswith("E0304") or not a.rerun or a.budget:
                        break


if __name__ == "__main__":
    main()
