"""Machine files a machine can run safely (issue 83, reliability round seven): every G-code
program (laser, router, plotter) and HP-GL file travels to its first cut with the beam off
or the tool up, wherever that cut starts (a job starting at X0 Y0 cut from wherever the head
was); a lead-in keeps the promised 0.5 mm from every other cut, part and the sheet's edge
(measured with shapely on the replayed file, over generated layouts), or is shortened or
left out with a note; profile numbers that cannot mean anything (a tab of 0 mm, a lead-in
of 1e-308 mm) are refused with their range, and a laser operation at power 0 is said to cut
nothing.  The G-code is re-read by test_gcode's independent replay (``gcodeparser``), the
HP-GL by ``ezhpgl``."""
import math

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

gcodeparser = pytest.importorskip("gcodeparser")
shapely = pytest.importorskip("shapely")
from shapely.geometry import LineString, Point  # noqa: E402

from test_gcode import paths, replay  # noqa: E402

from aidl_lang.cli.main import main  # noqa: E402
from aidl_lang.output import build, for_cutting  # noqa: E402
from aidl_lang.output.fabrication.machine import DEFAULTS, MachineError, from_dict  # noqa: E402
from aidl_lang.output.writers import gcode  # noqa: E402
from aidl_lang.pipeline import compile_source  # noqa: E402

LAW = settings(deadline=None, max_examples=12,
               suppress_health_check=[HealthCheck.too_slow])


def _output(src: str):
    c = compile_source(src, "t.aidl")
    assert c.ok, [d.message for d in c.sink.items]
    return for_cutting(build(c.drawing, "t"), None)


def _plate(x0: float, y0: float, w: float = 20, h: float = 10) -> str:
    """A plate whose lower-left corner is at (x0, y0)."""
    return f"""solid plate {{
    body = Rectangle(center=({x0 + w / 2}, {y0 + h / 2}), width={w}, height={h})
    Fixed(body)
}}
"""


# ------------------------------------------------------------------ 1. the first travel
def check_travel_first(text: str, kind: str):
    """Replayed from an unknown position: the first cutting move comes after a travel (G0,
    the beam off / the tool up) that ends at its start, and nothing moves in XY between
    them; for a router or plotter that travel is above the work (z > 0)."""
    moves = replay(text, kind, origin=None)
    first = next(i for i, m in enumerate(moves) if m.on)
    cut = moves[first]
    assert cut.p[0] is not None, f"cuts from wherever the head is: {text[:300]}"
    travel = [j for j in range(first) if moves[j].g == 0 and moves[j].q == cut.p]
    assert travel, f"no travel to the first cut's start {cut.p}"
    j = travel[-1]
    assert all(moves[k].p == moves[k].q and not moves[k].on for k in range(j + 1, first))
    if kind != "laser":
        assert moves[j].z is not None and moves[j].z > 0, "travel with the tool down"


def check_hpgl_travel_first(data: bytes):
    """HP-GL re-read by ezhpgl's command reader: the pen goes down (PD, AA) only after a
    pen-up move (PU x,y) to where it starts."""
    import ezhpgl.raw
    up = None
    for c in ezhpgl.raw.parse_commands(data).commands:
        if c.name == "IN":
            up = None
        elif c.name == "PU":
            if c.args:
                up = tuple(c.args[-2:])
        elif c.name in ("PD", "AA"):
            assert up is not None, f"{c.raw} before any pen-up move"
            return up
    raise AssertionError("nothing drawn")


# the built-in router's tool path: the plate's left edge r right of x = 0 and its bottom at
# y = 0 puts a tool-path corner (an entry) at X0 Y0
R = 3.175 / 2
ORIGIN_JOBS = {"laser": _plate(0, 0), "plotter": _plate(0, 0), "router": _plate(R, 0)}


@pytest.mark.parametrize("kind", ["laser", "router", "plotter"])
def test_a_job_starting_at_the_origin_travels_there_first(kind):
    text = gcode.job(_output(ORIGIN_JOBS[kind]), DEFAULTS[kind]).text
    moves = replay(text, kind, origin=None)
    first = next(m for m in moves if m.on)
    assert first.p == (0.0, 0.0)                  # the case: the first cut starts at X0 Y0
    check_travel_first(text, kind)
    if kind == "laser":                           # G0 X0 Y0 S0 before M4's first burn
        lines = [ln for ln in text.splitlines() if not ln.startswith(";")]
        assert lines[lines.index("M4 S0") + 1] == "G0 X0 Y0 S0"


