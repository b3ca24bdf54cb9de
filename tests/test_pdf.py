"""The PDF template (`-o x.pdf`, issue 50): every file re-read by an independent reader,
pdfplumber (pdfminer.six), and compared with the design (the compiled exact output model):
page sizes; every cut and engraving line's end points to 1e-6 mm at 72/25.4 pt per mm (with
the page's or tile's offset); every arc and circle as a chain of Béziers whose ends are the
arc's to 1e-6 mm, whose turning adds up to the arc's sweep (its direction too) and whose
points stay within ARC_TOL (1e-3 mm) of the circle; spline spans as their own Béziers; the
scale bar 100 mm long to 1e-6 mm with ticks every 10 mm; tiles that cover every point of the
design at the right place and overlap by 10 mm.  Broken writers (a scale of 72/25.5, half
turns in one Bézier, Béziers bulging the wrong way, a 5 mm overlap) are caught."""
import io
import math
from pathlib import Path

import numpy as np
import pytest

pdfplumber = pytest.importorskip("pdfplumber")
pytest.importorskip("reportlab")

from aidl_lang import api                                            # noqa: E402
from aidl_lang.cli.main import main                                  # noqa: E402
from aidl_lang.output import for_cutting                             # noqa: E402
from aidl_lang.output.part.extent import extent                           # noqa: E402
from aidl_lang.output.part.part import (Arc, Circle, EllipticArc, Line,   # noqa: E402
                                   MissingDependency, OutputError, Spline)
from aidl_lang.output.writers import pdf as W                        # noqa: E402
from aidl_lang.output.writers import beziers as B                     # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"
K = 72.0 / 25.4              # pt per mm: the test's own, never the writer's
EXACT = 1e-6                 # mm
BOUND = 1e-3                 # mm: the stated most a Bézier strays from its arc
CHECK = "100 mm \u2014 check this is 100 mm before cutting"
BLACK, BLUE = (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)


# ------------------------------------------------------------------ the reader
def read(data: bytes) -> list[dict]:
    """Each page: its size (pt), its stroked pieces by (colour, width) as ('l', p0, p1) or
    ('c', p0, p1, p2, p3) in pt with y up, its words with their positions (pt, y up)."""
    pages = []
    with pdfplumber.open(io.BytesIO(data)) as pdf:
        for pg in pdf.pages:
            h = float(pg.height)
            pieces: dict = {}
            for kind in ("line", "rect", "curve"):
                for o in pg.objects.get(kind, []):
                    key = (tuple(float(v) for v in o["stroking_color"]), float(o["linewidth"]))
                    out = pieces.setdefault(key, [])
                    cur = start = None
                    for op, *pts in o["path"]:
                        pts = [(float(x), h - float(y)) for x, y in pts]
                        if op == "m":
                            cur = start = pts[0]
                        elif op == "l":
                            out.append(("l", cur, pts[0]))
                            cur = pts[0]
                        elif op == "c":
                            out.append(("c", cur, *pts))
                            cur = pts[2]
                        elif op == "h":
                            if math.dist(cur, start) > 1e-9:
                                out.append(("l", cur, start))
                            cur = start
            words = [(w["text"], float(w["x0"]), h - float(w["bottom"]), float(w["x1"]),
                      h - float(w["top"])) for w in pg.extract_words()]
            big = [c["text"] for c in pg.chars if round(float(c["size"])) == 22]
            rects = [(tuple(float(v) for v in o["stroking_color"]), float(o["linewidth"]),
                      float(o["x0"]), h - float(o["bottom"]), float(o["x1"]), h - float(o["top"]))
                     for o in pg.objects.get("rect", [])]
            pages.append({"size": (float(pg.width), float(pg.height)), "pieces": pieces,
                          "rects": rects,
                          "words": words, "text": pg.extract_text(), "label": "".join(big)})
    return pages


def mm(p, off):
    """A page point (pt) in the drawing's mm, the page's bottom-left corner at ``off``."""
    return (p[0] / K + off[0], p[1] / K + off[1])


