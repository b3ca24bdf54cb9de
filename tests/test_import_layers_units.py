"""`aidl import` where it was silently wrong beside `--infer` (issue 85): a layer whose
every shape is engraved (`--engrave LABELS`) keeps its texts with and without `--infer`;
holes on their own layer (HOLES) are the holes of the part they lie in, so a kerf shrinks
them and a layout keeps them in the plate; a drawing without a unit whose numbers fit
inches says so with `--units in`; an inch drawing's program stays in `units in` with the
file's inch numbers.  Each drawing is made with ezdxf, read back with ezdxf."""
from __future__ import annotations

import io
import math

import ezdxf
import pytest

import aidl_lang
from aidl_lang.drawing.infer import import_drawing

LABELS = [("POT0", (15, 40), 3.0), ("POT1", (45, 40), 3.0), ("POT2", (75, 40), 3.0),
          ("VOL", (100, 10), 2.5)]


def _panel(path, labels=True) -> bytes:
    """A 120 x 60 mm front panel: its outline on OUTLINE, three 7 mm pot holes on HOLES,
    four TEXT labels and a two-line MTEXT on LABELS."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    for ly in ("OUTLINE", "LABELS", "HOLES"):
        doc.layers.add(ly)
    m.add_lwpolyline([(0, 0), (120, 0), (120, 60), (0, 60)], close=True,
                     dxfattribs={"layer": "OUTLINE"})
    for x in (20, 50, 80):
        m.add_circle((x, 30), 3.5, dxfattribs={"layer": "HOLES"})
    if labels:
        for t, at, h in LABELS:
            m.add_text(t, height=h, dxfattribs={"layer": "LABELS", "insert": at})
        m.add_mtext("LINE ONE\\PLINE TWO", dxfattribs={"layer": "LABELS", "insert": (5, 55),
                                                       "char_height": 2.5})
    doc.saveas(path)
    return path.read_bytes()


def _compile(text, tmp_path, name="p.aidl"):
    res = aidl_lang.compile(text, path=tmp_path / name)
    assert res.ok, [str(d) for d in res.errors]
    return res


def _entities(res, layer: str, digits: int = 9, **encode) -> list:
    """The entities of ``layer`` in the DXF ``res`` renders, read by ezdxf: LINE and
    LWPOLYLINE as their points, CIRCLE as (centre, radius), rounded to ``digits`` decimals
    of a mm (1e-9), sorted."""
    doc = ezdxf.read(io.StringIO(res.encode("dxf", **encode).decode()
                                 if encode else res.to_dxf()))
    out = []
    for e in doc.modelspace():
        if e.dxf.layer != layer:
            continue
        if e.dxftype() == "CIRCLE":
            out.append(("C", round(e.dxf.center.x, digits), round(e.dxf.center.y, digits),
                        round(e.dxf.radius, digits)))
        elif e.dxftype() == "LINE":
            out.append(("L", tuple(sorted([(round(e.dxf.start.x, digits), round(e.dxf.start.y, digits)),
                                           (round(e.dxf.end.x, digits), round(e.dxf.end.y, digits))]))))
        elif e.dxftype() == "LWPOLYLINE":
            out.append(("P", tuple((round(x, digits), round(y, digits)) for x, y, *_ in e.get_points())))
    return sorted(out)


def _labels_program() -> str:
    """The labels as a person would write them: the truth the import's strokes must match."""
    lines = [f'    t{i} = Text("{t}", position=({x}, {y}), size={h}, anchor="start", '
             f'valign="baseline")' for i, (t, (x, y), h) in enumerate(LABELS)]
    lines += ['    m1 = Text("LINE ONE", position=(5, 55), size=2.5, anchor="start", valign="top")',
              f'    m2 = Text("LINE TWO", position=(5, {55 - 2.5 * 5 / 3!r}), size=2.5, '
              'anchor="start", valign="top")']
    return "units mm\ndrawing labels {\n" + "\n".join(lines) + "\n}\n"


