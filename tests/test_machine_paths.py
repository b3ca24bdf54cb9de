"""Machine paths (issue 70, "nothing silently wrong"): an edge two pieces share (a `cut` from
edge to edge) is cut once along its line, the outer edges keep their offset (router bit,
kerf) and a note says what the shared line costs each side; G-code lead-ins never cross
another part and stay on the sheet; tabs that do not fit are fitted, with a note.  Every
file is re-read (the G-code replayed as GRBL runs it by test_gcode's independent replay,
the DXF by ezdxf) and the pieces' sizes worked out from the tool centre's path."""
import math

import pytest

gcodeparser = pytest.importorskip("gcodeparser")
ezdxf = pytest.importorskip("ezdxf")

from test_gcode import replay  # noqa: E402

from aidl_lang.cli.main import main  # noqa: E402

R = 3.175 / 2                       # the built-in router's bit radius

SPLIT = """solid plate {
    body = Rectangle(center=(30, 15), width=60, height=30)
    cut split {
        a = Line((30, 0), (30, 30))
    }
    Fixed(body)
}
"""


def _render(tmp_path, capsys, src, out, *args, name="t.aidl", profile=None):
    p = tmp_path / name
    p.write_text(src)
    extra = []
    if profile is not None:
        (tmp_path / "m.toml").write_text(profile)
        extra = ["--machine", str(tmp_path / "m.toml")]
    code = main(["render", str(p), "-o", str(tmp_path / out), *extra, *args])
    said = capsys.readouterr()
    assert code == 0, said.err
    return (tmp_path / out), said.out + said.err


def _cutting(moves, z=None):
    """The cutting XY moves (at depth ``z`` for a router)."""
    return [m for m in moves if m.on and m.p != m.q and (z is None or m.z == z)]


def _lines_at(moves, axis: int) -> dict:
    """Straight cutting moves along ``axis`` (0: vertical lines, x fixed) -> mm cut there."""
    got: dict = {}
    for m in moves:
        if m.g == 1 and abs(m.p[axis] - m.q[axis]) < 1e-9:
            k = round(m.p[axis], 9)
            got[k] = got.get(k, 0.0) + m.length
    return got


# ------------------------------------------------------------------ 1. shared cuts
def test_router_cuts_the_shared_edge_once_and_keeps_the_outer_edges(tmp_path, capsys):
    f, said = _render(tmp_path, capsys, SPLIT, "p.gcode", profile='kind = "router"\n')
    text = f.read_text()
    moves = replay(text, "router")
    deepest = min(m.z for m in moves if m.on)
    cut = _cutting(moves, deepest)
    xs = _lines_at(cut, 0)                    # vertical tool-centre lines at full depth
    ys = _lines_at(cut, 1)
    # the outer edges r outside the design, the shared line on its own line (not two lines
    # r either side of it: 28.4125 and 31.5875 before)
    assert sorted(xs) == pytest.approx([-R, 30, 60 + R], abs=1e-9)
    assert sorted(ys) == pytest.approx([-R, 30 + R], abs=1e-9)
    # cut once per depth: 30 mm plus r past each outer edge
    assert xs[30.0] == pytest.approx(30 + 2 * R, abs=1e-9)
    # each piece as the bit leaves it: between two tool-centre lines less a radius each side
    x = sorted(xs)
    widths = [b - a - 2 * R for a, b in zip(x, x[1:])]
    assert widths == pytest.approx([30 - R, 30 - R], abs=1e-9)       # 26.825 each before
    y = sorted(ys)
    assert y[1] - y[0] - 2 * R == pytest.approx(30, abs=1e-9)
    note = (f"the shared cut between `plate` and `plate.piece1` is cut once along its line; "
            f"each side loses {R:g} mm (half the bit, 3.175 mm)")
    assert note in said and note in text
    assert "warning" not in said


