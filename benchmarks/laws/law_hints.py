"""Law 4 of issue 109, *a hint keeps the design*: a warning's suggested edit, applied as a
model or ``aidl generate``'s repair loop applies it, leaves the solved design where it was.

For a program: compile it (as ``aidl check`` does: the redundancy search, W0401, and the
sliding search, W0404, bounded as there), then take every warning whose hint or fix can be
applied mechanically, each on its own, to the program's text:

* a fix (``Diagnostic.fix``: a span and its replacement), or a hint "write `STMT` in `PATH`"
  (the statement added at the end of that structure's block);
* W0401's drops: a group's "drop `X` (line N), ..." and a lone constraint that "is redundant:
  ... removing it would free nothing" (not a partly redundant one: "drop one of them only if
  it repeats the same intent" is a judgement, not an edit; not one whose hint says to keep
  it);
* a warning whose hint says to delete the statement it points at (:data:`DELETES`).

The edited text is compiled again (statements blanked with spaces, so every other place in the
file keeps its line and column) and compared with the original: no error, the warning gone,
and every part's outline and every contour (area, centre and box) and every engraved line to
:data:`TOL` mm; a drop also frees no degree of freedom and starts no feature sliding (W0401
says "removing it would free nothing").  The fixes that say they change the part they name
(:data:`CHANGING`) are held only to what they name.  Each edit that breaks one of these is
one line of :func:`check`.

The same helpers serve the suite (tests/test_hints_safe.py, tests/test_law_hints.py): the
compile, the edits, the design as drawn and its comparison.
"""
from __future__ import annotations

import re

from .common import NotApplicable

NAME = "a warning's suggested edit, applied, leaves the solved design where it was"
TOLERANCE = ("1e-6 mm: every contour's centre and box, every engraved line's points; areas "
             "and the symmetric difference of each part's outline to 1e-6 of its area")
TOL = 1e-6

# "write `STMT` in `PATH`": a statement a hint proposes, added at the end of that structure
STMT = re.compile(r"write `([A-Za-z_]\w*\([^`]*\))` in `([\w.\[\]]+)`")
# a W0401 group's drop list: "`X` (line N)"
LISTED = re.compile(r"`([^`]*)` \((line \d+)\)")
# warnings whose hint says to delete the statement they point at, for what it adds nothing
# to the design: a child solid inside the rest of its parent (W0506), a face of zero area
# (W0509), a through-cut that cuts nothing (W0522), an AllowOverlap that allows nothing
# (W0523), an engraved Line of zero length (W0524)
DELETES = {"W0506", "W0509", "W0522", "W0523", "W0524"}
# fixes that say they change the part: W0109's `CutInto` makes a stray hole cut the part it
# lies over (the part it names and the hole change); W0508's fix moves a hole clear of
# another (issue 91: never an AllowOverlap that hides the overlap; the part holding the two
# holes changes, with one more opening)
CHANGING = {"W0109", "W0508"}


# ------------------------------------------------------------------ compiling
def compile_text(source: str, path: str, overrides: dict | None = None):
    """``source`` through the whole pipeline (:func:`aidl_lang.pipeline.compile_source`) as
    the file ``path`` (imports resolve beside it; nothing is written), ``overrides`` as
    ``--set`` takes them."""
    from aidl_lang.pipeline import compile_source
    return compile_source(source, path, overrides=overrides or None)


def checked(c, bounded: bool = False) -> tuple:
    """What `aidl check` adds after the compile ``c``: ``(items, dof)``, the W0401 and W0404
    warnings, and the degrees of freedom per structure (``[(path, dof)]``).  ``bounded``:
    the redundancy search within `aidl check`'s bounds (else none)."""
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.pipeline import report_redundancies, report_sliding
    from aidl_lang.solver.diagnosis import freedom
    sink = DiagnosticSink()
    if bounded:
        from aidl_lang.api import REDUNDANCY_ROWS, REDUNDANCY_SECONDS
        report_redundancies(sink, c.solve, REDUNDANCY_SECONDS, REDUNDANCY_ROWS)
    else:
        report_redundancies(sink, c.solve)
    report_sliding(sink, c.solve)
    dof = [(d.structure.path, d.unknowns - d.rank)
           for d in freedom.degrees_of_freedom(c.solve.solver, floating=False)]
    return sink.items, dof


# ------------------------------------------------------------------ the edits
def applied_fix(src: str, d, model):
    """``(text, at)``: the program with warning ``d``'s proposed code applied (its fix, else
    the statement of a "write `STMT` in `PATH`" hint at the end of that structure), and the
    offset where the text changed; None when it proposes none."""
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


