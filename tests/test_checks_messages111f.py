"""Issue 111's model runs aa-ab (round ten) and what run z7 left: an Align relation that
reads a point."""
from __future__ import annotations

from pathlib import Path

import pytest

import aidl_lang

RUNS = Path(__file__).resolve().parent.parent / "data" / "model_runs"


def _w(r, code):
    return [d for d in r.diagnostics if d.code == code]


def _num(r, name):
    return r.value(name).value


TAG = """solid stocking {
    sock = Spline([(-20, 75), (20, 75), (21, 45), (58, 6), (20, -12), (-25, 6)], closed=true,
                  corners=[0, 1])
    cuff = RoundedRectangle(center=(0, 78), width=56, height=20, corner_radius=4)
    Fixed(sock)
    AlignCenterX(cuff, sock.points[1])
    AlignBottom(cuff, sock.points[0])
}
"""


def test_an_align_relation_reads_a_point_as_its_coordinate():
    """Run z7's stocking tag wrote `AlignCenterX(cuff, sock.points[0])` and got E0108 ("must
    be a structure or geometry, got point"). A point is what a model reaches for to put a
    box's centre (or side) on it: each Align relation now reads a point as its x (center_x,
    left, right) or y (center_y, top, bottom), the first-named moving as with two boxes."""
    r = aidl_lang.compile(source=TAG)
    assert r.ok, [d.message for d in r.diagnostics]
    assert not [d for d in r.diagnostics if d.code.startswith("E")]
    c = r.value("stocking.cuff.center").value
    assert tuple(c) == pytest.approx((20.0, 85.0), abs=1e-9)    # points[1].x; points[0].y + 10
    assert _num(r, "stocking.cuff.width") == pytest.approx(56.0)   # the cuff kept its size
    # the spline did not move (it is Fixed; the cuff is the first-named)
    p = r.value("stocking.sock.p1").value
    assert tuple(p) == pytest.approx((20.0, 75.0), abs=1e-9)


@pytest.mark.parametrize("rel,side,want", [
    ("AlignLeft", "left", 30.0), ("AlignRight", "right", 30.0),
    ("AlignTop", "top", -12.0), ("AlignBottom", "bottom", -12.0),
    ("AlignCenterY", "center_y", -12.0)])
def test_each_align_relation_reads_the_points_own_axis(rel, side, want):
    src = f"""solid plate {{
    body = Rectangle(center=(0, 0), width=100, height=60)
    mark = Point(30 mm, -12 mm)
    Fixed(body)
    Fixed(mark)
    hole h {{ c = Circle(center=(0, 0), diameter=8) }}
    {rel}(h, mark.p)
    assert h.bb.{side} == {want} mm
}}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]


def test_a_relation_between_boxes_still_refuses_a_point():
    """`Above(lid, p)` has no meaning for a point (which side of it?): E0108 as before."""
    src = """solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    mark = Point(30 mm, -12 mm)
    Above(body, mark.p)
}
"""
    r = aidl_lang.compile(source=src)
    assert not r.ok
    assert any(d.code == "E0108" and "got point" in d.message for d in r.diagnostics)


def test_divider_tray_lowers_its_dividers_for_a_lid():
    """Run z7's tea box: a lid's 3 mm locating plate sat on the 2 x 2 dividers (as high as
    the walls), so the lid stood 3 mm proud; the model reached for a lower divider.
    `divider_height=` sets the dividers' height above the bottom, their halvings half of it;
    the tray assembled stands on z = 0 (its docs say so), and nothing collides."""
    src = """import "std/boxes.aidl"
