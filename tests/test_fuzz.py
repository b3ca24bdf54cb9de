"""Fuzzing: random text, mutated example programs and randomly generated programs go through
the whole pipeline, which must answer with diagnostics or a model and never raise."""
import functools
import re

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from aidl_lang.base.codes import CODES
from aidl_lang.base.diagnostics import LINE_BREAK, render_text, split_lines
from aidl_lang.pipeline import compile_source
from aidl_lang.output import render_model, to_svg

from conftest import EXAMPLES, ROOT

SOURCES = [(str(p), p.read_text()) for p in EXAMPLES]
TOKEN = re.compile(r"[A-Za-z_][A-Za-z_0-9]*|\d+\.?\d*|\S")
VOCAB = ["(", ")", "[", "]", "{", "}", ",", "=", "==", "<=", ">=", ".", "//", "/*", "*/", "#",
         '"', "'", 'f"{', "}\"", "for", "in", "if", "else", "elif", "and", "or", "not", "0", "-1",
         "2.5", "0.0", "1e-9", "deg", "mm", "in", "°", "self", "bb", "solid", "hole", "drawing",
         "assembly", "def", "param", "import", "units", "as", ";", "\n", "Circle", "Line", "Arc",
         "Rectangle", "Polygon", "Text", "Slot", "RegularPolygon", "range", "sqrt", "Fixed",
         "Above", "Tangent", "Angle", "Inside", "x", "**", "%", "\\", "->", ":", "\t", "é", "\x00",
         "tooth[0]", "[i for i in range(3)]", "construction=true", "1/0"]

FUZZ = settings(deadline=None, max_examples=150,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.filter_too_much])


def check_result(src: str, path: str):
    """compile_source answers without raising, and its diagnostics are well formed."""
    c = compile_source(src, path)
    n_lines = len(split_lines(src))          # CR LF, CR and LF each end a line
    for d in c.sink.items:
        assert d.code in CODES and d.code != "E0900", d.code
        assert d.severity in ("error", "warning", "note")
        assert d.message and "internal error" not in d.message
        # every diagnostic located, but the empty drawing's W0104 (nothing to point at)
        assert d.span is not None or d.code == "W0104", (d.code, d.message)
        if d.span is not None and d.span.file == path:
            s = d.span
            assert 1 <= s.line <= s.end_line <= n_lines + 1, (d.code, s)
            assert s.col >= 1 and (s.end_line > s.line or s.end_col >= s.col), (d.code, s)
        render_text(d, c.sink.sources)
    if c.ok:
        assert c.model is not None and c.solve is not None and c.solve.converged
    else:
        assert any(d.is_error for d in c.sink.items)
    return c


# ------------------------------------------------------------------ mutations of examples
@st.composite
def mutated_examples(draw):
    i = draw(st.integers(0, len(SOURCES) - 1))
    path, src = SOURCES[i]
    for _ in range(draw(st.integers(1, 4))):
        toks = [(m.start(), m.end()) for m in TOKEN.finditer(src)]
        a, b = toks[draw(st.integers(0, len(toks) - 1))]
        op = draw(st.sampled_from(["delete", "duplicate", "replace", "insert", "delchar",
                                   "swap"]))
        if op == "delete":
            src = src[:a] + src[b:]
        elif op == "duplicate":
            src = src[:b] + src[a:b] + src[b:]
        elif op == "replace":
            src = src[:a] + draw(st.sampled_from(VOCAB)) + src[b:]
        elif op == "insert":
            src = src[:a] + draw(st.sampled_from(VOCAB)) + " " + src[a:]
        elif op == "delchar":
            k = draw(st.integers(0, len(src) - 1))
            src = src[:k] + src[k + 1:]
        else:
            c, d = toks[draw(st.integers(0, len(toks) - 1))]
            if b <= c:
                src = src[:a] + src[c:d] + src[b:c] + src[a:b] + src[d:]
    return path, src


@FUZZ
@given(mutated_examples())
def test_mutated_examples_never_raise(case):
    path, src = case
    check_result(src, path)


@st.composite
def line_break_mutations(draw):
    """A mutated example whose line breaks are turned, at random, into CR or CR LF, and whose
    lines get a `#` comment ending at a lone CR with code after it (issue 83)."""
    path, src = draw(mutated_examples())
    lines = src.split("\n")
    for _ in range(draw(st.integers(1, 6))):
        k = draw(st.integers(0, len(lines) - 1))
        if draw(st.booleans()):        # a comment, a CR, then the next line's code
            lines[k] = lines[k] + "  # " + draw(st.sampled_from(["note", "x = (", "{", "'"]))
    breaks = [draw(st.sampled_from(["\n", "\r", "\r\n"])) for _ in lines[1:]]
    out = lines[0]
    for br, line in zip(breaks, lines[1:]):
        out += br + line
    return path, out


@settings(FUZZ, max_examples=40)
@given(line_break_mutations())
def test_mutated_examples_with_cr_line_breaks_compile_as_their_lf_version(case):
    """Never raises, and the diagnostics (code, line, column) are the LF version's: a lone CR
    in a comment or between statements is a line break, as every editor shows it."""
    path, src = case
    got = check_result(src, path)
    ref = compile_source(LINE_BREAK.sub("\n", src), path)
    where = [(d.code, d.span and (d.span.line, d.span.col)) for d in got.sink.items]
    assert where == [(d.code, d.span and (d.span.line, d.span.col)) for d in ref.sink.items]