def proposed_fixes(src: str, c):
    """``(warning, text, at)`` for each warning (or note) of the compile ``c`` of ``src`` that
    proposes code: the program with it applied (:func:`applied_fix`) and the offset of the
    change.  A note proposes as a warning does (W0515's wide window, W0508's crossing holes
    are notes): what it proposes is held to the same law."""
    for d in c.sink.items:
        if d.severity not in ("warning", "note"):
            continue
        fixed = applied_fix(src, d, c.model)
        if fixed is not None:
            yield d, fixed[0], fixed[1]


def statement(src: str, span) -> tuple:
    """``(start, end)`` of the statement at ``span``, with a name it is given (`corners = `)."""
    start, end = span.start, span.end
    head = src[src.rfind("\n", 0, start) + 1:start]
    named = re.search(r"[A-Za-z_]\w*\s*=\s*$", head)
    return (start - len(named.group(0)) if named else start), end


def dropped(d, model) -> list | None:
    """The constraints warning ``d`` says to drop, or None when it names none for sure: a
    group's "drop `X` (line N), ..."; a constraint that "is redundant: ... removing it would
    free nothing" itself (unless the hint says to keep it); nothing for a partly redundant
    one ("drop one of them only if it repeats the same intent" is a judgement, not an edit)."""
    if d.code != "W0401":
        return None
    written = [c for c in model.constraints if not c.implicit and c.span is not None]
    if "say the same thing" in d.message:
        m = re.search(r"drop (.*?): the (model|template)", d.hint or "")
        if m is None:
            return None
        out = []
        for text, line in LISTED.findall(m.group(1)):
            n = int(line.split()[1])
            out += [c for c in written if c.span.line == n and c.describe() == text][:1]
        return out
    if " is redundant: " in d.message and "not `" not in (d.hint or ""):
        return [c for c in written if c.span.start == d.span.start][:1]
    return None


def edits(d, model, src: str) -> list | None:
    """The ``(start, end)`` of each statement warning ``d`` says to drop or delete (with
    the name it is given), or None."""
    if d.code in DELETES and d.span is not None and "delete" in (d.hint or ""):
        return [statement(src, d.span)]
    drop = dropped(d, model)
    return [statement(src, c.span) for c in drop] if drop else None


def blanked(src: str, spans: list) -> str:
    """``src`` with the statements at ``spans`` blanked (spaces: no offset moves)."""
    for a, b in spans:
        src = src[:a] + re.sub(r"[^\n]", " ", src[a:b]) + src[b:]
    return src


# ------------------------------------------------------------------ the design as drawn
def design(c) -> tuple:
    """The design as the outputs see it: part name -> (kind, shape), and the lines."""
    d = c.drawing
    return {p.name: (p.kind, p.shape) for p in d.parts}, [(s, len(pl)) for s, pl in d.lines]


def drawn(c) -> tuple:
    """The design as :func:`design` gives it, its lines only those that draw something: of
    some length, and meeting a part's box (a through-cut beside the part, W0522, or a Line
    of zero length, W0524, draws nothing), each with its points to 1e-6 mm."""
    import numpy as np
    parts, _ = design(c)
    boxes = [p.shape.bounds() for p in c.drawing.parts]
    lines = []
    for stroke, pl in c.drawing.lines:
        pl = np.asarray(pl, dtype=float)
        lo, hi = pl.min(axis=0), pl.max(axis=0)
        if float(np.abs(np.diff(pl, axis=0)).sum()) <= 1e-9 or not any(
                lo[0] <= b[2] and hi[0] >= b[0] and lo[1] <= b[3] and hi[1] >= b[1]
                for b in boxes):
            continue
        lines.append((stroke, tuple(np.round(pl, 6).ravel().tolist())))
    return parts, sorted(lines)


def changed(before, after) -> list:
    """The names of parts whose area or outline differs (or that appear or vanish), and
    ``<engraved lines>`` when those differ."""
    (pa, la), (pb, lb) = before, after
    out = sorted(set(pa) ^ set(pb))
    for name in set(pa) & set(pb):
        (ka, a), (kb, b) = pa[name], pb[name]
        whole = max(a.area(), b.area(), 1.0)
        diff = (a - b).area() + (b - a).area()
        if ka != kb or abs(a.area() - b.area()) > TOL * whole or diff > TOL * whole \
                or a.num_contour() != b.num_contour():
            out.append(name)
    if la != lb:
        out.append("<engraved lines>")
    return out


