"""Syntactically valid but nasty AIDL programs (issue 15): nested loops and comprehensions,
self-instantiating templates with fan-out, numbers at the extremes (0, 5e-324, 1e14, 1e300),
degenerate shapes (zero sizes, repeated points, zero-length lines in direction constraints),
huge strings and format widths, deep expressions, odd imports; and issue 26's classes:
``Fixed`` on every geometry kind, huge patterns, many concentric circles, many structures,
import diamonds (:func:`diamond_dir`), zero-area loops, deep nesting.

:func:`program` builds one program from a *chooser* — anything with ``pick(seq)`` and
``int(lo, hi)`` — so the same generator drives a hypothesis strategy (``tests/test_hostile.py``,
a few examples in CI) and a seeded long run (``benchmarks/checks/fuzz_nasty.py``).

:func:`verdict` runs one program through the real pipeline (and the SVG writer when it
compiles) and returns ``None`` or the kind of failure: an exception, an unlocated
diagnostic, a run over the time allowed.
"""
from __future__ import annotations

import random
import re
import time

NUMBERS = ["0", "1", "2", "3", "-1", "0.5", "3.5", "10", "100", "1e-9", "5e-324", "1e6",
           "1e9", "1e14", "1e300", "-1e14", "1 / 5e-324", "1e14 * 1e14", "0 * 1e300",
           "7 mm", "2 in", "45 deg"]
COUNTS = ["0", "1", "3", "10", "100", "1000", "10000"]
# diagnostics that may legitimately carry no span (whole-model conditions)
UNLOCATED_OK = {"E0402", "E0304", "E0401", "W0104"}


class RandomChooser:
    """A chooser over :class:`random.Random` (for the long run)."""

    def __init__(self, seed: int):
        self.r = random.Random(seed)

    def pick(self, seq):
        return seq[self.r.randrange(len(seq))]

    def int(self, lo: int, hi: int) -> int:
        return self.r.randint(lo, hi)


class DrawChooser:
    """A chooser over hypothesis' ``draw`` (for the property test)."""

    def __init__(self, draw):
        from hypothesis import strategies as st
        self.draw, self.st = draw, st

    def pick(self, seq):
        return self.draw(self.st.sampled_from(list(seq)))

    def int(self, lo: int, hi: int) -> int:
        return self.draw(self.st.integers(lo, hi))


def expr(c, names: list[str], depth: int = 0) -> str:
    k = c.int(0, 9) if depth < 3 else 0
    if k <= 3 or not names and k <= 5:
        return c.pick(NUMBERS)
    if k <= 5:
        return c.pick(names)
    if k == 6:
        return f"({expr(c, names, depth + 1)} {c.pick(['+', '-', '*', '/', '**', '%', '//'])} " \
               f"{expr(c, names, depth + 1)})"
    if k == 7:
        return f"{c.pick(['sqrt', 'abs', 'sin', 'tan', 'square', 'round', 'ceil', 'str'])}({expr(c, names, depth + 1)})"
    if k == 8:
        return f"({expr(c, names, depth + 1)} if {c.pick(['true', 'false'])} else " \
               f"{expr(c, names, depth + 1)})"
    n = c.pick(["50", "300", "600"])
    return c.pick(["-" * int(n) + "1", "(" + " ** ".join(["1"] * int(n)) + ")",
                   "(" + " if true else ".join(["1"] * int(n)) + ")"])


def point(c, names) -> str:
    return f"({expr(c, names)}, {expr(c, names)})"


def shape(c, names, kind: str) -> str:
    e = lambda: expr(c, names)          # noqa: E731
    return c.pick([
        f"Circle(center={point(c, names)}, radius={e()})",
        f"Rectangle(center={point(c, names)}, width={e()}, height={e()})",
        f"Line({point(c, names)}, {point(c, names)})",
        "Line((0, 0), (0, 0))",
        f"Arc(center={point(c, names)}, radius={e()}, start_angle=0 deg, end_angle={e()} * 1 deg)",
        f"Polygon([{point(c, names)}, {point(c, names)}, {point(c, names)}])",
        "Polygon([(0, 0), (0, 0), (1, 1)])",
        f"RegularPolygon(center={point(c, names)}, radius={e()}, sides={e()})",
        f"Slot(center={point(c, names)}, length={e()}, width={e()})",
    ])