# ------------------------------------------------------------------ random text
ALPHABET = st.sampled_from(list("abcxyz_019.,;:=+-*/%<>!()[]{}#\"'\\ \t\n°é") +
                           ["solid ", "hole ", "for ", "if ", "else ", "def ", "param ",
                            "import ", "units ", " mm", " deg", "Circle", "//", "/*", "*/",
                            "->", "**", "f\""])


@FUZZ
@given(st.lists(ALPHABET, max_size=80).map("".join))
def test_random_text_never_raises(src):
    check_result(src, str(ROOT / "examples" / "fuzz.aidl"))


@FUZZ
@given(st.text(max_size=200))
def test_random_unicode_never_raises(src):
    check_result(src, str(ROOT / "examples" / "fuzz.aidl"))


# ------------------------------------------------------------------ generated programs
NAMES = ["a", "b", "c", "n", "w", "pts", "xs", "g", "h", "k"]
PRELUDE = ("a = 1; b = 2 mm; c = 30 deg; n = 3; w = 5; pts = [(0, 0), (10, 0), (0, 10)]; "
           "xs = [1, 2, 3]; g = Circle((0, 0), 5); h = Line((0, 0), (10, 1)); "
           "k = Rectangle(center=(20, 0), width=8, height=4)")


# The strategy builders are cached: `programs` calls them on every draw, and a fresh strategy
# tree is re-derived by hypothesis each time (49 s of the module's 63 s for the same 150
# examples; 4.5 s with one tree).
@functools.cache
def exprs(depth=3):
    leaf = st.one_of(
        st.sampled_from(["0", "1", "2", "3.5", "10 mm", "2 in", "30 deg", "45°", "1.2 rad",
                         "pi", "true", "false", '"txt"', "-1", "1e3", "0.001"]),
        st.sampled_from(NAMES),
    )
    if depth == 0:
        return leaf
    sub = exprs(depth - 1)
    return st.one_of(
        leaf,
        st.tuples(sub, st.sampled_from(["+", "-", "*", "/", "//", "%", "**", "==", "<",
                                         ">=", "and", "or"]), sub).map(
            lambda t: f"({t[0]} {t[1]} {t[2]})"),
        st.tuples(sub, sub).map(lambda t: f"({t[0]}, {t[1]})"),
        st.lists(sub, max_size=3).map(lambda xs: "[" + ", ".join(xs) + "]"),
        st.tuples(sub, st.sampled_from(NAMES), st.integers(0, 4), st.booleans(), sub).map(
            lambda t: f"[{t[0]} for {t[1]} in range({t[2]})" + (f" if {t[4]}]" if t[3] else "]")),
        st.tuples(sub, sub, sub).map(lambda t: f"({t[0]} if {t[1]} else {t[2]})"),
        st.tuples(st.sampled_from(["sqrt", "sin", "cos", "abs", "min", "max", "len", "round",
                                   "floor", "str", "norm", "range", "atan2"]),
                  st.lists(sub, min_size=1, max_size=2)).map(
            lambda t: f"{t[0]}({', '.join(t[1])})"),
        st.tuples(sub, st.integers(-1, 3)).map(lambda t: f"{t[0]}[{t[1]}]"),
        st.tuples(sub, st.sampled_from(["x", "y", "center", "bb", "width", "start", "top_left",
                                        "radius", "bb.left"])).map(lambda t: f"{t[0]}.{t[1]}"),
        leaf.map(lambda e: f'f"v={{{e}}}"' if '"' not in e else e),
        sub.map(lambda e: f"-{e}"),
        sub.map(lambda e: f"(not {e})"),
    )


@functools.cache
def geometry_calls():
    e = exprs(2)
    return st.one_of(
        st.tuples(e, e).map(lambda t: f"Circle(center={t[0]}, radius={t[1]})"),
        st.tuples(e, e, e).map(lambda t: f"Rectangle(center={t[0]}, width={t[1]}, height={t[2]})"),
        st.tuples(e, e).map(lambda t: f"Line({t[0]}, {t[1]})"),
        st.tuples(e, e).map(lambda t: f"Point({t[0]}, {t[1]})"),
        st.tuples(e, e, e).map(lambda t: f"Arc(center={t[0]}, start={t[1]}, end={t[2]})"),
        e.map(lambda x: f"Polygon({x})"),
        st.tuples(e, e, e).map(lambda t: f"RegularPolygon({t[0]}, {t[1]}, {t[2]})"),
        st.tuples(e, e).map(lambda t: f"Text({t[0]}, {t[1]})"),
    )