@pytest.mark.parametrize("infer", [False, True], ids=["plain", "infer"])
def test_engrave_layer_keeps_its_texts(tmp_path, infer):
    """`--engrave LABELS` once gave `--infer` an empty `solid labels { }` (exit 0, `check`
    ok): the seven texts gone.  Now both imports write `drawing labels`, and its engraved
    strokes are those of the four TEXT and two MTEXT lines written by hand at their places
    and heights (to 1e-9 mm); `--infer` holds them all (fully constrained)."""
    data = _panel(tmp_path / "panel.dxf")
    text, _ = import_drawing(data, "panel.dxf", infer=infer, engrave="LABELS")
    assert "drawing labels {" in text and "solid labels" not in text, text
    res = _compile(text, tmp_path)
    truth = _compile(_labels_program(), tmp_path, "truth.aidl")
    # the inferred program places a label from the feature or edge it is tied to, its
    # numbers rounded within 1e-9 mm (its header says so): compared to 1e-8 mm
    digits = 8 if infer else 9
    got, want = _entities(res, "ENGRAVE", digits), _entities(truth, "ENGRAVE", digits)
    assert len(want) > 30 and got == want
    if infer:
        assert res.freedom()["dof"] == 0


@pytest.mark.parametrize("infer", [False, True], ids=["plain", "infer"])
def test_holes_layer_holes_are_the_parts_holes(tmp_path, infer):
    """The plain import once wrote the HOLES layer as `solid holes` beside the plate: with a
    0.2 mm kerf its three 7 mm holes were cut 7.2 mm (the kerf grew the discs, 0.4 mm too
    big against a hole's 6.8 mm) and the layout nested the plate alone (two parts, W0504).
    Now they are the plate's holes: cut at 6.8 mm and laid out as one part of 3 holes."""
    data = _panel(tmp_path / "panel.dxf", labels=False)
    text, _ = import_drawing(data, "panel.dxf", infer=infer)
    assert "# holes: layer `HOLES` in `OUTLINE`" in text and text.count("solid ") == 1, text
    res = _compile(text, tmp_path)
    assert not [d for d in res.diagnostics if d.severity == "warning"]
    circles = [e for e in _entities(res, "CUT", kerf=0.2) if e[0] == "C"]
    assert [(x, y, r) for _, x, y, r in circles] == [(20, 30, 3.4), (50, 30, 3.4), (80, 30, 3.4)]
    lay = res.layout(sheet=(300, 200))
    assert lay.parts == 1 and lay.use()[0] == pytest.approx(
        (120 * 60 - 3 * math.pi * 3.5 ** 2) / (300 * 200), abs=1e-4)


