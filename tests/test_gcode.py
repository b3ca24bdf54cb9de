"""The G-code writer (aidl_lang/output/writers/gcode.py, issue 50), re-read by an independent
parser (``gcodeparser`` from PyPI) and replayed here as GRBL would run it: modal F and S,
``G0``/``G1``/``G2``/``G3`` with I/J from the current point.  The toolpath rebuilt from the
file must be every loop of the exact output model to 1e-9 mm (arc centres, radii, ends and
directions; line ends), holes before the outline they are cut from, S and F as the profile
says; ellipse and spline pieces within the stated CURVE_TOL; a router's path the tool radius
outside outlines and inside holes.  Broken writers (G2/G3 swapped, outlines before holes, a
wrong S) are caught."""
import math
import re

import numpy as np
import pytest

gcodeparser = pytest.importorskip("gcodeparser")

from aidl_lang.output import build, for_cutting  # noqa: E402
from aidl_lang.output.fabrication.machine import DEFAULTS, from_dict  # noqa: E402
from aidl_lang.output.writers import gcode  # noqa: E402
from aidl_lang.pipeline import compile_source  # noqa: E402

from conftest import EXAMPLES, ROOT  # noqa: E402

TOL = 1e-9


# ------------------------------------------------------------------ the independent replay
class Move:
    def __init__(self, g, p, q, z0, z, center, f, s, on):
        self.g, self.p, self.q, self.z0, self.z = g, p, q, z0, z
        self.center, self.f, self.s, self.on = center, f, s, on

    @property
    def length(self) -> float:
        if self.g in (0, 1):
            return math.dist(self.p, self.q)
        return abs(self.sweep) * self.radius

    @property
    def radius(self) -> float:
        return math.dist(self.center, self.p)

    @property
    def sweep(self) -> float:
        """Signed sweep of an arc move: G3 counter-clockwise (> 0), G2 clockwise."""
        c = self.center
        a0 = math.atan2(self.p[1] - c[1], self.p[0] - c[0])
        a1 = math.atan2(self.q[1] - c[1], self.q[0] - c[0])
        d = (a1 - a0) % (2 * math.pi)
        if self.g == 3:
            return d or 2 * math.pi
        return (d - 2 * math.pi) if d else -2 * math.pi


def replay(text: str, kind: str = "laser", origin=(0.0, 0.0)) -> list[Move]:
    """Every motion of ``text`` as GRBL runs it.  ``on``: the tool cuts (laser: M3/M4 with
    S > 0; router and plotter: Z below 0, or at 0 for a pen).  ``origin``: where the head
    is when the program starts; None: unknown (a move from there starts at (None, None))."""
    x, y = origin if origin is not None else (None, None)
    z = None
    f = s = None
    spindle = False
    moves = []
    for line in gcodeparser.parse_gcode_lines(text):
        letter, code = line.command
        prm = line.params
        if letter == "M":
            if code in (3, 4):
                spindle = True
            elif code == 5:
                spindle = False
            if "S" in prm:
                s = float(prm["S"])
            continue
        if letter != "G":
            continue
        assert code in (0, 1, 2, 3, 17, 21, 90), line.gcode_str
        if "F" in prm:
            f = float(prm["F"])
        if "S" in prm:
            s = float(prm["S"])
        if code not in (0, 1, 2, 3):
            continue
        nx = float(prm["X"]) if "X" in prm else x
        ny = float(prm["Y"]) if "Y" in prm else y
        nz = float(prm["Z"]) if "Z" in prm else z
        center = None
        if code in (2, 3):
            center = (x + float(prm.get("I", 0.0)), y + float(prm.get("J", 0.0)))
        if (nx, ny, nz) != (x, y, z):
            if kind == "laser":
                on = code != 0 and spindle and bool(s)
            else:
                on = code != 0 and nz is not None and nz <= 0 and (nz == z)
            moves.append(Move(code, (x, y), (nx, ny), z, nz, center, f, s, on))
        x, y, z = nx, ny, nz
    return moves