@functools.cache
def statements(depth=2):
    e = exprs(2)
    simple = st.one_of(
        st.tuples(st.sampled_from(NAMES), e).map(lambda t: f"{t[0]} = {t[1]}"),
        st.tuples(st.sampled_from(NAMES), geometry_calls()).map(lambda t: f"{t[0]} = {t[1]}"),
        st.tuples(st.sampled_from(["Fixed", "Horizontal", "Vertical", "Coincident", "Distance",
                                   "Tangent", "Angle", "Above", "LeftOf", "Inside",
                                   "CenterInside", "Equal", "Radius"]),
                  st.lists(e, min_size=1, max_size=3)).map(
            lambda t: f"{t[0]}({', '.join(t[1])})"),
        st.tuples(e, st.sampled_from(["==", "<=", ">="]), e).map(lambda t: f"{t[0]} {t[1]} {t[2]}"),
        e,
    )
    if depth == 0:
        return simple
    inner = st.lists(statements(depth - 1), max_size=3).map(lambda ss: "; ".join(ss))
    return st.one_of(
        simple,
        st.tuples(st.sampled_from(["solid", "hole", "drawing", "assembly"]),
                  st.sampled_from(["p", "q", "r"]), inner).map(
            lambda t: f"{t[0]} {t[1]} {{ {t[2]} }}"),
        st.tuples(st.sampled_from(NAMES), e, inner).map(lambda t: f"for {t[0]} in {t[1]} {{ {t[2]} }}"),
        st.tuples(e, inner, inner).map(lambda t: f"if {t[0]} {{ {t[1]} }} else {{ {t[2]} }}"),
    )


@st.composite
def programs(draw):
    lines = []
    if draw(st.booleans()):
        lines.append("units " + draw(st.sampled_from(["mm", "inch", "cm", "parsec"])))
    for name in draw(st.lists(st.sampled_from(["w", "n"]), max_size=2, unique=True)):
        lines.append(f"param {name} = " + draw(st.sampled_from(["3", "2.5 mm", "1 in", "4", "-1",
                                                               "0", "30 deg", "true"])))
    has_def = draw(st.booleans())
    if has_def:
        body = "\n    ".join(draw(st.lists(statements(1), max_size=3)))
        lines.append(f"def t(a = 1, b = 2 mm) -> solid {{\n    {body}\n}}")
    body = [PRELUDE] + draw(st.lists(statements(2), min_size=1, max_size=6))
    if has_def and draw(st.booleans()):
        body.append("x = t(a=" + draw(exprs(1)) + ")")
    lines.append("solid top {\n    " + "\n    ".join(body) + "\n}")
    return "\n".join(lines) + "\n"


@FUZZ
@given(programs())
def test_generated_programs_never_raise(src):
    check_result(src, str(ROOT / "examples" / "generated.aidl"))