def test_a_t_of_cuts_is_cut_once_per_line(tmp_path, capsys):
    src = SPLIT.replace("a = Line((30, 0), (30, 30))",
                        "a = Line((30, 0), (30, 30))\n        b = Line((30, 15), (60, 15))")
    f, said = _render(tmp_path, capsys, src, "g.gcode", profile='kind = "router"\n')
    moves = replay(f.read_text(), "router")
    deepest = min(m.z for m in moves if m.on)
    cut = _cutting(moves, deepest)
    xs, ys = _lines_at(cut, 0), _lines_at(cut, 1)
    assert sorted(xs) == pytest.approx([-R, 30, 60 + R], abs=1e-9)
    assert sorted(ys) == pytest.approx([-R, 15, 30 + R], abs=1e-9)
    # the long cut once (the left piece's whole side), the short one from it to the edge
    assert xs[30.0] == pytest.approx(30 + 2 * R, abs=1e-9)
    assert ys[15.0] == pytest.approx(30 + R, abs=1e-9)
    # every outer edge once: 2 x (60 + 30) mm of straight lines less the 4 corner arcs' ends
    assert sum(m.length for m in cut) == pytest.approx(
        2 * (60 + 30) + 2 * math.pi * R + 30 + 2 * R + 30 + R, abs=1e-6)
    # one note for the cut part (not one a pair of pieces: a grid's would be dozens)
    assert said.count("shared cut") == 1
    assert ("note: the 3 shared cuts between the 3 pieces of `plate` are each cut once along "
            f"their line; each side loses {R:g} mm (half the bit, 3.175 mm) along each") in said


def test_an_edge_shared_in_part_steps_out_square(tmp_path, capsys):
    # an L plate cut at x = 30 up to its inner corner: the left piece's right side is shared
    # from y = 0 to 20 and its own outline from 20 to 30
    src = """solid plate {
    body = Polygon(points=[(0, 0), (60, 0), (60, 20), (30, 20), (30, 30), (0, 30)])
    cut split { a = Line((30, 0), (30, 20)) }
}
"""
    f, said = _render(tmp_path, capsys, src, "l.gcode", profile='kind = "router"\n')
    moves = replay(f.read_text(), "router")
    deepest = min(m.z for m in moves if m.on)
    cut = _cutting(moves, deepest)
    segs = {(tuple(round(v, 9) for v in m.p), tuple(round(v, 9) for v in m.q)) for m in cut}
    r = round(R, 9)
    # the shared line on x = 30 runs r past the inner corner, a square step r across, then
    # the outline's own offset at x = 30 + r: the right piece's corner (30, 20) stays r
    # from every tool-centre path but the shared line (a diagonal step came 1.12 mm near)
    assert ((30.0, -r), (30.0, 20 + r)) in segs
    assert ((30.0, 20 + r), (30 + r, 20 + r)) in segs
    assert ((30 + r, 20 + r), (30 + r, 30.0)) in segs
    for m in cut:
        if m.g == 1 and not (m.p[0] == m.q[0] == 30.0):
            for k in range(21):
                p = (m.p[0] + (m.q[0] - m.p[0]) * k / 20, m.p[1] + (m.q[1] - m.p[1]) * k / 20)
                assert math.dist(p, (30, 20)) >= R - 1e-9, (m.p, m.q)


def test_kerf_keeps_the_outer_edges_and_cuts_the_shared_line_on_it(tmp_path, capsys):
    f, said = _render(tmp_path, capsys, SPLIT, "p.dxf", "--kerf", "0.2mm")
    xs = set()
    for e in ezdxf.readfile(str(f)).modelspace():
        pts = [tuple(p[:2]) for p in e.get_points()] if e.dxftype() == "LWPOLYLINE" else []
        pts += pts[:1]
        xs |= {round(a[0], 9) for a, b in zip(pts, pts[1:]) if abs(a[0] - b[0]) < 1e-12}
    # both loops have the shared line at x = 30 (before: 29.9 and 30.1, each loop offset
    # into its neighbour, both pieces 29.8 mm)
    assert sorted(xs) == pytest.approx([-0.1, 30, 60.1], abs=1e-9)
    assert ("note: the shared cut between `plate` and `plate.piece1` is cut once along its "
            "line; each side loses 0.1 mm (half the kerf, 0.2 mm)") in said


