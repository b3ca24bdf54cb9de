"""Reliefs where a router's bit cannot reach (issue 102; output/fabrication/reliefs.py).

Real programs through the parser, solver, booleans and G-code writer; the G-code re-read by
an independent reader (``gcodeparser``, replayed as GRBL runs it by test_gcode.replay) and
the tool's centre path measured against the drawn corners:

* the law: for a generated plate with a notch whose inside corners have any angle of
  60-150 degrees and a rotated rectangular hole, cut with a bit of 1-6 mm, every inside
  corner is reached (the tool's edge within 0.01 mm of the drawn corner, never past it) with
  ``relief = "dogbone"`` or ``"tbone"``, each relief's stroke removes no more material than
  a disc of the tool's radius (Manifold's exact area of the swept stadium inside the
  part), and without a relief the material stays ``r / sin(a/2) - r`` from each;
* examples/generators/drawer.aidl to the built-in router: every inside corner of its finger
  joints reached; with ``relief = "none"`` W0527 names the corners, located at each part,
  and the assembled fit check of the parts as routed fails (W0517 at each of its 16 joints),
  while it passes with dogbones and T-bones.
"""
from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

gcodeparser = pytest.importorskip("gcodeparser")
manifold3d = pytest.importorskip("manifold3d")

from aidl_lang.output import build, for_cutting  # noqa: E402
from aidl_lang.output.fabrication.machine import MachineError, from_dict  # noqa: E402
from aidl_lang.output.fabrication.reliefs import inside_corners  # noqa: E402
from aidl_lang.output.writers import gcode  # noqa: E402
from aidl_lang.pipeline import compile_source  # noqa: E402

from conftest import ROOT  # noqa: E402
from test_gcode import replay  # noqa: E402

REACH = 0.01        # mm: the tool's edge from the drawn corner (the bound)


def _fmt(p) -> str:
    return f"({p[0]!r}, {p[1]!r})"


def plate(angle_deg: float, turn_deg: float) -> tuple[str, list]:
    """A 100 x 60 mm plate with a notch from its top edge (bottom 36 mm wide, 14 mm deep, its
    walls at ``angle_deg`` to the bottom in the free space: a dovetail's socket below 90, a
    V above) and a 26 x 14 mm rectangular hole turned ``turn_deg``: the program and the
    drawn inside corners ``[(x, y, free-space angle in rad)]``."""
    a = math.radians(angle_deg)
    D, B, W, H = 14.0, 36.0, 100.0, 60.0
    lb, rb = (50 - B / 2, H - D), (50 + B / 2, H - D)
    run = D * math.cos(a) / math.sin(a)
    lt, rt = (lb[0] + run, H), (rb[0] - run, H)
    outline = [(0.0, 0.0), (W, 0.0), (W, H), rt, rb, lb, lt, (0.0, H)]
    t = math.radians(turn_deg)
    c, s = math.cos(t), math.sin(t)
    hole = [(30 + x * c - y * s, 20 + x * s + y * c)
            for x, y in ((-13, -7), (13, -7), (13, 7), (-13, 7))]
    src = ("units mm\nthickness 3 mm\nsolid plate {\n"
           f"    body = Polygon(points=[{', '.join(_fmt(p) for p in outline)}])\n"
           f"    hole window {{ w = Polygon(points=[{', '.join(_fmt(p) for p in hole)}]) }}\n"
           "}\n")
    corners = [(*lb, a), (*rb, a)] + [(*p, math.pi / 2) for p in hole]
    return src, corners


def _compiled(src: str):
    c = compile_source(src, "t.aidl")
    assert c.ok, [d.message for d in c.sink.items]
    return c, build(c.drawing, "t")


def _dist_to_move(mv, p) -> float:
    """Distance from ``p`` to the path of a replayed cutting move (line or arc)."""
    if mv.g == 1:
        (x0, y0), (x1, y1) = mv.p, mv.q
        dx, dy = x1 - x0, y1 - y0
        L2 = dx * dx + dy * dy
        u = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / L2))
        return math.hypot(p[0] - x0 - u * dx, p[1] - y0 - u * dy)
    c, r = mv.center, mv.radius
    a0 = math.atan2(mv.p[1] - c[1], mv.p[0] - c[0])
    a = math.atan2(p[1] - c[1], p[0] - c[0])
    sw = mv.sweep
    rel = (a - a0) % (2 * math.pi) if sw > 0 else (a0 - a) % (2 * math.pi)
    if rel <= abs(sw):
        return abs(math.dist(p, c) - r)
    return min(math.dist(p, mv.p), math.dist(p, mv.q))


def _cutting(moves, depth: float):
    return [mv for mv in moves if mv.on and mv.p != mv.q and mv.z == pytest.approx(depth)]