@settings(deadline=None, max_examples=60,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(programs())
def test_generated_programs_that_compile_also_render(src):
    c = check_result(src, str(ROOT / "examples" / "generated.aidl"))
    if c.ok:
        to_svg(render_model(c.model))


# ------------------------------------------------------------------ regressions
# Inputs found by fuzzing or by hand that once raised: each must now give diagnostics or a model.
REGRESSIONS = [
    pytest.param("solid s { xs = [Circle((i, 0), 1) for i in range(3)] }", id="listcomp-no-filter"),
    pytest.param("x = 2 ** 3\nsolid s { c = Circle((0, 0), x) }", id="power"),
    pytest.param("x = " + " + ".join(["1"] * 3000), id="long-sum"),
    pytest.param("x = " + "-" * 3000 + "1", id="many-signs"),
    pytest.param("x = " + "not " * 3000 + "true", id="many-nots"),
    pytest.param("x = [" * 60 + "]" * 60, id="nested-lists"),
    pytest.param('solid s { drawing d { t = Text(f"{1+}", (0, 0)) } }', id="bad-fstring"),
    pytest.param('solid s { drawing d { t = Text(f"{x", (0, 0)) } }', id="open-fstring"),
    pytest.param("solid s { c = Circle((0, 0), 1e400) }", id="infinite-radius"),
    pytest.param("solid s { c = Circle((1e400 - 1e400, 0), 3) }", id="nan-center"),
    pytest.param("solid s { l = Line((0, 0), (0, 0)); Length(l, 5) }", id="zero-length-line"),
    pytest.param("solid s { p = RegularPolygon((0, 0), 5, 1e9) }", id="huge-sides"),
    pytest.param("solid s { a = Arc(center=(0, 0), start=(0, 0), end=(0, 0)) }", id="point-arc"),
    pytest.param("solid s { p = Polygon([(0, 0), (0, 0), (0, 0)]) }", id="point-polygon"),
    pytest.param("solid s { r = Rectangle(corner=(0, 0), opposite=(0, 0)) }", id="point-rect"),
    pytest.param("solid s { c = Circle((0, 0), 1); Tangent(c, c) }", id="self-tangent"),
    pytest.param("solid s { a = Line((0, 0), (1, 0)); Angle(a, a, 30 deg) }", id="self-angle"),
    pytest.param("solid s { Fixed(self) ; Above(self, self) }", id="empty-self"),
    pytest.param("solid s { }", id="empty-solid"),
    pytest.param("", id="empty-file"),
    pytest.param("\x00\x00", id="nul"),
    pytest.param("solid s { x = self.bb.width; c = Circle((0, 0), 1) }", id="empty-bb-const"),
    pytest.param("param p = p\nsolid s { }", id="param-self-reference"),
    pytest.param("def f() -> solid { g = f() }\nsolid s { a = f() }", id="recursive-template"),
    pytest.param('import "std/shapes.aidl" as s\nsolid t { x = s }', id="namespace-value"),
    pytest.param("solid s { for i in range(3) { solid t { } }; Above(t[0], t[1]) }",
                 id="empty-structures-above"),
    pytest.param("solid s { c = Circle(center=polar((0, 0), (0, 0), 30 deg), radius=3) }",
                 id="polar-point-radius"),          # found by the fuzz of issue 70
]


@pytest.mark.parametrize("src", REGRESSIONS)
def test_regression_inputs_do_not_raise(src):
    check_result(src + "\n", str(ROOT / "examples" / "regression.aidl"))


RENDER_REGRESSIONS = [
    pytest.param("solid s { c = Circle((0, 0), 1e300) }", id="huge-radius"),
    pytest.param("solid s { c = Circle((0, 0), 1e400) }", id="infinite-radius"),
    pytest.param("solid s { c = Circle((0, 0), 1e12) }", id="radius-1e12"),
    pytest.param("solid s { r = Rectangle(center=(0, 0), width=1e14 * 1e14, height=1) }",
                 id="computed-huge-width"),
    pytest.param("solid s { c = Circle((0, 0), 1e-12) }", id="tiny-radius"),
    pytest.param("solid s { r = Rectangle(center=(0, 0), width=0, height=0) }", id="zero-rect"),
    pytest.param("solid s { a = Line((0, 0), (0, 0)) }", id="zero-line"),
    pytest.param("drawing d { t = Text(\"\", (0, 0)) }", id="empty-text"),
    pytest.param("drawing d { t = Text(\"héllo ☃ \\t\", (0, 0)) }", id="unicode-text"),
]


@pytest.mark.parametrize("src", RENDER_REGRESSIONS)
def test_render_regressions(src):
    c = check_result(src + "\n", str(ROOT / "examples" / "regression.aidl"))
    if c.ok:
        svg = to_svg(render_model(c.model))
        assert "viewBox" in svg


# ------------------------------------------------------------------ issue 70: no internal errors
# Mutations of programs that use the newer constructs (`cut`, `min_wall`, `CutInto`, `polar`,
# `Mirrored` of lists), run through the command line's own `check` and `render` in process,
# machine profiles and malformed DXF entities: each answers with located diagnostics (or a
# one-line usage error), never a traceback, "internal error" or an unlocated diagnostic.
SEEDS = [
    """min_wall 0.3 mm
solid plate {
    r = Rectangle(center=(0, 0), width=60, height=40)
    cut slits {
        a = Line((-20, 0), (20, 0))
        b = Line((-20, 5), (20, 5))
    }
    hole bolt {
        c = Circle(center=polar((0, 0), 12, 30 deg), radius=3)
    }
    axis = Line((0, -30), (0, 30), construction=true)
    Fixed(axis)
    legs = [Circle((5 + 6 * i, 12), 1) for i in range(3)]
    right = Mirrored(legs, axis)
}
""",
    """assembly kit {
    solid lid {
        min_wall 0.5 mm
        r = Rectangle(center=(0, 0), width=50, height=30)
    }
    solid base {
        r = Rectangle(center=(70, 0), width=50, height=30)
        cut hinge {
            for i in range(4) {
                l = Line((52 + 4 * i, -10), (52 + 4 * i, 10))
            }
        }
    }
    hole vent {
        c = Circle(center=(0, 0), radius=5)
    }
    CutInto(vent, lid)
    m = Mirrored([lid], Line((35, -20), (35, 20), construction=true))
}
""",
]
# what a mutation puts in place of a number, in place of a name, and as a line of its own
NEW_VALUES = ["0", "-1", "1e-300", "1e300", "0.001", "360", "0 mm", "30 deg", "(0, 0)", "[]",
              "legs", "axis", "1/0", "sqrt(-1)", "10 ** 400", "polar((0, 0), 0, 0 deg)"]
NEW_NAMES = ["cut", "min_wall", "CutInto", "polar", "Mirrored", "legs", "axis", "lid", "base",
             "vent", "slits", "hinge", "right", "Line", "Circle", "self", "Drawing2D"]
NEW_LINES = ["min_wall 1e-300 mm", "min_wall 0", "min_wall 1e300 mm", "kerf 0.1 mm",
             "cut c { l = Line((0, 0), (10, 0)) }", "cut e { }", "hole h2 { }",
             "z = Mirrored(legs, Line((0, 0), (0, 0)))", "z = Mirrored([], axis)",
             "z = Mirrored([legs, legs], axis)", "CutInto(vent, lid)", "CutInto(lid, vent)",
             "q = polar((0, 0), 0, 0 deg)", "q = polar(self.bb.center, 1e300, 1 deg)",
             'd = Drawing2D("bad.dxf")', "hole h3 { c = Circle((0, 0), 100) }",
             "Mirrored(axis, axis)", "w = Mirrored(right, axis)", "Fixed(axis)",
             "Coincident(axis.start, axis.end)", "cut k { Line((0, 0), (0, 0)) }"]


@st.composite
def mutated_seeds(draw):
    """A seed program with one to three mutations that keep most of it well formed: a number
    or a name replaced, a line inserted or deleted."""
    src = draw(st.sampled_from(SEEDS))
    for _ in range(draw(st.integers(1, 3))):
        op = draw(st.sampled_from(["number", "name", "line", "line", "delete"]))
        lines = src.split("\n")
        if op in ("line", "delete"):
            k = draw(st.integers(1, max(1, len(lines) - 2)))
            if op == "delete":
                del lines[k]
            else:
                lines.insert(k, "    " + draw(st.sampled_from(NEW_LINES)))
            src = "\n".join(lines)
            continue
        pat = r"\b\d+(\.\d+)?\b" if op == "number" else r"\b[A-Za-z_]\w*\b"
        toks = [(m.start(), m.end()) for m in re.finditer(pat, src)]
        a, b = toks[draw(st.integers(0, len(toks) - 1))]
        src = src[:a] + draw(st.sampled_from(NEW_VALUES if op == "number" else NEW_NAMES)) \
            + src[b:]
    return src


_WORK = None


@pytest.fixture(scope="module", autouse=True)
def _remove_workdir():
    """The folder of `_workdir` is removed when the module's tests end (it was left in /tmp)."""
    global _WORK
    yield
    if _WORK is not None:
        import shutil
        shutil.rmtree(_WORK, ignore_errors=True)
        _WORK = None


def _workdir():
    """One folder for the in-process command line's files (hypothesis runs many examples
    per test; a function-scoped tmp_path would be shared by them anyway)."""
    global _WORK
    if _WORK is None:
        import tempfile
        _WORK = tempfile.mkdtemp(prefix="aidl-fuzz-")
    return _WORK


LOCATED = re.compile(r"^\S+:\d+:\d+: (error|warning|note)\[[A-Z]\d{4}\]: ")
UNLOCATED = re.compile(r"(error|warning|note)\[[A-Z]\d{4}\]")


def cli_no_internal(*argv):
    """``aidl ARGV`` in this process: its exit status and what it printed to stderr, which
    holds no traceback, no internal error and no diagnostic without its place."""
    import contextlib
    import io
    from aidl_lang.cli.main import main
    err, out = io.StringIO(), io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
        try:
            rc = main(list(argv))
        except SystemExit as e:         # argparse's usage error (--min-wall 1e-300): exit 2
            rc = e.code
    said = err.getvalue()
    if rc == 2:
        assert said.splitlines()[-1].startswith("aidl: error: argument"), said
        return rc, said
    assert rc != 3 and "internal error" not in said and "Traceback" not in said, said
    for line in said.splitlines():
        if UNLOCATED.search(line) and not line.startswith(" "):
            assert LOCATED.match(line), (line, said)
    return rc, said


def _drawing_file(folder):
    """bad.dxf beside the program: a plate, a spline of 15 degrees and an unknown entity."""
    import os
    p = os.path.join(folder, "bad.dxf")
    if not os.path.exists(p):
        write_malformed_dxf(p, [("spline", 15, 16, 32, 0, ()), ("unknown",)])
    return p


FUZZ_CLI = settings(deadline=None, max_examples=25,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                           HealthCheck.filter_too_much])


