"""A drawing given to a template's part with `CutInto` is engraved on it (issue 111's fourth
fresh-model run, data/model_runs/issue111d: "TEA" on a finger box's front was left beside the
box, and `--layout sheet` cut the front blank), W0116 for a drawing left in the assembly on a
part, and `aidl import` giving a drawing layer that lies on a part to it (a board's
silkscreen), through the real compiler, layout and importer."""
from __future__ import annotations

from pathlib import Path

import pytest

import aidl_lang

ROOT = Path(__file__).resolve().parent.parent

TEA = """import "std/joints.aidl"
thickness 3 mm
assembly kit {
    box = finger_box(length=150 mm, depth=75 mm, height=80 mm, thickness=3 mm, finger=10 mm,
                     closed=false)
    drawing label {
        word = Text("TEA", position=(0, 0), size=25, font="sans:Bold", valign="middle", fill=true)
    }
    AlignCenterX(label, box.front)
    label.bb.center_y == box.front.bb.bottom + 50 mm
%s}
"""


def _w(r, code):
    return [d for d in r.diagnostics if d.code == code]


def test_a_drawing_left_on_a_part_is_W0116_and_its_fix_engraves_it_there():
    """Without `CutInto`, the word lies on the front and belongs to no part: W0116, whose fix
    is the call; the layout leaves its strokes out.  With the fix applied, no warning, every
    stroke of the word is the front's, and the layout keeps them all."""
    loose = aidl_lang.compile(TEA % "")
    (w,) = _w(loose, "W0116")
    assert "drawing `kit.label` is declared in assembly `kit`" in w.message
    assert "it lies on `kit.box.front`" in w.message
    assert w.fix.replacement.startswith("CutInto(label, box.front)\n")
    strokes = [s for s in loose.output.engrave if s.style in ("drawing", "fill")]
    assert strokes and {s.part for s in strokes} == {""}
    assert loose.layout().dropped == len(strokes)
    text = TEA % ""
    fixed = text[:w.fix.span.start] + w.fix.replacement + text[w.fix.span.end:]
    given = aidl_lang.compile(fixed)
    assert given.ok and not [d for d in given.diagnostics if d.severity == "warning"], \
        [d.message for d in given.diagnostics]
    mine = [s for s in given.output.engrave if s.style in ("drawing", "fill")]
    assert len(mine) == len(strokes) and {s.part for s in mine} == {"kit.box.front"}
    assert given.layout().dropped == 0
    # the flat sheet is the same part either way: the word's strokes where they were
    assert [s.segments for s in mine] == [s.segments for s in strokes]
    # the layout's DXF, re-read by ezdxf: the word is engraved (FILL) inside the front's cut
    # outline wherever the nesting put it, and the loose word is on no layer of it at all
    import io
    import ezdxf
    from ezdxf import bbox

    def layers(res):
        (data,) = res.layout().encode("dxf")
        doc = ezdxf.read(io.StringIO(data.decode()))
        out: dict = {}
        for ent in doc.modelspace():
            out.setdefault(ent.dxf.layer, []).append(ent)
        return out
    assert "FILL" not in layers(loose)
    got = layers(given)
    word, front = bbox.extents(got["FILL"]), bbox.extents(got["CUT-kit.box.front"])
    assert sorted((front.size.x, front.size.y)) == pytest.approx([80, 150], abs=1e-6)
    assert front.inside(word.extmin) and front.inside(word.extmax)


def test_a_given_drawing_is_checked_on_its_part_and_said_meant_from_the_assembly():
    """A line given to the front that runs past its right edge is W0505 on the front; its hint
    writes the call in the assembly (`self` is not the front there), which silences it."""
    src = TEA % ("    drawing mark { l = Line((0, 0), (80, 0)) }\n"
                 "    mark.bb.left == box.front.bb.left + 100 mm\n"
                 "    mark.bb.bottom == box.front.bb.bottom + 10 mm\n"
                 "    CutInto(mark, box.front)\n    CutInto(label, box.front)\n")
    r = aidl_lang.compile(src)
    (w,) = _w(r, "W0505")
    assert "engraving `kit.mark.l` runs outside the outline of `kit.box.front`" in w.message
    assert "`AllowOverlap(mark.l, box.front)` in `kit`" in w.hint
    r2 = aidl_lang.compile(src.replace("    CutInto(mark, box.front)\n",
                                       "    CutInto(mark, box.front)\n"
                                       "    AllowOverlap(mark.l, box.front)\n"))
    assert r2.ok and not _w(r2, "W0505") and not _w(r2, "W0523")


def test_CutInto_of_a_drawing_in_a_solid_or_twice_is_E0108():
    r = aidl_lang.compile("""solid a {
    body = Rectangle(center=(0, 0), width=50, height=30)
    drawing d { l = Line((-10, 0), (10, 0)) }
}
assembly k {
    b = a
}
""")
    assert r.ok
    inside = aidl_lang.compile("""assembly k {
    solid a {
        body = Rectangle(center=(0, 0), width=50, height=30)
        drawing d { l = Line((-10, 0), (10, 0)) }
    }
    CutInto(a.d, a)
}
""")
    (e,) = _w(inside, "E0108")
    assert "lies on `k.a`, the solid it is declared in" in e.message
    assert "`CutInto` is for a drawing declared in an assembly" in e.message


def test_import_gives_a_silkscreen_layer_to_its_board(tmp_path):
    """The KiCad board of examples/parts: its `F.SilkS` text lies on `Edge.Cuts`, so both
    importers write `CutInto(f_silks, edge_cuts)`; the program checks without a warning and
    the layout keeps the text."""
    from aidl_lang.drawing.infer import import_drawing
    data = (ROOT / "examples" / "parts" / "pcb_board.dxf").read_bytes()
    for infer in (True, False):
        text, _ = import_drawing(data, "pcb_board.dxf", infer=infer)
        assert "    CutInto(f_silks, edge_cuts)\n" in text, text[-400:]
        r = aidl_lang.compile(text)
        assert r.ok and not [d for d in r.diagnostics if d.severity == "warning"], \
            [d.message for d in r.diagnostics]
        assert {s.part for s in r.output.engrave} == {"drawing_import.edge_cuts"}
        assert r.layout().dropped == 0


def test_a_patterns_copies_follow_their_original_into_the_part():
    """issue111l's hamster house: `GridPattern(air, 3, 5, ...)` then `CutInto(air, box.lid)`
    cut 1 of 15 air holes (14 W0109s).  The copies follow their original, whichever is
    written first, and `CutInto(vents, box.lid)` takes the pattern's list: 15 holes in the
    lid each way, no W0109."""
    head = ('import "std/joints.aidl"\nthickness 3 mm\nassembly kit {\n'
            '    box = finger_box(length=120 mm, depth=80 mm, height=50 mm)\n'
            '    hole air { c = Circle(center=(-20, -20), diameter=5) }\n'
            '    CenterInside(air, box.lid)\n')
    for body in ("    vents = GridPattern(air, 3, 5, 10)\n    CutInto(air, box.lid)\n",
                 "    CutInto(air, box.lid)\n    vents = GridPattern(air, 3, 5, 10)\n",
                 "    vents = GridPattern(air, 3, 5, 10)\n    CutInto(vents, box.lid)\n"):
        r = aidl_lang.compile(head + body + "}\n")
        assert r.ok and not _w(r, "W0109"), [d.message for d in r.diagnostics]
        lid = {p.name: p for p in r.output.parts}["kit.box.lid"]
        assert len(lid.loops) == 16, body                # the outline and 15 holes