def paths(moves: list[Move]) -> list[list[Move]]:
    """Runs of cutting XY moves (each without a break); a run that comes back to its start
    is one pass of a loop."""
    out, cur = [], []
    for m in moves:
        if m.on and m.p != m.q:
            if cur and cur[-1].q != m.p:
                out.append(cur)
                cur = []
            cur.append(m)
            if len(cur) > 1 and m.q == cur[0].p:     # a loop closed: the next pass is new
                out.append(cur)
                cur = []
        elif cur:
            out.append(cur)
            cur = []
    if cur:
        out.append(cur)
    return out


# ------------------------------------------------------------------ against the exact model
def _on_line(p, a, b) -> float:
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    L2 = dx * dx + dy * dy
    u = max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L2)) if L2 else 0.0
    return math.hypot(p[0] - ax - u * dx, p[1] - ay - u * dy)


def _matches(m: Move, seg) -> bool:
    """Move ``m`` lies on the model segment ``seg`` (exact: 1e-9 mm), in its direction."""
    from aidl_lang.output.part.part import Arc, Circle, Line
    if m.g == 1:
        if not isinstance(seg, Line):
            return False
        d = (seg.end[0] - seg.start[0], seg.end[1] - seg.start[1])
        e = (m.q[0] - m.p[0], m.q[1] - m.p[1])
        return (_on_line(m.p, seg.start, seg.end) < TOL and _on_line(m.q, seg.start, seg.end) < TOL
                and d[0] * e[0] + d[1] * e[1] > 0)
    if isinstance(seg, Circle):
        ccw = seg.ccw
    elif isinstance(seg, Arc):
        ccw = seg.sweep > 0
    else:
        return False
    if math.dist(m.center, seg.center) > TOL or abs(m.radius - seg.radius) > TOL \
            or abs(math.dist(m.q, seg.center) - seg.radius) > TOL or (m.g == 3) != ccw:
        return False
    if isinstance(seg, Arc):        # within the model arc's span
        for p in (m.p, m.q):
            a = math.atan2(p[1] - seg.center[1], p[0] - seg.center[0])
            rel = (a - seg.start_angle) % (2 * math.pi) if ccw else \
                (seg.start_angle - a) % (2 * math.pi)
            if rel > abs(seg.sweep) + 1e-9 and rel < 2 * math.pi - 1e-9:
                return False
    return True


def match_paths(text: str, output, kind="laser"):
    """Each cut path of ``text`` as ``(part, loop)`` of ``output`` whose segments hold every
    move exactly and whose perimeter the path's length equals; AssertionError otherwise."""
    loops = [(p, lp) for p in output.parts for lp in p.loops]
    found = []
    for path in paths(replay(text, kind)):
        length = sum(m.length for m in path)
        hit = None
        for p, lp in loops:
            if abs(length - lp.perimeter) > 1e-9 * max(1, len(lp.segments)):
                continue
            if all(any(_matches(m, s) for s in lp.segments) for m in path):
                hit = (p, lp)
                break
        found.append((hit, path))
    return found


def check_exact(text, output, passes=2, kind="laser"):
    """Every loop of ``output`` is cut ``passes`` times, each pass exactly the loop; every
    other cut is engraving."""
    found = match_paths(text, output, kind)
    counts: dict = {}
    for hit, path in found:
        if hit is not None:
            counts[id(hit[1])] = counts.get(id(hit[1]), 0) + 1
    for p in output.parts:
        for lp in p.loops:
            assert counts.get(id(lp), 0) == passes, (p.name, lp.is_hole, counts.get(id(lp), 0))
    return found


def check_holes_first(text, output, kind="laser"):
    """Within each part, every hole is cut (every pass) before the outline."""
    done_outer = set()
    for hit, _ in match_paths(text, output, kind):
        if hit is None:
            continue
        p, lp = hit
        if lp.is_hole:
            assert p.name not in done_outer, f"a hole of {p.name} cut after its outline"
        else:
            done_outer.add(p.name)