@FUZZ_CLI
@given(mutated_seeds(), st.sampled_from(["svg", "dxf", "gcode"]),
       st.sampled_from([None, "0", "1e-300", "0.5"]))
@example(SEEDS[0], "svg", "1e-300")                   # ValueError in the wall check
@example(SEEDS[0].replace("min_wall 0.3 mm", "min_wall 1e-300 mm"), "dxf", None)
@example(SEEDS[0].replace("(0, -30), (0, 30)", "(0, 0), (0, 0)"), "dxf", None)  # LinAlgError
@example(SEEDS[1].replace("[lid]", "[lid, base]"), "gcode", "0")
@example(SEEDS[1] + 'solid s2 {\n    d = Drawing2D("bad.dxf")\n}\n', "svg", None)
def test_new_constructs_through_check_and_render_never_fail_internally(src, fmt, wall):
    import os
    folder = _workdir()
    _drawing_file(folder)
    path = os.path.join(folder, "p.aidl")
    with open(path, "w") as f:
        f.write(src)
    extra = ["--min-wall", wall] if wall is not None else []
    rc, _ = cli_no_internal("check", path, *extra)
    out = os.path.join(folder, "p." + fmt)
    if os.path.exists(out):
        os.remove(out)
    rc2, said = cli_no_internal("render", path, "-o", out, *extra)
    if rc2 != 0:
        assert not os.path.exists(out), said       # refused: nothing written


# machine profiles: any table a TOML file or the API may give is a Machine or one MachineError
def _profile_values():
    return st.one_of(st.integers(-10 ** 400, 10 ** 400), st.integers(-3, 200),
                     st.floats(allow_nan=True, allow_infinity=True), st.booleans(),
                     st.text(max_size=5), st.lists(st.integers(0, 3), max_size=2),
                     st.sampled_from([0, 1, 0.001, 1e-300, 5e-324, 1e308, -0.0]))


@functools.cache
def _profile_keys():
    from aidl_lang.output.fabrication.machine import OP_RANGES, OPERATIONS, RANGES
    return sorted(RANGES) + ["kind", "units", "laser_mode", "speed", "cut_outer"], \
        sorted(OP_RANGES), sorted(OPERATIONS)


@st.composite
def profiles(draw):
    keys, op_keys, ops = _profile_keys()
    d = {}
    for k in draw(st.lists(st.sampled_from(keys), max_size=4, unique=True)):
        d[k] = draw(st.sampled_from(["laser", "router", "plotter", "mm", "inch", "M3", "x"])
                    if k in ("kind", "units", "laser_mode") else _profile_values())
    for op in draw(st.lists(st.sampled_from(ops), max_size=2, unique=True)):
        d[op] = {k: draw(_profile_values())
                 for k in draw(st.lists(st.sampled_from(op_keys + ["bogus"]), max_size=3,
                                        unique=True))}
    return d