assembly tea {
    tray = divider_tray(length=160 mm, width=160 mm, height=60 mm, rows=2, cols=2,
                        divider_height=45 mm)
    assert tray.row_divider[0].plate.bb.height == 45 mm
    assert tray.col_divider[0].plate.bb.height == 45 mm
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    assert not _w(r, "W0517") and not _w(r, "W0518")
    bad = aidl_lang.compile(source=src.replace("45 mm)", "58 mm)"))
    assert not bad.ok            # past the walls less the bottom (57 mm): the template's assert
    assert any("at most as high as the walls" in d.message for d in bad.diagnostics)


def test_text_takes_halign_for_its_anchor():
    """`halign="center"` beside `valign=` is what a model writes (run z5's sign, E0105 "no
    argument `halign`"): it is `anchor`'s other name."""
    src = """solid sign {
    body = Rectangle(center=(0, 0), width=120, height=50)
    drawing d { t = Text("AB", position=(0, 0), size=10, halign="left", valign="middle") }
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    ref = aidl_lang.compile(source=src.replace("halign=", "anchor="))
    assert [d.message for d in r.diagnostics] == [d.message for d in ref.diagnostics]
    assert r.to_svg() == ref.to_svg()


SUNDIAL = RUNS / "issue111aa/drafts/04_sundial.attempt3.aidl"


def test_a_strict_bound_below_the_tolerance_is_the_tolerance():
    """Run aa's sundial asserted `abs(dial.hours.ln[7].dx) < 1e-9` (the noon line runs
    north) and got E0405 at dx = 1.3e-15 ("`<` needs a gap of more than 1e-06 mm"): the
    author's own epsilon, below the one every comparison is judged within, is read as it.
    A strict comparison with a bound of 0 or above the tolerance keeps its gap."""
    from aidl_lang.geometry.relations.assertions import holds
    assert holds("<", 1.3e-15, 1e-9, "right") and holds(">", 1e-9, 1.3e-15, "left")
    assert holds("<", 5e-7, 1e-9, "right")      # within the tolerance, as `==` is
    assert not holds("<", 2e-6, 1e-9, "right")
    assert not holds("<", 1.3e-15, 1e-9)        # not a bound as written: the gap
    assert not holds("<", 1e-15, 0.0, "right")  # `x < 0` at x = 1e-15: a bound of 0
    assert not holds(">", 1e-7, 0.0, "right")   # `a > 0` at a = 1e-7 (issue 105)
    assert holds("<", 0.0095, 0.01, "right")    # a bound above the tolerance: strict
    assert not holds("<", 0.01, 0.01, "right")
    r = aidl_lang.compile(path=str(SUNDIAL))
    assert r.ok, [(d.code, d.message) for d in r.errors]


def test_a_long_condition_is_cut_with_an_ellipsis():
    """The sundial's third assert was quoted `... - 51` for `- 51.5 deg`: a quote cut at
    120 characters now ends in "..."."""
    src = SUNDIAL.read_text().replace("51.5 deg) < 1e-9)", "51.5 deg) < 1e-9 and 1 > 2)")
    r = aidl_lang.compile(source=src)
    e = [d for d in r.errors if d.code == "E0405"]
    assert len(e) == 1
    quote = e[0].message.split("`")[1]
    assert quote.endswith("...") and len(quote) == 120


TOPPER = RUNS / "issue111aa/run/06_cake_topper.first_valid.aidl"


def test_W0515_leads_with_the_fill_for_a_narrow_opening():
    """Run aa's cake topper: a star's two lower tips on the base rail enclosed a 7.1 x 2.4 mm
    window, a defect; W0515's suggested fix was `AllowOverlap(star_l, base_rail)`, which keeps
    it (a hint whose fix damages the part). An opening under 3 mm across is led by the fill,
    with no suggested fix; a wide window (a frame's) keeps its AllowOverlap fix."""
    r = aidl_lang.compile(path=str(TOPPER))
    w = _w(r, "W0515")
    assert len(w) == 2
    for d in w:
        assert "7.11 x 2.37 mm" in d.message
        assert d.hint.startswith("an opening under 3 mm across is rarely meant: fill it")
        assert d.fix is None
    frame = """solid frame {
    top = Rectangle(center=(0, 25), width=60, height=10)
    bottom = Rectangle(center=(0, -25), width=60, height=10)
    left = Rectangle(center=(-25, 0), width=10, height=62)
    right = Rectangle(center=(25, 0), width=10, height=62)
}
"""
    w2 = _w(aidl_lang.compile(source=frame), "W0515")
    assert len(w2) == 1 and w2[0].fix is not None and w2[0].hint.startswith("if it is meant")


def test_W0117_a_template_nothing_calls():
    """Run aa's lipstick stand kept `def joint_slots(x) -> hole` and never called it: a part
    or hole meant and not made, nothing said. W0117 names it; a library (no structure of its
    own) and a called template are not warned."""
    r = aidl_lang.compile(path=str(RUNS / "issue111aa/run/03_lipstick_stand.first_valid.aidl"))
    w = _w(r, "W0117")
    assert len(w) == 1 and "template `joint_slots` is defined but nothing calls it" in w[0].message
    lib = "def slot(x) -> hole { s = Rectangle(center=(x, 0), width=3, height=20) }\n"
    assert not _w(aidl_lang.compile(source=lib), "W0117")
    used = lib + "solid p {\n    b = Rectangle(center=(0, 0), width=50, height=40)\n    s = slot(5)\n}\n"
    assert not _w(aidl_lang.compile(source=used), "W0117")
    fn = "def twice(x) = 2 * x\n" + used
    w3 = _w(aidl_lang.compile(source=fn), "W0117")
    assert len(w3) == 1 and w3[0].message == "function `twice` is defined but nothing calls it"


def test_a_text_reads_its_string():
    """Run aa's sundial asserted a numeral's text (`num[7].text == "12"`): E0102 "no member
    `text`". A Text's `text` is the string it draws."""
    src = """def hour_name(h) = f"{h}"
solid plate {
    body = Rectangle(center=(0, 0), width=100, height=60)
    drawing d { t = Text(hour_name(12), position=(0, 0), size=10) }
    assert d.t.text == "12"
}
"""
    assert aidl_lang.compile(source=src).ok
    bad = aidl_lang.compile(source=src.replace('== "12"', '== "11"'))
    assert any('"12" == "11" is false' in d.message for d in bad.errors)


KERF_SRC = """kerf 0.2 mm
solid blob { s = Spline([(0, 0), (60, -10), (80, 30), (40, 50), (-10, 35)], closed=true) }
solid egg { e = Ellipse(center=(150, 0), rx=40, ry=25) }
solid word {
    body = Rectangle(center=(0, -80), width=120, height=50)
    hole w { t = Text("MUSIC", position=(0, -80), size=20, font="sans:Bold", valign="middle") }
}
"""


def _dxf_points(data: bytes, n: int = 8) -> dict:
    """Points along every LINE and ARC of a DXF, read by ezdxf, per layer."""
    import io
    import math
    import ezdxf
    doc = ezdxf.read(io.StringIO(data.decode()))
    pts: list = []
    ents = []
    for e in doc.modelspace():          # a polyline with bulges: its lines and arcs
        ents += list(e.virtual_entities()) if e.dxftype() == "LWPOLYLINE" else [e]
    for e in ents:
        if e.dxftype() == "LINE":
            a, b = e.dxf.start, e.dxf.end
            pts += [(a.x + (b.x - a.x) * i / n, a.y + (b.y - a.y) * i / n) for i in range(n + 1)]
        elif e.dxftype() == "ARC":
            c, r = e.dxf.center, e.dxf.radius
            a0, a1 = math.radians(e.dxf.start_angle), math.radians(e.dxf.end_angle)
            sweep = (a1 - a0) % (2 * math.pi)
            pts += [(c.x + r * math.cos(a0 + sweep * i / n), c.y + r * math.sin(a0 + sweep * i / n))
                    for i in range(n + 1)]
        else:
            assert e.dxftype() in ("CIRCLE", "TEXT", "MTEXT"), e.dxftype()
    return pts


def test_a_kerf_on_splines_ellipses_and_font_letters_is_cut_within_its_bound():
    """Run ab: `aidl check` said ok and `aidl render` refused three of eight parts ("the
    spline ... cannot be offset exactly": a Spline bird, a stencil's font letters, an
    Ellipse arch), with a hint, `kerf 0 mm`, that was E0109. Each curve is now followed by
    circular arcs within 1e-4 mm and offset exactly: the DXF, read back by ezdxf, has every
    point of every cut 0.1 mm (half the kerf) from the drawn curves, +- 1e-4."""
    import math
    from aidl_lang.geometry.shapes.curves import Arc, Circle, EllipticArc, Line, Spline
    r = aidl_lang.compile(source=KERF_SRC)
    assert r.ok
    drawn = [g for p in r.output.parts for lp in p.loops for g in lp.segments]

    def dist(q):
        best = math.inf
        for c in drawn:
            if isinstance(c, (Spline, EllipticArc)):
                d = c.curve.distance(q)
            elif isinstance(c, Line):
                (x0, y0), (x1, y1) = c.start, c.end
                dx, dy = x1 - x0, y1 - y0
                u = max(0.0, min(1.0, ((q[0] - x0) * dx + (q[1] - y0) * dy) / (dx * dx + dy * dy)))
                d = math.hypot(q[0] - x0 - u * dx, q[1] - y0 - u * dy)
            else:
                assert isinstance(c, (Arc, Circle))
                d = abs(math.dist(q, c.center) - c.radius)     # (the letters have no arcs)
            best = min(best, d)
        return best
    pts = _dxf_points(r.encode("dxf"))
    assert len(pts) > 5000
    d = [dist(q) for q in pts[::23]]
    assert 0.1 - 1e-4 < min(d) and max(d) < 0.1 + 1e-4
    for prog in ("03_balancing_bird", "04_music_stand", "06_camp_stool"):
        rr = aidl_lang.compile(path=str(RUNS / f"issue111ab/run/{prog}.first_valid.aidl"))
        assert rr.ok and rr.encode("svg")


def test_kerf_0_in_a_structure_and_on_the_command_line(tmp_path):
    """`kerf 0 mm` in a structure (the advice of the old refusal) was E0109 "must be a
    positive length"; `--kerf 0mm` was refused. Both now leave the cuts where drawn."""
    import subprocess
    import sys
    src = "kerf 0.2 mm\nsolid a {\n    kerf 0 mm\n    r = Rectangle(center=(0, 0), width=20, height=10)\n}\n"
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.diagnostics]
    plain = aidl_lang.compile(source=src.replace("kerf 0.2 mm\n", "").replace("    kerf 0 mm\n", ""))
    assert r.encode("dxf").count(b"LINE") == plain.encode("dxf").count(b"LINE")
    assert r.to_svg() == plain.to_svg()
    f = tmp_path / "a.aidl"
    f.write_text(src.replace("    kerf 0 mm\n", ""))
    out = subprocess.run([sys.executable, "-m", "aidl_lang", "render", str(f), "-o",
                          str(tmp_path / "a.svg"), "--kerf", "0mm"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "a.svg").read_text() == plain.to_svg()


def test_fillet_at_a_disc_and_an_arcslot_rounds_every_pattern_copy():
    """Run ab's boomerang: `Fillet([hub, blade.b], 8)` (a Circle and an ArcSlot, the form the
    prompt gives for "a tab on a disc") was E0108 "... got circular", naming neither. An
    ArcSlot's outline is now one the form reaches; and the blade's two copies (a
    CircularPattern of 3) are rounded alike, as a CAD pattern copies a fillet: six R8 arcs,
    three pairs alike, where the original's two were all."""
    from aidl_lang.geometry.shapes.curves import Arc
    r = aidl_lang.compile(path=str(RUNS / "issue111ab/drafts/05_boomerang.attempt1.aidl"))
    assert r.ok and not r.diagnostics, [(d.code, d.message) for d in r.diagnostics]
    arcs = [g for p in r.output.parts for lp in p.loops for g in lp.segments
            if isinstance(g, Arc) and abs(g.radius - 8) < 1e-9]
    sweeps = sorted(round(abs(a.sweep), 6) for a in arcs)
    assert len(arcs) == 6 and sweeps[0] == sweeps[2] and sweeps[3] == sweeps[5]
    src = (RUNS / "issue111ab/drafts/05_boomerang.attempt1.aidl").read_text()
    bad = aidl_lang.compile(source=src.replace("Fillet([hub, blade.b], 8)",
                                               "Fillet([hub, blade.b.center], 8)"))
    assert any(d.code == "E0108" for d in bad.errors)


def test_a_fillet_at_a_copy_that_meets_nothing_says_nothing():
    """A pattern copy whose outline does not reach the other shape (the original's does) is
    passed over: no E0408 for a corner the call never named."""
    src = """solid plate {
    hub = Circle(center=(0, 0), diameter=40)
    solid arm { a = Slot(start=(15, 0), end=(40, 0), width=10) }
    far = LinearPattern(arm, 2, (200, 0))
    Fillet([hub, arm.a], 3)
}
"""
    r = aidl_lang.compile(source=src)
    assert not [d for d in r.diagnostics if d.code in ("E0408", "W0406")], \
        [(d.code, d.message) for d in r.diagnostics]


def test_W0405_not_for_the_spacing_of_separate_parts():
    """Run ab's camp stool: `RightOf(leg_b, leg_a, gap=10)` between two separate legs of an
    assembly, each with `Fillet` at its feet, was W0405 twice ("reads the box ... before its
    Fillet ... 0.540 mm in"): the legs lie 10.54 mm apart on the drawing, which cuts nothing
    differently. A spacing relation between separate parts is not warned; within one part
    it still is."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ab/run/06_camp_stool.first_valid.aidl"))
    assert r.ok and not _w(r, "W0405")
    one = """solid sign {
    base = Rectangle(center=(0, 0), width=100, height=20)
    solid post {
        p = Polygon([(0, 10), (10, 30), (0, 50), (-10, 30)])
        Fillet(5)
    }
    Above(post, base, gap=-1)
}
"""
    assert _w(aidl_lang.compile(source=one), "W0405")


def test_W0502_of_a_template_hole_says_it_can_be_turned():
    """Run ab's fume extractor: two `cross_halving` slots with their mouths on the plate's
    bottom edge ran down off it at rotation 0; W0502's hint ("a sign or a unit off?") did not
    name the direction. For a template's hole with a `rotation`, it now does."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ab/run/02_fume_extractor.first_valid.aidl"))
    w = _w(r, "W0502")
    assert len(w) == 2
    assert all("`rotation=180 deg` (it has 0 deg) runs it the other way" in d.hint
               and "aidl docs cross_halving" in d.hint for d in w)


def test_E0401_says_a_shape_keeps_the_sizes_written_in_its_call():
    """Run aa's cake topper: a rail `Rectangle(..., width=100, ...)` between `AlignLeft(rail,
    star_l)` and `AlignRight(rail, star_r)`: E0401 listed "`Rectangle shape` (held by a
    constructor)" among seven, and the model had to guess that its placeholder width was
    held. The hint now says the sizes written in a call are kept, and how to let a relation
    set one."""
    r = aidl_lang.compile(path=str(RUNS / "issue111aa/drafts/06_cake_topper.attempt2.aidl"))
    (e,) = [d for d in r.errors if d.code == "E0401"]
    assert "The shapes on lines 21, 23, 24 keep the sizes written in their calls" in e.hint
    assert "`width=b.bb.right - a.bb.left`" in e.hint


def test_a_label_placed_between_a_hole_and_the_part_moves_alone():
    """Run ac's lucet: `mark.w.position.y == (hang.bb.top + head.bb.bottom) / 2` (a word
    centred between the hanging hole and the head, a shape of the part) moved the hole 1.9 mm
    as well as the word, while the freedom line called the hole "free but stays where written
    on its part". The first-named (the drawing) moves; the hole stays as written."""
    src = """solid lucet {
    handle = Rectangle(center=(0, 30), width=22, height=60)
    head = Circle(center=(0, 66), diameter=44)
    hole hang { c = Circle(center=(0, 8), diameter=5) }
    drawing mark { w = Text("EM", position=(0, 30), size=6) }
    mark.w.position.y == (hang.bb.top + head.bb.bottom) / 2
    assert hang.c.center.y == 8 mm
    assert head.center.y == 66 mm
    assert mark.w.position.y == (10.5 mm + 44 mm) / 2
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]
    r2 = aidl_lang.compile(path=str(RUNS / "issue111ac/drafts/07_lucet.attempt2.aidl"))
    assert r2.ok, [(d.code, d.message) for d in r2.errors]


def test_a_line_ending_in_a_comma_goes_on():
    """Runs aa (sundial) and ad (cue rack) put an assert's message on the line after its
    comma: E0001 "unexpected newline; expected a string". A newline after a `,` before a line
    indented deeper than the statement is now ignored (as inside brackets); the formatter
    indents the continuation one step; both first tries check. At the statement's own indent
    the line is a statement of its own: the error stays where the operand is missing."""
    from aidl_lang.editor.fmt import format_source
    src = ("param w = 100 mm,\n  min = 50 mm, max = 200 mm\nsolid plate {\n"
           "    body = Rectangle(center=(0, 0), width=w, height=60)\n"
           "    assert body.width == 100 mm,\n      \"the plate is 100 wide\"\n}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok and not r.diagnostics
    bad = aidl_lang.compile(source=src.replace("== 100 mm,", "== 90 mm,"))
    assert any("(the plate is 100 wide)" in d.message for d in bad.errors)
    out = format_source(src)
    assert "param w = 100 mm,\n    min = 50 mm" in out
    assert "    assert body.width == 100 mm,\n        \"the plate is 100 wide\"\n" in out
    assert format_source(out) == out
    for f in ("issue111aa/drafts/04_sundial.attempt1.aidl",
              "issue111ad/drafts/06_cue_rack.attempt1.aidl"):
        assert aidl_lang.compile(path=str(RUNS / f)).ok
    flat = aidl_lang.compile(source="solid p {\n    r = 5 +\n    c = Circle(center=(0, 0), radius=5)\n}\n")
    (e,) = flat.errors
    assert (e.code, e.span.line, e.span.col) == ("E0001", 2, 12)


def test_a_triangle_reads_its_base_and_height():
    """Run ac's plant obelisk asserted `t.height` of a `Triangle(center, base, height)`:
    E0102 "a Triangle has no member `height`". `base` is |ab| and `height` the apex c's
    distance from ab, for either form, turned or not."""
    src = """solid ob {
    t = Triangle(center=(0, 0), base=40, height=90, rotation=30 deg)
    u = Triangle((0, 0), (30, 0), (10, 20))
    assert t.base == 40 mm and t.height == 90 mm
    assert u.base == 30 mm and u.height == 20 mm
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]
    bad = aidl_lang.compile(source=src.replace("u.height == 20 mm", "u.height == 21 mm"))
    assert any("20 mm == 21 mm is false" in d.message for d in bad.errors)


def test_W0506_does_not_offer_to_delete_a_solid_other_statements_name():
    """Run s's no-parking sign: W0506 on its bar (cut away by the ring's hole) ended "else
    delete it"; applied, `At(bar.b.center, disc.center)` and an assert named nothing (E0101).
    A solid that a constraint places is meant: the hint keeps only the restructuring."""
    r = aidl_lang.compile(path=str(RUNS / "issue111s/run/08_no_parking_sign.first_valid.aidl"))
    w = _w(r, "W0506")
    assert len(w) == 2 and all("delete it" not in d.hint and "beside" in d.hint for d in w)


def test_living_hinge_docs_say_its_box_is_its_cuts():
    """Run ac's napkin ring asserted a living hinge's box as its band (`width` 41.5 mm) and
    found 0.75 mm less each side: the docs now say the box is the cuts' and by how much."""
    from aidl_lang.library.reference import stdlib_templates
    doc = stdlib_templates()["living_hinge"].doc
    assert "41.5 mm at pitch 2: 0.75 mm in each side" in doc
    src = """import "std/plates.aidl"
solid ring {
    band = Rectangle(center=(0, 0), width=60, height=80)
    h = living_hinge(width=41.5 mm, height=80 mm, pitch=2 mm)
    assert h.bb.width == 41.5 mm - 2 * 0.75 mm
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]


def test_W0513_measures_text_along_a_curve_by_its_strokes():
    """Run af's resistor colour-code wheel: labels set along circles were W0513 21 times
    ("their boxes overlap by 39.72 mm^2"): a curved text's straight box holds the curve's
    inside. Text along a curve is judged by how near the two texts' strokes come: none left
    (the nearest, VIOLET and its digit 7, 1.47 mm apart at 3 mm text, is a single character,
    which the rule leaves to a word laid out letter by letter, as for straight text). Two
    numbers round the kumihimo disc at 6 mm, strokes 0.62 mm apart, are warned as strokes."""
    r = aidl_lang.compile(path=str(RUNS / "issue111af/run/02_resistor_code_wheel.first_valid.aidl"))
    assert not _w(r, "W0513")
    src = (RUNS / "issue111z3/run/08_kumihimo_disc.first_valid.aidl").read_text()
    w = _w(aidl_lang.compile(source=src.replace("size=4, valign", "size=6, valign")), "W0513")
    assert len(w) == 1 and "their strokes are 0.62 mm apart" in w[0].message


def test_W0504_of_a_words_letters_does_not_lead_to_E0120():
    """Run af's house-number sign: "42" to glue on digit by digit was W0504, whose hint ("make
    the structure an `assembly`") gave E0120 (a font's letters stand in a solid). The hint
    now says the form that works: each letter a Text in a solid of its own in an assembly."""
    r = aidl_lang.compile(path=str(RUNS / "issue111af/run/08_house_number_sign.first_valid.aidl"))
    (w,) = _w(r, "W0504")
    assert "write each letter as a Text in a `solid` of its own in an `assembly`" in w.hint
    assert "make the structure an `assembly`" not in w.hint


def test_a_line_ending_in_an_operator_goes_on():
    """Run ae broke two asserts after `and` (knife block, gate latch): E0001 "unexpected
    newline". A line ending in an operator or `=` cannot end its statement, so it goes on;
    the formatter indents the continuation, and formats it back the same."""
    from aidl_lang.editor.fmt import format_source
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=100, height=60)\n"
           "    assert body.width == 100 mm and\n        body.height == 60 mm, \"the plate\"\n"
           "    w = body.width +\n        10 mm\n    assert w ==\n        110 mm\n}\n")
    r = aidl_lang.compile(source=src)
    assert r.ok and not r.diagnostics
    assert format_source(src) == src
    bad = aidl_lang.compile(source=src.replace("60 mm, ", "61 mm, "))
    assert any("(the plate)" in d.message for d in bad.errors)


def test_place_starts_from_the_parts_frame_not_its_place_on_the_sheet():
    """Run ae's pill organiser: the model put the lid's Place from where the sheet's layout
    had moved it, and the lid landed beside the tray. `aidl docs Place` now says Place starts
    from the part's own frame; here is that law: `RightOf(lid, tray, gap=10)` moves the lid
    on the sheet and not in 3D."""
    import numpy as np
    from aidl_lang.library.reference import lookup_text
    assert "the sheet's layout does not move the part in" in " ".join(lookup_text("Place")[0].split())
    src = """thickness 3 mm
assembly box {
    solid tray { r = Rectangle(center=(0, 0), width=60, height=40) }
    solid lid { r = Rectangle(center=(0, 0), width=60, height=40) }
    RightOf(lid, tray, gap=10)
    Place(lid, position=(0, 0, 20))
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok
    d = r.output.drawing
    name = next(n for n in d.placement if n.endswith("lid"))
    M = d.placement[name]
    sheet_centre = np.array([70.0, 0.0, 0.0, 1.0])          # where the lid lies on the sheet
    assert np.allclose((M @ sheet_centre)[:3], (0.0, 0.0, 20.0), atol=1e-9)


def test_W0505_says_an_engraving_lies_across_the_pieces_a_cut_frees():
    """Run ae's jigsaw: a heart, "10" and "ANNA & TOM" engraved across the 12 pieces its cut
    lines free were W0505 "runs outside the outline ... 71% off the material", with an
    AllowOverlap hint that silenced it and left the layout wrong (a cutting layout keeps the
    engraving with the first piece). The warning now says what happens and offers no
    AllowOverlap."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ae/run/08_jigsaw_puzzle.first_valid.aidl"))
    w = _w(r, "W0505")
    assert len(w) == 3
    assert all("of the pieces that the through-cuts free from `anniversary_puzzle.puzzle`"
               in d.message and "AllowOverlap" not in d.hint for d in w)
    assert [int(d.message.split("lies across ")[1].split()[0]) for d in w] == [4, 2, 4]


def test_exp_and_log_and_an_exponent_with_a_unit():
    """Run ah's Galton board wrote a bell curve with `e = 2.718281828` and `e ** (-(x ** 2) /
    (2 * sigma ** 2))` where sigma was a length: E0108 "an exponent must be a plain number"
    naming neither the unit nor the way out. `exp` and `log` now exist (plain numbers), and
    the message says what the exponent is and how its units cancel."""
    src = """solid g {
    sigma = 12 mm
    pts = [(x * 1 mm, 40 mm * exp(-(x * 1 mm / sigma) ** 2 / 2)) for x in range(-30, 31, 5)]
    p = Polygon(pts + [(30, -5), (-30, -5)])
    assert abs(log(exp(2)) - 2) < 1e-9
    assert p.bb.top == 40 mm
}
"""
    r = aidl_lang.compile(source=src)
    assert r.ok, [(d.code, d.message) for d in r.errors]
    bad = aidl_lang.compile(source=src.replace("exp(-(x * 1 mm / sigma) ** 2 / 2)",
                                               "2.718 ** (-(x * 1 mm) ** 2 / (2 * sigma))"))
    (e,) = bad.errors
    assert e.code == "E0108" and "this one is a length" in e.message and "exp(" in e.hint
    unit = aidl_lang.compile(source=src.replace("exp(-(x * 1 mm / sigma) ** 2 / 2)",
                                                "exp(-(x * 1 mm) / 2)"))
    assert any(d.code == "E0109" and "`exp` takes a plain number" in d.message
               for d in unit.errors)


def test_a_structure_that_hides_a_constant_is_said():
    """Run ag's donut wall: a constant `foot_l = 60 mm` and a `solid foot_l` whose Rectangle
    read `width=foot_l`: E0108 "must be a length, got solid structure", the cause unsaid. The
    hint now names the structure that hides the value, and the fix."""
    src = """foot_l = 60 mm
assembly wall {
    solid board { b = Rectangle(center=(0, 0), width=400, height=600) }
    solid foot_l {
        r = Rectangle(center=(0, -350), width=foot_l, height=20)
    }
}
"""
    (e,) = aidl_lang.compile(source=src).errors
    assert e.code == "E0108"
    assert "`foot_l` here is the solid `wall.foot_l` (line 4), which hides the outer `foot_l`" \
        in e.hint


def test_W0508_of_two_crossing_holes_leads_with_the_cross():
    """Run ag's earring tree: two tab_and_slot mortises crossing as one plus-shaped opening
    (a halved trunk) were W0508 with "move hole `mortise_b` 3.67 mm further" first, which
    breaks the joint. Holes that cross lead with the one opening and its AllowOverlap."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ag/run/08_earring_tree.first_valid.aidl"))
    (w,) = _w(r, "W0508")
    # round eleven: a note (both crossings of the corpus were meant), the cross first
    assert w.severity == "note" and "they cut one cross-shaped opening" in w.message
    assert w.hint.startswith("if it is meant, nothing is needed")
    assert w.hint.index("AllowOverlap(mortise_a, mortise_b)") < w.hint.index("3.67 mm further")


def test_W0513_near_a_mark_offers_a_move_before_a_smaller_text():
    """Run ag's switch plate: a 20 mm name too close to a row of engraved stars, hint "make
    the text smaller" alone (a size the request gave). A move is offered first."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ag/drafts/01_switch_finger_plate.attempt1.aidl"))
    w = [d for d in _w(r, "W0513") if "too close to the engraved" in d.message]
    # round twelve: a font's letters get the size that clears too
    assert w and w[0].hint.endswith("move the text or the mark clear of each other, or make "
                                    "the text at most 13.62 mm (size=13.62 mm)")
    fixed = (RUNS / "issue111ag/drafts/01_switch_finger_plate.attempt1.aidl").read_text()
    assert fixed.count("name_size = 20 mm") == 1
    r = aidl_lang.compile(source=fixed.replace("name_size = 20 mm", "name_size = 13.62 mm"))
    assert not [d for d in _w(r, "W0513") if "too close to the engraved" in d.message]


def test_W0518_of_a_part_never_placed_and_lying_away_is_a_note():
    """Run ai's nest box: a finger_box places its panels, the roof had no `Place` and lay on
    the sheet 243 mm away: W0518 "touches no other part", a false alarm as to the cut parts.
    A part with no Place farther than 5 mm from every other is a note saying so; one just
    short of another (a base 0.25 mm under its wall: tests/test_checks.py) stays a warning."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ai/run/04_nest_box.first_valid.aidl"))
    (w,) = _w(r, "W0518")
    assert w.severity == "note" and "243 mm away" in w.message


def test_W0411_not_for_a_windows_tip():
    """Run ai's clothes hanger: `Fillet(3)` rounded the 23.5 deg ends of a decorative window
    12.68 mm back: W0411 twice, no way to accept it, and harmless (a window's tip rounded is
    material kept). W0411 is for tips of the material (run z2's tail, run k's stake)."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ai/run/02_clothes_hanger.first_valid.aidl"))
    assert not _w(r, "W0411")


def test_tab_and_slot_docs_say_which_thickness_each_half_takes():
    """Run aj's DIN-rail clip (two materials): `thickness` is the mating panel's in the tab
    half and the tab panel's in the slot half; the docs now say so."""
    from aidl_lang.library.reference import stdlib_templates
    doc = " ".join(stdlib_templates()["tab_and_slot"].doc.split())
    assert 'the slotted panel\'s for "tab"' in doc and 'the tab panel\'s for "slot"' in doc


def test_W0502_not_for_an_overrun_shape_at_the_edge():
    """Run ak's squeegee hanger: a 1 mm `overrun=true` strip past the shelf's edge (where its
    slot opens) was W0502 "cuts nothing ... a sign or a unit off?"; it lies past the edge on
    purpose. An overrun shape at its solid's edge is not warned."""
    r = aidl_lang.compile(path=str(RUNS / "issue111ak/run/02_squeegee_hanger.first_valid.aidl"))
    assert not _w(r, "W0502")


def test_the_stroke_line_says_its_ends_are_round_by_default():
    """Run ak: the prompt's Stroke line read `cap="flat"`, the docs "round (the default)"."""
    from aidl_lang.llm.prompt import system_prompt
    line = next(t for t in system_prompt().splitlines() if t.startswith("- Stroke("))
    assert 'round ends, or cap="flat" for square ones' in line


def test_a_kerf_leaves_out_a_segment_its_neighbours_cover():
    """Run al's spirograph: `aidl check` said ok, `aidl render` refused the 52-tooth
    `spur_gear` at `kerf 0.15 mm` ("the arc ... is too short for an offset of 0.075 mm: its
    neighbours' offsets cover it"). Such a segment is left out and its neighbours' offsets
    meet where they cross: the exact offset. Every point of the cut path lies 0.075 mm from
    the drawn outline, +- 1e-9."""
    import math
    from aidl_lang.geometry.shapes.curves import Arc, Circle, Line
    from aidl_lang.output.fabrication.layout import for_cutting
    r = aidl_lang.compile(path=str(RUNS / "issue111al/run/02_spirograph.first_valid.aidl"))
    out = r.output
    cut = for_cutting(out)

    def dist(p, g):
        if isinstance(g, Line):
            (x0, y0), (x1, y1) = g.start, g.end
            dx, dy = x1 - x0, y1 - y0
            u = max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / (dx * dx + dy * dy)))
            return math.hypot(p[0] - x0 - u * dx, p[1] - y0 - u * dy)
        if isinstance(g, Circle):
            return abs(math.dist(p, g.center) - g.radius)
        a = math.atan2(p[1] - g.center[1], p[0] - g.center[0])
        lo = g.start_angle if g.sweep > 0 else g.start_angle + g.sweep
        if (a - lo) % (2 * math.pi) <= abs(g.sweep) + 1e-12:
            return abs(math.dist(p, g.center) - g.radius)
        return min(math.dist(p, g.start), math.dist(p, g.end))

    def points(g):
        if isinstance(g, Line):
            return [g.start, ((g.start[0] + g.end[0]) / 2, (g.start[1] + g.end[1]) / 2)]
        return [g.at(g.start_angle + g.sweep * i / 4) for i in range(5)] \
            if isinstance(g, Arc) else []
    (drawn,) = [p for p in out.parts if p.name.endswith(".big")]
    (offset,) = [p for p in cut.parts if p.name.endswith(".big")]
    segs = [g for lp in drawn.loops for g in lp.segments]
    d = [min(dist(q, g) for g in segs) for lp in offset.loops for s in lp.segments
         for q in points(s)[::3]]
    assert len(d) > 500 and max(abs(x - 0.075) for x in d) < 1e-9


def test_log_of_0_is_located():
    """`log(0)` is E0112 at the call, not a math error."""
    r = aidl_lang.compile(source="solid s {\n    b = Rectangle(center=(0, 0), width=10 * log(0), "
                                 "height=5)\n}\n")
    (e,) = r.errors
    assert e.code == "E0112" and "`log` of 0" in e.message and e.span.line == 2
