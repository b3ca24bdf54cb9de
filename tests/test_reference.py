"""`aidl docs` and the reference it prints (aidl_lang/library/reference.py): a topic for every registry
name, statement and standard-library template, each with an example that compiles; lenient
lookups; the stdlib doc comments the prompt and the topics are generated from."""
from __future__ import annotations

import contextlib
import io

import pytest

from aidl_lang import ast as A
from aidl_lang.api import compile as aidl_compile
from aidl_lang.cli.main import main
from aidl_lang.llm.prompt import system_prompt
from aidl_lang.pipeline import compile_source
from aidl_lang.library.reference import (STATEMENTS, find, index_text, lookup_text, stdlib_templates,
                                 suggest, topics)
from aidl_lang.registry import ENTRIES, SYNONYMS

STDLIB_NAMES = {"spur_gear", "gear_pair", "washer", "bolt_circle", "rounded_tab", "slot_hole",
                "hex_pocket", "finger_panel", "finger_box", "clearance_hole", "nut_trap",
                "t_slot", "rounded_plate", "chamfered_plate", "mounting_plate", "keyhole",
                "slot", "living_hinge", "text_on_arc"}
STDLIB_NAMES |= {"lid_box", "sliding_lid_box", "divider_tray"}                  # issue 52: boxes
STDLIB_NAMES |= {"tab_and_slot", "dovetail", "cross_halving", "finger_edge",    # issue 52: joints,
                 "tablet_stand", "laptop_stand", "tool_holder", "wall_shelf"}   # stands, holders
STDLIB_NAMES |= {"board_enclosure", "gear_train", "rack_and_pinion",         # issue 52: enclosures,
                 "planetary"}                                                    # mechanisms
STDLIB_NAMES |= {"ring_gear"}                                   # issue 95: the internal gear
STDLIB_NAMES |= {"hinged_box", "drawer", "flex_box"}                          # issue 52: more boxes