@settings(deadline=None, max_examples=150)
@given(profiles())
def test_machine_profiles_are_a_machine_or_one_profile_error(d):
    from aidl_lang.output.fabrication.machine import Machine, MachineError, from_dict
    try:
        m = from_dict(d, "fuzz.toml")
    except MachineError as e:
        assert "\n" not in str(e) and "fuzz.toml" in str(e) and len(str(e)) < 600
    else:
        assert isinstance(m, Machine)


@settings(deadline=None, max_examples=60)
@given(st.lists(st.sampled_from(["tabs = ", "kerf = ", "[cut_outer]\n", "passes = ", "9" * 400,
                                 "9" * 5000, "1e999", "nan", "-", "\n", '"x"', "0", "[", "]",
                                 "units = \"inch\"\n", "kind = \"router\"\n", "="]),
                max_size=12).map("".join))
def test_machine_profile_files_are_a_machine_or_one_profile_error(text):
    import os
    from aidl_lang.output.fabrication.machine import Machine, MachineError, load
    p = os.path.join(_workdir(), "m.toml")
    with open(p, "w") as f:
        f.write(text)
    try:
        assert isinstance(load(p), Machine)
    except MachineError as e:
        assert "m.toml" in str(e)


# malformed DXF entities: read_drawing gives a drawing (what it left out in notes) or a
# DrawingError, for `aidl import` and Drawing2D alike
def write_malformed_dxf(path, entities):
    """A DXF at ``path``: a 100 x 50 plate and a circle, then ``entities``: ``("spline",
    degree, control points, knots, weights, fit points)`` with raw attributes, ``("unknown",)``
    an entity type ezdxf does not know, ``("line", x)`` a line to ``(x, 0)``."""
    import ezdxf
    doc = ezdxf.new("R2010")
    doc.units = 4
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (100, 0), (100, 50), (0, 50)], close=True)
    msp.add_circle((20, 20), 3)
    unknown = 0
    for e in entities:
        if e[0] == "spline":
            _, deg, n, k, w, fit = e
            s = msp.add_spline(fit_points=list(fit) or None)
            s.dxf.__dict__["degree"] = deg
            if n:
                s.control_points = [(40 + 3 * i, 10 + 7 * (i % 2)) for i in range(n)]
            if k:
                s.knots = [min(i, max(k // 2, 1)) / 2 for i in range(k)]
            if w:
                s.weights = [1.0 + (i % 2) * (w - 1) for i in range(n or 1)] if w > 0 else \
                    [w] * max(n, 1)
        elif e[0] == "line":
            msp.add_line((0, 0), (e[1], 0))
        elif e[0] == "hatch":              # an edge path of one ellipse of axis ratio e[1]
            edge = msp.add_hatch().paths.add_edge_path()
            edge.add_ellipse((50, 25), (10, 0), 0.5)
            edge.edges[0].ratio = e[1]
        elif e[0] == "lwpolyline":         # vertices (x, y, start width, end width, bulge)
            msp.add_lwpolyline(e[1], format="xyseb", close=e[2])
        elif e[0] == "arc":
            a = msp.add_arc((50, 25), e[1], 0, 90)
            a.dxf.__dict__["end_angle"] = e[2]
        else:
            unknown += 1
    doc.saveas(path)
    if unknown:
        with open(path) as f:
            text = f.read()
        end = text.index("  0\nENDSEC", text.index("ENTITIES"))
        raw = "".join(f"  0\nACME_THING\n  5\nF{k:03X}\n330\n1F\n100\nAcDbEntity\n  8\n0\n"
                      for k in range(unknown))
        with open(path, "w") as f:
            f.write(text[:end] + raw + text[end:])


@st.composite
def malformed_entities(draw):
    out = []
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(["spline", "spline", "spline", "unknown", "line", "hatch",
                                     "lwpolyline", "arc"]))
        odd = st.sampled_from([0.0, -1.0, 1.0, 0.5, 1e300, float("inf"), float("nan")])
        if kind == "spline":
            fit = draw(st.lists(st.sampled_from([(40, 10), (50, 30), (60, 10), (50, 30)]),
                                max_size=4))
            out.append(("spline", draw(st.sampled_from([-1, 0, 1, 2, 3, 4, 15, 20])),
                        draw(st.integers(0, 7)) if not fit else 0, draw(st.integers(0, 14)),
                        draw(st.sampled_from([0, 1, 2.5, -1])), tuple(fit)))
        elif kind == "line":
            out.append(("line", draw(st.sampled_from([10.0, 0.0, 1e300, float("inf")]))))
        elif kind == "hatch":
            out.append(("hatch", draw(odd)))
        elif kind == "arc":
            out.append(("arc", draw(odd), draw(odd)))
        elif kind == "lwpolyline":
            pts = draw(st.lists(st.tuples(st.sampled_from([0.0, 10.0]), st.sampled_from(
                [0.0, 10.0]), st.just(0.0), st.just(0.0), odd), max_size=4))
            out.append(("lwpolyline", pts, draw(st.booleans())))
        else:
            out.append(("unknown",))
    return out


@settings(deadline=None, max_examples=40,
          suppress_health_check=[HealthCheck.too_slow])
@given(malformed_entities())
def test_malformed_dxf_entities_are_notes_or_a_drawing_error(entities):
    import os
    from aidl_lang.drawing import DrawingError, read_drawing
    folder = _workdir()
    p = os.path.join(folder, "m.dxf")
    write_malformed_dxf(p, entities)
    with open(p, "rb") as f:
        data = f.read()
    try:
        d = read_drawing(data, "m.dxf")
    except DrawingError as e:
        assert e.code in CODES and e.message
    else:
        assert any(c.radius == 3.0 for c in d.circles)          # the rest is read
    src = 'solid plate {\n    d = Drawing2D("m.dxf")\n}\n'
    prog = os.path.join(folder, "d.aidl")
    with open(prog, "w") as f:
        f.write(src)
    c = check_result(src, prog)
    assert all(d.span is not None for d in c.sink.items), [(d.code, d.message)
                                                           for d in c.sink.items]


# malformed SVG elements: a drawing (what was left out in notes) or a DrawingError
SVG_ELEMENTS = ['<path d="{d}"/>', '<circle cx="{a}" cy="{b}" r="{c}"/>',
                '<ellipse cx="{a}" cy="{b}" rx="{c}" ry="{a}"/>',
                '<rect x="{a}" y="{b}" width="{c}" height="{a}" rx="{b}"/>',
                '<polygon points="{d}"/>', '<polyline points="{d}"/>',
                '<line x1="{a}" y1="{b}" x2="{c}" y2="{a}"/>',
                '<g transform="{t}"><path d="{d}"/></g>',
                '<g transform="{t}"><circle cx="{a}" cy="{b}" r="{c}"/></g>',
                '<g transform="{t}"><ellipse cx="{a}" cy="{b}" rx="{c}" ry="{a}"/></g>',
                '<g transform="{t}"><rect x="{a}" y="{b}" width="{c}" height="{a}" rx="{c}"/></g>',
                '<text x="{a}" y="{b}" font-size="{c}">hi</text>']
SVG_WORDS = ["M", "m", "L", "l", "H", "v", "C", "s", "Q", "T", "A", "a", "Z", "z", "0", "1", "-1",
             "10", "1e400", "nan", "0.5", ",", " ", "1e-300", "360", ".5.5", "1e", "+"]
SVG_NUMBERS = ["0", "1", "-1", "10", "1e400", "nan", "inf", "", "abc", "1e-300", "50%"]
SVG_TRANSFORMS = ["scale(0)", "scale(1e400)", "rotate(nan)", "matrix(0 0 0 0 0 0)",
                  "skewX(90)", "translate(1e300)", "scale(-1 1)", "matrix(1,2)",
                  "scale(-1,-1)", "scale(-2 -2)", "matrix(-1,0,0,-2,0,0)", "scale(-1e-300)",
                  "scale(-1 -1) skewX(30)", "scale(-1e300 -1)"]


@st.composite
def malformed_svgs(draw):
    body = []
    for _ in range(draw(st.integers(1, 3))):
        body.append(draw(st.sampled_from(SVG_ELEMENTS)).format(
            d=" ".join(draw(st.lists(st.sampled_from(SVG_WORDS), max_size=12))),
            a=draw(st.sampled_from(SVG_NUMBERS)), b=draw(st.sampled_from(SVG_NUMBERS)),
            c=draw(st.sampled_from(SVG_NUMBERS)), t=draw(st.sampled_from(SVG_TRANSFORMS))))
    w = draw(st.sampled_from(["100mm", "100", "0", "abc", "100in"]))
    vb = draw(st.sampled_from(["0 0 100 100", "", "0 0 0 0", "nan 0 1 1"]))
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{w}" viewBox="{vb}">'
            f'<rect x="0" y="0" width="50" height="50"/>{"".join(body)}</svg>')


@settings(deadline=None, max_examples=150,
          suppress_health_check=[HealthCheck.too_slow])
@given(malformed_svgs())
@example('<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 '
         '100"><path d="z c z -0 A h c t"/></svg>')
@example('<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="">'
         '<text x="1e400" y="10" font-size="1e-300">hi</text></svg>')
@example('<svg xmlns="http://www.w3.org/2000/svg" width="100in" height="100in" viewBox="">'
         '<g transform="scale(-1 1)"><path d="+ 1 m 1e 0.5"/></g><rect x="50%" y="1e-300" '
         'width="1e-300" height="50%" rx="1e-300"/></svg>')
def test_malformed_svg_elements_are_notes_or_a_drawing_error(svg):
    """Found by this fuzz: path data before its first moveto (TypeError), a text at an
    infinite place (an internal exception), a length in % with no viewBox (ValueError)."""
    from aidl_lang.drawing import DrawingError, read_drawing
    try:
        read_drawing(svg.encode(), "f.svg")
    except DrawingError as e:
        assert e.code in CODES and e.message


# machine jobs: seeds with parts laid close (lead-ins must keep clear of their neighbours)
# and router slits near edges, holes and each other (the bit's bridges), mutated; each is
# rendered as G-code with a lead-in profile, a router profile with tabs or the plotter:
# never an internal error, and every lead-in of the file keeps the promised clearance
from test_machine_safety import CLEAR, kit, lead_in_clearances  # noqa: E402

MACHINE_SEEDS = [
    kit("body = Rectangle(center=(0, 0), width=20, height=20)\n"
        "hole h { c = Circle(center=(2, 2), radius=5) }",
        "body = Rectangle(center=(20.3, 0), width=20, height=20)",
        "body = Circle(center=(40.6, 0), radius=10)"),
    """solid plate {
    body = Rectangle(center=(30, 20), width=60, height=40)
    hole h { c = Circle(center=(45, 20), radius=5) }
    cut slit {
        l = Line((30, 1), (30, 39))
    }
    cut near {
        for i in range(3) {
            l = Line((8 + 2 * i, 2), (8 + 2 * i, 18))
        }
    }
    Fixed(body)
}
""",
]
MACHINE_PROFILES = ["lead_in = 5\n", "lead_in = 30\n", 'kind = "router"\nlead_in = 3\ntabs = 2\n',
                    'kind = "router"\ntool_diameter = 6\n', 'kind = "plotter"\n']


@st.composite
def mutated_machine_seeds(draw):
    """A machine seed with one or two of its numbers replaced (sizes, gaps, slit ends)."""
    src = draw(st.sampled_from(MACHINE_SEEDS))
    for _ in range(draw(st.integers(1, 2))):
        toks = [(m.start(), m.end()) for m in re.finditer(r"\b\d+(\.\d+)?\b", src)]
        a, b = toks[draw(st.integers(0, len(toks) - 1))]
        src = src[:a] + draw(st.sampled_from(["0", "0.5", "1", "1.6", "2", "3", "39.5", "60",
                                              "1e-300", "1e300", "-1"])) + src[b:]
    return src


@settings(deadline=None, max_examples=20,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(mutated_machine_seeds(), st.sampled_from(MACHINE_PROFILES))
@example(MACHINE_SEEDS[0], MACHINE_PROFILES[1])
@example(MACHINE_SEEDS[1], MACHINE_PROFILES[2])
def test_machine_jobs_of_mutated_programs_keep_their_promises(src, profile):
    import os
    folder = _workdir()
    path = os.path.join(folder, "m.aidl")
    with open(path, "w") as f:
        f.write(src)
    prof = os.path.join(folder, "fuzz-machine.toml")
    with open(prof, "w") as f:
        f.write(profile)
    out = os.path.join(folder, "m.gcode")
    if os.path.exists(out):
        os.remove(out)
    rc, said = cli_no_internal("render", path, "-o", out, "--machine", prof)
    if rc != 0:
        assert not os.path.exists(out), said
        return
    kind = "router" if "router" in profile else "plotter" if "plotter" in profile else "laser"
    with open(out) as f:
        text = f.read()
    if kind != "plotter":
        for length, d_other, d_own in lead_in_clearances(text, kind):
            assert d_other >= CLEAR - 1e-6 and d_own >= CLEAR - 1e-6, (length, d_other, said)


# well-formed shapes under mirrors and negative scales: every one drawn (issue 83: a circle
# or ellipse under scale(-1,-1) was dropped without a word)
NEGATIVE_SCALES = ["scale(-1,-1)", "scale(-2 -2)", "matrix(-1,0,0,-2,0,0)", "scale(-1 1)",
                   "scale(1,-0.5)", "scale(-0.5,-3)", "matrix(-1,0.5,0,-2,10,5)",
                   "rotate(30) scale(-1,-2)", "scale(-1,-1) skewY(20)"]
SHAPES = ['<circle cx="{x}" cy="{y}" r="4"/>', '<ellipse cx="{x}" cy="{y}" rx="5" ry="2"/>',
          '<rect x="{x}" y="{y}" width="6" height="3"/>',
          '<rect x="{x}" y="{y}" width="6" height="3" rx="1" ry="0.5"/>',
          '<polygon points="{x},{y} {x1},{y} {x},{y1}"/>',
          '<polyline points="{x},{y} {x1},{y} {x1},{y1}"/>',
          '<line x1="{x}" y1="{y}" x2="{x1}" y2="{y1}"/>',
          '<path d="M {x} {y} C {x1} {y} {x1} {y1} {x} {y1} A 3 2 0 0 1 {x} {y} Z"/>',
          '<path d="M {x} {y} Q {x1} {y} {x1} {y1}"/>']


@settings(deadline=None, max_examples=60,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.tuples(st.sampled_from(SHAPES), st.sampled_from(NEGATIVE_SCALES),
                          st.booleans()), min_size=1, max_size=4))
def test_shapes_under_negative_scales_are_each_drawn(shapes):
    """Each shape (every element type), under a group's or its own mirror or negative scale,
    is drawn: one closed loop, circle, ellipse or open path each (they lie 40 units apart),
    no note; none left out."""
    from aidl_lang.drawing import read_drawing
    body = []
    for i, (shape, t, own) in enumerate(shapes):
        x, y = 40.0 * i + 5, 7.0
        el = shape.format(x=x, y=y, x1=x + 6, y1=y + 5)
        body.append(el.replace("/>", f' transform="{t}"/>') if own else
                    f'<g transform="{t}">{el}</g>')
    d = read_drawing(('<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="200mm" '
                      'viewBox="0 0 200 200">' + "".join(body) + "</svg>").encode(), "n.svg")
    assert not d.notes, [n.message for n in d.notes]
    assert len(d.outlines) + len(d.circles) + len(d.ellipses) + len(d.paths) == len(shapes)