def _spikes(cuts):
    """The reliefs in cutting moves: a line to a point and straight back (in each closed
    run, also across its end and start, where a loop may begin)."""
    runs, cur = [], []
    for mv in cuts:
        if cur and cur[-1].q != mv.p:
            runs.append(cur)
            cur = []
        cur.append(mv)
    runs += [cur] if cur else []
    out = []
    for run in runs:
        pairs = list(zip(run, run[1:])) + ([(run[-1], run[0])] if run[-1].q == run[0].p
                                           and len(run) > 2 else [])
        out += [(a.p, a.q) for a, b in pairs
                if a.g == b.g == 1 and a.q == b.p and a.p == b.q]
    return out


def _stadium(p, q, r):
    CS = manifold3d.CrossSection
    n = 256
    disc = lambda c: CS.circle(r, n).translate(list(c))      # noqa: E731
    return CS.batch_hull([disc(p), disc(q)])


@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(angle=st.floats(60, 150), bit=st.floats(1, 6), turn=st.floats(0, 90),
       style=st.sampled_from(["dogbone", "tbone"]))
def test_every_relieved_corner_is_reached_and_no_relief_takes_more_than_a_disc(
        angle, bit, turn, style):
    src, drawn = plate(angle, turn)
    _, out = _compiled(src)
    r = bit / 2
    # the model's corners are the drawn ones, with their angles
    found = inside_corners(out.parts[0], r)
    assert len(found) == len(drawn) == 6
    for x, y, a in drawn:
        c = min(found, key=lambda c: math.dist(c.at, (x, y)))
        assert math.dist(c.at, (x, y)) < 1e-9 and c.angle == pytest.approx(a, abs=1e-9)
    text = gcode.job(out, from_dict({"kind": "router", "tool_diameter": bit,
                                     "relief": style})).text
    cuts = _cutting(replay(text, "router"), -3.0)
    for x, y, _ in drawn:
        near = min(_dist_to_move(mv, (x, y)) for mv in cuts)
        assert r - 1e-6 <= near <= r + REACH, (x, y, near, r)
    spikes = _spikes(cuts)
    assert len(spikes) == len(drawn)
    material = out.parts[0].shape
    for p, q in spikes:
        assert min(math.dist(q, (x, y)) for x, y, _ in drawn) == pytest.approx(r, abs=1e-6)
        removed = (_stadium(p, q, r) ^ material).area()
        assert 0 < removed <= math.pi * r * r, (p, q, removed, math.pi * r * r)
    # without a relief: the same corners, each left r / sin(a/2) - r away
    text = gcode.job(out, from_dict({"kind": "router", "tool_diameter": bit,
                                     "relief": "none"})).text
    assert "(W0527)" in text
    cuts = _cutting(replay(text, "router"), -3.0)
    assert not _spikes(cuts)
    for x, y, a in drawn:
        near = min(_dist_to_move(mv, (x, y)) for mv in cuts)
        assert near == pytest.approx(r / math.sin(a / 2), abs=1e-6)
        assert near - r > REACH


DRAWER = ROOT / "examples" / "generators" / "drawer.aidl"


def test_drawer_to_a_router_reaches_every_inside_corner_of_its_joints():
    """The built-in router relieves (dogbone); the G-code re-read: at the full depth every
    inside corner of the outline the machine cuts (the program's 0.15 mm kerf applied) has
    the tool's edge on it to 1e-6 mm, none past it; 272 corners over the 10 parts."""
    c, out = _compiled(DRAWER.read_text())
    cut = for_cutting(out, None)
    m = from_dict({"kind": "router"})
    assert m.relief == "dogbone"
    r = m.tool_diameter / 2
    job = gcode.job(cut, m)
    assert any("272 inside corners of 10 parts relieved (dogbone)" in n for n in job.notes)
    cuts = _cutting(replay(job.text, "router"), -3.0)
    corners = [k for p in cut.parts for k in inside_corners(p, r)]
    assert len(corners) == 272
    assert sorted({round(math.degrees(k.angle), 6) for k in corners}) == [90.0]
    import numpy as np
    lines = [mv for mv in cuts if mv.g == 1]
    A = np.array([mv.p for mv in lines])
    B = np.array([mv.q for mv in lines])
    e = B - A
    L2 = np.maximum((e * e).sum(1), 1e-300)
    worst = 0.0
    for k in corners:
        P = np.array(k.at)
        u = np.clip(((P - A) * e).sum(1) / L2, 0, 1)
        d = np.hypot(*(A + u[:, None] * e - P).T)
        near = min(d.min(), min(_dist_to_move(mv, k.at) for mv in cuts if mv.g != 1))
        assert near >= r - 1e-6, k
        worst = max(worst, near - r)
    assert worst <= 1e-6