def check_settings(text, machine, output):
    """S = power % x max_power and F = the operation's speed on every cutting move."""
    ops = {}
    for hit, path in match_paths(text, output):
        op = "cut_inner" if hit is not None and hit[1].is_hole else \
            "cut_outer" if hit is not None else None
        for m in path:
            if op is None:
                continue
            o = machine.operation(op)
            assert m.f == pytest.approx(o.speed, abs=1e-9), (op, m.f)
            assert m.s == pytest.approx(o.power / 100 * machine.max_power, abs=1e-9), (op, m.s)
            ops[op] = True
    assert ops, "no cutting move seen"


def _output(path, kerf=None):
    src = path.read_text() if hasattr(path, "read_text") else path
    c = compile_source(src, str(path) if hasattr(path, "read_text") else "t.aidl")
    assert c.ok, [d.message for d in c.sink.items]
    return for_cutting(build(c.drawing, "t"), kerf)


BOX = ROOT / "examples" / "laser_box.aidl"

PLATE = """units mm
thickness 6 mm
solid plate {
    body = RoundedRectangle(center=(0, 0), width=100, height=60, radius=8)
    hole big { c = Circle(center=(-20, 0), radius=10) }
    hole slot { s = Slot(start=(10, 0), end=(30, 0), width=8) }
}
"""

CURVES = """units mm
solid egg {
    e = Ellipse(center=(0, 0), rx=40, ry=25, rotation=20 deg)
    hole eye { s = Spline(points=[(-10, 0), (0, 8), (12, 2), (4, -8)], closed=true) }
}
"""


# ------------------------------------------------------------------ tests
def test_laser_box_is_every_loop_exactly_holes_first_settings_followed():
    out = _output(BOX)
    m = from_dict({"max_power": 255, "cut_inner": {"power": 60, "speed": 500},
                   "cut_outer": {"power": 85, "speed": 350, "passes": 3}})
    text = gcode.job(out, m).text
    assert text.count("G3") + text.count("G2") > 0
    found = match_paths(text, out)
    counts = {}
    for hit, _ in found:
        if hit:
            counts[id(hit[1])] = counts.get(id(hit[1]), 0) + 1
    for p in out.parts:
        for lp in p.loops:
            assert counts[id(lp)] == (2 if lp.is_hole else 3)
    check_holes_first(text, out)
    check_settings(text, m, out)
    # engraving before every cut
    kinds = [hit is not None for hit, _ in found]
    assert kinds == sorted(kinds)
    # every line fits GRBL's 80-character line buffer; no exponents
    assert max(len(x) for x in text.splitlines() if not x.startswith(";")) <= 80
    assert not re.search(r"\d[eE][-+]?\d", text)


def test_arcs_circles_and_slots_exact_to_1e9():
    out = _output(PLATE)
    text = gcode.job(out).text
    check_exact(text, out, passes=2)
    check_holes_first(text, out)
    # the whole circle as two half-circles about its exact centre
    halves = [m for m in replay(text) if m.g in (2, 3) and m.on
              and math.dist(m.center, (-20, 0)) < TOL]
    assert len(halves) == 4 and all(abs(abs(m.sweep) - math.pi) < 1e-9 for m in halves)


@pytest.mark.parametrize("name", ["laser_box", "gear", "name_tag", "telephone", "wrench",
                                  "bottle_opener"])