def every_kind(c, names) -> str:
    """One geometry of any kind (issue 26: ``Fixed`` on every geometry kind)."""
    e = lambda: expr(c, names)          # noqa: E731
    p = lambda: point(c, names)         # noqa: E731
    return c.pick([
        f"Point({e()}, {e()})", f"Line({p()}, {p()})", f"Circle({p()}, {e()})",
        f"Circle({p()}, diameter={e()})", f"Arc({p()}, {p()}, {p()})",
        f"Arc(center={p()}, radius={e()}, start_angle={e()}, end_angle={e()})",
        f"Arc(start={p()}, through={p()}, end={p()})",
        f"Rectangle({p()}, {e()}, {e()}, rotation={e()})",
        f"Rectangle(corner={p()}, opposite={p()})",
        f"RoundedRectangle({p()}, {e()}, {e()}, {e()})",
        f"Triangle({p()}, {p()}, {p()})", f"Triangle(center={p()}, base={e()}, height={e()})",
        f"Trapezoid({p()}, {e()}, {e()}, {e()})", f"Ellipse({p()}, {e()}, {e()})",
        f"Polygon([{p()}, {p()}, {p()}, {p()}], flexible=true)",
        f"RegularPolygon({p()}, {e()}, {e()})",
        f"RegularPolygon(center={p()}, across_flats={e()}, sides={c.pick(['3', '6', '1000'])})",
        f"Slot({p()}, {p()}, {e()})", f"Slot(center={p()}, length={e()}, width={e()})",
        f"ArcSlot({p()}, {e()}, {e()}, {e()}, {e()})",
        f"Star({p()}, {c.pick(['2', '5', '500'])}, {e()}, {e()})",
        f'Text("{c.pick(["A", "ok", "é漢字"])}", {p()}, size={e()})',
    ])


ZERO_AREA = [
    "Polygon([(0, 0), (1, 0), (2, 0)])", "Polygon([(0, 0), (5, 5), (0, 0), (5, 5)])",
    "Polygon([(1, 1), (1, 1), (1, 1)])", "Rectangle(center=(0, 0), width=0, height=5)",
    "Rectangle(center=(0, 0), width=5, height=0)", "Triangle((0, 0), (1, 1), (2, 2))",
    "RegularPolygon(center=(0, 0), radius=0, sides=6)", "Ellipse((0, 0), 5, 0)",
    "Slot(center=(0, 0), length=0, width=0)", "Circle((0, 0), 0)",
    "Star((0, 0), 5, 0, 0)", "Trapezoid((0, 0), 0, 0, 3)",
    "RoundedRectangle((0, 0), 4, 4, 2)", "ArcSlot((0, 0), 5, 0, 0, 1)",
]


