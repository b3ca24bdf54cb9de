"""Issue 73, "every hint's fix is safe": for each warning that proposes code (a fix, or a
"write `STMT` in `PATH`" hint), the code applied to the program that raised it removes that
warning AND leaves the design as it was: every part's area and outline (their symmetric
difference), the engraved lines and the hole parts, compared before and after.  The
programs: the issue's cases (a triangular opening beside a brace, W0515; a pattern of
spokes over a rim's opening, W0501; a scalloped bite of three circles, W0512; a screw hole
on a window's edge, W0508), every example, the test programs and the model runs in data/.
Each program is compiled once (module cache); only the fixed texts are compiled again.

A fix that corrects rather than accepts (W0109: `CutInto` makes the stray hole cut the part
it lies over) may change the part it names and the stray hole, nothing else."""
import re

import pytest

from conftest import EXAMPLES, ROOT

TRIANGLE = """solid bracket {
    base = Rectangle(center=(0, 0), width=60, height=6)
    post = Rectangle(center=(-27, 27), width=6, height=60)
    brace = Polygon([(30, 0), (30, 6), (-24, 60), (-30, 60), (-30, 54)])
}
"""

ROUND = """solid ring {
    left = Rectangle(center=(-15, 0), width=14, height=44)
    right = Rectangle(center=(15, 0), width=14, height=44)
    top = Rectangle(center=(0, 18), width=44, height=10)
    bottom = Rectangle(center=(0, -18), width=44, height=10)
    disc = Circle(center=(0, 0), radius=9)
}
"""

SPOKES = """solid wheel {
    solid rim {
        outer = Circle(center=(0, 0), radius=40)
        hole opening { c = Circle(center=(0, 0), radius=20) }
    }
    spoke = Rectangle(center=(0, 25), width=4, height=30)
    spokes = CircularPattern(spoke, 8, (0, 0))
}
"""

SCALLOP = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole bite {
        a = Circle(center=(-6, 20), radius=5)
        b = Circle(center=(0, 20), radius=5)
        c = Circle(center=(6, 20), radius=5)
    }
}
"""

SCALLOP_LOOP = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole bite {
        for i in range(4) { c = Circle(center=(-9 + 6 * i, 20), radius=4) }
    }
}
"""

