"""Real drawings round two, the import half (issue 59): what a laser file cuts stays cut.

- An open path on a cut role (Boxes.py's blue slits of a living hinge, `--roles laser`; or by
  layer, `--cut LAYER`) is written as a through-cut, ``cut cuts { ... }`` in its part, never
  an engraving; its G-code and LightBurn cut layers hold each slit as one pass along one line.
- A path whose end crosses its own start (Boxes.py's D-bores end past their start) is closed
  at the crossing, exactly: the overshoot trimmed, a line still the line, an arc the arc.
- SVG ``<text>`` comes in as ``Text(...)`` engravings; a red (annotation) one stays out; one
  that cannot (mirrored) is counted in the note with its words.
- ``inf``/``nan`` in an SVG path's data is counted in the note with its place.

The SVGs are written here in Boxes.py's manner (mm units, ``rgb(...)`` strokes, one ``<g>``),
with our own content; nothing of Boxes.py's files is copied.  Real programs (FreeCAD, KiCad,
Inkscape) write their drawings at test time in tests/test_import_programs.py."""
from __future__ import annotations

import math
import re

import pytest

import aidl_lang
from aidl_lang.drawing.write.program import import_drawing
from aidl_lang.drawing.read import read_drawing

HEAD = ('<?xml version="1.0" encoding="utf-8"?>\n'
        '<svg xmlns="http://www.w3.org/2000/svg" width="{w}mm" height="{h}mm" '
        'viewBox="0.0 0.0 {w} {h}">\n<g id="p-0" style="fill:none;stroke-linecap:round;">\n')
BLACK, BLUE, RED, GREEN = "rgb(0,0,0)", "rgb(0,0,255)", "rgb(255,0,0)", "rgb(0,255,0)"