def contours(c) -> dict:
    """part -> its contours' (area, centre x, centre y, box), sorted: every opening's place."""
    out = {}
    for p in c.drawing.parts:
        rows = []
        for poly in p.shape.to_polygons():
            xs, ys = poly[:, 0], poly[:, 1]
            a = 0.5 * float((xs * (ys.take(range(1, len(ys) + 1), mode="wrap"))
                             - ys * (xs.take(range(1, len(xs) + 1), mode="wrap"))).sum())
            box = (float(xs.min()), float(ys.min()), float(xs.max()), float(ys.max()))
            rows.append((round(abs(a), 3), float(xs.mean()), float(ys.mean()), box))
        out[p.name] = sorted(rows, key=lambda r: (r[0], round(r[1], 4), round(r[2], 4)))
    return out


def moved_contours(before: dict, after: dict) -> list:
    """The parts one of whose contours went, came, or moved (its centre or box) by more
    than :data:`TOL` mm, or changed its area (to 1e-3 mm^2)."""
    out = sorted(set(before) ^ set(after))
    for k in set(before) & set(after):
        a, b = before[k], after[k]
        if len(a) != len(b) or any(
                u[0] != v[0] or abs(u[1] - v[1]) > TOL or abs(u[2] - v[2]) > TOL
                or max(abs(p - q) for p, q in zip(u[3], v[3])) > TOL
                for u, v in zip(a, b)):
            out.append(k)
    return sorted(out)


# ------------------------------------------------------------------ the law
def unsafe_drops(name: str, src: str, compile_as, bounded: bool = False) -> tuple:
    """``(hints applied, problems)`` for every warning of ``src`` that names statements to
    drop or delete (W0401, :data:`DELETES`), each applied on its own to the program it came
    from.  ``compile_as(name, text)`` compiles a text (the tests keep a cache); ``bounded``
    as :func:`checked`.  Each problem is ``(hint, [why...])``."""
    c = compile_as(name, src)
    if c.drawing is None or not c.ok or c.solve is None:
        return 0, []
    items, dof = checked(c, bounded)
    before = drawn(c)
    shape = contours(c)
    slide = sorted(x.message for x in items if x.code == "W0404")
    applied, bad = 0, []
    for d in items + [x for x in c.sink.items if x.code in DELETES]:
        spans = edits(d, c.model, src)
        if not spans:
            continue
        applied += 1
        after = compile_as(name, blanked(src, spans))
        errs = [(x.code, x.message) for x in after.sink.items if x.severity == "error"]
        if errs or after.drawing is None or after.solve is None:
            bad.append((d.hint, ["errors", errs[:2]]))
            continue
        why = []
        items2, dof2 = checked(after, bounded)
        if [x for x in items2 + after.sink.items if x.code == d.code and x.message == d.message]:
            why.append("the warning stays")
        left = dict(dof2)
        if any(left.get(path, 0) > n for path, n in dof):     # deleted geometry: fewer
            why.append(f"freedom {dof} -> {dof2}")
        if sorted(x.message for x in items2 if x.code == "W0404") != slide:
            why.append("a feature slides")
        moved = changed(before, drawn(after))
        if moved:
            why.append(f"changed {moved}")
        moved = moved_contours(shape, contours(after))
        if moved:
            why.append(f"an opening moved or went in {moved}")
        if why:
            bad.append((d.hint, why))
    return applied, bad


def unsafe_fixes(name: str, src: str, compile_as) -> tuple:
    """``(fixes applied, problems)`` for every warning of ``src``'s compile with a fix or a
    "write `STMT` in `PATH`" hint (:func:`applied_fix`), each applied on its own: the
    edited program has no error and draws the same design (:func:`changed`), but for the
    fixes that say they change the part (:data:`CHANGING`), held to what they name."""
    c = compile_as(name, src)
    if c.drawing is None:
        return 0, []
    before = drawn(c)
    applied, bad = 0, []
    for d, text, _ in proposed_fixes(src, c):
        applied += 1
        after = compile_as(name, text)
        errs = [(x.code, x.message) for x in after.sink.items if x.severity == "error"]
        if errs or after.drawing is None:
            bad.append((d.code, d.message, ["errors", errs[:2]]))
            continue
        moved = changed(before, drawn(after))
        if d.code in CHANGING:
            stmt = d.fix.replacement if d.fix is not None else (d.hint or "")
            moved = [n for n in moved if n.split(".")[-1] not in stmt
                     and not any(n.endswith("." + w) for w in re.findall(r"\w+", stmt))]
            if d.code == "W0508":       # the part holding the two holes gets the move
                part = re.search(r" of `([^`]+)` (?:overlap|touch)", d.message)
                moved = [n for n in moved if part is None or n != part.group(1)]
        if moved:
            bad.append((d.code, d.message, [f"changed {moved}"]))
    return applied, bad