def test_hpgl_starting_at_the_origin_puts_the_pen_up_there_first():
    from aidl_lang.output.writers import hpgl
    data = hpgl.to_hpgl(_output(_plate(0, 0)))
    assert check_hpgl_travel_first(data.encode()) == (0.0, 0.0)


@LAW
@given(st.sampled_from(["laser", "router", "plotter"]),
       st.sampled_from([0.0, R, 0.5, 7.25]), st.sampled_from([0.0, R, 3.0]))
def test_every_machine_file_travels_to_its_first_cut_tool_up(kind, x0, y0):
    out = _output(_plate(x0, y0))
    check_travel_first(gcode.job(out, DEFAULTS[kind]).text, kind)
    from aidl_lang.output.writers import hpgl
    check_hpgl_travel_first(hpgl.to_hpgl(out).encode())


# ------------------------------------------------------------------ 2. lead-in clearance
CLEAR = gcode.LEAD_CLEARANCE


def _pts(m, step=0.02):
    """A replayed move as points (arcs at most ``step`` mm apart)."""
    if m.g in (0, 1):
        return [m.p, m.q]
    c, r, sw = m.center, m.radius, m.sweep
    a0 = math.atan2(m.p[1] - c[1], m.p[0] - c[0])
    n = max(2, math.ceil(abs(sw) * r / step))
    return [(c[0] + r * math.cos(a0 + sw * i / n), c[1] + r * math.sin(a0 + sw * i / n))
            for i in range(n + 1)]


def lead_in_clearances(text: str, kind: str = "laser"):
    """Each lead-in of the replayed ``text`` (a run's first move after a travel when it is a
    straight line from a point off the rest of the run: onto its loop from the scrap) as ``(length,
    distance to the nearest other cut path or lead-in, distance to its own loop's path from
    0.52 mm on)``, by shapely."""
    moves = replay(text, kind)
    after_travel, last = set(), None          # the moves whose last XY move was a travel
    for mv in moves:
        if last is not None and last.g == 0:
            after_travel.add(id(mv))
        if mv.p != mv.q:
            last = mv
    leads, runs = [], []
    for run in paths(moves):
        m = run[0]
        rest = [p for mv in run[1:] for p in _pts(mv)]
        if m.g == 1 and id(m) in after_travel and len(rest) > 1 and \
                LineString(rest).distance(Point(m.p)) > 1e-6:
            leads.append(m)
            runs.append(LineString(rest))
        else:
            runs.append(LineString([p for mv in run for p in _pts(mv)]))
    heads = [LineString([m.p, m.q]) for m in leads]
    out = []
    for m, seg in zip(leads, heads):
        end = Point(m.q)
        own = [r for r in runs if r.distance(end) < 1e-7]
        others = [r for r in runs if r.distance(end) >= 1e-7] + \
            [h for h, o in zip(heads, leads) if o.q != m.q]
        d_other = min((seg.distance(r) for r in others), default=math.inf)
        d_own = math.inf
        if m.length > CLEAR + 0.02:
            k = (CLEAR + 0.02) / m.length
            far = LineString([m.p, (m.q[0] + (m.p[0] - m.q[0]) * k,
                                    m.q[1] + (m.p[1] - m.q[1]) * k)])
            d_own = min((far.distance(r) for r in own), default=math.inf)
        out.append((m.length, d_other, d_own))
    return out


def kit(*solids: str) -> str:
    """An assembly of solids `a`, `b`, ... each given as its lines (``body = ...``, a hole
    line), each held where it is drawn (``Fixed(body)``)."""
    parts = [f"    solid {chr(97 + i)} {{\n"
             + "".join(f"        {ln}\n" for ln in lines.split("\n"))
             + "        Fixed(body)\n    }\n" for i, lines in enumerate(solids)]
    return "assembly kit {\n" + "".join(parts) + "}\n"


SHAPES = st.one_of(
    st.tuples(st.just("rect"), st.floats(6, 30), st.floats(6, 30)),
    st.tuples(st.just("disc"), st.floats(3, 15), st.just(0.0)))


@st.composite
def layouts(draw):
    """Two to four parts (rectangles and discs, some with a hole) in a row, each 0.05 to
    3 mm from the one before and shifted up or down: parts near enough that a lead-in has to
    keep clear of its neighbours."""
    src, x = [], 0.0
    n = draw(st.integers(2, 4))
    for _ in range(n):
        kind, a, b = draw(SHAPES)
        gap = draw(st.sampled_from([0.05, 0.3, 0.6, 1.0, 3.0]))
        dy = draw(st.floats(-8, 8))
        w = a if kind == "rect" else 2 * a
        cx = x + gap + w / 2
        body = (f"Rectangle(center=({cx:.4f}, {dy:.4f}), width={a:.4f}, height={b:.4f})"
                if kind == "rect" else f"Circle(center=({cx:.4f}, {dy:.4f}), radius={a:.4f})")
        hole = ""
        size = min(w, a if kind == "disc" else b)
        if size >= 12 and draw(st.booleans()):          # a hole the router's tool fits
            r = size / 5
            hole = f"\nhole h {{ c = Circle(center=({cx:.4f}, {dy:.4f}), radius={r:.4f}) }}"
        src.append(f"body = {body}{hole}")
        x += gap + w
    return kit(*src)