def bez(b, t):
    p0, p1, p2, p3 = (np.array(q) for q in b)
    return (1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * p1 + 3 * (1 - t) * t ** 2 * p2 + t ** 3 * p3


def design_segments(output, cut: bool):
    if cut:
        return [s for p in output.parts for lp in p.loops for s in lp.segments]
    return [s for st in output.engrave for s in st.segments]


def check_geometry(output, page: dict, off, colour, width, cut=True, window=None):
    """Every segment of the design (cut or engraving) on ``page`` exactly, and nothing else
    of that colour and width.  ``window``: only the design's parts drawn on this tile."""
    pieces = [[q[0]] + [mm(p, off) for p in q[1:]] for q in page["pieces"].get((colour, width), [])]
    lines = np.array([q[1] + q[2] for q in pieces if q[0] == "l"]).reshape(-1, 4)
    curves = [q[1:] for q in pieces if q[0] == "c"]
    starts = np.array([c[0] for c in curves]).reshape(-1, 2)
    segs = design_segments(output, cut)
    if window is not None:
        segs = [s for s in segs if on_page(s, window)]
    used = 0
    for s in segs:
        if isinstance(s, Line):
            d = np.abs(lines - np.array(s.start + s.end)).max(axis=1) if len(lines) else [1]
            assert min(d) <= EXACT, f"line {s} not in the PDF (off by {min(d):.3g} mm)"
            used += 1
        elif isinstance(s, (Arc, Circle)):
            used += check_arc(s, curves, starts)
        elif isinstance(s, Spline):
            for b in s.spans:
                d = [max(math.dist(a, q) for a, q in zip(b, c)) for c in curves]
                assert min(d) <= EXACT, "a spline span is not its own Bézier"
                used += 1
        else:
            assert isinstance(s, EllipticArc)
            used += check_ellipse(s, curves, starts)
    if window is None:              # nothing more: every line and Bézier is the design's
        assert used == len(lines) + len(curves), (used, len(lines), len(curves))
    return used


def check_arc(s, curves, starts) -> int:
    """The chain of Béziers from the arc's start: each one's ends on the circle to 1e-6 mm,
    its points (the middle too) within BOUND, the turning adding up to the sweep, ending at
    the arc's end.  Returns the number of Béziers."""
    c, r = np.array(s.center), s.radius
    if isinstance(s, Circle):
        sweep = 2 * math.pi if s.ccw else -2 * math.pi
        begin = end = (c[0] + r, c[1])
    else:
        sweep, begin, end = s.sweep, s.start, s.end
    here, turned, n = np.array(begin), 0.0, 0
    tol = 4 * EXACT / r + 1e-12          # rad: the angle of ends read to 1e-6 mm
    while abs(turned - sweep) > tol:
        d = np.abs(starts - here).max(axis=1)
        cand = [i for i in np.flatnonzero(d <= EXACT)
                if abs(math.dist(curves[i][3], c) - r) <= EXACT]
        assert cand, f"no Bézier of {s} from {tuple(here)} (turned {turned} of {sweep})"
        b = curves[cand[0]]
        pts = np.array([bez(b, t) for t in np.linspace(0, 1, 41)])
        dev = np.abs(np.hypot(*(pts - c).T) - r)
        assert dev.max() <= BOUND, f"a Bézier of {s} strays {dev.max():.3g} mm"
        assert dev[20] <= BOUND                               # its middle
        a0 = math.atan2(b[0][1] - c[1], b[0][0] - c[0])
        a1 = math.atan2(b[3][1] - c[1], b[3][0] - c[0])
        step = (a1 - a0 + math.pi) % (2 * math.pi) - math.pi
        assert abs(step) <= math.pi / 2 + tol, "a piece over a quarter turn"
        turned += step
        here = np.array(b[3])
        n += 1
        assert n <= 1000 and abs(turned) <= abs(sweep) + tol, f"{s} runs the wrong way"
    assert math.dist(here, end) <= EXACT
    return n


def check_ellipse(s, curves, starts) -> int:
    n, here = 0, np.array(s.start)
    e = s.curve
    while math.dist(here, s.end) > EXACT or n == 0:
        d = np.abs(starts - here).max(axis=1)
        i = int(np.argmin(d))
        assert d[i] <= EXACT
        for t in np.linspace(0, 1, 21):
            p = bez(curves[i], t) - np.array(e.center)
            co, si = math.cos(e.rotation), math.sin(e.rotation)
            u, v = (co * p[0] + si * p[1]) / e.rx, (-si * p[0] + co * p[1]) / e.ry
            assert abs(math.hypot(u, v) - 1) * max(e.rx, e.ry) <= BOUND * 1.01
        here = np.array(curves[i][3])
        n += 1
        assert n <= 1000
    return n


def check_scale_bar(page: dict):
    """One black 0.5 pt horizontal line exactly 100 mm long, 11 ticks every 10 mm on it."""
    (bar,) = page["pieces"][(BLACK, W.BAR_WIDTH)]
    _, (ax, ay), (bx, by) = bar
    assert ay == by
    assert abs((bx - ax) / K - 100.0) <= EXACT, f"the bar is {(bx - ax) / K} mm"
    ticks = sorted(q[1][0] for q in page["pieces"][(BLACK, W.TICK_WIDTH)])
    assert len(ticks) == 11
    for i, x in enumerate(ticks):
        assert abs((x - ax) / K - 10 * i) <= EXACT
    assert CHECK in page["text"]


def page_origin(output):
    """The drawing point at the bottom-left corner of the page from the drawing (the
    documented layout: the drawing's extent, 10 mm margin, the footer below)."""
    x0, y0, _, _ = extent(output)
    return (x0 - W.MARGIN, y0 - W.MARGIN - W.FOOTER)


def compiled(name, **kw):
    r = api.compile(path=EX / f"{name}.aidl", **kw)
    assert r.ok
    return r


# ------------------------------------------------------------------ one page
@pytest.mark.parametrize("name", ["laser_box", "gear", "name_tag", "violin", "telephone"])
def test_one_page_is_the_design_exactly(name):
    r = compiled(name)
    out = for_cutting(r.output, None)                        # what encode writes
    (page,) = read(r.encode("pdf"))
    x0, y0, x1, y1 = extent(out)
    w = max(x1 - x0 + 20, 140.0)
    assert page["size"][0] / K == pytest.approx(w, abs=1e-3)
    assert page["size"][1] / K == pytest.approx(y1 - y0 + 20 + W.FOOTER, abs=1e-3)
    off = page_origin(out)
    n = check_geometry(out, page, off, BLACK, W.CUT_WIDTH)
    assert n >= len(design_segments(out, True))
    if out.engrave:
        check_geometry(out, page, off, BLUE, W.ENGRAVE_WIDTH, cut=False)
    check_scale_bar(page)
    assert r.output.title in page["text"]


def test_part_names_are_printed_inside_their_parts():
    r = compiled("laser_box")
    (page,) = read(r.encode("pdf"))
    off = page_origin(r.output)
    words = {t: (mm((a, b), off), mm((c, d), off)) for t, a, b, c, d in page["words"]}
    for p in r.output.parts:
        assert p.name in words, p.name
        (a, b), (c, d) = words[p.name]
        bx0, by0, bx1, by1 = extent(type(r.output)(parts=[p]))
        assert bx0 < a < c < bx1 and by0 < b < d < by1, p.name


def test_engraving_is_blue_and_exact_on_the_name_tag():
    r = compiled("name_tag")
    (page,) = read(r.encode("pdf"))
    n = check_geometry(r.output, page, page_origin(r.output), BLUE, W.ENGRAVE_WIDTH, cut=False)
    assert n >= 440                                          # the text's strokes, the dots
    assert (BLUE, W.CUT_WIDTH) not in page["pieces"]


def test_bezier_bound_as_stated():
    # each piece's radial error bound (beziers.arc_error) is kept under ARC_TOL; sampled here
    for r in (0.5, 3.0, 3.7, 50.0, 1000.0, 1e5):
        for sweep in (0.1, math.pi / 2, math.pi, 2 * math.pi, -3.0):
            n = B.arc_pieces(r, sweep, W.ARC_TOL)
            assert abs(sweep) / n <= math.pi / 2 + 1e-12
            a = Arc((1.0, 2.0), r, 0.3, sweep)
            bs = B.arc_beziers(a, W.ARC_TOL)
            assert len(bs) == n and bs[0][0] == a.start
            here, worst = a.start, 0.0
            for b in bs:
                assert math.dist(b[0], here) <= 1e-9          # the joints meet
                pts = np.array([bez(b, t) for t in np.linspace(0, 1, 201)])
                worst = max(worst, np.abs(np.hypot(*(pts - a.center).T) - r).max())
                here = b[3]
            assert worst <= W.ARC_TOL * 1.001, (r, sweep, worst)
            assert here == a.end
    assert B.arc_pieces(100.0, math.pi / 2, W.ARC_TOL) > 1     # 2.7e-2 mm as one piece: split


def test_spline_spans_are_exact_on_the_violin():
    r = compiled("violin")
    (page,) = read(r.encode("pdf"))
    assert any(isinstance(s, Spline) for s in design_segments(r.output, True))
    check_geometry(r.output, page, page_origin(r.output), BLACK, W.CUT_WIDTH)


def test_ellipse_as_beziers():
    r = api.compile("solid s {\n    e = Ellipse(center=(10, 5), rx=30, ry=12, rotation=20 deg)\n"
                    "    hole h { c = Circle(center=(10, 5), radius=4) }\n}\n")
    if not r.ok:
        pytest.skip("no Ellipse shape")
    segs = design_segments(r.output, True)
    assert any(isinstance(s, EllipticArc) for s in segs)
    (page,) = read(r.encode("pdf"))
    check_geometry(r.output, page, page_origin(r.output), BLACK, W.CUT_WIDTH)


# ------------------------------------------------------------------ broken writers
def test_a_wrong_scale_is_caught(monkeypatch):
    r = compiled("laser_box")
    monkeypatch.setattr(W, "PT_PER_MM", 72.0 / 25.5)
    (page,) = read(r.encode("pdf"))
    with pytest.raises(AssertionError, match="the bar is"):
        check_scale_bar(page)
    with pytest.raises(AssertionError):
        check_geometry(r.output, page, page_origin(r.output), BLACK, W.CUT_WIDTH)


def test_half_turn_beziers_are_caught(monkeypatch):
    r = compiled("gear")
    monkeypatch.setattr(B, "arc_pieces",
                        lambda radius, sweep, tol: max(1, math.ceil(abs(sweep) / math.pi - 1e-9)))
    (page,) = read(r.encode("pdf"))
    with pytest.raises(AssertionError, match="strays|quarter turn"):
        check_geometry(r.output, page, page_origin(r.output), BLACK, W.CUT_WIDTH)


def test_beziers_bulging_the_wrong_way_are_caught(monkeypatch):
    r = compiled("laser_box")

    real = B.unit_arc_beziers

    def inward(t0, sweep, n):                   # each handle mirrored through its end point
        return [(p0, (2 * p0[0] - p1[0], 2 * p0[1] - p1[1]),
                 (2 * p3[0] - p2[0], 2 * p3[1] - p2[1]), p3) for p0, p1, p2, p3 in real(t0, sweep, n)]
    monkeypatch.setattr(B, "unit_arc_beziers", inward)
    (page,) = read(r.encode("pdf"))
    with pytest.raises(AssertionError, match="strays"):
        check_geometry(r.output, page, page_origin(r.output), BLACK, W.CUT_WIDTH)


def test_arcs_run_the_other_way_round_are_caught(monkeypatch):
    r = compiled("laser_box")
    real = B.arc_beziers

    def other_way(a, tol):                      # the same ends, the complementary arc
        if isinstance(a, Arc) and abs(a.sweep) < 2 * math.pi - 1e-9:
            a = Arc(a.center, a.radius, a.start_angle,
                    a.sweep - math.copysign(2 * math.pi, a.sweep))
        return real(a, tol)
    monkeypatch.setattr(B, "arc_beziers", other_way)
    (page,) = read(r.encode("pdf"))
    with pytest.raises(AssertionError, match="wrong way|no Bézier"):
        check_geometry(r.output, page, page_origin(r.output), BLACK, W.CUT_WIDTH)


# ------------------------------------------------------------------ tiles
def tile_offsets(output, pages, overlap=10.0):
    """Each page's drawing point at its bottom-left corner, two ways: from its geometry (the
    translation that puts most of its points on design points) and from the documented tile
    rule (its window's left and top, from the trim line, at x0 + column (window - overlap)
    and y1 - row (window - overlap)); they must agree."""
    x0, _, _, y1 = extent(output)
    design = np.array([q for s in design_segments(output, True) + design_segments(output, False)
                       if not isinstance(s, Circle) for q in (s.start, s.end)])
    got = []
    for page in pages:
        grey = page["pieces"][(W.MARK_RGB, W.MARK_WIDTH)]
        xs = [p[0] for q in grey for p in q[1:]]
        ys = [p[1] for q in grey for p in q[1:]]
        # the trim line: the one grey rectangle (the window's edge), the crop marks outside
        ((_, _, lx, by, rx, ty),) = [q for q in page["rects"]
                                     if q[:2] == (W.MARK_RGB, W.MARK_WIDTH)]
        assert min(xs) < lx and max(ys) > ty                 # crop marks outside it
        ww, wh = (rx - lx) / K, (ty - by) / K
        label = page["label"]
        letters = label.rstrip("0123456789")
        row = sum((ord(ch) - 64) * 26 ** i for i, ch in enumerate(reversed(letters))) - 1
        col = int(label.lstrip("ABCDEFGHIJKLMNOPQRSTUVWXYZ")) - 1
        rule = (x0 + col * (ww - overlap) - lx / K, y1 - row * (wh - overlap) - ty / K)
        pts = np.array([mm(p, (0, 0)) for key, qs in page["pieces"].items()
                        if key[0] in (BLACK, BLUE) and key[1] in (W.CUT_WIDTH, W.ENGRAVE_WIDTH)
                        for q in qs if q[0] == "l" for p in (q[1], q[-1])])
        cand = np.round(design[:, None, :] - pts[None, :1, :], 6).reshape(-1, 2)
        best, most = None, -1
        for off in {tuple(c) for c in cand}:
            hit = (np.abs(pts[:, None, :] + off - design[None]).max(axis=2).min(axis=1)
                   <= EXACT).sum()
            if hit > most:
                best, most = off, hit
        assert most >= 0.9 * len(pts)
        assert math.dist(best, rule) <= 1e-5, (label, best, rule)
        got.append({"label": label, "row": row, "col": col, "off": rule,
                    "window": (lx / K + rule[0], by / K + rule[1], rx / K + rule[0],
                               ty / K + rule[1])})
    return got


def check_tiles(output, data, paper):
    pages = read(data)
    pw, ph = W.page_size(paper)
    for page in pages:
        assert page["size"][0] / K == pytest.approx(pw, abs=1e-3)
        assert page["size"][1] / K == pytest.approx(ph, abs=1e-3)
        check_scale_bar(page)
    tiles = tile_offsets(output, pages)
    assert len({t["label"] for t in tiles}) == len(tiles) > 1
    # neighbours overlap by exactly 10 mm
    at = {(t["row"], t["col"]): t["window"] for t in tiles}
    pairs = 0
    for (r, c), w in at.items():
        if (r, c + 1) in at:
            assert abs(w[2] - at[r, c + 1][0] - 10.0) <= EXACT
            pairs += 1
        if (r + 1, c) in at:
            assert abs(at[r + 1, c][3] - w[1] - 10.0) <= EXACT
            pairs += 1
    assert pairs >= 1
    # every point of the design is inside some page's window, drawn there at its place
    for s in design_segments(output, True):
        for p in ([s.start, s.end] if not isinstance(s, Circle) else
                  [(s.center[0] + s.radius, s.center[1])]):
            ok = False
            for t, page in zip(tiles, pages):
                x0, y0, x1, y1 = t["window"]
                if x0 - EXACT <= p[0] <= x1 + EXACT and y0 - EXACT <= p[1] <= y1 + EXACT:
                    ends = [mm(q[i], t["off"]) for q in page["pieces"][(BLACK, W.CUT_WIDTH)]
                            for i in (1, -1)]
                    if min(math.dist(p, e) for e in ends) <= EXACT:
                        ok = True
                        break
            assert ok, f"{p} is on no page"
    for t, page in zip(tiles, pages):
        check_geometry(output, page, t["off"], BLACK, W.CUT_WIDTH, window=t["window"])
    return tiles


def on_page(s, window):
    b = s.box()
    return b[0] <= window[2] and b[2] >= window[0] and b[1] <= window[3] and b[3] >= window[1]


def test_tiles_of_a_cutting_sheet_on_a4():
    r = compiled("laser_box")
    lay = r.layout((600.0, 400.0))
    (data,) = lay.encode("pdf", page="A4")
    tiles = check_tiles(lay._cut[0], data, "A4")
    assert {"A1", "B1"} <= {t["label"] for t in tiles}


def test_tiles_on_letter_landscape_cover_the_box():
    r = compiled("laser_box")
    out = for_cutting(r.output, None)
    tiles = check_tiles(out, r.encode("pdf", page="letter-landscape"), "Letter-landscape")
    assert len(tiles) == 2                       # 212 mm high: two rows of a landscape page


def test_a_wrong_overlap_is_caught(monkeypatch):
    r = compiled("laser_box")
    out = for_cutting(r.output, None)
    monkeypatch.setattr(W, "OVERLAP", 5.0)
    with pytest.raises(AssertionError):
        check_tiles(out, r.encode("pdf", page="Letter-landscape"), "Letter-landscape")


# ------------------------------------------------------------------ front ends
def test_cli_writes_pdf_with_page_and_layout(tmp_path, capsys):
    box = str(EX / "laser_box.aidl")
    assert main(["render", box, "-o", str(tmp_path / "a.pdf")]) == 0
    assert main(["render", box, "--page", "A4-landscape", "-o", str(tmp_path / "t.pdf")]) == 0
    assert main(["render", box, "--layout", "sheet", "-o", str(tmp_path / "box.pdf")]) == 0
    assert (tmp_path / "a.pdf").read_bytes()[:5] == b"%PDF-"
    assert len(read((tmp_path / "t.pdf").read_bytes())) == 2
    (sheet,) = read((tmp_path / "box.pdf").read_bytes())       # the sheet, its margins
    assert sheet["size"][0] / K == pytest.approx(620.0, abs=1e-3)
    assert sheet["size"][1] / K == pytest.approx(420.0 + W.FOOTER, abs=1e-3)
    check_scale_bar(sheet)
    assert "wrote" in capsys.readouterr().out


def test_cli_page_usage_errors(tmp_path, capsys):
    box = str(EX / "laser_box.aidl")
    assert main(["render", box, "--page", "B5", "-o", str(tmp_path / "a.pdf")]) == 2
    err = capsys.readouterr().err
    assert "--page takes A4, A4-landscape, A3" in err and "Letter" in err and "`B5`" in err
    assert main(["render", box, "--page", "A4", "-o", str(tmp_path / "a.svg")]) == 2
    assert "add -o NAME.pdf" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_api_errors_and_missing_library(monkeypatch):
    r = compiled("gear")
    with pytest.raises(OutputError, match="unknown page `B5`; use one of A4"):
        r.encode("pdf", page="B5")
    with pytest.raises(OutputError, match="leaves no room"):
        r.encode("pdf", page="A4", margin=100)
    import builtins
    real = builtins.__import__

    def no_reportlab(name, *a, **kw):
        if name.startswith("reportlab"):
            raise ImportError("No module named 'reportlab'")
        return real(name, *a, **kw)
    monkeypatch.setattr(builtins, "__import__", no_reportlab)
    with pytest.raises(MissingDependency, match=r"pip install 'aidl-lang\[pdf\]'"):
        r.encode("pdf")


def test_too_many_pages_is_refused():
    r = api.compile("solid s { b = Rectangle(center=(0, 0), width=6000, height=4000) }\n")
    with pytest.raises(OutputError, match="pages of A4"):
        r.encode("pdf", page="A4")
    with pytest.raises(OutputError, match="larger than PDF readers show"):
        r.encode("pdf")


def test_kerf_applies_as_for_svg():
    r = compiled("gear")
    out = for_cutting(r.output, 0.2)
    (page,) = read(r.encode("pdf", kerf=0.2))
    check_geometry(out, page, page_origin(out), BLACK, W.CUT_WIDTH)


def test_mcp_render_writes_a_tiled_pdf(tmp_path):
    pytest.importorskip("cairosvg")
    from aidl_lang.mcp import tools as T
    src = (EX / "laser_box.aidl").read_text()
    doc, _ = T.render(T.Workspace(tmp_path), source=src, output="box.pdf",
                      page="Letter-landscape", width=64)
    assert doc["written"] == "box.pdf"
    pages = read((tmp_path / "box.pdf").read_bytes())
    assert len(pages) == 2 and {p["label"] for p in pages} == {"A1", "B1"}
    for args, said in (({"page": "B5", "output": "x.pdf"}, "unknown page `B5`"),
                       ({"page": "A4", "output": "x.svg"}, "output ending in .pdf")):
        with pytest.raises(T.Refused, match=said):
            T.render(T.Workspace(tmp_path), source=src, width=64, **args)