def test_examples_exact_and_in_order(name):
    out = _output(ROOT / "examples" / f"{name}.aidl")
    text = gcode.job(out).text
    check_exact(text, out, passes=2)
    check_holes_first(text, out)
    assert max(len(x) for x in text.splitlines() if not x.startswith(";")) <= 80


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_travel_and_header_numbers(path):
    """The file's G0 travel (the replay's) is the header's, and the tour's travel is at most
    1.5 x the drawing's own order (measured 0.08-1.35, as tests/test_toolpath.py)."""
    from aidl_lang.output.fabrication.toolpath import Cut, travel
    out = _output(path)
    j = gcode.job(out)
    moves = replay(j.text)
    g0 = sum(m.length for m in moves if m.g == 0)
    assert g0 == pytest.approx(j.travel, abs=1e-6)
    head = re.search(r"; cut (?:([\d.]+) mm path x (\d+) passes = )?([\d.]+) mm[^,]*, "
                     r"travel ([\d.]+) mm", j.text)
    assert float(head[4]) == pytest.approx(j.travel, abs=0.051)
    cutlen = sum(m.length for m in moves if m.on)
    assert float(head[3]) == pytest.approx(cutlen, abs=0.051)
    # the path and its passes (issue 86): the replayed cut is the path that many times
    n = gcode.passes(j.runs)
    if n is not None and n > 1:
        assert int(head[2]) == n and float(head[1]) * n == pytest.approx(cutlen, abs=0.051 * n)
    else:
        assert sum(p * k for k, (p, _) in j.runs.items()) == pytest.approx(cutlen, abs=1e-6)
    plain = [Cut("engrave", s.part, list(s.segments), s.closed) for s in out.engrave] + \
        [Cut("cut", p.name, list(lp.segments), True) for p in out.parts for lp in p.loops]
    last = moves[-1].p                   # the way home to X0 Y0 comes on top of the tour
    assert g0 - math.dist(last, (0, 0)) <= 1.5 * travel(plain) + 1e-6


def test_ellipse_and_spline_within_curve_tol():
    """Sampled densely, the curve is within CURVE_TOL of the written arcs and the arcs
    within CURVE_TOL of the curve; the arcs chain tangentially enough to be one path."""
    out = _output(CURVES)
    text = gcode.job(out).text
    ps = paths(replay(text))
    assert len(ps) == 4                                  # 2 loops x 2 passes

    def dist_to_move(p, m):
        if m.g == 1:
            return _on_line(p, m.p, m.q)
        c = m.center
        a = math.atan2(p[1] - c[1], p[0] - c[0])
        a0 = math.atan2(m.p[1] - c[1], m.p[0] - c[0])
        rel = (a - a0) % (2 * math.pi) if m.sweep > 0 else (a0 - a) % (2 * math.pi)
        if rel <= abs(m.sweep):
            return abs(math.dist(p, c) - m.radius)
        return min(math.dist(p, m.p), math.dist(p, m.q))

    def dense(lp, n=4000):
        """The loop's curves sampled here from their own definitions (n points a piece)."""
        from aidl_lang.geometry.shapes.spline import bez_at
        from aidl_lang.output.part.part import EllipticArc, Spline
        pts = []
        for g in lp.segments:
            if isinstance(g, EllipticArc):
                pts += [g.at(g.start_param + g.sweep * k / n) for k in range(n + 1)]
            elif isinstance(g, Spline):
                pts += [bez_at(b, k / n) for b in g.spans for k in range(n + 1)]
            else:
                raise AssertionError(type(g))
        return np.asarray(pts)

    def to_polyline(P, x, y):
        a, b = P[:-1], P[1:]
        d = b - a
        L2 = np.maximum((d ** 2).sum(1), 1e-300)
        u = np.clip(((x - a[:, 0]) * d[:, 0] + (y - a[:, 1]) * d[:, 1]) / L2, 0, 1)
        return np.min(np.hypot(a[:, 0] + u * d[:, 0] - x, a[:, 1] + u * d[:, 1] - y))

    for p in out.parts:
        for lp in p.loops:
            curve = dense(lp)
            path = min(ps, key=lambda q: min(math.dist(q[0].p, tuple(x)) for x in curve))
            worst = max(min(dist_to_move(tuple(x), m) for m in path) for x in curve[::5])
            assert worst <= gcode.CURVE_TOL, worst
            # the arcs' own points, against the dense curve (chords of 1e-6 mm)
            pts = []
            for m in path:
                for k in range(1, 8):
                    if m.g == 1:
                        t = k / 8
                        pts.append((m.p[0] + (m.q[0] - m.p[0]) * t, m.p[1] + (m.q[1] - m.p[1]) * t))
                    else:
                        a0 = math.atan2(m.p[1] - m.center[1], m.p[0] - m.center[0])
                        a = a0 + m.sweep * k / 8
                        pts.append((m.center[0] + m.radius * math.cos(a),
                                    m.center[1] + m.radius * math.sin(a)))
            back = max(to_polyline(curve, x, y) for x, y in pts)
            assert back <= gcode.CURVE_TOL, back
            assert sum(m.length for m in path) == pytest.approx(lp.perimeter, rel=1e-4)
    assert len(replay(text)) > 20        # curves really became several arcs