def check_lead_ins(job, lead: float, kind: str = "laser"):
    got = lead_in_clearances(job.text, kind)
    for length, d_other, d_own in got:
        assert d_other >= CLEAR - 1e-6, (length, d_other)
        assert d_own >= CLEAR - 1e-6, (length, d_own)
        assert length <= lead + 1e-9
    short = [g for g in got if g[0] < lead - 1e-9]
    if short:
        assert any("shortened to" in n for n in job.notes), job.notes
    return got


@LAW
@given(layouts(), st.sampled_from([2.0, 5.0, 30.0]), st.sampled_from(["laser", "router"]))
def test_no_lead_in_comes_nearer_than_the_clearance_to_another_cut(src, lead, kind):
    import dataclasses
    m = dataclasses.replace(DEFAULTS[kind], lead_in=lead)
    out = _output(src)
    job = gcode.job(out, m)
    check_lead_ins(job, lead, kind)
    # every closed cut has its lead-in or a note that it starts on its path
    loops = sum(len(p.loops) for p in out.parts)
    passes = 2 if kind == "laser" else 2             # 2 passes, or 2 depths of 1.5 mm
    n = len(lead_in_clearances(job.text, kind))
    if n < loops * passes:
        assert any("without a lead-in" in t for t in job.notes), job.notes


NEIGHBOURS = kit("body = Rectangle(center=(0, 0), width=40, height=40)",
                 "body = Rectangle(center=(0, 50), width=40, height=40)",
                 "body = Circle(center=(60, 0), radius=15)")


def test_laid_out_lead_ins_keep_the_clearance(tmp_path, capsys):
    """The round-seven case: laid out, a 30 mm lead-in ran along another part's edge
    0.038 mm away at full power; now each keeps 0.5 mm from every other cut."""
    pytest.importorskip("spyrrow")
    p = tmp_path / "k.aidl"
    p.write_text(NEIGHBOURS)
    (tmp_path / "m.toml").write_text("lead_in = 30\n")
    code = main(["render", str(p), "-o", str(tmp_path / "k.gcode"), "--layout", "sheet",
                 "--sheet", "200x200mm", "--machine", str(tmp_path / "m.toml")])
    said = capsys.readouterr()
    assert code == 0, said.err
    text = (tmp_path / "k.gcode").read_text()
    got = lead_in_clearances(text)
    assert len(got) == 3 * 2
    for length, d_other, d_own in got:
        assert d_other >= CLEAR - 1e-6 and d_own >= CLEAR - 1e-6, got


def test_a_lead_in_tangent_to_a_disc_is_moved_or_said():
    """The plate's lead-in runs from (10, 20) down onto its corner (10, 10) (alone, as
    before); a disc of radius 5 at (15, 15) touches that line: the lead-in ran tangent to it
    at distance 0 with no note (the ray test missed the disc's chords, which lie inside the
    circle); now it starts at another corner, its whole 10 mm clear of the disc."""
    src = kit("body = Rectangle(center=(0, 0), width=20, height=20)",
              "body = Circle(center=(15, 15), radius=5)")
    import dataclasses
    job = gcode.job(_output(src), dataclasses.replace(DEFAULTS["laser"], lead_in=10))
    got = check_lead_ins(job, 10)
    assert len(got) == 2 * 2 and all(g[0] == pytest.approx(10, abs=1e-9) for g in got)
    assert min(g[1] for g in got) > CLEAR


# ------------------------------------------------------------------ 4. profile numbers
@pytest.mark.parametrize("table, key, words", [
    ({"tabs": 4, "tab_width": 0}, "tab_width",
     "must be greater than 0 with `tabs = 4`: a number from 0.01 to 100 mm"),
    ({"lead_in": 1e-308}, "lead_in", "must be 0 (none) or a number from 0.01 to 100 mm, not "
     "1e-308"),
    ({"lead_in": 0.001}, "lead_in", "from 0.01 to 100 mm"),
    ({"units": "inch", "lead_in": 1e-5}, "lead_in", "(0.000394 to 3.94 in)"),
    ({"tab_width": 5e-324, "tabs": 2}, "tab_width", "from 0.01 to 100 mm"),
    ({"kind": "router", "tool_diameter": 1e-300}, "tool_diameter", "from 0.01 to 50 mm"),
])
def test_absurd_lengths_are_refused_with_their_range(table, key, words):
    with pytest.raises(MachineError) as e:
        from_dict(table, "m.toml")
    assert f"machine profile `m.toml`: `{key}` " in str(e.value)
    assert words in str(e.value)