def test_kerf_on_a_disc_cut_in_two_runs_the_chord_on_to_the_offset_arc(tmp_path, capsys):
    # the chord is shared, the arcs offset 0.1 mm: each arc runs on to where the chord's line
    # meets the offset circle (x = +-sqrt(5.1^2 - 1)); before, the smaller half's arc was "too
    # short for an offset of 0.1 mm" (an arc running on to a kept line was taken for one eaten)
    src = """solid disc {
    body = Circle(center=(0, 0), radius=5)
    cut split { a = Line((-6, 1), (6, 1)) }
}
"""
    f, said = _render(tmp_path, capsys, src, "d.dxf", "--kerf", "0.2mm")
    x = math.sqrt(5.1 ** 2 - 1)
    chords, radii, ends = [], set(), []
    for e in ezdxf.readfile(str(f)).modelspace():
        if e.dxftype() == "ARC":
            radii.add(round(e.dxf.radius, 9))
            for a in (e.dxf.start_angle, e.dxf.end_angle):
                px, py = e.dxf.radius * math.cos(math.radians(a)), \
                    e.dxf.radius * math.sin(math.radians(a))
                assert py == pytest.approx(1, abs=1e-9)
                ends.append(px)
            continue
        if e.dxftype() == "LINE":
            chords.append((tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]))
            continue
        pts = [tuple(p) for p in e.get_points("xyb")]
        pairs = zip(pts, pts[1:] + (pts[:1] if e.closed else []))
        for (x0, y0, b), (x1, y1, _) in pairs:
            if b == 0:
                chords.append(((x0, y0), (x1, y1)))
            else:
                c = math.dist((x0, y0), (x1, y1))
                radii.add(round(c / (2 * math.sin(2 * math.atan(abs(b)))), 9))
    # the chord's line once, from -6 to 6 (before: both halves' outlines cut it again): the
    # shared stretch in the disc's outline, the through-cut's two ends past the disc as strokes
    # of their own (each place cut once: part._cut_once, issue 83)
    spans = sorted(sorted((p[0], q[0])) for p, q in chords)
    assert all(p[1] == q[1] == 1.0 for p, q in chords)
    assert spans[0][0] == -6.0 and spans[-1][1] == 6.0
    assert all(a[1] == pytest.approx(b[0], abs=1e-9) for a, b in zip(spans, spans[1:]))
    assert sum(hi - lo for lo, hi in spans) == pytest.approx(12.0, abs=1e-9)
    # both halves' arcs offset 0.1 mm, each running on to the chord's line
    assert radii == {5.1}
    assert sorted(round(v, 9) for v in ends) == pytest.approx([-x, -x, x, x], abs=1e-9)
    assert ("note: the shared cut between `disc` and `disc.piece1` is cut once along its "
            "line; each side loses 0.1 mm (half the kerf, 0.2 mm) along it") in said


def test_laser_with_a_kerf_cuts_the_shared_line_once_a_pass(tmp_path, capsys):
    f, said = _render(tmp_path, capsys, "kerf 0.2 mm\n" + SPLIT, "p.gcode")
    cut = _cutting(replay(f.read_text()))
    xs = _lines_at(cut, 0)
    assert sorted(xs) == pytest.approx([-0.1, 30, 60.1], abs=1e-9)
    # 2 passes (the built-in laser), the shared line 30.2 mm once in each
    assert xs[30.0] == pytest.approx(2 * 30.2, abs=1e-9)
    assert xs[-0.1] == pytest.approx(2 * 30, abs=1e-9)
    assert "each side loses 0.1 mm (half the kerf, 0.2 mm)" in said


def test_laid_out_pieces_are_apart_and_offset_whole(tmp_path, capsys):
    pytest.importorskip("spyrrow")
    f, said = _render(tmp_path, capsys, SPLIT, "p.dxf", "--kerf", "0.2mm", "--layout", "sheet",
                      "--sheet", "200x100mm")
    boxes = []
    for e in ezdxf.readfile(str(f)).modelspace():
        if e.dxftype() == "LWPOLYLINE":
            x = [p[0] for p in e.get_points()]
            y = [p[1] for p in e.get_points()]
            boxes += [max(x) - min(x), max(y) - min(y)]
    # each piece on its own: the kerf offset all round (30.2 x 30.2), nothing shared
    assert boxes == pytest.approx([30.2] * 4, abs=1e-6)
    assert "shared cut" not in said


# ------------------------------------------------------------------ 2. lead-ins
TWO = """assembly kit {
    solid a {
        body = Rectangle(center=(0, 0), width=40, height=40)
        Fixed(body)
    }
    solid b {
        body = Rectangle(center=(42, -5), width=40, height=40)
        Fixed(body)
    }
}
"""


def _leads(moves):
    """Each cut's first cutting move after a travel: the lead-in."""
    return [m for prev, m in zip(moves, moves[1:]) if prev.g == 0 and m.g != 0 and m.on]


def _in_box(p, box, eps=1e-9) -> bool:
    return box[0] + eps < p[0] < box[2] - eps and box[1] + eps < p[1] < box[3] - eps