def test_router_offsets_by_the_tool_radius_and_steps_down():
    out = _output(PLATE)
    m = DEFAULTS["router"]
    r = m.tool_diameter / 2
    text = gcode.job(out, m).text
    moves = replay(text, "router")
    assert "M3 S18000" in text
    # depths: 6 mm in 1.5 mm passes, plunged at the plunge feed
    plunges = [mv for mv in moves if mv.g == 1 and mv.p == mv.q and mv.z is not None and mv.z < 0]
    assert sorted({round(mv.z, 9) for mv in plunges}) == [-6, -4.5, -3, -1.5]
    assert all(mv.f == 300 for mv in plunges)
    # the big hole: arcs about (-20, 0) of radius 10 - r, clockwise; the outline's corners:
    # arcs about the rounded rectangle's corner centres of radius 8 + r
    cutting = [mv for mv in moves if mv.on and mv.g in (2, 3)]
    hole = [mv for mv in cutting if math.dist(mv.center, (-20, 0)) < TOL]
    assert hole and all(abs(mv.radius - (10 - r)) < TOL and mv.g == 2 for mv in hole)
    corners = [mv for mv in cutting if math.dist(mv.center, (42, 22)) < TOL]
    assert corners and all(abs(mv.radius - (8 + r)) < TOL and mv.g == 3 for mv in corners)
    lines = [mv for mv in moves if mv.on and mv.g == 1]
    assert any(abs(mv.p[0] - (50 + r)) < TOL and abs(mv.q[0] - (50 + r)) < TOL for mv in lines)
    # the tool is above the stock on every G0 in XY
    assert all(mv.z == m.safe_height for mv in moves if mv.g == 0 and mv.p != mv.q)
    check_holes_first_router(moves)


def check_holes_first_router(moves):
    """The outline (the moves beyond x = 50) comes after every hole's move."""
    last_hole = max(i for i, mv in enumerate(moves) if mv.on and mv.g == 2)
    first_outer = min(i for i, mv in enumerate(moves) if mv.on and mv.g == 3)
    assert last_hole < first_outer


def test_router_curves_as_biarcs_offset():
    out = _output(CURVES)
    text = gcode.job(out, DEFAULTS["router"]).text
    assert "G2" in text and "G3" in text


def test_tabs_leave_gaps_and_lead_in_starts_on_the_scrap_side():
    from aidl_lang.output.fabrication.toolpath import _inside
    out = _output(PLATE)
    m = from_dict({"tabs": 4, "tab_width": 3, "lead_in": 2})
    text = gcode.job(out, m).text
    moves = replay(text)
    outer = [lp for lp in out.parts[0].loops if not lp.is_hole][0]
    # moves with the beam off along the outline: 4 tabs x 3 mm x 2 passes
    off = [mv for mv in moves if mv.g != 0 and not mv.on and mv.p != mv.q]
    assert sum(mv.length for mv in off) == pytest.approx(4 * 3 * 2, abs=1e-6)
    for mv in off:
        assert any(_matches(mv, s) for s in outer.segments)
    # each closed cut starts with a 2 mm line onto the loop from outside / inside
    starts = [mv for prev, mv in zip(moves, moves[1:]) if prev.g == 0 and mv.g != 0]
    assert len(starts) == 3 * 2                        # 3 loops x 2 passes
    poly = np.asarray(outer.points())
    for first in starts:
        assert first.g == 1 and first.length == pytest.approx(2, abs=1e-9)
        hole = any(lp.is_hole and min(math.dist(first.q, tuple(x)) for x in lp.points()) < 1e-6
                   for lp in out.parts[0].loops)
        assert _inside(first.p, poly) == hole


def test_plotter_pen_up_and_down():
    out = _output(PLATE)
    text = gcode.job(out, DEFAULTS["plotter"]).text
    moves = replay(text, "plotter")
    assert "M3" not in text and "M4" not in text
    check_exact(text, out, passes=1, kind="plotter")