def test_zero_lengths_still_mean_none():
    m = from_dict({"lead_in": 0, "tabs": 0, "tab_width": 0, "tab_height": 0}, "m.toml")
    assert (m.lead_in, m.tabs, m.tab_width) == (0, 0, 0)


PLATE = """solid plate {
    body = Rectangle(center=(30, 20), width=50, height=30)
    hole h { c = Circle(center=(20, 20), radius=4) }
    Fixed(body)
}
"""


def test_a_laser_operation_at_power_0_cuts_nothing_and_is_said():
    out = _output(PLATE)
    m = from_dict({"cut_outer": {"power": 0}}, "p0.toml")
    job = gcode.job(out, m)
    moves = replay(job.text)
    hole = 2 * math.pi * 4
    # what burns: the hole's two passes; the outline's 2 x 160 mm run at S0
    assert sum(mv.length for mv in moves if mv.on) == pytest.approx(2 * hole, abs=1e-6)
    assert job.cut == pytest.approx(2 * hole, abs=1e-6)           # 370.3 mm before
    assert job.dark == pytest.approx(2 * 160, abs=1e-6)
    assert ("the machine profile `p0.toml` gives `cut_outer.power = 0`: the 320.0 mm of cut "
            "outer run with the beam off and cut nothing") in job.warnings[0]
    assert job.summary("p.gcode").startswith(
        f"p.gcode: cut {hole:.1f} mm path x 2 passes = {2 * hole:.1f} mm (320.0 mm more with "
        "the beam off: power 0), travel")
    estimate, warnings, _ = gcode.read_summary(job.text.encode())
    assert warnings == job.warnings and "beam off" in estimate


def test_power_0_everywhere_reports_no_cut(tmp_path, capsys):
    p = tmp_path / "p.aidl"
    p.write_text(PLATE)
    (tmp_path / "m.toml").write_text("".join(f"[{op}]\npower = 0\n" for op in
                                             ("engrave", "score", "cut_inner", "cut_outer")))
    code = main(["render", str(p), "-o", str(tmp_path / "p.gcode"), "--machine",
                 str(tmp_path / "m.toml")])
    said = capsys.readouterr()
    assert code == 0
    assert "p.gcode: cut 0.0 mm (370.3 mm more with the beam off: power 0)" in said.out
    assert said.err.count("aidl: warning: the machine profile") == 2      # inner and outer
    assert not any(m.on for m in replay((tmp_path / "p.gcode").read_text()))


# ------------------------------------------------------------------ 3. the router's bit
def _slit_plate(bridge: float, extra: str = "") -> str:
    """A 60 x 40 plate with a slit along x = 30 stopped ``bridge`` mm short of both edges."""
    return f"""solid plate {{
    body = Rectangle(center=(30, 20), width=60, height=40)
    cut slit {{
        l = Line((30, {bridge}), (30, {40 - bridge}))
    }}{extra}
    Fixed(body)
}}
"""


def _render_cli(tmp_path, capsys, src, out, *args):
    p = tmp_path / "t.aidl"
    p.write_text(src)
    code = main(["render", str(p), "-o", str(tmp_path / out), *args])
    said = capsys.readouterr()
    assert code == 0, said.err
    return (tmp_path / out), said.out + said.err


def _pieces_after_the_bit(text: str, r: float) -> int:
    """The plate (60 x 40) less every full-depth cutting move of the replayed router file
    widened by the bit's radius (shapely): how many pieces the router leaves, counted apart
    from the writer."""
    from shapely.geometry import box
    from shapely.ops import unary_union
    moves = replay(text, "router")
    deepest = min(m.z for m in moves if m.on)
    swept = unary_union([LineString(_pts(m)).buffer(r, 64) for m in moves
                         if m.on and m.p != m.q and m.z == deepest])
    left = box(0, 0, 60, 40).difference(swept)
    return len([g for g in getattr(left, "geoms", [left]) if g.area > 1e-6])