def run_cli(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()


def test_every_registry_name_statement_and_template_has_a_topic():
    ts = topics()
    for name in ENTRIES:
        assert name in ts and ts[name].kind in ("shape", "constraint", "structural relation", "3D placement",
                                                "operation"), name
    for name in STATEMENTS:
        assert ts[name].kind == "statement"
    assert set(stdlib_templates()) == STDLIB_NAMES        # the library as it is today
    for name in STDLIB_NAMES:
        assert find(name).kind.endswith(".aidl") and "template" in find(name).kind
    for needed in ("assert", "kerf", "thickness", "import", "param", "def", "bb", "hole"):
        assert needed in ts
    for syn, canon in SYNONYMS.items():
        assert find(syn).name == canon, syn


@pytest.mark.parametrize("name", sorted(topics()))
def test_every_topic_example_compiles_cleanly(name):
    t = topics()[name]
    assert t.example, f"{name} has no example"
    # as `aidl check` runs it: the redundancy (W0401) and sliding (W0404) searches too; a
    # model copies these examples, so none may warn (issue 61: 19 of them did)
    res = aidl_compile(t.example, path=f"/tmp/aidl-docs-{name}.aidl")
    res.find_redundant(seconds=None, max_rows=None)
    assert res.ok and not res.sink.items, [f"{d.code} {d.message}" for d in res.sink.items]
    # the printed topic carries the example as it compiled
    assert t.example.strip().splitlines()[0] in t.render()


def test_topic_gives_signature_units_and_members():
    text = find("spur_gear").render()
    assert "spur_gear(teeth=20, module=2 mm, pressure_angle=20 deg, bore=0 mm" in text
    assert "phase = 0 deg: an angle" in text and "angle: degrees (`30` or `30 deg`" in text
    # its Anchor line (issue 111), no longer a generic "center's starting position"
    assert "cx = 0 mm: a length; the x of (cx, cy), the centre of `hub`" in text
    assert "teeth = 20: a number" in text
    for m in ("bore_hole", "pitch", "hub", "teeth_ring"):
        assert m in text.split("Members")[-1]
    assert "hub.center" in text                             # where the gear's center is
    assert 'import "std/gears.aidl"' in text
    # a list default is shown with its kind, not `teeth = ...: any` (issue 86)
    train = find("gear_train").render()
    assert "teeth = [12, 36, 12, 30]: a list of numbers" in train
    assert "gear_train(teeth=[12, 36, 12, 30], module=2 mm" in train
    circle = find("Circle").render()
    assert "Circle(center, radius)" in circle and "Circle(center, diameter)" in circle
    assert "radius: length" in circle and "length: a number in the file's unit" in circle
    assert "points: center top bottom left right" in circle
    assert "construction=false" in circle
    assert "Also written" in find("Perpendicular").render()        # Orthogonal
    assert "Contains" in find("Inside").render()


@pytest.mark.parametrize("written, topic", [
    ("SpurGear", "spur_gear"), ("spur-gear", "spur_gear"), ("SPUR_GEAR", "spur_gear"),
    ("gears.spur_gear", "spur_gear"), ("spur_gear()", "spur_gear"),
    ("Slot", "Slot"), ("slot", "slot"), ("regular_polygon", "RegularPolygon"),
    ("Orthogonal", "Perpendicular"), ("Contains", "Inside"), ("bbox", "bb"), ("self", "bb"),
    ("elif", "if"), ("sin", "functions"), ("mm", "units"), ("Assert", "assert"),
    ("text-on-arc", "text_on_arc"), ("template", "def"),
])
def test_lookups_are_lenient(written, topic):
    assert find(written).name == topic


def test_unknown_names_get_did_you_mean():
    assert suggest("spur_gaer")[0] == "spur_gear"
    assert "spur_gear" in suggest("gear")
    assert suggest("Rectangel")[0] == "Rectangle"
    text, found = lookup_text("Rectangel")
    assert not found and "did you mean `Rectangle`" in text
    assert find("Frobnicate") is None


def test_aidl_docs_command():
    rc, out, _ = run_cli("docs")
    assert rc == 0
    for name in list(ENTRIES) + list(STDLIB_NAMES) + ["assert", "kerf", "thickness"]:
        assert name in out, name
    assert out == index_text()
    rc, out, _ = run_cli("docs", "SpurGear")
    assert rc == 0 and out.startswith("spur_gear (solid template, std/gears.aidl)")
    rc, out, err = run_cli("docs", "spur-gaer")
    assert rc == 2 and out == "" and "did you mean `spur_gear`" in err


def _body_names(stmts) -> set:
    out = set()
    for st in stmts:
        if isinstance(st, (A.Assign, A.StructDecl)):
            out.add(st.name)
        elif isinstance(st, A.For):
            out |= _body_names(st.body.stmts)
        elif isinstance(st, A.If):
            out |= _body_names(st.body.stmts)
            if st.orelse is not None:
                out |= _body_names(st.orelse.stmts)
    return out


def test_stdlib_doc_comments_are_complete_and_true():
    """Every stdlib template has a doc comment whose first sentence is one short line, and the
    members it names exist in its body (the prompt and `aidl docs` are made from them)."""
    for t in stdlib_templates().values():
        assert t.doc and t.summary.endswith("."), t.name
        assert len(t.summary.split()) <= 20, (t.name, t.summary)
        assert t.members, f"{t.name}: no `Members:` sentence"
        names = _body_names(t.node.body.stmts)
        for m in t.members:
            assert m in names, (t.name, m)
        assert "cx" in [p.name for p in t.node.params], t.name


def test_prompt_lists_every_stdlib_template_from_its_doc_comment():
    text = system_prompt()
    for t in stdlib_templates().values():
        line = next(ln for ln in text.splitlines() if ln.startswith(f"- {t.name}("))
        assert t.summary in line and f"-> {t.node.kind}" in line
        assert "cx=" not in line                   # said once for all
        assert ", ".join(t.members) in line
    for needle in ("assert cond", "thickness 3 mm", "kerf 0.15 mm", "Rigid(a, b, ...)", "Fixed(x)",
                   "never turns", "holes included", "plate.body.bb"):
        assert needle in text, needle


def test_no_message_or_hint_names_a_file_the_model_cannot_read():
    """Diagnostics and `aidl explain` point to `aidl docs X`, never to docs/*.md: a model
    (through the CLI or MCP) has the tool but not the source tree.  Every string literal of the
    compiler that is not a docstring is looked at; the front ends that link documentation
    for people (command-line help, the language server's code links, MCP resource
    descriptions, LLM report files) are left out."""
    import ast
    import re
    from pathlib import Path

    import aidl_lang
    from aidl_lang.base.codes import CODES
    md = re.compile(r"\b[\w./-]+\.md\b")
    for code, (title, text) in CODES.items():
        assert not md.search(title + text), code
    pkg = Path(aidl_lang.__file__).parent
    people = {"cli", "editor", "llm", "mcp", "batch", "serve"}
    bad = []
    for f in sorted(pkg.rglob("*.py")):
        rel = f.relative_to(pkg)
        if rel.parts[0] in people:
            continue
        tree = ast.parse(f.read_text(encoding="utf-8"))
        docs = {id(n.body[0].value) for n in ast.walk(tree)
                if isinstance(n, (ast.Module, ast.FunctionDef, ast.ClassDef,
                                  ast.AsyncFunctionDef))
                and n.body and isinstance(n.body[0], ast.Expr)
                and isinstance(n.body[0].value, ast.Constant)}
        for n in ast.walk(tree):
            if (isinstance(n, ast.Constant) and isinstance(n.value, str)
                    and id(n) not in docs and md.search(n.value)):
                bad.append(f"{rel}:{n.lineno}: {n.value[:80]!r}")
    assert not bad, bad


def test_unknown_function_hint_points_to_aidl_docs(compile_text):
    res = compile_source("solid p {\n    x = Frobnicate(1)\n}\n", "/tmp/aidl-frob.aidl")
    [d] = [d for d in res.sink.items if d.code == "E0103"]
    assert "aidl docs" in d.hint and ".md" not in d.hint


# ------------------------------------------------------------------ did-you-mean and units
def _diag(src: str, code: str, tmp_path):
    f = tmp_path / "p.aidl"
    f.write_text(src)
    res = compile_source(src, str(f))
    found = [d for d in res.sink.items if d.code == code]
    assert found, [f"{d.code} {d.message}" for d in res.sink.items]
    return found[0]


def test_did_you_mean_ignores_case_and_word_style():
    from aidl_lang.base.diagnostics import did_you_mean
    assert did_you_mean("SpurGear", ["spur_gear", "Rectangle", "gear_pair"])[0] == "spur_gear"
    assert did_you_mean("spur-gear", ["spur_gear"]) == ["spur_gear"]
    assert did_you_mean("ROUNDED_PLATE", ["rounded_plate", "rounded_tab"])[0] == "rounded_plate"


def test_imported_template_in_another_style_is_named_with_its_parameters(tmp_path):
    d = _diag('import "std/gears.aidl"\nsolid part {\n    g = SpurGear(teeth=20)\n}\n',
              "E0103", tmp_path)
    assert d.suggestions[0] == "spur_gear" and d.fix.replacement == "spur_gear"
    assert "spur_gear(teeth=20, module=2 mm, pressure_angle=20 deg" in d.hint
    assert "angles (degrees" in d.hint and "pressure_angle, phase" in d.hint
    assert "cx, cy: (cx, cy) is the centre of `hub`" in d.hint      # its Anchor line
    # a template of the file itself, too
    d = _diag("def my_plate(w=40 mm) -> solid {\n    r = Rectangle(center=(0, 0), width=w, "
              "height=10)\n}\nsolid part {\n    p = MyPlate(w=30 mm)\n}\n", "E0103", tmp_path)
    assert d.suggestions[0] == "my_plate" and "`my_plate(w=40 mm) -> solid`" in d.hint


def test_a_stdlib_template_used_without_its_import_names_the_import(tmp_path):
    d = _diag("solid part {\n    g = spur_gear(teeth=20)\n}\n", "E0103", tmp_path)
    assert 'import "std/gears.aidl"' in d.hint and "aidl docs spur_gear" in d.hint


def test_unknown_argument_hint_gives_every_unit(tmp_path):
    # an imported template: checked when it runs (the interpreter)
    d = _diag('import "std/gears.aidl"\nsolid part {\n    g = spur_gear(teeth=20, '
              'angle=10 deg)\n}\n', "E0105", tmp_path)
    assert "phase=0 deg" in d.hint and "angles (degrees" in d.hint and "phase" in d.hint
    assert "lengths (the file's unit" in d.hint and "cx, cy" in d.hint
    # a template of the file (the checker), with did-you-mean
    d = _diag("def tab(width=10 mm, turn=0 deg) -> solid {\n    r = Rectangle(center=(0, 0), "
              "width=width, height=5, rotation=turn)\n}\nsolid part {\n    t = tab(widht=5)\n}\n",
              "E0105", tmp_path)
    assert d.hint.startswith("did you mean `width`?")
    assert "lengths (the file's unit, mm by default, or e.g. `5 mm`): width" in d.hint
    assert "angles (degrees, or e.g. `1 rad`): turn" in d.hint
    # a shape of the registry
    d = _diag("solid part {\n    c = Circle(centre=(0, 0), radius=3)\n}\n", "E0105", tmp_path)
    assert d.suggestions[0] == "center"
    assert "units: points `(x, y)`: center; lengths (the file's unit" in d.hint
    assert "radius, diameter" in d.hint


# ------------------------------------------------------------------ what the prompt claims
def _booleans_example() -> str:
    from aidl_lang.llm.prompt import code_blocks
    return code_blocks(system_prompt(examples=0))[0]


def test_the_prompt_booleans_example_is_true():
    """The four-line example: the hole cuts its solid's own shape and its solid child (one
    opening through both); declared inside the child instead, it cuts only the child and the
    parent's body fills it again (W0501)."""
    import aidl_lang
    src = _booleans_example()
    r = aidl_lang.compile(src, path="booleans.aidl")
    assert r.ok and not r.diagnostics
    [part] = r.parts
    assert part.holes == 1
    # body 60 x 30 plus the boss's cap above y = 15, minus the whole bore (r = 4)
    import math
    cap = 64 * math.acos(5 / 8) - 5 * math.sqrt(64 - 25)      # circular segment, h = 3
    assert part.area == pytest.approx(60 * 30 + cap - math.pi * 16, abs=1e-3)
    inside = src.replace("    hole bore { c = Circle(center=(-15, 10), radius=4) }   # opening "
                         "through body and boss\n", "")
    inside = inside.replace("radius=8) }", "radius=8)\n        hole bore { c = Circle(center="
                            "(-15, 10), radius=4) } }")
    assert inside != src and "hole bore" in inside
    r = aidl_lang.compile(inside, path="booleans.aidl")
    assert "W0501" in [d.code for d in r.diagnostics]
    assert r.parts[0].holes == 0                   # the body filled the opening again


@pytest.mark.parametrize("turn", [
    "tri = Polygon([(0, 0), (20, 0), (10, 10)])\n    tri.edges[0].angle == 30 deg",
    "r = Rectangle(center=(0, 0), width=20, height=10)\n    r.bottom.angle == 30 deg",
    "a = Rectangle(center=(0, 0), width=20, height=10)\n    b = Rectangle(center=(30, 0), "
    "width=10, height=10)\n    Rigid(a, b)\n    Angle(a.bottom, b.bottom, 30 deg)",
])
def test_shapes_the_prompt_says_never_turn_do_not(turn, tmp_path):
    d = _diag("solid p {\n    " + turn + "\n}\n", "E0401", tmp_path)
    assert "conflict" in d.message


def test_a_line_through_guessed_points_may_turn(tmp_path):
    src = ("solid p {\n    a = Line((0, 0), (20, 0))\n    b = Line(start=a.end, end=(0, 10))\n"
           "    c = Line(start=b.end, end=a.start)\n    Fixed(a.start)\n    a.angle == 30 deg\n}\n")
    res = compile_source(src, str(tmp_path / "p.aidl"))
    assert res.ok and not [d for d in res.sink.items if d.severity == "error"]


def test_rigid_ties_two_structures_together(tmp_path):
    """What the prompt says of Rigid: `Rigid(a, b)` of two structures moves them as one body,
    so placing each hole somewhere else conflicts (E0401 naming the Rigid), and placing one
    carries the other along."""
    src = ("solid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    hole a { c = Circle(center=(-10, 0), radius=3) }\n"
           "    hole b { c = Circle(center=(10, 0), radius=3) }\n    Fixed(body)\n"
           "    Rigid(a, b)\n    a.c.center == (-12, 2)\n    %s\n}\n")
    res = compile_source(src % "b.c.center == (12, -2)", str(tmp_path / "p.aidl"))
    (e,) = [d for d in res.sink.items if d.code == "E0401"]
    assert "Rigid(a, b)" in str([lab.message for lab in e.labels])
    res = compile_source(src % "assert b.c.center == (8, 2)", str(tmp_path / "p.aidl"))
    assert res.ok and not [d for d in res.sink.items if d.severity == "error"]


def test_template_parameters_say_their_kind_and_a_missing_default_as_required():
    """Issue 86: a template parameter without a default is `required`, lists say what they
    hold, a point default is a point."""
    from aidl_lang import ast as A
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.parser import parse
    from aidl_lang.library.reference import StdTemplate, _template_topic
    src = ("def tray(cells, widths=[10 mm, 20 mm], at=(0, 0), spots=[(1, 2), (3, 4)],\n"
           "         rows=[[1, 2], [3, 4]]) -> solid {\n"
           "    body = Rectangle(center=at, width=10, height=10)\n}\n")
    d = next(s for s in parse(src, "t.aidl", DiagnosticSink()).stmts if isinstance(s, A.Def))
    text = _template_topic(StdTemplate("tray", "trays", d, "A tray.", ())).render()
    assert "  cells: a value, required" in text
    assert "  widths = [10 mm, 20 mm]: a list of lengths" in text
    assert "  at = (0, 0): a point (x, y)" in text
    assert "  spots = [(1, 2), (3, 4)]: a list of points" in text
    assert "  rows = [[1, 2], [3, 4]]: a list" in text