def test_holes_layer_is_found_in_one_pass(tmp_path):
    """Which hole of the HOLES layer lies in which part is found once for all layers (a
    grid of boxes): 40 x 50 = 2,000 holes in a plate of OUTLINE are its holes."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (410, 0), (410, 510), (0, 510)], close=True,
                     dxfattribs={"layer": "OUTLINE"})
    for i in range(40):
        for j in range(50):
            m.add_circle((10 + 10 * i, 10 + 10 * j), 2, dxfattribs={"layer": "HOLES"})
    doc.saveas(tmp_path / "many.dxf")
    text, _ = import_drawing((tmp_path / "many.dxf").read_bytes(), "many.dxf")
    assert "# holes: layer `HOLES` in `OUTLINE`" in text and text.count("solid ") == 1
    assert text.count("hole hole") == 2000


def _inch_plate(path, insunits=None) -> bytes:
    """A 4.4 x 2.9 in plate drawn in inches: four 0.197 in corner holes 0.25 in from the
    edges, a 3/8 in bore in the middle, a 1/8 in hole; ``insunits``: its $INSUNITS, or None
    for a file with no HEADER section (ezdxf's R12 writer writes only ENTITIES)."""
    pts = [(0, 0), (4.4, 0), (4.4, 2.9), (0, 2.9)]
    holes = [((x, y), 0.197 / 2) for x in (0.25, 4.15) for y in (0.25, 2.65)]
    holes += [((2.2, 1.45), 0.375 / 2), ((1.0, 1.45), 0.125 / 2)]
    if insunits is None:
        from ezdxf.addons import r12writer
        with r12writer(str(path)) as w:
            w.add_polyline(pts, closed=True)
            for c, r in holes:
                w.add_circle(c, r)
    else:
        doc = ezdxf.new("R2010")
        doc.header["$INSUNITS"] = insunits
        m = doc.modelspace()
        m.add_lwpolyline(pts, close=True)
        for c, r in holes:
            m.add_circle(c, r)
        doc.saveas(path)
    return path.read_bytes()


@pytest.mark.parametrize("insunits", [None, 0], ids=["headerless", "insunits-0"])
def test_unitless_inch_drawing_says_inches(tmp_path, insunits):
    """A drawing with no unit whose numbers are an inch drawing's (4.4 x 2.9 units, holes
    0.197, 0.375, 0.125) was read as a 4.4 mm part with only "read as millimetres": its
    W0130 now says the numbers fit inches, with the fix `--units in`."""
    data = _inch_plate(tmp_path / "p.dxf", insunits)
    _, notes = import_drawing(data, "p.dxf")
    said = [n for n in notes if "gives no unit" in n.message]
    assert len(said) == 1 and "fit inches better" in said[0].message, notes
    assert "4.4 x 2.9 units" in said[0].message and "--units in" in said[0].hint
    _, notes = import_drawing(data, "p.dxf", unit="in")
    assert not [n for n in notes if "unit" in n.message]


def test_unitless_mm_drawings_are_not_said_inches(tmp_path):
    """No false alarm: the mm panel above and small mm parts (a 40 x 20 mm plate with
    3.2 mm holes, a 10 mm washer, a 30 mm square with a 1/4 in = 6.35 mm hole) without a
    unit are read as millimetres with the plain note."""
    from aidl_lang.drawing.model import Drawing, Outline
    from aidl_lang.drawing.write.units import fits_inches
    from aidl_lang.geometry.shapes.curves import Circle, Line

    def plate(w, h, holes):
        segs = [Line((0, 0), (w, 0)), Line((w, 0), (w, h)), Line((w, h), (0, h)),
                Line((0, h), (0, 0))]
        return Drawing(outlines=[Outline(segs)], circles=[Circle(c, r) for c, r in holes])
    assert fits_inches([plate(120, 60, [((20, 30), 3.5)])]) is None
    assert fits_inches([plate(40, 20, [((5, 5), 1.6), ((35, 5), 1.6)])]) is None
    assert fits_inches([plate(10, 10, [((5, 5), 2.5)])]) is None
    assert fits_inches([plate(30, 30, [((15, 15), 3.175)])]) is None
    assert fits_inches([plate(4.4, 2.9, [((1, 1), 0.0985), ((2, 1), 0.1875)])]) is None   # 2 to 2
    assert fits_inches([plate(4.4, 2.9, [((1, 1), 0.0985), ((2, 1), 0.1875),
                                         ((3, 1), 0.0625)])]) == (3, 5)
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 0
    doc.modelspace().add_lwpolyline([(0, 0), (40, 0), (40, 20), (0, 20)], close=True)
    doc.modelspace().add_circle((5, 5), 1.6)
    doc.saveas(tmp_path / "mm.dxf")
    _, notes = import_drawing((tmp_path / "mm.dxf").read_bytes(), "mm.dxf")
    said = [n for n in notes if "gives no unit" in n.message]
    assert len(said) == 1 and "inches" not in said[0].message


@pytest.mark.parametrize("infer", [False, True], ids=["plain", "infer"])
@pytest.mark.parametrize("how", ["insunits", "option"])
def test_inch_drawing_program_stays_in_inches(tmp_path, infer, how):
    """An inch drawing ($INSUNITS 1, or `--units in`) was written in mm (`width = 111.76
    mm`, holes 5.0038): now `units in` with the file's numbers (4.4, 0.197), and the program
    renders the drawing exactly (every circle and corner to 1e-9 mm of the file's inches
    times 25.4, read by ezdxf)."""
    data = _inch_plate(tmp_path / "p.dxf", 1 if how == "insunits" else 0)
    text, _ = import_drawing(data, "p.dxf", infer=infer,
                             **({"unit": "in"} if how == "option" else {}))
    assert "\nunits in\n" in text and "units mm" not in text, text
    assert "4.4" in text and "111.76" not in text and "5.0038" not in text, text
    assert ("0.197" if infer else "0.0985") in text and "9999" not in text, text
    res = _compile(text, tmp_path)
    got = _entities(res, "CUT")
    want = sorted([("C", round(x * 25.4, 9), round(y * 25.4, 9), round(r * 25.4, 9))
                   for (x, y), r in [((x, y), 0.0985) for x in (0.25, 4.15)
                                     for y in (0.25, 2.65)] +
                   [((2.2, 1.45), 0.1875), ((1.0, 1.45), 0.0625)]])
    assert [e for e in got if e[0] == "C"] == want
    corners = {p for e in got if e[0] != "C" for p in (e[1] if e[0] == "P" else e[1])}
    assert corners == {(0, 0), (111.76, 0), (111.76, 73.66), (0, 73.66)}


# ------------------------------------------------------------------ fresh imports that warn
def _arc_slot(m, c, radius, half_width, a0, a1, layer="0"):
    """An arc slot about ``c``: two concentric ARCs and two half-circle end caps (degrees)."""
    m.add_arc(c, radius + half_width, a0, a1, dxfattribs={"layer": layer})
    m.add_arc(c, radius - half_width, a0, a1, dxfattribs={"layer": layer})
    for a, s in ((a0, a0 + 180), (a1, a1)):
        e = (c[0] + radius * math.cos(math.radians(a)), c[1] + radius * math.sin(math.radians(a)))
        m.add_arc(e, half_width, s, s + 180, dxfattribs={"layer": layer})


def _rounded(m, x0, y0, w, h, r, layer="0"):
    """A rounded rectangle of LINE and ARC entities, as CAD programs draw its corners."""
    m.add_line((x0 + r, y0), (x0 + w - r, y0), dxfattribs={"layer": layer})
    m.add_arc((x0 + w - r, y0 + r), r, 270, 360, dxfattribs={"layer": layer})
    m.add_line((x0 + w, y0 + r), (x0 + w, y0 + h - r), dxfattribs={"layer": layer})
    m.add_arc((x0 + w - r, y0 + h - r), r, 0, 90, dxfattribs={"layer": layer})
    m.add_line((x0 + w - r, y0 + h), (x0 + r, y0 + h), dxfattribs={"layer": layer})
    m.add_arc((x0 + r, y0 + h - r), r, 90, 180, dxfattribs={"layer": layer})
    m.add_line((x0, y0 + h - r), (x0, y0 + r), dxfattribs={"layer": layer})
    m.add_arc((x0 + r, y0 + r), r, 180, 270, dxfattribs={"layer": layer})


def arc_slot_plate(path, seed: int = 0) -> bytes:
    """A maker's plate made from ``seed``: a rounded rectangle of LINE+ARC entities (or an
    LWPOLYLINE with bulges), a centre bore, three arc slots round it, corner holes, a
    straight slot, a TEXT and a two-line MTEXT label above the bore, and sometimes a
    separate washer and an L bracket with its mirror image beside it."""
    import random
    rnd = random.Random(seed)
    W, H = rnd.randrange(80, 160, 2), rnd.randrange(90, 140, 2)
    r = rnd.choice([3, 4, 5, 6])
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    if rnd.random() < 0.5:
        _rounded(m, 0, 0, W, H, r)
    else:
        k = math.tan(math.radians(90) / 4)          # a quarter turn's bulge
        m.add_lwpolyline([(r, 0, 0, 0, 0), (W - r, 0, 0, 0, k), (W, r, 0, 0, 0),
                          (W, H - r, 0, 0, k), (W - r, H, 0, 0, 0), (r, H, 0, 0, k),
                          (0, H - r, 0, 0, 0), (0, r, 0, 0, k)], format="xyseb", close=True)
    c = (W / 2, H / 2 - 10)
    bore = rnd.choice([8, 10, 12])
    m.add_circle(c, bore / 2)
    R, hw = bore / 2 + rnd.choice([10, 12, 14]), rnd.choice([1.5, 2, 2.5])
    turn = rnd.choice([0, 15, 30])
    sweep = rnd.choice([40, 60, 80])
    for k in range(3):
        a0 = turn + k * 120
        _arc_slot(m, c, R, hw, a0, a0 + sweep)
    inset, hole = rnd.choice([5, 6, 8]), rnd.choice([1.6, 1.7, 2.2])
    for x in (inset, W - inset):
        for y in (inset, H - inset):
            m.add_circle((x, y), hole)
    # a straight slot near the bottom edge: two lines and two half circles
    sx, sy, sl, sw = W / 2 - 15, 6 + inset, 30, rnd.choice([3, 4])
    m.add_line((sx, sy - sw / 2), (sx + sl, sy - sw / 2))
    m.add_arc((sx + sl, sy), sw / 2, 270, 90)
    m.add_line((sx + sl, sy + sw / 2), (sx, sy + sw / 2))
    m.add_arc((sx, sy), sw / 2, 90, 270)
    m.add_text("PLATE", height=3, dxfattribs={"insert": (inset + 6, H - inset - 10)})
    m.add_mtext("REV A\\PTOP", dxfattribs={"insert": (W - inset - 30, H - inset - 4),
                                          "char_height": 2.5})
    if rnd.random() < 0.5:                          # a washer beside the plate
        m.add_circle((W + 20, 15), 8)
        m.add_circle((W + 20, 15), 3)
    if rnd.random() < 0.5:                          # an L bracket and its mirror image
        L = [(0, 0), (40, 0), (40, 5), (5, 5), (5, 30), (0, 30)]
        m.add_lwpolyline([(x, y + H + 10) for x, y in L], close=True)
        m.add_lwpolyline([(100 - x, y + H + 10) for x, y in L], close=True)
        for x, y in ((20, 2.5), (2.5, 20)):
            m.add_circle((x, y + H + 10), 1.2)
            m.add_circle((100 - x, y + H + 10), 1.2)
    doc.saveas(path)
    return path.read_bytes()


def _fresh(text, tmp_path):
    """The warnings of the compiled program and its degrees of freedom."""
    res = _compile(text, tmp_path)
    warn = [f"{d.code} {d.message}" for d in res.diagnostics if d.severity == "warning"]
    return warn, res.freedom()


@pytest.mark.parametrize("infer", [False, True], ids=["plain", "infer"])
def test_arc_slot_plate_imports_clean(tmp_path, infer):
    """The issue's arc-slot plate (LINE+ARC rounded corners, three arc slots, a washer and
    mirrored brackets beside it): `--infer` once gave 10 x W0401 and 6 free degrees (a slot's
    half-circle end cap held by its radius, which pins nothing at a half turn), the plain
    import W0504 (the parts in one solid) and 66 free degrees.  Now both check with no
    warning, fully constrained, and render the drawing exactly (1e-9 mm)."""
    from benchmarks.imports.infer_edits import same
    data = arc_slot_plate(tmp_path / "a.dxf", seed=3)
    text, _ = import_drawing(data, "a.dxf", infer=infer)
    assert "Mirrored(" in text if infer else text.count("solid ") == 4   # plate, 3 parts
    warn, free = _fresh(text, tmp_path)
    assert not warn and free["dof"] == 0, (warn, free["text"], text)
    back = ezdxf.read(io.StringIO(_compile(text, tmp_path).to_dxf()))
    for e in list(back.modelspace()):
        if e.dxf.layer == "ENGRAVE":            # the labels' strokes: the file has TEXT
            back.modelspace().delete_entity(e)
    back.saveas(tmp_path / "back.dxf")
    assert same(tmp_path / "a.dxf", tmp_path / "back.dxf", 1e-9)


def test_every_fresh_import_is_clean():
    """The law: every fresh import of a generated maker plate (rounded corners as LINE+ARC
    or bulges, arc slots, a straight slot, corner holes, TEXT and MTEXT labels, washers and
    mirrored brackets beside it), plain and `--infer`, checks with no W04xx or W0504 and no
    free degree."""
    import tempfile
    from pathlib import Path

    from hypothesis import given, settings
    from hypothesis import strategies as st

    @settings(max_examples=6, deadline=None)
    @given(st.integers(0, 10_000))
    def law(seed):
        with tempfile.TemporaryDirectory() as tmp:
            tmp = Path(tmp)
            data = arc_slot_plate(tmp / "g.dxf", seed)
            for infer in (False, True):
                text, _ = import_drawing(data, "g.dxf", infer=infer)
                warn, free = _fresh(text, tmp)
                bad = [w for w in warn if w.startswith(("W04", "W0504"))]
                assert not bad and free["dof"] == 0, (seed, infer, bad, free["text"])
    law()


def test_parts_apart_are_solids_and_overlapping_frames_stay_one(tmp_path):
    """Two brackets and a washer apart on one layer are three solids (one solid of them
    fell apart: W0504); frames drawn across one another (ezdxf's text samples) stay one
    solid, as before, so no new W0511 between parts that overlap."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (40, 0), (40, 5), (5, 5), (5, 30), (0, 30)], close=True)
    m.add_lwpolyline([(60, 0), (100, 0), (100, 30), (95, 30), (95, 5), (60, 5)], close=True)
    m.add_circle((120, 10), 8)
    doc.saveas(tmp_path / "apart.dxf")
    text, _ = import_drawing((tmp_path / "apart.dxf").read_bytes(), "apart.dxf")
    assert text.count("solid ") == 3, text
    warn, free = _fresh(text, tmp_path)
    assert not warn and free["dof"] == 0, warn
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (40, 0), (40, 20), (0, 20)], close=True)
    m.add_lwpolyline([(30, 10), (70, 10), (70, 30), (30, 30)], close=True)
    doc.saveas(tmp_path / "cross.dxf")
    text, _ = import_drawing((tmp_path / "cross.dxf").read_bytes(), "cross.dxf")
    assert text.count("solid ") == 1, text


def sink_plate(layer: str):
    """``(doc, modelspace)`` of an 80 x 50 mm plate on OUTLINE in mm, with the layers HOLES
    and ``layer`` (a countersink layer) made, for the holes and their marks."""
    doc = ezdxf.new("R2010")
    doc.units = 4
    m = doc.modelspace()
    for ly in ("OUTLINE", "HOLES", layer):
        doc.layers.add(ly)
    m.add_lwpolyline([(0, 0), (80, 0), (80, 50), (0, 50)], close=True,
                     dxfattribs={"layer": "OUTLINE"})
    return doc, m


@pytest.mark.parametrize("infer", [False, True], ids=["plain", "infer"])
@pytest.mark.parametrize("layer", ["COUNTERSINK", "CSK", "C-Bore"])
def test_countersink_circles_are_marked_and_the_holes_are_the_parts(tmp_path, infer, layer):
    """A plate on OUTLINE, four 3.3 mm holes on HOLES and the countersinks' 6.6 mm top
    circles about them on a layer of their own: each hole lay inside a countersink circle,
    so the HOLES layer was not moved into the plate, and the holes and the countersinks came
    out as two solids of discs (cut as written: 6.6 mm through-holes), with no word.  Now the
    countersinks are a `drawing` (marked, not cut) and the holes the plate's."""
    doc, m = sink_plate(layer)
    centres = [(6, 6), (74, 6), (74, 44), (6, 44)]
    for c in centres:
        m.add_circle(c, 1.65, dxfattribs={"layer": "HOLES"})
        m.add_circle(c, 3.3, dxfattribs={"layer": layer})
    doc.saveas(tmp_path / "csk.dxf")
    text, _ = import_drawing((tmp_path / "csk.dxf").read_bytes(), "csk.dxf", infer=infer)
    assert "# holes: layer `HOLES` in `OUTLINE`" in text, text
    assert f"# countersinks: layer `{layer}` (4 circles) marked, not cut" in text, text
    # inferred, each countersink's mark is its hole's `Countersink` (issue 102), on the
    # COUNTERSINK layer; a counterbore's (no depth in the drawing) stays a drawing
    sunk = infer and "bore" not in layer.lower()
    assert text.count("solid ") == 1 and text.count("drawing ") == (0 if sunk else 1), text
    assert ("Countersink(" in text) == sunk, text
    res = _compile(text, tmp_path)
    assert not [d for d in res.diagnostics if d.severity == "warning"], res.diagnostics
    cut = sorted(e[1:] for e in _entities(res, "CUT") if e[0] == "C")
    marked = sorted(e[1:] for e in _entities(res, "COUNTERSINK" if sunk else "ENGRAVE")
                    if e[0] == "C")
    assert cut == sorted((x, y, 1.65) for x, y in centres)
    assert marked == sorted((x, y, 3.3) for x, y in centres)