@pytest.mark.parametrize("bridge, pieces", [(1.0, 2), (1.5, 2), (1.6, 1), (3.0, 1)])
def test_a_slit_the_router_widens_through_the_edges_is_W0510(tmp_path, capsys, bridge, pieces):
    """The design's numbers: bridges of 1 and 1.5 mm are less than the 3.175 mm bit's
    radius (1.5875 mm): the slot runs through both edges and the plate comes out in two
    pieces (said by nothing before); 1.6 and 3 mm leave bridges of 0.0125 and 1.41 mm."""
    f, said = _render_cli(tmp_path, capsys, _slit_plate(bridge), "p.gcode", "--machine",
                          "router")
    assert _pieces_after_the_bit(f.read_text(), R) == pieces     # the replayed file agrees
    if pieces == 1:         # 1.6 mm leaves 0.0125 mm: W0507 (tests/test_toolpath_walls.py)
        assert "W0510" not in said and ("W0507" in said) == (bridge - R < 0.5)
        return
    assert f"t.aidl:3:5: warning[W0510]: part `plate` comes out of the router in 2 pieces, " \
        "not 1" in said
    assert (f"(between through-cut `plate.slit.l` and the outline of `plate`: {bridge:g} mm "
            "wide, less than the bit's reach, 1.5875 mm)") in said
    assert said.count("comes out of the router") == 1      # located once, not again unlocated
    assert "; warning: part `plate` comes out of the router in 2 pieces" in f.read_text()


def test_the_laser_and_a_small_bit_leave_the_slit_alone(tmp_path, capsys):
    _, said = _render_cli(tmp_path, capsys, _slit_plate(1.0), "p.gcode")
    assert "W0510" not in said
    (tmp_path / "m.toml").write_text('kind = "router"\ntool_diameter = 1.5\n')
    f, said = _render_cli(tmp_path, capsys, _slit_plate(1.0), "p.gcode", "--machine",
                          str(tmp_path / "m.toml"))
    assert "W0510" not in said          # one piece; the 0.25 mm bridges left are W0507
    assert "the router's bit (1.5 mm across) leaves 0.25 mm of the bridge" in said
    assert _pieces_after_the_bit(f.read_text(), 0.75) == 1


def test_a_bridge_the_bit_cuts_away_without_splitting_is_W0507(tmp_path, capsys):
    """A slit 1 mm from a hole and another slit 2 mm from it: the bit joins them (less than
    its radius, less than its diameter) but the plate stays one piece: a located W0507 each
    (a note before, unlocated)."""
    extra = """
    hole h { c = Circle(center=(45, 20), radius=5) }
    cut near { l = Line((39, 10), (39, 30)) }
    cut twin { l = Line((32, 10), (32, 30)) }"""
    f, said = _render_cli(tmp_path, capsys, _slit_plate(3.0, extra), "p.gcode", "--machine",
                          "router")
    assert "W0510" not in said
    assert ("t.aidl:7:20: warning[W0507]: the router's bit (3.175 mm across) cuts away the "
            "strip of `plate` between through-cut `plate.near.l` and a hole of `plate` over "
            "7.5 mm of the cut near (39.00, 20.00): 1 mm as drawn") in said
    assert ("t.aidl:4:13: warning[W0507]: the router's bit (3.175 mm across) cuts away the "
            "strip of `plate` between through-cut `plate.slit.l` and through-cut "
            "`plate.twin.l` over 26 mm of the cut") in said
    assert "2 mm as drawn, and the tool takes its radius, 1.5875 mm, from each cut's side" \
        in said


@LAW
@given(st.floats(0.2, 4.0), st.floats(0.2, 4.0), st.sampled_from([1.0, 3.175, 6.0]))
def test_the_router_splits_a_plate_exactly_when_both_bridges_are_narrower_than_its_reach(
        low, high, tool):
    """A slit from ``low`` mm above the plate's bottom to ``high`` mm below its top: the
    plate comes apart exactly when both bridges are less than the tool radius; the G-code
    says W0510 then and only then."""
    import dataclasses
    src = f"""solid plate {{
    body = Rectangle(center=(30, 20), width=60, height=40)
    cut slit {{ l = Line((30, {low:.3f}), (30, {40 - high:.3f})) }}
    Fixed(body)
}}
"""
    r = tool / 2
    if min(abs(low - r), abs(high - r)) < 0.01:
        return                                           # too close to call by sampling
    job = gcode.job(_output(src), dataclasses.replace(DEFAULTS["router"], tool_diameter=tool))
    split = round(low, 3) < r and round(high, 3) < r
    assert _pieces_after_the_bit(job.text, r) == (2 if split else 1)
    assert any("comes out of the router in 2 pieces" in w for w in job.warnings) == split