def body(c, names: list[str], depth: int, n_stmts: int, lines: list[str], ind: str,
         shapes: list[str], kind: str) -> None:
    for k in range(n_stmts):
        what = c.int(0, 18)
        v = f"v{depth}_{k}"
        if what <= 2:
            lines.append(f"{ind}{v} = {shape(c, names, kind)}")
            shapes.append(v)
        elif what == 3:
            lines.append(f"{ind}{v} = {expr(c, names)}")
            names.append(v)
        elif what == 4 and depth < 3:
            lines.append(f"{ind}for i{depth} in range({c.pick(COUNTS)}) {{")
            body(c, names + [f"i{depth}"], depth + 1, c.int(1, 2), lines, ind + "    ", [], kind)
            lines.append(f"{ind}}}")
        elif what == 5:
            lines.append(f"{ind}{v} = [{expr(c, names)} for j in range({c.pick(COUNTS)})]")
        elif what == 6:
            lines.append(f"{ind}{v} = [[j for j in range({c.pick(COUNTS)})] for q in "
                         f"range({c.pick(COUNTS)})]")
        elif what == 7:
            w = c.pick(["5", "80", "999999", "999999999"])
            lines.append(f'{ind}{v} = f"{{{expr(c, names)}:{w}}}"')
        elif what == 8 and len(shapes) >= 1:
            a, b = c.pick(shapes), c.pick(shapes)
            con = c.pick([f"Fixed({a})", f"Coincident({a}, {b})", f"Tangent({a}, {b})",
                          f"Angle({a}, {b}, {expr(c, names)} * 1 deg)", f"Parallel({a}, {b})",
                          f"Perpendicular({a}, {b})", f"Length({a}, {expr(c, names)})",
                          f"Distance({a}, {b}, {expr(c, names)})", f"Horizontal({a})",
                          f"{a}.bb.width == {expr(c, names)}"])
            lines.append(f"{ind}{con}")
        elif what == 9:
            lines.append(f'{ind}drawing d{depth}_{k} {{ t = Text("{c.pick(["ok", "é漢字", "x" * 50])}", '
                         f"{point(c, names)}) }}")
        elif what == 10:
            lines.append(f"{ind}{v} = fan({c.pick(['1', '3', '6', '14'])})")
        elif what == 12:                # Fixed on every geometry kind
            lines.append(f"{ind}{v} = {every_kind(c, names)}")
            lines.append(f"{ind}Fixed({v})")
            shapes.append(v)
        elif what == 13 and shapes:     # huge patterns
            n = c.pick(["0", "1", "2", "1000", "5000", "10000", "100000", "1e9", "-3", "2.5"])
            lines.append(f"{ind}{v} = " + c.pick([
                f"LinearPattern({c.pick(shapes)}, {n}, {point(c, names)})",
                f"CircularPattern({c.pick(shapes)}, {n}, {point(c, names)})",
                f"CircularPattern({c.pick(shapes)}, {n}, (0, 0), angle={expr(c, names)} * 1 deg)"]))
        elif what == 14:                # many concentric circles
            n = c.pick(["10", "1000", "5000", "20000"])
            step = c.pick(["0.1", "1e-9", "0", "1"])
            if c.int(0, 1):
                lines.append(f"{ind}{v} = [Circle(center=(0, 0), radius=1 + j * {step}) "
                             f"for j in range({n})]")
            else:
                lines.append(f"{ind}for j in range({n}) {{ {v} = Circle(center=(0, 0), "
                             f"radius=1 + j * {step}) }}")
        elif what == 15:                # many structures
            n = c.pick(["10", "500", "5000", "20000"])
            sk = c.pick(["solid", "hole", "drawing", "assembly"])
            lines.append(f"{ind}for j in range({n}) {{ {sk} s{v} {{ c = Circle(center=(j * 3, 0), "
                         f"radius=1) }} }}")
        elif what == 16:                # zero-area loops
            lines.append(f"{ind}{v} = {c.pick(ZERO_AREA)}")
            shapes.append(v)
        elif what == 17:                # deep nesting of structures (and of blocks)
            d = int(c.pick(["5", "20", "60", "200"]))
            kinds = ["solid", "hole", "assembly", "drawing"]
            open_ = "".join(f"{c.pick(kinds)} n{i} {{ " for i in range(d))
            mid = c.pick(["c = Circle((0, 0), 1)", "l = Line((0, 0), (1, 0))", ""])
            lines.append(f"{ind}{open_}{mid}{' }' * d}")
            if c.int(0, 1):
                lines.append(f"{ind}" + "if true { " * d + f"{v} = Circle((0, 0), 2)" + " }" * d)
        else:
            lines.append(f"{ind}if {expr(c, names)} > 1 {{")
            body(c, names, depth + 1, 1, lines, ind + "    ", shapes, kind)
            lines.append(f"{ind}}}")


DIAMOND_LEVELS = 24