# the flex panel: a 100 x 60 mm outline (black) and 9 slits in three staggered columns (blue)
SLITS = [(x, y0, y1) for x in (20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
         for (y0, y1) in ([(5.0, 28.0), (32.0, 55.0)] if x % 20 == 0 else [(15.0, 45.0)])]


def _svg(body: list[str], w=100, h=60) -> bytes:
    return (HEAD.format(w=w, h=h) + "\n".join(body) + "\n</g>\n</svg>\n").encode()


def flex_svg() -> bytes:
    body = [f'<path d="M 0.000 0.000 H 100.000 V 60.000 H 0.000 V 0.000 Z" stroke="{BLACK}" '
            'stroke-width="0.20" />']
    body += [f'<path d="M {x:.3f} {y0:.3f} V {y1:.3f}" stroke="{BLUE}" stroke-width="0.20" />'
             for x, y0, y1 in SLITS]
    body.append(f'<path d="M 2 62 H 12 V 64 H 2 Z" stroke="{RED}" stroke-width="0.20" />')
    return _svg(body)


@pytest.fixture(scope="module")
def flex():
    """The flex panel imported with --roles laser, and compiled."""
    text, notes = import_drawing(flex_svg(), "flex.svg", roles="laser")
    res = aidl_lang.compile(source=text, path="flex.aidl")
    return text, notes, res


def test_open_cut_paths_are_written_as_through_cuts(flex):
    text, notes, res = flex
    assert res.ok, [d.message for d in res.diagnostics if d.severity == "error"]
    body = text.split("cut cuts {", 1)
    assert len(body) == 2 and "drawing paths" not in text
    lines = re.findall(r"= Line\(start=\(([-\d.]+), ([-\d.]+)\), end=\(([-\d.]+), ([-\d.]+)\)\)",
                       body[1])
    # every slit, once, in the file's place (the SVG's y turned up)
    got = sorted((float(a), -float(b), -float(d)) for a, b, c, d in lines)
    assert got == sorted(SLITS), got
    note = next(n.message for n in notes if "through-cuts" in n.message)
    assert f"{len(SLITS)} open paths" in note
    total = sum(y1 - y0 for _x, y0, y1 in SLITS)
    assert f"({total:g} mm)" in note


def test_a_sheet_of_parts_keeps_each_parts_through_cuts():
    body = [f'<path d="M 0 0 H 40 V 60 H 0 Z" stroke="{BLACK}" />',
            f'<path d="M 50 0 H 100 V 60 H 50 Z" stroke="{BLACK}" />',
            f'<path d="M 20 10 V 50" stroke="{BLUE}" />',
            f'<path d="M 70 10 V 50" stroke="{BLUE}" />']
    text, _ = import_drawing(_svg(body), "sheet.svg", roles="laser", parts=True)
    assert text.count("cut cuts {") == 2 and "drawing" not in text
    res = aidl_lang.compile(source=text, path="sheet.aidl")
    assert res.ok and len(res.output.parts) == 2


def test_without_a_role_open_paths_stay_engravings():
    text, _ = import_drawing(flex_svg(), "flex.svg")
    assert "cut cuts" not in text and "drawing paths {" in text


def test_an_engrave_role_stays_engraved():
    body = [f'<path d="M 0 0 H 100 V 60 H 0 Z" stroke="{BLACK}" />',
            f'<path d="M 20 10 V 50" stroke="{GREEN}" />',
            # an engraved ellipse (its writer named a variable it did not have: a traceback)
            f'<ellipse cx="60" cy="30" rx="8" ry="4" stroke="{GREEN}" />']
    text, _ = import_drawing(_svg(body), "g.svg", roles="laser")
    assert "cut cuts" not in text and "drawing engrave {" in text
    assert "Ellipse(center=(60, -30), rx=8, ry=4" in text


def _gcode_runs(gcode: str):
    """The G1 moves of a G-code job as ``(S, (x0, y0), (x1, y1))``, by this small reader."""
    x = y = 0.0
    s = 0.0
    out = []
    for ln in gcode.splitlines():
        ln = ln.split(";")[0].strip()
        m = re.match(r"G([01])\b(.*)", ln)
        if not m:
            continue
        words = dict((w[0], float(w[1:])) for w in m.group(2).split() if w[0] in "XYSF")
        s = words.get("S", s)
        nx, ny = words.get("X", x), words.get("Y", y)
        if m.group(1) == "1" and (nx, ny) != (x, y):
            out.append((s, (x, y), (nx, ny)))
        x, y = nx, ny
    return out


def test_gcode_cuts_each_slit_in_one_pass_along_one_line(flex):
    _text, _notes, res = flex
    gcode = res.encode("gcode").decode()
    passes = int(re.search(r"; cut_inner: .* (\d+) pass", gcode).group(1))
    runs = _gcode_runs(gcode)
    top = max(s for s, _a, _b in runs)                       # the cut power
    for x, y0, y1 in SLITS:
        # the line itself, at cut power, once per pass of the profile's cut_inner
        along = [r for r in runs if {r[1], r[2]} == {(x, -y0), (x, -y1)}]
        assert len(along) == passes and all(s == top for s, _a, _b in along), \
            (x, y0, y1, along)
        # never beside the line (a slit drawn as a rectangle has two sides)
        beside = [r for r in runs if r[1][0] == r[2][0] and 0 < abs(r[1][0] - x) < 1
                  and min(r[1][1], r[2][1]) >= -y1 - 1e-9 and max(r[1][1], r[2][1]) <= -y0 + 1e-9]
        assert not beside


def test_lightburn_cut_layer_holds_each_slit_as_one_line(flex):
    etree = pytest.importorskip("lxml.etree")
    _text, _notes, res = flex
    root = etree.fromstring(res.encode("lbrn2"))
    cut_layers = {cs.find("index").get("Value") for cs in root.findall("CutSetting")
                  if "cut" in (cs.find("name").get("Value") or "").lower()}
    found = []
    for sh in root.iter("Shape"):
        if sh.get("Type") != "Path" or sh.get("CutIndex") not in cut_layers:
            continue
        a, b, c, d, e, f = (float(v) for v in sh.find("XForm").text.split())
        vs = [(float(x), float(y)) for x, y in
              re.findall(r"V(-?[\d.]+) (-?[\d.]+)", sh.find("VertList").text)]
        prims = re.findall(r"([LB])(\d+) (\d+)", sh.find("PrimList").text)
        if len(prims) == 1 and prims[0][0] == "L":
            p, q = vs[int(prims[0][1])], vs[int(prims[0][2])]
            found.append(tuple(sorted(((round(a * x + c * y + e, 9), round(b * x + d * y + f, 9))
                                       for x, y in (p, q)))))
    for x, y0, y1 in SLITS:
        assert found.count(tuple(sorted(((x, -y1), (x, -y0))))) == 1, (x, y0, y1)


# ------------------------------------------------------------------ overshoot
def test_a_path_past_its_start_closes_at_the_crossing_exactly():
    """A square drawn from (9.9, 10) that ends 0.5 mm past (10, 10) where its last side
    crosses its first: a 20 x 20 outline, corner (10, 10) exact; and a D-bore (circle r = 5
    about (50, 50), the flat at x = 54.68) drawn as Boxes.py draws one: the arc from
    (54.8, 48.6), 0.38 mm before the flat, round to (54.68, 51.76), then the flat 0.24 mm past
    the arc: the arc from the crossing (54.68, 48.24) round and the flat back, its area the
    circle less the segment beyond the flat, 25 pi - (25 acos(0.936) - 4.68 x 1.76)."""
    body = [f'<path d="M 9.9 10 L 30 10 L 30 30 L 10 30 L 10 9.5" stroke="{BLACK}" />',
            f'<path d="M 54.8 48.6 A 5 5 0 1 0 54.68 51.76 L 54.68 48" stroke="{BLUE}" />']
    d = read_drawing(_svg(body, 100, 100), "o.svg", roles="laser")
    assert not d.paths and len(d.outlines) == 2
    sq, bore = sorted(d.outlines, key=lambda o: -abs(o.area))
    assert abs(sq.area - 400) < 1e-9
    assert {(round(s.start[0], 12), round(s.start[1], 12)) for s in sq.segments} == \
        {(10, -10), (30, -10), (30, -30), (10, -30)}
    assert [type(s).__name__ for s in bore.segments] == ["Arc", "Line"] or \
        [type(s).__name__ for s in bore.segments] == ["Line", "Arc"]
    want = 25 * math.pi - (25 * math.acos(0.936) - 4.68 * 1.76)
    assert abs(bore.area - want) < 1e-9, (bore.area, want)
    ends = {(round(p[0], 9), round(p[1], 9)) for s in bore.segments for p in (s.start, s.end)}
    assert ends == {(54.68, -48.24), (54.68, -51.76)}
    note = next(n.message for n in d.notes if "crosses" in n.message)
    assert note.startswith("2 paths of `o.svg` closed where their end crosses their start")
    # and close_tolerance=0 keeps them as drawn (open)
    d0 = read_drawing(_svg(body, 100, 100), "o.svg", roles="laser", close_tolerance=0)
    assert len(d0.paths) == 2 and not d0.outlines


def test_an_overshoot_compiles_into_a_hole():
    body = [f'<path d="M 0 0 H 100 V 100 H 0 Z" stroke="{BLACK}" />',
            f'<path d="M 54.8 48.6 A 5 5 0 1 0 54.68 51.76 L 54.68 48" stroke="{BLUE}" />']
    text, _ = import_drawing(_svg(body, 100, 100), "o.svg", roles="laser")
    assert "hole hole2 {" in text and "cut cuts" not in text
    res = aidl_lang.compile(source=text, path="o.aidl")
    assert res.ok
    (part,) = res.output.parts           # the exact output: the plate less the D
    want = 25 * math.pi - (25 * math.acos(0.936) - 4.68 * 1.76)
    assert abs(part.area - (10000 - want)) < 1e-9, part.area


# ------------------------------------------------------------------ text
def test_svg_text_comes_in_as_text_engravings():
    body = [f'<path d="M 0 0 H 100 V 60 H 0 Z" stroke="{BLACK}" />',
            # Boxes.py's way: a matrix, font-size in px (user units), hanging, "left"
            '<text dominant-baseline="hanging" font-size="10px" style="fill: rgb(0,0,0)" '
            'text-anchor="left" transform="matrix( 1.000 0.000 0.000 1.000 10.000 20.000 )">'
            'Lid A</text>',
            '<text x="50" y="40" font-size="5" text-anchor="middle" fill="rgb(0,255,0)" '
            'transform="rotate(-90 50 40)">UP</text>',
            f'<text x="5" y="5" font-size="4" fill="{RED}">100.0mm, burn:0.10mm</text>',
            '<text x="0" y="0" font-size="5" fill="rgb(0,0,0)" '
            'transform="matrix(-1 0 0 1 80 50)">MIRROR</text>']
    d = read_drawing(_svg(body), "t.svg", roles="laser")
    cut_texts = d.texts
    assert cut_texts == [("Lid A", (10.0, -20.0), 7.0, -0.0, "start", "top")]
    (g,) = d.engrave.texts
    assert g[0] == "UP" and math.dist(g[1], (50, -40)) < 1e-12 and abs(g[2] - 3.5) < 1e-12
    assert abs(g[3] - math.pi / 2) < 1e-12 and g[4:] == ("middle", "baseline")
    note = next(n.message for n in d.notes if "not imported" in n.message)
    assert note == "1 text of `t.svg` not imported: `MIRROR` (mirrored)"
    text, notes = import_drawing(_svg(body), "t.svg", roles="laser")
    assert 'Text("Lid A", position=(10, -20), size=7, anchor="start", valign="top")' in text
    assert 'Text("UP", position=(50, -40), size=3.5, anchor="middle", valign="baseline", ' \
           'rotation=90 deg)' in text
    assert "100.0mm" not in text                    # the red annotation stays out
    assert not any("text is not imported" in n.message for n in notes)
    res = aidl_lang.compile(source=text, path="t.aidl")
    assert res.ok, [d.message for d in res.diagnostics]


# ------------------------------------------------------------------ numbers
def test_unreadable_numbers_in_path_data_are_counted_with_their_place():
    svg = _svg([f'<path d="M 0 0 H 100 V 60 H 0 Z" stroke="{BLACK}" />',
                f'<path id="bad" d="M 10 10 L 20 10 L nan 5 L 30 30" stroke="{BLACK}" />',
                f'<path d="M 10 50 L 20 50 L 30 inf" stroke="{BLACK}" />',
                f'<polyline points="0,0 10,0 nan,5 20,20" stroke="{BLACK}" />'])
    d = read_drawing(svg, "n.svg")
    note = next(n.message for n in d.notes if "cannot be read" in n.message)
    assert note == ("3 paths of `n.svg` hold a number that cannot be read: a path's data is "
                    "read up to it: <path> (id `bad`) at line 5, character 19: `nan` (13 "
                    "characters left out); <path> at line 6, character 22: `inf` (3 "
                    "characters left out); <polyline> at line 7, character 10: `nan` (the "
                    "whole shape left out)")
    # what comes before the word is read (svgelements stops there); the polyline, whose
    # numbers svgelements would pair up wrongly after the word, is left out
    assert sorted(round(p.segments[0].end[0], 9) for p in d.paths) == [20, 20]


def test_a_cut_loop_that_crosses_itself_is_split_at_the_crossing_into_holes():
    """A bow tie on a cut role (it crosses itself at (20, 20), far from a small loop): a
    laser cuts both its triangles out, so it is split at the crossing into the two loops,
    each a hole, every line kept (it was an engraving: its 97 mm of cut lost, issue 71); the
    open slit beside it is a through-cut."""
    body = [f'<path d="M 0 0 H 100 V 60 H 0 Z" stroke="{BLACK}" />',
            f'<path d="M 10 10 L 30 30 L 30 10 L 10 30 Z" stroke="{BLUE}" />',
            f'<path d="M 60 10 V 50" stroke="{BLUE}" />']
    text, notes = import_drawing(_svg(body), "bow.svg", roles="laser")
    cut = text.split("cut cuts {", 1)[1].split("}", 1)[0]
    assert cut.strip().splitlines()[0] == "p1_0 = Line(start=(60, -10), end=(60, -50))"
    assert "drawing paths {" not in text
    holes = [h.split("}", 1)[0] for h in text.split("hole hole")[1:]]
    assert len(holes) == 2 and all(h.count("= Line(") == 3 and "(20, -20)" in h for h in holes)
    assert any(n.message == "1 loop of `bow.svg` crosses itself: split at the crossings into "
                            "2 loops that do not, every line kept (a laser cuts each out: a "
                            "part, a hole or a crumb; a corner curve that loops round on "
                            "itself is cut off at its ends)" for n in notes)
    c = aidl_lang.compile(source=text, path="bow.aidl")
    assert c.ok
    # the two triangles meet at the crossing: one opening, as the laser cuts it
    assert [d.code for d in c.sink.items] == ["W0508"]


# ------------------------------------------------------------------ Drawing2D in a program
DRAWN = """units mm
solid panel {
    outline = Drawing2D("flex.svg", cut="rgb(0,0,0)", engrave="rgb(0,255,0)",
                        ignore=["rgb(0,0,255)", "rgb(255,0,0)"])
    cut slits {
        d = Drawing2D("flex.svg", cut="rgb(0,0,255)", ignore=["rgb(0,0,0)", "rgb(0,255,0)",
                      "rgb(255,0,0)"])
    }
}
"""


def test_a_drawing2d_in_a_cut_cuts_its_open_paths_and_the_engrave_role_is_engraved(tmp_path):
    """``Drawing2D`` reads the same file as ``aidl import``: inside a ``cut`` its open paths
    are through-cuts (each slit one cut stroke, exactly where the file has it, drawing y
    down); beside it in the solid the engrave role's shapes are engraved on the part (before,
    they were dropped without a word); in the solid itself an open chain stays E0131, whose
    hint names the `cut`."""
    svg = flex_svg().replace(b"</g>", f'<path d="M 30 3 H 70" stroke="{GREEN}" />\n</g>'.encode())
    (tmp_path / "flex.svg").write_bytes(svg)
    res = aidl_lang.compile(source=DRAWN, path=str(tmp_path / "panel.aidl"))
    assert res.ok, [d.message for d in res.diagnostics if d.severity == "error"]
    out = res.output
    cuts = sorted((round(s.segments[0].start[0], 9), round(-s.segments[0].start[1], 9),
                   round(-s.segments[0].end[1], 9)) for s in out.engrave if s.style == "cut")
    assert cuts == sorted((x, y0, y1) for x, y0, y1 in SLITS)
    assert all(len(s.segments) == 1 for s in out.engrave if s.style == "cut")
    marks = [s for s in out.engrave if s.style == "drawing"]
    assert len(marks) == 1 and marks[0].segments[0].start == pytest.approx((30.0, -3.0))
    assert [round(p.area, 6) for p in out.parts] == [6000.0]
    # what ignore= names is left out as asked: no W0130 about it (a warning on a design as
    # meant); a preset's ignored colour is still counted
    assert not [d for d in res.diagnostics if d.code == "W0130"], \
        [d.message for d in res.diagnostics]
    preset = read_drawing(flex_svg(), "flex.svg", roles="laser")
    assert any("left out by their role: red (1)" in n.message for n in preset.notes)
    asked = read_drawing(flex_svg(), "flex.svg", roles="laser", ignore="rgb(255,0,0)")
    assert not any("left out by their role" in n.message for n in asked.notes)
    (tmp_path / "open.aidl").write_text('units mm\nsolid panel {\n    d = Drawing2D("flex.svg", '
                                        'roles="laser")\n}\n')
    bad = aidl_lang.compile(source=(tmp_path / "open.aidl").read_text(),
                            path=str(tmp_path / "open.aidl"))
    err = [d for d in bad.diagnostics if d.severity == "error"]
    assert [d.code for d in err] == ["E0131"] and "inside a `cut`" in err[0].hint