def applies(entry) -> bool:
    """Every program: which warnings it raises is known only once compiled (one that does
    not compile is :class:`NotApplicable` in :func:`check`)."""
    return True


def check(entry) -> list[str]:
    """One line per suggested edit of ``entry`` that, applied, breaks the design or errs:
    ``W0401 line 26: drop ... -> changed ['lid']``."""
    overrides = dict(getattr(entry, "overrides", None) or {})
    cache: dict = {}

    def compile_as(_name, text):
        if text not in cache:
            cache[text] = compile_text(text, entry.path, overrides)
        return cache[text]
    try:
        c = compile_as(entry.name, entry.source)
    except Exception as ex:       # the compiler's own failure: another law's business
        raise NotApplicable(f"the compiler raised {type(ex).__name__}") from ex
    if not c.ok or c.drawing is None or c.solve is None:
        raise NotApplicable("does not compile")
    out = []
    try:
        _, bad = unsafe_drops(entry.name, entry.source, compile_as, bounded=True)
        out += [f"drop: {hint} -> {'; '.join(map(str, why))}" for hint, why in bad]
        _, bad = unsafe_fixes(entry.name, entry.source, compile_as)
        out += [f"{code} fix: {msg} -> {'; '.join(map(str, why))}" for code, msg, why in bad]
    except Exception as ex:       # an edit the compiler could not take: said, never raised
        out.append(f"applying a hint raised {type(ex).__name__}: {ex}")
    return out


# ------------------------------------------------------------------ generated programs
def generated_program(seed: int) -> str:
    """A plate whose holes are each placed by a combination that says it twice (a pattern
    with distances, `Fixed` with `At`, a symmetric pair with `AlignCenterY` and a distance,
    `AlignCenterX` with `At`, a duplicate), with statements that add nothing (an
    `AllowOverlap` of two holes apart, a through-cut beside the plate, an engraved Line of
    zero length, a child solid inside the plate), statements shuffled, starting positions off
    the solution; seeded (``random.Random(seed)``), the same on every machine."""
    import random
    rnd = random.Random(seed)
    w, h = rnd.choice([100, 120, 140]), rnd.choice([70, 80, 90])
    inset, x, y = rnd.choice([6, 8, 10]), rnd.choice([20, 25, 30]), rnd.choice([12, 15])
    shapes = [f"body = Rectangle(center=(0, 0), width={w}, height={h})"]
    stmts = []
    kinds = rnd.sample(["corner", "fixed_at", "align_at", "sym", "dup"], rnd.randint(1, 3))

    def hole(name, cx, cy):
        shapes.append(f"hole {name} {{ c = Circle(center=({cx + rnd.choice([-1.5, 1, 2])}, "
                      f"{cy + rnd.choice([-1, 1.5])}), diameter=4) }}")
    if "corner" in kinds:
        hole("corner", -w / 2 + inset, -h / 2 + inset)
        stmts.append(f"CornerPattern(corner, body, inset={inset} mm)")
        extra = [f"HorizontalDistance(body.left.midpoint, corner.c.center, {inset} mm)",
                 f"VerticalDistance(body.bottom.midpoint, corner.c.center, {inset} mm)",
                 f"At(corner.c.center, body.bottom_left, dx={inset}, dy={inset})"]
        stmts += rnd.sample(extra, rnd.randint(1, 3))
    if "fixed_at" in kinds:
        shapes.append(f"hole pin {{ c = Circle(center=({-x}, {-y}), diameter=4) }}")
        stmts += ["Fixed(body)", "Fixed(pin.c.center)",
                  f"At(pin.c.center, body.center, dx={-x}, dy={-y})"]
    if "align_at" in kinds:
        hole("slot", 0, y)
        stmts += [f"At(slot.c.center, body.center, dx=0, dy={y})", "AlignCenterX(slot, body)"]
    if "sym" in kinds:
        hole("left", -x, y)
        hole("right", x, y)
        shapes.append(f"axis = Line(start=(0, {-h / 2}), end=(0, {h / 2}), construction=true)")
        stmts += ["Fixed(axis)", f"At(left.c.center, body.center, dx={-x}, dy={y})",
                  "Symmetric(left.c.center, right.c.center, axis)"]
        stmts += rnd.sample(["AlignCenterY(left, right)",
                             f"HorizontalDistance(left.c.center, right.c.center, {2 * x} mm)"],
                            rnd.randint(1, 2))
    if "dup" in kinds:
        hole("vent", x, -y)
        stmts += [f"At(vent.c.center, body.center, dx={x}, dy={-y})"] * 2
    if rnd.random() < 0.3:
        hole("mark", 0, -y)
        hole("dot", 0, 0)
        stmts.append("AllowOverlap(mark, dot)")
    if rnd.random() < 0.3:
        shapes.append(f"cut slits {{ a = Line(start=({w / 2 + 5}, 0), end=({w / 2 + 15}, 0)) }}")
    if rnd.random() < 0.3:
        shapes.append(f"drawing marks {{ z = Line(start=({-x}, 0), end=({-x}, 0)) }}")
    if rnd.random() < 0.3:
        shapes.append(f"solid boss {{ r = Rectangle(center=({x}, 0), width=6, height=4) }}")
    if rnd.random() < 0.5 and "Fixed(body)" not in stmts:
        stmts.append("Fixed(body)")
    rnd.shuffle(stmts)
    return "solid plate {\n" + "".join(f"    {s}\n" for s in shapes + stmts) + "}\n"