WINDOW = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole opening { r = Rectangle(center=(0, 0), width=30, height=20) }
    hole screw_hole { c = Circle(center=(15, 0), radius=3) }
}
"""

VENTS = """solid plate {
    body = Rectangle(center=(0, 0), width=80, height=40)
    hole vent { c = Circle(center=(-20, 0), radius=4) }
    vents = LinearPattern(vent, 4, (7, 0))
}
"""

CASES = {"triangle": (TRIANGLE, "W0515"), "round": (ROUND, "W0515"),
         "spokes": (SPOKES, "W0501"), "scallop": (SCALLOP, "W0512"),
         "scallop_loop": (SCALLOP_LOOP, "W0512"), "window": (WINDOW, "W0508"),
         "vents": (VENTS, "W0508")}

STMT = re.compile(r"write `([A-Za-z_]\w*\([^`]*\))` in `([\w.\[\]]+)`")
CORRECTING = {"W0109"}      # fixes that change the part they name (and the stray hole)


def _programs():
    """The cases, then every example, test program and model run, each text once (a model
    run's `before/` and `after/` often hold the same program)."""
    out = [(name, src) for name, (src, _) in CASES.items()]
    seen = {src for _, src in out}
    for p in EXAMPLES + sorted((ROOT / "tests" / "programs").glob("*.aidl")) \
            + sorted((ROOT / "data" / "model_runs").glob("**/*.aidl")):
        src = p.read_text()
        if src not in seen:
            seen.add(src)
            out.append((str(p.relative_to(ROOT)), src))
    return out


PROGRAMS = _programs()


def _compile(src, name, tmp):
    from aidl_lang.pipeline import compile_source
    p = tmp / name.replace("/", "_")
    p = p if p.suffix == ".aidl" else p.with_suffix(".aidl")
    p.write_text(src)
    return compile_source(src, str(p))


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    """name -> the program compiled once (shared by the tests of this module)."""
    tmp = tmp_path_factory.mktemp("hints_safe")
    cache = {}

    def get(name, src, tag=""):
        key = (name, tag, src)
        if key not in cache:
            cache[key] = _compile(src, tag + name, tmp)
        return cache[key]
    return get


def _apply(src, d, model):
    """The program with warning ``d``'s proposed code applied (its fix, else the statement
    of a "write `STMT` in `PATH`" hint at the end of that structure), or None."""
    if d.fix is not None:
        sp = d.fix.span
        return src[:sp.start] + d.fix.replacement + src[sp.end:], sp.start

    m = STMT.search(d.hint or "")
    if m is None or model is None:
        return None
    stmt, path = m.groups()
    s = next((x for x in model.structures if x.path == path), None)
    if s is None or s.span is None or src[s.span.end - 1:s.span.end] != "}":
        return None
    end = s.span.end
    return src[:end - 1] + f"    {stmt}\n" + src[end - 1:], end - 1


def _design(c) -> dict:
    """The design as the outputs see it: part name -> (kind, shape), and the lines."""
    d = c.drawing
    return {p.name: (p.kind, p.shape) for p in d.parts}, [(s, len(pl)) for s, pl in d.lines]


def _changed(before, after) -> list:
    """The names of parts whose area or outline differs (or that appear or vanish)."""
    (pa, la), (pb, lb) = before, after
    out = sorted(set(pa) ^ set(pb))
    for name in set(pa) & set(pb):
        (ka, a), (kb, b) = pa[name], pb[name]
        whole = max(a.area(), b.area(), 1.0)
        diff = (a - b).area() + (b - a).area()
        if ka != kb or abs(a.area() - b.area()) > 1e-6 * whole or diff > 1e-6 * whole \
                or a.num_contour() != b.num_contour():
            out.append(name)
    if la != lb:
        out.append("<engraved lines>")
    return out


def _same(d, x, at: int, grew: int) -> bool:
    """``x`` (of the program grown by ``grew`` characters at offset ``at``) is warning ``d``
    again: its code, place and subject (:func:`_subject`: a hole refilled by what is left of
    a pattern is the same warning)."""
    if x.code != d.code or x.span is None or d.span is None:
        return x.code == d.code and x.message == d.message
    start = x.span.start - (grew if x.span.start >= at else 0)
    return start == d.span.start and _subject(x.message) == _subject(d.message)


def _subject(message: str) -> tuple:
    """What a warning is about: its first four words and the place it names (``near (x, y)``:
    two openings of one part are two warnings)."""
    return message.split()[:4], re.findall(r"near \([^)]*\)", message)


@pytest.mark.parametrize("name,src", PROGRAMS, ids=[n for n, _ in PROGRAMS])
def test_every_fix_removes_its_warning_and_changes_nothing_else(compiled, name, src):
    c = compiled(name, src)
    if c.drawing is None:
        return
    before = _design(c)
    tried = []
    for d in c.sink.items:
        if d.severity != "warning":
            continue
        fixed = _apply(src, d, c.model)
        if fixed is None:
            continue
        new, at = fixed
        after = compiled(name, new, tag=f"fixed{len(tried)}_")
        tried.append(d.code)
        errs = [(x.code, x.message) for x in after.sink.items if x.severity == "error"]
        assert not errs, (d.code, d.message, errs)
        grew = len(new) - len(src)
        assert not [x for x in after.sink.items if _same(d, x, at, grew)], \
            (d.code, d.message, new)
        assert not [x for x in after.sink.items if x.code == "W0523"], (d.code, new)
        changed = _changed(before, _design(after))
        if d.code in CORRECTING:
            stmt = d.fix.replacement if d.fix is not None else d.hint
            changed = [n for n in changed if n.split(".")[-1] not in stmt
                       and not any(n.endswith("." + w) for w in re.findall(r"\w+", stmt))]
        assert not changed, (d.code, d.message, changed, new)
    if name in CASES:
        assert CASES[name][1] in tried, (name, [(x.code, x.hint) for x in c.sink.items])


def test_W0515_offers_the_openings_own_outline_not_its_box(compiled):
    c = compiled("triangle", TRIANGLE)
    (w,) = [d for d in c.sink.items if d.code == "W0515"]
    assert "Polygon([" in w.fix.replacement and "Rectangle" not in w.fix.replacement
    pts = re.findall(r"\((-?[\d.]+), (-?[\d.]+)\)", w.fix.replacement.split("Polygon")[1])
    assert len(pts) == 3                    # the triangle, inset by 0.01 mm
    xs = sorted(float(x) for x, _ in pts)
    assert xs[0] == pytest.approx(-23.99, abs=1e-3) and xs[-1] == pytest.approx(26.64, abs=1e-2)


def test_W0501_names_the_patterns_list_so_every_copy_is_allowed(compiled):
    c = compiled("spokes", SPOKES)
    (w,) = [d for d in c.sink.items if d.code == "W0501"]
    assert "write `AllowOverlap(rim.opening, spoke, spokes)` in `wheel`" in w.hint


def test_AllowOverlap_between_two_holes_silences_W0508_and_one_allowing_nothing_says_so(
        compiled):
    c = compiled("window_allowed", WINDOW.replace(
        "\n}\n", "\n    AllowOverlap(opening, screw_hole)\n}\n"))
    assert c.ok and not [d for d in c.sink.items if d.code in ("W0508", "W0523")]
    far = WINDOW.replace("center=(15, 0)", "center=(30, 12)").replace(
        "\n}\n", "\n    AllowOverlap(opening, screw_hole)\n}\n")
    c = compiled("window_far", far)
    (w,) = [d for d in c.sink.items if d.code == "W0523"]
    assert (w.span.line, w.span.col) == (5, 5)
    assert "no two of `plate.opening`, `plate.screw_hole` overlap or touch" in w.message


def test_AllowOverlap_of_the_spokes_original_alone_is_not_W0523_but_W0501_remains(compiled):
    c = compiled("spokes_original", SPOKES.replace(
        "\n}\n", "\n    AllowOverlap(rim.opening, spoke)\n}\n"))
    assert not [d for d in c.sink.items if d.code == "W0523"]   # the original overlaps too
    (w,) = [d for d in c.sink.items if d.code == "W0501"]
    assert "7 copies" in w.message and "AllowOverlap(rim.opening, spokes)" in w.hint


def test_W0501_for_an_unnamed_patterns_copies_says_to_name_it_and_offers_no_broad_fix(compiled):
    src = SPOKES.replace("    spokes = CircularPattern", "    CircularPattern")
    c = compiled("spokes_unnamed", src)
    (w,) = [d for d in c.sink.items if d.code == "W0501"]
    assert "(`NAME = ` before it) and add `AllowOverlap(rim.opening, spoke, NAME)`" in w.hint
    assert w.fix is None and "self" not in w.hint     # was AllowOverlap(..., self): all of wheel
    fixed = compiled("spokes_named", SPOKES.replace("\n}\n",
                                                   "\n    AllowOverlap(rim.opening, spoke, spokes)\n}\n"))
    assert not [d for d in fixed.sink.items if d.code in ("W0501", "W0523")]


def test_W0515_round_an_island_offers_no_hole_that_would_cut_it_away(compiled):
    src = TRIANGLE.replace("\n}\n", "\n    dot = Circle(center=(-12, 15), radius=3)\n}\n")
    c = compiled("island", src)
    (w,) = [d for d in c.sink.items if d.code == "W0515"]
    assert w.fix is None and "leaves out the material inside it" in w.hint