def test_drawer_without_a_relief_is_w0527_at_each_part(tmp_path):
    from aidl_lang.cli.main import main
    prof = tmp_path / "router.toml"
    prof.write_text('kind = "router"\nrelief = "none"\n')
    import contextlib
    import io
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        rc = main(["render", str(DRAWER), "-o", str(tmp_path / "d.nc"), "--machine", str(prof)])
    assert rc == 0
    said, code = err.getvalue(), "W0527"
    assert said.count(f"warning[{code}]") == 10
    assert "does not reach 36 inside corners of part `desk_drawer.unit.carcass.back`" in said
    assert "the material stays up to 0.658 mm" in said
    # the back panel's line of std/boxes.aidl's drawer (the template's own, as a note)
    back = next(n for n, ln in enumerate((ROOT / "stdlib" / "boxes.aidl").read_text()
                                         .splitlines(), 1)
                if ln.startswith("        back = finger_panel(width=lo, height=ho"))
    assert f"std/boxes.aidl:{back}:16" in said and 'relief = "dogbone"' in said
    text = (tmp_path / "d.nc").read_text()
    cuts = _cutting(replay(text, "router"), -3.0)
    assert not _spikes(cuts)
    # the assembled fit check of the routed parts: the 16 finger joints collide without
    # reliefs (each joint's pair once; the first 10 said, `--json` lists all) and not with
    # dogbones or T-bones (the design's check passes)
    assert said.count("warning[W0517]: assembled as the router cuts them (3.175 mm bit, "
                      "with no relief)") == 10 and "and 6 more of W0517" in said
    assert "`desk_drawer.unit.carcass.bottom` and `desk_drawer.unit.carcass.back` collide: " \
        "they share 45.5 mm^3" in said
    for relief in ("dogbone", "tbone"):
        prof.write_text(f'kind = "router"\nrelief = "{relief}"\n')
        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            rc = main(["render", str(DRAWER), "-o", str(tmp_path / "d.nc"), "--machine",
                       str(prof)])
        assert rc == 0 and "W0517" not in err.getvalue()
        said = err.getvalue()
        if relief == "dogbone":
            assert "W0527" not in said
        else:
            # the 3 mm fingers are shorter than the 3.175 mm bit: a T-bone into a finger's
            # side opens through its end (issue 109), so each part's are cut as dogbones,
            # said once a part at the part's outline
            assert said.count("warning[W0527]") == 10, said
            assert "a T-bone would cut through the 2.92 mm of material between the corner " \
                "and another edge of the same outline" in said
            assert "each cut as a dogbone instead" in said


def test_relief_key_is_checked():
    with pytest.raises(MachineError, match='`relief` is \'dogbones\', not one of "dogbone"'):
        from_dict({"kind": "router", "relief": "dogbones"})
    assert from_dict({"kind": "laser"}).relief == "none"
    assert from_dict({"kind": "router", "relief": "tbone"}).relief == "tbone"


def test_mcp_render_to_a_router_says_the_corners_and_the_routed_fit(tmp_path):
    """The MCP `render` tool as `aidl render`: with `relief = "none"` W0527 at each part and
    the routed fit check's W0517; with the built-in router (dogbones) neither."""
    pytest.importorskip("mcp")
    from aidl_lang.mcp import tools as T
    (tmp_path / "none.toml").write_text('kind = "router"\nrelief = "none"\n')
    src = DRAWER.read_text()
    codes = {}
    for prof in ("none.toml", "router"):
        doc, _ = T.render(T.Workspace(tmp_path), source=src, output="d.nc", width=64,
                          machine=prof)
        codes[prof] = [d["code"] for d in doc.get("diagnostics", [])]
    assert codes["none.toml"].count("W0527") == 10 and codes["none.toml"].count("W0517") == 16
    assert "W0527" not in codes["router"] and "W0517" not in codes["router"]


@pytest.mark.parametrize("apart,said", [(3.0, 1), (3.2, 0)])
def test_parts_nearer_than_the_bit_are_w0531(tmp_path, apart, said):
    """Two 12 mm squares ``apart`` mm apart to the built-in router (3.175 mm bit): at 3 mm
    the bit's cut round each takes 0.175 mm of the other (the G-code replayed and swept: the
    law of tests/test_law_machine.py finds it), W0531 at the second part; at 3.2 mm nothing."""
    from aidl_lang.cli.main import main
    import contextlib
    import io
    f = tmp_path / "two.aidl"
    f.write_text("units mm\nthickness 3 mm\n"
                 "solid a { r = Rectangle(center=(0, 0), width=12, height=12) }\n"
                 f"solid b {{ r = Rectangle(center=({12 + apart}, 0), width=12, height=12) }}\n")
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        rc = main(["render", str(f), "-o", str(tmp_path / "t.nc"), "--machine", "router"])
    text = err.getvalue()
    assert rc == 0 and text.count("warning[W0531]") == said, text
    code = "W0531"
    if said:
        assert f":4:1: warning[{code}]: the router's bit (3.175 mm across) runs between parts " \
            "`model.a` and `model.b`, 3 mm apart near (7.50, " in text
        assert "its cut round each takes 0.175 mm of the other" in text
        assert "--layout sheet --gap 4mm" in text
    from benchmarks.laws import law_machine as law
    moves = law.replay((tmp_path / "t.nc").read_text(), "router")
    loops, opens, spikes = law.runs(moves, 3.0, True)
    c, out, cut = law.compiled(f.read_text(), str(f))
    found = law.measure(out, loops, opens, spikes, 3.175 / 2)
    assert len(found) == 2 * said      # each square loses material to the other's cut
    assert law.check_program(f.read_text(), str(f), machines=law.MACHINES[:1]) == []