# ------------------------------------------------------------------ broken writers caught
def test_swapped_g2_g3_is_caught(monkeypatch):
    out = _output(PLATE)
    orig = gcode._Writer.out

    def swapped(self, line):
        if line.startswith(("G2 ", "G3 ")):
            line = ("G3" if line[1] == "2" else "G2") + line[2:]
        orig(self, line)
    monkeypatch.setattr(gcode._Writer, "out", swapped)
    with pytest.raises(AssertionError):
        check_exact(gcode.job(out).text, out)


def test_outlines_before_holes_is_caught(monkeypatch):
    from aidl_lang.output.fabrication import toolpath
    out = _output(PLATE)
    real = toolpath.plan

    def outer_first(o, origin=(0.0, 0.0), back=(), hatch=None):
        cuts = real(o, origin, back, hatch)
        return sorted(cuts, key=lambda c: c.operation != "cut_outer")
    monkeypatch.setattr(toolpath, "plan", outer_first)
    text = gcode.job(out).text
    check_exact(text, out)                      # the loops are still all there, exactly
    with pytest.raises(AssertionError):
        check_holes_first(text, out)


def test_wrong_power_is_caught(monkeypatch):
    out = _output(PLATE)
    m = from_dict({"max_power": 255})
    orig = gcode._Writer.setting

    def percent(self, feed, power=None):        # S written as the percent, not of max_power
        orig(self, feed, None if power is None else power / 2.55)
    monkeypatch.setattr(gcode._Writer, "setting", percent)
    with pytest.raises(AssertionError):
        check_settings(gcode.job(out, m).text, m, out)


def test_profile_warnings():
    out = _output(PLATE)
    j = gcode.job(out, from_dict({"kerf": 0.2, "thickness": 6}, "m.toml"))
    assert len(j.warnings) == 1 and "`kerf = 0.2`" in j.warnings[0] and "m.toml" in j.warnings[0]
    assert "; warning: the machine profile `m.toml` says `kerf" in j.text


# ------------------------------------------------------------------ front ends
def test_cli_estimate_line_errors_and_layout(tmp_path, capsys):
    from aidl_lang.cli.main import main
    o = tmp_path / "box.gcode"
    assert main(["render", str(BOX), "-o", str(o)]) == 0
    said = capsys.readouterr().out
    # the outlines cut twice, the engraving once (the built-in laser): said apart (issue 86)
    line = re.search(r"box\.gcode: (cut ([\d.]+) mm \(([\d.]+) mm path x 2 passes \+ "
                     r"([\d.]+) mm path x 1 pass\)), travel ([\d.]+) mm, about (\d+) min "
                     r"(\d+) s at the profile's speeds", said)
    assert line, said
    assert float(line[2]) == pytest.approx(2 * float(line[3]) + float(line[4]), abs=0.15)
    head = o.read_text().splitlines()[2]
    assert f"{line[1]}, travel {line[5]} mm" in head
    # errors: a missing file, bad TOML, an unknown key; exit 2, nothing written
    bad = tmp_path / "m.toml"
    for text, key in [(None, "cannot read"), ('kind = "laser', "is not TOML"),
                      ("tabz = 3", "`tabz` is not a profile key")]:
        if text is not None:
            bad.write_text(text)
        out = tmp_path / "x.gcode"
        prof = str(bad) if text is not None else str(tmp_path / "none.toml")
        assert main(["render", str(BOX), "-o", str(out), "--machine", prof]) == 2
        err = capsys.readouterr().err
        assert key in err and prof in err and len(err.strip().splitlines()) == 1
        assert not out.exists()
    # a warning on stderr for a profile's kerf unlike the program's
    bad.write_text("kerf = 0.25\n")
    assert main(["render", str(BOX), "-o", str(o), "--machine", str(bad)]) == 0
    assert "warning: the machine profile" in capsys.readouterr().err
    # the sheet layout: one file per sheet, each a program of its own
    pytest.importorskip("spyrrow")
    o = tmp_path / "sheet.gcode"
    assert main(["render", str(BOX), "--layout", "sheet", "--sheet", "200x150mm",
                 "-o", str(o), "--machine", "router"]) == 0
    said = capsys.readouterr().out
    files = sorted(tmp_path.glob("sheet*.gcode"))
    assert len(files) >= 2 and said.count("at the profile's speeds") == len(files)
    for f in files:
        t = f.read_text()
        assert t.startswith("; ") and t.rstrip().endswith("M2") and "G0 Z5" in t


