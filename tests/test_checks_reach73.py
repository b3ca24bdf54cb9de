"""Issue 73, "what models reach for": what the prompt left untold and the messages did not
say.  A Triangle (any shape) with literal corners is rigid; the conflict it takes part in
says `flexible=true` lets its points follow the constraints, and the prompt teaches it for
every shape that takes it."""
TRIANGLE = """solid s {
    body = Rectangle(center=(0, 0), width=40, height=20)
    t = Triangle((0, 0), (10, 0), (5, 8)%s)
    Coincident(t.c, body.top_right)
    Coincident(t.a, body.center)
}
"""


def test_a_conflict_with_a_literal_triangle_says_flexible_true_and_that_solves_it(compile_text):
    c = compile_text(TRIANGLE % "")
    (e,) = [d for d in c.sink.items if d.code == "E0401"]
    assert "The Triangle (line 3) keeps the shape its literal coordinates give" in e.hint
    assert "add `flexible=true` to its call" in e.hint
    c = compile_text(TRIANGLE % ", flexible=true")
    assert c.ok and not c.sink.errors()


def test_the_prompt_teaches_flexible_for_every_shape_that_takes_it():
    from aidl_lang.llm.prompt import system_prompt
    from aidl_lang.registry import ENTRIES
    text = system_prompt(examples=False)
    line = next(l for l in text.splitlines() if "flexible=true" in l)
    takers = sorted(n for n, e in ENTRIES.items()
                    if any(a.name == "flexible" for v in e.variants for a in v))
    assert takers and all(n in line for n in takers), (takers, line)


RACKET = """solid racket {
    head = Ellipse(center=(0, 0), rx=40, ry=55)
    drawing strings {
        for i in range(5) {
            s = Line((-30 + 15 * i, -40), (-30 + 15 * i, 40))
            dot = Line((-30 + 15 * i, 0), (-30 + 15 * i, 0))
        }
    }
}
"""


def test_a_drawing_line_of_zero_length_is_W0524_once_per_statement_located(compile_text):
    c = compile_text(RACKET)
    (w,) = [d for d in c.sink.items if d.code == "W0524"]
    assert (w.span.line, w.span.col) == (6, 19)
    assert w.message.startswith("`racket.strings.dot` is a Line of zero length (5 copies): its "
                                "start and end are both at (-30, 0)")
    c = compile_text(RACKET.replace("(-30 + 15 * i, 0))", "(-25 + 15 * i, 0))"))
    assert not [d for d in c.sink.items if d.code == "W0524"]


def test_W0524_measures_every_line_at_once_to_1e_9_mm_beside_a_texts_strokes(compile_text):
    """W0524 measures every drawing line's length in one array pass (a text's strokes are
    lines too): a Line 1e-10 mm long is warned, one 2e-9 mm long is not, and the text beside
    them (its strokes all longer) adds nothing.  Two compiles, ~0.3 s."""
    src = ("solid tag {\n    body = Rectangle(center=(0, 0), width=60, height=30)\n"
           "    drawing marks {\n        label = Text(\"TAG 1.\", (0, 5), size=5)\n"
           "        a = Line((-20, -8), (-20 + %s, -8))\n        b = Line((10, -8), (20, -8))\n"
           "    }\n}\n")
    c = compile_text(src % "1e-10")
    (w,) = [d for d in c.sink.items if d.code == "W0524"]
    assert w.span.line == 5 and w.message.startswith("`tag.marks.a` is a Line of zero length: ")
    c = compile_text(src % "2e-9")
    assert not [d for d in c.sink.items if d.code == "W0524"]


def test_an_AllowOverlap_naming_holes_30_mm_apart_is_W0523_at_the_statement(compile_text):
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=80, height=40)\n"
           "    hole a { c = Circle(center=(-20, 0), radius=5) }\n"
           "    hole b { c = Circle(center=(%s, 0), radius=5) }\n    AllowOverlap(a, b)\n}\n")
    c = compile_text(src % "20")
    (w,) = [d for d in c.sink.items if d.code == "W0523"]
    assert (w.span.line, w.span.col) == (5, 5) and "`plate.a`, `plate.b`" in w.message
    c = compile_text(src % "-12")          # they overlap: it silences the W0508
    assert not [d for d in c.sink.items if d.code in ("W0523", "W0508")]


CORNERS = """thickness 1.5875 mm
solid plate {
    body = Rectangle(center=(0, 0), width=100, height=40)
    hole corners {
        a = Rectangle(center=(-49, 19), width=4, height=4)
        b = Rectangle(center=(49, 19), width=4, height=4)
    }
    hole nut { hex = RegularPolygon(center=(0, 0), sides=6, radius=10) }
}
"""


def test_describe_states_the_thickness_as_written_a_hexagons_side_and_one_notch_per_cut_out(
        tmp_path, capsys):
    import json
    from aidl_lang.cli.main import main
    f = tmp_path / "corners.aidl"
    f.write_text(CORNERS)
    assert main(["check", str(f), "--describe"]) == 0
    out = capsys.readouterr().out
    assert "material: 1.5875 mm thick" in out              # was 1.587
    assert "6-gon 20 x 17.321, side 10 at (0, 0)" in out    # was no side
    notches = [ln for ln in out.splitlines() if "notch in the top edge" in ln]
    assert [n.split(",")[0:2] for n in notches] == [["  notch in the top edge: 3 wide", " 3 deep"]] * 2
    assert "at (-48.5, 18.5)" in notches[0] and "at (48.5, 18.5)" in notches[1]   # was one, 100 wide
    assert main(["check", str(f), "--describe", "--json"]) == 0
    part = json.loads(capsys.readouterr().out)["describe"]["parts"][0]
    assert part["thickness"] == 1.5875 and [n["width"] for n in part["notches"]] == [3, 3]