def test_lead_in_never_runs_through_a_neighbouring_part(tmp_path, capsys):
    # 2 mm between the parts, 5 mm lead-ins: b's lead-in began at (17, 15), 3 mm inside a
    f, said = _render(tmp_path, capsys, TWO, "k.gcode", profile="lead_in = 5\n")
    moves = replay(f.read_text())
    parts = [(-20, -20, 20, 20), (22, -25, 62, 15)]
    leads = _leads(moves)
    assert len(leads) == 2 * 2                                  # 2 loops x 2 passes
    for m in leads:
        assert m.length == pytest.approx(5, abs=1e-9)          # room for the whole of it
        own = [b for b in parts if _in_box(m.q, b, -1e-9)]
        assert len(own) == 1                                    # it ends on its own part
        for k in range(11):                                     # and touches no other
            p = (m.p[0] + (m.q[0] - m.p[0]) * k / 10, m.p[1] + (m.q[1] - m.p[1]) * k / 10)
            assert not any(_in_box(p, b, -1e-9) for b in parts if b not in own), (m.p, m.q)


def test_lead_in_in_a_small_hole_is_shortened_and_said(tmp_path, capsys):
    src = """solid p {
    body = Rectangle(center=(0, 0), width=40, height=40)
    hole h { c = Circle(center=(0, 0), radius=2) }
    Fixed(body)
}
"""
    f, said = _render(tmp_path, capsys, src, "h.gcode", profile="lead_in = 5\n")
    moves = replay(f.read_text())
    inner = [m for m in _leads(moves) if math.dist(m.q, (0, 0)) == pytest.approx(2, abs=1e-9)]
    # left out before (its start was past the hole); now across the hole to 0.5 mm short
    # of its far side (4 - 0.5 mm, less the 0.01 mm allowed for the chords the clearance is
    # measured to, which lie a hair inside the circle)
    assert len(inner) == 2
    for m in inner:
        assert 3.48 < m.length <= 3.49
        assert 2 - math.dist(m.p, (0, 0)) >= 0.5              # 0.5 mm from the far side
    assert "1 lead-in of `p` shortened to 3.49 mm (of 5 mm)" in said


def test_lead_in_stays_on_the_sheet(tmp_path, capsys):
    pytest.importorskip("spyrrow")
    src = """solid a {
    body = Rectangle(center=(0, 0), width=40, height=40)
    Fixed(body)
}
"""
    f, said = _render(tmp_path, capsys, src, "s.gcode", "--layout", "sheet",
                      "--sheet", "100x100mm", profile="lead_in = 5\n")
    moves = replay(f.read_text())
    # the part 1.5 mm from the sheet's corner: the lead-in began at y = -1.98 before
    for m in moves:
        if m.on or m.g == 0 and m.q != (0.0, 0.0):
            for p in (m.p, m.q):
                assert -1e-9 <= p[0] <= 100 and -1e-9 <= p[1] <= 100, (m.p, m.q)
    assert all(m.length == pytest.approx(5, abs=1e-9) for m in _leads(moves))


# ------------------------------------------------------------------ 3. tabs
def test_tabs_that_do_not_fit_are_fewer_and_said(tmp_path, capsys):
    src = """solid sq {
    body = Rectangle(center=(0, 0), width=25, height=25)
    Fixed(body)
}
"""
    f, said = _render(tmp_path, capsys, src, "t.gcode",
                      profile="tabs = 4\ntab_width = 20\n")
    moves = replay(f.read_text())
    # the beam off along the 100 mm outline: 2 tabs x 20 mm x 2 passes (none before)
    off = [m for m in moves if m.g != 0 and not m.on and m.p != m.q]
    assert sum(m.length for m in off) == pytest.approx(2 * 20 * 2, abs=1e-6)
    assert sum(m.length for m in _cutting(moves)) == pytest.approx((100 - 40) * 2, abs=1e-6)
    assert ("4 tabs of 20 mm do not fit the 100 mm cut of `sq` (tabs take at most half of "
            "it): cut with 2 tabs of 20 mm") in said


def test_fit_tabs():
    from aidl_lang.output.writers.gcode import fit_tabs
    assert fit_tabs(100, 4, 3) == (4, 3)
    assert fit_tabs(100, 4, 20) == (2, 20)
    assert fit_tabs(100, 4, 25) == (1, 25)          # exactly half: one tab
    assert fit_tabs(30, 2, 20) == (1, 7.5)          # not even one: a quarter of the cut
    assert fit_tabs(100, 0, 20) == (0, 0.0)