def test_api_encode_with_machine(tmp_path):
    import aidl_lang
    r = aidl_lang.compile(path=str(ROOT / "examples" / "name_tag.aidl"))
    laser = r.encode("gcode").decode()
    router = r.encode("gcode", machine="router").decode()
    prof = tmp_path / "p.toml"
    prof.write_text("max_power = 255\n[cut_outer]\npower = 50\n")
    half = r.encode(".nc", machine=str(prof)).decode()
    assert "M4 S0" in laser and "M3 S18000" in router and re.search(r"^G1 (F400 )?S127.5$", half, re.M)
    with pytest.raises(Exception) as e:
        r.encode("gcode", machine={"kind": "drill"})
    assert "`kind` is `drill`" in str(e.value)


def test_mcp_render_writes_gcode_with_a_machine(tmp_path):
    pytest.importorskip("mcp")
    from aidl_lang.mcp import tools as T
    src = PLATE
    doc, _ = T.render(T.Workspace(tmp_path), source=src, output="p.gcode", width=64,
                      machine="router")
    text = (tmp_path / "p.gcode").read_text()
    assert doc["written"] == "p.gcode" and "M3 S18000" in text
    (tmp_path / "m.toml").write_text("tabz = 1\n")
    with pytest.raises(T.Refused) as e:
        T.render(T.Workspace(tmp_path), source=src, output="q.gcode", width=64,
                 machine="m.toml")
    assert "`tabz` is not a profile key" in str(e.value)
    assert not (tmp_path / "q.gcode").exists()


def test_router_paths_are_the_tool_offset_loops_holes_first_where_offsets_overlap():
    """examples/mounting_plate.aidl's washers lie closer than the tool: their offset outlines
    overlap their neighbours', and each washer's hole must still come before its outline.
    Each depth's path is exactly the loop offset by the tool radius (output/fabrication/layout.py's
    exact offset), 2 depths for 3 mm at 1.5 mm per pass."""
    out = _output(ROOT / "examples" / "mounting_plate.aidl")
    m = DEFAULTS["router"]
    text = gcode.job(out, m).text
    tooled, _, _ = gcode.routed_path(out, m)          # with the profile's dogbones
    check_exact(text, tooled, passes=2, kind="router")
    check_holes_first(text, tooled, kind="router")


def test_router_tabs_rise_to_tab_height_on_the_deep_passes():
    out = _output(PLATE)                                 # 6 mm thick: depths 1.5 ... 6
    m = from_dict({"kind": "router", "tabs": 2, "tab_width": 4, "tab_height": 1})
    moves = replay(gcode.job(out, m).text, "router")
    r = m.tool_diameter / 2
    # along the outline (x beyond the holes), moves at z = -5 over the tabs: 2 tabs x 4 mm on
    # the only depth below -5 (-6); everything else on the outline at its depth
    over = [mv for mv in moves if mv.g != 0 and mv.p != mv.q and mv.z == -5]
    assert sum(mv.length for mv in over) == pytest.approx(2 * 4, abs=1e-6)
    outer_len = 2 * (100 + 60 - 4 * 8) + 2 * math.pi * (8 + r)
    def outside(p):                                      # of the holes: on the outline
        return max(abs(p[0]) / 50, abs(p[1]) / 30) > 0.95
    deepest = [mv for mv in moves if mv.g != 0 and mv.p != mv.q and mv.z == -6
               and outside(mv.p) and outside(mv.q)]
    assert sum(mv.length for mv in deepest) == pytest.approx(outer_len - 8, abs=1e-6)