def diamond_dir(d) -> None:
    """Write an import diamond of :data:`DIAMOND_LEVELS` levels into folder ``d``: ``dKa.aidl``
    and ``dKb.aidl`` both import ``d(K+1)a`` and ``d(K+1)b``; the last level imports
    ``bottom.aidl``; ``cycle.aidl`` imports itself through ``cycle2.aidl``.  Programs from
    :func:`program` import ``dK?.aidl`` when they are checked as a file of that folder."""
    import pathlib
    d = pathlib.Path(d)
    (d / "bottom.aidl").write_text("def base() -> solid {\n  c = Circle(center=(0, 0), radius=1)\n}\n")
    for k in range(DIAMOND_LEVELS - 1, -1, -1):
        for s in "ab":
            imps = 'import "bottom.aidl"\n' if k == DIAMOND_LEVELS - 1 else \
                f'import "d{k + 1}a.aidl"\nimport "d{k + 1}b.aidl"\n'
            (d / f"d{k}{s}.aidl").write_text(
                imps + f"def t{k}{s}() -> solid {{\n  c = Circle(center=(0, 0), radius=1)\n}}\n"
                f"k{k}{s} = {k}\n")
    (d / "cycle.aidl").write_text('import "cycle2.aidl"\ndef cy() -> solid { c = Circle((0, 0), 1) }\n')
    (d / "cycle2.aidl").write_text('import "cycle.aidl"\n')


def program(c) -> str:
    """One nasty program from chooser ``c``."""
    lines: list[str] = []
    if c.int(0, 5) == 0:
        lines.append(c.pick(['import "std/shapes.aidl"', 'import "../outside.aidl"',
                             'import "' + "a" * 300 + '"', 'import "/etc/passwd"',
                             'import "std/../../x.aidl"']))
    if c.int(0, 5) == 0:                # import diamonds (see diamond_dir)
        k = c.int(0, DIAMOND_LEVELS - 1)
        lines.append(f'import "d{k}{c.pick("ab")}.aidl"')
        lines.append(c.pick([f"k_ = k{DIAMOND_LEVELS - 1}a", f"solid dd {{ x = t{k}a() }}", "",
                             'import "cycle.aidl"', "b_ = base()"]))
    lines.append("def fan(n = 3) -> assembly {")
    lines.append("    if n > 0 {")
    for k in range(c.int(1, 3)):
        lines.append(f"        s{k} = fan(n - 1)")
    lines.append("    }")
    lines.append("    c = Circle((0, 0), 1)")
    lines.append("}")
    names: list[str] = []
    for k in range(c.int(0, 2)):
        lines.append(f"k{k} = {expr(c, names)}")
        names.append(f"k{k}")
    kind = c.pick(["solid", "assembly"])
    lines.append(f"{kind} top {{")
    body(c, names, 0, c.int(1, 6), lines, "    ", [], kind)
    lines.append("}")
    return "\n".join(lines) + "\n"


def verdict(src: str, path: str, budget=None, seconds: float = 30.0, render: bool = True):
    """``None`` if the pipeline answered properly, else a short failure kind."""
    from aidl_lang.base.codes import CODES
    from aidl_lang.pipeline import compile_source
    t0 = time.perf_counter()
    try:
        c = compile_source(src, path, budget=budget) if budget else compile_source(src, path)
    except MemoryError:
        return "memory"
    except Exception as ex:                 # an internal error: the bug this looks for
        return f"exception:{type(ex).__name__}:{str(ex)[:80]}"
    if time.perf_counter() - t0 > seconds:
        return "slow"
    for d in c.sink.items:
        if d.code not in CODES:
            return f"unknown-code:{d.code}"
        if d.span is None and d.code not in UNLOCATED_OK:
            return f"unlocated:{d.code}:{d.message[:60]}"
    if c.ok and (c.solve is None or not c.solve.converged):
        return "ok-without-solve"
    if c.ok and render:
        try:
            from aidl_lang.output import OutputError, build, encode, render_model
            # as ``aidl render`` does: the compile's drawing (made under its deadline), its exact
            # outlines and the SVG writer under the same deadline (rendering again without it
            # timed the fuzzer, not AIDL)
            drawing = c.drawing if c.drawing is not None else render_model(c.model)
            out = build(drawing, "", deadline=c.deadline)
            svg = encode(out, ".svg", deadline=c.deadline).decode()
            if time.perf_counter() - t0 > seconds:      # compile + writer, as a user waits
                return "slow"
            if re.search(r"\b(nan|inf|infinity)\b", svg, re.IGNORECASE):
                return "non-finite-in-svg"
        except OutputError:                 # the writers' own clear refusal: an answer
            return None
        except MemoryError:
            return "memory"
        except Exception as ex:
            return f"render:{type(ex).__name__}:{str(ex)[:80]}"
    return None