def generated_joint_program(seed: int) -> str:
    """A panel with two joints of std/joints.aidl (`cross_halving`, `dovetail`) on its top
    edge, each placed one of the ways models and makers write it: by its arguments alone
    (the template holds itself there), by `AlignTop` and a distance from the panel's edge,
    by `AlignTop` and a distance from the other joint (issue 109's divider), by `CenterInside`
    or `AlignCenterX` (a lid's dovetail), with some statement said twice (a redundancy whose
    drop is safe), the panel `Fixed` or floating; seeded (``random.Random(seed)``)."""
    import random
    rnd = random.Random(seed)
    w, h = rnd.choice([160, 200, 240]), rnd.choice([60, 80])
    pitch = rnd.choice([60, 80, 100])
    calls = {"cross_halving": "cross_halving(depth={d} mm, thickness=3 mm{at})",
             "dovetail": "dovetail(part=\"{part}\", length=40 mm, depth=8 mm, tails=1{at})"}
    cut = {"cross_halving": "{}.cut.center", "dovetail": "{}.cut[0].center"}  # a list: per tail
    kinds: dict = {}
    lines = [f"body = Rectangle(center=(0, 0), width={w}, height={h})"]
    stmts = []
    for i, name in enumerate(("a", "b")):
        kind = kinds[name] = rnd.choice(list(calls))
        how = rnd.choice(["args", "edge", "other", "center"] if i else ["args", "edge", "center"])
        x = -pitch / 2 if i == 0 else pitch / 2
        at = f", cx={x} mm, cy={h / 2} mm" if how == "args" else \
            rnd.choice(["", f", cy={h / 2} mm", f", cx={rnd.choice([0, x])} mm"])
        lines.append(f"{name} = " + calls[kind].format(d=rnd.choice([20, 30]), at=at,
                                                        part=rnd.choice(["tail", "socket"])))
        if how == "edge":
            stmts += [f"AlignTop({name}, body)",
                      f"HorizontalDistance(body.left.midpoint, {cut[kind].format(name)}, "
                      f"{w / 2 + x} mm)"]
        elif how == "other":
            stmts += [f"HorizontalDistance({cut[kinds['a']].format('a')}, "
                      f"{cut[kind].format(name)}, {pitch} mm)", f"AlignTop({name}, a)"]
        elif how == "center":
            stmts += [rnd.choice([f"CenterInside({name}, body)", f"AlignCenterX({name}, body)"])]
    if stmts and rnd.random() < 0.4:
        stmts.append(rnd.choice(stmts))                 # said twice: a drop that is safe
    if rnd.random() < 0.6:
        stmts.append("Fixed(body)")
    rnd.shuffle(stmts)
    return ('import "std/joints.aidl"\n\nthickness 3 mm\n\nsolid panel {\n'
            + "".join(f"    {t}\n" for t in lines + stmts) + "}\n")


def generated(n: int):
    """``n`` programs as corpus entries of kind ``generated``: by turns
    :func:`generated_program` (``generated/hints/plate/SEED``) and
    :func:`generated_joint_program` (``generated/hints/joints/SEED``), seeds from 0; their
    path a file in the repository's root (never written; not in stdlib/, whose constraints
    are a template's own)."""
    from pathlib import Path

    from .corpus import Entry
    root = Path(__file__).resolve().parents[2]
    for k in range(n):
        seed = k // 2
        if k % 2 == 0:
            yield Entry(f"generated/hints/plate/{seed}", generated_program(seed),
                        str(root / "generated_hints_plate.aidl"), {}, "generated")
        else:
            yield Entry(f"generated/hints/joints/{seed}", generated_joint_program(seed),
                        str(root / "generated_hints_joints.aidl"), {}, "generated")
